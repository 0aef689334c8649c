// TEST_FONCTION: checks a function's value at given parameters (OK/NOOK).
#include "commands/check_keywords.hpp"
#include "commands/function_concepts.hpp"
#include "core/error.hpp"
#include "core/number_format.hpp"
#include "lang/operators.hpp"
#include "post/check.hpp"

namespace aster::lang {
namespace {

ConceptPtr testFonction(const Keywords& k, Session& session, ConceptPtr) {
  for (const auto& occ : k.factor("VALEUR")) {
    const ConceptPtr fc = occ.conceptPtr("FONCTION");
    const auto f = functionOf(fc);
    const auto x = occ.reals("VALE_PARA");
    if (x.size() != f->parameters().size())
      throw Error(occ.path + ": VALE_PARA has " + std::to_string(x.size()) + " value(s) but the function takes " +
                  std::to_string(f->parameters().size()) + " (" + expr::joinNames(f->parameters()) + ")");
    std::string params, values;
    for (std::size_t i = 0; i < x.size(); ++i) {
      params += (i ? "," : "") + f->parameters()[i];
      values += (i ? "," : "") + format::asterValue(x[i]);
    }
    recordCheck(session, f->evaluate(x.data()), checkSpecOf(occ),
                {{"FONCTION", session.nameOf(*fc)}, {"NOM_PARA", params}, {"VALE_PARA", values}});
  }
  return nullptr;
}

RegisterOperator reg("TEST_FONCTION", testFonction);

}  // namespace
}  // namespace aster::lang
