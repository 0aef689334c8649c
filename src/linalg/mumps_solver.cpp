#include "linalg/mumps_solver.hpp"

#include <dmumps_c.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include "linalg/mumps_instance.hpp"
#include "linalg/pivot_audit.hpp"
#include "linalg/stopwatch.hpp"

namespace aster::linalg {

namespace {

constexpr double kSymmetryTolerance = 1e-10;

// ICNTL(7) of each RENUM name. Debian 12's sequential MUMPS is built with SCOTCH and PORD but
// without METIS (libmumps_common_seq links libscotch/libesmumps, not libmetis).
struct OrderingCode {
  const char* renum;
  int icntl7;
};
constexpr OrderingCode kOrderings[] = {{"AUTO", 7}, {"AMD", 0}, {"AMF", 2}, {"SCOTCH", 3}, {"PORD", 4}, {"QAMD", 6}};

// What INFOG(1) < 0 means (MUMPS 5.5 user's guide, section "Error diagnostics").
std::string mumpsError(int code, int info2) {
  std::ostringstream s;
  s << "error " << code << " (";
  switch (code) {
    case -5: s << "not enough memory for the analysis"; break;
    case -6: s << "the matrix is structurally singular, structural rank " << info2; break;
    case -7: s << "integer workspace allocation failed in the analysis"; break;
    case -8: s << "the integer workspace of the factorization is too small; PCENT_PIVOT (ICNTL(14)) gives more"; break;
    case -9: s << "the real workspace of the factorization is too small; PCENT_PIVOT (ICNTL(14)) gives more"; break;
    case -10: s << "the matrix is numerically singular"; break;
    case -11: case -14: s << "the workspace of the solution is too small"; break;
    case -12: case -15: s << "the workspace of the iterative refinement is too small"; break;
    case -13: s << "a memory allocation failed (" << info2 << " entries)"; break;
    case -16: s << "the order of the matrix is out of range"; break;
    case -17: case -20: s << "the communication buffer is too small; PCENT_PIVOT (ICNTL(14)) gives more"; break;
    case -40: s << "the matrix declared symmetric positive definite (TYPE_RESOL='SYMDEF') is not"; break;
    default: s << "INFO(2) = " << info2 << ", see MUMPS's user's guide"; break;
  }
  s << ")";
  return s.str();
}

bool workspaceShort(int code) { return code == -8 || code == -9 || code == -17 || code == -20; }

// Whether every pair of unknowns is coupled in A or A^T: the graph is one clique. PORD (5.5)
// ends the process (exit(-1) in orderMinPriority, "no valid number of stages in
// multisector") on such a graph, from one unknown up: one element's matrix, say.
bool denseGraph(const SparseMatrix& M) {
  const long long n = M.cols();
  if (2 * static_cast<long long>(M.nonZeros()) < n * (n + 1)) return false;  // too few entries to cover every pair
  std::vector<char> coupled(static_cast<size_t>(n * n), 0);
  for (int j = 0; j < n; ++j)
    for (int k = M.outerIndexPtr()[j]; k < M.outerIndexPtr()[j + 1]; ++k) {
      const int i = M.innerIndexPtr()[k];
      coupled[static_cast<size_t>(i * n + j)] = coupled[static_cast<size_t>(j * n + i)] = 1;
    }
  return std::all_of(coupled.begin(), coupled.end(), [](char c) { return c != 0; });
}

}  // namespace

struct MumpsSolver::Handle : MumpsInstance<DMUMPS_STRUC_C, dmumps_c> {};

MumpsSolver::MumpsSolver() : h_(std::make_unique<Handle>()) {}

MumpsSolver::~MumpsSolver() = default;

std::vector<std::string> MumpsSolver::orderings() const {
  std::vector<std::string> names;
  for (const auto& o : kOrderings) names.emplace_back(o.renum);
  return names;
}

void MumpsSolver::setOptions(const MumpsOptions& options) {
  const std::string& s = options.symmetry;
  if (s != "AUTO" && s != "NONSYM" && s != "SYMGEN" && s != "SYMDEF")
    throw Error("MUMPS: TYPE_RESOL='" + s + "' is none of 'AUTO', 'NONSYM', 'SYMGEN', 'SYMDEF'");
  const std::string& r = options.refinement;
  if (r != "AUTO" && r != "SANS" && r != "MINI" && r != "FORCE")
    throw Error("MUMPS: POSTTRAITEMENTS='" + r + "' is none of 'SANS', 'AUTO', 'FORCE', 'MINI'");
  if (options.pivotPercent < 1) throw Error("MUMPS: PCENT_PIVOT must be at least 1");
  options_ = options;
}

// A new MUMPS instance (JOB = -1): SYM is fixed for its life.
void MumpsSolver::start(int sym) {
  h_->start(sym);
  if (h_->infog(1) < 0) throw Error("MUMPS: initialisation failed: " + mumpsError(h_->infog(1), h_->infog(2)));
  sym_ = sym;
  pivotPercent_ = options_.pivotPercent;
}

void MumpsSolver::applyControls() {
  Handle& h = *h_;
  // Quiet: no error, diagnostic or global information stream, print level 0.
  h.icntl(1) = -1;
  h.icntl(2) = -1;
  h.icntl(3) = -1;
  h.icntl(4) = 0;
  h.icntl(5) = 0;  // assembled matrix, coordinates
  h.icntl(18) = 0;  // centralized on the host
  h.icntl(20) = 0;  // dense right-hand side
  h.icntl(21) = 0;  // centralized solution, written over rhs
  for (const auto& o : kOrderings)
    if (ordering_ == o.renum) h.icntl(7) = o.icntl7;
  h.icntl(6) = options_.preprocess ? 7 : 0;   // permutation to a zero-free diagonal: automatic / none
  h.icntl(8) = options_.preprocess ? 77 : 0;  // scaling: automatic / none
  h.icntl(10) = options_.refinement == "FORCE" ? 10 : options_.refinement == "MINI" ? -1 : 0;
  h.icntl(14) = pivotPercent_;
  // Null pivots: a pivot row below CNTL(3) * ||A_pre||_inf (relative), or below |CNTL(3)| when
  // CNTL(3) < 0: the smallest normal double keeps only rows that are exactly zero.
  h.icntl(24) = 1;
  h.id.cntl[2] = nprec_ > 0 ? std::pow(10.0, -nprec_) : -std::numeric_limits<double>::min();
}

void MumpsSolver::analyze(const SparseMatrix& A) {
  ScopedSeconds t(stats_.analyzeSeconds, stats_.analyzeCount);
  requireSquare(A, name());
  SparseMatrix storage;
  const SparseMatrix& M = compressedMatrix(A, storage);
  factorized_ = false;
  pattern_.record(M);
  int sym = 0;
  if (options_.symmetry == "SYMDEF") {
    sym = 1;
  } else if (options_.symmetry == "SYMGEN") {
    sym = 2;
  } else if (options_.symmetry == "AUTO") {
    symmetry_ = std::make_unique<SymmetryCheck>(M, !symmetricByConstruction_);
    sym = 2;
    if (!symmetricByConstruction_) {
      try {
        symmetry_->require(M, kSymmetryTolerance, name());
      } catch (const UnsymmetricMatrixError&) {
        sym = 0;
      }
    }
  }
  if (sym != 0 && options_.symmetry != "AUTO")
    symmetry_ = std::make_unique<SymmetryCheck>(M, !symmetricByConstruction_);
  start(sym);
  loadValues(M);
  runAnalysis();
}

// The entries MUMPS reads: all of them (SYM = 0) or the lower triangle.
void MumpsSolver::loadValues(const SparseMatrix& M) {
  const bool triangle = sym_ != 0;
  irn_.clear();
  jcn_.clear();
  entries_.clear();
  for (int j = 0; j < M.cols(); ++j)
    for (int k = M.outerIndexPtr()[j]; k < M.outerIndexPtr()[j + 1]; ++k) {
      const int i = M.innerIndexPtr()[k];
      if (triangle && i < j) continue;
      irn_.push_back(i + 1);
      jcn_.push_back(j + 1);
      entries_.push_back(k);
    }
  values_.assign(entries_.size(), 0.0);
  for (size_t e = 0; e < entries_.size(); ++e) values_[e] = M.valuePtr()[entries_[e]];
  matrix_ = M;
}

void MumpsSolver::runAnalysis() {
  Handle& h = *h_;
  applyControls();
  h.id.n = pattern_.size();
  h.id.nnz = static_cast<MUMPS_INT8>(irn_.size());
  h.id.irn = irn_.data();
  h.id.jcn = jcn_.data();
  h.id.a = values_.data();
  // A dense matrix has no fill to reduce: every ordering is as good, and PORD cannot take it.
  const bool densePord = ordering_ == "PORD" && denseGraph(matrix_);
  if (densePord) h.icntl(7) = 0;
  h.run(1);
  if (h.infog(1) < 0) throw Error("MUMPS: analysis failed: " + mumpsError(h.infog(1), h.infog(2)));
  stats_.ordering = mumpsOrderingName(h.infog(7));
  if (densePord) {
    stats_.ordering += " (a dense matrix, which PORD cannot order)";
  } else if (ordering_ != "AUTO" && stats_.ordering != ordering_) {
    throw Error("MUMPS: RENUM='" + ordering_ + "' asked, but the library ordered with " + stats_.ordering);
  }
}

void MumpsSolver::factorize(const SparseMatrix& A) {
  ScopedSeconds t(stats_.factorizeSeconds, stats_.factorizeCount);
  SparseMatrix storage;
  const SparseMatrix& M = compressedMatrix(A, storage);
  pattern_.requireSame(M, name());
  factorized_ = false;
  bool unsymmetric = false;
  if (sym_ != 0 && !symmetricByConstruction_) {
    try {
      symmetry_->require(M, kSymmetryTolerance, name());
    } catch (const UnsymmetricMatrixError&) {
      if (options_.symmetry != "AUTO") throw;  // TYPE_RESOL said symmetric
      unsymmetric = true;
    }
  }
  if (unsymmetric) start(0);  // LU from now on: a new instance, a new analysis
  loadValues(M);
  if (unsymmetric) runAnalysis();
  runFactorization();
  factorized_ = true;
}

void MumpsSolver::runFactorization() {
  Handle& h = *h_;
  applyControls();
  h.id.a = values_.data();
  const auto startTime = std::chrono::steady_clock::now();
  h.run(2);
  if (workspaceShort(h.infog(1))) {  // once more with twice the margin
    pivotPercent_ *= 2;
    h.icntl(14) = pivotPercent_;
    h.run(2);
  }
  const double numeric = std::chrono::duration<double>(std::chrono::steady_clock::now() - startTime).count();
  if (stats_.numericSeconds == 0.0) stats_.firstNumericSeconds = numeric;
  stats_.numericSeconds += numeric;
  const int code = h.infog(1);
  if (code == -6 || code == -10) throwZeroPivot(name(), -1, -1, " (" + mumpsError(code, h.infog(2)) + ")");
  if (code < 0) throw Error("MUMPS: factorization failed: " + mumpsError(code, h.infog(2)));
  stats_.factorFlops = h.rinfog(3);
  const int entries = h.infog(29);  // negative: millions
  stats_.factorNonzeros = entries >= 0 ? entries : -static_cast<long long>(entries) * 1000000;
  factorMegabytes_ = h.infog(22);
  if (h.infog(28) > 0) {
    const int column = h.id.pivnul_list ? h.id.pivnul_list[0] - 1 : -1;
    std::ostringstream s;
    s << "MUMPS: the matrix is " << (nprec_ > 0 ? "numerically singular" : "singular") << ": " << h.infog(28)
      << " null pivot(s), the first in column " << column;
    if (nprec_ > 0)
      s << " (its row fell below 1e-" << nprec_ << " times the matrix's norm, NPREC = " << nprec_ << ")";
    else
      s << " (zero)";
    s << "; the structure may be free to move (missing Dirichlet conditions?)";
    throw SingularMatrixError(s.str(), column, column);
  }
}

void MumpsSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  ScopedSeconds t(stats_.solveSeconds, stats_.solveCount);
  requireReadyToSolve(factorized_, b);
  rhs_.assign(b.data(), b.data() + b.size());
  Handle& h = *h_;
  h.id.rhs = rhs_.data();
  h.id.nrhs = 1;
  h.id.lrhs = static_cast<int>(b.size());
  h.run(3);
  if (h.infog(1) < 0) throw Error("MUMPS: solve failed: " + mumpsError(h.infog(1), h.infog(2)));
  x = Eigen::Map<const Eigen::VectorXd>(rhs_.data(), b.size());
  if (options_.residualTolerance > 0.0) {
    const double bNorm = b.norm();
    const double residual = bNorm > 0.0 ? (matrix_ * x - b).norm() / bNorm : (matrix_ * x).norm();
    if (!(residual <= options_.residualTolerance)) {
      std::ostringstream s;
      s.precision(3);
      s << "MUMPS: the solution's relative residual ||A x - b|| / ||b|| = " << residual << " exceeds RESI_RELA = "
        << options_.residualTolerance << " (an ill-conditioned or nearly singular matrix)";
      throw Error(s.str());
    }
  }
}

}  // namespace aster::linalg
