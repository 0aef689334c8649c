// MODI_MAILLAGE: changes a mesh in place (reuse= is required). ORIE_PEAU (and
// its older 2D spelling ORIE_PEAU_2D) orients boundary segments so that their
// normal points out of the 2D cell they bound.
#include <string>
#include <vector>

#include "commands/mesh_concept.hpp"
#include "core/error.hpp"
#include "core/messages.hpp"
#include "lang/operators.hpp"
#include "mesh/group_ops.hpp"
#include "mesh/orient.hpp"

namespace aster::lang {
namespace {

// Orients the segments of `groups`; returns how many were reversed.
int orient(mesh::Mesh& m, const std::vector<std::string>& groups, const std::string& where,
           const std::string& insideKeyword, const std::vector<std::string>& inside, int info) {
  // Every group named must exist, inside groups included (the kernel finds the
  // inside itself: the only 2D cell on each boundary edge).
  for (const auto& g : inside) m.cellGroup(g);
  if (!inside.empty() && info >= 2)
    Messages::info(where + ": " + insideKeyword +
                   " is checked but not needed: each segment is oriented against its only 2D cell");
  const std::vector<int> cells = mesh::unionOfCellGroups(m, groups);
  int reversed = 0;
  try {
    reversed = mesh::orientBoundarySegments(m, cells);
  } catch (const Error& e) {
    throw Error(where + ": " + e.what());
  }
  if (info >= 1) {
    std::string names;
    for (const auto& g : groups) names += (names.empty() ? "" : ", ") + g;
    Messages::info("MODI_MAILLAGE " + where + ": " + std::to_string(reversed) + " of the " +
                   std::to_string(cells.size()) + " segments of " + names + " reversed");
  }
  return reversed;
}

ConceptPtr modiMaillage(const Keywords& k, Session& session, ConceptPtr reuse) {
  const ConceptPtr given = k.conceptPtr("MAILLAGE");
  if (!reuse) throw Error("reuse=: MODI_MAILLAGE modifies the mesh in place, give reuse=" + session.nameOf(*given));
  if (reuse.get() != given.get())
    throw Error("MAILLAGE: the mesh to modify must be the one given with reuse=");
  mesh::Mesh& m = meshOf(reuse);
  const int info = static_cast<int>(k.integer("INFO"));
  int total = 0;
  const auto& peau = k.factor("ORIE_PEAU");
  for (std::size_t i = 0; i < peau.size(); ++i) {
    const std::string where = "ORIE_PEAU" + (peau.size() > 1 ? "[" + std::to_string(i + 1) + "]" : std::string());
    total += orient(m, peau[i].texts("GROUP_MA_PEAU"), where, "GROUP_MA_INTERNE", peau[i].texts("GROUP_MA_INTERNE"),
                    info);
  }
  const auto& peau2d = k.factor("ORIE_PEAU_2D");
  for (std::size_t i = 0; i < peau2d.size(); ++i) {
    const std::string where =
        "ORIE_PEAU_2D" + (peau2d.size() > 1 ? "[" + std::to_string(i + 1) + "]" : std::string());
    total += orient(m, peau2d[i].texts("GROUP_MA"), where, "GROUP_MA_SURF", peau2d[i].texts("GROUP_MA_SURF"), info);
  }
  if (info >= 1 && peau.size() + peau2d.size() > 1)
    Messages::info("MODI_MAILLAGE: " + std::to_string(total) + " segments reversed in all");
  return reuse;
}

RegisterOperator reg("MODI_MAILLAGE", modiMaillage);

}  // namespace
}  // namespace aster::lang
