// AFFE_MODELE: plane mechanical elements on the 2D cells of the mesh.
#include <sstream>

#include "commands/mesh_concept.hpp"
#include "commands/model_concepts.hpp"
#include "commands/selection.hpp"
#include "core/error.hpp"
#include "core/messages.hpp"
#include "lang/operators.hpp"

namespace aster::lang {
namespace {

ConceptPtr affeModele(const Keywords& k, Session&, ConceptPtr) {
  auto mesh = static_cast<MeshConcept&>(*k.conceptPtr("MAILLAGE")).mesh;
  auto m = std::make_shared<model::Model>(mesh);
  std::ostringstream info;
  for (const auto& occ : k.factor("AFFE")) {
    const auto cells = selectCells(*mesh, occ);
    const auto mod = model::modelisationFromName(occ.text("MODELISATION"));
    const int n = m->assign(cells, mod);
    if (n == 0)
      throw Error(occ.path + ": none of the " + std::to_string(cells.size()) +
                  " cells selected is a 2D cell (TRIA3, TRIA6, QUAD4, QUAD8, QUAD9) or a segment: no element assigned");
    info << "  " << n << " cells -> MECANIQUE " << occ.text("MODELISATION") << "\n";
  }
  Messages::info("AFFE_MODELE:\n" + info.str());
  return std::make_shared<ModelConcept>(m);
}

RegisterOperator reg("AFFE_MODELE", affeModele);

}  // namespace
}  // namespace aster::lang
