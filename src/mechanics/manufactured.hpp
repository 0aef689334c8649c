// Manufactured solutions for 2D elasticity (code_aster's SSNP150 and friends):
// from an exact displacement U(X, Y) given as two FORMULE expressions, the loads
// that make it the solution, following the SSNP150 spec's equations (3)-(13):
//   F = I + grad U                                     (3)
//   E = (F^T F - I) / 2,  S = lambda tr(E) I + 2 mu E  (5)-(6)   Saint Venant-Kirchhoff
//   Pi = F S                                           (8)       first Piola-Kirchhoff
//   f = -div Pi                                        (9)       body force (reference volume)
//   t = Pi N                                           (10)      nominal traction, reference normal N
//   n = F^-T N / |F^-T N|                              (4)       Nanson: current normal
//   p = (Pi N) . n,  t_T = Pi N - p n                  (11)-(13) contact pressure, tangential part
// With small strains (PETIT): Pi = sigma(eps), eps = sym grad U, and n = N (the
// configuration is not updated). Plane stress (C_PLAN) uses lambda* = 2 lambda mu /
// (lambda + 2 mu), exact for SVK too since S is linear in E and S_33 = 0 fixes E_33.
// Second derivatives of U come from dual numbers (dual.hpp): exact, no finite differences.
#pragma once
#include <Eigen/Core>
#include <memory>
#include <string>

#include "expr/expression.hpp"
#include "mechanics/modelling.hpp"

namespace aster::mechanics {

struct ContactTraction {
  Eigen::Vector2d normal;      // n, unit normal of the deformed boundary
  double pressure;             // p = (Pi N).n, negative in compression
  Eigen::Vector2d tangential;  // t_T = Pi N - p n
};

class ManufacturedElasticity {
 public:
  // ux, uy: expressions of X and/or Y only (reference coordinates).
  ManufacturedElasticity(expr::ExpressionPtr ux, expr::ExpressionPtr uy, double young, double poisson,
                         PlaneHypothesis hypothesis, Kinematics kinematics);

  Eigen::Vector2d displacement(double X, double Y) const;
  Eigen::Matrix2d displacementGradient(double X, double Y) const;
  // Pi for GROT_GDEP, sigma for PETIT.
  Eigen::Matrix2d firstPiola(double X, double Y) const;
  Eigen::Vector2d bodyForce(double X, double Y) const;
  // N: outward normal of the reference boundary (normalised here).
  Eigen::Vector2d traction(double X, double Y, const Eigen::Vector2d& N) const;
  ContactTraction contact(double X, double Y, const Eigen::Vector2d& N) const;

  double lambda() const { return lambda_; }  // the plane one (lambda* for C_PLAN)
  double mu() const { return mu_; }

 private:
  template <class T>
  void evaluateU(double X, double Y, T u[2]) const;

  expr::ExpressionPtr u_[2];
  int slot_[2][2];  // slot_[c][k]: argument k of u_[c] is X (0) or Y (1)
  double lambda_, mu_;
  Kinematics kinematics_;
};

using ManufacturedPtr = std::shared_ptr<const ManufacturedElasticity>;

// The quantities above as Functions of (X, Y), e.g. for FORCE_INTERNE / FORCE_CONTOUR
// loads or for the exact pressure in a norm. component: 0 (x) or 1 (y).
enum class ManufacturedQuantity {
  BodyForce,           // -div Pi
  Traction,            // Pi N
  ContactPressure,     // p (component ignored)
  TangentialTraction,  // t_T
};
expr::FunctionPtr manufacturedFunction(ManufacturedPtr solution, ManufacturedQuantity quantity,
                                 int component, const Eigen::Vector2d& N = Eigen::Vector2d::Zero());

}  // namespace aster::mechanics
