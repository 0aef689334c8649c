#include "post/check.hpp"

#include <algorithm>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace aster::post {
namespace {

std::string padRight(const std::string& s, std::size_t width) {
  return s.size() >= width ? s : s + std::string(width - s.size(), ' ');
}

std::string upperE(std::string s) {
  for (char& c : s)
    if (c == 'e') c = 'E';
  return s;
}

std::string printfText(const char* fmt, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

std::string printfText(const char* fmt, int width, int digits, double v) {
  char buf[400];
  std::snprintf(buf, sizeof buf, fmt, width, digits, v);
  return buf;
}

std::string printfText(const char* fmt, int digits, double v) {
  char buf[400];
  std::snprintf(buf, sizeof buf, fmt, digits, v);
  return buf;
}

std::string strip(const std::string& s) {
  const auto b = s.find_first_not_of(' ');
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(' ') - b + 1);
}

// The reference of `refs` closest to the computed value (absolute values with VALE_ABS).
double closest(double computed, const std::vector<double>& refs, bool valeAbs) {
  double best = valeAbs ? std::fabs(refs[0]) : refs[0];
  for (double r : refs) {
    const double a = valeAbs ? std::fabs(r) : r;
    if (std::fabs(computed - a) < std::fabs(computed - best)) best = a;
  }
  return best;
}

std::string valueText(double v, bool integer) {
  if (integer) return std::to_string(static_cast<long long>(v));
  return pythonRepr(v);
}

// code_aster's TestResult.write: "%-4s " then columns of 16 (values: `width`), joined by a blank.
std::string row(std::size_t width, const std::vector<std::string>& cols) {
  std::string out = padRight(cols[0], 4) + " ";
  for (std::size_t i = 1; i < cols.size(); ++i)
    out += " " + padRight(cols[i], (i == 3 || i == 4) ? width : 16);
  return out + "\n";
}

}  // namespace

std::string pythonRepr(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v < 0 ? "-inf" : "inf";
  char buf[64];
  auto res = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::scientific);
  const std::string sci(buf, res.ptr);  // "-1.2345e-05": shortest digits that read back
  const bool negative = sci[0] == '-';
  const std::size_t epos = sci.find('e');
  std::string digits;
  for (std::size_t i = negative ? 1 : 0; i < epos; ++i)
    if (sci[i] != '.') digits += sci[i];
  const int exponent = std::atoi(sci.c_str() + epos + 1);
  const int decpt = exponent + 1;  // value = 0.digits * 10^decpt
  std::string out = negative ? "-" : "";
  if (decpt <= -4 || decpt > 16) {
    out += digits.substr(0, 1);
    if (digits.size() > 1) out += "." + digits.substr(1);
    char e[16];
    std::snprintf(e, sizeof e, "E%c%02d", exponent < 0 ? '-' : '+', std::abs(exponent));
    return out + e;
  }
  if (decpt <= 0) return out + "0." + std::string(-decpt, '0') + digits;
  if (static_cast<int>(digits.size()) <= decpt) return out + digits + std::string(decpt - digits.size(), '0') + ".0";
  return out + digits.substr(0, decpt) + "." + digits.substr(decpt);
}

CheckLine compareValue(double computed, double expected, double tolerance, bool relative, double compare) {
  CheckLine line;
  line.expected = expected;
  line.computed = computed;
  line.relative = relative;
  line.compare = compare;
  const double diff = std::fabs(expected - computed);
  bool ok;
  if (relative) {
    ok = diff <= std::fabs(tolerance * expected);
    line.tolerance = tolerance * 100.0;
    line.error = expected != 0.0 ? diff / std::fabs(expected) * 100.0 : ok ? 0.0 : 999.999999;
  } else {
    line.tolerance = std::fabs(tolerance * compare);
    ok = diff <= line.tolerance;
    line.error = diff;
  }
  line.diag = ok ? CheckLine::Diag::Ok : CheckLine::Diag::Nook;  // NaN compares false: NOOK
  return line;
}

std::vector<CheckLine> check(double computed, const CheckSpec& spec) {
  std::vector<CheckLine> lines;
  const double value = spec.valeAbs ? std::fabs(computed) : computed;
  if (!spec.valeCalc.empty()) {
    // A VALE_CALC of zero has no relative scale: ORDRE_GRANDEUR gives one, else skip.
    const bool zero = std::fabs(spec.valeCalc[0]) <= DBL_EPSILON;
    CheckLine l = compareValue(value, closest(value, spec.valeCalc, spec.valeAbs), spec.toleMachine, spec.relative,
                               zero && spec.hasOrdreGrandeur ? spec.ordreGrandeur : 1.0);
    if (zero && !spec.hasOrdreGrandeur) l.diag = CheckLine::Diag::Skip;
    l.reference = "NON_REGRESSION";
    l.integer = spec.integer;
    lines.push_back(l);
  }
  if (!spec.reference.empty() && !spec.valeRefe.empty()) {
    CheckLine l = compareValue(value, closest(value, spec.valeRefe, spec.valeAbs), spec.precision, spec.relative);
    l.reference = spec.reference;
    l.integer = spec.integer;
    lines.push_back(l);
  }
  return lines;
}

std::string formatLines(const std::vector<CheckLine>& lines, const std::string& legende) {
  std::string out;
  bool label = true;
  for (const auto& l : lines) {
    const std::string pct = l.relative ? "%" : "";
    std::string sref = valueText(l.expected, l.integer), sval = valueText(l.computed, l.integer);
    const std::size_t width = std::max<std::size_t>({16, sref.size(), sval.size()}) + 2;
    std::string serr = pythonRepr(l.error);
    if (serr.size() > 15) serr = upperE(printfText("%13.6e", l.error));
    std::string stol = pythonRepr(l.tolerance);
    serr += pct;
    stol += pct;
    std::string diag = l.diag == CheckLine::Diag::Ok ? " OK " : l.diag == CheckLine::Diag::Nook ? "NOOK" : "SKIP";
    std::string leg = legende;
    if (l.diag == CheckLine::Diag::Skip) leg = sref = sval = serr = stol = "-";
    if (l.compare != 1.0) out += row(width, {" ", "ORDRE DE GRANDEUR :", pythonRepr(l.compare)});
    if (label) out += row(width, {" ", "REFERENCE", "LEGENDE", "VALE_REFE", "VALE_CALC", "ERREUR", "TOLE"});
    label = false;
    out += row(width, {diag, l.reference, leg, sref, sval, serr, stol});
  }
  return out;
}

std::string formatHeader(const std::vector<std::pair<std::string, std::string>>& what, bool leadingBlank) {
  std::string names, values;
  for (std::size_t i = 0; i < what.size(); ++i) {
    if (i == 0) {
      names = padRight("---- " + what[i].first, 21);
      values = padRight("     " + what[i].second, 21);
    } else {
      names += " " + padRight(what[i].first, 16);
      values += " " + padRight(what[i].second, 16);
    }
  }
  const auto trimmed = [](std::string s) { return s.erase(s.find_last_not_of(' ') + 1); };
  return (leadingBlank ? " " : "") + trimmed(names) + "\n " + trimmed(values) + "\n";
}

std::string formatTextLine(bool ok, const std::string& reference, const std::string& legende,
                           const std::string& expected, const std::string& computed, bool label) {
  std::string out;
  if (label)
    out += std::string(5, ' ') + " " + padRight("REFERENCE", 16) + " " + padRight("LEGENDE", 16) + " " +
           padRight("VALE_REFE", 24) + " " + padRight("VALE_CALC", 24) + "\n";
  out += std::string(ok ? " OK " : "NOOK") + " " + " " + padRight(reference, 16) + " " + padRight(legende, 16) + " " +
         padRight(expected, 24) + " " + padRight(computed, 24) + "\n";
  return out;
}

std::vector<CheckLine> checkFunctionValue(double computed, const CheckSpec& spec) {
  const double value = spec.valeAbs ? std::fabs(computed) : computed;
  auto one = [&](const std::vector<double>& refs, double tol, const std::string& reference) {
    const double ref = closest(value, refs, false);
    CheckLine l;
    l.reference = reference;
    l.expected = ref;
    l.computed = value;
    l.relative = spec.relative;
    bool ok;
    if (spec.relative) {
      ok = std::fabs(value - ref) <= tol * std::fabs(ref);
      l.error = ref != 0 ? (value - ref) / ref * 100 : 999.999999;
      l.tolerance = tol * 100;
    } else {
      ok = std::fabs(value - ref) <= tol;
      l.error = value - ref;
      l.tolerance = tol;
    }
    l.diag = ok ? CheckLine::Diag::Ok : CheckLine::Diag::Nook;
    return l;
  };
  std::vector<CheckLine> lines;
  if (!spec.valeCalc.empty()) lines.push_back(one(spec.valeCalc, spec.toleMachine, "NON_REGRESSION"));
  if (!spec.reference.empty() && !spec.valeRefe.empty()) lines.push_back(one(spec.valeRefe, spec.precision, spec.reference));
  return lines;
}

namespace {

// TEST_FONCTION's rounding of the computed and expected values: digits enough for
// the tolerance (at least 12 for NON_REGRESSION), without exponent between 0.01 and 1e5.
std::string roundedValue(double v, int ndigit) {
  const double a = std::fabs(v);
  if (a >= 0.01 && a < 1e5) {
    int nap, ntot;
    if (a < 1.0) {
      nap = ndigit + 2;
      ntot = nap + 1;
    } else {
      const int nav = static_cast<int>(std::log10(a)) + 1;
      nap = ndigit + 1 - nav;
      ntot = nav + nap;
    }
    return strip(printfText("%*.*f", ntot, std::max(nap, 0), v));
  }
  return strip(printfText("%25.*E", ndigit, v));
}

// "%5.1E" below 0.1 and from 1e5, else "%5.1f", of the absolute value.
std::string roundedError(double e) {
  const double a = std::fabs(e);
  if (a > 0.1 && a < 100000) return strip(printfText("%5.1f", a));
  return strip(printfText("%5.1E", a));
}

std::size_t fieldWidth(std::size_t n) { return n <= 16 ? 16 : n <= 24 ? 24 : n <= 36 ? 36 : 48; }

}  // namespace

std::string formatFunctionLines(const std::vector<CheckLine>& lines, const std::string& legende) {
  std::string out;
  bool label = true;
  for (const auto& l : lines) {
    // Digits of log10, bounded (a zero tolerance or an infinite value gives the most digits).
    const auto digitsOf = [](double x) {
      const double d = std::log10(std::fabs(x));
      return std::isfinite(d) ? static_cast<int>(std::clamp(d, -20.0, 20.0)) : (d < 0 ? -20 : 20);
    };
    int ndigit;
    if (l.relative) {
      ndigit = std::max(-digitsOf(l.tolerance) + 2, 2);
    } else {
      ndigit = l.tolerance != 0 ? -digitsOf(l.tolerance) : 10;
      if (l.computed != 0 && !std::isnan(l.computed)) ndigit += digitsOf(l.computed);
      ndigit = std::max(ndigit, 2);
    }
    if (l.reference == "NON_REGRESSION") ndigit = std::max(12, ndigit);
    ndigit = std::min(ndigit, 15);
    const std::string valRef = roundedValue(l.expected, ndigit), valCal = roundedValue(l.computed, ndigit);
    const std::size_t nvref = fieldWidth(valRef.size()), nvcal = fieldWidth(valCal.size());
    const std::string pct = l.relative ? "%" : " ";
    if (label)
      out += "      " + padRight("REFERENCE", 16) + " " + padRight("LEGENDE", 16) + " " + padRight("VALE_REFE", nvref) +
             " " + padRight("VALE_CALC", nvcal) + " " + padRight("ERREUR", 16) + " " + padRight("TOLE", 16) + " \n";
    label = false;
    out += std::string(l.diag == CheckLine::Diag::Ok ? " OK " : "NOOK") + "  " + padRight(l.reference, 16) + " " +
           padRight(legende, 16) + " " + padRight(valRef, nvref) + " " + padRight(valCal, nvcal) + " " +
           padRight(roundedError(l.error) + pct, 16) + " " + padRight(roundedError(l.tolerance) + pct, 16) + " \n";
  }
  return out;
}

}  // namespace aster::post
