// CREA_MAILLAGE: a new mesh made from a mesh, which is left unchanged (no
// reuse=, as in code_aster). LINE_QUAD, QUAD_LINE and MODI_MAILLE change the
// type of cells (mesh/cell_conversion.hpp); DECOUPE_LAC cuts the cells under
// slave segments into LAC patches (mesh/lac_patches.hpp).
#include <memory>
#include <string>
#include <vector>

#include "commands/mesh_concept.hpp"
#include "core/error.hpp"
#include "core/messages.hpp"
#include "lang/operators.hpp"
#include "mesh/cell_conversion.hpp"
#include "mesh/group_ops.hpp"
#include "mesh/lac_patches.hpp"

namespace aster::lang {
namespace {

// The cells a TOUT / MAILLE / GROUP_MA occurrence names, each once.
std::vector<int> selectedCells(const mesh::Mesh& m, const Keywords& k) {
  if (k.has("TOUT")) {
    std::vector<int> all(m.cellCount());
    for (int c = 0; c < m.cellCount(); ++c) all[c] = c;
    return all;
  }
  std::vector<int> cells;
  std::vector<char> seen(m.cellCount(), 0);
  if (k.has("GROUP_MA"))
    for (int c : mesh::unionOfCellGroups(m, k.texts("GROUP_MA")))
      if (!seen[c]) seen[c] = 1, cells.push_back(c);
  if (k.has("MAILLE"))
    for (const auto& name : k.texts("MAILLE")) {
      const int c = m.cellIndex(name);
      if (!seen[c]) seen[c] = 1, cells.push_back(c);
    }
  return cells;
}

// code_aster converts 3D cells too; aster-lite refuses them rather than leave them linear.
void refuseVolumes(const mesh::Mesh& m, const std::vector<int>& cells, const std::string& where) {
  for (int c : cells)
    if (mesh::topologicalDimension(m.cellType(c)) == 3)
      throw Error(where + ": cell " + m.cellName(c) + " is a " + mesh::cellTypeName(m.cellType(c)) +
                  "; aster-lite converts 1D and 2D cells only (SEG, TRIA, QUAD)");
}

int countOf(const mesh::Mesh& m, const std::vector<int>& cells, std::initializer_list<mesh::CellType> types) {
  int n = 0;
  for (int c : cells)
    for (auto t : types) n += m.cellType(c) == t;
  return n;
}

// reuse= is refused before this runs (reentrant='n' in the catalogue).
ConceptPtr creaMaillage(const Keywords& k, Session& session, ConceptPtr) {
  const ConceptPtr source = k.conceptPtr("MAILLAGE");
  const mesh::Mesh& in = meshOf(source);
  using CT = mesh::CellType;
  std::string what;
  mesh::Mesh out;

  if (k.has("LINE_QUAD")) {
    const Keywords& f = k.factor("LINE_QUAD").front();
    const auto cells = selectedCells(in, f);
    refuseVolumes(in, cells, "LINE_QUAD");
    if (countOf(in, cells, {CT::SEG2, CT::TRIA3, CT::QUAD4}) == 0)
      throw Error("LINE_QUAD: no linear cell (SEG2, TRIA3, QUAD4) among the cells given");
    try {
      out = mesh::lineToQuadratic(in, cells, f.text("PREF_NOEUD"), static_cast<int>(f.integer("PREF_NUME")));
    } catch (const Error& e) {
      throw Error(std::string("LINE_QUAD: ") + e.what());
    }
    what = "LINE_QUAD";
  } else if (k.has("QUAD_LINE")) {
    const auto cells = selectedCells(in, k.factor("QUAD_LINE").front());
    refuseVolumes(in, cells, "QUAD_LINE");
    if (countOf(in, cells, {CT::SEG3, CT::TRIA6, CT::TRIA7, CT::QUAD8, CT::QUAD9}) == 0)
      throw Error("QUAD_LINE: no quadratic cell (SEG3, TRIA6, TRIA7, QUAD8, QUAD9) among the cells given");
    out = mesh::quadraticToLinear(in, cells);
    what = "QUAD_LINE";
  } else if (k.has("MODI_MAILLE")) {
    const auto& occurrences = k.factor("MODI_MAILLE");
    out = in;
    for (std::size_t i = 0; i < occurrences.size(); ++i) {
      const Keywords& f = occurrences[i];
      const std::string where = "MODI_MAILLE" + (occurrences.size() > 1 ? "[" + std::to_string(i + 1) + "]" : "");
      const std::string option = f.text("OPTION");
      if (option == "SEG3_4" || option == "QUAD_TRIA3")
        throw Error(where + ": OPTION='" + option +
                    "' is not available in aster-lite (QUAD8_9 and TRIA6_7 are)");
      const auto cells = selectedCells(out, f);
      const CT from = option == "QUAD8_9" ? CT::QUAD8 : CT::TRIA6;
      if (countOf(out, cells, {from}) == 0)
        throw Error(where + ": OPTION='" + option + "' changes " + mesh::cellTypeName(from) +
                    " cells and there is none among the cells given");
      try {
        out = mesh::addCentreNodes(out, cells, option, f.text("PREF_NOEUD"), static_cast<int>(f.integer("PREF_NUME")));
      } catch (const Error& e) {
        throw Error(where + ": " + e.what());
      }
    }
    what = "MODI_MAILLE";
  } else {
    const Keywords& f = k.factor("DECOUPE_LAC").front();
    if (in.meshDimension() != 2)
      throw Error("DECOUPE_LAC: aster-lite cuts LAC patches in 2D meshes only (this mesh has " +
                  std::to_string(in.meshDimension()) + "D cells)");
    const auto slaves = mesh::unionOfCellGroups(in, f.texts("GROUP_MA_ESCL"));
    try {
      out = std::move(mesh::cutLacPatches(in, slaves).mesh);
    } catch (const Error& e) {
      throw Error(std::string("DECOUPE_LAC: ") + e.what());
    }
    what = "DECOUPE_LAC";
  }
  if (k.has("TITRE")) out.title = k.text("TITRE");

  auto result = std::make_shared<MeshConcept>(std::make_shared<mesh::Mesh>(std::move(out)));
  const mesh::Mesh& made = *result->mesh;
  const int info = static_cast<int>(k.integer("INFO"));
  Messages::info("CREA_MAILLAGE " + what + ": " + session.nameOf(*source) + " (" + std::to_string(in.nodeCount()) +
                 " nodes, " + std::to_string(in.cellCount()) + " cells) -> " + std::to_string(made.nodeCount()) +
                 " nodes, " + std::to_string(made.cellCount()) + " cells");
  if (info >= 2) Messages::info(made.summary());
  return result;
}

RegisterOperator reg("CREA_MAILLAGE", creaMaillage);

}  // namespace
}  // namespace aster::lang
