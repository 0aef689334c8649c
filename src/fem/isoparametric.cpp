#include "fem/isoparametric.hpp"

namespace aster::fem {

void throwSingularMap(const char* cell, double det) {
  throw Error(std::string("isoparametric map of a ") + cell + " cell is singular or inverted (detJ = " +
              std::to_string(det) + "): degenerate cell or nodes not counterclockwise");
}

}  // namespace aster::fem
