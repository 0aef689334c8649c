// Equivalent stresses of a plane stress state (SIEQ_ELGA / SIEQ_ELNO / SIEQ_NOEU),
// with code_aster's components in its order (SIEQ in the SIEF_R quantity):
//   VMIS      von Mises, sqrt(3/2 s:s), s the deviator
//   TRESCA    largest difference of two principal stresses
//   PRIN_1..3 principal stresses, increasing
//   VMIS_SG   VMIS with the sign of the trace (+ for a zero trace)
//   VECT_i_X, VECT_i_Y, VECT_i_Z  unit principal direction of PRIN_i (its sign:
//             the largest component, in absolute value, is positive; the first
//             of equal ones)
//   TRSIG     trace
//   TRIAX     triaxiality, (trace / 3) / VMIS (0 when VMIS <= 1e-10 |trace|)
// The state is (SIXX, SIYY, SIZZ, SIXY) with SIXZ = SIYZ = 0.
#pragma once
#include <string>
#include <vector>

namespace aster::post {

inline constexpr int kEquivalentStressComponents = 17;

const std::vector<std::string>& equivalentStressComponents();

// stress: SIXX, SIYY, SIZZ, SIXY; out: kEquivalentStressComponents values.
void equivalentStresses(const double* stress, double* out);

}  // namespace aster::post
