#include "mechanics/behaviour_law.hpp"

namespace aster::mechanics {

// Out of line: the class's vtable is emitted here, in baseline code only.
BehaviourLaw::~BehaviourLaw() = default;

}  // namespace aster::mechanics
