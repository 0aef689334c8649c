#include "linalg/multifrontal_cholesky.hpp"

#include <algorithm>
#include <atomic>
#include <climits>
#include <cstdint>
#include <functional>
#include <cmath>
#include <memory>
#include <new>
#include <numeric>

#include "core/worker_pool.hpp"
#include "linalg/blas_info.hpp"
#include "linalg/dense_front.hpp"

extern "C" {
void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info);
void dtrsm_(const char* side, const char* uplo, const char* transa, const char* diag, const int* m, const int* n,
            const double* alpha, const double* a, const int* lda, double* b, const int* ldb);
void dgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k, const double* alpha,
            const double* a, const int* lda, const double* b, const int* ldb, const double* beta, double* c,
            const int* ldc);
void dsyrk_(const char* uplo, const char* trans, const int* n, const int* k, const double* alpha, const double* a,
            const int* lda, const double* beta, double* c, const int* ldc);
void dtrsv_(const char* uplo, const char* trans, const char* diag, const int* n, const double* a, const int* lda,
            double* x, const int* incx);
void dgemv_(const char* trans, const int* m, const int* n, const double* alpha, const double* a, const int* lda,
            const double* x, const int* incx, const double* beta, double* y, const int* incy);
}

namespace aster::linalg {

namespace {

// A child's update matrix (u x u, lower triangle) is added into its parent's front in two
// parts: the columns that fall on the parent's own columns go into its block of L (m x width)
// before the parent is factorized; the others go into the parent's update matrix after the
// parent's dsyrk has written it. relative[i]: position of the child's update row i among the
// parent's rows (ascending), so the first part is the columns j < split.
int blockColumns(const int* relative, int u, int width) {
  return static_cast<int>(std::lower_bound(relative, relative + u, width) - relative);
}

void addIntoBlock(const double* update, int u, const int* relative, int split, double* block, int m) {
  for (int j = 0; j < split; ++j) {
    const double* column = update + static_cast<size_t>(j) * u;
    double* destination = block + static_cast<size_t>(relative[j]) * m;
    for (int i = j; i < u; ++i) destination[relative[i]] += column[i];
  }
}

void addIntoUpdate(const double* update, int u, const int* relative, int split, int width, double* parentUpdate,
                   int parentU) {
  for (int j = split; j < u; ++j) {
    const double* column = update + static_cast<size_t>(j) * u;
    double* destination = parentUpdate + static_cast<size_t>(relative[j] - width) * parentU;
    for (int i = j; i < u; ++i) destination[relative[i] - width] += column[i];
  }
}

// Dense kernels of the large fronts in `parts` independent pieces (one-thread BLAS each),
// which the pool's threads claim as they come free, rather than left to a multithreaded
// BLAS, whose idle threads spin for a while after each call and slow down whatever runs
// next. The pieces depend on `parts` alone, so a front's numbers do not depend on which
// threads ran them.
void inParallel(int parts, const std::function<void(int)>& piece) {
  WorkerPool::shared().forEach(parts, piece, blasCallersThatFit(parts));
}

// First row of the p-th of `parts` equal slices of [0, rows).
int slice(int rows, int parts, int p) { return static_cast<int>(static_cast<long long>(rows) * p / parts); }

// B (rows x n, ld ldb) := B L^-T, L lower n x n: slices of rows.
void parallelTrsm(int parts, int rows, int n, const double* L, int ldl, double* B, int ldb) {
  const double one = 1.0;
  inParallel(parts, [&](int p) {
    const int r0 = slice(rows, parts, p), r = slice(rows, parts, p + 1) - r0;
    if (r > 0) dtrsm_("R", "L", "T", "N", &r, &n, &one, L, &ldl, B + r0, &ldb);
  });
}

// Lower triangle of C (n x n) := beta C - A A^T (A n x k): slices of columns of equal work,
// each a dsyrk on its diagonal block and a dgemm below it.
void parallelSyrk(int parts, int n, int k, const double* A, int lda, double beta, double* C, int ldc) {
  std::vector<int> first(parts + 1, n);
  first[0] = 0;
  const double total = 0.5 * n * (n + 1.0);
  double work = 0;
  for (int j = 0, p = 1; j < n && p < parts; ++j) {
    work += n - j;
    if (work >= total * p / parts) first[p++] = j + 1;
  }
  const double minusOne = -1.0;
  inParallel(parts, [&](int p) {
    const int c0 = first[p], c = first[p + 1] - c0, below = n - c0 - c;
    if (c <= 0) return;
    double* diagonal = C + c0 + static_cast<size_t>(c0) * ldc;
    dsyrk_("L", "N", &c, &k, &minusOne, A + c0, &lda, &beta, diagonal, &ldc);
    if (below > 0)
      dgemm_("N", "T", &below, &c, &k, &minusOne, A + c0 + c, &lda, A + c0, &lda, &beta, diagonal + c, &ldc);
  });
}

// C (rows x n) -= A B^T (A rows x k, B n x k): slices of rows.
void parallelGemm(int parts, int rows, int n, int k, const double* A, int lda, const double* B, int ldb, double* C,
                  int ldc) {
  const double one = 1.0, minusOne = -1.0;
  inParallel(parts, [&](int p) {
    const int r0 = slice(rows, parts, p), r = slice(rows, parts, p + 1) - r0;
    if (r > 0) dgemm_("N", "T", &r, &n, &k, &minusOne, A + r0, &lda, B, &ldb, &one, C + r0, &ldc);
  });
}

// The columns of a front (block: m x width, ld m) factorized right-looking, panel by panel:
// each panel's dpotrf, then the rows below it (dtrsm) and the columns right of it (dsyrk,
// dgemm) in slices. Returns LAPACK's info (0, or the 1-based column of a non-positive pivot).
int parallelFrontCholesky(int parts, int width, int m, double* block) {
  constexpr int kPanel = 192;
  for (int p = 0; p < width; p += kPanel) {
    const int b = std::min(kPanel, width - p);
    double* panel = block + p + static_cast<size_t>(p) * m;
    int info = 0;
    dpotrf_("L", &b, panel, &m, &info);
    if (info != 0) return p + info;
    const int below = m - p - b, right = width - p - b;
    if (below > 0) parallelTrsm(parts, below, b, panel, m, panel + b, m);
    if (right > 0) {
      double* trailing = panel + b + static_cast<size_t>(b) * m;
      parallelSyrk(parts, right, b, panel + b, m, 1.0, trailing, m);
      parallelGemm(parts, below - right, right, b, panel + b + right, m, panel + b, m, trailing + right, m);
    }
  }
  return 0;
}

// Per-thread workspace of the dense front kernels for fronts of `rows` rows (none for the BLAS).
double* frontWorkspaceFor(FrontKernels kernels, int rows) {
  if (kernels == FrontKernels::Blas) return nullptr;
  thread_local std::vector<double> workspace;
  const size_t size = frontWorkspace(rows);
  if (workspace.size() < size) workspace.resize(size);
  return workspace.data();
}

// Boundaries of `parts` slices of the columns [0, n) of a lower trapezoid of `rows` rows
// (column j holds rows - j entries) that hold about the same number of entries.
std::vector<int> balancedColumns(int parts, int rows, int n) {
  std::vector<int> first(parts + 1, n);
  first[0] = 0;
  const double total = n * (rows - 0.5 * (n - 1.0));
  double work = 0;
  for (int j = 0, p = 1; j < n && p < parts; ++j) {
    work += rows - j;
    if (work >= total * p / parts) first[p++] = j + 1;
  }
  return first;
}

// The front factorized by the dense front kernels in `parts` pieces the pool's threads
// claim, panel by panel: its diagonal block on one thread, then the rows below it in
// slices, then its products with the front's next columns in slices of those columns.
int parallelFrontKernels(int parts, int width, int m, double* block, FrontKernels kernels) {
  for (int p0 = 0; p0 < width; p0 += kFrontPanel) {
    const int b = std::min(kFrontPanel, width - p0);
    double* panel = block + p0 + static_cast<size_t>(p0) * m;
    const int info = factorDiagonalBlock(b, m, panel, kernels);
    if (info != 0) return p0 + info;
    const int below = m - p0 - b, trailing = width - p0 - b;
    if (below > 0)
      inParallel(parts, [&](int p) {
        const int r0 = slice(below, parts, p), r = slice(below, parts, p + 1) - r0;
        if (r > 0) solveRowsBelow(b, m, panel, r, panel + b + r0, kernels);
      });
    if (trailing > 0) {
      const std::vector<int> first = balancedColumns(parts, below, trailing);
      inParallel(parts, [&](int p) {
        if (first[p] < first[p + 1])
          subtractLowerProducts(below, first[p], first[p + 1], b, panel + b, m, panel + b + static_cast<size_t>(b) * m,
                                m, frontWorkspaceFor(kernels, below - first[p]), false, kernels);
      });
    }
  }
  return 0;
}

// U := -L21 L21^T (u x u) by the dense front kernels in `parts` slices of its columns.
void parallelUpdateKernels(int parts, int u, int width, const double* L21, int ld, double* U, FrontKernels kernels) {
  const std::vector<int> first = balancedColumns(parts, u, u);
  inParallel(parts, [&](int p) {
    if (first[p] < first[p + 1])
      subtractLowerProducts(u, first[p], first[p + 1], width, L21, ld, U, u, frontWorkspaceFor(kernels, u - first[p]),
                            true, kernels);
  });
}

// A front of signed columns: its `width` pivot columns of the m x width block are
// factorized in place, L(k,k) = sqrt|d| and sign[k] = sign d for each pivot d, the rows
// below included (they become L's). The diagonal block by panels of kSignedPanel columns:
// each panel column by column, then the columns after it at once, C -= L_p S_p L_p^T, as
// two dsyrk (the panel's + columns, then its - ones), so that the wide fronts at the top
// of the tree (a contact surface's multipliers cross its separators) run at BLAS-3 speed;
// the rows below by dtrsm: A21 = L21 S L11^T. Returns 0, or the 1-based column of a zero
// or non-finite pivot.
constexpr int kSignedPanel = 48;
int signedFrontFactor(int width, int m, double* block, double* sign) {
  std::vector<double> positive, negative;
  for (int j0 = 0; j0 < width; j0 += kSignedPanel) {
    const int jb = std::min(kSignedPanel, width - j0), end = j0 + jb;
    for (int j = j0; j < end; ++j) {
      double* col = block + static_cast<size_t>(j) * m;
      const double d = col[j];
      if (d == 0.0 || !std::isfinite(d)) return j + 1;
      const double l = std::sqrt(std::abs(d));
      sign[j] = d > 0 ? 1.0 : -1.0;
      col[j] = l;
      const double scale = 1.0 / (sign[j] * l);  // L(i,j) = a(i,j) / (S(j,j) L(j,j))
      for (int i = j + 1; i < width; ++i) col[i] *= scale;
      for (int k = j + 1; k < end; ++k) {
        double* target = block + static_cast<size_t>(k) * m;
        const double f = sign[j] * col[k];
        if (f != 0.0)
          for (int i = k; i < width; ++i) target[i] -= col[i] * f;
      }
    }
    const int r = width - end;
    if (r <= 0) continue;
    // The panel's rows below it, split by sign: C -= L+ L+^T - L- L-^T.
    int np = 0, nq = 0;
    positive.resize(static_cast<size_t>(r) * jb);
    negative.resize(static_cast<size_t>(r) * jb);
    for (int j = j0; j < end; ++j) {
      const double* col = block + static_cast<size_t>(j) * m + end;
      double* to = sign[j] > 0 ? positive.data() + static_cast<size_t>(np++) * r
                               : negative.data() + static_cast<size_t>(nq++) * r;
      std::copy(col, col + r, to);
    }
    double* trailing = block + end + static_cast<size_t>(end) * m;
    const double minusOne = -1.0, plusOne = 1.0;
    if (np > 0) dsyrk_("L", "N", &r, &np, &minusOne, positive.data(), &r, &plusOne, trailing, &m);
    if (nq > 0) dsyrk_("L", "N", &r, &nq, &plusOne, negative.data(), &r, &plusOne, trailing, &m);
  }
  const int u = m - width;
  if (u > 0) {
    const double one = 1.0;
    dtrsm_("R", "L", "T", "N", &u, &width, &one, block, &m, block + width, &m);  // L21 S
    for (int k = 0; k < width; ++k)
      if (sign[k] < 0) {
        double* column = block + static_cast<size_t>(k) * m;
        for (int i = width; i < m; ++i) column[i] = -column[i];
      }
  }
  return 0;
}

// The update matrix of a signed front, -L21 S L21^T (u x u, written whole): a dgemm with
// the columns of L21 signed.
void signedUpdate(int u, int width, const double* L21, int ld, const double* sign, double* update) {
  std::vector<double> signedL21(static_cast<size_t>(u) * width);
  for (int k = 0; k < width; ++k)
    for (int i = 0; i < u; ++i)
      signedL21[i + static_cast<size_t>(k) * u] = sign[k] * L21[i + static_cast<size_t>(k) * ld];
  const double minusOne = -1.0, zero = 0.0;
  dgemm_("N", "T", &u, &u, &width, &minusOne, signedL21.data(), &u, L21, &ld, &zero, update, &u);
}

}  // namespace

MultifrontalCholesky::MultifrontalCholesky(const SupernodalStructure& structure, const SparseMatrix& A,
                                           int threads, double parallelFlops, const std::vector<char>& indefinite)
    : structure_(structure) {
  const SupernodalStructure& S = structure_;
  const int n = S.n, ns = S.supernodeCount;
  if (A.rows() != n || A.cols() != n || !A.isCompressed())
    throw Error("multifrontal Cholesky: the matrix does not match the symbolic factorization");

  std::vector<int> owner(n);
  for (int s = 0; s < ns; ++s)
    for (int k = S.firstColumn[s]; k < S.firstColumn[s + 1]; ++k) owner[k] = s;
  parent_.assign(ns, -1);
  childStart_.assign(ns + 1, 0);
  flops_.resize(ns);
  for (int s = 0; s < ns; ++s) {
    const int width = S.firstColumn[s + 1] - S.firstColumn[s];
    const int m = S.rowStart[s + 1] - S.rowStart[s];
    if (m > width) {
      parent_[s] = owner[S.rows[S.rowStart[s] + width]];
      ++childStart_[parent_[s] + 1];
    }
    const double w = width, u = m - width;
    flops_[s] = w * w * w / 3 + u * w * w + u * u * w + u * u;  // dpotrf, dtrsm, dsyrk, extend-add
  }
  totalFlops_ = std::accumulate(flops_.begin(), flops_.end(), 0.0);
  signedFront_.assign(ns, 0);
  if (!indefinite.empty()) {
    if (static_cast<int>(indefinite.size()) != n) throw Error("multifrontal Cholesky: one flag per column expected");
    for (int k = 0; k < n; ++k)
      if (indefinite[k]) signedFront_[owner[k]] = 1;
  }
  std::partial_sum(childStart_.begin(), childStart_.end(), childStart_.begin());
  children_.resize(childStart_[ns]);
  {
    std::vector<int> next(childStart_.begin(), childStart_.end() - 1);
    for (int s = 0; s < ns; ++s)  // ascending: each front adds its children in a fixed order
      if (parent_[s] >= 0) children_[next[parent_[s]]++] = s;
  }

  // Positions of each child's update rows among its parent's rows.
  std::vector<int> position(n, -1);
  relativeStart_.assign(ns + 1, 0);
  for (int s = 0; s < ns; ++s) {
    const int width = S.firstColumn[s + 1] - S.firstColumn[s];
    relativeStart_[s + 1] = relativeStart_[s] + (S.rowStart[s + 1] - S.rowStart[s] - width);
  }
  relative_.resize(relativeStart_[ns]);
  for (int p = 0; p < ns; ++p) {
    for (int i = S.rowStart[p]; i < S.rowStart[p + 1]; ++i) position[S.rows[i]] = i - S.rowStart[p];
    for (int e = childStart_[p]; e < childStart_[p + 1]; ++e) {
      const int c = children_[e];
      const int width = S.firstColumn[c + 1] - S.firstColumn[c];
      long long out = relativeStart_[c];
      for (int i = S.rowStart[c] + width; i < S.rowStart[c + 1]; ++i) {
        const int at = position[S.rows[i]];
        if (at < 0) throw Error("multifrontal Cholesky: a row of a supernode is missing from its parent");
        relative_[out++] = at;
      }
    }
    for (int i = S.rowStart[p]; i < S.rowStart[p + 1]; ++i) position[S.rows[i]] = -1;
  }

  // Where each entry of the lower triangle of P A P^T goes in L's storage.
  std::vector<int> inverse(n);
  for (int k = 0; k < n; ++k) inverse[S.permutation ? S.permutation[k] : k] = k;
  entryStart_.assign(ns + 1, 0);
  entryInFactor_.assign((static_cast<size_t>(A.nonZeros()) + 63) / 64, 0);
  entryTarget_.clear();
  entryTarget_.reserve(A.nonZeros() / 2 + n);
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  for (int s = 0; s < ns; ++s) {
    const int k1 = S.firstColumn[s], m = S.rowStart[s + 1] - S.rowStart[s];
    for (int i = S.rowStart[s]; i < S.rowStart[s + 1]; ++i) position[S.rows[i]] = i - S.rowStart[s];
    for (int k = k1; k < S.firstColumn[s + 1]; ++k) {
      const int j = S.permutation ? S.permutation[k] : k;
      for (int p = outer[j]; p < outer[j + 1]; ++p) {
        const int r = inverse[inner[p]];
        if (r < k) continue;
        if (position[r] < 0) throw Error("multifrontal Cholesky: an entry of the matrix is outside the factor's pattern");
        entryInFactor_[static_cast<size_t>(p) / 64] |= std::uint64_t{1} << (p % 64);
        entryTarget_.push_back(position[r] + (k - k1) * m);
      }
    }
    for (int i = S.rowStart[s]; i < S.rowStart[s + 1]; ++i) position[S.rows[i]] = -1;
    entryStart_[s + 1] = static_cast<long long>(entryTarget_.size());
  }
  schedule(threads, parallelFlops);
}

// Plans the parallel run: the supernodes in a postorder (each subtree a contiguous run of
// it), and the flops of each subtree, which decide where the tree stops being split.
void MultifrontalCholesky::schedule(int threads, double parallelFlops) {
  const int ns = structure_.supernodeCount;
  threads_ = threads >= 2 && totalFlops_ >= parallelFlops ? threads : 1;
  subtreeFlops_ = flops_;
  for (int s = 0; s < ns; ++s)
    if (parent_[s] >= 0) subtreeFlops_[parent_[s]] += subtreeFlops_[s];
  roots_.clear();
  for (int s = 0; s < ns; ++s)
    if (parent_[s] < 0) roots_.push_back(s);
  postorder_.clear();
  postorder_.reserve(ns);
  subtreeStart_.assign(ns, 0);
  position_.assign(ns, 0);
  std::vector<std::pair<int, int>> stack;  // (supernode, next child to visit)
  for (int root : roots_) {
    stack.push_back({root, childStart_[root]});
    subtreeStart_[root] = static_cast<int>(postorder_.size());
    while (!stack.empty()) {
      auto& [s, e] = stack.back();
      if (e < childStart_[s + 1]) {
        const int c = children_[e++];
        subtreeStart_[c] = static_cast<int>(postorder_.size());
        stack.push_back({c, childStart_[c]});
      } else {
        position_[s] = static_cast<int>(postorder_.size());
        postorder_.push_back(s);
        stack.pop_back();
      }
    }
  }
  // Subtrees below this many flops run whole on one thread: enough pieces for the threads
  // to share them out as they go, few enough that claiming them costs nothing.
  splitFlops_ = std::max(1e6, totalFlops_ / (16.0 * threads_));
}

int MultifrontalCholesky::factorizeSupernode(int s, const SparseMatrix& A, double* values, double* pivots,
                                             Updates& updates, int parts) const {
  const SupernodalStructure& S = structure_;
  const int k1 = S.firstColumn[s];
  const int width = S.firstColumn[s + 1] - k1;
  const int m = S.rowStart[s + 1] - S.rowStart[s];
  const int u = m - width;
  double* block = values + S.valueStart[s];
  std::fill(block, block + static_cast<size_t>(m) * width, 0.0);
  {  // A's entries in the front: those of its columns flagged at the plan, in their order
    const double* a = A.valuePtr();
    const int* outer = A.outerIndexPtr();
    long long e = entryStart_[s];
    for (int k = k1; k < k1 + width; ++k) {
      const int j = S.permutation ? S.permutation[k] : k;
      for (int p = outer[j]; p < outer[j + 1]; ++p)
        if (entryInFactor_[static_cast<size_t>(p) / 64] >> (p % 64) & 1u) block[entryTarget_[e++]] = a[p];
    }
  }
  auto childUpdate = [&](int e, int& cu, const int*& relative) {
    const int c = children_[e];
    cu = static_cast<int>(relativeStart_[c + 1] - relativeStart_[c]);
    relative = relative_.data() + relativeStart_[c];
    return updates[c].get();
  };
  for (int e = childStart_[s]; e < childStart_[s + 1]; ++e) {
    int cu = 0;
    const int* relative = nullptr;
    const double* update = childUpdate(e, cu, relative);
    addIntoBlock(update, cu, relative, blockColumns(relative, cu, width), block, m);
  }
  int info = 0;
  std::vector<double> sign(signedFront_[s] ? width : 0);
  if (signedFront_[s]) {
    info = signedFrontFactor(width, m, block, sign.data());
  } else if (parts > 1) {  // the rows below too
    info = kernels_ != FrontKernels::Blas ? parallelFrontKernels(parts, width, m, block, kernels_)
                                          : parallelFrontCholesky(parts, width, m, block);
  } else {
    info = factorFront(width, m, block, frontWorkspaceFor(kernels_, m), kernels_);
  }
  if (info != 0) return k1 + std::max(info, 1) - 1;
  if (pivots)
    for (int k = 0; k < width; ++k)
      pivots[k1 + k] = (sign.empty() ? 1.0 : sign[k]) * block[k + static_cast<size_t>(k) * m];
  if (u > 0) {
    updates[s] = pool_.take(static_cast<size_t>(u) * u);  // its lower triangle written below (all of it if signed)
    if (!sign.empty()) {
      signedUpdate(u, width, block + width, m, sign.data(), updates[s].get());
    } else if (parts > 1) {
      if (kernels_ != FrontKernels::Blas)
        parallelUpdateKernels(parts, u, width, block + width, m, updates[s].get(), kernels_);
      else
        parallelSyrk(parts, u, width, block + width, m, 0.0, updates[s].get(), u);
    } else {
      updateMatrix(u, width, block + width, m, updates[s].get(), frontWorkspaceFor(kernels_, u), kernels_);
    }
  }
  for (int e = childStart_[s]; e < childStart_[s + 1]; ++e) {
    int cu = 0;
    const int* relative = nullptr;
    const double* update = childUpdate(e, cu, relative);
    addIntoUpdate(update, cu, relative, blockColumns(relative, cu, width), width, updates[s].get(), u);
    updates[children_[e]].reset();
  }
  return -1;
}

// One factorization's shared state: the first failing column (INT_MAX: none yet).
struct MultifrontalCholesky::Run {
  const SparseMatrix& A;
  double* values;
  double* pivots;
  Updates updates;
  double* forward;  // P b, turned into L^-1 P b front by front (null: no right-hand side)
  Updates vectors;  // the forward substitution's update vectors
  std::atomic<int> failure{INT_MAX};
};

// A front is skipped once a column before its own failed: its children's update matrices
// may be missing, and the column reported stays the one a single thread meets first (the
// smallest failing one, as a front's columns follow its descendants').
void MultifrontalCholesky::factorizeFront(int s, Run& run) const {
  if (run.failure.load(std::memory_order_relaxed) < structure_.firstColumn[s]) return;
  // A large front in pieces for the pool's threads. The front kernels give the same bits
  // cut or whole, so while the pool runs on one thread (other programs holding the other
  // cores) the front is computed whole, which is faster; BLAS pieces are cut the same way
  // whatever the load, since their bits depend on the cut.
  const bool cut = threads_ > 1 && flops_[s] >= kSliceFlops &&
                   (kernels_ == FrontKernels::Blas || WorkerPool::shared().threadsNow() > 1);
  const int parts = cut ? 2 * threads_ : 1;
  const int column = factorizeSupernode(s, run.A, run.values, run.pivots, run.updates, parts);
  if (column < 0) {
    if (run.forward) forwardFront(s, run.values, run.forward, 1, run.vectors);  // the front is in cache
    return;
  }
  int seen = run.failure.load();
  while (column < seen && !run.failure.compare_exchange_weak(seen, column)) {
  }
}

// The subtree of s, children before parents: a chain of single children walked down to
// where the tree branches, the branches as items of one loop (each a subtree, split the same
// way while it is large), then the fronts of the chain upwards. Small subtrees run whole, in
// postorder.
void MultifrontalCholesky::walkUp(int s, const std::function<void(int)>& front, int depth) const {
  std::vector<int> chain{s};
  for (int c = onlyLargeChild(s); c >= 0; c = onlyLargeChild(c)) chain.push_back(c);
  const int bottom = chain.back();
  if (subtreeFlops_[bottom] < splitFlops_ || depth > kMaxDepth) {
    for (int k = subtreeStart_[bottom]; k <= position_[bottom]; ++k) front(postorder_[k]);
  } else {
    const int first = childStart_[bottom], count = childStart_[bottom + 1] - first;
    WorkerPool::shared().forEach(
        count, [&](int e) { walkUp(children_[first + e], front, depth + 1); }, blasCallersThatFit(threads_));
    front(bottom);
  }
  for (int k = static_cast<int>(chain.size()) - 2; k >= 0; --k) front(chain[k]);
}

// The subtree of s, parents before children: the mirror of walkUp.
void MultifrontalCholesky::walkDown(int s, const std::function<void(int)>& front, int depth) const {
  int bottom = s;
  front(s);
  for (int c = onlyLargeChild(s); c >= 0; c = onlyLargeChild(c)) front(bottom = c);
  if (subtreeFlops_[bottom] < splitFlops_ || depth > kMaxDepth) {
    for (int k = position_[bottom] - 1; k >= subtreeStart_[bottom]; --k) front(postorder_[k]);
  } else {
    const int first = childStart_[bottom], count = childStart_[bottom + 1] - first;
    WorkerPool::shared().forEach(
        count, [&](int e) { walkDown(children_[first + e], front, depth + 1); }, blasCallersThatFit(threads_));
  }
}

int MultifrontalCholesky::onlyLargeChild(int s) const {
  if (childStart_[s + 1] - childStart_[s] != 1) return -1;
  const int c = children_[childStart_[s]];
  return subtreeFlops_[c] >= splitFlops_ ? c : -1;
}

// Every front of the tree once, children before parents (upward) or parents first: on the
// calling thread in the order of the supernodes, or on the pool's threads.
void MultifrontalCholesky::forEachFront(bool upward, const std::function<void(int)>& front) const {
  const int ns = structure_.supernodeCount;
  if (threads_ < 2) {
    if (upward)
      for (int s = 0; s < ns; ++s) front(s);
    else
      for (int s = ns - 1; s >= 0; --s) front(s);
    return;
  }
  ScopedBlasThreads oneEach(1);  // every BLAS call on its calling thread, the threads being the pool's
  WorkerPool::shared().forEach(
      static_cast<int>(roots_.size()),
      [&](int r) { upward ? walkUp(roots_[r], front, 0) : walkDown(roots_[r], front, 0); },
      blasCallersThatFit(threads_));
}

int MultifrontalCholesky::factorize(const SparseMatrix& A, double* values, double* pivots, double* forward) const {
  const int failed = factorizeRun(A, values, pivots, forward);
  pool_.endRun();  // every update matrix is back in the pool
  return failed;
}

int MultifrontalCholesky::factorizeRun(const SparseMatrix& A, double* values, double* pivots, double* forward) const {
  const int ns = structure_.supernodeCount;
  Run run{A, values, pivots, Updates(ns), forward, Updates(forward ? ns : 0)};
  if (threads_ < 2) {
    for (int s = 0; s < ns; ++s) {
      const int column = factorizeSupernode(s, A, values, pivots, run.updates, 1);
      if (column >= 0) return column;
      if (forward) forwardFront(s, values, forward, 1, run.vectors);
    }
    return -1;
  }
  try {
    forEachFront(true, [&](int s) { factorizeFront(s, run); });
  } catch (const std::bad_alloc&) {
    throw Error("multifrontal Cholesky: out of memory for the update matrices of the factorization");
  }
  const int failed = run.failure.load();
  return failed == INT_MAX ? -1 : failed;
}

// L z = y front by front, children first: a front's columns of z from its own entries of y
// less its children's update vectors (L21 z of the columns below them, carried up to the
// front that owns each row, as the factorization carries its update matrices); then
// z := S z; then L^T w = z, parents first, each front reading the rows below it from its
// ancestors' results. With several right-hand sides the vectors are u x nrhs blocks and
// each front's L is read once for all of them (dtrsm, dgemm).
void MultifrontalCholesky::solve(const double* values, const double* pivots, double* y, int nrhs) const {
  Updates vectors(structure_.supernodeCount);
  forEachFront(true, [&](int s) { forwardFront(s, values, y, nrhs, vectors); });
  backward(values, pivots, y, nrhs);
}

// Front s's step of L z = y: its columns of z, and its update vectors L21 z (u x nrhs)
// for its parent, once its children's are added.
void MultifrontalCholesky::forwardFront(int s, const double* values, double* y, int nrhs, Updates& vectors) const {
  const SupernodalStructure& S = structure_;
  const int n = S.n, one = 1;
  const double plusOne = 1.0;
  const int k1 = S.firstColumn[s], width = S.firstColumn[s + 1] - k1;
  const int m = S.rowStart[s + 1] - S.rowStart[s], u = m - width;
  const double* block = values + S.valueStart[s];
  double* own = y + k1;
  double* below = u > 0 ? new double[static_cast<size_t>(u) * nrhs]() : nullptr;
  vectors[s] = BlockPool::Block(below, BlockPool::Return{});
  for (int e = childStart_[s]; e < childStart_[s + 1]; ++e) {
    const int c = children_[e];
    const int cu = static_cast<int>(relativeStart_[c + 1] - relativeStart_[c]);
    const int* relative = relative_.data() + relativeStart_[c];
    const double* update = vectors[c].get();
    for (int r = 0; r < nrhs; ++r) {
      double* ownR = own + static_cast<size_t>(r) * n;
      double* belowR = below + static_cast<size_t>(r) * u;
      const double* updateR = update + static_cast<size_t>(r) * cu;
      for (int i = 0; i < cu; ++i) {
        const int row = relative[i];
        if (row < width)
          ownR[row] -= updateR[i];
        else
          belowR[row - width] += updateR[i];
      }
    }
    vectors[c].reset();
  }
  if (nrhs == 1) {
    dtrsv_("L", "N", "N", &width, block, &m, own, &one);
    if (u > 0) dgemv_("N", &u, &width, &plusOne, block + width, &m, own, &one, &plusOne, below, &one);
  } else {
    dtrsm_("L", "L", "N", "N", &width, &nrhs, &plusOne, block, &m, own, &n);
    if (u > 0) dgemm_("N", "N", &u, &nrhs, &width, &plusOne, block + width, &m, own, &n, &plusOne, below, &u);
  }
}

void MultifrontalCholesky::backward(const double* values, const double* pivots, double* y, int nrhs) const {
  const SupernodalStructure& S = structure_;
  const int n = S.n, one = 1;
  const double plusOne = 1.0, minusOne = -1.0;
  forEachFront(false, [&](int s) {
    const int k1 = S.firstColumn[s], width = S.firstColumn[s + 1] - k1;
    const int m = S.rowStart[s + 1] - S.rowStart[s], u = m - width;
    const double* block = values + S.valueStart[s];
    double* own = y + k1;
    if (pivots)
      for (int k = 0; k < width; ++k)
        if (pivots[k1 + k] < 0)
          for (int r = 0; r < nrhs; ++r) own[k + static_cast<size_t>(r) * n] = -own[k + static_cast<size_t>(r) * n];
    if (u > 0) {
      std::vector<double> rowsBelow(static_cast<size_t>(u) * nrhs);
      const int* rows = S.rows + S.rowStart[s] + width;
      for (int r = 0; r < nrhs; ++r)
        for (int i = 0; i < u; ++i) rowsBelow[i + static_cast<size_t>(r) * u] = y[rows[i] + static_cast<size_t>(r) * n];
      if (nrhs == 1)
        dgemv_("T", &u, &width, &minusOne, block + width, &m, rowsBelow.data(), &one, &plusOne, own, &one);
      else
        dgemm_("T", "N", &width, &nrhs, &u, &minusOne, block + width, &m, rowsBelow.data(), &u, &plusOne, own, &n);
    }
    if (nrhs == 1)
      dtrsv_("L", "T", "N", &width, block, &m, own, &one);
    else
      dtrsm_("L", "L", "T", "N", &width, &nrhs, &plusOne, block, &m, own, &n);
  });
}

}  // namespace aster::linalg
