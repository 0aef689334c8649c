// CALC_FONC_INTERP: a formula (or function) tabulated on a list of parameters.
#include "commands/function_concepts.hpp"
#include "core/error.hpp"
#include "expr/tabulated.hpp"
#include "lang/operators.hpp"

namespace aster::lang {

namespace {

ConceptPtr calcFoncInterp(const Keywords& k, Session&, ConceptPtr) {
  const auto f = functionOf(k.conceptPtr("FONCTION"));
  if (f->parameters().size() != 1)
    throw Error("FONCTION must have one parameter to be tabulated, it has " +
                std::to_string(f->parameters().size()) + " (" + expr::joinNames(f->parameters()) + ")");
  if (k.has("NOM_PARA") && !expr::takesOnly(*f, k.text("NOM_PARA")))
    throw Error("NOM_PARA='" + k.text("NOM_PARA") + "' but FONCTION's parameter is " + f->parameters().front());
  const auto& list = static_cast<RealListConcept&>(*k.conceptPtr("LIST_PARA")).values;
  return std::make_shared<FunctionConcept>("fonction_sdaster", expr::tabulate(*f, list, tabulatedOptionsOf(k)));
}

RegisterOperator reg("CALC_FONC_INTERP", calcFoncInterp);

}  // namespace
}  // namespace aster::lang
