// DEFI_LIST_INST: instants plus what STAT_NON_LINE does when a step fails.
#include "commands/function_concepts.hpp"
#include "commands/list_inst_concept.hpp"
#include "core/error.hpp"
#include "lang/operators.hpp"

namespace aster::lang {
namespace {

ConceptPtr defiListInst(const Keywords& k, Session&, ConceptPtr) {
  auto out = std::make_shared<ListInstConcept>();
  const auto& defi = k.factor("DEFI_LIST").front();
  out->times = defi.has("LIST_INST") ? static_cast<RealListConcept&>(*defi.conceptPtr("LIST_INST")).values
                                     : defi.reals("VALE");
  for (std::size_t i = 1; i < out->times.size(); ++i)
    if (!(out->times[i] > out->times[i - 1]))
      throw Error("DEFI_LIST: the instants must increase strictly (instant " + std::to_string(i + 1) + ")");
  for (const auto& e : k.factor("ECHEC")) {
    if (e.text("ACTION") == "ARRET") {
      out->subdNiveau = 0;
      continue;
    }
    out->subdAuto = e.text("SUBD_METHODE") == "AUTO";
    out->subdPasMini = e.real("SUBD_PAS_MINI");
    if (!out->subdAuto) {
      out->subdPas = static_cast<int>(e.integer("SUBD_PAS"));
      out->subdNiveau = static_cast<int>(e.integer("SUBD_NIVEAU"));
    }
  }
  return out;
}

RegisterOperator reg("DEFI_LIST_INST", defiListInst);

}  // namespace
}  // namespace aster::lang
