// DEBUT and FIN: the study's bounds. Both are optional.
#include "lang/operators.hpp"

namespace aster::lang {
namespace {

ConceptPtr debut(const Keywords&, Session&, ConceptPtr) { return nullptr; }

ConceptPtr fin(const Keywords&, Session&, ConceptPtr) { throw StudyFinished{}; }

RegisterOperator regDebut("DEBUT", debut);
RegisterOperator regFin("FIN", fin);

}  // namespace
}  // namespace aster::lang
