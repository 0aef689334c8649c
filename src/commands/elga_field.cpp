// CREA_CHAMP towards fields at Gauss points (TYPE_CHAM ELGA_*), as code_aster's
// U4.72.04 describes them:
//   AFFE  values (VALE) or functions (VALE_F, ELGA_NEUT_F) on cells of a MODELE;
//   DISC  a nodal field interpolated at the Gauss points with each cell's shape
//         functions (NOEU_GEOM_R -> ELGA_GEOM_R gives the points' coordinates);
//   EVAL  an ELGA_NEUT_F evaluated at every point with parameters taken from
//         ELGA fields (CHAM_PARA), giving an ELGA_NEUT_R;
//   ASSE  components of ELGA fields combined on parts of the model (NOM_CMP_RESU,
//         CUMUL, COEF_R);
//   EXTR  SIEF_ELGA of a result (ELGA_SIEF_R).
// PROL_ZERO='OUI' makes the field cover every cell of the model, components not
// given being zero; with 'NON' (default) a cell carries only what was given.
#include <algorithm>
#include <cstdio>
#include <iterator>
#include <map>

#include "commands/elga_field.hpp"
#include "commands/field_concepts.hpp"
#include "commands/function_concepts.hpp"
#include "commands/model_concepts.hpp"
#include "commands/selection.hpp"
#include "core/error.hpp"
#include "core/messages.hpp"
#include "core/number_format.hpp"
#include "lang/session.hpp"
#include "post/norms.hpp"

namespace aster::lang {
namespace {

// Every cell of the model, surface cells and edge cells alike, in mesh order.
std::vector<int> modelCellsInOrder(const model::Model& m) {
  std::vector<int> out;
  out.reserve(m.cells().size() + m.segments().size());
  std::merge(m.cells().begin(), m.cells().end(), m.segments().begin(), m.segments().end(), std::back_inserter(out));
  return out;
}

// Collects a field component by component on the cells of a model, then lays it
// out as a CellField (cell after cell, point after point, component after component).
class Builder {
 public:
  Builder(std::shared_ptr<model::Model> model, std::string quantity)
      : model_(std::move(model)), quantity_(std::move(quantity)), cells_(modelCellsInOrder(*model_)) {
    const auto& mesh = model_->mesh();
    position_.assign(mesh.cellCount(), -1);
    start_.assign(cells_.size() + 1, 0);
    for (std::size_t k = 0; k < cells_.size(); ++k) {
      position_[cells_[k]] = static_cast<int>(k);
      start_[k + 1] = start_[k] + post::modelGaussPointCount(mesh.cellType(cells_[k]), model_->axisymmetric());
    }
  }
  const model::Model& model() const { return *model_; }
  const std::vector<int>& cells() const { return cells_; }
  int position(int cell) const { return position_[cell]; }
  int points(std::size_t k) const { return start_[k + 1] - start_[k]; }
  const std::vector<std::string>& components() const { return names_; }

  // The index of a component, added when new.
  int component(const std::string& name) {
    auto it = std::find(names_.begin(), names_.end(), name);
    if (it != names_.end()) return static_cast<int>(it - names_.begin());
    names_.push_back(name);
    values_.emplace_back(static_cast<std::size_t>(start_.back()), 0.0);
    present_.emplace_back(cells_.size(), 0);
    functions_.emplace_back(cells_.size());
    return static_cast<int>(names_.size()) - 1;
  }
  double* values(int c, std::size_t k) { return values_[c].data() + start_[k]; }
  bool present(int c, std::size_t k) const { return present_[c][k] != 0; }
  void setPresent(int c, std::size_t k) { present_[c][k] = 1; }
  void setFunction(int c, std::size_t k, expr::FunctionPtr f) { functions_[c][k] = std::move(f); }

  // The field on the cells that carry a component (every cell of the model with
  // PROL_ZERO='OUI', missing components then zero). Throws `empty` when none.
  std::shared_ptr<ElgaFieldConcept> build(const std::string& name, bool prolZero, bool functions,
                                          const std::string& empty) const {
    const std::size_t nc = names_.size();
    CellField f;
    f.name = name;
    f.components = names_;
    f.offsets.push_back(0);
    std::vector<char> present;
    std::vector<expr::FunctionPtr> fns;
    for (std::size_t k = 0; k < cells_.size(); ++k) {
      bool any = prolZero && nc > 0;
      for (std::size_t c = 0; c < nc; ++c) any = any || present_[c][k];
      if (!any) continue;
      f.cells.push_back(cells_[k]);
      for (int q = 0; q < points(k); ++q)
        for (std::size_t c = 0; c < nc; ++c) f.values.push_back(values_[c][start_[k] + q]);
      f.offsets.push_back(static_cast<int>(f.values.size()));
      for (std::size_t c = 0; c < nc; ++c) {
        present.push_back(prolZero || present_[c][k] ? 1 : 0);
        if (functions) fns.push_back(functions_[c][k]);
      }
    }
    if (f.cells.empty()) throw Error(empty);
    auto out = std::make_shared<ElgaFieldConcept>(model_, quantity_, std::move(f));
    out->present = std::move(present);
    out->functionField = functions;
    out->functions = std::move(fns);
    return out;
  }

 private:
  std::shared_ptr<model::Model> model_;
  std::string quantity_;
  std::vector<int> cells_;
  std::vector<int> position_;  // mesh cell -> index in cells_, -1 outside the model
  std::vector<int> start_;     // first point of each cell in a one-component layout
  std::vector<std::string> names_;
  std::vector<std::vector<double>> values_;  // per component, per point
  std::vector<std::vector<char>> present_;   // per component, per cell
  std::vector<std::vector<expr::FunctionPtr>> functions_;
};

// Where a field at Gauss points has each cell of its mesh (-1: not there).
std::vector<int> cellPositions(const CellFieldConcept& f) {
  std::vector<int> pos(f.mesh->cellCount(), -1);
  for (std::size_t k = 0; k < f.field.cells.size(); ++k) pos[f.field.cells[k]] = static_cast<int>(k);
  return pos;
}

bool isFunctionElga(const CellFieldConcept& f) {
  const auto* e = dynamic_cast<const ElgaFieldConcept*>(&f);
  return e && e->functionField;
}

std::shared_ptr<model::Model> modelOf(const Keywords& k, const std::string& typeCham, const std::string& op) {
  if (!k.has("MODELE"))
    throw Error("MODELE is missing: OPERATION='" + op + "' towards TYPE_CHAM='" + typeCham +
                "' needs the model whose cells and Gauss points carry the field" +
                (k.has("MAILLAGE") ? " (MAILLAGE is for nodal fields)" : ""));
  return k.concept<ModelConcept>("MODELE")->model;
}

// `where` names the keyword: "AFFE[1]: NOM_CMP".
void checkComponent(const std::string& quantity, const std::string& cmp, const std::string& typeCham,
                    const std::string& where) {
  try {
    checkComponentOfQuantity(quantity, cmp);
  } catch (const Error& e) {
    throw Error(where + ": " + e.what() + ", that of TYPE_CHAM='" + typeCham + "'");
  }
}

// ------------------------------------------------------------------ AFFE

ConceptPtr affe(const Keywords& k, const std::string& typeCham, const std::string& quantity, bool functions) {
  Builder b(modelOf(k, typeCham, "AFFE"), quantity);
  const auto& mesh = b.model().mesh();
  for (const auto& occ : k.factor("AFFE")) {
    for (const char* key : {"GROUP_NO", "NOEUD"})
      if (occ.has(key))
        throw Error(occ.path + ": " + key + ": a field at Gauss points (TYPE_CHAM='" + typeCham +
                    "') is assigned on cells: give TOUT='OUI', GROUP_MA or MAILLE");
    if (functions && occ.has("VALE"))
      throw Error(occ.path + ": TYPE_CHAM " + typeCham + " takes functions: VALE_F, not VALE");
    if (!functions && occ.has("VALE_F"))
      throw Error(occ.path + ": VALE_F (functions) needs a TYPE_CHAM ending in _F, such as ELGA_NEUT_F");
    const auto names = occ.texts("NOM_CMP");
    const std::size_t given = functions ? occ.values("VALE_F").size() : occ.values("VALE").size();
    if (given != names.size())
      throw Error(occ.path + ": NOM_CMP has " + std::to_string(names.size()) + " component(s) but " +
                  (functions ? "VALE_F" : "VALE") + " has " + std::to_string(given) + " value(s)");
    std::vector<std::size_t> cells;
    for (int c : selectCells(mesh, occ))
      if (b.position(c) >= 0) cells.push_back(static_cast<std::size_t>(b.position(c)));
    if (cells.empty())
      throw Error(occ.path + ": no cell of " +
                  (occ.has("TOUT")       ? std::string("the mesh")
                   : occ.has("GROUP_MA") ? "GROUP_MA " + expr::joinNames(occ.texts("GROUP_MA"))
                                         : "MAILLE " + expr::joinNames(occ.texts("MAILLE"))) +
                  " belongs to the model (AFFE_MODELE)");
    std::vector<double> vals = functions ? std::vector<double>{} : occ.reals("VALE");
    std::vector<expr::FunctionPtr> fns;
    if (functions)
      for (const auto& c : occ.concepts("VALE_F")) fns.push_back(functionOf(c));
    for (std::size_t i = 0; i < names.size(); ++i) {
      checkComponent(quantity, names[i], typeCham, occ.path + ": NOM_CMP");
      const int c = b.component(names[i]);
      for (std::size_t kc : cells) {
        if (functions) b.setFunction(c, kc, fns[i]);
        else std::fill(b.values(c, kc), b.values(c, kc) + b.points(kc), vals[i]);
        b.setPresent(c, kc);
      }
    }
  }
  return b.build(typeCham, k.text("PROL_ZERO") == "OUI", functions, "AFFE: the field is empty");
}

// ------------------------------------------------------------------ DISC

ConceptPtr disc(const Keywords& k, const std::string& typeCham, const std::string& quantity, Session& session) {
  const auto sc = k.conceptPtr("CHAM_GD");
  const std::string name = session.nameOf(*sc);
  if (std::dynamic_pointer_cast<CellFieldConcept>(sc))
    throw Error("CHAM_GD " + name + " is already a field at Gauss points; OPERATION='DISC' moves a nodal field (NOEU_*) to them");
  auto src = std::dynamic_pointer_cast<NodalFieldConcept>(sc);
  if (!src) throw Error("CHAM_GD " + name + " is not a nodal field");
  if (isFunctionField(*src))
    throw Error("CHAM_GD " + name + " is a field of functions; evaluate it first (OPERATION='EVAL') or assign "
                "the functions at the Gauss points (OPERATION='AFFE', TYPE_CHAM='ELGA_NEUT_F')");
  const auto model = modelOf(k, typeCham, "DISC");
  if (src->mesh != model->meshPtr()) throw Error("CHAM_GD " + name + " lies on another mesh than MODELE");
  for (const auto& c : src->field.components) {
    try {
      checkComponentOfQuantity(quantity, c);
    } catch (const Error& e) {
      throw Error("CHAM_GD " + name + ": " + e.what() + ": TYPE_CHAM='" + typeCham +
                  "' keeps the components of the nodal field (rename them first with OPERATION='ASSE', NOM_CMP_RESU)");
    }
  }
  const bool prolZero = k.text("PROL_ZERO") == "OUI";
  Builder b(model, quantity);
  const auto& mesh = model->mesh();
  const std::size_t nc = src->field.components.size();
  std::vector<int> comps;
  for (const auto& c : src->field.components) comps.push_back(b.component(c));
  std::vector<char> defined(mesh.nodeCount(), src->support.empty() ? 1 : 0);
  for (int n : src->support) defined[n] = 1;
  for (std::size_t kc = 0; kc < b.cells().size(); ++kc) {
    const int cell = b.cells()[kc];
    const auto nodes = mesh.cellNodes(cell);
    bool whole = true;
    for (int n : nodes) whole = whole && defined[n];
    if (!whole && !prolZero) continue;  // the field is not defined on the whole cell
    const post::CellGaussPoints g = post::modelGaussPoints(mesh, cell, model->axisymmetric());
    for (std::size_t c = 0; c < nc; ++c) {
      double* out = b.values(comps[c], kc);
      for (int q = 0; q < g.count; ++q) {
        double v = 0;
        for (int a = 0; a < g.nodes; ++a)
          if (defined[nodes[a]]) v += g.shape[q * g.nodes + a] * src->field.values[nodes[a] * nc + c];
        out[q] = v;
      }
      b.setPresent(comps[c], kc);
    }
  }
  return b.build(typeCham, prolZero, false,
                 "CHAM_GD " + name + " is defined on no whole cell of the model (PROL_ZERO='OUI' takes the missing "
                 "nodal values as zero)");
}

// ------------------------------------------------------------------ EVAL

ConceptPtr eval(const Keywords& k, const std::string& typeCham, const std::string& quantity, Session& session) {
  if (quantity != "NEUT") throw Error("OPERATION='EVAL' gives an ELGA_NEUT_R field, not " + typeCham);
  const auto fc = k.conceptPtr("CHAM_F");
  const auto ff = std::dynamic_pointer_cast<ElgaFieldConcept>(fc);
  if (!ff || !ff->functionField) {
    if (std::dynamic_pointer_cast<NodalFieldConcept>(fc))
      throw Error("CHAM_F: " + session.nameOf(*fc) + " is a nodal field; its evaluation is TYPE_CHAM='NOEU_NEUT_R'");
    throw Error("CHAM_F: " + session.nameOf(*fc) +
                " is not a field of functions at Gauss points (make one with CREA_CHAMP{OPERATION='AFFE', "
                "TYPE_CHAM='ELGA_NEUT_F', MODELE=...})");
  }
  struct Param {
    const CellFieldConcept* field;
    int component;
  };
  std::map<std::string, Param> params;
  std::map<const CellFieldConcept*, std::vector<int>> positions;
  std::string available;
  for (const auto& pc : k.concepts("CHAM_PARA")) {
    const std::string pname = session.nameOf(*pc);
    auto p = std::dynamic_pointer_cast<CellFieldConcept>(pc);
    if (!p) {
      if (std::dynamic_pointer_cast<NodalFieldConcept>(pc))
        throw Error("CHAM_PARA: " + pname + " is a nodal field; CHAM_F is at Gauss points: move " + pname +
                    " to them first (CREA_CHAMP{OPERATION='DISC', TYPE_CHAM='ELGA_GEOM_R', MODELE=..., CHAM_GD=" +
                    pname + "} for the geometry)");
      throw Error("CHAM_PARA: " + pname + " is not a field");
    }
    if (isFunctionElga(*p)) throw Error("CHAM_PARA: " + pname + " is a field of functions; give real fields");
    if (p->mesh != ff->mesh) throw Error("CHAM_PARA: " + pname + " lies on another mesh than CHAM_F");
    positions[p.get()] = cellPositions(*p);
    for (std::size_t c = 0; c < p->field.components.size(); ++c) {
      const auto& cname = p->field.components[c];
      if (params.count(cname)) continue;
      params[cname] = {p.get(), static_cast<int>(c)};
      available += (available.empty() ? "" : ", ") + cname;
    }
  }
  Builder b(ff->model, "NEUT");
  const auto& mesh = ff->model->mesh();
  const auto& comps = ff->field.components;
  const std::size_t nc = comps.size();
  std::vector<int> out;
  for (const auto& c : comps) out.push_back(b.component(c));
  std::vector<double> args;
  for (std::size_t kf = 0; kf < ff->field.cells.size(); ++kf) {
    const int cell = ff->field.cells[kf];
    const int kb = b.position(cell);
    const int points = pointsOf(ff->field, kf);
    for (std::size_t c = 0; c < nc; ++c) {
      if (!ff->present[kf * nc + c]) continue;
      b.setPresent(out[c], static_cast<std::size_t>(kb));
      const auto& f = ff->functions[kf * nc + c];
      if (!f) continue;  // PROL_ZERO: zero
      double* dest = b.values(out[c], static_cast<std::size_t>(kb));
      args.assign(f->parameters().size(), 0.0);
      for (int q = 0; q < points; ++q) {
        for (std::size_t i = 0; i < args.size(); ++i) {
          const auto& pname = f->parameters()[i];
          if (pname == expr::kAnyParameter) continue;  // a constant: any argument
          auto it = params.find(pname);
          if (it == params.end())
            throw Error("the function of component " + comps[c] + " takes the parameter " + pname +
                        " that no field of CHAM_PARA gives (components given: " +
                        (available.empty() ? "none" : available) + ")");
          const CellFieldConcept& p = *it->second.field;
          const int kp = positions[&p][cell];
          if (kp < 0 || !componentPresent(p, static_cast<std::size_t>(kp), it->second.component))
            throw Error("the field " + session.nameOf(p) + " giving " + pname + " is not defined on cell " +
                        mesh.cellName(cell));
          if (pointsOf(p.field, kp) != points)
            throw Error("the field " + session.nameOf(p) + " has " + std::to_string(pointsOf(p.field, kp)) +
                        " points on cell " + mesh.cellName(cell) + ", CHAM_F " + std::to_string(points));
          const std::size_t pnc = p.field.components.size();
          args[i] = p.field.values[p.field.offsets[kp] + q * pnc + it->second.component];
        }
        dest[q] = f->evaluate(args.data());
      }
    }
  }
  return b.build(typeCham, false, false, "EVAL: CHAM_F carries no component");
}

// ------------------------------------------------------------------ ASSE

ConceptPtr asse(const Keywords& k, const std::string& typeCham, const std::string& quantity, Session& session) {
  const auto model = modelOf(k, typeCham, "ASSE");
  Builder b(model, quantity);
  const auto& mesh = model->mesh();
  bool any = false;
  for (const auto& occ : k.factor("ASSE")) {
    for (const char* key : {"GROUP_NO", "NOEUD"})
      if (occ.has(key))
        throw Error(occ.path + ": " + key + ": a field at Gauss points (TYPE_CHAM='" + typeCham +
                    "') is assembled on cells: give TOUT='OUI', GROUP_MA or MAILLE");
    const auto sc = occ.conceptPtr("CHAM_GD");
    const std::string name = session.nameOf(*sc);
    auto src = std::dynamic_pointer_cast<CellFieldConcept>(sc);
    if (!src) {
      if (std::dynamic_pointer_cast<NodalFieldConcept>(sc))
        throw Error(occ.path + ": CHAM_GD " + name + " is a nodal field; a field at Gauss points assembles fields at "
                    "Gauss points: move it to them first (OPERATION='DISC')");
      throw Error(occ.path + ": CHAM_GD " + name + " is not a field");
    }
    if (isFunctionElga(*src))
      throw Error(occ.path + ": CHAM_GD " + name + " is a field of functions; evaluate it first (OPERATION='EVAL')");
    if (src->mesh != model->meshPtr()) throw Error(occ.path + ": CHAM_GD " + name + " lies on another mesh than MODELE");
    const AsseTerm term = asseTermOf(occ, src->field.components);
    const auto& names = term.names;
    const auto& resultNames = term.resultNames;
    const bool cumul = term.cumul;
    const double coef = term.coef;
    const auto positions = cellPositions(*src);
    const std::size_t snc = src->field.components.size();
    std::vector<int> sourceComps;
    for (const auto& n : names) {
      try {
        sourceComps.push_back(componentIndex(src->field.components, n, name));
      } catch (const Error& e) {
        throw Error(occ.path + ": NOM_CMP: " + e.what());
      }
    }
    for (std::size_t i = 0; i < names.size(); ++i) {
      checkComponent(quantity, resultNames[i], typeCham,
                     occ.path + (occ.has("NOM_CMP_RESU") ? ": NOM_CMP_RESU" : ": NOM_CMP"));
      const int rc = b.component(resultNames[i]);
      for (int cell : selectCells(mesh, occ)) {
        const int kb = b.position(cell), ks = positions[cell];
        if (kb < 0 || ks < 0 || !componentPresent(*src, static_cast<std::size_t>(ks), sourceComps[i])) continue;
        const int points = pointsOf(src->field, ks);
        if (points != b.points(kb))
          throw Error(occ.path + ": CHAM_GD " + name + " has " + std::to_string(points) + " points on cell " +
                      mesh.cellName(cell) + " where the model has " + std::to_string(b.points(kb)));
        double* dest = b.values(rc, kb);
        const double* from = src->field.values.data() + src->field.offsets[ks] + sourceComps[i];
        for (int q = 0; q < points; ++q) {
          const double v = coef * from[q * snc];
          dest[q] = cumul ? dest[q] + v : v;
        }
        b.setPresent(rc, kb);
        any = true;
      }
    }
  }
  if (!any) throw Error("ASSE: no cell of the designated parts carries the source fields");
  return b.build(typeCham, k.text("PROL_ZERO") == "OUI", false, "ASSE: the field is empty");
}

// ------------------------------------------------------------------ EXTR

ConceptPtr extr(const Keywords& k, const std::string& typeCham, const std::string& quantity) {
  if (k.has("MAILLAGE"))
    throw Error("NOM_CHAM='GEOMETRIE' of a mesh is the nodal field NOEU_GEOM_R; the coordinates of the Gauss points "
                "are CREA_CHAMP{OPERATION='DISC', TYPE_CHAM='ELGA_GEOM_R', MODELE=..., CHAM_GD=<that NOEU_GEOM_R field>}");
  const auto result = k.concept<ResultConcept>("RESULTAT");
  const std::string name = k.text("NOM_CHAM");
  if (k.text("INTERPOL") != "NON")
    throw Error("INTERPOL='" + k.text("INTERPOL") + "' is not available yet: give a stored INST or NUME_ORDRE");
  const ResultInstant& inst = instantOf(*result, k);
  const CellField* g = ResultConcept::cellField(inst, name);
  if (!g) {
    ResultConcept::nodalField(inst, name);  // throws listing the fields when absent
    throw Error("NOM_CHAM='" + name + "' is a nodal field: TYPE_CHAM='NOEU_..._R' (then OPERATION='DISC' to move it "
                "to the Gauss points), not " + typeCham);
  }
  const std::string expected = quantityOfField(name);  // SIGM_ELGA -> SIEF
  if (g->location != CellLocation::GaussPoints)
    throw Error("NOM_CHAM='" + name + "' is a field at the nodes of cells: TYPE_CHAM='ELNO_" + expected + "_R', not " +
                typeCham);
  if (quantity != expected) throw Error("NOM_CHAM='" + name + "' gives an ELGA_" + expected + "_R field, not " + typeCham);
  const auto& mesh = result->model->mesh();
  for (std::size_t kc = 0; kc < g->cells.size(); ++kc)
    if (pointsOf(*g, kc) != post::modelGaussPointCount(mesh.cellType(g->cells[kc]), result->model->axisymmetric()))
      throw Error("NOM_CHAM='" + name + "': cell " + mesh.cellName(g->cells[kc]) + " holds " +
                  std::to_string(pointsOf(*g, kc)) + " points, not those of the model's integration scheme");
  auto out = std::make_shared<ElgaFieldConcept>(result->model, quantity, *g);
  out->present.assign(g->cells.size() * g->components.size(), 1);
  return out;
}

void printField(const ElgaFieldConcept& f, const std::string& name) {
  const std::size_t nc = f.field.components.size();
  std::string s = "field " + name + " at Gauss points (" + std::to_string(f.field.cells.size()) + " cells):\n";
  for (std::size_t k = 0; k < f.field.cells.size(); ++k)
    for (int q = 0; q < pointsOf(f.field, k); ++q) {
      s += "  " + f.mesh->cellName(f.field.cells[k]) + " point " + std::to_string(q + 1);
      for (std::size_t c = 0; c < nc; ++c) {
        if (!f.present[k * nc + c]) continue;
        s += "  " + f.field.components[c] + "=" + format::significant(f.field.values[f.field.offsets[k] + q * nc + c], 6);
      }
      s += "\n";
    }
  Messages::info(s);
}

}  // namespace

ConceptPtr creaChampElga(const Keywords& k, Session& session, const std::string& typeCham,
                         const std::string& quantity, bool functions) {
  const std::string op = k.text("OPERATION");
  std::shared_ptr<ElgaFieldConcept> out;
  if (op == "AFFE") out = std::static_pointer_cast<ElgaFieldConcept>(affe(k, typeCham, quantity, functions));
  else if (op == "DISC") out = std::static_pointer_cast<ElgaFieldConcept>(disc(k, typeCham, quantity, session));
  else if (op == "EVAL") out = std::static_pointer_cast<ElgaFieldConcept>(eval(k, typeCham, quantity, session));
  else if (op == "ASSE") out = std::static_pointer_cast<ElgaFieldConcept>(asse(k, typeCham, quantity, session));
  else out = std::static_pointer_cast<ElgaFieldConcept>(extr(k, typeCham, quantity));
  if (k.integer("INFO") >= 2 && !out->functionField) printField(*out, session.assignedName.empty() ? typeCham : session.assignedName);
  return out;
}

}  // namespace aster::lang
