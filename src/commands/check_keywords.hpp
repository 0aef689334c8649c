// The keywords every TEST_* command shares (VALE_CALC, VALE_REFE, REFERENCE,
// PRECISION, CRITERE, TOLE_MACHINE, ORDRE_GRANDEUR, LEGENDE), read into a CheckSpec.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "lang/keywords.hpp"
#include "lang/session.hpp"
#include "post/check.hpp"

namespace aster::lang {

post::CheckSpec checkSpecOf(const Keywords& k);

// Runs the comparison, prints and records it; `what` describes the tested quantity.
void recordCheck(Session& session, double computed, const post::CheckSpec& spec,
                 const std::vector<std::pair<std::string, std::string>>& what);

}  // namespace aster::lang
