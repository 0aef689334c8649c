#include "linalg/linear_solver.hpp"

#include <sstream>

#include "linalg/cholmod_solver.hpp"
#include "linalg/eigen_lu_solver.hpp"
#include "linalg/gcpc_solver.hpp"
#include "linalg/klu_solver.hpp"
#include "linalg/mult_front_solver.hpp"
#include "linalg/mumps_solver.hpp"
#include "linalg/umfpack_solver.hpp"

namespace aster::linalg {

LinearSolver::~LinearSolver() = default;

void LinearSolver::factorizeAndSolve(const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  factorize(A);
  solve(b, x);
}

void LinearSolver::solveMany(const Eigen::MatrixXd& B, Eigen::MatrixXd& X) const {
  X.resize(B.rows(), B.cols());
  Eigen::VectorXd x;
  for (Eigen::Index c = 0; c < B.cols(); ++c) {
    solve(B.col(c), x);
    X.col(c) = x;
  }
}

void LinearSolver::requireReadyToSolve(bool factorized, const Eigen::VectorXd& b) const {
  if (!factorized) throw Error(name() + ": solve() called without a successful factorize()");
  if (b.size() != pattern_.size()) {
    std::ostringstream s;
    s << name() << ": the right-hand side has " << b.size() << " entries but the matrix has " << pattern_.size()
      << " rows";
    throw Error(s.str());
  }
}

void LinearSolver::setOrdering(const std::string& renum) {
  const auto names = orderings();
  for (const auto& n : names)
    if (n == renum) {
      ordering_ = renum;
      return;
    }
  std::ostringstream s;
  s << name() << " does not take RENUM='" << renum << "'; it takes:";
  for (std::size_t i = 0; i < names.size(); ++i) s << (i ? ", " : " ") << "'" << names[i] << "'";
  throw Error(s.str());
}

std::vector<std::string> linearSolverMethods() {
  return {"MULT_FRONT", "MUMPS", "UMFPACK", "CHOLMOD", "CHOLMOD_LDLT", "KLU", "EIGEN_LU"};
}

std::unique_ptr<LinearSolver> makeLinearSolver(const std::string& methode) {
  if (methode == "MULT_FRONT") return std::make_unique<MultFrontSolver>();
  if (methode == "MUMPS") return std::make_unique<MumpsSolver>();
  if (methode == "UMFPACK") return std::make_unique<UmfpackSolver>();
  if (methode == "CHOLMOD") return std::make_unique<CholmodSolver>(CholmodSolver::Mode::Cholesky);
  if (methode == "CHOLMOD_LDLT") return std::make_unique<CholmodSolver>(CholmodSolver::Mode::LDLT);
  if (methode == "KLU") return std::make_unique<KluSolver>();
  if (methode == "EIGEN_LU") return std::make_unique<EigenLuSolver>();
  if (methode == "GCPC") return std::make_unique<GcpcSolver>();
  std::ostringstream s;
  s << "unknown linear solver METHODE '" << methode << "'; allowed:";
  const auto names = linearSolverMethods();
  for (std::size_t i = 0; i < names.size(); ++i) s << (i ? ", " : " ") << "'" << names[i] << "'";
  s << ", 'GCPC'";
  throw Error(s.str());
}

}  // namespace aster::linalg
