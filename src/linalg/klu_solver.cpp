#include "linalg/klu_solver.hpp"

#include <klu.h>

#include "linalg/pivot_audit.hpp"
#include "linalg/stopwatch.hpp"

namespace aster::linalg {

struct KluSolver::Handles {
  klu_common common;
  klu_symbolic* symbolic = nullptr;
  klu_numeric* numeric = nullptr;
};

namespace {

std::string kluStatus(int status) {
  switch (status) {
    case KLU_OUT_OF_MEMORY: return "out of memory";
    case KLU_INVALID: return "invalid input (row indices must be sorted, without duplicates)";
    case KLU_TOO_LARGE: return "integer overflow: the matrix is too large";
    case KLU_SINGULAR: return "singular matrix";
    default: return "status " + std::to_string(status);
  }
}

}  // namespace

KluSolver::KluSolver() : h_(std::make_unique<Handles>()) {
  klu_defaults(&h_->common);
  h_->common.halt_if_singular = 1;
}

KluSolver::~KluSolver() {
  freeNumeric();
  freeSymbolic();
}

void KluSolver::freeNumeric() {
  if (h_->numeric) klu_free_numeric(&h_->numeric, &h_->common);
  h_->numeric = nullptr;
}

void KluSolver::freeSymbolic() {
  if (h_->symbolic) klu_free_symbolic(&h_->symbolic, &h_->common);
  h_->symbolic = nullptr;
}

void KluSolver::analyze(const SparseMatrix& A) {
  ScopedSeconds t(stats_.analyzeSeconds, stats_.analyzeCount);
  requireSquare(A, name());
  SparseMatrix storage;
  const SparseMatrix& M = compressedMatrix(A, storage);
  freeNumeric();
  freeSymbolic();
  pattern_.record(M);
  // RENUM: AMD (KLU's default) or COLAMD after the block triangular form; SANS: neither.
  h_->common.ordering = ordering_ == "COLAMD" ? 1 : 0;
  h_->common.btf = ordering_ == "SANS" ? 0 : 1;
  if (ordering_ == "SANS")
    h_->symbolic = klu_analyze_given(static_cast<int>(M.rows()), const_cast<int*>(M.outerIndexPtr()),
                                     const_cast<int*>(M.innerIndexPtr()), nullptr, nullptr, &h_->common);
  else
    h_->symbolic = klu_analyze(static_cast<int>(M.rows()), const_cast<int*>(M.outerIndexPtr()),
                               const_cast<int*>(M.innerIndexPtr()), &h_->common);
  if (!h_->symbolic) throw Error("KLU: symbolic analysis failed: " + kluStatus(h_->common.status));
  stats_.ordering = h_->symbolic->ordering == 0 ? "AMD" : h_->symbolic->ordering == 1 ? "COLAMD" : "natural";
}

void KluSolver::factorize(const SparseMatrix& A) {
  ScopedSeconds t(stats_.factorizeSeconds, stats_.factorizeCount);
  SparseMatrix storage;
  const SparseMatrix& M = compressedMatrix(A, storage);
  pattern_.requireSame(M, name());
  freeNumeric();
  h_->numeric = klu_factor(const_cast<int*>(M.outerIndexPtr()), const_cast<int*>(M.innerIndexPtr()),
                           const_cast<double*>(M.valuePtr()), h_->symbolic, &h_->common);
  if (!h_->numeric) {
    if (h_->common.status == KLU_SINGULAR) {
      const int col = h_->common.singular_col;
      throwZeroPivot(name(), col >= 0 && col < pattern_.size() ? col : -1, -1);
    }
    throw Error("KLU: numeric factorization failed: " + kluStatus(h_->common.status));
  }
  klu_flops(h_->symbolic, h_->numeric, &h_->common);
  stats_.factorFlops = h_->common.flops;
  stats_.factorNonzeros =
      static_cast<long long>(h_->numeric->lnz) + h_->numeric->unz + h_->numeric->nzoff - pattern_.size();
  try {
    auditFactor(M);
  } catch (...) {
    freeNumeric();
    throw;
  }
}

// KLU factors P (R\A) Q = L U + off-diagonal blocks, R the row scaling; after the
// factorization KLU holds the scale factors in pivot order (Rs[k] is row Pnum[k]'s).
void KluSolver::auditFactor(const SparseMatrix& A) const {
  const int* P = h_->numeric->Pnum;
  const int* Q = h_->symbolic->Q;
  const double* udiag = static_cast<const double*>(h_->numeric->Udiag);
  const double* rs = h_->numeric->Rs;
  auditPivots(name(), pattern_.size(), nprec_, [&](int k) {
    const int row = P[k], col = Q[k];
    const double a = entryOf(A, row, col);
    return Pivot{udiag[k], rs ? a / rs[k] : a, row, col};
  });
}

void KluSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  ScopedSeconds t(stats_.solveSeconds, stats_.solveCount);
  requireReadyToSolve(h_->numeric != nullptr, b);
  x = b;
  if (!klu_solve(h_->symbolic, h_->numeric, static_cast<int>(x.size()), 1, x.data(), &h_->common))
    throw Error("KLU: solve failed: " + kluStatus(h_->common.status));
}

}  // namespace aster::linalg
