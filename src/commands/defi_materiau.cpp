// DEFI_MATERIAU: linear elastic material (ELAS).
#include "commands/model_concepts.hpp"
#include "core/error.hpp"
#include "lang/operators.hpp"

namespace aster::lang {
namespace {

ConceptPtr defiMateriau(const Keywords& k, Session&, ConceptPtr) {
  const auto& elas = k.factor("ELAS").front();
  auto m = std::make_shared<model::ElasticMaterial>();
  m->E = elas.real("E");
  m->NU = elas.real("NU");
  if (!(m->E > 0)) throw Error("ELAS/E must be positive, got " + std::to_string(m->E));
  if (!(m->NU > -1 && m->NU < 0.5)) throw Error("ELAS/NU must lie in ]-1, 0.5[, got " + std::to_string(m->NU));
  if (elas.has("RHO")) {
    m->RHO = elas.real("RHO");
    m->hasRho = true;
  }
  return std::make_shared<MaterialConcept>(m);
}

RegisterOperator reg("DEFI_MATERIAU", defiMateriau);

}  // namespace
}  // namespace aster::lang
