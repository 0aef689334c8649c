// FORMULE: a Python-syntax arithmetic expression of named parameters, compiled
// once into flat postfix code and evaluated natively.
//   operators  + - * / ** (Python precedence: -2**2 == -4, 2**3**2 == 512, 2**-1 == 0.5)
//   numbers    1  1.  .5  4.0E-05  1e3
//   functions  sin cos tan asin acos atan atan2 sinh cosh tanh exp log log10 sqrt
//              abs min max (min, max: two or more arguments); pow(a, b) == a ** b;
//              constant pi
//   context    names given with the expression (FORMULE's other keywords): real
//              constants, substituted at compile time, and functions called by name
//              with as many arguments as they have parameters
// evaluateT<T> runs the same code with double or an AD number (dual.hpp), so a
// load can take exact derivatives of a formula. Evaluation allocates nothing
// (up to kInlineDepth stack entries, far more than any real formula needs).
#pragma once
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "expr/function.hpp"

namespace aster::expr {

enum class OpCode : std::uint8_t {
  Constant,   // push constants_[arg]
  Parameter,  // push args[arg]
  Negate,
  Add,
  Subtract,
  Multiply,
  Divide,
  Power,          // a ** b, both computed
  PowerConstant,  // a ** constants_[arg] (non-integer constant exponent)
  PowerInteger,   // a ** arg, small integer exponent known at compile time
  Square,
  Cube,
  Sin, Cos, Tan, Asin, Acos, Atan, Sinh, Cosh, Tanh, Exp, Log, Log10, Sqrt, Abs,
  Atan2,
  Min,  // arg operands
  Max,  // arg operands
  Call,  // callees_[arg] of its parameter count operands
};

struct Instruction {
  OpCode op;
  std::int32_t arg;
};

class Expression;

// Names an expression may use besides its parameters.
struct ExpressionContext {
  std::vector<std::pair<std::string, double>> constants;
  std::vector<std::pair<std::string, FunctionPtr>> functions;
};

class Expression : public Function {
 public:
  // Parses and compiles; throws aster::Error naming the 1-based column of the problem.
  static std::shared_ptr<Expression> compile(const std::string& text,
                                             const std::vector<std::string>& params,
                                             const ExpressionContext& context = {});

  const std::vector<std::string>& parameters() const override { return params_; }
  double evaluate(const double* args) const override { return evaluateT<double>(args); }
  template <class T>
  T evaluateT(const T* args) const;

  // As evaluate, but throws aster::Error when an operation leaves the real numbers
  // or overflows (log or sqrt of a negative, division by zero, ...), saying which
  // operation, where in the text, and at which parameter values.
  double evaluateChecked(const double* args) const;

  const std::string& text() const { return text_; }
  // The compiled code, for tests and diagnostics.
  const std::vector<Instruction>& code() const { return code_; }
  int stackDepth() const { return depth_; }

  static constexpr int kInlineDepth = 64;

 private:
  Expression() = default;
  template <class T>
  T run(const T* args, T* stack) const;

  // A function of the context called by the expression.
  struct Callee {
    std::string name;
    FunctionPtr function;
    const Expression* expression;  // function as a compiled expression, or null
    int arity;
  };
  template <class T>
  T call(const Callee& c, const T* args) const;
  // A function that is not an expression has no derivatives to propagate.
  [[noreturn]] void notDifferentiable(const Callee& c) const;

  std::string text_;
  std::vector<std::string> params_;
  std::vector<Instruction> code_;
  std::vector<double> constants_;
  std::vector<Callee> callees_;
  std::vector<int> columns_;  // 1-based column of each instruction in text_, for messages
  int depth_ = 0;

  friend class ExpressionCompiler;
};

using ExpressionPtr = std::shared_ptr<const Expression>;

template <class T>
T Expression::evaluateT(const T* args) const {
  if (depth_ <= kInlineDepth) {
    T stack[kInlineDepth];
    return run(args, stack);
  }
  std::vector<T> stack(static_cast<std::size_t>(depth_));  // pathological nesting only
  return run(args, stack.data());
}

template <class T>
T Expression::run(const T* args, T* s) const {
  // std:: versions for double, the hidden friends of dual.hpp for AD numbers.
  using std::abs, std::acos, std::asin, std::atan, std::atan2, std::cos, std::cosh, std::exp,
      std::log, std::log10, std::pow, std::sin, std::sinh, std::sqrt, std::tan, std::tanh;
  int top = -1;  // index of the top of the stack
  for (const Instruction& in : code_) {
    switch (in.op) {
      case OpCode::Constant: s[++top] = T(constants_[in.arg]); break;
      case OpCode::Parameter: s[++top] = args[in.arg]; break;
      case OpCode::Negate: s[top] = -s[top]; break;
      case OpCode::Add: --top; s[top] = s[top] + s[top + 1]; break;
      case OpCode::Subtract: --top; s[top] = s[top] - s[top + 1]; break;
      case OpCode::Multiply: --top; s[top] = s[top] * s[top + 1]; break;
      case OpCode::Divide: --top; s[top] = s[top] / s[top + 1]; break;
      case OpCode::Power: --top; s[top] = pow(s[top], s[top + 1]); break;
      case OpCode::PowerConstant: s[top] = pow(s[top], constants_[in.arg]); break;
      case OpCode::PowerInteger: s[top] = pow(s[top], static_cast<double>(in.arg)); break;
      case OpCode::Square: s[top] = s[top] * s[top]; break;
      case OpCode::Cube: s[top] = s[top] * s[top] * s[top]; break;
      case OpCode::Sin: s[top] = sin(s[top]); break;
      case OpCode::Cos: s[top] = cos(s[top]); break;
      case OpCode::Tan: s[top] = tan(s[top]); break;
      case OpCode::Asin: s[top] = asin(s[top]); break;
      case OpCode::Acos: s[top] = acos(s[top]); break;
      case OpCode::Atan: s[top] = atan(s[top]); break;
      case OpCode::Sinh: s[top] = sinh(s[top]); break;
      case OpCode::Cosh: s[top] = cosh(s[top]); break;
      case OpCode::Tanh: s[top] = tanh(s[top]); break;
      case OpCode::Exp: s[top] = exp(s[top]); break;
      case OpCode::Log: s[top] = log(s[top]); break;
      case OpCode::Log10: s[top] = log10(s[top]); break;
      case OpCode::Sqrt: s[top] = sqrt(s[top]); break;
      case OpCode::Abs: s[top] = abs(s[top]); break;
      case OpCode::Atan2: --top; s[top] = atan2(s[top], s[top + 1]); break;
      case OpCode::Min: {
        top -= in.arg - 1;
        for (int k = 1; k < in.arg; ++k)
          if (s[top + k] < s[top]) s[top] = s[top + k];
        break;
      }
      case OpCode::Max: {
        top -= in.arg - 1;
        for (int k = 1; k < in.arg; ++k)
          if (s[top + k] > s[top]) s[top] = s[top + k];
        break;
      }
      case OpCode::Call: {
        const Callee& c = callees_[in.arg];
        top -= c.arity - 1;
        s[top] = call(c, s + top);
        break;
      }
    }
  }
  return s[0];
}

template <class T>
T Expression::call(const Callee& c, const T* args) const {
  if constexpr (std::is_same_v<T, double>) {
    return c.function->evaluate(args);
  } else {
    if (!c.expression) notDifferentiable(c);
    return c.expression->evaluateT<T>(args);
  }
}

}  // namespace aster::expr
