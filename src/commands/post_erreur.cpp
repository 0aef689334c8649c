// POST_ERREUR: L2 error of a computed nodal field against exact functions of
// (X, Y): DEPL_* over surface cells (components DX, DY), LAGR_* over edges
// (LAGS_C), both interpolated with the cells' shape functions (a LAGS_C linear
// along a SEG3 shows the mean of its ends at the middle node). One row per group, then
// a row TOTAL: ERREUR (absolute, or relative to the exact norm) and REFERENCE
// (the exact norm); the row TOTAL also has code_aster's ERREUR RELATIVE, the norm
// of the difference over the exact norm, whatever the option (absent, as
// code_aster's, when the exact norm is not above 1e-16).
#include <cmath>

#include "commands/field_concepts.hpp"
#include "commands/function_concepts.hpp"
#include "commands/model_concepts.hpp"
#include "commands/table_concept.hpp"
#include "core/error.hpp"
#include "lang/operators.hpp"
#include "post/norms.hpp"

namespace aster::lang {
namespace {

// An exact solution as a function of (x, y): its parameters must be among X, Y (Z = 0).
post::ExactFunction exactOf(const expr::FunctionPtr& f, const std::string& what) {
  std::vector<int> which;  // 0: X, 1: Y, 2: Z
  for (const auto& p : f->parameters()) {
    if (p == "X") which.push_back(0);
    else if (p == "Y") which.push_back(1);
    else if (p == "Z" || p == expr::kAnyParameter) which.push_back(2);
    else throw Error(what + ": the exact solution takes the parameter " + p + "; only X, Y (and Z = 0) are given");
  }
  return [f, which](double x, double y) {
    double args[3];
    for (std::size_t i = 0; i < which.size(); ++i) args[i] = which[i] == 0 ? x : which[i] == 1 ? y : 0.0;
    return f->evaluate(args);
  };
}

ConceptPtr postErreur(const Keywords& k, Session& session, ConceptPtr) {
  const std::string option = k.text("OPTION");
  const bool lagr = option.rfind("LAGR", 0) == 0;
  const bool relative = option.size() > 4 && option.substr(option.size() - 4) == "RELA";
  const auto model = k.concept<ModelConcept>("MODELE")->model;
  if (model->axisymmetric())
    throw Error("MODELE is axisymmetric (MODELISATION='AXIS'); aster-lite integrates the errors over "
                "the plane section only, not per radian: POST_ERREUR takes a D_PLAN or C_PLAN model (of the same "
                "mesh, for the norm of the section)");
  const auto c = k.conceptPtr("CHAM_GD");
  const auto cham = std::dynamic_pointer_cast<NodalFieldConcept>(c);
  if (!cham || isFunctionField(*cham)) throw Error("CHAM_GD " + session.nameOf(*c) + " is not a field of real nodal values");
  if (cham->mesh != model->meshPtr()) throw Error("CHAM_GD lies on another mesh than MODELE");
  const mesh::Mesh& mesh = model->mesh();
  const auto groups = k.texts("GROUP_MA");
  const std::vector<std::string> cmps = lagr ? std::vector<std::string>{"LAGS_C"} : std::vector<std::string>{"DX", "DY"};
  // Exact functions per component: one for all groups or one per group.
  std::vector<std::vector<ConceptPtr>> exact;
  for (const auto& cmp : cmps) {
    auto fs = k.concepts(cmp);
    if (fs.size() != 1 && fs.size() != groups.size())
      throw Error(cmp + " has " + std::to_string(fs.size()) + " functions for " + std::to_string(groups.size()) +
                  " groups: give one for all groups or one per group");
    exact.push_back(fs);
  }
  post::NodalValues nv;
  nv.values = &cham->field.values;
  nv.componentCount = static_cast<int>(cham->field.components.size());
  for (const auto& cmp : cmps) nv.components.push_back(componentIndex(cham->field, cmp, session.nameOf(*c)));
  std::vector<char> inSupport(mesh.nodeCount(), cham->support.empty() ? 1 : 0);
  for (int n : cham->support) inSupport[n] = 1;

  post::Table table;
  double err2 = 0, ref2 = 0;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const auto& cells = mesh.cellGroup(groups[g]);
    for (int cell : cells) {
      const int dim = mesh::topologicalDimension(mesh.cellType(cell));
      if (lagr && dim != 1)
        throw Error(option + ": GROUP_MA " + groups[g] + " holds the " + mesh::cellTypeName(mesh.cellType(cell)) +
                    " cell " + mesh.cellName(cell) + "; the contact pressure is integrated over edges (SEG2, SEG3)");
      if (!lagr && dim != 2)
        throw Error(option + ": GROUP_MA " + groups[g] + " holds the " + mesh::cellTypeName(mesh.cellType(cell)) +
                    " cell " + mesh.cellName(cell) + "; displacements are integrated over surface cells");
      const auto nodes = mesh.cellNodes(cell);
      for (int n : nodes)
        if (!inSupport[n])
          throw Error("CHAM_GD is not defined at node " + mesh.nodeName(n) + " of cell " + mesh.cellName(cell));
    }
    std::vector<post::ExactFunction> fns;
    for (std::size_t i = 0; i < cmps.size(); ++i)
      fns.push_back(exactOf(functionOf(exact[i][exact[i].size() == 1 ? 0 : g]), cmps[i]));
    const auto r = post::l2Norms(mesh, cells, nv, fns);
    err2 += r.error * r.error;
    ref2 += r.exact * r.exact;
    if (relative && r.exact == 0)
      throw Error(option + ": the exact solution is zero on " + groups[g] + "; a relative error is undefined (use " +
                  option.substr(0, 4) + "_ABSO)");
    table.addRow({{"GROUP_MA", post::TableValue::ofText(groups[g])},
                  {"ERREUR", post::TableValue::ofReal(relative ? r.error / r.exact : r.error)},
                  {"REFERENCE", post::TableValue::ofReal(r.exact)}});
  }
  const double err = std::sqrt(err2), ref = std::sqrt(ref2);
  std::vector<std::pair<std::string, post::TableValue>> total = {
      {"GROUP_MA", post::TableValue::ofText("TOTAL")},
      {"ERREUR", post::TableValue::ofReal(relative ? err / ref : err)},
      {"REFERENCE", post::TableValue::ofReal(ref)}};
  if (ref > 1e-16) total.push_back({"ERREUR RELATIVE", post::TableValue::ofReal(err / ref)});
  table.addRow(total);
  return std::make_shared<TableConcept>(table);
}

RegisterOperator reg("POST_ERREUR", postErreur);

}  // namespace
}  // namespace aster::lang
