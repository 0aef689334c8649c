// DETRUIRE: destroys concepts. Each is marked destroyed (any later use of it is
// a fatal error saying where it was destroyed) and the interpreter unbinds the
// study's variables that hold it, so that its memory is freed unless another
// concept still uses it (a model keeps its mesh) and its name can be reused.
#include "core/messages.hpp"
#include "lang/operators.hpp"

namespace aster::lang {
namespace {

ConceptPtr detruire(const Keywords& k, Session& session, ConceptPtr) {
  std::string names;
  auto add = [&](const Keywords& level) {
    for (const auto& c : level.concepts("NOM")) {
      if (!c->destroyedAt.empty()) continue;  // given twice in this call
      c->name = session.nameOf(*c);  // the name later messages give it
      c->destroyedAt = session.where;
      session.destroyed.push_back(c);
      names += (names.empty() ? "" : ", ") + c->name;
    }
  };
  if (k.has("NOM")) add(k);
  for (const auto& occ : k.factor("CONCEPT")) add(occ);
  if (k.integer("INFO") >= 2) Messages::info("DETRUIRE: " + names + " destroyed");
  return nullptr;
}

RegisterOperator reg("DETRUIRE", detruire);

}  // namespace
}  // namespace aster::lang
