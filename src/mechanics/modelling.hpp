// The two choices that fix a plane element's formulation, each one enum for the
// whole program: the plane hypothesis (AFFE_MODELE's MODELISATION) and the strain
// measure (COMPORTEMENT's DEFORMATION). The element owns both; a behaviour law
// (behaviour_law.hpp) only maps the strain measure to a stress.
#pragma once
#include <string>

namespace aster::mechanics {

// D_PLAN (plane strain, e_zz = 0), C_PLAN (plane stress, s_zz = 0) and AXIS
// (axisymmetric: r = X, the axis is Y, the out-of-plane strain is the hoop strain
// u_r / r; integrals are per radian, weighted by r).
enum class PlaneHypothesis { PlaneStrain, PlaneStress, Axisymmetric };

// PETIT: eps = sym(grad u), Cauchy stress, reference configuration.
// GROT_GDEP (also GREEN_LAGRANGE): total Lagrangian, Green-Lagrange strain E and
// second Piola-Kirchhoff stress S.
// GDEF_LOG: the law (written for small strains) maps the logarithmic strain
// T = ln(F^T F) / 2 to its dual stress; the element runs it total Lagrangian as
// GROT_GDEP through LogarithmicStrainLaw (log_strain_law.hpp), which maps E to S.
enum class Kinematics { SmallStrain, GreenLagrange, Logarithmic };

// Throw aster::Error naming the word and the choices.
PlaneHypothesis planeHypothesisFromName(const std::string& word);  // D_PLAN, C_PLAN, AXIS
const char* planeHypothesisName(PlaneHypothesis hypothesis);
Kinematics kinematicsFromName(const std::string& word);  // PETIT, GROT_GDEP, GREEN_LAGRANGE, GDEF_LOG

}  // namespace aster::mechanics
