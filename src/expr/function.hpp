// A scalar function of named parameters: what FORMULE, DEFI_FONCTION and the
// manufactured loads all are, so that loads and post-processing take any of them.
#pragma once
#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

namespace aster::expr {

class Function {
 public:
  virtual ~Function();
  // Parameter names in the order evaluate() expects its arguments (e.g. X, Y, INST).
  virtual const std::vector<std::string>& parameters() const = 0;
  // args[i] is the value of parameters()[i]. Must not allocate: called in hot loops.
  virtual double evaluate(const double* args) const = 0;

  // Convenience for setup code and tests: checks the argument count, then evaluates.
  double operator()(std::initializer_list<double> args) const;
  // Position of a parameter in parameters(), or -1 when the function does not use it.
  int parameterIndex(const std::string& name) const;
};

using FunctionPtr = std::shared_ptr<const Function>;


// "X, Y" (or "none"), for messages that list names.
std::string joinNames(const std::vector<std::string>& names);

}  // namespace aster::expr
