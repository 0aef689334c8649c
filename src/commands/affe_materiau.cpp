// AFFE_MATERIAU: a material per cell.
#include "commands/mesh_concept.hpp"
#include "commands/model_concepts.hpp"
#include "commands/selection.hpp"
#include "lang/operators.hpp"

namespace aster::lang {
namespace {

ConceptPtr affeMateriau(const Keywords& k, Session& session, ConceptPtr) {
  std::shared_ptr<mesh::Mesh> mesh;
  if (k.has("MAILLAGE"))
    mesh = static_cast<MeshConcept&>(*k.conceptPtr("MAILLAGE")).mesh;
  else
    mesh = modelOf(k.conceptPtr("MODELE")).meshPtr();
  auto field = std::make_shared<model::MaterialField>(mesh->cellCount());
  for (const auto& occ : k.factor("AFFE")) {
    const std::vector<int> cells = selectCells(*mesh, occ);
    field->assign(cells, static_cast<MaterialConcept&>(*occ.conceptPtr("MATER")).material);
    field->assignName(cells, session.nameOf(*occ.conceptPtr("MATER")));
  }
  return std::make_shared<MaterialFieldConcept>(mesh, field);
}

RegisterOperator reg("AFFE_MATERIAU", affeMateriau);

}  // namespace
}  // namespace aster::lang
