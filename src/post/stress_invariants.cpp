#include "post/stress_invariants.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Core>

namespace aster::post {

const std::vector<std::string>& equivalentStressComponents() {
  static const std::vector<std::string> names{"VMIS",     "TRESCA",   "PRIN_1",   "PRIN_2",   "PRIN_3",   "VMIS_SG",
                                              "VECT_1_X", "VECT_1_Y", "VECT_1_Z", "VECT_2_X", "VECT_2_Y", "VECT_2_Z",
                                              "VECT_3_X", "VECT_3_Y", "VECT_3_Z", "TRSIG",    "TRIAX"};
  return names;
}

void equivalentStresses(const double* s, double* out) {
  const double xx = s[0], yy = s[1], zz = s[2], xy = s[3];
  const double trace = xx + yy + zz;
  const double p = trace / 3;
  const double dxx = xx - p, dyy = yy - p, dzz = zz - p;
  const double vmis = std::sqrt(1.5 * (dxx * dxx + dyy * dyy + dzz * dzz + 2 * xy * xy));
  // The in-plane block in closed form (z is a principal direction).
  const double c = 0.5 * (xx + yy), r = std::hypot(0.5 * (xx - yy), xy);
  const double theta = 0.5 * std::atan2(2 * xy, xx - yy);  // direction of the larger in-plane value
  struct Principal {
    double value;
    Eigen::Vector3d dir;
  };
  Principal pr[3] = {{c + r, {std::cos(theta), std::sin(theta), 0}},
                     {c - r, {-std::sin(theta), std::cos(theta), 0}},
                     {zz, {0, 0, 1}}};
  std::stable_sort(pr, pr + 3, [](const Principal& a, const Principal& b) { return a.value < b.value; });
  out[0] = vmis;
  out[1] = std::max({std::abs(pr[0].value - pr[1].value), std::abs(pr[0].value - pr[2].value),
                     std::abs(pr[1].value - pr[2].value)});
  for (int i = 0; i < 3; ++i) out[2 + i] = pr[i].value;
  out[5] = trace >= 0 ? vmis : -vmis;
  for (int i = 0; i < 3; ++i) {
    Eigen::Vector3d v = pr[i].dir;
    int big = 0;
    for (int d = 1; d < 3; ++d)
      if (std::abs(v(d)) > std::abs(v(big)) * (1 + 1e-12)) big = d;
    if (v(big) < 0) v = -v;
    for (int d = 0; d < 3; ++d) out[6 + 3 * i + d] = v(d);
  }
  out[15] = trace;
  out[16] = vmis > 1e-10 * std::abs(trace) ? p / vmis : 0.0;
}

}  // namespace aster::post
