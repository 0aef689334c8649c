// DEBUT and FIN: the study's bounds. Both are optional. POURSUITE begins a study
// file that continues the one run before it (its concepts are still there).
#include "core/error.hpp"
#include "lang/operators.hpp"

namespace aster::lang {
namespace {

ConceptPtr debut(const Keywords&, Session&, ConceptPtr) { return nullptr; }

ConceptPtr poursuite(const Keywords&, Session& session, ConceptPtr) {
  if (!session.continuesEarlierFile)
    throw Error("POURSUITE continues a study begun in an earlier file, and no study file ran before this one: "
                "give both files, in order (aster-lite part1.lua part2.lua, or an .export listing both "
                "command files), or begin this one with DEBUT");
  return nullptr;
}

ConceptPtr fin(const Keywords&, Session&, ConceptPtr) { throw StudyFinished{}; }

RegisterOperator regDebut("DEBUT", debut);
RegisterOperator regPoursuite("POURSUITE", poursuite);
RegisterOperator regFin("FIN", fin);

}  // namespace
}  // namespace aster::lang
