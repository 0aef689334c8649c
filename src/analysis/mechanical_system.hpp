// The discrete mechanical problem of STAT_NON_LINE without contact: DOF
// numbering (DX, DY on each node of the model), the sparsity pattern (built
// once), internal forces and tangent, external loads at an instant, and the
// imposed displacements (eliminated). Contact adds its own terms on top
// (analysis/contact_terms.hpp).
#pragma once
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "core/error.hpp"
#include "expr/function.hpp"
#include "fem/assembly_pattern.hpp"
#include "fem/dof_map.hpp"
#include "linalg/linear_constraints.hpp"
#include "mechanics/behaviour_law.hpp"
#include "mechanics/element_kernel.hpp"
#include "mechanics/modelling.hpp"
#include "model/loads.hpp"
#include "model/material.hpp"
#include "model/model.hpp"

namespace aster::analysis {


// An element kernel refused the state (an inverted cell after too large a
// Newton correction): a failure that cutting the step may cure.
class InvalidStateError : public Error {
 public:
  using Error::Error;
};

struct AppliedLoad {
  const model::MechanicalLoad* load = nullptr;
  expr::FunctionPtr multiplier;  // FONC_MULT of INST; null means 1
  // TYPE_CHARGE='SUIV': its pressures act on the deformed edges (and enter the
  // tangent); otherwise (FIXE_CSTE) they are dead loads on the reference edges.
  bool follower = false;
  // Throws aster::Error when FONC_MULT is not a finite number at t.
  double factor(double t) const;
};

struct MechanicalProblem {
  std::shared_ptr<const model::Model> model;
  std::shared_ptr<const model::MaterialField> materials;
  std::vector<AppliedLoad> loads;
  // Per cell of model->cells(): its kinematics (COMPORTEMENT's DEFORMATION).
  std::vector<mechanics::Kinematics> kinematics;
  // Per cell of model->cells(): its behaviour law (COMPORTEMENT's RELATION), or
  // empty: ELAS of the cell's material (mechanics::IsotropicElasticity) everywhere.
  std::vector<std::shared_ptr<const mechanics::BehaviourLaw>> relations;
};

class MechanicalSystem {
 public:
  explicit MechanicalSystem(MechanicalProblem problem);

  const fem::DofMap& dofMap() const { return dofs_; }
  int dofCount() const { return dofs_.dofCount(); }
  const model::Model& model() const { return *problem_.model; }
  // "unknown DY of node N12" for a displacement unknown, "" for any other index.
  std::string unknownName(int dof) const;
  const MechanicalProblem& problem() const { return problem_; }
  // DOF of (node, component), -1 when the node carries none.
  int dof(int node, int component) const { return dofs_.count(node) ? dofs_.dof(node, component) : -1; }

  // Element DOF lists of every term that has a stiffness (cells, pressure edges):
  // the driver adds contact's and builds the pattern.
  const fem::ElementDofs& elementDofs() const { return elements_; }

  // Fint(U) and Fext(U, t) (follower pressures act on the deformed edges); when K is given,
  // K = dFint/dU - dFext/dU (every value of K set, zero outside these terms), with K on a
  // pattern containing elementDofs() (the first elementDofs().elementCount() elements of
  // `pattern`).
  // naturalState: the laws integrate from the natural state (no stress, no internal
  // variables, U = 0) instead of the accepted one: at U = 0, K is then the initial
  // elastic matrix whatever the history (NEWTON MATRICE='ELASTIQUE').
  void evaluate(const Eigen::VectorXd& U, double t, Eigen::VectorXd& fint, Eigen::VectorXd& fext,
                const fem::AssemblyPattern* pattern, linalg::SparseMatrix* K, bool naturalState = false) const;
  // Fint(U) alone, no load evaluated: the internal forces of a given state (STAT_NON_LINE's
  // initial one, at an instant where a FONC_MULT may be undefined).
  // The laws integrate from the accepted state over no time.
  void internalForces(const Eigen::VectorXd& U, Eigen::VectorXd& fint) const;

  // K is exactly symmetric whatever U: every element matrix is (its kernel mirrors one
  // triangle when the law's tangent is symmetric), and the assembly adds the same element
  // values in the same order into (i, j) and (j, i). Follower pressures and the laws with
  // a non-symmetric tangent (mechanics::BehaviourLaw::symmetricTangent) make it unsymmetric.
  bool symmetricTangent() const { return pressureEdges_.empty() && symmetricLaws_; }
  // Whether a cell's law predicts from the accepted state (mechanics::BehaviourLaw::predictsFromAcceptedState).
  bool predictsFromAcceptedState() const { return predictsFromAcceptedState_; }

  // Imposed displacements at t: (dof, value), each DOF once (the last load wins).
  std::vector<std::pair<int, double>> imposed(double t) const;
  // The DOFs imposed by AFFE_CHAR_MECA(_F) alone, which code_aster dualizes (Lagrange
  // multipliers) where AFFE_CHAR_CINE's are eliminated; in increasing order.
  std::vector<int> dualizedImposed() const;

  // The linear relations of the loads (LIAISON_DDL, LIAISON_UNIF, LIAISON_SOLIDE, FACE_IMPO
  // DNOR/DTAN) on DOF numbers, their right-hand sides at t (times FONC_MULT), in the order
  // of the loads; relationOrigin(k) names the command and keyword that defined relation k.
  bool hasLinearRelations() const { return !relationOrigins_.empty(); }
  std::vector<linalg::LinearRelation> linearRelations(double t) const;
  const std::string& relationOrigin(int k) const { return relationOrigins_[k]; }
  // The fixed values and relations at t, eliminated (the drivers' path when hasLinearRelations());
  // a contradictory set throws aster::Error naming the relation and where it was defined.
  linalg::ConstraintElimination eliminate(const std::vector<char>& fixed, const Eigen::VectorXd& values,
                                          double t) const;

  // The laws' state at the last accepted step (the natural state, U = 0, at first):
  // evaluate() and gaussStresses() integrate from it. acceptState(U) integrates
  // the laws at U (mechanical DOFs first) and keeps the result: the driver calls it
  // once per converged step, t the step's end instant (rate-dependent laws integrate
  // over t minus the instant of the state before). Free for laws without history (ELAS).
  void acceptState(const Eigen::VectorXd& U, double t);
  // The first state of a run at its first instant t0: U integrated from the accepted
  // state (the natural one or ETAT_INIT's) over no time.
  void acceptInitialState(const Eigen::VectorXd& U, double t0) {
    acceptedTime_ = t0;
    acceptState(U, t0);
  }
  // Sets the accepted state (STAT_NON_LINE's ETAT_INIT): U (mechanical DOFs first) and,
  // for the cells whose law has history, the stresses (the laws' measure: S in
  // GROT_GDEP), laid out as gaussStresses() gives them, and the internal variables,
  // laid out as gaussVariables() gives them; a null one stands for zero.
  void setAcceptedState(const Eigen::VectorXd& U, const std::vector<double>* stresses,
                        const std::vector<double>* variables);
  // Whether a cell of the model (its index in model().cells()) has a law with history.
  bool hasHistory(int k) const { return cells_[k].state >= 0; }
  // The Gauss points of each cell of the model (offsets into 4-component stresses / 4).
  int gaussPoints(int k) const { return cells_[k].kernel->gaussPoints(); }

  // SIEF_ELGA at U: per cell of the model, 4 components per Gauss point (SIZZ the
  // hoop stress in AXIS), Cauchy stresses (in GROT_GDEP sigma = F S F^T / J, as
  // code_aster stores them; the laws' state keeps S).
  void gaussStresses(const Eigen::VectorXd& U, std::vector<int>& offsets, std::vector<double>& values) const;
  // VARI_ELGA of the accepted state: internalVariableCount() values (V1, V2, ...) per
  // Gauss point of every cell of the model, zero past a cell's own law's count.
  int internalVariableCount() const { return maxVariables_; }
  // The laws' names of V1, V2, ... (code_aster's NOM_VARI) when every law with internal
  // variables names them alike, else empty.
  std::vector<std::string> internalVariableNames() const;
  void gaussVariables(std::vector<int>& offsets, std::vector<double>& values) const;
  // Gauss point positions and weights*detJ in the reference configuration (times r
  // in AXIS: per radian).
  void gaussGeometry(std::vector<int>& offsets, std::vector<double>& xy, std::vector<double>& weights) const;

 private:
  struct Cell {
    int meshCell;
    const mechanics::ElementKernel* kernel;
    int element;  // index in elements_
    int state;      // first of its Gauss points in the accepted state, -1 when its law has no history
    int variables;  // first of its internal variables in the accepted state
  };
  struct Edge {  // an edge of a follower pressure
    int meshCell;
    int element;
    const model::SpaceFunction* p;
    const AppliedLoad* load;
  };
  void gatherCoords(int meshCell, double* X) const;
  // The accepted state of a cell (u_n gathered into `un`); empty without history. With
  // natural, the natural state (zero stresses and variables, u_n = 0).
  // The accepted state of `cell` as the laws integrate from it to instant t.
  mechanics::ElementHistory historyOf(const Cell& cell, double* un, double t, bool natural = false) const;
  void addDeadLoads(double t, Eigen::VectorXd& fext) const;
  // The cells' part of evaluate(): fint and, when K is given, every value of K set.
  void assembleCells(const Eigen::VectorXd& U, double t, Eigen::VectorXd& fint, const fem::AssemblyPattern* pattern,
                     linalg::SparseMatrix* K, bool naturalState = false) const;
  Eigen::VectorXd deadLoadVector(const AppliedLoad& applied, double t) const;

  MechanicalProblem problem_;
  fem::DofMap dofs_;
  fem::ElementDofs elements_;
  std::vector<std::unique_ptr<mechanics::ElementKernel>> kernels_;
  std::vector<Cell> cells_;
  // Runs of kChunkCells consecutive cells (chunk k: cells_[k * kChunkCells ...]) by colour:
  // chunks of one colour share no DOF, so each colour is assembled by all threads without
  // races (and with the same sums for any thread count), and each chunk's cells one after
  // the other, neighbours in the mesh's order, so that they write the same columns of the
  // matrix while those are in cache (SVK square N = 256: 82 -> 71 ms per tangent assembly;
  // colours of single cells made each pass touch the whole matrix).
  static constexpr int kChunkCells = 32;
  std::vector<std::vector<int>> chunkColours_;
  std::vector<Edge> pressureEdges_;
  bool symmetricLaws_ = true;  // every law's tangent is symmetric
  bool predictsFromAcceptedState_ = false;
  std::vector<std::string> relationOrigins_;  // per relation of the loads, in their order
  // Dead loads independent of time, computed once: F(t) = factor(t) * F0.
  std::vector<Eigen::VectorXd> constantDeadLoads_;  // per problem_.loads entry, empty if time dependent
  // The accepted state of the cells whose law has history: U, 4 stresses per Gauss
  // point, the law's internal variables per Gauss point.
  int maxVariables_ = 0;
  bool hasHistory_ = false;
  Eigen::VectorXd acceptedU_;
  double acceptedTime_ = 0.0;  // the INST of the accepted state
  std::vector<double> acceptedStress_, acceptedVariables_;
  std::vector<double> naturalVariables_;  // zeros, for one cell
};

}  // namespace aster::analysis
