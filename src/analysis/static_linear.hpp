// MECA_STATIQUE's algorithm: linear elasticity in small strain at one or several
// instants. The stiffness does not depend on the instant: it is assembled and
// factorized once (again only if the set of imposed unknowns changes), and each
// instant is one solve with its loads. Imposed displacements are eliminated as
// the Newton driver does (rows and columns replaced by the identity's); with linear
// relations (LIAISON_*, FACE_IMPO) the slave unknowns are eliminated with them
// (linalg::ConstraintElimination).
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "analysis/mechanical_system.hpp"
#include "analysis/static_nonlinear.hpp"
#include "linalg/gcpc_solver.hpp"
#include "linalg/linear_solver.hpp"
#include "linalg/mumps_solver.hpp"

namespace aster::analysis {

struct LinearSettings {
  std::string method = "MULT_FRONT";  // SOLVEUR/METHODE
  std::string renum = "AUTO";         // SOLVEUR/RENUM
  int nprec = 8;                      // SOLVEUR/NPREC (<= 0: only a zero pivot is singular)
  linalg::MumpsOptions mumps;         // METHODE='MUMPS': its controls
  linalg::GcpcOptions gcpc;           // METHODE='GCPC': its controls
};

struct LinearStatistics {
  int factorizations = 0;
  double assemblySeconds = 0, solveSeconds = 0, totalSeconds = 0;
};

class StaticLinear {
 public:
  // `system` must be linear: every cell in small strain with a law without history,
  // no follower load (the caller's to ensure).
  StaticLinear(const MechanicalSystem& system, LinearSettings settings);
  ~StaticLinear();

  // Solves K U = F(t) with the imposed values of t at each instant; `solved` gets
  // each (ConvergedInstant with iterations = 0: reactions = fint - fext).
  void run(const std::vector<double>& times, const std::function<void(const ConvergedInstant&)>& solved);

  int unknownCount() const { return system_.dofCount(); }
  const LinearStatistics& statistics() const { return stats_; }
  const linalg::LinearSolverStatistics& solverStatistics() const { return solver_->statistics(); }

 private:
  [[noreturn]] void throwSingular(const linalg::SingularMatrixError& e) const;
  void factorize(const linalg::SparseMatrix& A, bool patternChanged);
  // U at t with the linear relations: K reduced by the elimination of the relations and
  // fixed values (factorized again only when the transformation changed).
  Eigen::VectorXd solveWithRelations(const linalg::SparseMatrix& K, const Eigen::VectorXd& load,
                                     const std::vector<char>& fixed, const Eigen::VectorXd& target, double t);

  const MechanicalSystem& system_;
  LinearSettings settings_;
  std::unique_ptr<linalg::LinearSolver> solver_;
  LinearStatistics stats_;
  bool analyzed_ = false;
  std::unique_ptr<linalg::ConstraintElimination> factorizedElimination_;  // what the factorization reduced
};

}  // namespace aster::analysis
