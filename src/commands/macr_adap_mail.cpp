// MACR_ADAP_MAIL: mesh adaptation. aster-lite has the uniform refinement only
// (ADAPTATION='RAFFINEMENT_UNIFORME'): every 2D cell of GROUP_MA (all of them
// when absent) is split in 4, the boundary segments on split edges in 2. The new
// mesh is returned and bound to the name given with MAILLAGE_NP1=CO('name').
// Groups of cells list the children; a group of nodes follows the group of
// cells with exactly its nodes, and one that cannot be followed stops the
// command (mesh/refine.hpp).
#include <set>
#include <string>
#include <vector>

#include "commands/mesh_concept.hpp"
#include "core/error.hpp"
#include "core/messages.hpp"
#include "lang/operators.hpp"
#include "mesh/group_ops.hpp"
#include "mesh/refine.hpp"

namespace aster::lang {
namespace {

ConceptPtr macrAdapMail(const Keywords& k, Session& session, ConceptPtr) {
  const std::string adaptation = k.text("ADAPTATION");
  if (adaptation != "RAFFINEMENT_UNIFORME")
    throw Error("ADAPTATION='" + adaptation +
                "' is not available in aster-lite: only ADAPTATION='RAFFINEMENT_UNIFORME' (uniform refinement) is");
  const ConceptPtr source = k.conceptPtr("MAILLAGE_N");
  const mesh::Mesh& in = meshOf(source);

  // The 2D cells to split; empty means all of them.
  std::vector<int> cells;
  const bool restricted = k.has("GROUP_MA") || k.has("GROUP_NO");
  if (k.has("GROUP_MA")) {
    for (int c : mesh::unionOfCellGroups(in, k.texts("GROUP_MA")))
      if (mesh::topologicalDimension(in.cellType(c)) == 2) cells.push_back(c);
  } else if (restricted) {
    for (int c = 0; c < in.cellCount(); ++c)
      if (mesh::topologicalDimension(in.cellType(c)) == 2) cells.push_back(c);
  }
  if (k.has("GROUP_NO")) {  // keep the cells touching these nodes
    std::set<int> nodes;
    for (const auto& g : k.texts("GROUP_NO"))
      for (int n : in.nodeGroup(g)) nodes.insert(n);
    std::vector<int> touching;
    for (int c : cells) {
      bool touches = false;
      for (int n : in.cellNodes(c)) touches = touches || nodes.count(n) > 0;
      if (touches) touching.push_back(c);
    }
    cells.swap(touching);
  }
  if (restricted && cells.empty())
    throw Error(std::string(k.has("GROUP_MA") ? "GROUP_MA" : "GROUP_NO") +
                ": no 2D cell (triangle or quadrangle) to refine in the groups given");
  if (!restricted && in.meshDimension() != 2)
    throw Error("MAILLAGE_N: the mesh has no 2D cell to refine (RAFFINEMENT_UNIFORME splits triangles and quadrangles)");

  auto refined = std::make_shared<mesh::Mesh>(mesh::refineUniformly(in, cells));
  auto result = std::make_shared<MeshConcept>(refined);

  // MAILLAGE_NP1=CO('MA1') binds the name, as in code_aster; the new mesh is
  // also the command's value (MA1 = MACR_ADAP_MAIL{...}).
  std::string newName = "the new mesh";
  if (k.has("MAILLAGE_NP1")) {
    newName = k.value("MAILLAGE_NP1").text;
    session.produced.emplace_back(newName, result);
  }

  const int info = static_cast<int>(k.integer("INFO"));
  Messages::info("MACR_ADAP_MAIL: uniform refinement of " + session.nameOf(*source) + " (" +
                 std::to_string(in.nodeCount()) + " nodes, " + std::to_string(in.cellCount()) + " cells) into " +
                 newName + " (" + std::to_string(refined->nodeCount()) + " nodes, " +
                 std::to_string(refined->cellCount()) + " cells)");
  if (info >= 2) Messages::info(refined->summary());
  return result;
}

RegisterOperator reg("MACR_ADAP_MAIL", macrAdapMail);

}  // namespace
}  // namespace aster::lang
