// AFFE_CHAR_MECA (constant values), AFFE_CHAR_MECA_F (functions of X, Y, INST),
// AFFE_CHAR_CINE and AFFE_CHAR_CINE_F (imposed displacements eliminated from the
// system). Linear relations (LIAISON_*, FACE_IMPO DNOR/DTAN) are read into
// model::LinearRelation, eliminated by the analyses.
#include <algorithm>
#include <cmath>

#include "commands/function_concepts.hpp"
#include "commands/model_concepts.hpp"
#include "commands/selection.hpp"
#include "core/error.hpp"
#include "core/number_format.hpp"
#include "fem/edge_geometry.hpp"
#include "lang/operators.hpp"
#include "linalg/linear_constraints.hpp"
#include "mesh/orient.hpp"

namespace aster::lang {
namespace {

// currentPosition: the function may depend on XF, YF, ZF (a pressure, which
// follows the deformed edge when applied with TYPE_CHARGE='SUIV').
model::SpaceFunction valueOf(const Keywords& occ, const std::string& key, bool currentPosition = false) {
  if (!occ.has(key)) return model::SpaceFunction(0.0);
  const Value& v = occ.value(key);
  if (v.isNumber()) return model::SpaceFunction(v.real);
  try {
    return model::SpaceFunction(functionOf(v.concept), currentPosition);
  } catch (const Error& e) {
    throw Error(occ.path + "/" + key + ": " + e.what());
  }
}

std::vector<int> nodesOf(const mesh::Mesh& mesh, const Keywords& occ) { return selectNodes(mesh, occ); }

std::vector<int> cellsOf(const mesh::Mesh& mesh, const Keywords& occ) { return selectCells(mesh, occ); }

void requireInModel(const model::Model& m, const Keywords& occ, const std::vector<int>& nodes) {
  for (int n : nodes)
    if (!m.nodeInModel(n))
      throw Error(occ.path + ": node " + m.mesh().nodeName(n) + " carries no element of the model, so no DX, DY");
}

void readImposedAt(const Keywords& occ, const std::vector<int>& nodes, model::MechanicalLoad& load) {
  static const char* components[] = {"DX", "DY"};
  for (int c = 0; c < 2; ++c)
    if (occ.has(components[c])) load.imposed.push_back({nodes, c, valueOf(occ, components[c])});
}

void readImposed(const model::Model& m, const Keywords& occ, model::MechanicalLoad& load) {
  const auto nodes = nodesOf(m.mesh(), occ);
  requireInModel(m, occ, nodes);
  if (!occ.has("DX") && !occ.has("DY")) throw Error(occ.path + ": give at least one of DX, DY");
  readImposedAt(occ, nodes, load);
}

int componentOf(const std::string& ddl, const Keywords& occ) {
  if (ddl == "DX") return 0;
  if (ddl == "DY") return 1;
  throw Error(occ.path + "/DDL: '" + ddl + "' is not an unknown of the model (DX, DY are)");
}

// "AFFE_CHAR_MECA (study.lua:12) LIAISON_DDL[2]": where a relation was defined.
std::string commandOf(const Session& session) { return session.command + " (" + session.where + ") "; }
std::string originOf(const Session& session, const Keywords& occ) { return commandOf(session) + occ.path; }

// LIAISON_DDL: the nodes of the groups in their order (a node may come twice, with two DDL).
void readLiaisonDdl(const model::Model& m, const Session& session, const Keywords& occ,
                    model::MechanicalLoad& load) {
  const mesh::Mesh& mesh = m.mesh();
  std::vector<int> nodes;
  for (const auto& g : occ.texts("GROUP_NO")) {
    const auto& members = mesh.nodeGroup(g);
    nodes.insert(nodes.end(), members.begin(), members.end());
  }
  for (int n : namedNodes(mesh, occ, "NOEUD")) nodes.push_back(n);
  const auto ddl = occ.texts("DDL");
  const auto coef = occ.reals("COEF_MULT");
  if (nodes.size() != ddl.size() || coef.size() != ddl.size())
    throw Error(occ.path + ": " + std::to_string(nodes.size()) + " node(s), " + std::to_string(ddl.size()) +
                " DDL and " + std::to_string(coef.size()) + " COEF_MULT: one of each per term of the relation");
  requireInModel(m, occ, nodes);
  model::LinearRelation rel;
  for (std::size_t i = 0; i < nodes.size(); ++i) rel.terms.push_back({nodes[i], componentOf(ddl[i], occ), coef[i]});
  rel.value = valueOf(occ, "COEF_IMPO");
  rel.origin = originOf(session, occ);
  load.relations.push_back(std::move(rel));
}

// LIAISON_UNIF: u(n_i, c) - u(n_0, c) = 0 for every other node n_i and each DDL c.
void readLiaisonUnif(const model::Model& m, const Session& session, const Keywords& occ,
                     model::MechanicalLoad& load) {
  const auto nodes = nodesOf(m.mesh(), occ);
  requireInModel(m, occ, nodes);
  std::vector<int> components;
  for (const auto& d : occ.texts("DDL")) components.push_back(componentOf(d, occ));
  for (int c : components)
    for (std::size_t i = 1; i < nodes.size(); ++i) {
      model::LinearRelation rel;
      rel.terms = {{nodes[i], c, 1.0}, {nodes[0], c, -1.0}};
      rel.value = model::SpaceFunction(0.0);
      rel.origin = originOf(session, occ);
      load.relations.push_back(std::move(rel));
    }
}

// LIAISON_SOLIDE in 2D, linearized: u(M) = u(A) + theta k x AM for every node M, with A
// the first node and theta read from B, the node farthest from A:
//   (u(B) - u(A)) . AB = 0,
//   u(M) - u(A) - theta(u) k x AM = 0, theta(u) = (u(B) - u(A)) . (k x AB) / |AB|^2,
// 2N - 3 relations for N nodes. Nodes within DIST_MIN of A, or all of them when the set
// is a point, just move as A does; one node: nothing.
void readLiaisonSolide(const model::Model& m, const Session& session, const Keywords& occ,
                       model::MechanicalLoad& load) {
  const mesh::Mesh& mesh = m.mesh();
  const auto nodes = nodesOf(mesh, occ);
  requireInModel(m, occ, nodes);
  if (nodes.size() < 2) return;
  const int a = nodes[0];
  const Eigen::Vector2d pa = mesh.node(a).head<2>();
  int b = a;
  double farthest = 0;
  for (int n : nodes) {
    const double d = (mesh.node(n).head<2>() - pa).norm();
    if (d > farthest) farthest = d, b = n;
  }
  const double distMin = occ.has("DIST_MIN") ? occ.real("DIST_MIN") : 1e-10 * farthest;
  const std::string origin = originOf(session, occ);
  auto relation = [&](std::vector<model::RelationTerm> terms) {
    model::LinearRelation rel;
    rel.terms = std::move(terms);
    rel.value = model::SpaceFunction(0.0);
    rel.origin = origin;
    load.relations.push_back(std::move(rel));
  };
  if (farthest <= distMin) {  // a point: no rotation to read
    for (int n : nodes)
      if (n != a)
        for (int c = 0; c < 2; ++c) relation({{n, c, 1.0}, {a, c, -1.0}});
    return;
  }
  const Eigen::Vector2d d = mesh.node(b).head<2>() - pa;
  const double l2 = d.squaredNorm();
  relation({{b, 0, d(0)}, {a, 0, -d(0)}, {b, 1, d(1)}, {a, 1, -d(1)}});
  // theta(u) = (-d_y (u_Bx - u_Ax) + d_x (u_By - u_Ay)) / l2
  auto theta = [&](double scale) {
    return std::vector<model::RelationTerm>{{b, 0, -scale * d(1) / l2},
                                            {a, 0, scale * d(1) / l2},
                                            {b, 1, scale * d(0) / l2},
                                            {a, 1, -scale * d(0) / l2}};
  };
  for (int n : nodes) {
    if (n == a || n == b) continue;
    const Eigen::Vector2d am = mesh.node(n).head<2>() - pa;
    if (am.norm() <= distMin) {
      for (int c = 0; c < 2; ++c) relation({{n, c, 1.0}, {a, c, -1.0}});
      continue;
    }
    // u_Mx - u_Ax + am_y theta = 0, u_My - u_Ay - am_x theta = 0
    std::vector<model::RelationTerm> x = {{n, 0, 1.0}, {a, 0, -1.0}}, y = {{n, 1, 1.0}, {a, 1, -1.0}};
    for (const auto& t : theta(am(1))) x.push_back(t);
    for (const auto& t : theta(-am(0))) y.push_back(t);
    relation(std::move(x));
    relation(std::move(y));
  }
}

// The unit tangent dx/dxi at a node of an edge, for each node of the edge in its order.
std::vector<Eigen::Vector2d> nodalTangents(const mesh::Mesh& mesh, int cell) {
  const auto& nodes = mesh.cellNodes(cell);
  std::vector<Eigen::Vector2d> out;
  auto frames = [&](auto tag, std::initializer_list<double> xis) {
    constexpr fem::CellType T = decltype(tag)::value;
    fem::EdgeCoords<T> X;
    for (int i = 0; i < X.rows(); ++i) X.row(i) = mesh.node(nodes[i]).template head<2>().transpose();
    for (double xi : xis) out.push_back(fem::edgeFrame<T>(X, xi).tangent);
  };
  if (mesh.cellType(cell) == mesh::CellType::SEG2)
    frames(std::integral_constant<fem::CellType, fem::CellType::SEG2>(), {-1.0, 1.0});
  else
    frames(std::integral_constant<fem::CellType, fem::CellType::SEG3>(), {-1.0, 1.0, 0.0});
  return out;
}

// FACE_IMPO: DX, DY imposed on the nodes of the edges; DNOR, DTAN as one relation per node
// along the node's normal n (the mean of the unit normals (t_y, -t_x) of the edges there,
// normalized) or tangent (-n_y, n_x).
void readFaceImpo(const model::Model& m, const Session& session, const Keywords& occ, model::MechanicalLoad& load) {
  const mesh::Mesh& mesh = m.mesh();
  const auto cells = cellsOf(mesh, occ);
  for (int c : cells)
    if (mesh.cellType(c) != mesh::CellType::SEG2 && mesh.cellType(c) != mesh::CellType::SEG3)
      throw Error(occ.path + ": FACE_IMPO applies to edges (SEG2, SEG3) in 2D; cell " + mesh.cellName(c) + " is a " +
                  mesh::cellTypeName(mesh.cellType(c)));
  m.checkCellsOnModel(cells, occ.path);
  std::vector<char> excluded(mesh.nodeCount(), 0);
  for (int n : excludedNodes(mesh, occ)) excluded[n] = 1;
  std::vector<int> nodes;
  std::vector<Eigen::Vector2d> normalSum(mesh.nodeCount(), Eigen::Vector2d::Zero());
  std::vector<char> seen(mesh.nodeCount(), 0);
  for (int c : cells) {
    std::vector<Eigen::Vector2d> tangents;
    try {
      tangents = nodalTangents(mesh, c);
    } catch (const Error& e) {
      throw Error(occ.path + ": cell " + mesh.cellName(c) + ": " + e.what());
    }
    const auto& cn = mesh.cellNodes(c);
    for (std::size_t i = 0; i < tangents.size(); ++i) {
      const int n = cn[i];
      normalSum[n] += Eigen::Vector2d(tangents[i](1), -tangents[i](0));
      if (!seen[n] && !excluded[n]) {
        seen[n] = 1;
        nodes.push_back(n);
      }
    }
  }
  if (nodes.empty())
    throw Error(occ.path + ": every node is left out by SANS_GROUP_NO, SANS_NOEUD, SANS_GROUP_MA or SANS_MAILLE");
  readImposedAt(occ, nodes, load);
  for (const char* key : {"DNOR", "DTAN"}) {
    if (!occ.has(key)) continue;
    const model::SpaceFunction value = valueOf(occ, key);
    const bool normal = key[1] == 'N';
    for (int n : nodes) {
      const double len = normalSum[n].norm();
      if (!(len > 1e-12))
        throw Error(occ.path + "/" + key + ": the edges at node " + mesh.nodeName(n) +
                    " have opposite normals, so the node has none");
      const Eigen::Vector2d nn = normalSum[n] / len;
      const Eigen::Vector2d dir = normal ? nn : Eigen::Vector2d(-nn(1), nn(0));
      model::LinearRelation rel;
      rel.terms = {{n, 0, dir(0)}, {n, 1, dir(1)}};
      rel.value = value;
      rel.origin = originOf(session, occ) + "/" + key;
      load.relations.push_back(std::move(rel));
    }
  }
}

// VERI_NORM='OUI': a pressure pushes against the normal of each edge, so an edge
// walked the wrong way round would pull instead. Every PRES_REP edge must have
// its normal out of the 2D cell it bounds, as code_aster checks.
void checkOutwardNormals(const mesh::Mesh& mesh, const Keywords& occ, const std::vector<int>& cells) {
  const auto inward = mesh::inwardSegments(mesh, cells);
  if (inward.empty()) return;
  const int s = inward.front().segment;
  std::string group;
  for (const auto& g : occ.texts("GROUP_MA")) {
    const auto& members = mesh.cellGroup(g);
    if (std::find(members.begin(), members.end(), s) != members.end()) {
      group = g;
      break;
    }
  }
  std::string groups;
  for (const auto& g : occ.texts("GROUP_MA")) groups += (groups.empty() ? "'" : ", '") + g + "'";
  throw Error(occ.path + (group.empty() ? "/MAILLE" : "/GROUP_MA") + ": the normal of cell " + mesh.cellName(s) +
              (group.empty() ? "" : " (group " + group + ")") + " points into the cell " +
              mesh.cellName(inward.front().cell) + " it bounds" +
              (inward.size() > 1 ? " (" + std::to_string(inward.size()) + " of the " + std::to_string(cells.size()) +
                                       " edges are reversed)"
                                 : std::string()) +
              ", so the pressure would pull; orient the edges first: MODI_MAILLAGE{reuse = <mesh>, MAILLAGE = <mesh>, "
              "ORIE_PEAU = {GROUP_MA_PEAU = {" + (groups.empty() ? std::string("<a group holding them>") : groups) +
              "}}} (VERI_NORM = 'NON' skips this check)");
}

// The imposed values and relations of one load with constant values, eliminated: a set
// that contradicts itself is refused where it is defined (values that are functions are
// checked by the analysis at each instant, as are sets made of several loads).
void checkRelations(const model::Model& m, const model::MechanicalLoad& load, const Session& session) {
  if (load.relations.empty()) return;
  for (const auto& rel : load.relations)
    if (!rel.value.isConstant()) return;
  for (const auto& im : load.imposed)
    if (!im.value.isConstant()) return;
  const mesh::Mesh& mesh = m.mesh();
  std::vector<int> dofOfNode(mesh.nodeCount(), -1);
  int n = 0;
  auto dof = [&](int node, int c) {
    if (dofOfNode[node] < 0) dofOfNode[node] = n, n += 2;
    return dofOfNode[node] + c;
  };
  auto at = [&](const model::SpaceFunction& f, int node) {
    const Eigen::Vector3d p = mesh.node(node);
    return f(p(0), p(1), p(2), 0.0);
  };
  std::vector<std::pair<int, double>> fixed;
  for (const auto& im : load.imposed)
    for (int node : im.nodes) fixed.emplace_back(dof(node, im.component), at(im.value, node));
  std::vector<linalg::LinearRelation> relations;
  for (const auto& rel : load.relations) {
    linalg::LinearRelation r;
    for (const auto& t : rel.terms) r.terms.emplace_back(dof(t.node, t.component), t.coefficient);
    r.rhs = at(rel.value, rel.terms.front().node);
    relations.push_back(std::move(r));
  }
  std::vector<char> isFixed(n, 0);
  Eigen::VectorXd values = Eigen::VectorXd::Zero(n);
  for (const auto& [d, v] : fixed) isFixed[d] = 1, values(d) = v;
  try {
    linalg::ConstraintElimination(n, isFixed, values, relations);
  } catch (const linalg::ContradictoryRelationError& e) {
    // The command and its line are those of the message already: the keyword is enough.
    const std::string& origin = load.relations[e.relation()].origin;
    throw Error(origin.substr(commandOf(session).size()) + ": this linear relation contradicts the imposed displacements "
                "and the relations before it (its two sides differ by " + format::shortest(e.mismatch()) + ")");
  }
}

model::MechanicalLoad readMechanical(const model::Model& m, const Keywords& k, const Session& session) {
  model::MechanicalLoad load;
  const auto& mesh = m.mesh();
  for (const auto& occ : k.factor("DDL_IMPO")) readImposed(m, occ, load);
  for (const auto& occ : k.factor("FACE_IMPO")) readFaceImpo(m, session, occ, load);
  for (const auto& occ : k.factor("LIAISON_DDL")) readLiaisonDdl(m, session, occ, load);
  for (const auto& occ : k.factor("LIAISON_UNIF")) readLiaisonUnif(m, session, occ, load);
  for (const auto& occ : k.factor("LIAISON_SOLIDE")) readLiaisonSolide(m, session, occ, load);
  for (const auto& occ : k.factor("FORCE_CONTOUR")) {
    const auto cells = cellsOf(mesh, occ);
    for (int c : cells)
      if (mesh::topologicalDimension(mesh.cellType(c)) != 1)
        throw Error(occ.path + ": FORCE_CONTOUR applies to segments; cell " + mesh.cellName(c) + " is a " +
                    mesh::cellTypeName(mesh.cellType(c)));
    m.checkCellsOnModel(cells, occ.path);
    load.edgeForces.push_back({cells, valueOf(occ, "FX"), valueOf(occ, "FY")});
  }
  for (const auto& occ : k.factor("FORCE_INTERNE")) {
    std::vector<int> cells;
    for (int c : selectCells(mesh, occ))
      if (m.hasCell(c)) cells.push_back(c);
    if (cells.empty()) throw Error(occ.path + ": no cell of the model is selected");
    load.bodyForces.push_back({cells, valueOf(occ, "FX"), valueOf(occ, "FY")});
  }
  for (const auto& occ : k.factor("PRES_REP")) {
    const auto cells = cellsOf(mesh, occ);
    for (int c : cells)
      if (mesh::topologicalDimension(mesh.cellType(c)) != 1)
        throw Error(occ.path + ": PRES_REP applies to segments in 2D; cell " + mesh.cellName(c) + " is a " +
                    mesh::cellTypeName(mesh.cellType(c)));
    m.checkCellsOnModel(cells, occ.path);
    if (k.text("VERI_NORM") == "OUI") checkOutwardNormals(mesh, occ, cells);
    load.pressures.push_back({cells, valueOf(occ, "PRES", true)});
  }
  for (const auto& occ : k.factor("FORCE_NODALE"))
    load.nodalForces.push_back({nodesOf(mesh, occ), valueOf(occ, "FX"), valueOf(occ, "FY")});
  checkRelations(m, load, session);
  return load;
}

ConceptPtr affeCharMeca(const Keywords& k, Session& session, ConceptPtr) {
  auto m = static_cast<ModelConcept&>(*k.conceptPtr("MODELE")).model;
  return std::make_shared<LoadConcept>(m, readMechanical(*m, k, session));
}

ConceptPtr affeCharCine(const Keywords& k, Session&, ConceptPtr) {
  auto m = static_cast<ModelConcept&>(*k.conceptPtr("MODELE")).model;
  model::MechanicalLoad load;
  load.kinematic = true;
  for (const auto& occ : k.factor("MECA_IMPO")) readImposed(*m, occ, load);
  return std::make_shared<LoadConcept>(m, std::move(load));
}

RegisterOperator reg1("AFFE_CHAR_MECA", affeCharMeca);
RegisterOperator reg2("AFFE_CHAR_MECA_F", affeCharMeca);
RegisterOperator reg3("AFFE_CHAR_CINE", affeCharCine);
RegisterOperator reg4("AFFE_CHAR_CINE_F", affeCharCine);

}  // namespace
}  // namespace aster::lang
