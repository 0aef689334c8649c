// CREA_CHAMP for nodal fields (NOEU_*): AFFE (values or functions on parts of the
// mesh), EXTR (a field of a result at one instant, or the node coordinates),
// EVAL (a field of functions at the values of parameter fields) and ASSE
// (components of fields combined on parts of the mesh, with CUMUL and COEF_R).
// Fields at Gauss points (ELGA_*, DISC towards them) are in elga_field.cpp;
// fields at the nodes of cells (ELNO_*) are extracted from results (EXTR) only.
#include <algorithm>
#include <cstdio>
#include <map>
#include <set>

#include "commands/elga_field.hpp"
#include "commands/field_concepts.hpp"
#include "commands/function_concepts.hpp"
#include "commands/mesh_concept.hpp"
#include "commands/model_concepts.hpp"
#include "commands/selection.hpp"
#include "core/error.hpp"
#include "core/messages.hpp"
#include "core/number_format.hpp"
#include "lang/operators.hpp"

namespace aster::lang {
namespace {

struct FieldType {
  std::string support, quantity, scalar;  // NOEU, DEPL, R
};

FieldType parseType(const std::string& t) {
  const auto a = t.find('_'), b = t.rfind('_');
  return {t.substr(0, a), t.substr(a + 1, b - a - 1), t.substr(b + 1)};
}

std::shared_ptr<mesh::Mesh> meshOfKeywords(const Keywords& k) {
  if (k.has("MAILLAGE")) return k.concept<MeshConcept>("MAILLAGE")->mesh;
  if (k.has("MODELE")) return k.concept<ModelConcept>("MODELE")->model->meshPtr();
  throw Error("give MAILLAGE or MODELE");
}

void checkComponentName(const FieldType& type, const std::string& cmp) { checkComponentOfQuantity(type.quantity, cmp); }

// The support list: sorted, and empty when it is every node of the mesh.
std::vector<int> normalisedSupport(const std::set<int>& nodes, int nodeCount) {
  if (static_cast<int>(nodes.size()) == nodeCount) return {};
  return {nodes.begin(), nodes.end()};
}

void printField(const NodalFieldConcept& f) {
  std::string s = "field " + f.field.name + " (" + std::to_string(supportOf(f).size()) + " nodes):\n";
  for (int n : supportOf(f)) {
    s += "  " + f.mesh->nodeName(n);
    for (std::size_t c = 0; c < f.field.components.size(); ++c)
      s += "  " + f.field.components[c] + "=" +
           format::significant(f.field.values[static_cast<std::size_t>(n) * f.field.components.size() + c], 6);
    s += "\n";
  }
  Messages::info(s);
}

ConceptPtr affe(const Keywords& k, const FieldType& type) {
  auto mesh = meshOfKeywords(k);
  const bool functions = type.scalar == "F";
  std::vector<std::string> components;
  for (const auto& occ : k.factor("AFFE")) {
    if (functions && occ.has("VALE"))
      throw Error(occ.path + ": TYPE_CHAM " + type.support + "_" + type.quantity + "_F takes functions: VALE_F, not VALE");
    if (!functions && occ.has("VALE_F"))
      throw Error(occ.path + ": VALE_F (functions) needs a TYPE_CHAM ending in _F, such as NOEU_NEUT_F");
    for (const auto& c : occ.texts("NOM_CMP")) {
      checkComponentName(type, c);
      if (std::find(components.begin(), components.end(), c) == components.end()) components.push_back(c);
    }
  }
  const std::size_t nc = components.size();
  mesh::NodalField field{type.quantity, components, std::vector<double>(mesh->nodeCount() * nc, 0.0)};
  std::vector<expr::FunctionPtr> fns(functions ? mesh->nodeCount() * nc : 0);
  std::set<int> support;
  for (const auto& occ : k.factor("AFFE")) {
    const auto names = occ.texts("NOM_CMP");
    const std::size_t given = functions ? occ.values("VALE_F").size() : occ.values("VALE").size();
    if (given != names.size())
      throw Error(occ.path + ": NOM_CMP has " + std::to_string(names.size()) + " component(s) but " +
                  (functions ? "VALE_F" : "VALE") + " has " + std::to_string(given) + " value(s)");
    const auto nodes = selectNodes(*mesh, occ);
    std::vector<double> vals = functions ? std::vector<double>{} : occ.reals("VALE");
    std::vector<expr::FunctionPtr> f;
    if (functions)
      for (const auto& c : occ.concepts("VALE_F")) f.push_back(functionOf(c));
    for (std::size_t i = 0; i < names.size(); ++i) {
      const std::size_t c = static_cast<std::size_t>(std::find(components.begin(), components.end(), names[i]) - components.begin());
      for (int n : nodes) {
        if (functions) fns[n * nc + c] = f[i];
        else field.values[n * nc + c] = vals[i];
      }
    }
    support.insert(nodes.begin(), nodes.end());
  }
  std::shared_ptr<NodalFieldConcept> out;
  if (functions) {
    auto ff = std::make_shared<FunctionFieldConcept>(mesh, field);
    ff->functions = std::move(fns);
    out = ff;
  } else {
    out = std::make_shared<NodalFieldConcept>(mesh, field);
  }
  out->support = normalisedSupport(support, mesh->nodeCount());
  return out;
}

ConceptPtr extr(const Keywords& k, const FieldType& type, const std::string& typeCham) {
  if (k.has("MAILLAGE")) {
    if (type.quantity != "GEOM" || type.scalar != "R")
      throw Error("NOM_CHAM='GEOMETRIE' gives a NOEU_GEOM_R field, not " + typeCham);
    auto mesh = k.concept<MeshConcept>("MAILLAGE")->mesh;
    mesh::NodalField f{"GEOM", {"X", "Y", "Z"}, mesh->coordinates()};
    return std::make_shared<NodalFieldConcept>(mesh, f);
  }
  const auto result = k.concept<ResultConcept>("RESULTAT");
  const std::string name = k.text("NOM_CHAM");
  if (k.text("INTERPOL") != "NON")
    throw Error("INTERPOL='" + k.text("INTERPOL") + "' is not available yet: give a stored INST or NUME_ORDRE");
  const ResultInstant& inst = instantOf(*result, k);
  const std::string expected = quantityOfField(name);
  for (const auto& g : inst.cells)
    if (g.name == name)
      throw Error("NOM_CHAM='" + name + "' is a field on cells: TYPE_CHAM='" +
                  (g.location == CellLocation::Nodes ? "ELNO_" : "ELGA_") + expected + "_R', not " + typeCham);
  const mesh::NodalField& f = ResultConcept::nodalField(inst, name);
  if (type.scalar != "R" || (!expected.empty() && type.quantity != expected))
    throw Error("NOM_CHAM='" + name + "' gives a NOEU_" + (expected.empty() ? std::string("..") : expected) +
                "_R field, not " + typeCham);
  auto out = std::make_shared<NodalFieldConcept>(result->model->meshPtr(), f);
  const auto nodes = result->nodalSupportOf(inst, name);
  out->support = normalisedSupport(std::set<int>(nodes.begin(), nodes.end()), result->model->mesh().nodeCount());
  return out;
}

// EXTR of a field at the nodes of cells (ELNO_*_R) from a result.
ConceptPtr extrElno(const Keywords& k, const FieldType& type, const std::string& typeCham) {
  if (!k.has("RESULTAT"))
    throw Error("TYPE_CHAM='" + typeCham + "': a field at the nodes of cells is extracted from a result (RESULTAT)");
  const auto result = k.concept<ResultConcept>("RESULTAT");
  const std::string name = k.text("NOM_CHAM");
  if (k.text("INTERPOL") != "NON")
    throw Error("INTERPOL='" + k.text("INTERPOL") + "' is not available yet: give a stored INST or NUME_ORDRE");
  const ResultInstant& inst = instantOf(*result, k);
  const CellField* g = ResultConcept::cellField(inst, name);
  const std::string expected = quantityOfField(name);
  if (!g) {
    ResultConcept::nodalField(inst, name);  // throws listing the fields when absent
    throw Error("NOM_CHAM='" + name + "' is a nodal field: TYPE_CHAM='NOEU_" + expected + "_R', not " + typeCham);
  }
  if (g->location != CellLocation::Nodes)
    throw Error("NOM_CHAM='" + name + "' is a field at Gauss points: TYPE_CHAM='ELGA_" + expected + "_R', not " + typeCham);
  if (type.scalar != "R" || type.quantity != expected)
    throw Error("NOM_CHAM='" + name + "' gives an ELNO_" + expected + "_R field, not " + typeCham);
  return std::make_shared<CellFieldConcept>(result->model->meshPtr(), *g);
}

ConceptPtr eval(const Keywords& k, const FieldType& type, const std::string& typeCham, Session& session) {
  if (type.quantity != "NEUT" || type.scalar != "R")
    throw Error("OPERATION='EVAL' gives a NOEU_NEUT_R field, not " + typeCham);
  const auto fc = k.conceptPtr("CHAM_F");
  const auto ff = std::dynamic_pointer_cast<FunctionFieldConcept>(fc);
  if (std::dynamic_pointer_cast<ElgaFieldConcept>(fc))
    throw Error("CHAM_F: " + session.nameOf(*fc) + " is a field at Gauss points; its evaluation is TYPE_CHAM='ELGA_NEUT_R'");
  if (!ff)
    throw Error("CHAM_F: " + session.nameOf(*fc) + " is not a field of functions (make one with CREA_CHAMP{OPERATION='AFFE', TYPE_CHAM='NOEU_NEUT_F', ...})");
  // Parameter name -> (field, component index).
  std::map<std::string, std::pair<std::shared_ptr<NodalFieldConcept>, int>> params;
  std::string available;
  for (const auto& pc : k.concepts("CHAM_PARA")) {
    auto p = std::dynamic_pointer_cast<NodalFieldConcept>(pc);
    if (!p) throw Error("CHAM_PARA: " + session.nameOf(*pc) + " is not a nodal field (CHAM_F is a nodal field of functions)");
    if (isFunctionField(*p)) throw Error("CHAM_PARA: " + session.nameOf(*pc) + " is a field of functions; give real fields");
    if (p->mesh != ff->mesh) throw Error("CHAM_PARA: " + session.nameOf(*pc) + " lies on another mesh than CHAM_F");
    for (std::size_t c = 0; c < p->field.components.size(); ++c) {
      if (params.count(p->field.components[c])) continue;
      params[p->field.components[c]] = {p, static_cast<int>(c)};
      available += (available.empty() ? "" : ", ") + p->field.components[c];
    }
  }
  const auto& comps = ff->field.components;
  const std::size_t nc = comps.size();
  mesh::NodalField out{"NEUT", comps, std::vector<double>(ff->mesh->nodeCount() * nc, 0.0)};
  std::vector<double> args;
  std::map<const NodalFieldConcept*, std::vector<char>> inSupport;
  for (const auto& [name, fp] : params) {
    auto& flags = inSupport[fp.first.get()];
    if (!flags.empty()) continue;
    flags.assign(ff->mesh->nodeCount(), 0);
    for (int n : supportOf(*fp.first)) flags[n] = 1;
  }
  for (int n : supportOf(*ff)) {
    for (std::size_t c = 0; c < nc; ++c) {
      const auto& f = ff->functions[n * nc + c];
      if (!f) continue;
      args.assign(f->parameters().size(), 0.0);
      for (std::size_t i = 0; i < args.size(); ++i) {
        const auto& pname = f->parameters()[i];
        if (pname == expr::kAnyParameter) continue;  // a constant: any argument
        auto it = params.find(pname);
        if (it == params.end())
          throw Error("the function of component " + comps[c] + " takes the parameter " + pname +
                      " that no field of CHAM_PARA gives (components given: " + (available.empty() ? "none" : available) + ")");
        const auto& p = *it->second.first;
        if (!inSupport[&p][n])
          throw Error("the field giving " + pname + " is not defined at node " + ff->mesh->nodeName(n));
        args[i] = p.field.values[n * p.field.components.size() + it->second.second];
      }
      out.values[n * nc + c] = f->evaluate(args.data());
    }
  }
  auto result = std::make_shared<NodalFieldConcept>(ff->mesh, out);
  result->support = ff->support;
  return result;
}

ConceptPtr asse(const Keywords& k, const FieldType& type, const std::string& typeCham, Session& session) {
  if (type.scalar != "R") throw Error("OPERATION='ASSE' assembles real fields: TYPE_CHAM NOEU_*_R, not " + typeCham);
  auto mesh = meshOfKeywords(k);
  const int nn = mesh->nodeCount();
  std::vector<std::string> components;
  std::vector<std::vector<double>> values;  // per component, per node
  std::set<int> support;
  for (const auto& occ : k.factor("ASSE")) {
    const auto sc = occ.conceptPtr("CHAM_GD");
    auto src = std::dynamic_pointer_cast<NodalFieldConcept>(sc);
    if (!src)
      throw Error(occ.path + ": CHAM_GD " + session.nameOf(*sc) + " is not a nodal field; TYPE_CHAM='" + typeCham +
                  "' assembles nodal fields (fields at Gauss points assemble into ELGA_* fields)");
    if (isFunctionField(*src)) throw Error(occ.path + ": CHAM_GD " + session.nameOf(*sc) + " is a field of functions; evaluate it first (OPERATION='EVAL')");
    if (src->mesh != mesh) throw Error(occ.path + ": CHAM_GD " + session.nameOf(*sc) + " lies on another mesh");
    const AsseTerm term = asseTermOf(occ, src->field.components);
    const auto& names = term.names;
    const auto& resultNames = term.resultNames;
    const bool cumul = term.cumul;
    const double coef = term.coef;
    std::vector<char> inSource(nn, 0);
    for (int n : supportOf(*src)) inSource[n] = 1;
    std::vector<int> nodes;
    for (int n : selectNodes(*mesh, occ))
      if (inSource[n]) nodes.push_back(n);
    const std::size_t snc = src->field.components.size();
    for (std::size_t i = 0; i < names.size(); ++i) {
      checkComponentName(type, resultNames[i]);
      const auto& have = src->field.components;
      if (std::find(have.begin(), have.end(), names[i]) == have.end()) {
        // code_aster's fields carry the components given to them: one the source
        // lacks brings nothing to the assembly (ssnp150b relies on it).
        std::string list;
        for (const auto& c : have) list += (list.empty() ? "" : ", ") + c;
        Messages::alarm("CREA_CHAMP", occ.path + ": CHAM_GD " + session.nameOf(*sc) + " has no component " +
                                          names[i] + " (components: " + list + "): nothing is taken from it for " +
                                          resultNames[i]);
        continue;
      }
      const int sci = componentIndex(src->field, names[i], session.nameOf(*sc));
      auto it = std::find(components.begin(), components.end(), resultNames[i]);
      std::size_t rc = static_cast<std::size_t>(it - components.begin());
      if (it == components.end()) {
        components.push_back(resultNames[i]);
        values.emplace_back(nn, 0.0);
      }
      for (int n : nodes) {
        const double v = coef * src->field.values[n * snc + sci];
        values[rc][n] = cumul ? values[rc][n] + v : v;
      }
    }
    support.insert(nodes.begin(), nodes.end());
  }
  if (support.empty()) throw Error("ASSE: no node of the designated parts carries the source fields");
  const std::size_t nc = components.size();
  mesh::NodalField field{type.quantity, components, std::vector<double>(nn * nc, 0.0)};
  for (std::size_t c = 0; c < nc; ++c)
    for (int n = 0; n < nn; ++n) field.values[n * nc + c] = values[c][n];
  auto out = std::make_shared<NodalFieldConcept>(mesh, field);
  out->support = normalisedSupport(support, nn);
  return out;
}

ConceptPtr creaChamp(const Keywords& k, Session& session, ConceptPtr) {
  const std::string typeCham = k.text("TYPE_CHAM");
  const std::string op = k.text("OPERATION");
  const FieldType type = parseType(typeCham);
  if (type.support == "ELNO" && op != "EXTR")
    throw Error("TYPE_CHAM='" + typeCham + "': fields at the nodes of cells (ELNO) are made by OPERATION='EXTR' from a "
                "result only; NOEU_* and ELGA_* fields are made by '" + op + "'");
  if (type.support == "ELNO") return extrElno(k, type, typeCham);
  // A CART (constant per cell) is the field at the Gauss points of the model with one value per cell.
  if (type.support == "CART") {
    if (op != "AFFE") throw Error("TYPE_CHAM='" + typeCham + "' is made by OPERATION='AFFE' only, not '" + op + "'");
    if (!k.has("MODELE"))
      throw Error("TYPE_CHAM='" + typeCham + "': give MODELE (aster-lite makes a CART a field at the Gauss points "
                  "of the model's cells)");
    return creaChampElga(k, session, "ELGA_" + type.quantity + "_R", type.quantity, false);
  }
  if (type.support != "NOEU" && type.support != "ELGA")
    throw Error("TYPE_CHAM='" + typeCham + "': the support " + type.support + " is not available (NOEU, ELGA, ELNO are)");
  if (op != "AFFE" && type.scalar == "F")
    throw Error("TYPE_CHAM='" + typeCham + "' (functions) is made by OPERATION='AFFE' only, not '" + op + "'");
  if (type.support == "ELGA") return creaChampElga(k, session, typeCham, type.quantity, type.scalar == "F");
  if (op == "DISC") {
    const auto sc = k.conceptPtr("CHAM_GD");
    if (std::dynamic_pointer_cast<CellFieldConcept>(sc))
      throw Error("OPERATION='DISC' from the field at Gauss points " + session.nameOf(*sc) + " to TYPE_CHAM='" + typeCham +
                  "' is not possible: DISC moves nodal fields to the Gauss points (TYPE_CHAM='ELGA_*'), not back");
    throw Error("OPERATION='DISC': CHAM_GD " + session.nameOf(*sc) + " is already a nodal field; TYPE_CHAM='" + typeCham +
                "' is nodal too (DISC moves a nodal field to the Gauss points: TYPE_CHAM='ELGA_*')");
  }
  ConceptPtr out;
  if (op == "AFFE") out = affe(k, type);
  else if (op == "EXTR") out = extr(k, type, typeCham);
  else if (op == "EVAL") out = eval(k, type, typeCham, session);
  else out = asse(k, type, typeCham, session);
  auto& f = static_cast<NodalFieldConcept&>(*out);
  if (k.integer("INFO") >= 2 && !isFunctionField(f)) printField(f);
  return out;
}

RegisterOperator reg("CREA_CHAMP", creaChamp);

}  // namespace
}  // namespace aster::lang
