#include "analysis/static_nonlinear.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/messages.hpp"
#include "core/number_format.hpp"
#include "analysis/low_rank_update.hpp"
#include "analysis/step_cutting.hpp"
#include "linalg/blas_info.hpp"
#include "linalg/linear_solver.hpp"

namespace aster::analysis {

using format::scientific;

namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a) { return std::chrono::duration<double>(Clock::now() - a).count(); }


}  // namespace

struct StaticNonlinear::SolverHolder {
  std::unique_ptr<linalg::LinearSolver> solver;
};

StaticNonlinear::StaticNonlinear(MechanicalSystem& system, AdditionalTerms* terms, NewtonSettings settings)
    : system_(system), terms_(terms), settings_(std::move(settings)), solver_(std::make_shared<SolverHolder>()) {
  n_ = system_.dofCount();
  if (terms_) {
    terms_->setFirstUnknown(n_);
    n_ += terms_->unknownCount();
  }
  solver_->solver = linalg::makeLinearSolver(settings_.method);
  if (terms_) solver_->solver->setMultipliersFrom(system_.dofCount());
  solver_->solver->setOrdering(settings_.renum);
  solver_->solver->setSingularityDigits(settings_.nprec);
  if (auto* mumps = dynamic_cast<linalg::MumpsSolver*>(solver_->solver.get())) mumps->setOptions(settings_.mumps);
  if (auto* gcpc = dynamic_cast<linalg::GcpcSolver*>(solver_->solver.get())) gcpc->setOptions(settings_.gcpc);
  // Contact's terms keep the check: their symmetry is not exact by construction.
  solver_->solver->setSymmetricByConstruction(!terms_ && (system_.symmetricTangent() || settings_.symmetrize));
  dualized_ = system_.dualizedImposed();
}

void StaticNonlinear::buildPattern() {
  fem::ElementDofs all = system_.elementDofs();
  termsFirstElement_ = all.elementCount();
  if (terms_) terms_->elementDofs(all);
  // Every unknown gets its diagonal: eliminated rows become identity rows.
  for (int i = 0; i < n_; ++i) all.add(&i, 1);
  pattern_ = std::make_unique<fem::AssemblyPattern>(n_, all);
  pattern_->takeMatrix(K_);
  Kelastic_.resize(0, 0);
  analyzed_ = false;
  factorized_ = Factorized::None;
  lastFixed_.clear();
  lastElimination_.reset();
}

void StaticNonlinear::assemble(const Eigen::VectorXd& U, double t, bool withMatrix, bool naturalState) {
  const auto start = Clock::now();
  if (withMatrix) ++stats_.tangentAssemblies;  // evaluate() sets every value of K_
  system_.evaluate(U, t, fint_, fext_, pattern_.get(), withMatrix ? &K_ : nullptr, naturalState);
  r_.setZero(n_);
  r_.head(system_.dofCount()) = fint_ - fext_;
  if (terms_) terms_->assemble(U, r_, *pattern_, termsFirstElement_, withMatrix ? &K_ : nullptr);
  if (withMatrix && settings_.symmetrize) linalg::symmetrizeValues(K_);  // the pattern is structurally symmetric
  stats_.assemblySeconds += seconds(start);
}

struct StaticNonlinear::Step {
  double t0 = 0, t1 = 0;
  std::vector<std::pair<int, double>> imposed;  // imposed displacements at t1
  Eigen::VectorXd Ustart;                       // the state the step starts from
  // The size of the displacements the data of the step give: the state it starts from
  // and the imposed values (the round-off test of convergence()).
  double dataScale = 0;
  std::vector<char> fixed;  // per unknown: imposed, or fixed by the additional terms
  Eigen::VectorXd target;   // values of the fixed unknowns
  // With linear relations: the fixed values and the relations at t1, eliminated.
  std::shared_ptr<const linalg::ConstraintElimination> elimination;
  bool statusChanged = false;  // the additional terms changed status with the last correction
  bool statusesSettled = false;  // the active-set loop changed a correction (settleStatuses)
};

struct StaticNonlinear::Iteration {
  double time = 0;  // the step's end, t1
  int k = 0;
  Clock::time_point start;
  bool elastic = false;          // the elastic matrix serves this iteration
  bool assembleTangent = false;  // the tangent at U is assembled (else the kept factorization serves)
  bool residualFirst = false;    // the residual is assembled alone first, the tangent only if needed
  double rela = 0, resMax = 0;   // RESI_GLOB_RELA, RESI_GLOB_MAXI
  bool dirichletMet = true;      // U holds the imposed values
  std::string contact;           // the terms' status when the residual was measured (for the observers)
  bool refactored = false;
  Eigen::VectorXd correction;    // the Newton correction dU of this iteration
  bool fixedKept = false;        // dU leaves the fixed unknowns (and the relations) as they were
  int lineSearchTrials = -1;     // residuals the line search evaluated (-1: no line search)
  double rho = 1;                // the coefficient it chose
};

bool StaticNonlinear::solveStep(Eigen::VectorXd& U, double t0, double t1, std::vector<double>& history,
                                std::string& why) {
  Step step;
  step.t0 = t0;
  step.t1 = t1;
  step.imposed = system_.imposed(t1);
  step.fixed.assign(n_, 0);
  step.target = Eigen::VectorXd::Zero(n_);
  step.Ustart = U;
  step.dataScale = U.head(system_.dofCount()).lpNorm<Eigen::Infinity>();
  for (const auto& [d, v] : step.imposed) step.dataScale = std::max(step.dataScale, std::fabs(v));
  history.clear();
  dualizedPredictionValid_ = false;
  // PREDICTION='EXTRAPOLE': start from U_n + (dt_{n+1} / dt_n) (U_n - U_{n-1}), the last
  // converged (sub-)step's increment; the first step has none and starts from U_n.
  if (settings_.prediction == Prediction::Extrapolated && previousDt_ > 0)
    U += ((t1 - t0) / previousDt_) * previousIncrement_;
  for (NewtonObserver* o : observers_) o->stepStarted(t0, t1);
  for (int k = 0;; ++k) {
    Iteration it;
    it.time = t1;
    it.k = k;
    it.start = Clock::now();
    // Ctrl-C: the unconverged instant is abandoned; the converged ones are kept.
    if (interrupt::requested())
      throw Interrupted("interrupted (SIGINT) during the instant " + scientific(t1, 6) + " (Newton iteration " +
                        std::to_string(k) + "), which is abandoned");
    if (terms_ && terms_->update(U)) buildPattern();
    if (!pattern_) buildPattern();
    chooseMatrix(step, history, it);
    try {
      assembleIteration(U, step, it);
    } catch (const InvalidStateError& e) {
      // An inverted cell after too large a correction: the step may succeed
      // when cut, as with code_aster's EVENEMENT='ERREUR'. Invalid data (a
      // load that is not finite) stops at once.
      why = e.what();
      stats_.iterations += k;
      return false;
    }
    fixUnknowns(step);
    // A kept tangent factorization eliminated other unknowns: assemble anew.
    if (!it.elastic && !it.assembleTangent && !sameConstraints(step)) {
      assemble(U, t1, true);
      it.assembleTangent = true;
    }
    if (!measureResidual(step, it, history, why)) return false;
    const Verdict verdict = convergence(U, step, it);
    if (verdict == Verdict::Converged) {
      report(it, "");
      stats_.iterations += k;
      finishStep(U, step.Ustart, t1, t1 - t0);
      for (NewtonObserver* o : observers_) o->stepConverged(t1, k, true);
      return true;
    }
    if (verdict == Verdict::Exhausted) {
      report(it, "");
      why = "no convergence in ITER_GLOB_MAXI = " + std::to_string(settings_.iterGlobMaxi) + " Newton iterations (" +
            (settings_.useRela ? "RESI_GLOB_RELA = " + scientific(it.rela, 3) + (settings_.useMaxi ? ", " : "") : "") +
            (settings_.useMaxi ? "RESI_GLOB_MAXI = " + scientific(it.resMax, 3) : "") + ")";
      stats_.iterations += k;
      if (!settings_.arret && it.dirichletMet) {
        // CONVERGENCE/ARRET='NON': the step is kept as it is.
        Messages::alarm("STAT_NON_LINE", "instant " + scientific(t1, 6) + ": " + why +
                                             "; the step is accepted as it is (CONVERGENCE/ARRET='NON')");
        finishStep(U, step.Ustart, t1, t1 - t0);
        for (NewtonObserver* o : observers_) o->stepConverged(t1, k, false);
        return true;
      }
      return false;
    }
    if (it.residualFirst) assemble(U, t1, true);  // same state: same residual, and now the tangent
    factorAndSolve(U, step, it);
    settleStatuses(U, step, it);
    searchLine(U, step, it);
    predictDualizedResidual(it);
    report(it, !it.refactored ? "" : it.elastic ? "ELASTIQUE" : "TANGENTE");
    step.statusChanged = terms_ ? terms_->updateStatus(U) : false;
  }
}

// The matrix of this iteration: the elastic one, or the tangent at U assembled now, or the
// factorization kept from before (REAC_ITER, REAC_INCR).
void StaticNonlinear::chooseMatrix(const Step& step, const std::vector<double>& history, Iteration& it) const {
  const int k = it.k;
  it.elastic = settings_.elasticMatrix;
  it.assembleTangent = false;
  if (k == 0 && settings_.prediction == Prediction::Elastic) {
    it.elastic = true;
  } else if (k == 0 && settings_.prediction == Prediction::Tangent) {
    it.elastic = false;
    it.assembleTangent = factorized_ != Factorized::Tangent || steps_ == 0 ||
                         (settings_.reacIncr > 0 && steps_ % settings_.reacIncr == 0);
  } else if (!it.elastic) {
    it.assembleTangent = factorized_ != Factorized::Tangent || k == 0 ||
                         (settings_.reacIter > 0 && k % settings_.reacIter == 0);
  }
  // Near convergence the tangent is often not needed: Newton converges quadratically, so a
  // relative residual below the square root of RESI_GLOB_RELA is usually followed by a
  // converged one. The residual is then assembled alone first (a fifth of the cost of
  // residual and tangent), and the tangent only if the iteration goes on (SVK square:
  // 5 of 20 tangent assemblies saved). Not before the third iteration: the first one's
  // residual is the previous instant's (imposed displacements enter with the first
  // correction) and says nothing of the coming one.
  it.residualFirst = it.assembleTangent && k >= 2 && !step.statusChanged && settings_.useRela &&
                     !settings_.useMaxi && history.back() <= std::sqrt(settings_.resiGlobRela);
}

// The residual at U (and the tangent, as chosen), and the elastic matrix the first time it serves.
void StaticNonlinear::assembleIteration(const Eigen::VectorXd& U, const Step& step, Iteration& it) {
  assemble(U, step.t1, it.assembleTangent && !it.residualFirst);
  // The prediction from the accepted state (tangent or elastic matrix) balances its internal
  // forces, as code_aster's: with a viscous law they are not those of the state integrated
  // over the step at the same displacement (the relaxed ones).
  if (it.k == 0 && settings_.prediction != Prediction::Extrapolated && system_.predictsFromAcceptedState() && U == step.Ustart) {
    Eigen::VectorXd accepted;
    system_.internalForces(U, accepted);
    r_.head(system_.dofCount()) += accepted - fint_;
    fint_ = accepted;
  }
  if (it.elastic && Kelastic_.size() == 0) {
    Eigen::VectorXd zero = Eigen::VectorXd::Zero(n_);
    Eigen::VectorXd keepFint = fint_, keepFext = fext_, keepR = r_;
    // The laws' initial elastic matrix: at U = 0 from the natural state, whatever the
    // history (a plastic state, a restart).
    assemble(zero, step.t1, true, true);
    Kelastic_ = K_;
    fint_ = keepFint;
    fext_ = keepFext;
    r_ = keepR;
  }
}

// The fixed unknowns: imposed displacements, and what the terms fix.
void StaticNonlinear::fixUnknowns(Step& step) const {
  std::fill(step.fixed.begin(), step.fixed.end(), 0);
  for (const auto& [d, v] : step.imposed) {
    step.fixed[d] = 1;
    step.target(d) = v;
  }
  if (terms_) {
    std::vector<int> extra;
    terms_->fixedUnknowns(extra);
    for (int d : extra) {
      step.fixed[d] = 1;
      step.target(d) = 0.0;
    }
  }
  if (system_.hasLinearRelations())
    step.elimination = std::make_shared<const linalg::ConstraintElimination>(
        system_.eliminate(step.fixed, step.target, step.t1));
}

bool StaticNonlinear::sameConstraints(const Step& step) const {
  if (step.fixed != lastFixed_) return false;
  if (!step.elimination) return true;
  return lastElimination_ && step.elimination->sameTransformation(*lastElimination_);
}

// Residual on the free unknowns, relative to the forces that balance the internal forces
// (external loads plus support reactions), as code_aster. False when it is not a number.
bool StaticNonlinear::measureResidual(const Step& step, Iteration& it, std::vector<double>& history,
                                      std::string& why) {
  const int nm = system_.dofCount();
  // With relations, the residual of the free unknowns is T^T r: a master's own and what its
  // slaves pass on to it.
  // The loads that balance fint likewise: r - fint, reduced.
  Eigen::VectorXd reduced, balance;
  if (step.elimination) {
    reduced = step.elimination->reduce(r_);
    balance = r_;
    balance.head(nm) -= fint_;
    balance = step.elimination->reduce(balance);
  }
  const Eigen::VectorXd& res = step.elimination ? reduced : r_;
  const std::vector<char>& constrained = step.elimination ? step.elimination->constrained() : step.fixed;
  double resMax = 0, denom = 0;
  for (int i = 0; i < n_; ++i) {
    if (constrained[i]) {
      if (i < nm) denom = std::max(denom, std::fabs(fint_(i)));
      continue;
    }
    resMax = std::max(resMax, std::fabs(res(i)));
    if (i < nm) denom = std::max(denom, std::fabs(step.elimination ? balance(i) : r_(i) - fint_(i)));  // the loads that balance fint
  }
  if (!std::isfinite(resMax)) {
    why = "the residual is not a number (the state became invalid)";
    return false;
  }
  // At the supports of AFFE_CHAR_MECA, as code_aster: r beyond its linear prediction.
  dualizedResidual_.setZero(static_cast<int>(dualized_.size()));
  if (dualizedPredictionValid_)
    for (size_t j = 0; j < dualized_.size(); ++j)
      if (step.fixed[dualized_[j]]) {
        dualizedResidual_(j) = r_(dualized_[j]) - dualizedPredicted_(j);
        resMax = std::max(resMax, std::fabs(dualizedResidual_(j)));
      }
  it.resMax = resMax;
  it.rela = denom > 0 ? resMax / denom : resMax;
  history.push_back(settings_.useRela ? it.rela : resMax);
  // The observers' contact column says how contact stands when the residual is measured.
  if (terms_ && !observers_.empty()) it.contact = terms_->statusText();
  return true;
}

// CONVERGENCE: every criterion given must hold, after at least one correction, with the
// imposed values reached and the terms' status settled.
StaticNonlinear::Verdict StaticNonlinear::convergence(const Eigen::VectorXd& U, const Step& step,
                                                      Iteration& it) const {
  const bool criteriaMet = (!settings_.useRela || it.rela <= settings_.resiGlobRela) &&
                           (!settings_.useMaxi || it.resMax <= settings_.resiGlobMaxi) &&
                           (settings_.useRela || settings_.useMaxi);
  // With no load at all (a rigid motion imposed, say) the relative residual is
  // noise over noise: accept a residual at round-off level of the stiffness forces
  // of displacements of the size the data give. Not of the current ones: a
  // singular matrix solved anyway (NPREC <= 0, STOP_SINGULIER='NON') gives
  // displacements of 1e13 whose round-off would hide a residual that does not fall.
  double kmax = 0;
  const linalg::SparseMatrix& Kscale = it.elastic ? Kelastic_ : K_;
  for (int i = 0; i < Kscale.outerSize(); ++i) kmax = std::max(kmax, std::fabs(Kscale.coeff(i, i)));
  const bool atRoundOff = it.resMax <= 1e-13 * kmax * step.dataScale;
  it.dirichletMet = true;
  for (const auto& [d, v] : step.imposed)
    it.dirichletMet = it.dirichletMet && std::fabs(U(d) - v) <= 1e-12 * (1 + std::fabs(v));
  if (step.elimination) {
    const Eigen::VectorXd P = step.elimination->expand(U);
    for (int i = 0; i < n_ && it.dirichletMet; ++i)
      if (step.elimination->isSlave(i)) it.dirichletMet = std::fabs(U(i) - P(i)) <= 1e-12 * (1 + std::fabs(P(i)));
  }
  if (it.k > 0 && (criteriaMet || atRoundOff) && !step.statusChanged && it.dirichletMet) return Verdict::Converged;
  if (it.k >= settings_.iterGlobMaxi) return Verdict::Exhausted;
  return Verdict::Iterate;
}

// Rows and columns of the fixed unknowns replaced by the identity's (a symmetric matrix stays symmetric).
// Newton correction: K dU = -r on the free unknowns, dU = target - U on the fixed ones;
// the matrix is eliminated and factorized again when it changed.
void StaticNonlinear::factorAndSolve(Eigen::VectorXd& U, const Step& step, Iteration& it) {
  if (step.elimination) {
    solveWithRelations(U, step, it);
    return;
  }
  const auto solveStart = Clock::now();
  linalg::LinearSolver& solver = *solver_->solver;
  Eigen::VectorXd dUc = Eigen::VectorXd::Zero(n_);
  for (int i = 0; i < n_; ++i)
    if (step.fixed[i]) dUc(i) = step.target(i) - U(i);
  const linalg::SparseMatrix& Kuse = it.elastic ? Kelastic_ : K_;
  Eigen::VectorXd rhs = -r_;
  if (dUc.lpNorm<Eigen::Infinity>() > 0) rhs -= Kuse * dUc;
  for (int i = 0; i < n_; ++i)
    if (step.fixed[i]) rhs(i) = dUc(i);
  it.refactored = it.assembleTangent || (it.elastic && factorized_ != Factorized::Elastic) ||
                  step.fixed != lastFixed_;
  if (it.refactored) {
    // A tangent is eliminated in place (it is assembled again before it is factorized
    // again); the elastic matrix, kept for the whole run, is copied first.
    if (!dualized_.empty()) {
      linalg::SparseMatrix select(static_cast<int>(dualized_.size()), n_);
      std::vector<Eigen::Triplet<double>> ones;
      for (size_t j = 0; j < dualized_.size(); ++j) ones.emplace_back(static_cast<int>(j), dualized_[j], 1.0);
      select.setFromTriplets(ones.begin(), ones.end());
      dualizedRows_ = select * Kuse;
    }
    if (it.elastic) KelasticEliminated_ = Kelastic_;
    linalg::SparseMatrix& A = it.elastic ? KelasticEliminated_ : K_;
    linalg::eliminateFixedUnknowns(A, step.fixed);
    factorized_ = Factorized::None;
    factorize(A, false, it, &rhs, &it.correction);
    factorized_ = it.elastic ? Factorized::Elastic : Factorized::Tangent;
    lastFixed_ = step.fixed;
  } else {
    solver.solve(rhs, it.correction);
  }
  if (terms_) solvedRhs_ = std::move(rhs);
  stats_.solveSeconds += seconds(solveStart);
  it.fixedKept = dUc.lpNorm<Eigen::Infinity>() == 0;
  U += it.correction;
  if (!dualized_.empty()) {
    dualizedPredicted_.resize(static_cast<int>(dualized_.size()));
    for (size_t j = 0; j < dualized_.size(); ++j) dualizedPredicted_(j) = r_(dualized_[j]);
    dualizedPredictionValid_ = true;
  }
}

// The active-set loop: the terms' statuses (contact) settled on the linearized
// problem within the iteration. The correction dU was solved with the statuses
// of U; the terms may release some (those the linearized problem at U + dU
// puts in tension, AdditionalTerms::linearizedStatusChanges): dU is solved
// again with them, from the same factorization (low_rank_update.hpp), until
// none is left, a primal-dual active set method on the linearized problem
// (Hueber and Wohlmuth, Comput. Methods Appl. Mech. Engrg. 194 (2005)
// 3147-3166; Popp et al., Int. J. Numer. Meth. Engng 79 (2009) 1354-1391,
// whose semi-smooth Newton is the outer one here) inside the semi-smooth
// Newton of the nonlinear problem. Without it, an active set that overshoots
// (each increment's first correction, with the last increment's zone,
// penetrates past the new one) shrinks by a node or two per zone end per
// iteration (SSNP150 with LAC: 51 iterations against 37 at N = 64, 61 against
// 37 at N = 128; docs/performance.md). Not at the prediction (k = 0), whose
// correction moves the zones by many nodes, each one a solve, more than the
// factorizations saved; at most kStatusSolves solves, and once per step (a
// multiplier the linearized problem releases and the nonlinear one keeps
// would otherwise be released at every iteration). The loop changes only the
// iterates: an iteration whose correction it changed is not the last (the
// next residual is measured with the statuses of the new U, and the
// convergence test is unchanged), so the converged state is the same.
void StaticNonlinear::settleStatuses(Eigen::VectorXd& U, Step& step, Iteration& it) {
  constexpr int kStatusLoops = 20, kStatusSolves = 256;
  if (!terms_ || it.k == 0 || step.statusesSettled || !it.refactored || it.elastic || step.elimination) return;
  const auto start = Clock::now();
  const Eigen::VectorXd Ubefore = U - it.correction;
  const Eigen::VectorXd solved = it.correction;
  std::vector<AdditionalTerms::StatusChange> changes, applied;
  if (!terms_->linearizedStatusChanges(Ubefore, it.correction, changes)) return;
  // The terms' statuses read dU on their elements' unknowns: the rows kept.
  fem::ElementDofs elements;
  terms_->elementDofs(elements);
  std::vector<char> onTerms(n_, 0);
  for (int e = 0; e < elements.elementCount(); ++e)
    for (int j = 0; j < elements.size(e); ++j)
      if (elements.dofs(e)[j] >= 0) onTerms[elements.dofs(e)[j]] = 1;
  std::vector<int> rows;
  for (int i = 0; i < n_; ++i)
    if (onTerms[i]) rows.push_back(i);
  LowRankUpdate update(*solver_->solver, K_, step.fixed, solvedRhs_, solved, std::move(rows));
  for (int loop = 0; loop < kStatusLoops; ++loop) {
    if (update.solves() + update.solvesNeeded(changes) > kStatusSolves) break;
    Eigen::VectorXd x;
    if (!update.solve(changes, x, false)) break;
    it.correction = std::move(x);
    applied = std::move(changes);
    ++stats_.statusLoops;
    changes.clear();
    if (!terms_->linearizedStatusChanges(Ubefore, it.correction, changes)) break;
  }
  if (!applied.empty() && !update.solve(applied, it.correction, true)) it.correction = solved;
  step.statusesSettled = !applied.empty();
  stats_.statusSolves += update.solves();
  if (it.correction != solved) U += it.correction - solved;
  // The supports' prediction r + K dU: the rows of the changed columns.
  if (dualizedPredictionValid_ && it.correction != solved)
    for (const auto& c : applied)
      if (c.symmetric)
        for (const auto& [d, a] : c.row)
          for (std::size_t j = 0; j < dualized_.size(); ++j)
            if (dualized_[j] == d) dualizedRows_.coeffRef(static_cast<int>(j), c.unknown) += a;
  stats_.solveSeconds += seconds(start);
}

// The linear prediction of r at the supports of AFFE_CHAR_MECA after the correction
// (times the line search's coefficient).
void StaticNonlinear::predictDualizedResidual(const Iteration& it) {
  if (!dualizedPredictionValid_) return;
  dualizedPredicted_ += it.rho * (dualizedRows_ * it.correction) - (1 - it.rho) * dualizedResidual_;
}

// With linear relations: dU = T dv + g_d, where g_d = (T U + g) - U brings U onto the
// relations and fixed values (zero at the masters), and T^T K T dv = T^T (-r - K g_d).
// K itself is kept: the reduced matrix is a new one.
void StaticNonlinear::solveWithRelations(Eigen::VectorXd& U, const Step& step, Iteration& it) {
  const auto solveStart = Clock::now();
  const linalg::ConstraintElimination& e = *step.elimination;
  const linalg::SparseMatrix& Kuse = it.elastic ? Kelastic_ : K_;
  const Eigen::VectorXd gd = e.expand(U) - U;
  Eigen::VectorXd rhs = -r_;
  if (gd.lpNorm<Eigen::Infinity>() > 0) rhs -= Kuse * gd;
  rhs = e.reduce(rhs);
  it.refactored = it.assembleTangent || (it.elastic && factorized_ != Factorized::Elastic) || !sameConstraints(step);
  if (it.refactored) {
    const bool patternChanged = !lastElimination_ || !e.sameTransformation(*lastElimination_);
    factorized_ = Factorized::None;
    reduced_ = e.reduce(Kuse);
    factorize(reduced_, patternChanged, it);
    factorized_ = it.elastic ? Factorized::Elastic : Factorized::Tangent;
    lastFixed_ = step.fixed;
    lastElimination_ = step.elimination;
  }
  Eigen::VectorXd dv;
  solver_->solver->solve(rhs, dv);
  stats_.solveSeconds += seconds(solveStart);
  dualizedPredictionValid_ = false;  // with relations, the supports' residual is not measured
  it.correction = e.expand(dv) - e.offset() + gd;
  it.fixedKept = gd.lpNorm<Eigen::Infinity>() == 0;
  U += it.correction;
}

// RECH_LINEAIRE: U = U_before + rho dU with f(rho) = dU . r(U_before + rho dU) near zero.
// The fixed unknowns and the relations hold along dU when it leaves them as they were,
// so r's rows there do not enter (dU is zero on them, or, with relations, the projection
// is T^T r's). Not on the prediction, whose correction brings in the imposed values.
void StaticNonlinear::searchLine(Eigen::VectorXd& U, const Step& step, Iteration& it) {
  if (!settings_.lineSearch || it.k == 0 || !it.fixedKept) return;
  const Eigen::VectorXd& dU = it.correction;
  const Eigen::VectorXd start = U - dU;
  const double f0 = dU.dot(r_);  // r_ is the residual at the start of the iteration
  auto functional = [&](double rho, double& f) {
    try {
      assemble(start + rho * dU, step.t1, false);
    } catch (const InvalidStateError&) {
      return false;  // too long a step: the search keeps the best rho before it
    }
    f = dU.dot(r_);
    return std::isfinite(f);
  };
  const LineSearchOutcome found = lineSearch(settings_.lineSearchSettings, f0, functional);
  stats_.lineSearchTrials += found.trials;
  it.lineSearchTrials = found.trials;
  it.rho = found.rho;
  U = start + found.rho * dU;
}

// With rhs, also solves A x = rhs into x (the factorization may take part of the solve).
void StaticNonlinear::factorize(const linalg::SparseMatrix& A, bool patternChanged, const Iteration& it,
                                const Eigen::VectorXd* rhs, Eigen::VectorXd* x) {
  linalg::LinearSolver& solver = *solver_->solver;
  try {
    if (!analyzed_ || patternChanged) {
      if (!analyzed_) linalg::chooseBlasThreads(static_cast<int>(A.rows()));
      solver.analyze(A);
      analyzed_ = true;
    }
    if (rhs)
      solver.factorizeAndSolve(A, *rhs, *x);
    else
      solver.factorize(A);
  } catch (const linalg::SingularMatrixError& e) {
    report(it, it.elastic ? "ELASTIQUE" : "TANGENTE");
    throwSingular(e);
  }
  ++stats_.factorizations;
}

// The solver's message, with the unknown it names and, with contact, how contact stands.
void StaticNonlinear::throwSingular(const linalg::SingularMatrixError& e) const {
  const int nm = system_.dofCount();
  std::string where;
  const int col = e.column() >= 0 ? e.column() : e.row();
  if (col >= 0 && col < nm) {
    const std::string unknown = system_.unknownName(col);
    if (!unknown.empty()) where = " (" + unknown + ")";
  } else if (col >= nm) {
    where = " (a contact unknown)";
  }
  // Surfaces that never meet leave the body free: say how contact stands.
  if (terms_) where += " (contact: " + terms_->statusText() + ")";
  throw Error(std::string(e.what()) + where);
}

// Tells the observers the iteration is done; `matrix`: what it factorized.
void StaticNonlinear::report(const Iteration& it, const char* matrix) const {
  if (observers_.empty()) return;
  NewtonIteration done;
  done.time = it.time;
  done.index = it.k;
  done.rela = it.rela;
  done.maxi = it.resMax;
  done.matrix = matrix;
  done.seconds = seconds(it.start);
  done.contact = it.contact;
  done.lineSearchTrials = it.lineSearchTrials;
  done.rho = it.rho;
  for (NewtonObserver* o : observers_) o->iterationDone(done);
}

void StaticNonlinear::finishStep(const Eigen::VectorXd& U, const Eigen::VectorXd& Ustart, double t1, double dt) {
  system_.acceptState(U, t1);
  previousIncrement_ = U - Ustart;
  previousDt_ = dt;
  ++steps_;
}

const linalg::LinearSolverStatistics& StaticNonlinear::solverStatistics() const { return solver_->solver->statistics(); }

void StaticNonlinear::run(Eigen::VectorXd& U, const std::vector<double>& times,
                          const std::function<void(const ConvergedInstant&)>& converged) {
  const auto start = Clock::now();
  if (U.size() != n_) throw Error("internal error: the initial state has the wrong size");
  system_.acceptInitialState(U, times.empty() ? 0.0 : times.front());  // from the natural state or ETAT_INIT's
  std::vector<double> history;
  bool cutFloorReached = false;  // the failure is a step that would be cut below SUBD_PAS_MINI
  // The shortest sub-step without SUBD_PAS_MINI: at the round-off of the instants.
  const double roundOff =
      times.empty() ? 0.0
                    : 1e-12 * std::max({std::fabs(times.front()), std::fabs(times.back()), times.back() - times.front()});
  std::function<bool(double, double, int, std::string&)> interval = [&](double t0, double t1, int level,
                                                                        std::string& why) {
    const Eigen::VectorXd U0 = U, increment0 = previousIncrement_;
    const double dt0 = previousDt_;
    const int steps0 = steps_;
    if (terms_) terms_->saveStatus();
    if (solveStep(U, t0, t1, history, why)) return true;
    U = U0;
    previousIncrement_ = increment0;  // sub-steps start again from the last state kept
    previousDt_ = dt0;
    steps_ = steps0;
    if (terms_) terms_->restoreStatus();
    if (settings_.subdNiveau == 0) return false;  // ACTION='ARRET'
    StepCut cut;
    if (settings_.subdAuto) {
      cut = automaticCut(history, settings_.useRela ? settings_.resiGlobRela : settings_.resiGlobMaxi,
                         settings_.iterGlobMaxi);
    } else {
      if (level >= settings_.subdNiveau || settings_.subdPas < 2) return false;
      cut.parts = settings_.subdPas;
      cut.firstFraction = 1.0 / settings_.subdPas;
    }
    const std::vector<double> ends = subStepEnds(t0, t1, cut);
    double shortest = ends.front() - t0;
    for (std::size_t i = 1; i < ends.size(); ++i) shortest = std::min(shortest, ends[i] - ends[i - 1]);
    // Without SUBD_PAS_MINI, AUTO (no level limit) stops at sub-steps at round-off of the instants.
    const double floor = std::max(settings_.subdPasMini, roundOff);
    if (shortest < floor || shortest <= 0) {
      why += "; cutting the step [" + scientific(t0, 6) + ", " + scientific(t1, 6) + "] into " +
             std::to_string(cut.parts) + " would make a sub-step of " + scientific(shortest, 3) +
             (settings_.subdPasMini > 0 ? ", below SUBD_PAS_MINI = " + scientific(settings_.subdPasMini, 3)
                                        : ", at the round-off of the instants");
      cutFloorReached = true;
      return false;
    }
    ++stats_.cuts;
    const std::string how =
        !settings_.subdAuto ? ""
        : cut.extrapolated  ? " (SUBD_METHODE='AUTO', from the residuals' extrapolation: a first sub-step of " +
                                 scientific(ends.front() - t0, 4) + ")"
                            : " (SUBD_METHODE='AUTO', equal sub-steps: too few iterations to extrapolate)";
    Messages::alarm("STAT_NON_LINE", "instant " + scientific(t1, 6) + ": " + why + "; the step [" + scientific(t0, 4) +
                                         ", " + scientific(t1, 4) + "] is cut into " + std::to_string(cut.parts) +
                                         how + " (level " + std::to_string(level + 1) + ")");
    for (NewtonObserver* o : observers_) o->stepCut(t0, t1, cut.parts, level + 1, why);
    double a = t0;
    for (double b : ends) {
      if (!interval(a, b, level + 1, why)) return false;
      a = b;
    }
    return true;
  };
  for (std::size_t k = 1; k < times.size(); ++k) {
    std::string why;
    if (!interval(times[k - 1], times[k], 0, why)) {
      stats_.totalSeconds += seconds(start);
      // Without the pivot test a singular matrix is solved anyway: its garbage
      // correction is what keeps the residual from falling.
      const std::string singular =
          settings_.nprec <= 0 ? "; SOLVEUR: NPREC <= 0 or STOP_SINGULIER = 'NON' solves even a singular matrix, "
                                 "whose corrections do not reduce the residual: check the Dirichlet conditions "
                                 "(the default NPREC names a free unknown)"
                               : "";
      throw Error("the instant " + scientific(times[k], 6) + " did not converge: " + why +
                  (settings_.subdNiveau > 0 && !settings_.subdAuto && !cutFloorReached
                       ? " (even after cutting the step " + std::to_string(settings_.subdNiveau) + " times)"
                       : "") +
                  singular);
    }
    Eigen::VectorXd reactions = r_;
    Eigen::VectorXd internalForces = fint_;
    ConvergedInstant c;
    c.time = times[k];
    c.U = &U;
    c.reactions = &reactions;
    c.internalForces = &internalForces;
    c.iterations = static_cast<int>(history.size()) - 1;
    c.residuals = history;
    converged(c);
  }
  stats_.totalSeconds += seconds(start);
}

}  // namespace aster::analysis
