// STAT_NON_LINE's algorithm: incremental loading over a list of instants,
// Newton-Raphson at each instant with the consistent tangent, imposed
// displacements eliminated (rows and columns replaced by the identity, which
// keeps a symmetric tangent symmetric; with linear relations, the slave unknowns
// by the transformation of linalg::ConstraintElimination), and automatic step cutting on failure
// (DEFI_LIST_INST's ECHEC: SUBD_PAS sub-steps, at most SUBD_NIVEAU levels, or SUBD_METHODE='AUTO'
// by the residuals' extrapolation (step_cutting.hpp); never below SUBD_PAS_MINI).
//
// Each Newton iteration runs the same stages, each a member function below: choose the
// matrix (tangent, elastic, or the factorization kept), assemble, fix the unknowns
// (imposed displacements and what the additional terms fix), measure the residual, test
// convergence, eliminate the fixed unknowns from the matrix, factor and solve, search
// along the correction (RECH_LINEAIRE, line_search.hpp), report.
// Reporting is telling the observers (newton_observer.hpp): the convergence table is one.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "analysis/additional_terms.hpp"
#include "analysis/line_search.hpp"
#include "analysis/mechanical_system.hpp"
#include "analysis/newton_observer.hpp"
#include "linalg/gcpc_solver.hpp"
#include "linalg/linear_solver.hpp"
#include "linalg/mumps_solver.hpp"

namespace aster::analysis {

// NEWTON/PREDICTION: the first iteration of each step.
enum class Prediction {
  Tangent,       // the tangent at the last converged state (REAC_INCR: or the last factorization)
  Elastic,       // the elastic matrix (MATRICE='ELASTIQUE''s)
  Extrapolated,  // start from U_n + (dt_{n+1}/dt_n)(U_n - U_{n-1}), then iterate with MATRICE
};

struct NewtonSettings {
  bool elasticMatrix = false;  // MATRICE='ELASTIQUE': the initial elastic matrix (U = 0, natural state), kept
  Prediction prediction = Prediction::Tangent;
  int reacIter = 1;            // REAC_ITER: reassemble the tangent every n iterations (0: never)
  int reacIncr = 1;            // REAC_INCR: reassemble the prediction's tangent every n steps (0: first only)
  bool symmetrize = false;     // MATR_RIGI_SYME='OUI': solve with the symmetric part of the tangent
  bool arret = true;           // ARRET='NON': accept a step after ITER_GLOB_MAXI iterations
  bool useRela = true;         // RESI_GLOB_RELA is a criterion
  bool useMaxi = false;        // RESI_GLOB_MAXI is a criterion (both given: both must hold)
  double resiGlobRela = 1e-6;
  double resiGlobMaxi = 1e-6;
  int iterGlobMaxi = 10;
  std::string method = "MULT_FRONT";
  std::string renum = "AUTO";  // SOLVEUR/RENUM
  int nprec = 8;               // SOLVEUR/NPREC (<= 0: only a zero pivot is singular)
  linalg::MumpsOptions mumps;  // METHODE='MUMPS': its controls
  linalg::GcpcOptions gcpc;    // METHODE='GCPC': its controls
  int subdPas = 4;     // SUBD_PAS
  int subdNiveau = 3;  // SUBD_NIVEAU (0: no cutting)
  bool subdAuto = false;    // SUBD_METHODE='AUTO' (step_cutting.hpp): no level limit
  double subdPasMini = 0;   // SUBD_PAS_MINI: no sub-step shorter
  // RECH_LINEAIRE: a line search on each correction after the prediction.
  bool lineSearch = false;
  LineSearchSettings lineSearchSettings;
};

struct ConvergedInstant {
  double time = 0;
  const Eigen::VectorXd* U = nullptr;         // all unknowns
  const Eigen::VectorXd* reactions = nullptr;  // fint - fext (+ terms), nonzero at supports
  const Eigen::VectorXd* internalForces = nullptr;  // fint = int B^T sigma, per mechanical DOF (FORC_NODA)
  int iterations = 0;
  std::vector<double> residuals;  // RESI_GLOB_RELA (or MAXI) per iteration
};

struct NewtonStatistics {
  int iterations = 0, factorizations = 0, cuts = 0;
  int tangentAssemblies = 0;  // residual and tangent; residuals alone are not counted
  int lineSearchTrials = 0;   // residuals evaluated by the line search
  int statusLoops = 0;        // re-solves of the active-set loop (settleStatuses)
  int statusSolves = 0;       // the solves they took (low_rank_update.hpp)
  double assemblySeconds = 0, solveSeconds = 0, totalSeconds = 0;
};

class StaticNonlinear {
 public:
  // The driver accepts each converged step's state into `system` (its laws' history).
  StaticNonlinear(MechanicalSystem& system, AdditionalTerms* terms, NewtonSettings settings);

  // Observers are told of every step and iteration in the order they were added; they
  // must outlive the driver's run().
  void addObserver(NewtonObserver& observer) { observers_.push_back(&observer); }

  // Runs from U (the state at times[0]) through every later instant; calls
  // `converged` after each. Throws aster::Error naming the instant that failed;
  // instants converged before stay reported.
  void run(Eigen::VectorXd& U, const std::vector<double>& times,
           const std::function<void(const ConvergedInstant&)>& converged);

  int unknownCount() const { return n_; }
  const NewtonStatistics& statistics() const { return stats_; }
  // The linear solver's: analysis, factorizations, ordering, flops of the last factorization.
  const linalg::LinearSolverStatistics& solverStatistics() const;

 private:
  struct Step;       // what one step's iterations share
  struct Iteration;  // what one iteration's stages share
  enum class Verdict { Iterate, Converged, Exhausted };
  bool solveStep(Eigen::VectorXd& U, double t0, double t1, std::vector<double>& history, std::string& why);
  // The stages of an iteration, in their order.
  void chooseMatrix(const Step& step, const std::vector<double>& history, Iteration& it) const;
  void assembleIteration(const Eigen::VectorXd& U, const Step& step, Iteration& it);
  void fixUnknowns(Step& step) const;
  bool measureResidual(const Step& step, Iteration& it, std::vector<double>& history, std::string& why);
  Verdict convergence(const Eigen::VectorXd& U, const Step& step, Iteration& it) const;
  void factorAndSolve(Eigen::VectorXd& U, const Step& step, Iteration& it);
  void solveWithRelations(Eigen::VectorXd& U, const Step& step, Iteration& it);
  void settleStatuses(Eigen::VectorXd& U, Step& step, Iteration& it);
  void searchLine(Eigen::VectorXd& U, const Step& step, Iteration& it);
  void factorize(const linalg::SparseMatrix& A, bool patternChanged, const Iteration& it,
                 const Eigen::VectorXd* rhs = nullptr, Eigen::VectorXd* x = nullptr);
  // The factorization held eliminated the same fixed unknowns and relations as the step's.
  bool sameConstraints(const Step& step) const;
  void report(const Iteration& it, const char* matrix) const;
  [[noreturn]] void throwSingular(const linalg::SingularMatrixError& e) const;
  void finishStep(const Eigen::VectorXd& U, const Eigen::VectorXd& Ustart, double t1, double dt);
  void buildPattern();
  void assemble(const Eigen::VectorXd& U, double t, bool withMatrix, bool naturalState = false);

  MechanicalSystem& system_;
  AdditionalTerms* terms_;
  NewtonSettings settings_;
  int n_ = 0;
  std::unique_ptr<fem::AssemblyPattern> pattern_;
  int termsFirstElement_ = 0;
  linalg::SparseMatrix K_, Kelastic_;
  linalg::SparseMatrix KelasticEliminated_;  // Kelastic_ with the fixed unknowns eliminated
  Eigen::VectorXd fint_, fext_, r_;
  Eigen::VectorXd solvedRhs_;  // with additional terms: the right-hand side of the last solve
  NewtonStatistics stats_;
  struct SolverHolder;
  std::shared_ptr<SolverHolder> solver_;
  bool analyzed_ = false;
  // What the linear solver holds factorized, and the unknowns that were eliminated.
  enum class Factorized { None, Tangent, Elastic };
  Factorized factorized_ = Factorized::None;
  std::vector<char> lastFixed_;
  // code_aster's residual at the supports of AFFE_CHAR_MECA, dualized there: r at the DOF
  // plus the reaction of its Lagrange multiplier, which the linear solves update, i.e. what
  // r moved there beyond the linear prediction r + K dU (with a line search's rho:
  // e' = r(U + rho dU) - r(U) - rho K dU + (1 - rho) e). The DOFs, the rows of the matrix
  // last factorized at them (before elimination), r there as the last correction predicts
  // it, and the residual e last measured there.
  std::vector<int> dualized_;
  linalg::SparseMatrix dualizedRows_;
  Eigen::VectorXd dualizedPredicted_, dualizedResidual_;
  bool dualizedPredictionValid_ = false;
  void predictDualizedResidual(const Iteration& it);
  // With linear relations: the elimination the factorization held, and its reduced matrix.
  std::shared_ptr<const linalg::ConstraintElimination> lastElimination_;
  linalg::SparseMatrix reduced_;
  // The last converged (sub-)step, for PREDICTION='EXTRAPOLE' and REAC_INCR.
  Eigen::VectorXd previousIncrement_;
  double previousDt_ = 0;
  int steps_ = 0;
  std::vector<NewtonObserver*> observers_;
};

}  // namespace aster::analysis
