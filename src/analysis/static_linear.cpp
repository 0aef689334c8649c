#include "analysis/static_linear.hpp"

#include <chrono>
#include <cmath>

#include "core/error.hpp"
#include "linalg/blas_info.hpp"

namespace aster::analysis {
namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a) { return std::chrono::duration<double>(Clock::now() - a).count(); }

}  // namespace

StaticLinear::StaticLinear(const MechanicalSystem& system, LinearSettings settings)
    : system_(system), settings_(std::move(settings)) {
  solver_ = linalg::makeLinearSolver(settings_.method);
  solver_->setOrdering(settings_.renum);
  solver_->setFactorizationsPerAnalysis(1);  // one per stiffness, whatever the instants
  solver_->setSingularityDigits(settings_.nprec);
  if (auto* mumps = dynamic_cast<linalg::MumpsSolver*>(solver_.get())) mumps->setOptions(settings_.mumps);
  if (auto* gcpc = dynamic_cast<linalg::GcpcSolver*>(solver_.get())) gcpc->setOptions(settings_.gcpc);
  solver_->setSymmetricByConstruction(system_.symmetricTangent());
}

StaticLinear::~StaticLinear() = default;

void StaticLinear::run(const std::vector<double>& times,
                       const std::function<void(const ConvergedInstant&)>& solved) {
  const auto start = Clock::now();
  const int n = system_.dofCount();
  // The pattern: every term with a stiffness, and every diagonal (eliminated rows become identity rows).
  fem::ElementDofs all = system_.elementDofs();
  for (int i = 0; i < n; ++i) all.add(&i, 1);
  fem::AssemblyPattern pattern(n, all);
  linalg::SparseMatrix K, A;
  pattern.takeMatrix(K);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd fint, fext;
  bool assembled = false;
  std::vector<char> factorizedFixed;  // the fixed unknowns of the factorization held (empty: none)
  for (double t : times) {
    auto assemblyStart = Clock::now();
    // K = dFint/dU at U = 0 (the same at every U: the problem is linear), and F(t).
    system_.evaluate(zero, t, fint, fext, assembled ? nullptr : &pattern, assembled ? nullptr : &K);
    assembled = true;
    stats_.assemblySeconds += seconds(assemblyStart);
    const auto solveStart = Clock::now();
    std::vector<char> fixed(n, 0);
    Eigen::VectorXd target = Eigen::VectorXd::Zero(n);
    for (const auto& [d, v] : system_.imposed(t)) {
      fixed[d] = 1;
      target(d) = v;
    }
    Eigen::VectorXd U;
    if (system_.hasLinearRelations()) {
      U = solveWithRelations(K, fext - fint, fixed, target, t);
    } else {
      if (fixed != factorizedFixed) {
        A = K;
        linalg::eliminateFixedUnknowns(A, fixed);
        factorizedFixed.clear();
        factorize(A, false);
        factorizedFixed = fixed;
      }
      // Free unknowns: K_ff U_f = F_f - K_fd U_d; fixed ones: their values.
      Eigen::VectorXd rhs = fext - fint;
      if (target.lpNorm<Eigen::Infinity>() > 0) rhs -= K * target;
      for (int i = 0; i < n; ++i)
        if (fixed[i]) rhs(i) = target(i);
      solver_->solve(rhs, U);
    }
    stats_.solveSeconds += seconds(solveStart);
    if (!U.allFinite()) throw Error("the solution at the instant " + std::to_string(t) + " is not a number");
    assemblyStart = Clock::now();
    system_.evaluate(U, t, fint, fext, nullptr, nullptr);
    stats_.assemblySeconds += seconds(assemblyStart);
    Eigen::VectorXd reactions = fint - fext;
    ConvergedInstant c;
    c.time = t;
    c.U = &U;
    c.reactions = &reactions;
    c.internalForces = &fint;
    solved(c);
  }
  stats_.totalSeconds += seconds(start);
}

void StaticLinear::factorize(const linalg::SparseMatrix& A, bool patternChanged) {
  try {
    if (!analyzed_ || patternChanged) {
      if (!analyzed_) linalg::chooseBlasThreads(static_cast<int>(A.rows()));
      solver_->analyze(A);
      analyzed_ = true;
    }
    solver_->factorize(A);
  } catch (const linalg::SingularMatrixError& e) {
    throwSingular(e);
  }
  ++stats_.factorizations;
}

// U = T v + g with T^T K T v = T^T (F - K g): the relations hold exactly, and the residual
// F - K U at the slave unknowns is what the relations transmit (the reactions there).
Eigen::VectorXd StaticLinear::solveWithRelations(const linalg::SparseMatrix& K, const Eigen::VectorXd& load,
                                                 const std::vector<char>& fixed, const Eigen::VectorXd& target,
                                                 double t) {
  const linalg::ConstraintElimination elimination = system_.eliminate(fixed, target, t);
  if (!factorizedElimination_ || !elimination.sameTransformation(*factorizedElimination_)) {
    factorizedElimination_.reset();
    // Another transformation gives another pattern of T^T K T: analyzed again.
    factorize(elimination.reduce(K), true);
    factorizedElimination_ = std::make_unique<linalg::ConstraintElimination>(elimination);
  }
  const Eigen::VectorXd rhs = elimination.reduce(Eigen::VectorXd(load - K * elimination.offset()));
  Eigen::VectorXd v;
  solver_->solve(rhs, v);
  return elimination.expand(v);
}

// The solver's message, with the unknown it names.
void StaticLinear::throwSingular(const linalg::SingularMatrixError& e) const {
  const int col = e.column() >= 0 ? e.column() : e.row();
  const std::string unknown = col >= 0 ? system_.unknownName(col) : "";
  const std::string where = unknown.empty() ? "" : " (" + unknown + ")";
  throw Error(std::string(e.what()) + where + ": check that the Dirichlet conditions fix every rigid-body motion");
}

}  // namespace aster::analysis
