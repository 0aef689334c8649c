// Frictionless contact as terms added to the mechanical system (DEFI_CONTACT):
// DISCRETE (node-to-segment, a Lagrange multiplier per slave node, active set)
// and CONTINUE (LAGS_C at the slave vertex nodes, augmented Lagrangian solved
// by the generalized Newton method). Kernels and conventions: src/contact.
#pragma once
#include <memory>
#include <vector>

#include "contact/continue_formulation.hpp"
#include "solver/additional_terms.hpp"
#include "solver/mechanical_system.hpp"

namespace aster::solver {

struct ContactZone {
  std::vector<int> masterCells;  // mesh cells (SEG2/SEG3), oriented: the master normal points to the slave
  std::vector<int> slaveCells;
};

struct ContactSettings {
  bool continueFormulation = false;  // FORMULATION='CONTINUE', else 'DISCRETE'
  double rho = 100.0;                // COEF_CONT
  contact::ContactIntegration integration = contact::ContactIntegration::Gauss;
  int gaussPoints = 3;
  // LAGS_C at the vertex nodes, linear along a slave cell (code_aster's), or at
  // every node of a SEG3 slave, quadratic (aster-lite's INTERPOL_LAGS_C='QUADRATIQUE').
  contact::MultiplierInterpolation multipliers = contact::MultiplierInterpolation::Linear;
  double outsideTolerance = 0.5;  // TOLE_PROJ_EXT, in master xi units
};

std::unique_ptr<AdditionalTerms> makeContactTerms(const MechanicalSystem& system, std::vector<ContactZone> zones,
                                                  const ContactSettings& settings);

}  // namespace aster::solver
