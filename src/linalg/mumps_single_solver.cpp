#include "linalg/mumps_single_solver.hpp"

#include <smumps_c.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include "linalg/mumps_instance.hpp"
#include "linalg/pivot_audit.hpp"
#include "linalg/stopwatch.hpp"

namespace aster::linalg {

namespace {

bool workspaceShort(int code) { return code == -8 || code == -9 || code == -17 || code == -20; }

std::string failure(const char* stage, int code, int info2) {
  std::ostringstream s;
  s << "MUMPS (single precision): " << stage << " failed: error " << code << ", INFO(2) = " << info2
    << " (see MUMPS's user's guide, \"Error diagnostics\")";
  return s.str();
}

}  // namespace

struct MumpsSingleSolver::Handle : MumpsInstance<SMUMPS_STRUC_C, smumps_c> {};

MumpsSingleSolver::MumpsSingleSolver() : h_(std::make_unique<Handle>()) {}

MumpsSingleSolver::~MumpsSingleSolver() = default;

void MumpsSingleSolver::setPivotPercent(int percent) {
  if (percent < 1) throw Error("MUMPS (single precision): PCENT_PIVOT must be at least 1");
  pivotPercent_ = percent;
}

void MumpsSingleSolver::analyze(const SparseMatrix& A) {
  ScopedSeconds t(stats_.analyzeSeconds, stats_.analyzeCount);
  requireSquare(A, name());
  SparseMatrix storage;
  const SparseMatrix& M = compressedMatrix(A, storage);
  factorized_ = false;
  pattern_.record(M);
  Handle& h = *h_;
  h.start(2);  // general symmetric
  if (h.infog(1) < 0) throw Error(failure("initialisation", h.infog(1), h.infog(2)));
  // Quiet; assembled, centralized matrix; dense centralized right-hand side and solution.
  h.icntl(1) = -1;
  h.icntl(2) = -1;
  h.icntl(3) = -1;
  h.icntl(4) = 0;
  h.icntl(5) = 0;
  h.icntl(18) = 0;
  h.icntl(20) = 0;
  h.icntl(21) = 0;
  h.icntl(7) = 7;   // MUMPS's choice of ordering
  h.icntl(6) = 7;   // automatic permutation and scaling
  h.icntl(8) = 77;
  loadValues(M);
  h.id.n = pattern_.size();
  h.id.nnz = static_cast<MUMPS_INT8>(irn_.size());
  h.id.irn = irn_.data();
  h.id.jcn = jcn_.data();
  h.id.a = values_.data();
  h.run(1);
  if (h.infog(1) < 0) throw Error(failure("analysis", h.infog(1), h.infog(2)));
  stats_.ordering = mumpsOrderingName(h.infog(7));
}

void MumpsSingleSolver::loadValues(const SparseMatrix& M) {
  if (entries_.empty()) {
    for (int j = 0; j < M.cols(); ++j)
      for (int k = M.outerIndexPtr()[j]; k < M.outerIndexPtr()[j + 1]; ++k) {
        const int i = M.innerIndexPtr()[k];
        if (i < j) continue;
        irn_.push_back(i + 1);
        jcn_.push_back(j + 1);
        entries_.push_back(k);
      }
    values_.resize(entries_.size());
  }
  for (size_t e = 0; e < entries_.size(); ++e) values_[e] = static_cast<float>(M.valuePtr()[entries_[e]]);
}

void MumpsSingleSolver::factorize(const SparseMatrix& A) {
  ScopedSeconds t(stats_.factorizeSeconds, stats_.factorizeCount);
  SparseMatrix storage;
  const SparseMatrix& M = compressedMatrix(A, storage);
  pattern_.requireSame(M, name());
  factorized_ = false;
  loadValues(M);
  Handle& h = *h_;
  h.id.a = values_.data();
  h.icntl(14) = pivotPercent_;
  // Null pivots: a pivot row below 10^-NPREC times the scaled matrix's norm (NPREC <= 0: only zero rows).
  h.icntl(24) = 1;
  h.id.cntl[2] = nprec_ > 0 ? static_cast<float>(std::pow(10.0, -nprec_)) : -std::numeric_limits<float>::min();
  const auto start = std::chrono::steady_clock::now();
  h.run(2);
  if (workspaceShort(h.infog(1))) {  // once more with twice the margin
    h.icntl(14) = 2 * pivotPercent_;
    h.run(2);
  }
  const double numeric = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (stats_.numericSeconds == 0.0) stats_.firstNumericSeconds = numeric;
  stats_.numericSeconds += numeric;
  const int code = h.infog(1);
  if (code == -6 || code == -10) throwZeroPivot(name(), -1, -1, " (MUMPS error " + std::to_string(code) + ")");
  if (code < 0) throw Error(failure("factorization", code, h.infog(2)));
  if (h.infog(28) > 0) {
    const int column = h.id.pivnul_list ? h.id.pivnul_list[0] - 1 : -1;
    std::ostringstream s;
    s << name() << ": the matrix is " << (nprec_ > 0 ? "numerically singular" : "singular") << ": " << h.infog(28)
      << " null pivot(s), the first in column " << column << " (NPREC = " << nprec_
      << "); the structure may be free to move (missing Dirichlet conditions?)";
    throw SingularMatrixError(s.str(), column, column);
  }
  stats_.factorFlops = h.rinfog(3);
  const int entries = h.infog(29);  // negative: millions
  stats_.factorNonzeros = entries >= 0 ? entries : -static_cast<long long>(entries) * 1000000;
  factorized_ = true;
}

void MumpsSingleSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  ScopedSeconds t(stats_.solveSeconds, stats_.solveCount);
  requireReadyToSolve(factorized_, b);
  rhs_.resize(static_cast<size_t>(b.size()));
  for (Eigen::Index i = 0; i < b.size(); ++i) rhs_[static_cast<size_t>(i)] = static_cast<float>(b[i]);
  Handle& h = *h_;
  h.id.rhs = rhs_.data();
  h.id.nrhs = 1;
  h.id.lrhs = static_cast<int>(b.size());
  h.run(3);
  if (h.infog(1) < 0) throw Error(failure("solve", h.infog(1), h.infog(2)));
  x.resize(b.size());
  for (Eigen::Index i = 0; i < b.size(); ++i) x[i] = rhs_[static_cast<size_t>(i)];
}

}  // namespace aster::linalg
