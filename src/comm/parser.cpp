#include "comm/parser.hpp"

#include <set>

#include "comm/error.hpp"

namespace aster::comm {
namespace {

using K = Node::Kind;
using T = Token::Kind;

const std::set<std::string> kKeywords = {"False", "None", "True", "and", "as", "assert", "async", "await",
                                         "break", "class", "continue", "def", "del", "elif", "else", "except",
                                         "finally", "for", "from", "global", "if", "import", "in", "is",
                                         "lambda", "nonlocal", "not", "or", "pass", "raise", "return", "try",
                                         "while", "with", "yield", "exec"};

class Parser {
 public:
  explicit Parser(const std::vector<Token>& tokens) : t_(tokens) {}

  NodePtr file() {
    auto block = std::make_unique<Node>(K::Block, 1);
    while (!at(T::End)) {
      if (at(T::Newline)) {
        ++i_;
        continue;
      }
      if (at(T::Indent)) throw TranslateError(peek().line, "unexpected indentation");
      statement(*block);
    }
    return block;
  }

 private:
  struct Depth {
    explicit Depth(Parser& p) : p(p) {
      if (++p.depth_ > kMaxNesting)
        throw TranslateError(p.peek().line, "nesting deeper than " + std::to_string(kMaxNesting) + " levels is not supported");
    }
    ~Depth() { --p.depth_; }
    Parser& p;
  };

  // A chain (a + b + c, x.y.z) nests its tree one level per link: counted until the
  // chain's parse ends, so that no tree is deeper than kMaxNesting.
  void deeper() {
    if (++depth_ > kMaxNesting)
      fail("nesting deeper than " + std::to_string(kMaxNesting) + " levels is not supported");
  }

  // Puts the depth back when a chain's parse ends.
  struct Keep {
    explicit Keep(Parser& p) : p(p), saved(p.depth_) {}
    ~Keep() { p.depth_ = saved; }
    Parser& p;
    int saved;
  };

  const Token& peek(std::size_t k = 0) const { return t_[std::min(i_ + k, t_.size() - 1)]; }
  bool at(T kind) const { return peek().kind == kind; }
  bool atOp(const char* op) const { return peek().kind == T::Op && peek().text == op; }
  bool atWord(const char* w) const { return peek().kind == T::Name && peek().text == w; }
  int line() const { return peek().line; }
  const Token& next() { return t_[i_ < t_.size() - 1 ? i_++ : i_]; }

  [[noreturn]] void fail(const std::string& what) const { throw TranslateError(line(), what); }
  std::string shown() const {
    const Token& t = peek();
    switch (t.kind) {
      case T::Newline: return "the end of the line";
      case T::Indent: return "an indentation";
      case T::Dedent: return "the end of the block";
      case T::End: return "the end of the file";
      case T::String: return "a string";
      default: return "'" + t.text + "'";
    }
  }
  void expectOp(const char* op) {
    if (!atOp(op)) fail(std::string("'") + op + "' expected, found " + shown());
    ++i_;
  }
  std::string expectName() {
    if (!at(T::Name) || kKeywords.count(peek().text)) fail("a name expected, found " + shown());
    return next().text;
  }
  void endOfSimpleStatement() {
    if (at(T::Newline)) {
      ++i_;
      return;
    }
    if (at(T::End) || at(T::Dedent)) return;
    fail("the end of the statement expected, found " + shown());
  }

  // ---- statements
  void statement(Node& block) {
    const Depth d(*this);
    const Token& t = peek();
    const int ln = t.line;
    if (t.kind == T::Op && t.text == "@") fail("decorators are not supported");
    if (t.kind == T::Name) {
      const std::string& w = t.text;
      if (w == "if") return block.kids.push_back(ifStatement()), void();
      if (w == "while") {
        ++i_;
        auto n = std::make_unique<Node>(K::While, ln);
        n->kids.push_back(test());
        n->kids.push_back(suite());
        if (atWord("else")) fail("while ... else is not supported");
        return block.kids.push_back(std::move(n)), void();
      }
      if (w == "for") return block.kids.push_back(forStatement()), void();
      if (w == "def") return block.kids.push_back(defStatement()), void();
      if (w == "class") fail("class definitions are not supported");
      if (w == "try") return block.kids.push_back(tryImport()), void();
      if (w == "with") fail("with statements are not supported");
      if (w == "async") fail("async is not supported");
    }
    for (;;) {
      block.kids.push_back(smallStatement());
      if (!atOp(";")) break;
      ++i_;
      if (at(T::Newline)) break;
    }
    endOfSimpleStatement();
  }

  NodePtr ifStatement() {
    const int ln = line();
    ++i_;  // if / elif
    auto n = std::make_unique<Node>(K::If, ln);
    n->kids.push_back(test());
    n->kids.push_back(suite());
    if (atWord("elif")) {
      n->kids.push_back(ifStatement());
      n->kids.back()->text = "elif";
    } else if (atWord("else")) {
      ++i_;
      n->kids.push_back(suite());
    }
    return n;
  }

  // try: import X ... except ImportError: ... -- X (sympy...) never exists for a
  // translated study, so the handler is what runs: the only try translated.
  NodePtr tryImport() {
    const int ln = line();
    ++i_;
    expectOp(":");
    if (!at(T::Newline)) fail("try/except is not supported");
    ++i_;
    if (!at(T::Indent)) fail("an indented block expected, found " + shown());
    ++i_;
    if (!atWord("import") && !atWord("from")) throw TranslateError(ln, "try/except is not supported");
    ++skipModuleCheck_;
    NodePtr first = smallStatement();
    --skipModuleCheck_;
    const std::string module = first->kind == K::Import ? first->names[0] : first->text;
    const std::string top = module.substr(0, module.find('.'));
    if (top == "math" || top == "code_aster" || top == "__future__") throw TranslateError(ln, "try/except is not supported");
    // The rest of the try block never runs: skip it, token by token.
    int depth = 1;
    while (depth > 0 && !at(T::End)) {
      if (at(T::Indent)) ++depth;
      if (at(T::Dedent)) --depth;
      ++i_;
    }
    if (!atWord("except")) throw TranslateError(ln, "try/except is not supported");
    ++i_;
    bool importError = false;
    if (atWord("ImportError") || atWord("ModuleNotFoundError")) {
      importError = true;
      ++i_;
    } else if (atOp("(")) {
      ++i_;
      while (!atOp(")") && !at(T::End) && !at(T::Newline)) {
        importError = importError || atWord("ImportError") || atWord("ModuleNotFoundError") || atWord("Exception");
        ++i_;
      }
      if (atOp(")")) ++i_;
    } else if (atOp(":") || atWord("Exception")) {
      importError = true;
      if (atWord("Exception")) ++i_;
    }
    if (!importError) throw TranslateError(ln, "try/except is not supported");
    if (atWord("as")) {
      ++i_;
      expectName();
    }
    auto handler = suite();
    if (atWord("except") || atWord("else") || atWord("finally")) throw TranslateError(line(), "try/except is not supported beyond try: import ... except ImportError:");
    return handler;
  }

  NodePtr forStatement() {
    const int ln = line();
    ++i_;
    auto n = std::make_unique<Node>(K::For, ln);
    n->kids.push_back(targetList());
    if (!atWord("in")) fail("'in' expected in a for statement, found " + shown());
    ++i_;
    n->kids.push_back(testList());
    n->kids.push_back(suite());
    if (atWord("else")) fail("for ... else is not supported");
    return n;
  }

  NodePtr targetList() {
    const int ln = line();
    std::vector<NodePtr> items;
    bool comma = false;
    for (;;) {
      if (atOp("(") || atOp("[")) {
        fail("nested unpacking in a for target is not supported");
      }
      auto name = std::make_unique<Node>(K::Name, line());
      name->text = expectName();
      items.push_back(std::move(name));
      if (!atOp(",")) break;
      comma = true;
      ++i_;
      if (atWord("in")) break;
    }
    if (!comma) return std::move(items[0]);
    auto tuple = std::make_unique<Node>(K::Tuple, ln);
    tuple->kids = std::move(items);
    return tuple;
  }

  NodePtr defStatement() {
    const int ln = line();
    ++i_;
    auto n = std::make_unique<Node>(K::Def, ln);
    n->text = expectName();
    expectOp("(");
    std::vector<NodePtr> defaults;
    while (!atOp(")")) {
      if (atOp("*") || atOp("**")) fail("*args and **kwargs parameters are not supported");
      if (atOp("/")) fail("positional-only parameters are not supported");
      n->names.push_back(expectName());
      if (atOp(":")) fail("annotations are not supported");
      if (atOp("=")) {
        ++i_;
        defaults.push_back(test());
      } else {
        defaults.push_back(nullptr);
      }
      if (!atOp(",")) break;
      ++i_;
    }
    expectOp(")");
    if (atOp("->")) fail("annotations are not supported");
    n->kids.push_back(suite());
    for (auto& d : defaults) n->kids.push_back(std::move(d));
    return n;
  }

  NodePtr suite() {
    expectOp(":");
    auto block = std::make_unique<Node>(K::Block, line());
    if (!at(T::Newline)) {  // if x: y = 1
      for (;;) {
        block->kids.push_back(smallStatement());
        if (!atOp(";")) break;
        ++i_;
        if (at(T::Newline)) break;
      }
      endOfSimpleStatement();
      return block;
    }
    ++i_;
    if (!at(T::Indent)) fail("an indented block expected, found " + shown());
    ++i_;
    while (!at(T::Dedent) && !at(T::End)) {
      if (at(T::Newline)) {
        ++i_;
        continue;
      }
      statement(*block);
    }
    if (at(T::Dedent)) ++i_;
    return block;
  }

  NodePtr smallStatement() {
    const Token& t = peek();
    const int ln = t.line;
    if (t.kind == T::Name) {
      const std::string w = t.text;
      if (w == "pass" || w == "break" || w == "continue") {
        ++i_;
        return std::make_unique<Node>(w == "pass" ? K::Pass : w == "break" ? K::Break : K::Continue, ln);
      }
      if (w == "return") {
        ++i_;
        auto n = std::make_unique<Node>(K::Return, ln);
        if (!at(T::Newline) && !atOp(";") && !at(T::End) && !at(T::Dedent)) n->kids.push_back(testList());
        return n;
      }
      if (w == "global" || w == "nonlocal") fail(w + " declarations are not supported");
      if (w == "raise") fail("raise is not supported");
      if (w == "yield") fail("generators (yield) are not supported");
      if (w == "exec") fail("exec is not supported");
      if (w == "print" && peek(1).kind != T::Op && peek(1).kind != T::Newline)
        fail("the Python 2 print statement is not supported (print(...) is)");
      if (w == "print" && peek(1).kind == T::Op && peek(1).text == ">>")
        fail("the Python 2 print statement is not supported (print(...) is)");
      if (w == "del") {
        ++i_;
        auto n = std::make_unique<Node>(K::Del, ln);
        auto targets = testList();
        if (targets->kind == K::Tuple) n->kids = std::move(targets->kids);
        else n->kids.push_back(std::move(targets));
        return n;
      }
      if (w == "assert") {
        ++i_;
        auto n = std::make_unique<Node>(K::Assert, ln);
        n->kids.push_back(test());
        if (atOp(",")) {
          ++i_;
          n->kids.push_back(test());
        }
        return n;
      }
      if (w == "import") return importStatement();
      if (w == "from") return fromStatement();
    }
    auto first = testList(true);
    if (atOp("=")) {
      auto n = std::make_unique<Node>(K::Assign, ln);
      n->kids.push_back(std::move(first));
      while (atOp("=")) {
        ++i_;
        n->kids.push_back(testList(true));
      }
      for (std::size_t k = 0; k + 1 < n->kids.size(); ++k) checkTarget(*n->kids[k]);
      return n;
    }
    for (const char* aug : {"+=", "-=", "*=", "/=", "//=", "%=", "**="}) {
      if (atOp(aug)) {
        ++i_;
        auto n = std::make_unique<Node>(K::AugAssign, ln);
        n->text = std::string(aug).substr(0, std::string(aug).size() - 1);
        checkTarget(*first);
        if (first->kind == K::Tuple) fail("augmented assignment to a tuple");
        n->kids.push_back(std::move(first));
        n->kids.push_back(testList());
        return n;
      }
    }
    if (at(T::Op) && peek().text.size() >= 2 && peek().text.back() == '=' && peek().text != "==" &&
        peek().text != "<=" && peek().text != ">=" && peek().text != "!=")
      fail("the operator " + peek().text + " is not supported");
    if (atOp(":")) fail("annotations are not supported");
    auto n = std::make_unique<Node>(K::ExprStmt, ln);
    n->kids.push_back(std::move(first));
    return n;
  }

  void checkTarget(const Node& n) const {
    if (n.kind == K::Name || n.kind == K::Attribute || n.kind == K::Subscript) return;
    if (n.kind == K::Tuple || n.kind == K::List) {
      for (const auto& k : n.kids)
        if (k->kind != K::Name && k->kind != K::Subscript && k->kind != K::Attribute)
          throw TranslateError(k->line, "nested unpacking in an assignment is not supported");
      return;
    }
    throw TranslateError(n.line, "this expression cannot be assigned to");
  }

  std::string dottedName() {
    std::string name = expectName();
    while (atOp(".")) {
      ++i_;
      name += "." + expectName();
    }
    return name;
  }

  // Only math, __future__ and code_aster's commands exist in a translated study.
  void checkModule(const std::string& module) const {
    if (skipModuleCheck_) return;
    const std::string top = module.substr(0, module.find('.'));
    if (top == "math" || top == "__future__" || top == "code_aster") return;
    if (top == "numpy") fail("numpy is not supported");
    fail("import of " + module + " is not supported (only math and code_aster's commands)");
  }

  NodePtr importStatement() {
    auto n = std::make_unique<Node>(K::Import, line());
    ++i_;
    for (;;) {
      const std::string module = dottedName();
      std::string alias = module;
      if (atWord("as")) {
        ++i_;
        alias = expectName();
      }
      checkModule(module);
      n->names.push_back(module);
      n->names2.push_back(alias);
      if (!atOp(",")) break;
      ++i_;
    }
    return n;
  }

  NodePtr fromStatement() {
    auto n = std::make_unique<Node>(K::ImportFrom, line());
    ++i_;
    if (atOp(".")) fail("relative imports are not supported");
    n->text = dottedName();
    checkModule(n->text);
    if (!atWord("import")) fail("'import' expected, found " + shown());
    ++i_;
    if (atOp("*")) {
      ++i_;
      n->names.push_back("*");
      n->names2.push_back("*");
      return n;
    }
    const bool paren = atOp("(");
    if (paren) ++i_;
    for (;;) {
      const std::string name = expectName();
      std::string alias = name;
      if (atWord("as")) {
        ++i_;
        alias = expectName();
      }
      n->names.push_back(name);
      n->names2.push_back(alias);
      if (!atOp(",")) break;
      ++i_;
      if (paren && atOp(")")) break;
    }
    if (paren) expectOp(")");
    return n;
  }

  // ---- expressions
  // testlist: a, b -> Tuple (assignment targets and values, return, for iterables)
  NodePtr testList(bool allowStar = false) {
    const int ln = line();
    if (allowStar && atOp("*")) fail("starred assignment is not supported");
    auto first = test();
    if (!atOp(",")) return first;
    auto tuple = std::make_unique<Node>(K::Tuple, ln);
    tuple->kids.push_back(std::move(first));
    while (atOp(",")) {
      ++i_;
      if (at(T::Newline) || atOp("=") || atOp(")") || at(T::End) || atOp(":") || atOp(";")) break;
      tuple->kids.push_back(test());
    }
    return tuple;
  }

  NodePtr test() {
    const Depth d(*this);
    if (atWord("lambda")) fail("lambda is not supported");
    if (atWord("yield")) fail("generators (yield) are not supported");
    if (atWord("await")) fail("await is not supported");
    auto value = orTest();
    if (atWord("if")) {
      const int ln = line();
      ++i_;
      auto n = std::make_unique<Node>(K::IfExp, ln);
      n->kids.push_back(std::move(value));
      n->kids.push_back(orTest());
      if (!atWord("else")) fail("'else' expected in a conditional expression, found " + shown());
      ++i_;
      n->kids.push_back(test());
      return n;
    }
    if (atOp(":=")) fail("assignment expressions (:=) are not supported");
    return value;
  }

  NodePtr binary(K kind, const std::string& op, NodePtr a, NodePtr b, int ln) {
    auto n = std::make_unique<Node>(kind, ln);
    n->text = op;
    n->kids.push_back(std::move(a));
    n->kids.push_back(std::move(b));
    return n;
  }

  NodePtr orTest() {
    const Keep keep(*this);
    auto a = andTest();
    while (atWord("or")) {
      const int ln = line();
      ++i_;
      deeper();
      a = binary(K::BoolOp, "or", std::move(a), andTest(), ln);
    }
    return a;
  }
  NodePtr andTest() {
    const Keep keep(*this);
    auto a = notTest();
    while (atWord("and")) {
      const int ln = line();
      ++i_;
      deeper();
      a = binary(K::BoolOp, "and", std::move(a), notTest(), ln);
    }
    return a;
  }
  NodePtr notTest() {
    if (atWord("not")) {
      const Depth d(*this);
      auto n = std::make_unique<Node>(K::Unary, line());
      ++i_;
      n->text = "not";
      n->kids.push_back(notTest());
      return n;
    }
    return comparison();
  }
  NodePtr comparison() {
    const Keep keep(*this);
    auto a = arith();
    NodePtr cmp;
    for (;;) {
      std::string op;
      if (at(T::Op) && (peek().text == "<" || peek().text == ">" || peek().text == "==" || peek().text == "!=" ||
                        peek().text == "<=" || peek().text == ">=")) {
        op = next().text;
      } else if (atWord("in")) {
        ++i_;
        op = "in";
      } else if (atWord("not") && peek(1).kind == T::Name && peek(1).text == "in") {
        i_ += 2;
        op = "notin";
      } else if (atWord("is")) {
        ++i_;
        op = "is";
        if (atWord("not")) {
          ++i_;
          op = "isnot";
        }
      } else {
        break;
      }
      if (!cmp) {
        cmp = std::make_unique<Node>(K::Compare, a->line);
        cmp->kids.push_back(std::move(a));
      }
      deeper();
      cmp->names.push_back(op);
      cmp->kids.push_back(arith());
    }
    return cmp ? std::move(cmp) : std::move(a);
  }
  NodePtr arith() {
    const Keep keep(*this);
    if (at(T::Op) && (peek().text == "|" || peek().text == "&" || peek().text == "^" || peek().text == "<<" ||
                      peek().text == ">>"))
      fail("bitwise operators are not supported");
    auto a = term();
    while (atOp("+") || atOp("-")) {
      const int ln = line();
      const std::string op = next().text;
      deeper();
      a = binary(K::BinOp, op, std::move(a), term(), ln);
    }
    if (at(T::Op) && (peek().text == "|" || peek().text == "&" || peek().text == "^" || peek().text == "<<" ||
                      peek().text == ">>"))
      fail("bitwise operators (" + peek().text + ") are not supported");
    return a;
  }
  NodePtr term() {
    const Keep keep(*this);
    auto a = factor();
    while (atOp("*") || atOp("/") || atOp("//") || atOp("%") || atOp("@")) {
      if (atOp("@")) fail("the matrix product operator @ is not supported");
      const int ln = line();
      const std::string op = next().text;
      deeper();
      a = binary(K::BinOp, op, std::move(a), factor(), ln);
    }
    return a;
  }
  NodePtr factor() {
    if (atOp("-") || atOp("+")) {
      const Depth d(*this);
      auto n = std::make_unique<Node>(K::Unary, line());
      n->text = next().text;
      n->kids.push_back(factor());
      return n;
    }
    if (atOp("~")) fail("bitwise operators (~) are not supported");
    return power();
  }
  NodePtr power() {
    auto a = atomExpr();
    if (atOp("**")) {
      const int ln = line();
      ++i_;
      const Depth d(*this);
      a = binary(K::BinOp, "**", std::move(a), factor(), ln);
    }
    return a;
  }
  NodePtr atomExpr() {
    const Keep keep(*this);
    auto a = atom();
    int trailers = 0;  // the first call or index is no deeper than its name
    for (;;) {
      if (++trailers > 1) deeper();
      if (atOp("(")) {
        auto call = std::make_unique<Node>(K::Call, line());
        ++i_;
        call->kids.push_back(std::move(a));
        arguments(*call);
        a = std::move(call);
      } else if (atOp("[")) {
        auto sub = std::make_unique<Node>(K::Subscript, line());
        ++i_;
        sub->kids.push_back(std::move(a));
        sub->kids.push_back(subscript());
        expectOp("]");
        a = std::move(sub);
      } else if (atOp(".")) {
        auto attr = std::make_unique<Node>(K::Attribute, line());
        ++i_;
        attr->text = expectName();
        attr->kids.push_back(std::move(a));
        a = std::move(attr);
      } else {
        return a;
      }
    }
  }
  void arguments(Node& call) {
    const Depth d(*this);
    bool keywords = false;
    while (!atOp(")")) {
      if (atOp("*")) fail("* argument unpacking is not supported");
      if (atOp("**")) {  // CMD(**keywords): a Keyword named "**"
        auto kw = std::make_unique<Node>(K::Keyword, line());
        ++i_;
        kw->text = "**";
        kw->kids.push_back(test());
        call.kids.push_back(std::move(kw));
        keywords = true;
        if (!atOp(",")) break;
        ++i_;
        continue;
      }
      if (at(T::Name) && peek(1).kind == T::Op && peek(1).text == "=") {
        auto kw = std::make_unique<Node>(K::Keyword, line());
        kw->text = next().text;
        ++i_;
        kw->kids.push_back(test());
        call.kids.push_back(std::move(kw));
        keywords = true;
      } else {
        if (keywords) fail("a positional argument after keyword arguments");
        call.kids.push_back(test());
        if (atWord("for")) fail("generator expressions are not supported");
      }
      if (!atOp(",")) break;
      ++i_;
    }
    expectOp(")");
  }
  // [element for target in iterable if condition]: one for, any number of ifs.
  NodePtr comprehension(NodePtr element, int ln) {
    ++i_;  // for
    auto n = std::make_unique<Node>(K::ListComp, ln);
    n->kids.push_back(std::move(element));
    n->kids.push_back(targetList());
    if (!atWord("in")) fail("'in' expected in a list comprehension, found " + shown());
    ++i_;
    n->kids.push_back(orTest());
    while (atWord("if")) {
      const int cl = line();
      ++i_;
      auto c = orTest();
      if (n->kids.size() == 3) {
        n->kids.push_back(std::move(c));
      } else {
        n->kids[3] = binary(K::BoolOp, "and", std::move(n->kids[3]), std::move(c), cl);
      }
    }
    if (atWord("for")) throw TranslateError(ln, "list comprehensions with more than one for are not supported");
    expectOp("]");
    return n;
  }

  NodePtr subscript() {
    const int ln = line();
    NodePtr lower, upper, step;
    if (!atOp(":")) lower = test();
    if (!atOp(":")) {
      if (!atOp(",")) return lower;
      // T['PARA', 1]: a code_aster table's cell (column, row)
      auto pair = std::make_unique<Node>(K::Tuple, ln);
      pair->kids.push_back(std::move(lower));
      while (atOp(",")) {
        ++i_;
        if (atOp("]")) break;
        if (atOp(":")) fail("multi-dimensional indexing is not supported");
        pair->kids.push_back(test());
        if (atOp(":")) fail("multi-dimensional indexing is not supported");
      }
      return pair;
    }
    ++i_;
    if (!atOp("]") && !atOp(":") && !atOp(",")) upper = test();
    if (atOp(":")) {
      ++i_;
      if (!atOp("]") && !atOp(",")) step = test();
    }
    if (atOp(",")) fail("multi-dimensional indexing is not supported");
    auto n = std::make_unique<Node>(K::Slice, ln);
    n->kids.push_back(std::move(lower));
    n->kids.push_back(std::move(upper));
    n->kids.push_back(std::move(step));
    return n;
  }
  NodePtr atom() {
    const Depth d(*this);
    const Token& t = peek();
    const int ln = t.line;
    switch (t.kind) {
      case T::Number: {
        auto n = std::make_unique<Node>(K::Number, ln);
        n->text = t.text;
        n->isFloat = t.isFloat;
        ++i_;
        return n;
      }
      case T::String: {
        auto n = std::make_unique<Node>(K::String, ln);
        n->text = t.text;
        n->pieces = t.pieces;
        ++i_;
        return n;
      }
      case T::Name: {
        if (t.text == "True" || t.text == "False" || t.text == "None") {
          ++i_;
          return std::make_unique<Node>(t.text == "True" ? K::True : t.text == "False" ? K::False : K::None, ln);
        }
        if (t.text == "lambda") fail("lambda is not supported");
        if (kKeywords.count(t.text)) fail("'" + t.text + "' cannot start an expression");
        auto n = std::make_unique<Node>(K::Name, ln);
        n->text = t.text;
        ++i_;
        return n;
      }
      case T::Op: break;
      default: fail("an expression expected, found " + shown());
    }
    if (t.text == "(") {
      ++i_;
      if (atOp(")")) {
        ++i_;
        return std::make_unique<Node>(K::Tuple, ln);
      }
      auto first = test();
      if (atWord("for")) throw TranslateError(ln, "generator expressions are not supported");
      if (atOp(")")) {
        ++i_;
        return first;  // parentheses only group
      }
      auto tuple = std::make_unique<Node>(K::Tuple, ln);
      tuple->kids.push_back(std::move(first));
      while (atOp(",")) {
        ++i_;
        if (atOp(")")) break;
        tuple->kids.push_back(test());
      }
      expectOp(")");
      return tuple;
    }
    if (t.text == "[") {
      ++i_;
      auto list = std::make_unique<Node>(K::List, ln);
      while (!atOp("]")) {
        if (atOp("*")) fail("starred elements are not supported");
        list->kids.push_back(test());
        if (atWord("for") && list->kids.size() == 1) return comprehension(std::move(list->kids[0]), ln);
        if (atWord("for")) throw TranslateError(ln, "list comprehensions are not supported");
        if (!atOp(",")) break;
        ++i_;
      }
      expectOp("]");
      return list;
    }
    if (t.text == "{") {
      ++i_;
      auto dict = std::make_unique<Node>(K::Dict, ln);
      while (!atOp("}")) {
        if (atOp("**")) fail("** unpacking in a dict is not supported");
        dict->kids.push_back(test());
        if (atWord("for")) throw TranslateError(ln, "set comprehensions are not supported");
        if (!atOp(":")) fail("sets are not supported");
        ++i_;
        dict->kids.push_back(test());
        if (atWord("for")) throw TranslateError(ln, "dict comprehensions are not supported");
        if (!atOp(",")) break;
        ++i_;
      }
      expectOp("}");
      return dict;
    }
    if (t.text == "...") fail("Ellipsis (...) is not supported");
    fail("an expression expected, found " + shown());
  }

  const std::vector<Token>& t_;
  std::size_t i_ = 0;
  int depth_ = 0;
  int skipModuleCheck_ = 0;
};

}  // namespace

NodePtr parse(const LexedFile& file) { return Parser(file.tokens).file(); }

}  // namespace aster::comm
