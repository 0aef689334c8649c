#include "mechanics/hyperelasticity.hpp"

#include <cmath>
#include <limits>
#include <string>

#include <Eigen/LU>

#include "core/error.hpp"

namespace aster::mechanics {

namespace {

using Matrix3 = Eigen::Matrix3d;

// The (i, j) index pair of each Voigt component (xx, yy, zz, xy).
constexpr int kVoigtI[4] = {0, 1, 2, 0};
constexpr int kVoigtJ[4] = {0, 1, 2, 1};

struct StressAndTangent {
  Matrix3 S;             // second Piola-Kirchhoff
  VoigtTangent tangent;  // dS/dE, the full 4x4 (no condensation)
};

// The state of C with C13 = C23 = 0 (a plane element), from the in-plane E and C33.
Matrix3 rightCauchyGreen(const Eigen::Matrix2d& E, double c33) {
  Matrix3 C = Matrix3::Zero();
  C.topLeftCorner<2, 2>() = 2 * E + Eigen::Matrix2d::Identity();
  C(2, 2) = c33;
  return C;
}

}  // namespace

Hyperelasticity::Hyperelasticity(double c10, double c01, double c20, double bulk, PlaneHypothesis hypothesis)
    : c10_(c10), c01_(c01), c20_(c20), bulk_(bulk), hypothesis_(hypothesis) {
  if (!std::isfinite(c10) || !std::isfinite(c01) || !std::isfinite(c20))
    throw Error("ELAS_HYPER: C10, C01 and C20 must be finite numbers");
  if (!(c10 + c01 > 0))
    throw Error("ELAS_HYPER: the shear modulus 2 (C10 + C01) must be > 0, got C10 + C01 = " +
                std::to_string(c10 + c01));
  if (!(bulk > 0) || !std::isfinite(bulk))
    throw Error("ELAS_HYPER: the bulk modulus K must be > 0, got " + std::to_string(bulk));
  if (hypothesis == PlaneHypothesis::Axisymmetric)
    throw Error("ELAS_HYPER: the relation is available in D_PLAN and C_PLAN only, not in AXIS");
}

double Hyperelasticity::bulkFromPoisson(double c10, double c01, double nu) {
  // Small-strain isotropic elasticity: mu = 2 (C10 + C01), K = 2 mu (1 + nu) / (3 (1 - 2 nu)).
  if (!(nu > -1 && nu < 0.5))
    throw Error("ELAS_HYPER: Poisson's ratio NU must be in (-1, 0.5), got " + std::to_string(nu));
  return 4 * (c10 + c01) * (1 + nu) / (3 * (1 - 2 * nu));
}

namespace {

// S = 2 dW/dC and dS/dE = 4 d2W/dC2 at C (3x3, C13 = C23 = 0). With
// I3 = det C, J = sqrt(I3), a = dI1~/dC, b = dI2~/dC, P(A)_ijkl = (A_ik A_jl + A_il A_jk)/2:
//   a = I3^(-1/3) (1 - I1/3 C^-1),  b = I3^(-2/3) (I1 1 - C - 2/3 I2 C^-1)
//   S = 2 W1 a + 2 C01 b + K (I3 - J) C^-1,  W1 = C10 + 2 C20 (I1~ - 3)
//   da/dC = I3^(-1/3) [-1/3 (1 x C^-1 + C^-1 x 1) + I1/9 C^-1 x C^-1 + I1/3 P(C^-1)]
//   db/dC = I3^(-2/3) [-2/3 I1 (1 x C^-1 + C^-1 x 1) + 2/3 (C x C^-1 + C^-1 x C)
//                      + 4/9 I2 C^-1 x C^-1 + 1 x 1 - P(1) + 2/3 I2 P(C^-1)]
//   d(K (I3 - J) C^-1)/dC = K (I3 - J/2) C^-1 x C^-1 - K (I3 - J) P(C^-1)
//   dS/dE = 2 dS/dC = 2 [4 C20 a x a + 2 W1 da/dC + 2 C01 db/dC + dS_vol/dC].
StressAndTangent evaluate(const Matrix3& C, double c10, double c01, double c20, double bulk, bool withTangent) {
  const double I3 = C.determinant();
  if (!(I3 > 0))
    throw Error("ELAS_HYPER: det C = " + std::to_string(I3) + " <= 0 at a Gauss point (element turned inside out)");
  const double J = std::sqrt(I3);
  const double I1 = C.trace();
  const double I2 = 0.5 * (I1 * I1 - (C * C).trace());
  const double r1 = std::cbrt(1.0 / I3);  // I3^(-1/3)
  const double r2 = r1 * r1;              // I3^(-2/3)
  const Matrix3 Ci = C.inverse();
  const Matrix3 One = Matrix3::Identity();

  const Matrix3 a = r1 * (One - I1 / 3 * Ci);
  const Matrix3 b = r2 * (I1 * One - C - 2.0 / 3.0 * I2 * Ci);
  const double W1 = c10 + 2 * c20 * (r1 * I1 - 3);
  StressAndTangent result;
  result.S = 2 * W1 * a + 2 * c01 * b + bulk * (I3 - J) * Ci;
  if (!withTangent) return result;

  auto sym = [](const Matrix3& A, int i, int j, int k, int l) { return 0.5 * (A(i, k) * A(j, l) + A(i, l) * A(j, k)); };
  for (int p = 0; p < 4; ++p)
    for (int q = 0; q < 4; ++q) {
      const int i = kVoigtI[p], j = kVoigtJ[p], k = kVoigtI[q], l = kVoigtJ[q];
      const double cc = Ci(i, j) * Ci(k, l), pci = sym(Ci, i, j, k, l), pone = sym(One, i, j, k, l);
      const double oneCi = One(i, j) * Ci(k, l) + Ci(i, j) * One(k, l);
      const double cCi = C(i, j) * Ci(k, l) + Ci(i, j) * C(k, l);
      const double da = r1 * (-oneCi / 3 + I1 / 9 * cc + I1 / 3 * pci);
      const double db = r2 * (-2.0 / 3.0 * I1 * oneCi + 2.0 / 3.0 * cCi + 4.0 / 9.0 * I2 * cc + One(i, j) * One(k, l) -
                              pone + 2.0 / 3.0 * I2 * pci);
      const double dvol = bulk * (I3 - J / 2) * cc - bulk * (I3 - J) * pci;
      result.tangent(p, q) = 2 * (4 * c20 * a(i, j) * a(k, l) + 2 * W1 * da + 2 * c01 * db + dvol);
    }
  return result;
}

}  // namespace

void Hyperelasticity::integrate(const LawInput& in, LawOutput<VoigtTangent>& out, bool withTangent) const {
  if (out.variables) out.variables[0] = 0.0;  // VIDE
  if (hypothesis_ != PlaneHypothesis::PlaneStress) {
    const double ezz = in.strainZZ;  // 0 in D_PLAN
    const StressAndTangent st =
        evaluate(rightCauchyGreen(in.strain, 1 + 2 * ezz), c10_, c01_, c20_, bulk_, withTangent);
    out.stress = st.S.topLeftCorner<2, 2>();
    out.stressZZ = st.S(2, 2);
    out.strainZZ = ezz;
    if (withTangent) out.tangent = st.tangent;
    return;
  }

  // C_PLAN: Newton on C33 for S33 = 0, dS33/dC33 = D_zzzz / 2, from the
  // incompressible state det C = 1 (exact as K grows, the case of rubber).
  const double planeDet = (2 * in.strain + Eigen::Matrix2d::Identity()).determinant();
  if (!(planeDet > 0)) throw Error("ELAS_HYPER: det C = 0 or < 0 at a Gauss point (element turned inside out)");
  double c33 = 1 / planeDet;
  StressAndTangent st;
  bool converged = false;
  for (int iteration = 0; iteration < 60 && !converged; ++iteration) {
    st = evaluate(rightCauchyGreen(in.strain, c33), c10_, c01_, c20_, bulk_, true);
    const double s33 = st.S(2, 2), slope = 0.5 * st.tangent(kZZ, kZZ);
    const double scale = st.S.topLeftCorner<2, 2>().cwiseAbs().maxCoeff() + std::numeric_limits<double>::min();
    if (std::fabs(s33) <= 1e-14 * scale) {
      converged = true;
      break;
    }
    if (!(slope > 0)) break;  // S33 not increasing in C33: the energy is not convex there
    double step = -s33 / slope;
    // Keep C33 > 0 (det C > 0): at most divide C33 by 10 in one step.
    if (c33 + step < 0.1 * c33) step = -0.9 * c33;
    c33 += step;
    // A Newton step this small leaves an error of its square: E33 is then exact to
    // rounding, and S33 at the rounding floor of its evaluation (~ eps K).
    if (std::fabs(step) <= 1e-13 * c33) {
      st = evaluate(rightCauchyGreen(in.strain, c33), c10_, c01_, c20_, bulk_, true);
      converged = true;
    }
  }
  if (!converged) throw Error("ELAS_HYPER: the plane stress condition S_zz = 0 could not be solved at a Gauss point");
  out.stress = st.S.topLeftCorner<2, 2>();
  out.stressZZ = 0.0;
  out.strainZZ = 0.5 * (c33 - 1);
  if (withTangent) {
    const VoigtTangent& D = st.tangent;
    const double dzz = D(kZZ, kZZ);
    out.tangent = D - D.col(kZZ) * D.row(kZZ) / dzz;
    out.tangent.row(kZZ).setZero();
    out.tangent.col(kZZ).setZero();
  }
}

}  // namespace aster::mechanics
