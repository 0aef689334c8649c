// TEST_RESU: checks values of nodal fields (CHAM_NO), of fields on cells
// (CHAM_ELEM: at Gauss points, ELGA, or at cell nodes, ELNO) and of results (RESU,
// nodal fields and fields on cells): one node (or cell and Gauss point or node) and
// component, or TYPE_TEST over the field's support (SOMM_ABS: sum of absolute
// values, SOMM: sum, MAX / MIN: signed extremes), all components or NOM_CMP.
// Each check prints its .resu block and counts OK / NOOK.
#include <algorithm>
#include <cmath>
#include <functional>

#include "commands/check_keywords.hpp"
#include "commands/elga_field.hpp"
#include "commands/field_concepts.hpp"
#include "commands/mesh_concept.hpp"
#include "core/error.hpp"
#include "core/number_format.hpp"
#include "lang/operators.hpp"
#include "post/check.hpp"

namespace aster::lang {
namespace {

using What = std::vector<std::pair<std::string, std::string>>;

// The node NOEUD or GROUP_NO (a group of one node) names; -1 when neither is given.
int designatedNode(const Keywords& occ, const mesh::Mesh& mesh) {
  if (occ.has("NOEUD")) return mesh.nodeIndex(occ.text("NOEUD"));
  if (!occ.has("GROUP_NO")) return -1;
  const auto& g = mesh.nodeGroup(occ.text("GROUP_NO"));
  if (g.size() != 1)
    throw Error(occ.path + ": GROUP_NO " + occ.text("GROUP_NO") + " holds " + std::to_string(g.size()) +
                " nodes; a check needs a group of one node");
  return g[0];
}

double reduce(const std::string& test, const mesh::NodalField& f, const std::vector<int>& nodes,
              const std::vector<int>& comps) {
  const std::size_t nc = f.components.size();
  double sum = 0, sumAbs = 0, mx = -HUGE_VAL, mn = HUGE_VAL;
  for (int n : nodes)
    for (int c : comps) {
      const double v = f.values[n * nc + c];
      sum += v;
      sumAbs += std::abs(v);
      mx = std::max(mx, v);
      mn = std::min(mn, v);
    }
  if (nodes.empty() || comps.empty()) throw Error("TYPE_TEST='" + test + "': the field has no value to test");
  return test == "SOMM_ABS" ? sumAbs : test == "SOMM" ? sum : test == "MAX" ? mx : mn;
}

// The value an occurrence designates in a field: TYPE_TEST or NOEUD/GROUP_NO + NOM_CMP.
double fieldValue(const Keywords& occ, const mesh::Mesh& mesh, const mesh::NodalField& f,
                  const std::vector<int>& support, const std::string& fieldName) {
  std::vector<int> nodes = support;
  if (nodes.empty())
    for (int n = 0; n < mesh.nodeCount(); ++n) nodes.push_back(n);
  if (occ.has("TYPE_TEST")) {
    std::vector<int> comps;
    if (occ.has("NOM_CMP")) {
      comps.push_back(componentIndex(f, occ.text("NOM_CMP"), fieldName));
    } else {
      for (std::size_t c = 0; c < f.components.size(); ++c) comps.push_back(static_cast<int>(c));
    }
    return reduce(occ.text("TYPE_TEST"), f, nodes, comps);
  }
  const int node = designatedNode(occ, mesh);
  if (node < 0) throw Error(occ.path + ": give NOEUD or GROUP_NO with NOM_CMP, or TYPE_TEST");
  if (!occ.has("NOM_CMP")) throw Error(occ.path + ": give NOM_CMP with the node");
  if (std::find(nodes.begin(), nodes.end(), node) == nodes.end())
    throw Error(occ.path + ": the field " + fieldName + " is not defined at node " + mesh.nodeName(node));
  return f.values[node * f.components.size() + componentIndex(f, occ.text("NOM_CMP"), fieldName)];
}

// Whether component c of a field on cells is defined on its k-th cell.
using Present = std::function<bool(std::size_t, std::size_t)>;

// The value an occurrence designates in a field on cells (ELGA or ELNO): TYPE_TEST
// over every cell, point and component it carries (or NOM_CMP), or one cell
// (GROUP_MA of one cell, or MAILLE) + NOM_CMP and, at Gauss points (ELGA), POINT;
// at the nodes of cells (ELNO), NOEUD or GROUP_NO (a node of the cell) or POINT
// (the node's rank in the cell). SOUS_POINT may only be 1: no field has sub-points.
double cellValue(const Keywords& occ, const CellField& f, const mesh::Mesh& mesh, const Present& present,
                 const std::string& fieldName) {
  const std::size_t nc = f.components.size();
  const bool atNodes = f.location == CellLocation::Nodes;
  if (occ.has("SOUS_POINT") && occ.integer("SOUS_POINT") != 1)
    throw Error(occ.path + ": SOUS_POINT=" + std::to_string(occ.integer("SOUS_POINT")) + ": the field " + fieldName +
                " has no sub-points (SOUS_POINT=1 only)");
  if (!atNodes && (occ.has("NOEUD") || occ.has("GROUP_NO")))
    throw Error(occ.path + ": " + (occ.has("NOEUD") ? "NOEUD" : "GROUP_NO") +
                " designates a node of a field at the nodes of cells (ELNO); " + fieldName +
                " is at Gauss points: give GROUP_MA and POINT");
  auto index = [&](const std::string& name) {
    auto it = std::find(f.components.begin(), f.components.end(), name);
    if (it == f.components.end()) {
      std::string list;
      for (const auto& c : f.components) list += (list.empty() ? "" : ", ") + c;
      throw Error(occ.path + ": NOM_CMP: the field " + fieldName + " has no component " + name + " (components: " +
                  list + ")");
    }
    return static_cast<std::size_t>(it - f.components.begin());
  };
  if (occ.has("TYPE_TEST")) {
    if (occ.has("POINT")) throw Error(occ.path + ": POINT designates a point of the cell of GROUP_MA, not of TYPE_TEST");
    std::vector<std::size_t> comps;
    if (occ.has("NOM_CMP")) {
      comps.push_back(index(occ.text("NOM_CMP")));
    } else {
      for (std::size_t c = 0; c < nc; ++c) comps.push_back(c);
    }
    const std::string test = occ.text("TYPE_TEST");
    double sum = 0, sumAbs = 0, mx = -HUGE_VAL, mn = HUGE_VAL;
    bool any = false;
    for (std::size_t k = 0; k < f.cells.size(); ++k)
      for (std::size_t c : comps) {
        if (!present(k, c)) continue;
        for (int q = 0; q < pointsOf(f, k); ++q) {
          const double v = f.values[f.offsets[k] + q * nc + c];
          sum += v;
          sumAbs += std::abs(v);
          mx = std::max(mx, v);
          mn = std::min(mn, v);
          any = true;
        }
      }
    if (!any) throw Error(occ.path + ": TYPE_TEST='" + test + "': the field " + fieldName + " has no value to test");
    return test == "SOMM_ABS" ? sumAbs : test == "SOMM" ? sum : test == "MAX" ? mx : mn;
  }
  int cell = -1;
  if (occ.has("MAILLE")) {
    cell = mesh.cellIndex(occ.text("MAILLE"));
  } else if (occ.has("GROUP_MA")) {
    const std::string group = occ.text("GROUP_MA");
    const auto& cells = mesh.cellGroup(group);
    if (cells.size() != 1)
      throw Error(occ.path + ": GROUP_MA " + group + " holds " + std::to_string(cells.size()) +
                  " cells; a check needs a group of one cell");
    cell = cells[0];
  } else {
    throw Error(occ.path + ": the field " + fieldName + " is on cells: give GROUP_MA or MAILLE (the cell) with " +
                (atNodes ? "NOEUD or GROUP_NO" : "POINT") + " and NOM_CMP, or TYPE_TEST");
  }
  auto it = std::find(f.cells.begin(), f.cells.end(), cell);
  if (it == f.cells.end())
    throw Error(occ.path + ": the field " + fieldName + " is not defined on cell " + mesh.cellName(cell));
  const std::size_t k = static_cast<std::size_t>(it - f.cells.begin());
  const int points = pointsOf(f, k);
  int point = 0;  // 1-based
  if (atNodes && (occ.has("NOEUD") || occ.has("GROUP_NO"))) {
    const int node = designatedNode(occ, mesh);
    const auto nodes = mesh.cellNodes(cell);
    std::string list;
    for (int a = 0; a < nodes.size(); ++a) {
      if (nodes[a] == node) point = a + 1;
      list += (list.empty() ? "" : ", ") + mesh.nodeName(nodes[a]);
    }
    if (!point)
      throw Error(occ.path + ": node " + mesh.nodeName(node) + " is not a node of cell " + mesh.cellName(cell) +
                  " (its nodes: " + list + ")");
  } else {
    if (!occ.has("POINT"))
      throw Error(occ.path + ": POINT is missing: the " + (atNodes ? "node" : "Gauss point") + " of cell " +
                  mesh.cellName(cell) + " (1 to " + std::to_string(points) + ")" +
                  (atNodes ? ", or NOEUD / GROUP_NO" : ""));
    const long long p = occ.integer("POINT");
    if (p < 1 || p > points)
      throw Error(occ.path + ": POINT=" + std::to_string(p) + ": cell " + mesh.cellName(cell) + " has " +
                  std::to_string(points) + (atNodes ? " nodes" : " Gauss points") + " in the field " + fieldName);
    point = static_cast<int>(p);
  }
  if (!occ.has("NOM_CMP")) throw Error(occ.path + ": give NOM_CMP with the cell");
  const std::size_t c = index(occ.text("NOM_CMP"));
  if (!present(k, c))
    throw Error(occ.path + ": component " + f.components[c] + " of the field " + fieldName +
                " is not defined on cell " + mesh.cellName(cell));
  return f.values[f.offsets[k] + (point - 1) * nc + c];
}

// The header columns code_aster writes for a check of a field (after the field's
// own columns): NOM_CMP, VALE_ABS (fields outside results), then TYPE_TEST (and
// the component again) or the node, cell and point designating the value.
void designationColumns(const Keywords& occ, bool showValeAbs, bool onCells, bool resu, What& what) {
  auto add = [&](const char* key) {
    if (occ.has(key)) what.push_back({key, occ.text(key)});
  };
  auto addInteger = [&](const char* key) {
    if (occ.has(key)) what.push_back({key, std::to_string(occ.integer(key))});
  };
  if (occ.has("TYPE_TEST")) {
    add("NOM_CMP");
    if (showValeAbs && occ.text("VALE_ABS") == "OUI") what.push_back({"VALE_ABS", "OUI"});
    add("TYPE_TEST");
    add("NOM_CMP");
    return;
  }
  add("NOM_CMP");
  if (showValeAbs && occ.text("VALE_ABS") == "OUI") what.push_back({"VALE_ABS", "OUI"});
  if (resu) {
    // A result's field: the node first, then the cell and its point (0: not given).
    add("NOEUD");
    add("GROUP_NO");
    if (onCells) {
      add("MAILLE");
      add("GROUP_MA");
      what.push_back({"POINT", std::to_string(occ.has("POINT") ? occ.integer("POINT") : 0)});
      addInteger("SOUS_POINT");
    }
    return;
  }
  add("MAILLE");
  add("GROUP_MA");
  add("NOEUD");
  add("GROUP_NO");
  addInteger("POINT");
  addInteger("SOUS_POINT");
}

// Fields hold reals: their checks take VALE_CALC (code_aster refuses VALE_CALC_I on them).
void needsReal(const Keywords& occ, const std::string& what) {
  if (occ.has("VALE_CALC_I"))
    throw Error(occ.path + ": " + what + " holds real values: give VALE_CALC (and VALE_REFE), not VALE_CALC_I");
}

// A count of a mesh (MAILLAGE's CARA); a group the mesh lacks counts 0, as in code_aster.
long long meshCount(const Keywords& occ, const mesh::Mesh& m) {
  const std::string cara = occ.text("CARA");
  if (cara == "NB_MAILLE") return m.cellCount();
  if (cara == "NB_NOEUD") return m.nodeCount();
  if (cara == "NB_GROUP_MA") return static_cast<long long>(m.cellGroupNames().size());
  if (cara == "NB_GROUP_NO") return static_cast<long long>(m.nodeGroupNames().size());
  const bool cells = cara == "NB_MA_GROUP_MA";
  const char* key = cells ? "NOM_GROUP_MA" : "NOM_GROUP_NO";
  if (!occ.has(key)) throw Error(occ.path + ": CARA='" + cara + "' counts the members of a group: give " + key);
  const std::string g = occ.text(key);
  if (cells) return m.hasCellGroup(g) ? static_cast<long long>(m.cellGroup(g).size()) : 0;
  return m.hasNodeGroup(g) ? static_cast<long long>(m.nodeGroup(g).size()) : 0;
}

ConceptPtr testResu(const Keywords& k, Session& session, ConceptPtr) {
  // code_aster opens each TEST_RESU with a blank line and a rule of 80 dashes.
  std::string rule = "\n" + std::string(80, '-') + "\n";
  for (const auto& occ : k.factor("MAILLAGE")) {
    const auto c = occ.conceptPtr("MAILLAGE");
    // code_aster's header of a mesh check: two fixed lines, the name in 8 characters.
    std::string name = session.nameOf(*c);
    if (name.size() < 8) name.resize(8, ' ');
    const std::string header = " ---- MAILLAGE \n      " + name + "\n";
    recordCheckLines(session, static_cast<double>(meshCount(occ, meshOf(c))), checkSpecOf(occ), rule + header, "MAILLAGE");
    rule.clear();
  }
  for (const auto& occ : k.factor("CHAM_NO")) {
    const auto c = occ.conceptPtr("CHAM_GD");
    const auto f = std::dynamic_pointer_cast<NodalFieldConcept>(c);
    if (!f || isFunctionField(*f)) throw Error(occ.path + ": " + session.nameOf(*c) + " is not a field of real nodal values");
    needsReal(occ, "the field " + session.nameOf(*c));
    What what{{"CHAM_NO", session.nameOf(*c)}};
    designationColumns(occ, true, false, false, what);
    const double v = fieldValue(occ, *f->mesh, f->field, f->support, session.nameOf(*c));
    recordCheck(session, v, checkSpecOf(occ), what, true, rule);
    rule.clear();
  }
  for (const auto& occ : k.factor("CHAM_ELEM")) {
    const auto c = occ.conceptPtr("CHAM_GD");
    const auto g = std::dynamic_pointer_cast<CellFieldConcept>(c);
    if (!g) throw Error(occ.path + ": " + session.nameOf(*c) + " is not a field on cells");
    if (const auto* e = dynamic_cast<const ElgaFieldConcept*>(g.get()); e && e->functionField)
      throw Error(occ.path + ": " + session.nameOf(*c) + " is a field of functions; evaluate it first (CREA_CHAMP OPERATION='EVAL')");
    needsReal(occ, "the field " + session.nameOf(*c));
    What what{{"CHAM_ELEM", session.nameOf(*c)}};
    designationColumns(occ, true, true, false, what);
    const Present present = [&](std::size_t kc, std::size_t cc) { return componentPresent(*g, kc, cc); };
    const double v = cellValue(occ, g->field, *g->mesh, present, session.nameOf(*c));
    // code_aster writes the header of one value of a CHAM_ELEM without Fortran's leading blank.
    recordCheck(session, v, checkSpecOf(occ), what, occ.has("TYPE_TEST"), rule);
    rule.clear();
  }
  for (const auto& occ : k.factor("RESU")) {
    const auto r = occ.concept<ResultConcept>("RESULTAT");
    // INST is found with TOLE_MACHINE and CRITERE's second values (or their only one).
    const InstantLookup how = instantLookupOf(occ);
    Keywords lookup = occ;
    lookup.setSimple("PRECISION", {Value::ofReal(how.precision)});
    lookup.setSimple("CRITERE", {Value::ofText(how.criterion)});
    const ResultInstant& inst = instantOf(*r, lookup);
    What what{{"RESULTAT", session.nameOf(*r)}, {"NUME_ORDRE", std::to_string(inst.index)}};
    if (occ.has("PARA")) {
      const std::string p = occ.text("PARA");
      what.push_back({"PARA", p});
      double v = 0;
      if (p == "ITER_GLOB") {
        // An integer: VALE_CALC_I as code_aster wants it, or VALE_CALC (compared as a real).
        v = inst.newtonIterations;
      } else if (p == "INST") {
        needsReal(occ, "PARA='INST'");
        v = inst.time;
      } else {
        throw Error(occ.path + ": PARA='" + p + "' is not stored; available: ITER_GLOB, INST");
      }
      recordCheck(session, v, checkSpecOf(occ), what, true, rule);
      rule.clear();
      continue;
    }
    const std::string name = occ.text("NOM_CHAM");
    what.push_back({"NOM_CHAM", name});
    needsReal(occ, "the field " + name);
    const auto& model = *r->model;
    if (const CellField* cf = ResultConcept::cellField(inst, name)) {
      const Present all = [](std::size_t, std::size_t) { return true; };
      designationColumns(occ, false, true, true, what);
      recordCheck(session, cellValue(occ, *cf, model.mesh(), all, name), checkSpecOf(occ), what, true, rule);
      rule.clear();
      continue;
    }
    ResultConcept::requireNotExcluded(inst, name);
    // A cell beside the node of a nodal field says no more than the node (code_aster's
    // studies write MAILLE there): accepted when it holds the node.
    const int node = occ.has("MAILLE") ? designatedNode(occ, model.mesh()) : -1;
    if (node >= 0) {
      const auto nodes = model.mesh().cellNodes(model.mesh().cellIndex(occ.text("MAILLE")));
      if (std::find(nodes.begin(), nodes.end(), node) == nodes.end())
        throw Error(occ.path + ": MAILLE " + occ.text("MAILLE") + " does not hold the node " +
                    model.mesh().nodeName(node) + " of this nodal field");
    }
    for (const char* key : {"GROUP_MA", "MAILLE", "POINT", "SOUS_POINT"})
      if (occ.has(key) && !(node >= 0 && std::string(key) == "MAILLE"))
        throw Error(occ.path + ": " + key + " designates a cell or a point of a field on cells; NOM_CHAM='" + name +
                    "' is a nodal field: give NOEUD or GROUP_NO");
    designationColumns(occ, false, false, true, what);
    const double v = fieldValue(occ, model.mesh(), ResultConcept::nodalField(inst, name),
                                r->nodalSupportOf(inst, name), name);
    recordCheck(session, v, checkSpecOf(occ), what, true, rule);
    rule.clear();
  }
  return nullptr;
}

RegisterOperator reg("TEST_RESU", testResu);

}  // namespace
}  // namespace aster::lang
