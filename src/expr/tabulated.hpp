// DEFI_FONCTION: a function of one parameter given by points, with code_aster's
// INTERPOL (LIN or LOG on each axis) and PROL_GAUCHE / PROL_DROITE (CONSTANT,
// LINEAIRE, EXCLU). Also CALC_FONC_INTERP (tabulate any function on a list).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "expr/function.hpp"

namespace aster::expr {

enum class Interpolation { Linear, Logarithmic };     // 'LIN', 'LOG'
enum class Extension { Constant, Linear, Excluded };  // 'CONSTANT', 'LINEAIRE', 'EXCLU'

// From code_aster's words; throw aster::Error on anything else.
Interpolation interpolationFromName(const std::string& word);
Extension extensionFromName(const std::string& word);

// Defaults are DEFI_FONCTION's: INTERPOL=('LIN','LIN'), PROL_GAUCHE=PROL_DROITE='EXCLU'.
struct TabulatedOptions {
  Interpolation abscissa = Interpolation::Linear;
  Interpolation ordinate = Interpolation::Linear;
  Extension left = Extension::Excluded;
  Extension right = Extension::Excluded;
};

class Tabulated : public Function {
 public:
  // Abscissas strictly increasing, same count as ordinates, positive on a LOG axis.
  // One point is allowed only with CONSTANT or EXCLU extensions.
  Tabulated(std::string parameter, std::vector<double> abscissas, std::vector<double> ordinates,
            TabulatedOptions options = {});
  // VALE = (x0, y0, x1, y1, ...) as DEFI_FONCTION writes it.
  static std::shared_ptr<Tabulated> fromPairs(std::string parameter,
                                              const std::vector<double>& pairs,
                                              TabulatedOptions options = {});

  const std::vector<std::string>& parameters() const override { return parameter_; }
  double evaluate(const double* args) const override { return valueAt(args[0]); }
  double valueAt(double x) const;
  // The derivative of valueAt at x: the slope of the interpolation law of the
  // segment holding x (the one on its right at a point, the last one at the
  // last point), 0 on a CONSTANT extension. Throws where valueAt throws.
  double slopeAt(double x) const;

  const std::vector<double>& abscissas() const { return x_; }
  const std::vector<double>& ordinates() const { return y_; }
  const TabulatedOptions& options() const { return options_; }

 private:
  // The interpolation law of segment [i, i+1], also used to extend it (LINEAIRE).
  double onSegment(std::size_t i, double x) const;
  double slopeOnSegment(std::size_t i, double x) const;
  // The segment valueAt interpolates on for x inside [x_front, x_back].
  std::size_t segmentOf(double x) const;
  [[noreturn]] void outside(double x, const char* side) const;

  std::vector<std::string> parameter_;
  std::vector<double> x_, y_;
  TabulatedOptions options_;
};

// CALC_FONC_INTERP: the values of a one-parameter function at the given abscissas.
std::shared_ptr<Tabulated> tabulate(const Function& f, std::vector<double> abscissas,
                                    TabulatedOptions options = {});

}  // namespace aster::expr
