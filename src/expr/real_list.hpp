// DEFI_LIST_REEL: DEBUT and INTERVALLE = {JUSQU_A, NOMBRE | PAS} -> the list of reals.
#pragma once
#include <vector>

namespace aster::expr {

struct ListInterval {
  double upTo = 0.0;  // JUSQU_A
  int count = 0;      // NOMBRE: number of steps (0 when PAS is used)
  double step = 0.0;  // PAS (0 when NOMBRE is used)
};

// start, then each interval's points up to and including its upTo (exactly).
// PAS must divide its interval within 1e-6 relative; throws aster::Error otherwise.
std::vector<double> realList(double start, const std::vector<ListInterval>& intervals);

}  // namespace aster::expr
