#include "linalg/gcpc_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "linalg/mumps_single_solver.hpp"
#include "linalg/mumps_solver.hpp"
#include "linalg/stopwatch.hpp"

namespace aster::linalg {

namespace {

constexpr double kSymmetryTolerance = 1e-10;

}  // namespace

GcpcSolver::GcpcSolver() = default;

GcpcSolver::~GcpcSolver() = default;

void GcpcSolver::setOptions(const GcpcOptions& options) {
  const std::string& p = options.preconditioner;
  if (p == "LDLT_INC")
    throw Error("GCPC: PRE_COND='LDLT_INC' (incomplete factorization) is not available in aster-lite; "
                "use PRE_COND='LDLT_SP' or 'LDLT_DP' (complete factorizations of an earlier matrix)");
  if (p != "LDLT_SP" && p != "LDLT_DP")
    throw Error("GCPC: PRE_COND='" + p + "' is not available; GCPC takes 'LDLT_SP' or 'LDLT_DP'");
  if (options.reacPrecond < 0) throw Error("GCPC: REAC_PRECOND must be at least 0");
  if (!(options.relativeResidual > 0.0 && options.relativeResidual < 1.0))
    throw Error("GCPC: RESI_RELA must lie in ]0, 1[");
  if (options.maxIterations < 0) throw Error("GCPC: NMAX_ITER must be at least 0 (0: automatic)");
  if (options.pivotPercent < 1) throw Error("GCPC: PCENT_PIVOT must be at least 1");
  options_ = options;
}

void GcpcSolver::requireSymmetric(const SparseMatrix& M) const {
  if (symmetricByConstruction_) return;
  try {
    symmetry_->require(M, kSymmetryTolerance, name());
  } catch (const UnsymmetricMatrixError& e) {
    const std::string what = e.what();  // the pair of entries, before the check's own advice
    throw Error(what.substr(0, what.find(';')) +
                "; GCPC (conjugate gradient) solves symmetric positive definite systems only: use a direct "
                "solver (METHODE='MULT_FRONT' or 'MUMPS'), or NEWTON/MATR_RIGI_SYME='OUI'");
  }
}

void GcpcSolver::analyze(const SparseMatrix& A) {
  ScopedSeconds t(stats_.analyzeSeconds, stats_.analyzeCount);
  requireSquare(A, name());
  SparseMatrix storage;
  const SparseMatrix& M = compressedMatrix(A, storage);
  if (multipliersFrom_ >= 0 && multipliersFrom_ < M.rows())
    throw Error("GCPC: the system holds Lagrange multipliers (contact): its matrix is symmetric but indefinite, "
                "and the conjugate gradient needs a symmetric positive definite one; use METHODE='MULT_FRONT' "
                "or 'MUMPS' with contact");
  factorized_ = false;
  preconditionerReady_ = preconditionerCurrent_ = false;
  pattern_.record(M);
  symmetry_ = std::make_unique<SymmetryCheck>(M, !symmetricByConstruction_);
  requireSymmetric(M);
  if (options_.preconditioner == "LDLT_DP") {
    auto mumps = std::make_unique<MumpsSolver>();
    MumpsOptions o;
    o.symmetry = "SYMGEN";
    o.pivotPercent = options_.pivotPercent;
    mumps->setOptions(o);
    preconditioner_ = std::move(mumps);
  } else {
    auto single = std::make_unique<MumpsSingleSolver>();
    single->setPivotPercent(options_.pivotPercent);
    preconditioner_ = std::move(single);
  }
  preconditioner_->setSingularityDigits(nprec_);
  preconditioner_->setSymmetricByConstruction(true);  // checked above
  preconditioner_->analyze(M);
  stats_.ordering = preconditioner_->statistics().ordering;
}

void GcpcSolver::factorize(const SparseMatrix& A) {
  SparseMatrix storage;
  const SparseMatrix& M = compressedMatrix(A, storage);
  pattern_.requireSame(M, name());
  requireSymmetric(M);
  factorized_ = false;
  matrix_ = M;
  preconditionerCurrent_ = false;
  // code_aster's rule: a new preconditioner first, and after a solve that needed more than REAC_PRECOND iterations.
  if (!preconditionerReady_ || lastIterations_ > options_.reacPrecond) refreshPreconditioner();
  factorized_ = true;
}

void GcpcSolver::refreshPreconditioner() const {
  preconditionerReady_ = false;
  preconditioner_->setSingularityDigits(nprec_);
  preconditioner_->factorize(matrix_);
  preconditionerReady_ = preconditionerCurrent_ = true;
  const LinearSolverStatistics& p = preconditioner_->statistics();
  stats_.factorizeCount = p.factorizeCount;
  stats_.factorizeSeconds = p.factorizeSeconds;
  stats_.numericSeconds = p.numericSeconds;
  stats_.firstNumericSeconds = p.firstNumericSeconds;
  stats_.factorFlops = p.factorFlops;
  stats_.factorNonzeros = p.factorNonzeros;
}

// Preconditioned conjugate gradient from x = 0. The recursive residual drifts from b - A x
// in floating point: at its convergence the true residual is measured, and the iteration
// starts again from it if that one is still too large.
GcpcSolver::Outcome GcpcSolver::conjugateGradient(const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                                  int maxIterations) const {
  Outcome out;
  const Eigen::Index n = b.size();
  x.setZero(n);
  const double bNorm = b.norm();
  if (bNorm == 0.0) {
    out.converged = true;
    return out;
  }
  const double target = options_.relativeResidual * bNorm;
  Eigen::VectorXd r = b, z, p, q;
  // The preconditioner works on r / ||r||: a single precision factorization keeps its range.
  auto precondition = [&](const Eigen::VectorXd& v, Eigen::VectorXd& result) {
    const double s = v.norm();
    preconditioner_->solve(v / s, result);
    result *= s;
  };
  while (out.iterations < maxIterations) {
    precondition(r, z);
    p = z;
    double rz = r.dot(z);
    double rNorm = r.norm();
    while (rNorm > target && out.iterations < maxIterations) {
      q = matrix_ * p;
      const double pq = p.dot(q);
      if (!(pq > 0.0) || !(rz > 0.0)) {
        std::ostringstream s;
        s << "GCPC: the matrix is not positive definite (p^T A p = " << pq << " at iteration " << out.iterations + 1
          << "); the conjugate gradient needs a symmetric positive definite matrix: use a direct solver "
             "(METHODE='MULT_FRONT' or 'MUMPS')";
        throw Error(s.str());
      }
      const double alpha = rz / pq;
      x += alpha * p;
      r -= alpha * q;
      ++out.iterations;
      rNorm = r.norm();
      if (rNorm <= target) break;
      precondition(r, z);
      const double rzNext = r.dot(z);
      p = z + (rzNext / rz) * p;
      rz = rzNext;
    }
    r = b - matrix_ * x;
    out.residual = r.norm() / bNorm;
    if (r.norm() <= target) {
      out.converged = true;
      return out;
    }
  }
  return out;
}

void GcpcSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  ScopedSeconds t(stats_.solveSeconds, stats_.solveCount);
  requireReadyToSolve(factorized_, b);
  const int n = static_cast<int>(b.size());
  const int maxIterations = options_.maxIterations > 0 ? options_.maxIterations : std::max(10, n / 2);
  Outcome out = conjugateGradient(b, x, maxIterations);
  stats_.krylovIterations += out.iterations;
  if (!out.converged && !preconditionerCurrent_) {
    // A second chance with the preconditioner of this very matrix.
    refreshPreconditioner();
    out = conjugateGradient(b, x, maxIterations);
    stats_.krylovIterations += out.iterations;
  }
  lastIterations_ = out.iterations;
  if (!out.converged) {
    std::ostringstream s;
    s.precision(3);
    s << "GCPC: the conjugate gradient did not reach RESI_RELA = " << options_.relativeResidual << " within NMAX_ITER = "
      << maxIterations << " iterations (relative residual " << out.residual << "), with PRE_COND='"
      << options_.preconditioner << "' factorized from this matrix itself; raise NMAX_ITER, use PRE_COND='LDLT_DP', "
      << "or a direct solver (METHODE='MULT_FRONT' or 'MUMPS')";
    throw Error(s.str());
  }
}

}  // namespace aster::linalg
