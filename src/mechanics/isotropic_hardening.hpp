// Isotropic hardening of the von Mises laws: R(p), the radius of the elastic
// domain as a function of the cumulated plastic strain p, and the return
// equation that the radial return solves with it.
//  - linear (ECRO_LINE): R(p) = SY + H p;
//  - piecewise linear through points (p_k, R_k), p_0 = 0 (TRACTION): code_aster's
//    traction curve sigma(epsilon) gives p_k = epsilon_k - sigma_k / E and
//    R_k = sigma_k, with E = sigma_0 / epsilon_0 the slope of its first point;
//    past the last point R continues as the curve's PROL_DROITE says.
// Mixed hardening (VMIS_ECMI_*) removes the kinematic part 1.5 C p of the
// uniaxial curve (lessKinematic), so that the curve stays the uniaxial response.
#pragma once
#include <vector>

namespace aster::mechanics {

class IsotropicHardening {
 public:
  // Past the last point: continue the last segment, stay constant, or refuse
  // (PROL_DROITE LINEAIRE, CONSTANT, EXCLU).
  enum class Beyond { Linear, Constant, Refuse };

  // R = yield + slope p.
  static IsotropicHardening linear(double yield, double slope);
  // Through (p_k, R_k), p_0 = 0 < p_1 < ...; throws aster::Error unless so.
  static IsotropicHardening piecewise(std::vector<double> p, std::vector<double> R, Beyond beyond);
  // From a traction curve (epsilon_k, sigma_k), at least one point; `young` gets
  // sigma_0 / epsilon_0. Throws aster::Error naming the point that makes p
  // decrease (a slope steeper than the first) or a non-positive first point.
  static IsotropicHardening fromTractionCurve(const std::vector<double>& strain, const std::vector<double>& stress,
                                              Beyond beyond, double& young);

  // R(p) - 1.5 C p.
  IsotropicHardening lessKinematic(double prager) const;

  double yield() const { return value(0.0); }
  double value(double p) const;
  // dR/dp at p (the right slope at a corner).
  double slope(double p) const;
  // The increment dp > 0 such that q - h dp = R(p + dp), for q > R(p) and
  // h = 3 mu + 1.5 C > 0 (q: the trial von Mises stress). Throws aster::Error
  // when it lies past the end of a Refuse curve, or when no dp solves it
  // (softening steeper than h).
  double returnIncrement(double q, double h, double p) const;

 private:
  // Segment k runs from (p_[k], R_[k]) to (p_[k + 1], R_[k + 1]); past the last
  // point the slope is beyondSlope_.
  std::vector<double> p_, R_;
  double shift_ = 0;  // the C of lessKinematic: R(p) - 1.5 shift_ p
  Beyond beyond_ = Beyond::Linear;
  double beyondSlope_ = 0;
  // The segment holding p (a corner: the one on its right), -1 past the last point.
  int segmentOf(double p) const;
  double slopeOfSegment(int k) const;
};

}  // namespace aster::mechanics
