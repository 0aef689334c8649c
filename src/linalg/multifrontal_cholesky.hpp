// The numeric half of a supernodal Cholesky factorization A = L L^T, multifrontal.
//
// Each supernode (a run of columns of L with one row pattern) owns a dense frontal matrix
// over its rows: it gathers its columns of A and the update matrices of its children in the
// supernodal elimination tree, factorizes its own columns (dpotrf, dtrsm) straight into the
// storage of L, and leaves its Schur complement (dsyrk) as its update matrix for its parent.
// Every dense operation works on a whole front, so its inner dimension is the supernode's
// width; a left-looking method (CHOLMOD's) updates a supernode once per descendant instead,
// with that descendant's few columns as inner dimension, and ran at 11 % of dgemm's rate on
// 2D meshes (docs/performance.md).
//
// Subtrees of the elimination tree are independent: a front's children are the items of a
// loop of the program's worker pool (core/worker_pool.hpp), each run with a one-thread BLAS
// and split the same way while it is large, so the threads take subtrees as they come free
// rather than a share fixed in advance, which a busy machine would leave unbalanced. The
// dense work of a large front is split into pieces the free threads help with. Each front
// is computed the same way on any thread, in the same order of its children, and a failure
// names the same column as on one thread.
//
// The symbolic structure (ordering, supernodes, row patterns, storage of L) is CHOLMOD's
// supernodal analysis; the values of L are laid out as CHOLMOD's supernodal factor would
// hold them, in storage the caller owns.
//
// Signed columns (stiffness + Lagrange multipliers): P A P^T = L S L^T, S = diag(+-1), the
// sign of each pivot taken as it comes, without pivoting. Fronts holding a column flagged
// `indefinite` are factorized column by column (L(k,k) = sqrt|d|, S(k,k) = sign d); the
// others by dpotrf as above. With the multipliers ordered after the unknowns they
// constrain, a system [K B^T; B -C] with K positive definite and C >= 0 meets positive
// pivots first and then those of -(C + B K^-1 B^T), negative. Solve with
// L y = P b, z = S y, L^T P x = z.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "linalg/block_pool.hpp"
#include "linalg/dense_front.hpp"
#include "linalg/linear_solver.hpp"

namespace aster::linalg {

// CHOLMOD's supernodal symbolic factor, field by field (cholmod_factor with int indices).
struct SupernodalStructure {
  int n = 0;
  int supernodeCount = 0;
  const int* firstColumn = nullptr;  // L->super, size supernodeCount + 1
  const int* rowStart = nullptr;     // L->pi, size supernodeCount + 1, into rows
  const int* valueStart = nullptr;   // L->px, size supernodeCount + 1, into the values of L
  const int* rows = nullptr;         // L->s: rows of each supernode, its own columns first, ascending
  const int* permutation = nullptr;  // L->Perm: row k of L is row permutation[k] of A (null: identity)
};

class MultifrontalCholesky {
 public:
  // Below this many estimated flops a factorization runs on one thread.
  static constexpr double kParallelFlops = 2e7;
  // Fronts of this many flops or more have their dense work split into pieces.
  static constexpr double kSliceFlops = 4e6;

  // Plans the factorization of matrices with A's pattern, both triangles stored (the same
  // pattern the structure was computed from). threads: how many threads the work is planned for
  // (the pieces of a front depend on it; the pool's threads run them).
  // indefinite[k] (size n, or empty): column k of P A P^T may take a negative pivot.
  MultifrontalCholesky(const SupernodalStructure& structure, const SparseMatrix& A, int threads,
                       double parallelFlops = kParallelFlops, const std::vector<char>& indefinite = {});

  // L = chol(P A P^T) into values (the supernodal storage, column-major blocks at valueStart),
  // and L(k,k) into pivots[k] (size n) when given, negated where S(k,k) = -1. Returns -1, or
  // the first column of P A P^T whose pivot was not positive (not finite and non-zero in an
  // indefinite front; L is then partial).
  // With `forward` (P b, size n), each front also takes its step of L z = P b right after
  // its factorization, while it is in cache: on success forward holds z, and backward()
  // finishes the solve without reading L a first time.
  int factorize(const SparseMatrix& A, double* values, double* pivots = nullptr, double* forward = nullptr) const;

  // Solves P A P^T w = y in place (y: P b on entry, P x on exit) with the factor the last
  // factorize() left in values, and S from the signs of its pivots (null: S = I); for
  // nrhs right-hand sides at once, y is n x nrhs, column-major.
  void solve(const double* values, const double* pivots, double* y, int nrhs = 1) const;
  // The second half of solve(): z := S z, then L^T w = z (z: L^-1 P b on entry, P x on exit).
  void backward(const double* values, const double* pivots, double* z, int nrhs = 1) const;

  // Whether the factorization runs on the worker pool (false: every front on the calling thread).
  bool parallel() const { return threads_ > 1; }
  double estimatedFlops() const { return totalFlops_; }

 private:
  using Updates = std::vector<BlockPool::Block>;  // per supernode, until its parent adds it
  struct Run;
  static constexpr int kMaxDepth = 64;  // subtrees deeper than this run whole (a bound on the stack)
  int factorizeRun(const SparseMatrix& A, double* values, double* pivots, double* forward) const;
  void factorizeFront(int s, Run& run) const;
  void forwardFront(int s, const double* values, double* y, int nrhs, Updates& vectors) const;
  void forEachFront(bool upward, const std::function<void(int)>& front) const;
  void walkUp(int s, const std::function<void(int)>& front, int depth) const;
  void walkDown(int s, const std::function<void(int)>& front, int depth) const;
  int onlyLargeChild(int s) const;  // the one child of s when its subtree is split further, else -1
  // parts > 1: the front's dense work split between that many threads (top of the tree).
  int factorizeSupernode(int s, const SparseMatrix& A, double* values, double* pivots, Updates& updates,
                         int parts) const;
  void schedule(int threads, double parallelFlops);

  SupernodalStructure structure_;
  std::vector<int> parent_;            // supernode of the parent, -1 at a root
  std::vector<int> childStart_;        // children of s: children_[childStart_[s] .. childStart_[s + 1])
  std::vector<int> children_;
  std::vector<long long> relativeStart_;  // update rows of s as positions in its parent's rows
  std::vector<int> relative_;
  // The entries of A (lower triangle of P A P^T) in supernode s: those of its columns whose
  // bit is set in entryInFactor_ (one bit per entry of A's storage: a third of the memory
  // of an index per entry), in the order of the columns, at offsets
  // entryTarget_[entryStart_[s] .. entryStart_[s + 1]) of the supernode's block of L.
  std::vector<long long> entryStart_;
  std::vector<std::uint64_t> entryInFactor_;
  std::vector<int> entryTarget_;
  std::vector<double> flops_;          // estimate per supernode
  std::vector<char> signedFront_;      // per supernode: holds an indefinite column
  double totalFlops_ = 0;
  int threads_ = 1;
  std::vector<double> subtreeFlops_;   // per supernode, its whole subtree's
  double splitFlops_ = 0;              // subtrees below this run whole on one thread
  std::vector<int> roots_;
  std::vector<int> postorder_;         // the supernodes, each subtree a contiguous run
  std::vector<int> subtreeStart_;      // where s's subtree starts in postorder_
  std::vector<int> position_;          // where s is in postorder_
  FrontKernels kernels_ = frontKernelsInUse();  // the dense work of the fronts
  mutable BlockPool pool_;             // the large update matrices, from one factorization to the next
};

}  // namespace aster::linalg
