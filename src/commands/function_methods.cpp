// What a study may do with function concepts: F(0.3, 0.7) as in code_aster,
// and list:getValues().
#include "commands/function_concepts.hpp"
#include "core/error.hpp"
#include "expr/function.hpp"
#include "lang/operators.hpp"

namespace aster::lang {

expr::FunctionPtr functionOf(const ConceptPtr& c) {
  auto* f = dynamic_cast<FunctionConcept*>(c.get());
  if (!f) throw Error("internal error: a function was expected, got a " + (c ? c->typeName() : "null concept"));
  return f->function;
}

namespace {

Datum callFunction(Concept& self, const std::vector<Value>& args, Session&) {
  const auto& f = *static_cast<FunctionConcept&>(self).function;
  const auto& params = f.parameters();
  if (args.size() != params.size())
    throw Error("this function takes " + std::to_string(params.size()) + " argument" +
                (params.size() == 1 ? "" : "s") + " (" + expr::joinNames(params) + "), got " +
                std::to_string(args.size()));
  std::vector<double> x;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (!args[i].isNumber())
      throw Error("argument " + std::to_string(i + 1) + " (" + params[i] + ") must be a number, got " +
                  args[i].describe());
    x.push_back(args[i].real);
  }
  return Datum::ofReal(f.evaluate(x.data()));
}

Datum parameters(Concept& self, const std::vector<Value>&, Session&) {
  std::vector<Datum> out;
  for (const auto& p : static_cast<FunctionConcept&>(self).function->parameters()) out.push_back(Datum::ofText(p));
  return Datum::ofList(out);
}

Datum listValues(Concept& self, const std::vector<Value>&, Session&) {
  std::vector<Datum> out;
  for (double v : static_cast<RealListConcept&>(self).values) out.push_back(Datum::ofReal(v));
  return Datum::ofList(out);
}

RegisterMethod m1("formule", "__call", callFunction);
RegisterMethod m2("fonction_sdaster", "__call", callFunction);
RegisterMethod m3("formule", "getParameters", parameters);
RegisterMethod m4("fonction_sdaster", "getParameters", parameters);
RegisterMethod m5("listr8_sdaster", "getValues", listValues);

}  // namespace
}  // namespace aster::lang
