#include "mechanics/manufactured.hpp"
#include "core/number_format.hpp"

#include <cmath>
#include <type_traits>

#include <Eigen/LU>

#include "core/error.hpp"
#include "expr/dual.hpp"
#include "mechanics/isotropic_elasticity.hpp"

namespace aster::mechanics {

using expr::Dual1;
using expr::Dual2;
using expr::ExpressionPtr;
using expr::Function;
using expr::FunctionPtr;
using expr::joinNames;

namespace {

// Pi (or sigma) from grad U, for double and for Dual1 (whose derivatives then give div Pi).
template <class T>
void stressFromGradient(const T G[2][2], double lambda, double mu, Kinematics kinematics,
                        T P[2][2]) {
  if (kinematics == Kinematics::SmallStrain) {
    const T tr = G[0][0] + G[1][1];
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) P[i][j] = mu * (G[i][j] + G[j][i]);
    P[0][0] += lambda * tr;
    P[1][1] += lambda * tr;
    return;
  }
  T F[2][2];
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) F[i][j] = i == j ? G[i][j] + 1.0 : G[i][j];
  T E[2][2];  // Green-Lagrange: (F^T F - I) / 2
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      E[i][j] = 0.5 * (F[0][i] * F[0][j] + F[1][i] * F[1][j]);
      if (i == j) E[i][j] -= 0.5;
    }
  const T tr = E[0][0] + E[1][1];
  T S[2][2];
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) S[i][j] = 2.0 * mu * E[i][j];
  S[0][0] += lambda * tr;
  S[1][1] += lambda * tr;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) P[i][j] = F[i][0] * S[0][j] + F[i][1] * S[1][j];
}

Eigen::Vector2d unitNormal(const Eigen::Vector2d& N) {
  const double norm = N.norm();
  if (!(norm > 0) || !std::isfinite(norm))
    throw Error("manufactured solution: the boundary normal (" + format::shortest(N.x()) + ", " +
                format::shortest(N.y()) + ") is not a direction");
  return N / norm;
}

}  // namespace

ManufacturedElasticity::ManufacturedElasticity(ExpressionPtr ux, ExpressionPtr uy, double young,
                                               double poisson, PlaneHypothesis hypothesis,
                                               Kinematics kinematics)
    : u_{std::move(ux), std::move(uy)}, kinematics_(kinematics) {
  for (int c = 0; c < 2; ++c) {
    if (!u_[c]) throw Error("manufactured solution: displacement U" + std::string(c ? "y" : "x") +
                            " is missing");
    const auto& names = u_[c]->parameters();
    if (names.size() > 2)
      throw Error("manufactured solution: U" + std::string(c ? "y" : "x") +
                  " must be a function of X and Y only, it takes (" + joinNames(names) + ")");
    for (std::size_t k = 0; k < names.size(); ++k) {
      if (names[k] == "X") slot_[c][k] = 0;
      else if (names[k] == "Y") slot_[c][k] = 1;
      else
        throw Error("manufactured solution: U" + std::string(c ? "y" : "x") +
                    " must be a function of X and Y only, it takes (" + joinNames(names) + ")");
    }
  }
  if (!(young > 0)) throw Error("manufactured solution: E = " + format::shortest(young) + " must be > 0");
  if (!(poisson > -1.0 && poisson < 0.5))
    throw Error("manufactured solution: NU = " + format::shortest(poisson) + " must be in ]-1, 0.5[");
  const IsotropicElasticity law(young, poisson, hypothesis);
  lambda_ = law.planeLambda();
  mu_ = law.mu();
}

template <class T>
void ManufacturedElasticity::evaluateU(double X, double Y, T u[2]) const {
  // Dual numbers seed X as variable 0 and Y as variable 1; doubles are just the values.
  T xy[2];
  if constexpr (std::is_same_v<T, double>) {
    xy[0] = X;
    xy[1] = Y;
  } else {
    xy[0] = T::variable(X, 0);
    xy[1] = T::variable(Y, 1);
  }
  for (int c = 0; c < 2; ++c) {
    T args[2];
    const std::size_t n = u_[c]->parameters().size();
    for (std::size_t k = 0; k < n; ++k) args[k] = xy[slot_[c][k]];
    u[c] = u_[c]->evaluateT(args);
  }
}

Eigen::Vector2d ManufacturedElasticity::displacement(double X, double Y) const {
  double u[2];
  evaluateU(X, Y, u);
  return {u[0], u[1]};
}

Eigen::Matrix2d ManufacturedElasticity::displacementGradient(double X, double Y) const {
  Dual1<2> u[2];
  evaluateU(X, Y, u);
  Eigen::Matrix2d G;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) G(i, j) = u[i].d[j];
  return G;
}

Eigen::Matrix2d ManufacturedElasticity::firstPiola(double X, double Y) const {
  const Eigen::Matrix2d Gm = displacementGradient(X, Y);
  double G[2][2] = {{Gm(0, 0), Gm(0, 1)}, {Gm(1, 0), Gm(1, 1)}}, P[2][2];
  stressFromGradient(G, lambda_, mu_, kinematics_, P);
  Eigen::Matrix2d Pm;
  Pm << P[0][0], P[0][1], P[1][0], P[1][1];
  return Pm;
}

Eigen::Vector2d ManufacturedElasticity::bodyForce(double X, double Y) const {
  // grad U with its own gradient (the Hessian of U): Pi in Dual1 carries d Pi / dX_K.
  Dual2<2> u[2];
  evaluateU(X, Y, u);
  Dual1<2> G[2][2], P[2][2];
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      G[i][j] = Dual1<2>(u[i].g[j]);
      for (int k = 0; k < 2; ++k) G[i][j].d[k] = u[i].h[j][k];
    }
  stressFromGradient(G, lambda_, mu_, kinematics_, P);
  return {-(P[0][0].d[0] + P[0][1].d[1]), -(P[1][0].d[0] + P[1][1].d[1])};
}

Eigen::Vector2d ManufacturedElasticity::traction(double X, double Y,
                                                 const Eigen::Vector2d& N) const {
  return firstPiola(X, Y) * unitNormal(N);
}

ContactTraction ManufacturedElasticity::contact(double X, double Y,
                                                const Eigen::Vector2d& N) const {
  const Eigen::Vector2d unitN = unitNormal(N);
  const Eigen::Vector2d t = firstPiola(X, Y) * unitN;
  Eigen::Vector2d n = unitN;
  if (kinematics_ == Kinematics::GreenLagrange) {
    const Eigen::Matrix2d F = Eigen::Matrix2d::Identity() + displacementGradient(X, Y);
    const double J = F.determinant();
    if (!(J > 0))
      throw Error("manufactured solution: det F = " + format::shortest(J) + " <= 0 at X = " +
                  format::shortest(X) + ", Y = " + format::shortest(Y));
    n = F.inverse().transpose() * unitN;  // Nanson
    n.normalize();
  }
  const double p = t.dot(n);
  return {n, p, t - p * n};
}

namespace {

class ManufacturedFunction : public Function {
 public:
  ManufacturedFunction(ManufacturedPtr solution, ManufacturedQuantity quantity, int component,
                       const Eigen::Vector2d& N)
      : solution_(std::move(solution)), quantity_(quantity), component_(component), N_(N) {}
  const std::vector<std::string>& parameters() const override { return names_; }
  double evaluate(const double* args) const override {
    const double X = args[0], Y = args[1];
    switch (quantity_) {
      case ManufacturedQuantity::BodyForce: return solution_->bodyForce(X, Y)[component_];
      case ManufacturedQuantity::Traction: return solution_->traction(X, Y, N_)[component_];
      case ManufacturedQuantity::ContactPressure: return solution_->contact(X, Y, N_).pressure;
      case ManufacturedQuantity::TangentialTraction:
        return solution_->contact(X, Y, N_).tangential[component_];
    }
    throw Error("manufactured function: unknown quantity");
  }

 private:
  ManufacturedPtr solution_;
  ManufacturedQuantity quantity_;
  int component_;
  Eigen::Vector2d N_;
  std::vector<std::string> names_{"X", "Y"};
};

}  // namespace

FunctionPtr manufacturedFunction(ManufacturedPtr solution, ManufacturedQuantity quantity,
                                 int component, const Eigen::Vector2d& N) {
  if (!solution) throw Error("manufactured function: no solution given");
  if (component != 0 && component != 1)
    throw Error("manufactured function: component must be 0 (x) or 1 (y), got " +
                std::to_string(component));
  if (quantity != ManufacturedQuantity::BodyForce) unitNormal(N);  // reject a zero normal now
  return std::make_shared<ManufacturedFunction>(std::move(solution), quantity, component, N);
}

}  // namespace aster::mechanics
