// DEFI_FICHIER: binds a file to a logical unit (UNITE) for later commands.
#include "core/error.hpp"
#include "lang/operators.hpp"

namespace aster::lang {
namespace {

ConceptPtr defiFichier(const Keywords& k, Session& session, ConceptPtr) {
  const int unit = static_cast<int>(k.integer("UNITE"));
  if (k.text("ACTION") == "LIBERER") {
    session.units.erase(unit);
    return nullptr;
  }
  session.units[unit] = session.studyRelative(k.text("FICHIER"));
  if (k.text("ACCES", "NEW") == "OLD")  // declared for reading: never written over
    session.files.addInput(session.units[unit], "bound for reading by DEFI_FICHIER at " + session.where);
  return nullptr;
}

RegisterOperator reg("DEFI_FICHIER", defiFichier);

}  // namespace
}  // namespace aster::lang
