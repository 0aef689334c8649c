// FORMULE compiler: lexer, recursive-descent parser with Python's precedence,
// constant folding, emission of postfix code; and the checked evaluation.
#include "expr/expression.hpp"
#include "core/number_format.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <unordered_map>

#include "core/error.hpp"

namespace aster::expr {

namespace {

constexpr double kPi = 3.14159265358979323846264338327950288;

struct FunctionInfo {
  const char* name;
  OpCode op;
  int minArgs;
  int maxArgs;  // -1: variadic
};

constexpr FunctionInfo kFunctions[] = {
    {"sin", OpCode::Sin, 1, 1},     {"cos", OpCode::Cos, 1, 1},
    {"tan", OpCode::Tan, 1, 1},     {"asin", OpCode::Asin, 1, 1},
    {"acos", OpCode::Acos, 1, 1},   {"atan", OpCode::Atan, 1, 1},
    {"atan2", OpCode::Atan2, 2, 2}, {"sinh", OpCode::Sinh, 1, 1},
    {"cosh", OpCode::Cosh, 1, 1},   {"tanh", OpCode::Tanh, 1, 1},
    {"exp", OpCode::Exp, 1, 1},     {"log", OpCode::Log, 1, 1},
    {"log10", OpCode::Log10, 1, 1}, {"sqrt", OpCode::Sqrt, 1, 1},
    {"abs", OpCode::Abs, 1, 1},     {"min", OpCode::Min, 2, -1},
    {"max", OpCode::Max, 2, -1},
    {"pow", OpCode::Power, 2, 2},  // Python's pow(a, b) and math.pow: a ** b
};

const FunctionInfo* findFunction(const std::string& name) {
  for (const auto& f : kFunctions)
    if (name == f.name) return &f;
  return nullptr;
}

std::string functionNames() {
  std::string out;
  for (const auto& f : kFunctions) {
    if (!out.empty()) out += ", ";
    out += f.name;
  }
  return out;
}

const char* opName(OpCode op) {
  switch (op) {
    case OpCode::Negate: return "-";
    case OpCode::Add: return "+";
    case OpCode::Subtract: return "-";
    case OpCode::Multiply: return "*";
    case OpCode::Divide: return "/";
    case OpCode::Power:
    case OpCode::PowerConstant:
    case OpCode::PowerInteger:
    case OpCode::Square:
    case OpCode::Cube: return "**";
    default: break;
  }
  for (const auto& f : kFunctions)
    if (f.op == op) return f.name;
  return "?";
}

// Number of operands an instruction pops (Constant and Parameter pop none).
int arity(const Instruction& in) {
  switch (in.op) {
    case OpCode::Constant:
    case OpCode::Parameter: return 0;
    case OpCode::Add:
    case OpCode::Subtract:
    case OpCode::Multiply:
    case OpCode::Divide:
    case OpCode::Power:
    case OpCode::Atan2: return 2;
    case OpCode::Min:
    case OpCode::Max: return in.arg;
    default: return 1;
  }
}

// One instruction on doubles, exactly as Expression::run<double> does it.
double apply(const Instruction& in, const double* x, const std::vector<double>& constants) {
  switch (in.op) {
    case OpCode::Negate: return -x[0];
    case OpCode::Add: return x[0] + x[1];
    case OpCode::Subtract: return x[0] - x[1];
    case OpCode::Multiply: return x[0] * x[1];
    case OpCode::Divide: return x[0] / x[1];
    case OpCode::Power: return std::pow(x[0], x[1]);
    case OpCode::PowerConstant: return std::pow(x[0], constants[in.arg]);
    case OpCode::PowerInteger: return std::pow(x[0], static_cast<double>(in.arg));
    case OpCode::Square: return x[0] * x[0];
    case OpCode::Cube: return x[0] * x[0] * x[0];
    case OpCode::Sin: return std::sin(x[0]);
    case OpCode::Cos: return std::cos(x[0]);
    case OpCode::Tan: return std::tan(x[0]);
    case OpCode::Asin: return std::asin(x[0]);
    case OpCode::Acos: return std::acos(x[0]);
    case OpCode::Atan: return std::atan(x[0]);
    case OpCode::Sinh: return std::sinh(x[0]);
    case OpCode::Cosh: return std::cosh(x[0]);
    case OpCode::Tanh: return std::tanh(x[0]);
    case OpCode::Exp: return std::exp(x[0]);
    case OpCode::Log: return std::log(x[0]);
    case OpCode::Log10: return std::log10(x[0]);
    case OpCode::Sqrt: return std::sqrt(x[0]);
    case OpCode::Abs: return std::abs(x[0]);
    case OpCode::Atan2: return std::atan2(x[0], x[1]);
    case OpCode::Min: {
      double m = x[0];
      for (int k = 1; k < in.arg; ++k)
        if (x[k] < m) m = x[k];
      return m;
    }
    case OpCode::Max: {
      double m = x[0];
      for (int k = 1; k < in.arg; ++k)
        if (x[k] > m) m = x[k];
      return m;
    }
    case OpCode::Constant:
    case OpCode::Parameter:
    case OpCode::Call: break;
  }
  throw Error("internal error: expression instruction without operands applied");
}

// The text around a column, for messages about long generated formulas.
std::string excerpt(const std::string& text, int column) {
  constexpr int kWidth = 60;
  if (static_cast<int>(text.size()) <= kWidth) return "\"" + text + "\"";
  int start = std::max(0, column - 1 - kWidth / 2);
  start = std::min(start, static_cast<int>(text.size()) - kWidth);
  std::string out = text.substr(static_cast<std::size_t>(start), kWidth);
  return std::string(start > 0 ? "\"..." : "\"") + out +
         (start + kWidth < static_cast<int>(text.size()) ? "...\"" : "\"");
}

// A number inside an operation's description: parenthesised when negative.
std::string operand(double x) {
  std::string t = format::shortest(x);
  return x < 0 ? "(" + t + ")" : t;
}

std::string describeFailure(const Instruction& in, const double* x,
                            const std::vector<double>& constants) {
  switch (in.op) {
    case OpCode::Divide:
      if (x[1] == 0.0) return "division by zero (" + format::shortest(x[0]) + " / 0)";
      return "overflow in division (" + format::shortest(x[0]) + " / " + format::shortest(x[1]) + ")";
    case OpCode::Power:
    case OpCode::PowerConstant:
    case OpCode::PowerInteger:
    case OpCode::Square:
    case OpCode::Cube: {
      double b = in.op == OpCode::Power           ? x[1]
                 : in.op == OpCode::PowerConstant ? constants[in.arg]
                 : in.op == OpCode::PowerInteger  ? in.arg
                 : in.op == OpCode::Square        ? 2.0
                                                  : 3.0;
      std::string what = operand(x[0]) + " ** " + operand(b);
      if (x[0] == 0.0 && b < 0) return "zero raised to a negative power (" + what + ")";
      if (x[0] < 0 && b != std::floor(b))
        return "negative number raised to a non-integer power (" + what + ")";
      return "overflow in power (" + what + ")";
    }
    case OpCode::Log:
    case OpCode::Log10: {
      std::string f = opName(in.op);
      if (x[0] == 0.0) return f + " of zero";
      return f + " of a negative number (" + f + "(" + format::shortest(x[0]) + "))";
    }
    case OpCode::Sqrt:
      return "sqrt of a negative number (sqrt(" + format::shortest(x[0]) + "))";
    case OpCode::Asin:
    case OpCode::Acos:
      return std::string(opName(in.op)) + " of " + format::shortest(x[0]) + ", outside [-1, 1]";
    case OpCode::Negate:
    case OpCode::Abs:
    case OpCode::Min:
    case OpCode::Max: break;
    case OpCode::Add:
    case OpCode::Subtract:
    case OpCode::Multiply:
      return std::string("overflow in ") + format::shortest(x[0]) + " " + opName(in.op) + " " +
             operand(x[1]);
    default:
      if (arity(in) == 1)
        return std::string("overflow or domain error in ") + opName(in.op) + "(" +
               format::shortest(x[0]) + ")";
  }
  return std::string("operation '") + opName(in.op) + "' gives a non-finite value";
}

// ---------------------------------------------------------------- lexer

enum class Tok { Number, Name, Plus, Minus, Star, Slash, Power, LParen, RParen, Comma, End };

struct Token {
  Tok kind;
  int column;  // 1-based
  std::string text;
  double value = 0.0;
};

bool isNameStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isNameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool isDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

class Lexer {
 public:
  explicit Lexer(const std::string& text) : text_(text) {}

  std::vector<Token> run() {
    std::vector<Token> tokens;
    const std::size_t n = text_.size();
    std::size_t i = 0;
    while (true) {
      while (i < n && std::isspace(static_cast<unsigned char>(text_[i]))) ++i;
      const int column = static_cast<int>(i) + 1;
      if (i >= n) {
        tokens.push_back({Tok::End, column, "end of expression"});
        return tokens;
      }
      const char c = text_[i];
      if (isDigit(c) || (c == '.' && i + 1 < n && isDigit(text_[i + 1]))) {
        tokens.push_back(number(i));
        continue;
      }
      if (isNameStart(c)) {
        std::size_t j = i;
        while (j < n && isNameChar(text_[j])) ++j;
        tokens.push_back({Tok::Name, column, text_.substr(i, j - i)});
        i = j;
        continue;
      }
      auto single = [&](Tok kind) {
        tokens.push_back({kind, column, std::string(1, c)});
        ++i;
      };
      switch (c) {
        case '+': single(Tok::Plus); break;
        case '-': single(Tok::Minus); break;
        case '(': single(Tok::LParen); break;
        case ')': single(Tok::RParen); break;
        case ',': single(Tok::Comma); break;
        case '*':
          if (i + 1 < n && text_[i + 1] == '*') {
            tokens.push_back({Tok::Power, column, "**"});
            i += 2;
          } else {
            single(Tok::Star);
          }
          break;
        case '/':
          if (i + 1 < n && text_[i + 1] == '/')
            fail("operator '//' (floor division) is not supported at column " +
                     std::to_string(column),
                 column);
          single(Tok::Slash);
          break;
        case '%': fail("operator '%' is not supported at column " + std::to_string(column), column);
        case '^':
          fail("unexpected character '^' at column " + std::to_string(column) +
                   " (powers are written **)",
               column);
        default:
          fail("unexpected character '" + std::string(1, c) + "' at column " +
                   std::to_string(column),
               column);
      }
    }
  }

  [[noreturn]] void fail(const std::string& message, int column) const {
    throw Error(message + " in " + excerpt(text_, column));
  }

 private:
  // Python float literals: digits [. digits] [e [+-] digits], or . digits [...].
  Token number(std::size_t& i) {
    const std::size_t n = text_.size(), start = i;
    const int column = static_cast<int>(start) + 1;
    bool ok = true;
    while (i < n && isDigit(text_[i])) ++i;
    if (i < n && text_[i] == '.') {
      ++i;
      while (i < n && isDigit(text_[i])) ++i;
    }
    if (i < n && (text_[i] == 'e' || text_[i] == 'E')) {
      ++i;
      if (i < n && (text_[i] == '+' || text_[i] == '-')) ++i;
      if (i >= n || !isDigit(text_[i])) ok = false;
      while (i < n && isDigit(text_[i])) ++i;
    }
    // "1.2.3" or "2X" are not numbers: take the whole run for the message.
    if (i < n && (isNameChar(text_[i]) || text_[i] == '.')) {
      ok = false;
      while (i < n && (isNameChar(text_[i]) || text_[i] == '.')) ++i;
    }
    const std::string literal = text_.substr(start, i - start);
    if (!ok) fail("malformed number '" + literal + "' at column " + std::to_string(column), column);
    const double value = std::strtod(literal.c_str(), nullptr);
    if (!std::isfinite(value))
      fail("number '" + literal + "' at column " + std::to_string(column) + " is too large",
           column);
    return {Tok::Number, column, literal, value};
  }

  const std::string& text_;
};

}  // namespace

// ---------------------------------------------------------------- parser and emitter

class ExpressionCompiler {
 public:
  ExpressionCompiler(Expression& e, const ExpressionContext& context) : e_(e), context_(context) {}

  void compile() {
    checkParameters();
    checkContext();
    tokens_ = Lexer(e_.text_).run();
    if (tokens_.front().kind == Tok::End) throw Error("empty expression");
    const int root = parseSum();
    if (peek().kind != Tok::End) {
      const Token& t = peek();
      std::string hint = t.kind == Tok::RParen ? " (no '(' to close)"
                                                : ": expected an operator or the end of the expression";
      fail("unexpected '" + t.text + "' at column " + std::to_string(t.column) + hint, t.column);
    }
    emit(root);
  }

 private:
  struct Node {
    OpCode op;  // Constant, Parameter, or the operation
    int column;
    double value = 0.0;      // Constant
    int index = 0;           // Parameter
    std::vector<int> kids;   // operands
  };

  void checkParameters() {
    const auto& p = e_.params_;
    for (std::size_t i = 0; i < p.size(); ++i) {
      bool valid = !p[i].empty() && isNameStart(p[i][0]);
      for (char c : p[i]) valid = valid && isNameChar(c);
      if (!valid) throw Error("parameter name '" + p[i] + "' is not a valid name");
      if (findFunction(p[i]) || p[i] == "pi")
        throw Error("parameter name '" + p[i] + "' is reserved (a function or a constant)");
      for (std::size_t j = 0; j < i; ++j)
        if (p[j] == p[i]) throw Error("parameter '" + p[i] + "' is listed twice");
    }
  }

  // Context names are named like parameters, and none is also a parameter.
  void checkContext() const {
    auto check = [&](const std::string& name) {
      bool valid = !name.empty() && isNameStart(name[0]);
      for (char c : name) valid = valid && isNameChar(c);
      if (!valid) throw Error("context name '" + name + "' is not a valid name");
      if (findFunction(name) || name == "pi")
        throw Error("context name '" + name + "' is reserved (a function or a constant)");
      for (const auto& p : e_.params_)
        if (p == name) throw Error("context name '" + name + "' is also a parameter (NOM_PARA)");
    };
    for (const auto& [name, value] : context_.constants) {
      check(name);
      if (!std::isfinite(value))
        throw Error("context value " + name + " = " + format::shortest(value) + " is not a finite number");
    }
    for (const auto& [name, f] : context_.functions) check(name);
  }

  const double* contextConstant(const std::string& name) const {
    for (const auto& [n, v] : context_.constants)
      if (n == name) return &v;
    return nullptr;
  }

  const FunctionPtr* contextFunction(const std::string& name) const {
    for (const auto& [n, f] : context_.functions)
      if (n == name) return &f;
    return nullptr;
  }

  [[noreturn]] void fail(const std::string& message, int column) const {
    throw Error(message + " in " + excerpt(e_.text_, column));
  }

  // One more level of the parser's recursion (parentheses, calls, signs, powers):
  // bounded, so that a pathological text cannot overflow the C++ stack.
  void enter(const Token& t) {
    if (++nesting_ > kMaxNesting)
      fail("expression nested too deeply at column " + std::to_string(t.column) + " (more than " +
               std::to_string(kMaxNesting) + " levels of parentheses, calls, signs and powers)",
           t.column);
  }

  const Token& peek() const { return tokens_[pos_]; }
  const Token& next() { return tokens_[pos_++]; }

  int add(Node n) {
    nodes_.push_back(std::move(n));
    return static_cast<int>(nodes_.size()) - 1;
  }
  int constant(double v, int column) { return add({OpCode::Constant, column, v, 0, {}}); }

  // An operation node; folded to a constant when all operands are constants and
  // the result is finite (a failing constant operation stays, for the checked message).
  int operation(OpCode op, int column, std::vector<int> kids) {
    bool allConstant = true;
    double x[8] = {};
    for (std::size_t k = 0; k < kids.size(); ++k) {
      allConstant = allConstant && nodes_[kids[k]].op == OpCode::Constant && k < 8;
      if (allConstant) x[k] = nodes_[kids[k]].value;
    }
    if (allConstant) {
      const double v = apply({op, static_cast<std::int32_t>(kids.size())}, x, {});
      if (std::isfinite(v)) return constant(v, column);
    }
    return add({op, column, 0.0, 0, std::move(kids)});
  }

  // sum := product (('+' | '-') product)*
  int parseSum() {
    int left = parseProduct();
    while (peek().kind == Tok::Plus || peek().kind == Tok::Minus) {
      const Token& t = next();
      const int right = parseProduct();
      left = operation(t.kind == Tok::Plus ? OpCode::Add : OpCode::Subtract, t.column, {left, right});
    }
    return left;
  }

  // product := factor (('*' | '/') factor)*
  int parseProduct() {
    int left = parseFactor();
    while (peek().kind == Tok::Star || peek().kind == Tok::Slash) {
      const Token& t = next();
      const int right = parseFactor();
      left = operation(t.kind == Tok::Star ? OpCode::Multiply : OpCode::Divide, t.column,
                       {left, right});
    }
    return left;
  }

  // factor := ('+' | '-') factor | power      (so -2**2 == -(2**2))
  int parseFactor() {
    if (peek().kind == Tok::Plus || peek().kind == Tok::Minus) {
      const Token& t = next();
      enter(t);
      const int operand = parseFactor();
      --nesting_;
      return t.kind == Tok::Plus ? operand : operation(OpCode::Negate, t.column, {operand});
    }
    return parsePower();
  }

  // power := primary ['**' factor]            (right-associative, 2**-1 allowed)
  int parsePower() {
    const int base = parsePrimary();
    if (peek().kind != Tok::Power) return base;
    const Token& t = next();
    enter(t);
    const int exponent = parseFactor();
    --nesting_;
    return operation(OpCode::Power, t.column, {base, exponent});
  }

  int parsePrimary() {
    const Token& t = peek();
    switch (t.kind) {
      case Tok::Number: next(); return constant(t.value, t.column);
      case Tok::Name: next(); return parseName(t);
      case Tok::LParen: {
        next();
        enter(t);
        const int inner = parseSum();
        --nesting_;
        expectClosing(t, "'('");
        return inner;
      }
      case Tok::End: {
        const Token& previous = tokens_[pos_ - 1];
        fail("unterminated expression: an operand is expected after '" + previous.text +
                 "' at column " + std::to_string(previous.column),
             previous.column);
      }
      default:
        fail("unexpected '" + t.text + "' at column " + std::to_string(t.column) +
                 ": expected a number, a name or '('",
             t.column);
    }
  }

  void expectClosing(const Token& open, const std::string& what) {
    const Token& t = peek();
    if (t.kind == Tok::RParen) {
      next();
      return;
    }
    if (t.kind == Tok::End)
      fail("unterminated expression: missing ')' to close " + what + " at column " +
               std::to_string(open.column),
           open.column);
    fail("unexpected '" + t.text + "' at column " + std::to_string(t.column) +
             ": expected ')' to close " + what + " at column " + std::to_string(open.column),
         t.column);
  }

  int parseName(const Token& name) {
    const FunctionInfo* f = findFunction(name.text);
    const FunctionPtr* user = contextFunction(name.text);
    if (peek().kind == Tok::LParen) {
      if (user) return parseUserCall(name, *user);
      if (!f) {
        for (const auto& p : e_.params_)
          if (p == name.text)
            fail("'" + name.text + "' at column " + std::to_string(name.column) +
                     " is a parameter, not a function",
                 name.column);
        fail("unknown function '" + name.text + "' at column " + std::to_string(name.column) +
                 " (functions: " + functionNames() + ")",
             name.column);
      }
      return parseCall(name, *f);
    }
    for (std::size_t i = 0; i < e_.params_.size(); ++i)
      if (e_.params_[i] == name.text)
        return add({OpCode::Parameter, name.column, 0.0, static_cast<int>(i), {}});
    if (const double* v = contextConstant(name.text)) return constant(*v, name.column);
    if (name.text == "pi") return constant(kPi, name.column);
    if (user)
      fail("function '" + name.text + "' at column " + std::to_string(name.column) +
               " must be called with arguments in parentheses",
           name.column);
    if (f)
      fail("function '" + name.text + "' at column " + std::to_string(name.column) +
               " must be called with arguments in parentheses",
           name.column);
    fail("unknown name '" + name.text + "' at column " + std::to_string(name.column) +
             " (parameters: " + joinNames(e_.params_) + contextNames() + ")",
         name.column);
  }

  // "; context: A, F" when the expression has a context.
  std::string contextNames() const {
    std::vector<std::string> names;
    for (const auto& c : context_.constants) names.push_back(c.first);
    for (const auto& c : context_.functions) names.push_back(c.first);
    return names.empty() ? "" : "; context: " + joinNames(names);
  }

  // The arguments of a call "name(a, b, ...)", from its '(' to its ')'.
  std::vector<int> parseArguments(const Token& name) {
    const Token& open = next();  // '('
    enter(open);
    std::vector<int> args;
    if (peek().kind != Tok::RParen) {
      while (true) {
        args.push_back(parseSum());
        if (peek().kind != Tok::Comma) break;
        next();
      }
    }
    expectClosing(open, "'" + name.text + "('");
    --nesting_;
    return args;
  }

  // F(a, b) for a function F of the context: as many arguments as F has parameters.
  int parseUserCall(const Token& name, const FunctionPtr& f) {
    std::vector<int> args = parseArguments(name);
    const std::size_t expected = f->parameters().size();
    if (args.size() != expected)
      fail("function '" + name.text + "' takes " + std::to_string(expected) + " argument" +
               (expected == 1 ? "" : "s") + " (" + joinNames(f->parameters()) + "), got " +
               std::to_string(args.size()) + " at column " + std::to_string(name.column),
           name.column);
    int index = -1;
    for (std::size_t i = 0; i < e_.callees_.size(); ++i)
      if (e_.callees_[i].name == name.text) index = static_cast<int>(i);
    if (index < 0) {
      e_.callees_.push_back({name.text, f, dynamic_cast<const Expression*>(f.get()),
                             static_cast<int>(expected)});
      index = static_cast<int>(e_.callees_.size()) - 1;
    }
    return add({OpCode::Call, name.column, 0.0, index, std::move(args)});
  }

  int parseCall(const Token& name, const FunctionInfo& f) {
    std::vector<int> args = parseArguments(name);
    const int count = static_cast<int>(args.size());
    if (count < f.minArgs || (f.maxArgs >= 0 && count > f.maxArgs)) {
      std::string expected = f.maxArgs < 0 ? "at least " + std::to_string(f.minArgs)
                                            : std::to_string(f.minArgs);
      expected += (f.minArgs == 1 && f.maxArgs == 1) ? " argument" : " arguments";
      fail("function '" + name.text + "' takes " + expected + ", got " + std::to_string(count) +
               " at column " + std::to_string(name.column),
           name.column);
    }
    return operation(f.op, name.column, std::move(args));
  }

  // Postfix emission; integer and constant exponents get cheaper, exact-derivative opcodes.
  void emit(int root) {
    emitNode(root);
    e_.depth_ = maxDepth_;
  }

  void push(OpCode op, std::int32_t arg, int column, int pops, int pushes = 1) {
    e_.code_.push_back({op, arg});
    e_.columns_.push_back(column);
    depth_ += pushes - pops;
    maxDepth_ = std::max(maxDepth_, depth_);
  }

  // Constants are finite: equal values of the same sign have the same bits
  // (a map, not a search, for formulas with many distinct constants).
  std::int32_t constantIndex(double v) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    const auto found = constantIndices_.find(bits);
    if (found != constantIndices_.end()) return found->second;
    e_.constants_.push_back(v);
    const auto index = static_cast<std::int32_t>(e_.constants_.size() - 1);
    constantIndices_.emplace(bits, index);
    return index;
  }

  // Iterative: a sum of many terms is a tree as deep as it is long.
  void emitNode(int root) {
    struct Pending {
      int node;
      std::size_t emitted;  // operands already emitted
    };
    std::vector<Pending> stack{{root, 0}};
    while (!stack.empty()) {
      Pending& p = stack.back();
      const Node& n = nodes_[p.node];
      if (p.emitted < operandsToEmit(n)) {
        const int kid = n.kids[p.emitted++];
        stack.push_back({kid, 0});  // p is invalid from here
        continue;
      }
      stack.pop_back();
      emitOperation(n);
    }
  }

  static bool powerOfConstant(const Node& n, const std::vector<Node>& nodes) {
    return n.op == OpCode::Power && nodes[n.kids[1]].op == OpCode::Constant;
  }

  std::size_t operandsToEmit(const Node& n) const {
    return powerOfConstant(n, nodes_) ? 1 : n.kids.size();  // a constant exponent goes in the opcode
  }

  // The instruction of a node whose operands are on the stack.
  void emitOperation(const Node& n) {
    switch (n.op) {
      case OpCode::Constant: push(OpCode::Constant, constantIndex(n.value), n.column, 0); return;
      case OpCode::Parameter: push(OpCode::Parameter, n.index, n.column, 0); return;
      default: break;
    }
    if (powerOfConstant(n, nodes_)) {
      const double c = nodes_[n.kids[1]].value;
      if (c == 2.0) push(OpCode::Square, 0, n.column, 1);
      else if (c == 3.0) push(OpCode::Cube, 0, n.column, 1);
      else if (c == std::floor(c) && std::abs(c) <= 1024)
        push(OpCode::PowerInteger, static_cast<std::int32_t>(c), n.column, 1);
      else push(OpCode::PowerConstant, constantIndex(c), n.column, 1);
      return;
    }
    const int count = static_cast<int>(n.kids.size());
    if (n.op == OpCode::Call) {
      push(OpCode::Call, n.index, n.column, count);
      return;
    }
    const bool variadic = n.op == OpCode::Min || n.op == OpCode::Max;
    push(n.op, variadic ? count : 0, n.column, count);
  }

  Expression& e_;
  const ExpressionContext& context_;
  std::vector<Token> tokens_;
  std::size_t pos_ = 0;
  std::vector<Node> nodes_;
  int nesting_ = 0;
  std::unordered_map<std::uint64_t, std::int32_t> constantIndices_;
  int depth_ = 0;
  int maxDepth_ = 0;
  static constexpr int kMaxNesting = 200;
};

std::shared_ptr<Expression> Expression::compile(const std::string& text,
                                                const std::vector<std::string>& params,
                                                const ExpressionContext& context) {
  std::shared_ptr<Expression> e(new Expression());
  e->text_ = text;
  e->params_ = params;
  ExpressionCompiler(*e, context).compile();
  return e;
}

void Expression::notDifferentiable(const Callee& c) const {
  throw Error("function '" + c.name + "' called by " + excerpt(text_, 1) +
              " is not a formula given as a text: it cannot be differentiated exactly");
}

double Expression::evaluateChecked(const double* args) const {
  auto values = [&] {
    std::string out;
    for (std::size_t i = 0; i < params_.size(); ++i)
      out += (i ? ", " : "") + params_[i] + " = " + format::shortest(args[i]);
    return out.empty() ? std::string("no parameters") : out;
  };
  for (std::size_t i = 0; i < params_.size(); ++i)
    if (!std::isfinite(args[i]))
      throw Error("parameter " + params_[i] + " = " + format::shortest(args[i]) +
                  " is not a finite number, evaluating " + excerpt(text_, 1));
  double inlineStack[kInlineDepth] = {};
  std::vector<double> heap;
  double* s = inlineStack;
  if (depth_ > kInlineDepth) {
    heap.resize(static_cast<std::size_t>(depth_));
    s = heap.data();
  }
  int top = -1;
  for (std::size_t k = 0; k < code_.size(); ++k) {
    const Instruction& in = code_[k];
    if (in.op == OpCode::Constant) {
      s[++top] = constants_[in.arg];
      continue;
    }
    if (in.op == OpCode::Parameter) {
      s[++top] = args[in.arg];
      continue;
    }
    if (in.op == OpCode::Call) {
      const Callee& c = callees_[in.arg];
      top -= c.arity - 1;
      const double r = c.expression ? c.expression->evaluateChecked(s + top) : c.function->evaluate(s + top);
      if (!std::isfinite(r))
        throw Error("function '" + c.name + "' returns " + format::shortest(r) + " at column " +
                    std::to_string(columns_[k]) + " of " + excerpt(text_, columns_[k]) + ", with " +
                    values());
      s[top] = r;
      continue;
    }
    top -= arity(in) - 1;
    const double r = apply(in, s + top, constants_);
    if (!std::isfinite(r))
      throw Error(describeFailure(in, s + top, constants_) + " at column " +
                  std::to_string(columns_[k]) + " of " + excerpt(text_, columns_[k]) + ", with " +
                  values());
    s[top] = r;
  }
  return s[0];
}

}  // namespace aster::expr
