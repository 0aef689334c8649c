#include "linalg/cholmod_solver.hpp"

#include <cholmod.h>

#include <algorithm>
#include <chrono>
#include <sstream>
#include <vector>


#include "core/worker_pool.hpp"
#include "linalg/blas_info.hpp"
#include "linalg/cholmod_views.hpp"
#include "linalg/pivot_audit.hpp"
#include "linalg/stopwatch.hpp"
#include "linalg/warmed_block.hpp"

namespace aster::linalg {

struct CholmodSolver::Handles {
  cholmod_common common;
  cholmod_factor* factor = nullptr;
  Handles() {
    cholmod_start(&common);
    common.print = 0;  // kernels do not print: failures are read from common.status
  }
  ~Handles() {
    if (factor) cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
  }
};

namespace {

constexpr Eigen::Index kNestedDissectionSize = 20000;
// The factor's size guessed before the analysis, in entries per entry of the matrix:
// about 5 for the nested dissection of 2D meshes (SVK square N = 256: 4.7, N = 512: 5.1),
// more in 3D, where the guess falls short and the rest of the factor is touched later.
constexpr size_t kFactorEntriesPerEntry = 5;
constexpr int kFewFactorizations = 3;
// The factor's memory is touched ahead from this guessed size: a smaller factor's first
// touch costs less than the thread (SVK square N = 64, guess 31 MB: no faster after 20 s
// of idling, and the analysis delayed in half the runs with another program on the other
// core; N = 128, 124 MB: 0.12 s faster after idling).
constexpr size_t kWarmedFactorBytes = size_t{64} << 20;

std::string cholmodStatus(int status) {
  switch (status) {
    case CHOLMOD_OUT_OF_MEMORY: return "out of memory";
    case CHOLMOD_TOO_LARGE: return "integer overflow: the matrix is too large";
    case CHOLMOD_INVALID: return "invalid input";
    case CHOLMOD_NOT_INSTALLED: return "method not installed";
    case CHOLMOD_GPU_PROBLEM: return "GPU problem";
    default: return "status " + std::to_string(status);
  }
}

// Lagrange multipliers in a constrained system: the rows from multipliersFrom on (when
// >= 0), and those whose diagonal is absent or zero.
std::vector<int> constraintSets(const SparseMatrix& A, int multipliersFrom, int& count) {
  std::vector<int> set(static_cast<size_t>(A.cols()), 0);
  count = 0;
  for (int j = 0; j < A.cols(); ++j)
    if ((multipliersFrom >= 0 && j >= multipliersFrom) || entryOf(A, j, j) == 0.0) {
      set[j] = 1;
      ++count;
    }
  return set;
}

// Nested dissection of the graph of the nodes rather than of the unknowns: consecutive
// columns with the same pattern (a node's DX and DY) are one vertex, so METIS partitions a
// graph with half the vertices and a quarter of the edges (SVK square N = 256: analysis
// 2.5 -> 2.1 s, 2 % fewer flops per factorization; N = 128: 0.49 -> 0.38 s, 1.6 % more).
// Returns the permutation of the columns, or nothing when the columns do not pair up or
// CHOLMOD has no METIS.
// The pattern is given as compressed columns (outer, inner: sorted rows, both triangles).
std::vector<int> nodeNestedDissection(int n, const int* outer, const int* inner, cholmod_common& c) {
  std::vector<int> group(n), first{0};
  for (int j = 1; j < n; ++j) {
    const bool same = outer[j + 1] - outer[j] == outer[j] - outer[j - 1] &&
                      std::equal(inner + outer[j], inner + outer[j + 1], inner + outer[j - 1]);
    if (!same) first.push_back(j);
    group[j] = static_cast<int>(first.size()) - 1;
  }
  const int groups = static_cast<int>(first.size());
  first.push_back(n);
  if (3 * groups > 2 * n) return {};
  std::vector<int> p{0}, i, seen(groups, -1);
  for (int g = 0; g < groups; ++g) {
    const int j = first[g];
    for (int k = outer[j]; k < outer[j + 1]; ++k) {
      const int r = group[inner[k]];
      if (seen[r] == g) continue;
      seen[r] = g;
      i.push_back(r);
    }
    p.push_back(static_cast<int>(i.size()));
  }
  cholmod_sparse graph = symmetricView(groups, p.data(), i.data(), nullptr);
  std::vector<int> order(groups), parent(groups), member(groups);
  // Parts below nd_small nodes are left to CAMD rather than bisected further. CHOLMOD's
  // 200 spends most of the ordering on the deepest levels, whose separators save little:
  // groups / 64 parts, at most 4000 nodes (SVK square, ordering and flops per factorization:
  // N = 256 1.2-1.4 s -> 0.7 s, +4 %; N = 512 6.2 -> 3.5 s, +2.3 %; N = 64 and 128 keep
  // about CHOLMOD's value, where larger parts cost more flops than they save).
  const double savedSmall = c.method[c.current].nd_small;
  c.method[c.current].nd_small = std::clamp(groups / 64, 200, 4000);
  const long long components =
      cholmod_nested_dissection(&graph, nullptr, 0, order.data(), parent.data(), member.data(), &c);
  c.method[c.current].nd_small = savedSmall;
  if (components < 0) return {};
  std::vector<int> perm;
  perm.reserve(n);
  for (int g : order)
    for (int j = first[g]; j < first[g + 1]; ++j) perm.push_back(j);
  return perm;
}

std::vector<int> nodeNestedDissection(const SparseMatrix& M, cholmod_common& c) {
  return nodeNestedDissection(static_cast<int>(M.cols()), M.outerIndexPtr(), M.innerIndexPtr(), c);
}

// A saddle point system (the multipliers flagged in `sets`) ordered as one without them:
// nested dissection of the other unknowns by nodes, each multiplier placed right after the
// last of the unknowns its column couples it to. Those are eliminated before it, so its
// pivot is a Schur complement's (-b^T K^-1 b over what came before it), not its zero
// diagonal; the elimination tree keeps it above them, so the postorder does too.
// Constrained AMD (every multiplier last) costs more flops on a large mesh (SSNP150 with
// LAC, N = 128: 3.56e9 per factorization against 2.96e9). Returns nothing when the
// unknowns do not pair into nodes.
std::vector<int> multipliersAfterTheirUnknowns(const SparseMatrix& M, const std::vector<int>& sets,
                                               cholmod_common& c) {
  const int n = static_cast<int>(M.cols());
  const int* outer = M.outerIndexPtr();
  const int* inner = M.innerIndexPtr();
  std::vector<int> freeIndex(n, -1), freeColumns;
  for (int j = 0; j < n; ++j)
    if (!sets[j]) {
      freeIndex[j] = static_cast<int>(freeColumns.size());
      freeColumns.push_back(j);
    }
  const int nf = static_cast<int>(freeColumns.size());
  std::vector<int> p{0}, i;  // the pattern of the unknowns that are not multipliers
  i.reserve(static_cast<size_t>(outer[n]));
  for (int j : freeColumns) {
    for (int k = outer[j]; k < outer[j + 1]; ++k)
      if (freeIndex[inner[k]] >= 0) i.push_back(freeIndex[inner[k]]);
    p.push_back(static_cast<int>(i.size()));
  }
  const std::vector<int> freeOrder = nodeNestedDissection(nf, p.data(), i.data(), c);
  if (freeOrder.empty()) return {};
  std::vector<int> place(n, -1);
  for (int k = 0; k < nf; ++k) place[freeColumns[freeOrder[k]]] = k;
  std::vector<std::pair<int, int>> after;  // (place of the last unknown coupled, multiplier)
  for (int j = 0; j < n; ++j) {
    if (!sets[j]) continue;
    int last = nf;  // coupled to no other unknown: at the end
    for (int k = outer[j]; k < outer[j + 1]; ++k)
      if (!sets[inner[k]]) last = last == nf ? place[inner[k]] : std::max(last, place[inner[k]]);
    after.push_back({last, j});
  }
  std::stable_sort(after.begin(), after.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<int> perm;
  perm.reserve(n);
  size_t a = 0;
  for (int k = 0; k < nf; ++k) {
    perm.push_back(freeColumns[freeOrder[k]]);
    for (; a < after.size() && after[a].first == k; ++a) perm.push_back(after[a].second);
  }
  for (; a < after.size(); ++a) perm.push_back(after[a].second);
  return perm;
}

}  // namespace

CholmodSolver::CholmodSolver(Mode mode) : mode_(mode), h_(std::make_unique<Handles>()) {
  if (mode_ != Mode::LDLT) {
    h_->common.supernodal = CHOLMOD_SUPERNODAL;
    h_->common.final_ll = 1;
  } else {
    h_->common.supernodal = CHOLMOD_SIMPLICIAL;
    h_->common.final_ll = 0;
  }
}

CholmodSolver::~CholmodSolver() = default;

void CholmodSolver::analyze(const SparseMatrix& A) {
  ScopedSeconds t(stats_.analyzeSeconds, stats_.analyzeCount);
  requireSquare(A, name());
  SparseMatrix storage;
  const SparseMatrix& M = compressedMatrix(A, storage);
  factorized_ = false;
  multifrontal_.reset();
  factorStorage_.reset();
  if (h_->factor) cholmod_free_factor(&h_->factor, &h_->common);
  // The multifrontal factor of a large matrix: its memory touched while the ordering runs,
  // on the core the ordering leaves idle. When other programs hold that core (the pool then
  // runs one thread), the touching only delays the ordering (SVK square N = 128, a busy
  // loop on the other core: the analysis 0.19-0.87 s with it, 0.19-0.23 s without), so then
  // the factor's pages are touched where the factorization first writes them.
  const size_t factorGuess = kFactorEntriesPerEntry * static_cast<size_t>(M.nonZeros()) * sizeof(double);
  if (mode_ != Mode::LDLT && factorGuess >= kWarmedFactorBytes && WorkerPool::shared().threadsNow() > 1)
    factorStorage_ = std::make_unique<WarmedBlock>(factorGuess);
  struct StopWarming {  // an analysis that fails leaves no thread touching memory behind
    std::unique_ptr<WarmedBlock>& storage;
    bool done = false;
    ~StopWarming() {
      if (!done) storage.reset();
    }
  } stopWarming{factorStorage_};
  pattern_.record(M);
  symmetry_ = std::make_unique<SymmetryCheck>(M, !symmetricByConstruction_);
  cholmod_sparse view = lowerView(M);
  cholmod_common& c = h_->common;
  int constrained = 0;
  const std::vector<int> sets =
      mode_ != Mode::Cholesky ? constraintSets(M, multipliersFrom_, constrained) : std::vector<int>();
  bool multipliersInside = false;
  if (constrained > 0) {
    // Large and factorized many times: nested dissection, each multiplier after its
    // unknowns. Otherwise every multiplier after every other unknown: constrained AMD.
    std::vector<int> perm;
    if (ordering_ == "AUTO" && M.rows() >= kNestedDissectionSize && factorizationsPerAnalysis_ > kFewFactorizations)
      perm = multipliersAfterTheirUnknowns(M, sets, c);
    multipliersInside = !perm.empty();
    if (perm.empty()) {
      std::vector<int> sets_copy = sets;
      perm.resize(sets.size());
      if (!cholmod_camd(&view, nullptr, 0, sets_copy.data(), perm.data(), &c))
        throw Error(name() + ": constrained ordering failed: " + cholmodStatus(c.status));
    }
    const int savedMethods = c.nmethods;
    const int savedOrdering = c.method[0].ordering;
    c.nmethods = 1;
    c.method[0].ordering = CHOLMOD_GIVEN;
    h_->factor = cholmod_analyze_p(&view, perm.data(), nullptr, 0, &c);
    c.nmethods = savedMethods;
    c.method[0].ordering = savedOrdering;
  } else {
    // Large matrices factorized many times (Newton): nested dissection (CHOLMOD's NESDIS:
    // METIS node separators, CAMD on the parts), the fewest flops on meshes of surfaces
    // (SVK square N = 128: 2.52e9 flops against 2.61e9 with METIS and 2.77e9 with AMD,
    // which CHOLMOD's default keeps). Small ones, and a matrix factorized only a few
    // times, take AMD: computing the nested dissection costs more than the flops it saves
    // (plate with a hole, 1.6 M unknowns, one factorization: NESDIS 8 s of ordering for
    // 1.67e11 flops; AMD 2.06e11 flops, 5 s less in all).
    const int savedMethods = c.nmethods;
    const int savedOrdering = c.method[0].ordering;
    const int savedPostorder = c.postorder;
    std::vector<int> nodeOrder;
    if (ordering_ != "AUTO") {  // RENUM given: that ordering and no other
      c.nmethods = 1;
      c.method[0].ordering = ordering_ == "AMD" ? CHOLMOD_AMD : ordering_ == "METIS" ? CHOLMOD_METIS : CHOLMOD_NATURAL;
      if (ordering_ == "SANS") c.postorder = 0;
    } else if (M.rows() >= kNestedDissectionSize && factorizationsPerAnalysis_ > kFewFactorizations) {
      c.nmethods = 1;
      c.method[0].ordering = CHOLMOD_NESDIS;
      nodeOrder = nodeNestedDissection(M, c);
      if (!nodeOrder.empty()) c.method[0].ordering = CHOLMOD_GIVEN;
    } else if (M.rows() >= kNestedDissectionSize) {
      c.nmethods = 1;  // AMD alone: CHOLMOD's default would try METIS as well on such a matrix
      c.method[0].ordering = CHOLMOD_AMD;
    }
    h_->factor = nodeOrder.empty() ? cholmod_analyze(&view, &c) : cholmod_analyze_p(&view, nodeOrder.data(), nullptr, 0, &c);
    if (!h_->factor && c.status == CHOLMOD_NOT_INSTALLED) {  // CHOLMOD built without METIS
      c.nmethods = savedMethods;
      c.method[0].ordering = savedOrdering;
      c.postorder = savedPostorder;
      if (ordering_ == "METIS") throw Error(name() + ": RENUM='METIS' is not available: CHOLMOD was built without METIS");
      h_->factor = cholmod_analyze(&view, &c);
    }
    c.nmethods = savedMethods;
    c.method[0].ordering = savedOrdering;
    c.postorder = savedPostorder;
  }
  if (!h_->factor) throw Error(name() + ": symbolic analysis failed: " + cholmodStatus(c.status));
  switch (h_->factor->ordering) {
    case CHOLMOD_NATURAL: stats_.ordering = "natural"; break;
    case CHOLMOD_GIVEN:
      stats_.ordering = multipliersInside ? "NESDIS (nodes, multipliers after their unknowns)"
                        : constrained > 0 ? "CAMD (multipliers last)"
                                          : "NESDIS (nodes)";
      break;
    case CHOLMOD_AMD: stats_.ordering = "AMD"; break;
    case CHOLMOD_METIS: stats_.ordering = "METIS"; break;
    case CHOLMOD_NESDIS: stats_.ordering = "NESDIS"; break;
    case CHOLMOD_COLAMD: stats_.ordering = "COLAMD"; break;
    default: stats_.ordering = "other"; break;
  }
  stats_.factorFlops = c.fl;  // predicted by the analysis
  stats_.factorNonzeros = static_cast<long long>(c.lnz);
  if (mode_ != Mode::LDLT) planMultifrontal(M, sets);
  stopWarming.done = true;
}

// Gives the supernodal symbolic factor its numeric storage and plans the multifrontal
// factorization on CHOLMOD's structure.
void CholmodSolver::planMultifrontal(const SparseMatrix& A, const std::vector<int>& constraintSet) {
  cholmod_factor* L = h_->factor;
  if (!L->is_super) throw Error(name() + ": the analysis did not produce a supernodal factor");
  const SupernodalStructure structure = supernodalStructure(*L);
  if (!factorStorage_) factorStorage_ = std::make_unique<WarmedBlock>(0);
  try {
    // At least one entry: take() maps a block, and an empty matrix has none.
    const size_t entries = std::max<size_t>(1, static_cast<size_t>(structure.valueStart[structure.supernodeCount]));
    factorStorage_->take(entries * sizeof(double));
  } catch (const std::bad_alloc&) {
    throw Error(name() + ": cannot allocate the factor: out of memory");
  }
  const int threads = WorkerPool::shared().threads();
  std::vector<char> indefinite;  // the constraint columns, in the order of L
  if (std::find(constraintSet.begin(), constraintSet.end(), 1) != constraintSet.end()) {
    indefinite.resize(L->n);
    for (size_t k = 0; k < L->n; ++k)
      indefinite[k] = static_cast<char>(constraintSet[structure.permutation ? structure.permutation[k] : k]);
  }
  multifrontal_ = std::make_unique<MultifrontalCholesky>(structure, A, threads, MultifrontalCholesky::kParallelFlops,
                                                         indefinite);
}

void CholmodSolver::factorize(const SparseMatrix& A) { factorizeWith(A, nullptr); }

// The multifrontal factorization takes the forward substitution L z = P b with it.
void CholmodSolver::factorizeAndSolve(const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  if (!multifrontal_) {
    LinearSolver::factorizeAndSolve(A, b, x);
    return;
  }
  const cholmod_factor* L = h_->factor;
  const int n = static_cast<int>(L->n);
  if (b.size() != n) {
    factorize(A);
    solve(b, x);  // which names the wrong size
    return;
  }
  Eigen::MatrixXd y = toFactorOrder(b.data(), 1);
  factorizeWith(A, y.data());
  ScopedSeconds t(stats_.solveSeconds, stats_.solveCount);
  {
    ScopedBlasThreads one(1);
    multifrontal_->backward(values(), negativePivots_ ? pivots_.data() : nullptr, y.data());
  }
  x.resize(n);
  fromFactorOrder(y, x.data());
}

// The multifrontal solves work in the factor's order: P B for the k columns of B (n x k,
// column-major), and back.
Eigen::MatrixXd CholmodSolver::toFactorOrder(const double* B, Eigen::Index k) const {
  const int* perm = static_cast<const int*>(h_->factor->Perm);
  const Eigen::Index n = static_cast<Eigen::Index>(h_->factor->n);
  Eigen::MatrixXd Y(n, k);
  for (Eigen::Index c = 0; c < k; ++c)
    for (Eigen::Index i = 0; i < n; ++i) Y(i, c) = B[(perm ? perm[i] : i) + c * n];
  return Y;
}

void CholmodSolver::fromFactorOrder(const Eigen::MatrixXd& Y, double* X) const {
  const int* perm = static_cast<const int*>(h_->factor->Perm);
  const Eigen::Index n = Y.rows();
  for (Eigen::Index c = 0; c < Y.cols(); ++c)
    for (Eigen::Index i = 0; i < n; ++i) X[(perm ? perm[i] : i) + c * n] = Y(i, c);
}

void CholmodSolver::factorizeWith(const SparseMatrix& A, double* forward) {
  ScopedSeconds t(stats_.factorizeSeconds, stats_.factorizeCount);
  SparseMatrix storage;
  const SparseMatrix& M = compressedMatrix(A, storage);
  pattern_.requireSame(M, name());
  factorized_ = false;
  if (!symmetricByConstruction_) symmetry_->require(M, symmetryTolerance_, name());
  cholmod_common& c = h_->common;
  cholmod_factor* L = h_->factor;
  const auto start = std::chrono::steady_clock::now();
  if (multifrontal_) {
    pivots_.resize(L->n);
    const int failed = multifrontal_->factorize(M, values(), pivots_.data(), forward);
    L->minor = failed < 0 ? L->n : static_cast<size_t>(failed);
    negativePivots_ = std::any_of(pivots_.begin(), pivots_.end(), [](double p) { return p < 0; });
  } else {
    cholmod_sparse view = lowerView(M);
    const int ok = cholmod_factorize(&view, L, &c);
    if (!ok || c.status < CHOLMOD_OK) throw Error(name() + ": numeric factorization failed: " + cholmodStatus(c.status));
  }
  const double numeric = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (stats_.numericSeconds == 0.0) stats_.firstNumericSeconds = numeric;
  stats_.numericSeconds += numeric;
  if (L->minor < L->n) {
    const int* perm = static_cast<const int*>(L->Perm);
    const int col = perm ? perm[L->minor] : static_cast<int>(L->minor);
    if (mode_ == Mode::Cholesky) {
      std::ostringstream s;
      s << "CHOLMOD: the matrix is not positive definite: the Cholesky factorization failed at column " << col
        << " (singular or indefinite matrix; for stiffness + Lagrange multipliers use CHOLMOD_LDLT or UMFPACK)";
      throw SingularMatrixError(s.str() + "; if it should be positive definite, the structure may be free to move "
                                          "(missing Dirichlet conditions?)",
                                col, col);
    }
    if (mode_ == Mode::MultFront)  // dpotrf stops at a negative pivot too, outside the multipliers' fronts
      throwZeroPivot(name(), col, col, " (or negative, where no Lagrange multiplier is: an indefinite stiffness)");
    throwZeroPivot(name(), col, col);
  }
  auditFactor(M);
  factorized_ = true;
}

// Pivots are D(k,k) for LDL^T and L(k,k)^2 for LL^T, at row and column Perm[k] of A.
void CholmodSolver::auditFactor(const SparseMatrix& A) const {
  const cholmod_factor* L = h_->factor;
  const int* perm = static_cast<const int*>(L->Perm);
  const double* x = static_cast<const double*>(L->x);
  std::vector<double> diagonal(L->n);
  if (multifrontal_) {
    diagonal = pivots_;
  } else if (L->is_super) {
    const int* super = static_cast<const int*>(L->super);
    const int* pi = static_cast<const int*>(L->pi);
    const int* px = static_cast<const int*>(L->px);
    for (size_t s = 0; s < L->nsuper; ++s) {
      const int nrows = pi[s + 1] - pi[s];
      for (int k = super[s]; k < super[s + 1]; ++k) {
        const int local = k - super[s];
        diagonal[k] = x[px[s] + local + static_cast<size_t>(local) * nrows];
      }
    }
  } else {
    const int* p = static_cast<const int*>(L->p);
    for (size_t k = 0; k < L->n; ++k) diagonal[k] = x[p[k]];  // the diagonal comes first in each column
  }
  const bool ll = multifrontal_ || L->is_ll;  // the multifrontal factor is L L^T (signed), its L symbolic
  auditPivots(name(), static_cast<int>(L->n), nprec_, [&](int k) {
    const int i = perm ? perm[k] : k;
    const double d = ll ? diagonal[k] * std::abs(diagonal[k]) : diagonal[k];  // L(k,k) S(k,k) L(k,k)
    return Pivot{d, symmetry_->diagonal(A, i), i, i};
  });
}

void CholmodSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  ScopedSeconds t(stats_.solveSeconds, stats_.solveCount);
  requireReadyToSolve(factorized_, b);
  cholmod_dense rhs{};
  rhs.nrow = rhs.d = rhs.nzmax = static_cast<size_t>(b.size());
  rhs.ncol = 1;
  rhs.x = const_cast<double*>(b.data());
  rhs.xtype = CHOLMOD_REAL;
  rhs.dtype = CHOLMOD_DOUBLE;
  cholmod_dense* solution = nullptr;
  {
    // One BLAS thread: the triangular solves are bound by memory, and a second BLAS thread,
    // once woken, spins for a while after the call, taking a core from what runs next.
    ScopedBlasThreads one(1);
    if (multifrontal_) {
      // The factor is the multifrontal factorization's: solved front by front, on the pool.
      Eigen::MatrixXd y = toFactorOrder(b.data(), 1);
      multifrontal_->solve(values(), negativePivots_ ? pivots_.data() : nullptr,
                           y.data());
      x.resize(b.size());
      fromFactorOrder(y, x.data());
      return;
    }
    if (!negativePivots_) {
      solution = cholmod_solve(CHOLMOD_A, h_->factor, &rhs, &h_->common);
    } else {
      // P^T L^-T S L^-1 P b, one step at a time.
      cholmod_common& c = h_->common;
      cholmod_dense* y = cholmod_solve(CHOLMOD_P, h_->factor, &rhs, &c);
      cholmod_dense* z = y ? cholmod_solve(CHOLMOD_L, h_->factor, y, &c) : nullptr;
      cholmod_free_dense(&y, &c);
      if (z) {
        double* v = static_cast<double*>(z->x);
        for (size_t k = 0; k < z->nrow; ++k)
          if (pivots_[k] < 0) v[k] = -v[k];
        y = cholmod_solve(CHOLMOD_Lt, h_->factor, z, &c);
        cholmod_free_dense(&z, &c);
        solution = y ? cholmod_solve(CHOLMOD_Pt, h_->factor, y, &c) : nullptr;
        cholmod_free_dense(&y, &c);
      }
    }
  }
  if (!solution) throw Error(name() + ": solve failed: " + cholmodStatus(h_->common.status));
  x = Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(solution->x), b.size());
  cholmod_free_dense(&solution, &h_->common);
}

void CholmodSolver::solveMany(const Eigen::MatrixXd& B, Eigen::MatrixXd& X) const {
  if (!multifrontal_ || B.cols() < 2) {
    LinearSolver::solveMany(B, X);
    return;
  }
  ScopedSeconds t(stats_.solveSeconds, stats_.solveCount);
  requireReadyToSolve(factorized_, B.col(0));  // B has at least two columns here
  ScopedBlasThreads one(1);
  Eigen::MatrixXd Y = toFactorOrder(B.data(), B.cols());
  multifrontal_->solve(values(), negativePivots_ ? pivots_.data() : nullptr, Y.data(),
                       static_cast<int>(Y.cols()));
  X.resize(B.rows(), B.cols());
  fromFactorOrder(Y, X.data());
}

}  // namespace aster::linalg
