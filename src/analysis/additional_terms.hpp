// Terms that a formulation adds to the mechanical system, with unknowns of
// their own appended after the displacement DOFs: contact.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "fem/assembly_pattern.hpp"
#include "fem/element_dofs.hpp"
#include "mesh/nodal_field.hpp"

namespace aster::analysis {

class AdditionalTerms {
 public:
  virtual ~AdditionalTerms() = default;
  // Number of own unknowns; they are numbered from `first` on.
  virtual int unknownCount() const = 0;
  virtual void setFirstUnknown(int first) = 0;
  // Called before each Newton iteration with the current state: pairing in the
  // current configuration. Returns true when elementDofs() changed.
  virtual bool update(const Eigen::VectorXd& U) = 0;
  // Element DOF lists (global numbering) of the terms, for the sparsity pattern.
  virtual void elementDofs(fem::ElementDofs& out) const = 0;
  // r += terms' residual; K += their exact tangent (elements numbered from
  // `firstElement` in `pattern`, in the order of elementDofs()).
  virtual void assemble(const Eigen::VectorXd& U, Eigen::VectorXd& r, const fem::AssemblyPattern& pattern,
                        int firstElement, linalg::SparseMatrix* K) const = 0;
  // After a Newton correction: updates discrete statuses (active set); returns
  // true when a status changed, so the iteration cannot be the last.
  virtual bool updateStatus(const Eigen::VectorXd& U) = 0;
  // The active-set loop inside a Newton iteration (static_nonlinear.cpp,
  // low_rank_update.hpp). One change of the linear system when a status
  // changes: the equation of the terms' unknown `unknown` becomes
  // row . dU = rhs (global indices, the diagonal included, duplicates
  // summed); when `symmetric`, its column becomes the row too, else the
  // column stays as assembled.
  struct StatusChange {
    int unknown = -1;
    std::vector<std::pair<int, double>> row;
    double rhs = 0;
    bool symmetric = false;
  };
  // After the Newton correction dU from U, solved with the statuses of the
  // last assemble() at U (or of the last call's changes): the statuses of
  // the LINEARIZED problem at U + dU. Returns false when they are those dU
  // was solved with (settled), or when the linear system of the new statuses
  // is not one of these changes; else `changes` holds every change from the
  // assembled system, and the next call compares with these statuses.
  virtual bool linearizedStatusChanges(const Eigen::VectorXd& U, const Eigen::VectorXd& dU,
                                       std::vector<StatusChange>& changes) {
    (void)U;
    (void)dU;
    (void)changes;
    return false;
  }
  // A short state for the convergence table, as of the last assemble(): for
  // contact, the active nodes or points and a contact residual
  // ("12 active nodes, residual 1.23E-16"; see contact_terms.hpp).
  virtual std::string statusText() const = 0;
  // Restores the statuses of the last converged instant (step cutting).
  virtual void saveStatus() = 0;
  virtual void restoreStatus() = 0;
  // Own unknowns whose equation is trivial at this point (lambda = 0 imposed,
  // e.g. inactive DISCRETE nodes), eliminated like imposed displacements.
  virtual void fixedUnknowns(std::vector<int>& dofs) const { (void)dofs; }
  // Results: components the terms add to DEPL (e.g. LAGS_C), and fields of their own (CONT_NOEU).
  virtual void extendDisplacement(const Eigen::VectorXd& U, mesh::NodalField& depl) const {
    (void)U;
    (void)depl;
  }
  virtual void outputFields(const Eigen::VectorXd& U, std::vector<mesh::NodalField>& fields) const {
    (void)U;
    (void)fields;
  }
};

}  // namespace aster::analysis
