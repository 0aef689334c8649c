#include "analysis/step_cutting.hpp"

#include <cmath>
#include <limits>

namespace aster::analysis {

namespace {

// r for n sub-steps: the inverse of n = (sqrt(1 + 24 / r) - 1) / 3.
double fractionFor(int n) { return 24.0 / ((3.0 * n + 1) * (3.0 * n + 1) - 1); }

}  // namespace

StepCut automaticCut(const std::vector<double>& residuals, double criterion, int iterGlobMaxi) {
  StepCut uniform;  // 4 equal sub-steps
  const int last = static_cast<int>(residuals.size()) - 1;
  const int first = 3;  // the first iterations say little of the rate
  if (last < first + 3 || !(criterion > 0)) return uniform;
  // Weighted least squares of i = a + b x, x = log(residual_i), i = first..last.
  double sw = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int i = first; i <= last; ++i) {
    if (!(residuals[i] > 0) || !std::isfinite(residuals[i])) return uniform;
    const double w = i > last - 3 ? 2.0 : 1.0;
    const double x = std::log(residuals[i]);
    sw += w;
    sx += w * x;
    sy += w * i;
    sxx += w * x * x;
    sxy += w * x * i;
  }
  const double det = sw * sxx - sx * sx;
  if (det <= std::numeric_limits<double>::epsilon() * sw * sxx) return uniform;  // the residual did not move
  const double b = (sw * sxy - sx * sy) / det;
  const double a = (sy - b * sx) / sw;
  const double target = a + b * std::log(criterion);  // the iteration the criterion would be reached at
  StepCut cut;
  cut.extrapolated = true;
  cut.parts = 4;
  cut.firstFraction = fractionFor(4);
  if (target * 1.2 < iterGlobMaxi || b <= std::numeric_limits<double>::epsilon()) return cut;
  const double r = 0.48485 * std::exp(std::max((target - iterGlobMaxi) / b, -10.0));
  const double n = (std::sqrt(1 + 24 / r) - 1) / 3;
  if (n < 2) {
    cut.parts = 2;
    cut.firstFraction = 0.5;
  } else {
    cut.parts = static_cast<int>(std::lround(n));
    cut.firstFraction = r;
  }
  return cut;
}

std::vector<double> subStepEnds(double t0, double t1, const StepCut& cut) {
  std::vector<double> ends;
  const double dt = t1 - t0;
  const double first = cut.firstFraction * dt;
  const double next = cut.parts > 1 ? (dt - first) / (cut.parts - 1) : 0;
  for (int i = 1; i < cut.parts; ++i) ends.push_back(t0 + first + (i - 1) * next);
  ends.push_back(t1);
  return ends;
}

}  // namespace aster::analysis
