#include "expr/tabulated.hpp"
#include "core/number_format.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace aster::expr {

Interpolation interpolationFromName(const std::string& word) {
  if (word == "LIN") return Interpolation::Linear;
  if (word == "LOG") return Interpolation::Logarithmic;
  throw Error("INTERPOL must be 'LIN' or 'LOG', got '" + word + "'");
}

Extension extensionFromName(const std::string& word) {
  if (word == "CONSTANT") return Extension::Constant;
  if (word == "LINEAIRE") return Extension::Linear;
  if (word == "EXCLU") return Extension::Excluded;
  throw Error("PROL_GAUCHE / PROL_DROITE must be 'CONSTANT', 'LINEAIRE' or 'EXCLU', got '" + word +
              "'");
}

Tabulated::Tabulated(std::string parameter, std::vector<double> abscissas,
                     std::vector<double> ordinates, TabulatedOptions options)
    : parameter_{std::move(parameter)},
      x_(std::move(abscissas)),
      y_(std::move(ordinates)),
      options_(options) {
  const std::string& name = parameter_[0];
  if (x_.empty()) throw Error("function of " + name + " has no points");
  if (x_.size() != y_.size())
    throw Error("function of " + name + ": " + std::to_string(x_.size()) + " abscissas but " +
                std::to_string(y_.size()) + " ordinates");
  for (std::size_t i = 0; i < x_.size(); ++i) {
    if (!std::isfinite(x_[i]) || !std::isfinite(y_[i]))
      throw Error("function of " + name + ": point " + std::to_string(i) + " (" +
                  format::shortest(x_[i]) + ", " + format::shortest(y_[i]) + ") is not finite");
    if (i > 0 && !(x_[i] > x_[i - 1]))
      throw Error("function of " + name + ": abscissas must be strictly increasing, but " + name +
                  "[" + std::to_string(i) + "] = " + format::shortest(x_[i]) + " follows " + name + "[" +
                  std::to_string(i - 1) + "] = " + format::shortest(x_[i - 1]) + " (0-based indices)");
    if (options_.abscissa == Interpolation::Logarithmic && !(x_[i] > 0))
      throw Error("function of " + name + ": INTERPOL 'LOG' on the abscissas needs positive values, "
                  "but " + name + "[" + std::to_string(i) + "] = " + format::shortest(x_[i]));
    if (options_.ordinate == Interpolation::Logarithmic && !(y_[i] > 0))
      throw Error("function of " + name + ": INTERPOL 'LOG' on the ordinates needs positive values, "
                  "but ordinate " + std::to_string(i) + " = " + format::shortest(y_[i]));
  }
  if (x_.size() == 1 &&
      (options_.left == Extension::Linear || options_.right == Extension::Linear))
    throw Error("function of " + name + " has a single point: 'LINEAIRE' extension needs two");
}

std::shared_ptr<Tabulated> Tabulated::fromPairs(std::string parameter,
                                                const std::vector<double>& pairs,
                                                TabulatedOptions options) {
  if (pairs.size() % 2 != 0)
    throw Error("VALE of a function of " + parameter + " must hold (abscissa, ordinate) pairs, got " +
                std::to_string(pairs.size()) + " numbers");
  std::vector<double> x, y;
  for (std::size_t i = 0; i < pairs.size(); i += 2) {
    x.push_back(pairs[i]);
    y.push_back(pairs[i + 1]);
  }
  return std::make_shared<Tabulated>(std::move(parameter), std::move(x), std::move(y), options);
}

double Tabulated::onSegment(std::size_t i, double x) const {
  const bool logX = options_.abscissa == Interpolation::Logarithmic;
  const bool logY = options_.ordinate == Interpolation::Logarithmic;
  if (logX && !(x > 0))
    throw Error("function of " + parameter_[0] + " with INTERPOL 'LOG' on the abscissas: " +
                parameter_[0] + " = " + format::shortest(x) + " is not positive");
  const double x0 = logX ? std::log(x_[i]) : x_[i];
  const double x1 = logX ? std::log(x_[i + 1]) : x_[i + 1];
  const double y0 = logY ? std::log(y_[i]) : y_[i];
  const double y1 = logY ? std::log(y_[i + 1]) : y_[i + 1];
  const double t = ((logX ? std::log(x) : x) - x0) / (x1 - x0);
  const double y = y0 + t * (y1 - y0);
  return logY ? std::exp(y) : y;
}

void Tabulated::outside(double x, const char* side) const {
  throw Error("parameter " + parameter_[0] + " = " + format::shortest(x) + " is outside [" +
              format::shortest(x_.front()) + ", " + format::shortest(x_.back()) + "] and " + side +
              "='EXCLU'");
}

double Tabulated::valueAt(double x) const {
  if (std::isnan(x)) throw Error("parameter " + parameter_[0] + " is nan");
  const std::size_t n = x_.size();
  if (x < x_.front()) {
    switch (options_.left) {
      case Extension::Constant: return y_.front();
      case Extension::Linear: return onSegment(0, x);
      case Extension::Excluded: outside(x, "PROL_GAUCHE");
    }
  }
  if (x > x_.back()) {
    switch (options_.right) {
      case Extension::Constant: return y_.back();
      case Extension::Linear: return onSegment(n - 2, x);
      case Extension::Excluded: outside(x, "PROL_DROITE");
    }
  }
  if (n == 1) return y_[0];
  const std::size_t i = segmentOf(x);
  if (x == x_[i]) return y_[i];  // exact at the points, whatever the law
  if (x == x_[i + 1]) return y_[i + 1];
  return onSegment(i, x);
}

std::size_t Tabulated::segmentOf(double x) const {
  // Segment i with x_[i] <= x <= x_[i+1]; the last point belongs to the last segment.
  const auto above = std::upper_bound(x_.begin(), x_.end(), x);
  return std::min(static_cast<std::size_t>(above - x_.begin()), x_.size() - 1) - 1;
}

double Tabulated::slopeOnSegment(std::size_t i, double x) const {
  const bool logX = options_.abscissa == Interpolation::Logarithmic;
  const bool logY = options_.ordinate == Interpolation::Logarithmic;
  const double x0 = logX ? std::log(x_[i]) : x_[i];
  const double x1 = logX ? std::log(x_[i + 1]) : x_[i + 1];
  const double y0 = logY ? std::log(y_[i]) : y_[i];
  const double y1 = logY ? std::log(y_[i + 1]) : y_[i + 1];
  const double slope = (y1 - y0) / (x1 - x0);  // of the law in its own (log) axes
  return slope * (logY ? onSegment(i, x) : 1.0) / (logX ? x : 1.0);
}

double Tabulated::slopeAt(double x) const {
  valueAt(x);  // the same refusals (nan, EXCLU, LOG of a non-positive abscissa)
  const std::size_t n = x_.size();
  if (n == 1) return 0.0;
  if (x < x_.front()) return options_.left == Extension::Constant ? 0.0 : slopeOnSegment(0, x);
  if (x > x_.back()) return options_.right == Extension::Constant ? 0.0 : slopeOnSegment(n - 2, x);
  return slopeOnSegment(segmentOf(x), x);
}

std::shared_ptr<Tabulated> tabulate(const Function& f, std::vector<double> abscissas,
                                    TabulatedOptions options) {
  const auto& names = f.parameters();
  if (names.size() != 1)
    throw Error("only a function of one parameter can be tabulated, this one takes (" +
                joinNames(names) + ")");
  std::vector<double> values;
  values.reserve(abscissas.size());
  for (double x : abscissas) values.push_back(f.evaluate(&x));
  return std::make_shared<Tabulated>(names[0], std::move(abscissas), std::move(values), options);
}

}  // namespace aster::expr
