// DEFI_GROUP: creates and deletes groups of cells (GROUP_MA) and of nodes
// (GROUP_NO). With reuse= the mesh changes in place; without, a copy of the
// mesh with the new groups is returned. Order, as in code_aster: deletions,
// then groups of cells, then groups of nodes (which may use the new cell groups).
#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "commands/mesh_concept.hpp"
#include "commands/selection.hpp"
#include "core/error.hpp"
#include "core/messages.hpp"
#include "lang/operators.hpp"
#include "mesh/group_ops.hpp"

namespace aster::lang {
namespace {

std::string occurrenceName(const std::string& key, std::size_t i, std::size_t n) {
  return n > 1 ? key + "[" + std::to_string(i + 1) + "]" : key;
}

std::vector<int> uniqueInOrder(const std::vector<int>& items) {
  std::vector<int> out;
  std::set<int> seen;
  for (int i : items)
    if (seen.insert(i).second) out.push_back(i);
  return out;
}

// ---------------------------------------------------------------- GROUP_MA

std::vector<int> cellsOf(const mesh::Mesh& m, const Keywords& occ) {
  if (occ.has("TOUT")) {
    std::vector<int> all(m.cellCount());
    for (int c = 0; c < m.cellCount(); ++c) all[c] = c;
    return all;
  }
  if (occ.has("GROUP_MA")) return mesh::unionOfCellGroups(m, occ.texts("GROUP_MA"));
  if (occ.has("UNION")) return mesh::unionOfCellGroups(m, occ.texts("UNION"));
  if (occ.has("INTERSEC")) return mesh::intersectionOfCellGroups(m, occ.texts("INTERSEC"));
  if (occ.has("DIFFE")) return mesh::differenceOfCellGroups(m, occ.texts("DIFFE"));
  std::vector<int> out;
  for (int c : namedCells(m, occ, "MAILLE")) out.push_back(c);
  return uniqueInOrder(out);
}

void createCellGroup(mesh::Mesh& m, const Keywords& occ, const std::string& where, int info) {
  const std::string name = occ.text("NOM");
  if (m.hasCellGroup(name))
    throw Error(where + ": NOM='" + name + "': the group of cells already exists in the mesh "
                "(delete it first with DETR_GROUP_MA={NOM='" + name + "'})");
  std::vector<int> cells = cellsOf(m, occ);
  const std::string dim = occ.text("TYPE_MAILLE");
  if (dim != "TOUT") {
    const int d = dim == "1D" ? 1 : 2;
    cells.erase(std::remove_if(cells.begin(), cells.end(),
                               [&](int c) { return mesh::topologicalDimension(m.cellType(c)) != d; }),
                cells.end());
  }
  if (cells.empty())
    Messages::alarm("DEFI_GROUP", where + ": the group of cells '" + name + "' is empty");
  m.addCellGroup(name, cells);
  if (info >= 1) Messages::info("DEFI_GROUP: group of cells " + name + " created, " + std::to_string(cells.size()) + " cells");
}

// ---------------------------------------------------------------- GROUP_NO

// The nodes of the cells keeping those CRIT_NOEUD asks for.
std::vector<int> nodesOfCells(const mesh::Mesh& m, const std::vector<int>& cells, const std::string& crit) {
  std::vector<int> out;
  std::set<int> seen;
  for (int c : cells) {
    const mesh::CellType t = m.cellType(c);
    const auto n = m.cellNodes(c);
    const int nv = mesh::vertexCount(t);
    // Centre nodes: TRIA7's 7th, QUAD9's 9th, HEXA27's last ones; mid-edge nodes in between.
    int firstCentre = n.size();
    if (t == mesh::CellType::TRIA7) firstCentre = 6;
    if (t == mesh::CellType::QUAD9) firstCentre = 8;
    if (t == mesh::CellType::PENTA18) firstCentre = 15;
    if (t == mesh::CellType::HEXA27) firstCentre = 20;
    for (int i = 0; i < n.size(); ++i) {
      const bool keep = crit == "TOUS" || (crit == "SOMMET" && i < nv) ||
                        (crit == "MILIEU" && i >= nv && i < firstCentre) || (crit == "CENTRE" && i >= firstCentre);
      if (keep && seen.insert(n[i]).second) out.push_back(n[i]);
    }
  }
  return out;
}

std::vector<int> nodeGroupOperation(const mesh::Mesh& m, const std::vector<std::string>& groups, const std::string& op) {
  if (op == "UNION") {
    std::vector<int> all;
    for (const auto& g : groups) {
      const auto& nodes = m.nodeGroup(g);
      all.insert(all.end(), nodes.begin(), nodes.end());
    }
    return uniqueInOrder(all);
  }
  std::vector<std::set<int>> others;
  for (std::size_t k = 1; k < groups.size(); ++k) {
    const auto& nodes = m.nodeGroup(groups[k]);
    others.emplace_back(nodes.begin(), nodes.end());
  }
  std::vector<int> out;
  for (int n : uniqueInOrder(m.nodeGroup(groups.front()))) {
    bool inAll = true, inAny = false;
    for (const auto& o : others) {
      const bool in = o.count(n) > 0;
      inAll = inAll && in;
      inAny = inAny || in;
    }
    if (op == "INTERSEC" ? inAll : !inAny) out.push_back(n);
  }
  return out;
}

void addNodeGroupChecked(mesh::Mesh& m, const std::string& name, std::vector<int> nodes, const std::string& where,
                         int info) {
  if (m.hasNodeGroup(name))
    throw Error(where + ": NOM='" + name + "': the group of nodes already exists in the mesh "
                "(delete it first with DETR_GROUP_NO={NOM='" + name + "'})");
  if (nodes.empty()) Messages::alarm("DEFI_GROUP", where + ": the group of nodes '" + name + "' is empty");
  const std::size_t count = nodes.size();
  m.addNodeGroup(name, std::move(nodes));
  if (info >= 1) Messages::info("DEFI_GROUP: group of nodes " + name + " created, " + std::to_string(count) + " nodes");
}

// One node named by a group of one node (GROUP_NO_ORIG) or by name (NOEUD_ORIG); -1 when neither.
int endNode(const mesh::Mesh& m, const Keywords& occ, const std::string& groupKey, const std::string& nodeKey) {
  if (occ.has(nodeKey)) return namedNode(m, occ, nodeKey, occ.text(nodeKey));
  if (!occ.has(groupKey)) return -1;
  const std::string g = occ.text(groupKey);
  const auto& nodes = m.nodeGroup(g);
  if (nodes.size() != 1)
    throw Error(groupKey + "='" + g + "': the group must hold exactly one node, it holds " +
                std::to_string(nodes.size()));
  return nodes.front();
}

std::vector<int> orderedNodes(const mesh::Mesh& m, const Keywords& occ, const std::string& where) {
  const std::vector<int> cells = mesh::unionOfCellGroups(m, occ.texts("GROUP_MA"));
  const int origin = endNode(m, occ, "GROUP_NO_ORIG", "NOEUD_ORIG");
  const int extremity = endNode(m, occ, "GROUP_NO_EXTR", "NOEUD_EXTR");
  std::vector<int> nodes;
  try {
    nodes = mesh::orderedChainNodes(m, cells, origin);
  } catch (const Error& e) {
    throw Error(where + ": " + e.what());
  }
  if (extremity >= 0) {
    if (origin < 0 && nodes.front() == extremity) std::reverse(nodes.begin(), nodes.end());
    if (nodes.back() != extremity)
      throw Error(where + ": the node '" + m.nodeName(extremity) + "' given as the end (GROUP_NO_EXTR/NOEUD_EXTR) is " +
                  (nodes.front() == extremity ? "the origin of the line" : "not an end of the line"));
  } else if (origin < 0 && occ.has("VECT_ORIE") && nodes.size() >= 2) {
    // No end given: travel in the direction of VECT_ORIE.
    const auto v = occ.reals("VECT_ORIE");
    const Eigen::Vector3d d = m.node(nodes[1]) - m.node(nodes[0]);
    double dot = 0;
    for (std::size_t i = 0; i < v.size() && i < 3; ++i) dot += v[i] * d[static_cast<int>(i)];
    if (dot < 0) std::reverse(nodes.begin(), nodes.end());
  }
  return nodes;
}

void createNodeGroups(mesh::Mesh& m, const Keywords& occ, const std::string& where, int info) {
  if (occ.has("OPTION") && occ.text("OPTION") == "NOEUD_ORDO") {
    addNodeGroupChecked(m, occ.text("NOM"), orderedNodes(m, occ, where), where, info);
    return;
  }
  const std::vector<std::string> names = occ.texts("NOM");
  // One group of nodes per group of cells; names derived from the cell groups
  // are skipped with an alarm when taken (gmsh meshes come with them already).
  auto perCellGroup = [&](const std::vector<std::string>& groups, bool derivedNames, const std::string& crit) {
    if (!derivedNames && names.size() != groups.size())
      throw Error(where + ": NOM gives " + std::to_string(names.size()) + " names for " +
                  std::to_string(groups.size()) + " groups of GROUP_MA; give one name per group");
    for (std::size_t i = 0; i < groups.size(); ++i) {
      const std::string name = derivedNames ? groups[i] : names[i];
      std::vector<int> nodes = nodesOfCells(m, m.cellGroup(groups[i]), crit);
      if (derivedNames && m.hasNodeGroup(name)) {
        Messages::alarm("DEFI_GROUP", where + ": the group of nodes '" + name + "' exists already; it is kept as it is");
        continue;
      }
      addNodeGroupChecked(m, name, std::move(nodes), where, info);
    }
  };
  if (occ.has("TOUT_GROUP_MA")) {
    perCellGroup(m.cellGroupNames(), true, "TOUS");  // CRIT_NOEUD belongs to GROUP_MA: every node
    return;
  }
  if (occ.has("GROUP_MA")) {
    perCellGroup(occ.texts("GROUP_MA"), names.empty(), occ.text("CRIT_NOEUD"));
    return;
  }
  if (names.size() != 1)
    throw Error(where + ": NOM must give one name for the new group of nodes, it gives " +
                std::to_string(names.size()));
  std::vector<int> nodes;
  if (occ.has("GROUP_NO")) {
    nodes = nodeGroupOperation(m, occ.texts("GROUP_NO"), "UNION");
  } else if (occ.has("NOEUD")) {
    nodes = namedNodes(m, occ, "NOEUD");
    nodes = uniqueInOrder(nodes);
  } else {
    for (const char* op : {"UNION", "INTERSEC", "DIFFE"})
      if (occ.has(op)) nodes = nodeGroupOperation(m, occ.texts(op), op);
  }
  addNodeGroupChecked(m, names.front(), std::move(nodes), where, info);
}

// ---------------------------------------------------------------- operator

ConceptPtr defiGroup(const Keywords& k, Session&, ConceptPtr reuse) {
  const ConceptPtr given = k.conceptPtr("MAILLAGE");
  if (reuse && reuse.get() != given.get())
    throw Error("MAILLAGE: the mesh whose groups change must be the one given with reuse=");
  // Without reuse=, the groups go to a copy: the mesh given keeps its own.
  std::shared_ptr<MeshConcept> target =
      reuse ? std::static_pointer_cast<MeshConcept>(reuse)
            : std::make_shared<MeshConcept>(std::make_shared<mesh::Mesh>(meshOf(given)));
  mesh::Mesh& m = *target->mesh;
  const int info = static_cast<int>(k.integer("INFO"));

  const auto& detrMa = k.factor("DETR_GROUP_MA");
  for (std::size_t i = 0; i < detrMa.size(); ++i)
    for (const auto& name : detrMa[i].texts("NOM")) {
      if (!m.hasCellGroup(name)) {
        try {
          m.cellGroup(name);  // the kernel's message, with suggestions
        } catch (const Error& e) {
          throw Error(occurrenceName("DETR_GROUP_MA", i, detrMa.size()) + ": NOM: " + e.what());
        }
      }
      m.removeCellGroup(name);
    }
  const auto& detrNo = k.factor("DETR_GROUP_NO");
  for (std::size_t i = 0; i < detrNo.size(); ++i)
    for (const auto& name : detrNo[i].texts("NOM")) {
      if (!m.hasNodeGroup(name)) {
        try {
          m.nodeGroup(name);
        } catch (const Error& e) {
          throw Error(occurrenceName("DETR_GROUP_NO", i, detrNo.size()) + ": NOM: " + e.what());
        }
      }
      m.removeNodeGroup(name);
    }

  const auto& creaMa = k.factor("CREA_GROUP_MA");
  for (std::size_t i = 0; i < creaMa.size(); ++i) {
    const std::string where = occurrenceName("CREA_GROUP_MA", i, creaMa.size());
    try {
      createCellGroup(m, creaMa[i], where, info);
    } catch (const Error& e) {
      const std::string what = e.what();
      if (what.rfind(where, 0) == 0) throw;
      throw Error(where + ": " + what);
    }
  }
  const auto& creaNo = k.factor("CREA_GROUP_NO");
  for (std::size_t i = 0; i < creaNo.size(); ++i) {
    const std::string where = occurrenceName("CREA_GROUP_NO", i, creaNo.size());
    try {
      createNodeGroups(m, creaNo[i], where, info);
    } catch (const Error& e) {
      const std::string what = e.what();
      if (what.rfind(where, 0) == 0) throw;
      throw Error(where + ": " + what);
    }
  }
  if (info >= 2) Messages::info(m.summary());
  return target;
}

RegisterOperator reg("DEFI_GROUP", defiGroup);

}  // namespace
}  // namespace aster::lang
