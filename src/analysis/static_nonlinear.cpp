#include "analysis/static_nonlinear.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/messages.hpp"
#include "linalg/blas_info.hpp"
#include "linalg/linear_solver.hpp"

namespace aster::analysis {
namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a) { return std::chrono::duration<double>(Clock::now() - a).count(); }

std::string sci(double v, int digits = 6) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*E", digits, v);
  return buf;
}

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
  // Contact's terms keep the check: their symmetry is not exact by construction.
  solver_->solver->setSymmetricByConstruction(!terms_ && system_.symmetricTangent());
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
}

void StaticNonlinear::assemble(const Eigen::VectorXd& U, double t, bool withMatrix) {
  const auto start = Clock::now();
  if (withMatrix) ++stats_.tangentAssemblies;  // evaluate() sets every value of K_
  system_.evaluate(U, t, fint_, fext_, pattern_.get(), withMatrix ? &K_ : nullptr);
  r_.setZero(n_);
  r_.head(system_.dofCount()) = fint_ - fext_;
  if (terms_) terms_->assemble(U, r_, *pattern_, termsFirstElement_, withMatrix ? &K_ : nullptr);
  stats_.assemblySeconds += seconds(start);
}

bool StaticNonlinear::solveStep(Eigen::VectorXd& U, double t0, double t1, std::vector<double>& history,
                                std::string& why) {
  const int nm = system_.dofCount();
  const auto imposed = system_.imposed(t1);
  std::vector<char> fixed(n_, 0);
  Eigen::VectorXd target = Eigen::VectorXd::Zero(n_);  // values of the fixed unknowns
  linalg::SparseMatrix Kmod;
  bool statusChanged = false;
  linalg::LinearSolver& solver = *solver_->solver;
  history.clear();
  const Eigen::VectorXd Ustart = U;
  // The size of the displacements the data of the step give: the state it
  // starts from and the imposed values (the round-off test below).
  double dataScale = Ustart.head(nm).lpNorm<Eigen::Infinity>();
  for (const auto& [d, v] : imposed) dataScale = std::max(dataScale, std::fabs(v));
  // PREDICTION='EXTRAPOLE': start from U_n + (dt_{n+1} / dt_n) (U_n - U_{n-1}), the last
  // converged (sub-)step's increment; the first step has none and starts from U_n.
  if (settings_.prediction == Prediction::Extrapolated && previousDt_ > 0)
    U += ((t1 - t0) / previousDt_) * previousIncrement_;
  if (settings_.print)
    Messages::info("  Instant " + sci(t1) + "\n    iter  RESI_GLOB_RELA   RESI_GLOB_MAXI   matrix      time (s)   " +
                   (terms_ ? "contact" : ""));
  for (int k = 0;; ++k) {
    const auto iterationStart = Clock::now();
    // Ctrl-C: the unconverged instant is abandoned; the converged ones are kept.
    if (interrupt::requested())
      throw Interrupted("interrupted (SIGINT) during the instant " + sci(t1) + " (Newton iteration " +
                        std::to_string(k) + "), which is abandoned");
    if (terms_ && terms_->update(U)) buildPattern();
    if (!pattern_) buildPattern();
    // The matrix of this iteration: the elastic one, or the tangent at U assembled now,
    // or the factorization kept from before (REAC_ITER, REAC_INCR).
    bool elasticNow = settings_.elasticMatrix;
    bool assembleTangent = false;
    if (k == 0 && settings_.prediction == Prediction::Elastic) {
      elasticNow = true;
    } else if (k == 0 && settings_.prediction == Prediction::Tangent) {
      elasticNow = false;
      assembleTangent = factorized_ != Factorized::Tangent || steps_ == 0 ||
                        (settings_.reacIncr > 0 && steps_ % settings_.reacIncr == 0);
    } else if (!elasticNow) {
      assembleTangent = factorized_ != Factorized::Tangent || k == 0 ||
                        (settings_.reacIter > 0 && k % settings_.reacIter == 0);
    }
    // Near convergence the tangent is often not needed: Newton converges quadratically, so a
    // relative residual below the square root of RESI_GLOB_RELA is usually followed by a
    // converged one. The residual is then assembled alone first (a fifth of the cost of
    // residual and tangent), and the tangent only if the iteration goes on (SVK square:
    // 5 of 20 tangent assemblies saved). Not before the third iteration: the first one's
    // residual is the previous instant's (imposed displacements enter with the first
    // correction) and says nothing of the coming one.
    const bool residualFirst = assembleTangent && k >= 2 && !statusChanged &&
                               settings_.useRela && !settings_.useMaxi &&
                               history.back() <= std::sqrt(settings_.resiGlobRela);
    try {
      assemble(U, t1, assembleTangent && !residualFirst);
    } catch (const InvalidStateError& e) {
      // An inverted cell after too large a correction: the step may succeed
      // when cut, as with code_aster's EVENEMENT='ERREUR'. Invalid data (a
      // load that is not finite) stops at once.
      why = e.what();
      stats_.iterations += k;
      return false;
    }
    if (elasticNow && Kelastic_.size() == 0) {
      Eigen::VectorXd zero = Eigen::VectorXd::Zero(n_);
      Eigen::VectorXd keepFint = fint_, keepFext = fext_, keepR = r_;
      assemble(zero, t1, true);
      Kelastic_ = K_;
      fint_ = keepFint;
      fext_ = keepFext;
      r_ = keepR;
    }

    // The fixed unknowns: imposed displacements, and what the terms fix.
    std::fill(fixed.begin(), fixed.end(), 0);
    for (const auto& [d, v] : imposed) {
      fixed[d] = 1;
      target(d) = v;
    }
    if (terms_) {
      std::vector<int> extra;
      terms_->fixedUnknowns(extra);
      for (int d : extra) {
        fixed[d] = 1;
        target(d) = 0.0;
      }
    }
    // A kept tangent factorization eliminated other unknowns: assemble anew.
    if (!elasticNow && !assembleTangent && fixed != lastFixed_) {
      assemble(U, t1, true);
      assembleTangent = true;
    }

    // Residual on the free unknowns, relative to the forces that balance the
    // internal forces (external loads plus support reactions), as code_aster.
    double resMax = 0, denom = 0;
    for (int i = 0; i < n_; ++i) {
      if (fixed[i]) {
        if (i < nm) denom = std::max(denom, std::fabs(fint_(i)));
        continue;
      }
      resMax = std::max(resMax, std::fabs(r_(i)));
      if (i < nm) denom = std::max(denom, std::fabs(r_(i) - fint_(i)));  // the loads that balance fint
    }
    if (!std::isfinite(resMax)) {
      why = "the residual is not a number (the state became invalid)";
      return false;
    }
    const double rela = denom > 0 ? resMax / denom : resMax;
    const double measure = settings_.useRela ? rela : resMax;
    history.push_back(measure);
    // One row of the table, printed when the iteration ends (its time included); the
    // contact column says how contact stands when the residual is measured.
    const std::string contactText = terms_ ? terms_->statusText() : "";
    auto printRow = [&](const char* matrix) {
      if (!settings_.print) return;
      char buf[96];
      std::snprintf(buf, sizeof buf, "    %4d  %s     %s         %-9s   %.2E   ", k, sci(rela).c_str(),
                    sci(resMax, 2).c_str(), matrix, seconds(iterationStart));
      Messages::info(buf + contactText);
    };
    // CONVERGENCE: every criterion given must hold.
    const bool criteriaMet = (!settings_.useRela || rela <= settings_.resiGlobRela) &&
                             (!settings_.useMaxi || resMax <= settings_.resiGlobMaxi) &&
                             (settings_.useRela || settings_.useMaxi);
    // With no load at all (a rigid motion imposed, say) the relative residual is
    // noise over noise: accept a residual at round-off level of the stiffness forces
    // of displacements of the size the data give. Not of the current ones: a
    // singular matrix solved anyway (NPREC <= 0, STOP_SINGULIER='NON') gives
    // displacements of 1e13 whose round-off would hide a residual that does not fall.
    double kmax = 0;
    const linalg::SparseMatrix& Kscale = elasticNow ? Kelastic_ : K_;
    for (int i = 0; i < Kscale.outerSize(); ++i) kmax = std::max(kmax, std::fabs(Kscale.coeff(i, i)));
    const bool atRoundOff = resMax <= 1e-13 * kmax * dataScale;
    bool dirichletMet = true;
    for (const auto& [d, v] : imposed) dirichletMet = dirichletMet && std::fabs(U(d) - v) <= 1e-12 * (1 + std::fabs(v));
    if (k > 0 && (criteriaMet || atRoundOff) && !statusChanged && dirichletMet) {
      printRow("");
      stats_.iterations += k;
      finishStep(U, Ustart, t1 - t0);
      return true;
    }
    if (k >= settings_.iterGlobMaxi) {
      printRow("");
      why = "no convergence in ITER_GLOB_MAXI = " + std::to_string(settings_.iterGlobMaxi) + " Newton iterations (" +
            (settings_.useRela ? "RESI_GLOB_RELA = " + sci(rela, 3) + (settings_.useMaxi ? ", " : "") : "") +
            (settings_.useMaxi ? "RESI_GLOB_MAXI = " + sci(resMax, 3) : "") + ")";
      stats_.iterations += k;
      if (!settings_.arret && dirichletMet) {
        // CONVERGENCE/ARRET='NON': the step is kept as it is.
        Messages::alarm("STAT_NON_LINE", "instant " + sci(t1) + ": " + why +
                                             "; the step is accepted as it is (CONVERGENCE/ARRET='NON')");
        finishStep(U, Ustart, t1 - t0);
        return true;
      }
      return false;
    }

    if (residualFirst) assemble(U, t1, true);  // same state: same residual, and now the tangent

    // Newton correction: K dU = -r on the free unknowns, dU = target - U on the fixed ones.
    const auto solveStart = Clock::now();
    Eigen::VectorXd dUc = Eigen::VectorXd::Zero(n_);
    for (int i = 0; i < n_; ++i)
      if (fixed[i]) dUc(i) = target(i) - U(i);
    const linalg::SparseMatrix& Kuse = elasticNow ? Kelastic_ : K_;
    Eigen::VectorXd rhs = -r_;
    if (dUc.lpNorm<Eigen::Infinity>() > 0) rhs -= Kuse * dUc;
    const bool refactor = assembleTangent || (elasticNow && factorized_ != Factorized::Elastic) ||
                          fixed != lastFixed_;
    if (refactor) {
      // A tangent is eliminated in place (it is assembled again before it is factorized
      // again); the elastic matrix, kept for the whole run, is copied first.
      if (elasticNow) Kmod = Kelastic_;
      linalg::SparseMatrix& A = elasticNow ? Kmod : K_;
      A.makeCompressed();
      const int* outer = A.outerIndexPtr();
      const int* rows = A.innerIndexPtr();
      double* values = A.valuePtr();
      for (int j = 0; j < A.outerSize(); ++j)
        for (int p = outer[j]; p < outer[j + 1]; ++p)
          if (fixed[j] || fixed[rows[p]]) values[p] = rows[p] == j ? 1.0 : 0.0;
      factorized_ = Factorized::None;
      try {
        if (!analyzed_) {
          linalg::chooseBlasThreads(static_cast<int>(A.rows()));
          solver.analyze(A);
          analyzed_ = true;
        }
        solver.factorize(A);
      } catch (const linalg::SingularMatrixError& e) {
        printRow(elasticNow ? "ELASTIQUE" : "TANGENTE");
        std::string where;
        const int col = e.column() >= 0 ? e.column() : e.row();
        if (col >= 0 && col < nm) {
          const auto& map = system_.dofMap();
          for (int node = 0; node < map.nodeCount(); ++node)
            if (map.count(node) && col >= map.first(node) && col < map.first(node) + map.count(node))
              where = " (unknown " + std::string(col == map.first(node) ? "DX" : "DY") + " of node " +
                      system_.model().mesh().nodeName(node) + ")";
        } else if (col >= nm) {
          where = " (a contact unknown)";
        }
        // Surfaces that never meet leave the body free: say how contact stands.
        if (terms_) where += " (contact: " + terms_->statusText() + ")";
        throw Error(std::string(e.what()) + where);
      }
      ++stats_.factorizations;
      factorized_ = elasticNow ? Factorized::Elastic : Factorized::Tangent;
      lastFixed_ = fixed;
    }
    for (int i = 0; i < n_; ++i)
      if (fixed[i]) rhs(i) = dUc(i);
    Eigen::VectorXd dU;
    solver.solve(rhs, dU);
    stats_.solveSeconds += seconds(solveStart);
    U += dU;
    printRow(!refactor ? "" : elasticNow ? "ELASTIQUE" : "TANGENTE");
    statusChanged = terms_ ? terms_->updateStatus(U) : false;
  }
}

void StaticNonlinear::finishStep(const Eigen::VectorXd& U, const Eigen::VectorXd& Ustart, double dt) {
  system_.acceptState(U);
  previousIncrement_ = U - Ustart;
  previousDt_ = dt;
  ++steps_;
}

const linalg::LinearSolverStatistics& StaticNonlinear::solverStatistics() const { return solver_->solver->statistics(); }

void StaticNonlinear::run(Eigen::VectorXd& U, const std::vector<double>& times,
                          const std::function<void(const ConvergedInstant&)>& converged) {
  const auto start = Clock::now();
  if (U.size() != n_) throw Error("internal error: the initial state has the wrong size");
  system_.acceptState(U);  // the initial state, reached from the natural one
  std::vector<double> history;
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
    if (level >= settings_.subdNiveau || settings_.subdPas < 2) return false;
    ++stats_.cuts;
    Messages::alarm("STAT_NON_LINE", "instant " + sci(t1) + ": " + why + "; the step [" + sci(t0, 4) + ", " +
                                         sci(t1, 4) + "] is cut into " + std::to_string(settings_.subdPas) +
                                         " (level " + std::to_string(level + 1) + ")");
    for (int i = 1; i <= settings_.subdPas; ++i) {
      const double a = t0 + (t1 - t0) * (i - 1) / settings_.subdPas;
      const double b = (i == settings_.subdPas) ? t1 : t0 + (t1 - t0) * i / settings_.subdPas;
      if (!interval(a, b, level + 1, why)) return false;
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
      throw Error("the instant " + sci(times[k]) + " did not converge: " + why +
                  (settings_.subdNiveau > 0 ? " (even after cutting the step " + std::to_string(settings_.subdNiveau) +
                                                  " times)"
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
