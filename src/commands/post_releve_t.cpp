// POST_RELEVE_T: values of a field at nodes (GROUP_NO in the group's order,
// NOEUD, or TOUT) into a table, per occurrence of ACTION:
//  - OPERATION='EXTRACTION': one row per node: INTITULE, NOEUD, NUME_ORDRE and
//    INST (from a result), ABSC_CURV (distance along the listed nodes), COOR_X,
//    COOR_Y, then one column per component. A field at cell nodes (ELNO) is
//    averaged at each node over the field's cells there (MOYE_NOEUD='OUI', the
//    default), or gives one row per (node, cell) with a MAILLE column
//    (MOYE_NOEUD='NON'); GROUP_MA / MAILLE restrict the cells.
//  - RESULTANTE (with EXTRACTION): one row per instant, the sum over the nodes
//    of each component named; MOMENT ('DRZ', and DRX, DRY) with POINT adds the
//    moment about POINT of the resultant forces (DX, DY, DZ) at the nodes.
//  - OPERATION='MOYENNE': along the path of the listed nodes (abscissa s from
//    the first node, length L, the field linear between nodes), six rows per
//    instant by QUANTITE: MOMENT_0 = (1/L) int v ds (the mean), MOMENT_1 =
//    (12/L^2) int v (s - L/2) ds (the difference between the ends of the
//    linear fit), MINIMUM, MAXIMUM, MOYE_INT = MOMENT_0 - MOMENT_1/2, MOYE_EXT
//    = MOMENT_0 + MOMENT_1/2 (code_aster's linearization along a segment).
// Fields at Gauss points (ELGA) are refused: CALC_CHAMP gives them at nodes.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>

#include "commands/field_concepts.hpp"
#include "commands/instant_selection.hpp"
#include "commands/selection.hpp"
#include "commands/table_concept.hpp"
#include "core/error.hpp"
#include "core/messages.hpp"
#include "lang/operators.hpp"

namespace aster::lang {
namespace {

using Row = std::vector<std::pair<std::string, post::TableValue>>;

// One field to read: nodal (`nodal`, defined on `support`, empty: everywhere) or at cell nodes (`cells`).
struct Source {
  const mesh::NodalField* nodal = nullptr;
  const CellField* cells = nullptr;
  std::vector<int> support;
  int index = -1;
  double time = 0;
};

// The values of the components `ci` of a field at the listed nodes, per node (or per (node, cell)).
struct Sample {
  int node;
  int cell = -1;  // MOYE_NOEUD='NON': the cell of an ELNO value
  std::vector<double> values;
};

class Reader {
 public:
  Reader(const mesh::Mesh& mesh, const Keywords& occ, const std::string& what) : mesh_(mesh), occ_(occ), what_(what) {
    if (occ.has("GROUP_MA") || occ.has("MAILLE")) {
      restricted_ = true;
      for (const auto& g : occ.has("GROUP_MA") ? occ.texts("GROUP_MA") : std::vector<std::string>{})
        for (int c : mesh.cellGroup(g)) keep_.insert(c);
      for (int c : namedCells(mesh, occ, "MAILLE")) keep_.insert(c);
    }
  }

  std::vector<std::string> components(const Source& s) const {
    return s.nodal ? s.nodal->components : s.cells->components;
  }

  // The samples at `nodes`, components `cmps`; `perCell`: ELNO values cell by cell.
  std::vector<Sample> read(const Source& s, const std::vector<int>& nodes, const std::vector<std::string>& cmps,
                           bool perCell) const {
    const auto all = components(s);
    std::vector<int> ci;
    for (const auto& c : cmps) ci.push_back(componentIndex(all, c, what_));
    std::vector<Sample> out;
    if (s.nodal) {
      std::vector<char> in(mesh_.nodeCount(), s.support.empty() ? 1 : 0);
      for (int n : s.support) in[n] = 1;
      for (int n : nodes) {
        if (!in[n]) throw Error(occ_.path + ": the field " + what_ + " is not defined at node " + mesh_.nodeName(n));
        Sample x{n, -1, {}};
        for (int c : ci) x.values.push_back(s.nodal->values[static_cast<std::size_t>(n) * all.size() + c]);
        out.push_back(std::move(x));
      }
      return out;
    }
    // ELNO: the field's cells at each node, in the field's order.
    const CellField& f = *s.cells;
    std::map<int, std::vector<std::pair<std::size_t, int>>> at;  // node -> (field cell k, local node)
    for (std::size_t k = 0; k < f.cells.size(); ++k) {
      if (restricted_ && !keep_.count(f.cells[k])) continue;
      const auto cn = mesh_.cellNodes(f.cells[k]);
      for (int a = 0; a < static_cast<int>(cn.size()); ++a) at[cn[a]].emplace_back(k, a);
    }
    for (int n : nodes) {
      const auto it = at.find(n);
      if (it == at.end())
        throw Error(occ_.path + ": the field " + what_ + " has no value at node " + mesh_.nodeName(n) +
                    (restricted_ ? " on the cells of GROUP_MA / MAILLE" : " (no cell of the field holds it)"));
      auto valueOf = [&](std::size_t k, int a, int c) {
        return f.values[static_cast<std::size_t>(f.offsets[k]) + static_cast<std::size_t>(a) * all.size() + c];
      };
      if (perCell) {
        for (const auto& [k, a] : it->second) {
          Sample x{n, f.cells[k], {}};
          for (int c : ci) x.values.push_back(valueOf(k, a, c));
          out.push_back(std::move(x));
        }
      } else {
        Sample x{n, -1, {}};
        for (int c : ci) {
          double sum = 0;
          for (const auto& [k, a] : it->second) sum += valueOf(k, a, c);
          x.values.push_back(sum / static_cast<double>(it->second.size()));
        }
        out.push_back(std::move(x));
      }
    }
    return out;
  }

 private:
  const mesh::Mesh& mesh_;
  const Keywords& occ_;
  std::string what_;
  bool restricted_ = false;
  std::set<int> keep_;
};

void addInstant(Row& row, const Source& s) {
  if (s.index < 0) return;
  row.push_back({"NUME_ORDRE", post::TableValue::ofInteger(s.index)});
  row.push_back({"INST", post::TableValue::ofReal(s.time)});
}

// The fields an occurrence reads, with the mesh and the field's name for messages.
std::vector<Source> sourcesOf(const Keywords& occ, Session& session, std::shared_ptr<const mesh::Mesh>& mesh,
                              std::string& what) {
  std::vector<Source> sources;
  auto checkCells = [&](const CellField& f) {
    if (f.location == CellLocation::GaussPoints)
      throw Error(occ.path + ": " + what + " is a field at Gauss points; POST_RELEVE_T reads fields at nodes " +
                  "(CALC_CHAMP gives the ELNO and NOEU fields)");
  };
  if (occ.has("CHAM_GD")) {
    const auto c = occ.conceptPtr("CHAM_GD");
    what = session.nameOf(*c);
    if (auto f = std::dynamic_pointer_cast<NodalFieldConcept>(c); f && !isFunctionField(*f)) {
      sources.push_back({&f->field, nullptr, f->support});
      mesh = f->mesh;
    } else if (auto g = std::dynamic_pointer_cast<CellFieldConcept>(c)) {
      checkCells(g->field);
      sources.push_back({nullptr, &g->field, {}});
      mesh = g->mesh;
    } else {
      throw Error(occ.path + ": CHAM_GD " + what + " is not a field of real values");
    }
    return sources;
  }
  const auto r = occ.concept<ResultConcept>("RESULTAT");
  mesh = r->model->meshPtr();
  what = occ.text("NOM_CHAM");
  for (const ResultInstant* i : selectedInstants(*r, occ)) {
    if (const CellField* g = ResultConcept::cellField(*i, what)) {
      checkCells(*g);
      sources.push_back({nullptr, g, {}, i->index, i->time});
    } else {
      sources.push_back({&ResultConcept::nodalField(*i, what), nullptr, {}, i->index, i->time});
    }
  }
  return sources;
}

void extraction(const Keywords& occ, const Reader& reader, const mesh::Mesh& mesh, const std::vector<Source>& sources,
                const std::vector<int>& nodes, post::Table& table) {
  const bool perCell = occ.text("MOYE_NOEUD") == "NON";
  for (const auto& s : sources) {
    const std::vector<std::string> cmps = occ.has("NOM_CMP") ? occ.texts("NOM_CMP") : reader.components(s);
    double absc = 0;
    int previous = -1;
    for (const Sample& x : reader.read(s, nodes, cmps, perCell)) {
      if (previous >= 0 && x.node != previous) absc += (mesh.node(x.node) - mesh.node(previous)).norm();
      previous = x.node;
      Row row{{"INTITULE", post::TableValue::ofText(occ.text("INTITULE"))},
              {"NOEUD", post::TableValue::ofText(mesh.nodeName(x.node))}};
      if (x.cell >= 0) row.push_back({"MAILLE", post::TableValue::ofText(mesh.cellName(x.cell))});
      addInstant(row, s);
      row.push_back({"ABSC_CURV", post::TableValue::ofReal(absc)});
      row.push_back({"COOR_X", post::TableValue::ofReal(mesh.node(x.node)(0))});
      row.push_back({"COOR_Y", post::TableValue::ofReal(mesh.node(x.node)(1))});
      for (std::size_t c = 0; c < cmps.size(); ++c) row.push_back({cmps[c], post::TableValue::ofReal(x.values[c])});
      table.addRow(row);
    }
  }
}

void resultant(const Keywords& occ, const Reader& reader, const mesh::Mesh& mesh, const std::vector<Source>& sources,
               const std::vector<int>& nodes, post::Table& table) {
  const std::vector<std::string> sums = occ.texts("RESULTANTE");
  const std::vector<std::string> moments = occ.has("MOMENT") ? occ.texts("MOMENT") : std::vector<std::string>{};
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  if (!moments.empty()) {
    const auto p = occ.reals("POINT");
    if (p.size() < 2 || p.size() > 3)
      throw Error(occ.path + ": POINT gives " + std::to_string(p.size()) + " coordinate(s), expected 2 or 3");
    for (std::size_t d = 0; d < p.size(); ++d) point[static_cast<int>(d)] = p[d];
  }
  for (const auto& s : sources) {
    std::vector<std::string> cmps = sums;
    // The force at a node for the moments: DX, DY and DZ when the field has it.
    std::vector<std::string> force;
    if (!moments.empty()) {
      const auto all = reader.components(s);
      force = {"DX", "DY"};
      if (std::find(all.begin(), all.end(), "DZ") != all.end()) force.push_back("DZ");
      cmps.insert(cmps.end(), force.begin(), force.end());
    }
    std::vector<double> total(sums.size(), 0.0);
    Eigen::Vector3d moment = Eigen::Vector3d::Zero();
    for (const Sample& x : reader.read(s, nodes, cmps, false)) {
      for (std::size_t c = 0; c < sums.size(); ++c) total[c] += x.values[c];
      if (!moments.empty()) {
        Eigen::Vector3d f = Eigen::Vector3d::Zero();
        for (std::size_t d = 0; d < force.size(); ++d) f[static_cast<int>(d)] = x.values[sums.size() + d];
        const Eigen::Vector3d r = mesh.node(x.node) - point;
        moment += Eigen::Vector3d(r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2], r[0] * f[1] - r[1] * f[0]);
      }
    }
    Row row{{"INTITULE", post::TableValue::ofText(occ.text("INTITULE"))}};
    addInstant(row, s);
    for (std::size_t c = 0; c < sums.size(); ++c) row.push_back({sums[c], post::TableValue::ofReal(total[c])});
    for (const auto& m : moments)
      row.push_back({m, post::TableValue::ofReal(moment[m == "DRX" ? 0 : m == "DRY" ? 1 : 2])});
    table.addRow(row);
  }
}

void mean(const Keywords& occ, const Reader& reader, const mesh::Mesh& mesh, const std::vector<Source>& sources,
          const std::vector<int>& nodes, post::Table& table) {
  if (nodes.size() < 2)
    throw Error(occ.path + ": OPERATION='MOYENNE' needs a path of at least 2 nodes, " + std::to_string(nodes.size()) +
                " given");
  std::vector<double> s(nodes.size(), 0.0);
  for (std::size_t i = 1; i < nodes.size(); ++i) s[i] = s[i - 1] + (mesh.node(nodes[i]) - mesh.node(nodes[i - 1])).norm();
  const double length = s.back();
  if (!(length > 0)) throw Error(occ.path + ": OPERATION='MOYENNE': the nodes of the path are all at one point");
  for (const auto& src : sources) {
    const std::vector<std::string> cmps = occ.has("NOM_CMP") ? occ.texts("NOM_CMP") : reader.components(src);
    const auto samples = reader.read(src, nodes, cmps, false);
    const char* names[6] = {"MOMENT_0", "MOMENT_1", "MINIMUM", "MAXIMUM", "MOYE_INT", "MOYE_EXT"};
    std::vector<std::array<double, 6>> q(cmps.size());
    for (std::size_t c = 0; c < cmps.size(); ++c) {
      double integral = 0, first = 0;  // int v ds, int v s ds (exact for v linear on each segment)
      double lo = samples[0].values[c], hi = lo;
      for (std::size_t i = 0; i + 1 < nodes.size(); ++i) {
        const double v1 = samples[i].values[c], v2 = samples[i + 1].values[c];
        const double h = s[i + 1] - s[i];
        integral += 0.5 * h * (v1 + v2);
        first += h / 6.0 * (v1 * s[i] + 4.0 * 0.5 * (v1 + v2) * 0.5 * (s[i] + s[i + 1]) + v2 * s[i + 1]);
        lo = std::min({lo, v1, v2});
        hi = std::max({hi, v1, v2});
      }
      const double m0 = integral / length;
      const double m1 = 12.0 / (length * length) * (first - 0.5 * length * integral);
      q[c] = {m0, m1, lo, hi, m0 - 0.5 * m1, m0 + 0.5 * m1};
    }
    for (int k = 0; k < 6; ++k) {
      Row row{{"INTITULE", post::TableValue::ofText(occ.text("INTITULE"))}};
      addInstant(row, src);
      row.push_back({"QUANTITE", post::TableValue::ofText(names[k])});
      for (std::size_t c = 0; c < cmps.size(); ++c) row.push_back({cmps[c], post::TableValue::ofReal(q[c][k])});
      table.addRow(row);
    }
  }
}

ConceptPtr postReleveT(const Keywords& k, Session& session, ConceptPtr reuse) {
  post::Table table;
  if (reuse) table = static_cast<TableConcept&>(*reuse).table;
  for (const auto& occ : k.factor("ACTION")) {
    std::shared_ptr<const mesh::Mesh> mesh;
    std::string what;
    const std::vector<Source> sources = sourcesOf(occ, session, mesh, what);
    std::vector<int> nodes;
    if (occ.has("GROUP_NO")) {
      for (const auto& g : occ.texts("GROUP_NO"))
        for (int n : mesh->nodeGroup(g)) nodes.push_back(n);
    } else if (occ.has("NOEUD")) {
      nodes = namedNodes(*mesh, occ, "NOEUD");
    } else {  // TOUT: the nodes of the field
      if (sources.front().nodal) nodes = sources.front().support;
      if (nodes.empty() && sources.front().nodal)
        for (int n = 0; n < mesh->nodeCount(); ++n) nodes.push_back(n);
      if (sources.front().cells) {
        std::set<int> seen;
        for (int c : sources.front().cells->cells)
          for (int n : mesh->cellNodes(c)) seen.insert(n);
        nodes.assign(seen.begin(), seen.end());
      }
    }
    const Reader reader(*mesh, occ, what);
    const std::string operation = occ.text("OPERATION");
    if (operation == "MOYENNE") {
      if (occ.has("RESULTANTE")) throw Error(occ.path + ": RESULTANTE goes with OPERATION='EXTRACTION'");
      mean(occ, reader, *mesh, sources, nodes, table);
    } else if (occ.has("RESULTANTE")) {
      resultant(occ, reader, *mesh, sources, nodes, table);
    } else {
      extraction(occ, reader, *mesh, sources, nodes, table);
    }
  }
  if (k.has("TITRE")) table.titles = k.texts("TITRE");
  if (k.integer("INFO") >= 2) Messages::info(table.formatTableau());
  if (reuse) {
    static_cast<TableConcept&>(*reuse).table = table;
    return reuse;
  }
  return std::make_shared<TableConcept>(table);
}

RegisterOperator reg("POST_RELEVE_T", postReleveT);

}  // namespace
}  // namespace aster::lang
