// Microseconds per element of the plane element kernels (internal force and
// tangent of one QUAD8, TRIA6 and QUAD4 cell, PETIT and GROT_GDEP), for the
// three ways a law reaches them: ELAS inlined in the AVX2 + FMA build, ELAS
// inlined in the baseline build, and ELAS through the BehaviourLaw interface
// (a virtual call per Gauss point, baseline build), as any other law.
//   bench_element_kernel [repetitions]
#include <chrono>
#include <cstdio>
#include <algorithm>
#include <cstdlib>
#include <memory>
#include <string>

#include "mechanics/patch_support.hpp"
#include "mechanics/plane_element.hpp"

namespace {

using namespace aster::mechanics;

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

// Best of 5 runs of `reps` evaluations, in microseconds per evaluation.
template <class Element>
double microseconds(const Element& element, int reps) {
  const auto X = testing_support::distortedCell<Element::C::type>(3);
  typename Element::Vector u, f;
  typename Element::Matrix K;
  for (int i = 0; i < Element::dofs; ++i) u(i) = 0.01 * ((i * 7) % 5 - 2);
  double best = 1e300, sink = 0;
  for (int run = 0; run < 5; ++run) {
    const double t0 = now();
    for (int r = 0; r < reps; ++r) {
      element.internalForce(X, u, &f, &K);
      sink += K(0, 0);
    }
    best = std::min(best, (now() - t0) / reps * 1e6);
  }
  if (sink == 42.0) std::printf(" ");  // keeps the loop
  return best;
}

template <CellType T>
void row(const char* cell, Kinematics k, int reps) {
  const IsotropicElasticity elas(210e9, 0.3, PlaneHypothesis::PlaneStrain);
  PlaneElement<T> avx2(elas, k), baseline(elas, k);
  baseline.setBuild(KernelBuild::Baseline);
  const PlaneElement<T, BehaviourLaw> anyLaw(elas, k);  // IsotropicElasticity::integrate, virtual
  const bool hasAvx2 = kernelBuildAvailable(KernelBuild::Avx2Fma);
  char avx2Text[32] = "-";
  if (hasAvx2) std::snprintf(avx2Text, sizeof avx2Text, "%.3f", microseconds(avx2, reps));
  std::printf("| %s | %s | %s | %.3f | %.3f |\n", cell, k == Kinematics::SmallStrain ? "PETIT" : "GROT_GDEP", avx2Text,
              microseconds(baseline, reps), microseconds(anyLaw, reps));
}

}  // namespace

int main(int argc, char** argv) {
  const int reps = argc > 1 ? std::atoi(argv[1]) : 200000;
  std::printf("| cell | DEFORMATION | ELAS, AVX2 + FMA (us) | ELAS, baseline (us) | ELAS as any law (us) |\n");
  std::printf("|---|---|---|---|---|\n");
  for (Kinematics k : {Kinematics::SmallStrain, Kinematics::GreenLagrange}) {
    row<CellType::QUAD8>("QUAD8", k, reps);
    row<CellType::TRIA6>("TRIA6", k, reps);
    row<CellType::QUAD4>("QUAD4", k, reps);
  }
  return 0;
}
