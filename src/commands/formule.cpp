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
  const Value& vale = k.value("VALE");
  if (vale.kind == Value::Kind::Function)
    return std::make_shared<FunctionConcept>("formule", std::make_shared<StudyFunction>(vale.function, params));
  try {
    return std::make_shared<FunctionConcept>("formule", expr::Expression::compile(vale.text, params));
  } catch (const Error& e) {
    throw Error(std::string("VALE: ") + e.what());
  }
}

RegisterOperator reg("FORMULE", formule);

}  // namespace
}  // namespace aster::lang
