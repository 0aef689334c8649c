// AFFE_MODELE: plane mechanical elements on the 2D cells of the mesh.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "commands/mesh_concept.hpp"
#include "commands/model_concepts.hpp"
#include "commands/selection.hpp"
#include "core/error.hpp"
#include "core/number_format.hpp"
#include "core/messages.hpp"
#include "fem/jacobian_check.hpp"
#include "lang/operators.hpp"
#include "mesh/group_ops.hpp"
#include "mesh/mesh_check.hpp"

namespace aster::lang {
namespace {

// VERI_JACOBIEN: aster-lite's elements need det(dx/dxi) > 0 at every Gauss
// point (nodes counterclockwise) and segments of non-zero length; a cell that
// fails would stop the first computation without being named. code_aster only
// warns of a sign change (its elements integrate |det|), and stops at the
// first computation on a zero determinant.
void checkJacobians(const mesh::Mesh& mesh, const model::Model& model) {
  std::vector<std::string> inverted, distorted, degenerate;
  std::vector<std::vector<int>> groups;  // computed only when a cell is named
  auto name = [&](int c) {
    if (groups.empty()) groups = mesh::groupsOfEachCell(mesh);
    return mesh::describeCell(mesh, c, groups);
  };
  for (const auto* cells : {&model.cells(), &model.segments()})
    for (int c : *cells) {
      const fem::JacobianSigns s = fem::jacobianSigns(mesh, c, model.axisymmetric());
      if (s.negative == 0 && s.zero == 0) continue;
      if (s.positive > 0 && s.negative > 0) distorted.push_back(name(c));
      else if (s.negative > 0 && s.zero == 0) inverted.push_back(name(c));
      else degenerate.push_back(name(c));
    }
  std::string what;
  auto add = [&](const std::vector<std::string>& cells, const std::string& kind) {
    if (cells.empty()) return;
    what += std::string(what.empty() ? "" : "; ") + std::to_string(cells.size()) + " cell" +
            (cells.size() > 1 ? "s are " : " is ") + kind + ": ";
    for (std::size_t i = 0; i < cells.size() && i < 10; ++i) what += (i ? ", " : "") + cells[i];
    if (cells.size() > 10) what += " and " + std::to_string(cells.size() - 10) + " more";
  };
  add(inverted, "inverted (Jacobian < 0 at every Gauss point: nodes numbered clockwise)");
  add(distorted, "too distorted (the Jacobian changes sign between Gauss points)");
  add(degenerate, "degenerate (zero Jacobian, or a zero length, at a Gauss point)");
  if (!what.empty())
    throw Error("VERI_JACOBIEN: " + what +
                ". The elements need a positive Jacobian at every Gauss point: number the nodes of each cell "
                "counterclockwise and fix the mesh (VERI_JACOBIEN='NON' skips this check; the first computation "
                "on such a cell then fails)");
}

// AXIS: r = X, so a cell of an axisymmetric model must lie in X >= 0 (nodes on
// the axis are fine: Gauss points are interior); and AXIS is not mixed with the
// plane modelisations (its loads are per radian).
void checkAxisymmetric(const mesh::Mesh& mesh, const model::Model& model) {
  if (!model.axisymmetric()) return;
  bool plane = false;
  for (std::size_t k = 0; k < model.cells().size(); ++k)
    plane |= model.modelisation(static_cast<int>(k)) != model::Modelisation::Axisymmetric;
  if (plane)
    throw Error("MODELISATION='AXIS' is assigned to some cells and D_PLAN or C_PLAN to others: an axisymmetric "
                "model has AXIS on every cell");
  // A node meant to be on the axis may come out of a mesher at X = -1e-17: the
  // rounding of the mesh's size is tolerated.
  double size = 0;
  for (int n = 0; n < mesh.nodeCount(); ++n) size = std::max(size, std::abs(mesh.node(n)(0)));
  const double tolerance = 1e-10 * size;
  for (const auto* cells : {&model.cells(), &model.segments()})
    for (int c : *cells)
      for (int n : mesh.cellNodes(c))
        if (mesh.node(n)(0) < -tolerance) {
          std::vector<std::vector<int>> groups = mesh::groupsOfEachCell(mesh);
          throw Error("MODELISATION='AXIS': cell " + mesh::describeCell(mesh, c, groups) + " has node " +
                      mesh.nodeName(n) + " at X = " + format::shortest(mesh.node(n)(0)) +
                      " < 0; in AXIS, X is the radius r >= 0 (the axis is X = 0)");
        }
}

ConceptPtr affeModele(const Keywords& k, Session&, ConceptPtr) {
  auto mesh = static_cast<MeshConcept&>(*k.conceptPtr("MAILLAGE")).mesh;
  auto m = std::make_shared<model::Model>(mesh);
  std::ostringstream info;
  for (const auto& occ : k.factor("AFFE")) {
    const auto cells = selectCells(*mesh, occ);
    const auto mod = mechanics::planeHypothesisFromName(occ.text("MODELISATION"));
    const int n = m->assign(cells, mod);
    if (n == 0)
      throw Error(occ.path + ": none of the " + std::to_string(cells.size()) +
                  " cells selected is a 2D cell (TRIA3, TRIA6, QUAD4, QUAD8, QUAD9) or a segment: no element assigned");
    info << "  " << n << " cells -> MECANIQUE " << occ.text("MODELISATION") << "\n";
  }
  checkAxisymmetric(*mesh, *m);
  if (k.text("VERI_JACOBIEN") == "OUI") checkJacobians(*mesh, *m);
  Messages::info("AFFE_MODELE:\n" + info.str());
  return std::make_shared<ModelConcept>(m);
}

RegisterOperator reg("AFFE_MODELE", affeModele);

}  // namespace
}  // namespace aster::lang
