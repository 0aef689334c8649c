#include "linalg/umfpack_solver.hpp"

#include <umfpack.h>

#include <vector>

#include "linalg/pivot_audit.hpp"
#include "linalg/stopwatch.hpp"

namespace aster::linalg {

static_assert(UMFPACK_CONTROL == 20 && UMFPACK_INFO == 90, "UmfpackSolver's arrays follow umfpack.h");

namespace {

std::string umfpackStatus(int status) {
  switch (status) {
    case UMFPACK_ERROR_out_of_memory: return "out of memory";
    case UMFPACK_ERROR_invalid_matrix: return "invalid matrix (row indices must be sorted, without duplicates)";
    case UMFPACK_ERROR_different_pattern: return "the pattern changed since the symbolic analysis";
    case UMFPACK_ERROR_invalid_Symbolic_object: return "no valid symbolic analysis";
    case UMFPACK_ERROR_invalid_Numeric_object: return "no valid numeric factorization";
    case UMFPACK_ERROR_ordering_failed: return "the fill-reducing ordering failed";
    case UMFPACK_ERROR_internal_error: return "internal error";
    default: return "status " + std::to_string(status);
  }
}

void requireOk(int status, const char* step) {
  if (status == UMFPACK_OK) return;
  throw Error(std::string("UMFPACK: ") + step + " failed: " + umfpackStatus(status));
}

}  // namespace

UmfpackSolver::UmfpackSolver() {
  umfpack_di_defaults(control_);
  for (double& v : info_) v = 0.0;
}

UmfpackSolver::~UmfpackSolver() {
  freeNumeric();
  freeSymbolic();
}

void UmfpackSolver::freeNumeric() {
  if (numeric_) umfpack_di_free_numeric(&numeric_);
  numeric_ = nullptr;
}

void UmfpackSolver::freeSymbolic() {
  if (symbolic_) umfpack_di_free_symbolic(&symbolic_);
  symbolic_ = nullptr;
}

void UmfpackSolver::analyze(const SparseMatrix& A) {
  ScopedSeconds t(stats_.analyzeSeconds, stats_.analyzeCount);
  requireSquare(A, name());
  SparseMatrix storage;
  const SparseMatrix& M = compressedMatrix(A, storage);
  freeNumeric();
  freeSymbolic();
  pattern_.record(M);
  const int n = static_cast<int>(M.rows());
  // RENUM: AMD and COLAMD are UMFPACK's orderings of its symmetric and unsymmetric strategies.
  umfpack_di_defaults(control_);
  if (ordering_ == "AMD") {
    control_[UMFPACK_STRATEGY] = UMFPACK_STRATEGY_SYMMETRIC;
    control_[UMFPACK_ORDERING] = UMFPACK_ORDERING_AMD;
  } else if (ordering_ == "COLAMD") {
    control_[UMFPACK_STRATEGY] = UMFPACK_STRATEGY_UNSYMMETRIC;
    control_[UMFPACK_ORDERING] = UMFPACK_ORDERING_AMD;
  } else if (ordering_ == "METIS") {
    control_[UMFPACK_ORDERING] = UMFPACK_ORDERING_METIS;
  } else if (ordering_ == "SANS") {
    control_[UMFPACK_ORDERING] = UMFPACK_ORDERING_NONE;
  }
  const int status = umfpack_di_symbolic(n, n, M.outerIndexPtr(), M.innerIndexPtr(), M.valuePtr(), &symbolic_,
                                         control_, info_);
  if (status != UMFPACK_OK) symbolic_ = nullptr;
  requireOk(status, "symbolic analysis");
  const bool symmetric = info_[UMFPACK_STRATEGY_USED] == UMFPACK_STRATEGY_SYMMETRIC;
  switch (static_cast<int>(info_[UMFPACK_ORDERING_USED])) {
    case UMFPACK_ORDERING_AMD: stats_.ordering = symmetric ? "AMD" : "COLAMD"; break;
    case UMFPACK_ORDERING_METIS: stats_.ordering = "METIS"; break;
    case UMFPACK_ORDERING_NONE: stats_.ordering = "natural"; break;
    default: stats_.ordering = "other"; break;
  }
}

void UmfpackSolver::factorize(const SparseMatrix& A) {
  ScopedSeconds t(stats_.factorizeSeconds, stats_.factorizeCount);
  SparseMatrix storage;
  const SparseMatrix& M = compressedMatrix(A, storage);
  pattern_.requireSame(M, name());
  freeNumeric();
  matrix_ = M;
  const int status = umfpack_di_numeric(matrix_.outerIndexPtr(), matrix_.innerIndexPtr(), matrix_.valuePtr(),
                                        symbolic_, &numeric_, control_, info_);
  if (status != UMFPACK_OK && status != UMFPACK_WARNING_singular_matrix) {
    freeNumeric();
    requireOk(status, "numeric factorization");
  }
  stats_.factorFlops = info_[UMFPACK_FLOPS];
  const int n = pattern_.size();
  stats_.factorNonzeros = static_cast<long long>(info_[UMFPACK_LNZ] + info_[UMFPACK_UNZ]) - n;
  try {
    auditFactor();
  } catch (...) {
    freeNumeric();
    throw;
  }
}

// UMFPACK factors P R A Q = L U, R the row scaling: U's diagonal is compared with the scaled entry.
void UmfpackSolver::auditFactor() const {
  const int n = pattern_.size();
  std::vector<int> P(n), Q(n);
  std::vector<double> udiag(n), rs(n);
  int doRecip = 0;
  const int status = umfpack_di_get_numeric(nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, P.data(), Q.data(),
                                            udiag.data(), &doRecip, rs.data(), numeric_);
  requireOk(status, "reading the factors");
  auditPivots(name(), n, nprec_, [&](int k) {
    const int row = P[k], col = Q[k];
    const double a = entryOf(matrix_, row, col);
    const double scaled = doRecip ? a * rs[row] : a / rs[row];
    return Pivot{udiag[k], scaled, row, col};
  });
}

void UmfpackSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  ScopedSeconds t(stats_.solveSeconds, stats_.solveCount);
  requireReadyToSolve(numeric_ != nullptr, b);
  x.resize(b.size());
  const int status = umfpack_di_solve(UMFPACK_A, matrix_.outerIndexPtr(), matrix_.innerIndexPtr(),
                                      matrix_.valuePtr(), x.data(), b.data(), numeric_, control_, info_);
  requireOk(status, "solve");
}

}  // namespace aster::linalg
