// DEFI_CONSTANTE: a function with the same value at every abscissa.
#include "commands/function_concepts.hpp"
#include "lang/operators.hpp"

namespace aster::lang {
namespace {

ConceptPtr defiConstante(const Keywords& k, Session&, ConceptPtr) {
  return std::make_shared<FunctionConcept>("fonction_sdaster", std::make_shared<expr::Constant>(k.real("VALE")));
}

RegisterOperator reg("DEFI_CONSTANTE", defiConstante);

}  // namespace
}  // namespace aster::lang
