// DEFI_LIST_REEL: a list of reals, by intervals or by values.
#include "commands/function_concepts.hpp"
#include "core/error.hpp"
#include "expr/real_list.hpp"
#include "lang/operators.hpp"

namespace aster::lang {
namespace {

ConceptPtr defiListReel(const Keywords& k, Session&, ConceptPtr) {
  if (k.has("VALE")) {
    const auto v = k.reals("VALE");
    for (std::size_t i = 1; i < v.size(); ++i)
      if (!(v[i] > v[i - 1]))
        throw Error("VALE must be strictly increasing: value " + std::to_string(i + 1) + " does not exceed value " +
                    std::to_string(i));
    return std::make_shared<RealListConcept>(v);
  }
  std::vector<expr::ListInterval> intervals;
  for (const auto& occ : k.factor("INTERVALLE")) {
    expr::ListInterval in;
    in.upTo = occ.real("JUSQU_A");
    if (occ.has("NOMBRE")) in.count = static_cast<int>(occ.integer("NOMBRE"));
    if (occ.has("PAS")) in.step = occ.real("PAS");
    intervals.push_back(in);
  }
  return std::make_shared<RealListConcept>(expr::realList(k.real("DEBUT"), intervals));
}

RegisterOperator reg("DEFI_LIST_REEL", defiListReel);

}  // namespace
}  // namespace aster::lang
