// DETRUIRE: accepted for code_aster compatibility; concepts are freed by Lua's
// garbage collector once the study no longer refers to them.
#include "core/messages.hpp"
#include "lang/operators.hpp"

namespace aster::lang {
namespace {

ConceptPtr detruire(const Keywords& k, Session& session, ConceptPtr) {
  std::string names;
  auto add = [&](const Keywords& level) {
    for (const auto& c : level.concepts("NOM")) names += (names.empty() ? "" : ", ") + session.nameOf(*c);
  };
  if (k.has("NOM")) add(k);
  for (const auto& occ : k.factor("CONCEPT")) add(occ);
  Messages::info("DETRUIRE: nothing to do for " + names +
                 " (memory is freed when the study no longer uses a concept; set the variable to nil)");
  return nullptr;
}

RegisterOperator reg("DETRUIRE", detruire);

}  // namespace
}  // namespace aster::lang
