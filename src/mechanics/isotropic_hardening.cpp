#include "mechanics/isotropic_hardening.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "core/number_format.hpp"

namespace aster::mechanics {

IsotropicHardening IsotropicHardening::linear(double yield, double slope) {
  IsotropicHardening h;
  h.p_ = {0.0};
  h.R_ = {yield};
  h.beyond_ = Beyond::Linear;
  h.beyondSlope_ = slope;
  return h;
}

IsotropicHardening IsotropicHardening::piecewise(std::vector<double> p, std::vector<double> R, Beyond beyond) {
  if (p.empty() || p.size() != R.size()) throw Error("internal error: a hardening curve needs as many p as R, at least one");
  if (p[0] != 0.0) throw Error("internal error: a hardening curve starts at p = 0");
  for (std::size_t k = 1; k < p.size(); ++k)
    if (!(p[k] > p[k - 1]))
      throw Error("the hardening curve's plastic strain must increase: point " + std::to_string(k + 1) + " has p = " +
                  format::shortest(p[k]) + " after p = " + format::shortest(p[k - 1]));
  IsotropicHardening h;
  h.p_ = std::move(p);
  h.R_ = std::move(R);
  h.beyond_ = beyond;
  const std::size_t n = h.p_.size();
  h.beyondSlope_ = beyond == Beyond::Linear && n >= 2 ? h.slopeOfSegment(static_cast<int>(n) - 2) : 0.0;
  return h;
}

IsotropicHardening IsotropicHardening::fromTractionCurve(const std::vector<double>& strain,
                                                         const std::vector<double>& stress, Beyond beyond,
                                                         double& young) {
  if (strain.empty() || strain.size() != stress.size())
    throw Error("the traction curve needs at least one point (EPSI, SIGM)");
  if (!(strain[0] > 0 && stress[0] > 0))
    throw Error("the traction curve's first point (EPSI = " + format::shortest(strain[0]) + ", SIGM = " +
                format::shortest(stress[0]) + ") must have EPSI > 0 and SIGM > 0: it is the yield point, and "
                "SIGM/EPSI there is Young's modulus");
  young = stress[0] / strain[0];
  std::vector<double> p(strain.size()), R(stress);
  p[0] = 0.0;
  for (std::size_t k = 1; k < strain.size(); ++k) {
    p[k] = strain[k] - stress[k] / young;
    if (!(p[k] > p[k - 1]))
      throw Error("the traction curve between its points " + std::to_string(k) + " and " + std::to_string(k + 1) +
                  " (EPSI = " + format::shortest(strain[k]) + ") is not below the elastic slope SIGM/EPSI = " +
                  format::shortest(young) + " of its first point: the plastic strain EPSI - SIGM/E must increase");
  }
  return piecewise(std::move(p), std::move(R), beyond);
}

IsotropicHardening IsotropicHardening::lessKinematic(double prager) const {
  IsotropicHardening h = *this;
  h.shift_ += prager;
  return h;
}

double IsotropicHardening::slopeOfSegment(int k) const { return (R_[k + 1] - R_[k]) / (p_[k + 1] - p_[k]); }

int IsotropicHardening::segmentOf(double p) const {
  const int n = static_cast<int>(p_.size());
  if (n < 2 || p > p_.back()) return -1;
  int k = 0;
  while (k + 2 < n && p >= p_[k + 1]) ++k;
  return k;
}

double IsotropicHardening::value(double p) const {
  const int k = segmentOf(p);
  const double base = k >= 0 ? R_[k] + slopeOfSegment(k) * (p - p_[k]) : R_.back() + beyondSlope_ * (p - p_.back());
  return base - 1.5 * shift_ * p;
}

double IsotropicHardening::slope(double p) const {
  // A corner belongs to the segment on its right (segmentOf's), the last point to what lies beyond.
  const int k = segmentOf(p);
  const double base = k < 0 || p >= p_.back() ? beyondSlope_ : slopeOfSegment(k);
  return base - 1.5 * shift_;
}

double IsotropicHardening::returnIncrement(double q, double h, double p) const {
  // g(x) = q - h (x - p) - R(x) decreases along the piecewise linear R: walk the
  // segments from p to the one where g vanishes.
  double x = p, g = q - value(p);
  const int n = static_cast<int>(p_.size());
  for (int guard = 0; guard <= n + 1; ++guard) {
    const bool beyond = n < 2 || x >= p_.back();
    if (beyond && beyond_ == Beyond::Refuse)
      throw Error("the plastic strain p passes the last point of the traction curve (p = " + format::shortest(p_.back()) +
                  ") and its PROL_DROITE is EXCLU");
    const double s = slope(x);
    if (!(h + s > 0))
      throw Error("the hardening slope " + format::shortest(s) + " at p = " + format::shortest(x) +
                  " softens faster than the elastic return (3 mu + 1.5 C = " + format::shortest(h) +
                  "): the plastic increment is not unique");
    const double candidate = x + g / (h + s);
    if (beyond) return candidate - p;
    const double end = p_[segmentOf(x) + 1];
    if (candidate <= end) return candidate - p;
    x = end;
    g = q - h * (x - p) - value(x);
    if (g <= 0) return x - p;
  }
  throw Error("internal error: the radial return did not find its segment of the hardening curve");
}

}  // namespace aster::mechanics
