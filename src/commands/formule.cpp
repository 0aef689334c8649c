// FORMULE: a function given by an expression string (compiled once, evaluated
// natively) or by a Lua function of the study.
#include "commands/function_concepts.hpp"
#include "core/error.hpp"
#include "expr/expression.hpp"
#include "lang/operators.hpp"

namespace aster::lang {
namespace {

// A study's Lua function seen as an expr::Function.
class StudyFunction : public expr::Function {
 public:
  StudyFunction(CallablePtr f, std::vector<std::string> params) : f_(std::move(f)), params_(std::move(params)) {}
  const std::vector<std::string>& parameters() const override { return params_; }
  double evaluate(const double* args) const override { return f_->call(args, static_cast<int>(params_.size())); }

 private:
  CallablePtr f_;
  std::vector<std::string> params_;
};

ConceptPtr formule(const Keywords& k, Session&, ConceptPtr) {
  const std::vector<std::string> params = k.texts("NOM_PARA");
  for (std::size_t i = 0; i < params.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (params[i] == params[j]) throw Error("NOM_PARA: parameter " + params[i] + " is given twice");
  // The other keywords (CONTEXTE, gathered by the validator): names the expression text uses.
  expr::ExpressionContext context;
  for (const auto& values : k.factor("CONTEXTE")) {
    for (const auto& name : values.keys()) {
      for (const auto& p : params)
        if (p == name) throw Error("keyword " + name + " names both a parameter (NOM_PARA) and a value passed to the expression");
      const Value& v = values.value(name);
      if (v.kind == Value::Kind::Concept) context.functions.emplace_back(name, functionOf(v.concept));
      else context.constants.emplace_back(name, v.real);
    }
  }
  const Value& vale = k.value("VALE");
  if (vale.kind == Value::Kind::Function) {
    if (!k.factor("CONTEXTE").empty())
      throw Error("VALE is a Lua function: it sees the study's variables, other keywords are for an expression text");
    return std::make_shared<FunctionConcept>("formule", std::make_shared<StudyFunction>(vale.function, params));
  }
  try {
    return std::make_shared<FunctionConcept>("formule", expr::Expression::compile(vale.text, params, context));
  } catch (const Error& e) {
    throw Error(std::string("VALE: ") + e.what());
  }
}

RegisterOperator reg("FORMULE", formule);

}  // namespace
}  // namespace aster::lang
