// What a study may ask results and fields (code_aster's method names):
// resu:getField('DEPL', inst), resu:getAccessParameters(), field:getValues(),
// field:getComponents(). A nodal field (cham_no_sdaster) gives its values node
// after node; a field at Gauss points (cham_elem, SIEF_ELGA) cell after cell of
// the model, Gauss point after Gauss point, components in the order of getComponents().
#include "commands/result_concepts.hpp"
#include "core/error.hpp"
#include "lang/operators.hpp"

namespace aster::lang {
namespace {

Datum getField(Concept& self, const std::vector<Value>& args, Session&) {
  auto& r = static_cast<ResultConcept&>(self);
  if (args.empty() || args[0].kind != Value::Kind::Text)
    throw Error("getField takes a field name and an instant: resu:getField('DEPL', 1.0)");
  const ResultInstant& inst = args.size() > 1 && args[1].isNumber() ? r.at(args[1].real) : r.last();
  if (const CellField* g = ResultConcept::cellField(inst, args[0].text))
    return Datum::ofConcept(std::make_shared<CellFieldConcept>(r.model->meshPtr(), *g));
  auto c = std::make_shared<NodalFieldConcept>(r.model->meshPtr(), ResultConcept::nodalField(inst, args[0].text));
  // A field computed on part of the model (CALC_CHAMP's GROUP_MA) keeps the nodes where it is defined.
  if (auto s = inst.nodalSupport.find(args[0].text); s != inst.nodalSupport.end()) c->support = s->second;
  return Datum::ofConcept(c);
}

Datum accessParameters(Concept& self, const std::vector<Value>&, Session&) {
  auto& r = static_cast<ResultConcept&>(self);
  std::vector<Datum> inst, order, iterations;
  for (const auto& i : r.instants) {
    inst.push_back(Datum::ofReal(i.time));
    order.push_back(Datum::ofInteger(i.index));
    iterations.push_back(Datum::ofInteger(i.newtonIterations));
  }
  // ITER_GLOB: Newton iterations of each instant (0 for the initial state).
  return Datum::ofMap({{"INST", Datum::ofList(inst)},
                       {"NUME_ORDRE", Datum::ofList(order)},
                       {"ITER_GLOB", Datum::ofList(iterations)}});
}

// getValues and getComponents of a field concept, nodal or at Gauss points alike.
template <class FieldConcept>
Datum valuesOf(Concept& self, const std::vector<Value>&, Session&) {
  std::vector<Datum> out;
  for (double v : static_cast<FieldConcept&>(self).field.values) out.push_back(Datum::ofReal(v));
  return Datum::ofList(out);
}

template <class FieldConcept>
Datum componentsOf(Concept& self, const std::vector<Value>&, Session&) {
  std::vector<Datum> out;
  for (const auto& c : static_cast<FieldConcept&>(self).field.components) out.push_back(Datum::ofText(c));
  return Datum::ofList(out);
}

RegisterMethod m1("evol_noli", "getField", getField);
RegisterMethod m2("evol_noli", "getAccessParameters", accessParameters);
RegisterMethod e1("evol_elas", "getField", getField);
RegisterMethod e2("evol_elas", "getAccessParameters", accessParameters);
RegisterMethod m3("cham_no_sdaster", "getValues", valuesOf<NodalFieldConcept>);
RegisterMethod m4("cham_no_sdaster", "getComponents", componentsOf<NodalFieldConcept>);
RegisterMethod m5("cham_elem", "getValues", valuesOf<CellFieldConcept>);
RegisterMethod m6("cham_elem", "getComponents", componentsOf<CellFieldConcept>);

}  // namespace
}  // namespace aster::lang
