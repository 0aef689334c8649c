#include "commands/check_keywords.hpp"

#include <cmath>

#include "core/atomic_write.hpp"
#include "core/error.hpp"
#include "core/messages.hpp"

namespace aster::lang {

post::CheckSpec checkSpecOf(const Keywords& k) {
  const std::string where = k.path.empty() ? "" : k.path + ": ";
  post::CheckSpec s;
  s.integer = k.has("VALE_CALC_I");
  if (k.has("VALE_CALC")) s.valeCalc = k.reals("VALE_CALC");
  if (k.has("VALE_CALC_I")) s.valeCalc = k.reals("VALE_CALC_I");
  if (k.has("TOLE_MACHINE")) s.toleMachine = k.reals("TOLE_MACHINE")[0];
  if (k.has("CRITERE")) s.relative = k.texts("CRITERE")[0] == "RELATIF";
  if (k.has("REFERENCE")) {
    s.reference = k.text("REFERENCE");
    // The catalogue's block on REFERENCE holds VALE_REFE (one kind) and PRECISION.
    const bool refeI = k.has("VALE_REFE_I");
    if (refeI != s.integer || k.has("VALE_REFE_K"))
      throw Error(where + (s.integer ? "VALE_CALC_I needs VALE_REFE_I" : "VALE_CALC needs VALE_REFE") +
                  " (the same kind of value)");
    s.valeRefe = k.reals(refeI ? "VALE_REFE_I" : "VALE_REFE");
    s.precision = k.real("PRECISION");
  }
  if (k.has("ORDRE_GRANDEUR")) {
    // code_aster's catalogue offers ORDRE_GRANDEUR only when VALE_CALC is 0.
    if (s.valeCalc.empty() || s.integer || std::fabs(s.valeCalc[0]) >= 1e-16)
      throw Error(where + "ORDRE_GRANDEUR is allowed only with VALE_CALC = 0 (it scales the absolute tolerance "
                          "of a zero value)");
    s.hasOrdreGrandeur = true;
    s.ordreGrandeur = k.real("ORDRE_GRANDEUR");
  }
  s.valeAbs = k.has("VALE_ABS") && k.text("VALE_ABS") == "OUI";
  if (k.has("LEGENDE")) s.legende = k.text("LEGENDE");
  return s;
}

InstantLookup instantLookupOf(const Keywords& k) {
  InstantLookup l;
  if (k.has("TOLE_MACHINE")) l.precision = k.reals("TOLE_MACHINE").back();
  if (k.has("CRITERE")) l.criterion = k.texts("CRITERE").back();
  return l;
}

void recordCheck(Session& session, double computed, const post::CheckSpec& spec, const CheckWhat& what,
                 bool headerLeadingBlank, const std::string& prefix) {
  recordCheckLines(session, computed, spec, prefix + post::formatHeader(what, headerLeadingBlank), what.front().first);
}

void recordCheckLines(Session& session, double computed, const post::CheckSpec& spec, const std::string& header,
                      const std::string& origin) {
  const auto lines = post::check(computed, spec);
  bool ok = true;
  std::vector<CheckRecord> records;
  for (const auto& l : lines) {
    ok = ok && l.ok();
    if (l.diag == post::CheckLine::Diag::Skip)
      Messages::alarm(origin, "VALE_CALC is 0 and ORDRE_GRANDEUR is not given: the non-regression check at " +
                                  session.where + " is skipped (give ORDRE_GRANDEUR, the magnitude of the value)");
    const auto text = [&](double v) { return l.integer ? std::to_string(static_cast<long long>(v)) : post::pythonRepr(v); };
    records.push_back({l.diag == post::CheckLine::Diag::Ok ? "OK" : l.diag == post::CheckLine::Diag::Nook ? "NOOK" : "SKIP",
                       l.reference, text(l.computed), text(l.expected)});
  }
  appendCheckRecords(session, records);
  session.recordCheck(header + post::formatLines(lines, spec.legende) + "  \n", ok);
}

void appendCheckRecords(Session& session, const std::vector<CheckRecord>& records) {
  std::string text;
  for (const auto& r : records)
    text += r.diag + "\t" + session.command + "\t" + session.where + "\t" + r.reference + "\t" + r.computed + "\t" +
            r.expected + "\n";
  const auto path = session.outputFile(session.resuPath().stem().string() + ".checks");
  if (!session.studyPath.empty()) session.files.addInput(session.studyPath, "the study file");
  appendAtomically(path, text, session.files.written(path), &session.files);
}

}  // namespace aster::lang
