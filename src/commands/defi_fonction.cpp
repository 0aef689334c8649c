// DEFI_FONCTION: a tabulated function of one parameter.
#include "commands/function_concepts.hpp"
#include "core/error.hpp"
#include "expr/tabulated.hpp"
#include "lang/operators.hpp"

namespace aster::lang {

expr::TabulatedOptions tabulatedOptionsOf(const Keywords& k) {
  expr::TabulatedOptions o;
  const auto interpol = k.texts("INTERPOL");  // one value for both axes, or two
  o.abscissa = expr::interpolationFromName(interpol.front());
  o.ordinate = expr::interpolationFromName(interpol.back());
  o.left = expr::extensionFromName(k.text("PROL_GAUCHE"));
  o.right = expr::extensionFromName(k.text("PROL_DROITE"));
  return o;
}

namespace {

std::vector<double> realsOf(const Keywords& k, const std::string& key) {
  if (k.value(key).kind == Value::Kind::Concept)
    return static_cast<RealListConcept&>(*k.conceptPtr(key)).values;
  return k.reals(key);
}

ConceptPtr defiFonction(const Keywords& k, Session&, ConceptPtr) {
  const std::string param = k.text("NOM_PARA");
  const auto options = tabulatedOptionsOf(k);
  if (k.has("VALE")) {
    const auto pairs = k.reals("VALE");
    if (pairs.size() % 2 != 0)
      throw Error("VALE holds pairs (x1, y1, x2, y2, ...): got an odd count, " + std::to_string(pairs.size()));
    return std::make_shared<FunctionConcept>("fonction_sdaster", expr::Tabulated::fromPairs(param, pairs, options));
  }
  auto x = realsOf(k, "VALE_PARA");
  auto y = realsOf(k, "VALE_FONC");
  if (x.size() != y.size())
    throw Error("VALE_PARA has " + std::to_string(x.size()) + " values but VALE_FONC has " +
                std::to_string(y.size()));
  return std::make_shared<FunctionConcept>("fonction_sdaster",
                                           std::make_shared<expr::Tabulated>(param, x, y, options));
}

RegisterOperator reg("DEFI_FONCTION", defiFonction);

}  // namespace
}  // namespace aster::lang
