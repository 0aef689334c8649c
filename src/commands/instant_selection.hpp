// The instants of a result an occurrence designates: NUME_ORDRE, INST or
// LIST_INST (with CRITERE and PRECISION), else TOUT_ORDRE, every stored one
// (code_aster's default), in the order given.
#pragma once
#include <vector>

#include "commands/result_concepts.hpp"
#include "lang/keywords.hpp"

namespace aster::lang {

// Throws aster::Error naming what is not stored (listing what is).
std::vector<const ResultInstant*> selectedInstants(const ResultConcept& r, const Keywords& occ);

}  // namespace aster::lang
