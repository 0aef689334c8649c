#include "comm/emitter.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <functional>
#include <set>

#include "comm/error.hpp"
#include "comm/names.hpp"
#include "comm/prelude.hpp"
#include "comm/types.hpp"

namespace aster::comm {
namespace {

using K = Node::Kind;

struct Scope {
  bool function = false;
  Scope* parent = nullptr;
  std::map<std::string, Ty> types;       // names assigned in this scope
  std::map<std::string, const Node*> defs;  // functions defined in this scope
  std::set<std::string> params;
  std::map<std::string, bool> onlyFalse;  // names every assignment of which is False
};

struct Loop {
  bool hasContinue = false;
};

class Emitter {
 public:
  Emitter(const std::vector<std::string>& src, const std::map<int, std::string>& comments)
      : src_(src), comments_(comments) {}

  std::string run(const Node& file) {
    // code_aster runs a command file after `from math import *` (its legacy
    // auto-import): math's names are there unless the file binds them itself.
    for (const auto& [name, _] : mathNames()) bareMath_[name] = name;
    imports(file);
    module_.function = false;
    infer(file, module_);
    scope_ = &module_;
    out_.assign(src_.size() + 2, "");
    cur_ = 1;
    out_[1] = indentOf(1);
    block(file);
    // Comments, then the helpers on line 1, before its code.
    for (const auto& [line, text] : comments_) {
      if (line >= static_cast<int>(out_.size())) out_.resize(line + 1);
      std::string& l = out_[line];
      while (!l.empty() && (l.back() == ' ' || l.back() == '\t')) l.pop_back();
      const bool blank = l.find_first_not_of(" \t") == std::string::npos;
      // A line comment stays one: no "--[[" opening a long comment, no carriage return
      // (a line break for Lua) inside it.
      std::string kept = text;
      std::replace(kept.begin(), kept.end(), '\r', ' ');
      if (!kept.empty() && kept[0] == '[') kept.insert(0, " ");
      l += (blank ? "--" : " --") + kept;
    }
    const std::string pre = prelude(used_);
    if (!pre.empty()) out_[1] = pre + out_[1];
    std::string lua;
    const int last = std::max<int>(cur_, static_cast<int>(src_.size()));
    for (int i = 1; i <= last && i < static_cast<int>(out_.size()); ++i) {
      std::string& l = out_[i];
      while (!l.empty() && (l.back() == ' ' || l.back() == '\t')) l.pop_back();
      lua += l;
      lua += '\n';
    }
    return lua;
  }

 private:
  // ---------------------------------------------------------------- output
  std::string indentOf(int line) const {
    if (line < 1 || line > static_cast<int>(src_.size())) return "";
    const std::string& s = src_[line - 1];
    const auto n = s.find_first_not_of(" \t");
    return n == std::string::npos ? "" : s.substr(0, n);
  }
  void at(int line) {
    if (line <= cur_) return;
    if (line >= static_cast<int>(out_.size())) out_.resize(line + 1);
    for (int l = cur_ + 1; l <= line; ++l) out_[l] = indentOf(l);
    cur_ = line;
  }
  void put(const std::string& text) {
    std::string& l = out_[cur_];
    // A space between words; never two '-' glued into a comment.
    if (!text.empty() && l.find_first_not_of(" \t") != std::string::npos) {
      const char a = l.back(), b = text[0];
      const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
      if ((a == '-' && b == '-') || ((word(a) || a == ')' || a == '}' || a == ']' || a == '\'' || a == ':') && word(b)))
        l += ' ';
    }
    l += text;
  }
  void helper(const std::string& name) { used_.insert(name); }
  [[noreturn]] static void refuse(const Node& n, const std::string& what) { throw TranslateError(n.line, what); }

  // ---------------------------------------------------------------- names
  std::string rename(const std::string& name) const {
    if (kLuaReserved.count(name) || isHelperName(name)) return name + "_";
    // Python allows non-ASCII names (déplacement), Lua does not: each such byte as _xHH.
    if (std::any_of(name.begin(), name.end(), [](char c) { return static_cast<unsigned char>(c) >= 0x80; })) {
      std::string ascii;
      for (const char c : name) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x80) {
          ascii += c;
        } else {
          char hex[8];
          std::snprintf(hex, sizeof hex, "_x%02X", u);
          ascii += hex;
        }
      }
      return ascii;
    }
    return name;
  }
  bool assigned(const std::string& name) const {
    for (const Scope* s = scope_; s; s = s->parent)
      if (s->types.count(name) || s->params.count(name) || s->defs.count(name)) return true;
    return false;
  }
  const Node* userFunction(const std::string& name) const {
    for (const Scope* s = scope_; s; s = s->parent) {
      if (s->params.count(name)) return nullptr;
      const auto d = s->defs.find(name);
      if (d != s->defs.end()) return d->second;
      if (s->types.count(name)) return nullptr;
    }
    return nullptr;
  }
  Ty nameType(const std::string& name) const {
    for (const Scope* s = scope_; s; s = s->parent) {
      if (s->params.count(name)) return Ty::Unknown;
      const auto t = s->types.find(name);
      if (t != s->types.end()) return t->second == Ty::Bottom ? Ty::Unknown : t->second;
    }
    return Ty::Unknown;
  }
  bool isMathModule(const Node& n) const {
    return n.kind == K::Name && mathModules_.count(n.text) && !assigned(n.text);
  }

  // ---------------------------------------------------------------- imports
  void imports(const Node& block) {
    for (const auto& s : block.kids) {
      if (s->kind == K::Import) {
        for (std::size_t i = 0; i < s->names.size(); ++i) {
          const std::string& m = s->names[i];
          if (m == "math") {
            mathModules_.insert(s->names2[i]);
          } else if (m.rfind("code_aster", 0) == 0) {
            foreign_.insert(s->names2[i]);
          } else {
            refuseImport(*s, m);
          }
        }
      } else if (s->kind == K::ImportFrom) {
        const std::string& m = s->text;
        if (m == "math") {
          for (std::size_t i = 0; i < s->names.size(); ++i) {
            if (s->names[i] == "*") {
              for (const auto& [name, _] : mathNames()) bareMath_[name] = name;
            } else {
              if (!mathNames().count(s->names[i])) refuse(*s, "math." + s->names[i] + " is not supported");
              bareMath_[s->names2[i]] = s->names[i];
            }
          }
        } else if (m == "__future__") {
        } else if (m.rfind("code_aster", 0) == 0) {
          for (std::size_t i = 0; i < s->names.size(); ++i) {
            const std::string& n = s->names2[i];
            // Commands are global functions already; anything else is code_aster's Python API.
            const bool command = std::all_of(n.begin(), n.end(), [](char c) { return std::isupper(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) || c == '_'; });
            if (n != "*" && !command) foreign_.insert(n);
          }
        } else {
          refuseImport(*s, m);
        }
      } else if (s->kind == K::Block) {
        imports(*s);
      } else {
        for (const auto& k : s->kids)
          if (k && k->kind == K::Block) imports(*k);
        if (s->kind == K::If && s->kids.size() > 2 && s->kids[2]->kind == K::If) {
          Node chain(K::Block, s->line);  // an elif: its blocks sit in a nested If
          const Node* e = s->kids[2].get();
          while (e && e->kind == K::If) {
            imports(*e->kids[1]);
            if (e->kids.size() < 3) break;
            if (e->kids[2]->kind == K::Block) imports(*e->kids[2]);
            e = e->kids[2].get();
          }
        }
      }
    }
  }
  [[noreturn]] static void refuseImport(const Node& n, const std::string& module) {
    const std::string top = module.substr(0, module.find('.'));
    if (top == "numpy") refuse(n, "numpy is not supported");
    refuse(n, "import of " + module + " is not supported (only math and code_aster's commands)");
  }

  // ---------------------------------------------------------------- type inference
  // Each name's type is the join over every assignment in the scope, iterated to a fixed point.
  void infer(const Node& block, Scope& scope) {
    Scope* saved = scope_;
    scope_ = &scope;
    for (int pass = 0; pass < 4; ++pass) {
      std::map<std::string, Ty> next;
      collect(block, scope, next);
      for (auto& [name, t] : next)
        if (!scope.types.count(name)) scope.types[name] = Ty::Bottom;
      if (next == scope.types) break;
      scope.types = next;
    }
    scope_ = saved;
  }
  void bind(std::map<std::string, Ty>& types, const Node& target, Ty t, bool isFalse = false) {
    if (target.kind == K::Name) {
      auto& f = scope_->onlyFalse.try_emplace(target.text, true).first->second;
      f = f && isFalse;
      types[target.text] = join(types.count(target.text) ? types[target.text] : Ty::Bottom, t);
    } else if (target.kind == K::Tuple || target.kind == K::List) {
      for (const auto& k : target.kids) bind(types, *k, Ty::Unknown);
    }
  }
  void collect(const Node& block, Scope& scope, std::map<std::string, Ty>& types) {
    for (const auto& sp : block.kids) {
      const Node& s = *sp;
      switch (s.kind) {
        case K::Assign: {
          const Node& value = *s.kids.back();
          for (std::size_t i = 0; i + 1 < s.kids.size(); ++i) {
            const Node& t = *s.kids[i];
            if ((t.kind == K::Tuple || t.kind == K::List) && value.kind == t.kind &&
                value.kids.size() == t.kids.size()) {
              for (std::size_t k = 0; k < t.kids.size(); ++k) bind(types, *t.kids[k], typeOf(*value.kids[k]));
            } else {
              bind(types, t, typeOf(value), value.kind == K::False);
            }
          }
          break;
        }
        case K::AugAssign:
          if (s.kids[0]->kind == K::Name)
            bind(types, *s.kids[0], binaryType(s.text, typeOf(*s.kids[0]), typeOf(*s.kids[1])));
          break;
        case K::For: {
          Ty t = Ty::Unknown;
          const Node& it = *s.kids[1];
          if (isRangeCall(it)) t = rangeNonNegative(it) ? Ty::Index : Ty::Int;
          if (s.kids[0]->kind == K::Tuple && it.kind == K::Call && it.kids[0]->kind == K::Name &&
              it.kids[0]->text == "enumerate" && s.kids[0]->kids.size() == 2) {
            bind(types, *s.kids[0]->kids[0], Ty::Index);
            bind(types, *s.kids[0]->kids[1], Ty::Unknown);
          } else {
            bind(types, *s.kids[0], t);
          }
          collect(*s.kids[2], scope, types);
          break;
        }
        case K::If: {
          const Node* n = &s;
          while (n) {
            collect(*n->kids[1], scope, types);
            if (n->kids.size() < 3) break;
            if (n->kids[2]->kind == K::Block) {
              collect(*n->kids[2], scope, types);
              break;
            }
            n = n->kids[2].get();
          }
          break;
        }
        case K::While: collect(*s.kids[1], scope, types); break;
        case K::Block: collect(s, scope, types); break;
        case K::Def:
          scope.defs[s.text] = &s;
          types[s.text] = Ty::Func;
          break;
        case K::Del:
          for (const auto& t : s.kids) bind(types, *t, Ty::None);
          break;
        default: break;
      }
    }
  }

  bool isRangeCall(const Node& n) const {
    return n.kind == K::Call && n.kids[0]->kind == K::Name && n.kids[0]->text == "range" && !assigned("range");
  }
  static bool nonNegativeLiteral(const Node& n) { return n.kind == K::Number && !n.isFloat; }
  static bool positiveLiteral(const Node& n) { return n.kind == K::Number && !n.isFloat && n.text != "0"; }
  bool rangeNonNegative(const Node& call) const {
    const std::size_t n = call.kids.size() - 1;
    if (n == 1) return true;
    if (n == 2) return nonNegativeLiteral(*call.kids[1]) || typeOf(*call.kids[1]) == Ty::Index;
    if (n == 3)
      return (nonNegativeLiteral(*call.kids[1]) || typeOf(*call.kids[1]) == Ty::Index) && positiveLiteral(*call.kids[3]);
    return false;
  }

  Ty binaryType(const std::string& op, Ty a, Ty b) const {
    if (op == "+") {
      if (a == Ty::Str || b == Ty::Str) return Ty::Str;
      if (a == Ty::List || b == Ty::List) return Ty::List;
      if (isNum(a) || isNum(b)) return numeric(isNum(a) ? a : Ty::Num, isNum(b) ? b : Ty::Num);
      return Ty::Unknown;
    }
    if (op == "-") {
      const Ty t = numeric(isNum(a) ? a : Ty::Num, isNum(b) ? b : Ty::Num);
      return t == Ty::Index ? Ty::Int : t;
    }
    if (op == "*") {
      if (a == Ty::Str || b == Ty::Str) return Ty::Str;
      if (a == Ty::List || b == Ty::List) return Ty::List;
      if (isNum(a) && isNum(b)) return numeric(a, b);
      if (a == Ty::Float || b == Ty::Float) return Ty::Float;
      return Ty::Unknown;
    }
    if (op == "/") return Ty::Float;
    if (op == "//") return isNum(a) && isNum(b) ? (isInt(a) && isInt(b) ? (a == Ty::Index && b == Ty::Index ? Ty::Index : Ty::Int) : Ty::Num) : Ty::Num;
    if (op == "%") {
      if (a == Ty::Str) return Ty::Str;
      if (isNum(a)) return b == Ty::Index && isInt(a) ? Ty::Index : isInt(a) && isInt(b) ? Ty::Int : Ty::Num;
      return Ty::Unknown;
    }
    if (op == "**") {
      if (a == Ty::Float || b == Ty::Float) return Ty::Float;
      if (a == Ty::Index && b == Ty::Index) return Ty::Index;
      return Ty::Num;
    }
    return Ty::Unknown;
  }

  Ty typeOf(const Node& n) const {
    switch (n.kind) {
      case K::Name:
        if (bareMath_.count(n.text) && !assigned(n.text)) return Ty::Float;
        return nameType(n.text);
      case K::Number: return n.isFloat ? Ty::Float : Ty::Index;
      case K::String: return Ty::Str;
      case K::True: case K::False: return Ty::Bool;
      case K::None: return Ty::None;
      case K::Tuple: case K::List: case K::ListComp: return Ty::List;
      case K::Dict: return Ty::Dict;
      case K::Compare: return Ty::Bool;
      case K::Unary:
        if (n.text == "not") return Ty::Bool;
        if (n.text == "-") {
          const Ty t = typeOf(*n.kids[0]);
          return t == Ty::Index ? Ty::Int : isNum(t) ? t : Ty::Num;
        }
        return typeOf(*n.kids[0]);
      case K::BoolOp: return join(typeOf(*n.kids[0]), typeOf(*n.kids[1]));
      case K::BinOp: return binaryType(n.text, typeOf(*n.kids[0]), typeOf(*n.kids[1]));
      case K::IfExp: return join(typeOf(*n.kids[0]), typeOf(*n.kids[2]));
      case K::Attribute:
        if (isMathModule(*n.kids[0])) return Ty::Float;
        return Ty::Unknown;
      case K::Call: return callType(n);
      case K::Subscript:
        if (n.kids[1]->kind == K::Slice) return typeOf(*n.kids[0]) == Ty::Str ? Ty::Str : Ty::List;
        return typeOf(*n.kids[0]) == Ty::Str ? Ty::Str : Ty::Unknown;
      default: return Ty::Unknown;
    }
  }
  Ty callType(const Node& n) const {
    const Node& f = *n.kids[0];
    if (f.kind == K::Name && !assigned(f.text)) {
      const std::string& b = f.text;
      if (b == "len") return Ty::Index;
      if (b == "int") return Ty::Int;
      if (b == "float") return Ty::Float;
      if (b == "str" || b == "repr") return Ty::Str;
      if (b == "bool") return Ty::Bool;
      if (b == "round") return n.kids.size() == 2 ? Ty::Int : Ty::Float;
      if (b == "abs") return n.kids.size() == 2 ? typeOf(*n.kids[1]) : Ty::Unknown;
      if (b == "list" || b == "tuple" || b == "sorted" || b == "range") return Ty::List;
      if (b == "dict") return Ty::Dict;
      if ((b == "min" || b == "max") && n.kids.size() > 2) {
        Ty t = Ty::Bottom;
        for (std::size_t i = 1; i < n.kids.size(); ++i) t = join(t, typeOf(*n.kids[i]));
        return t == Ty::Bottom ? Ty::Unknown : t;
      }
      if (bareMath_.count(b)) {
        const std::string& m = bareMath_.at(b);
        return m == "floor" || m == "ceil" || m == "trunc" ? Ty::Int : Ty::Float;
      }
    }
    if (f.kind == K::Attribute) {
      if (isMathModule(*f.kids[0])) return f.text == "floor" || f.text == "ceil" || f.text == "trunc" ? Ty::Int : Ty::Float;
      const std::string& m = f.text;
      if (m == "format" || m == "join" || m == "upper" || m == "lower" || m == "strip" || m == "replace") return Ty::Str;
      if (m == "split") return Ty::List;
      if (m == "startswith" || m == "endswith") return Ty::Bool;
    }
    return Ty::Unknown;
  }

  // ---------------------------------------------------------------- precedence
  // Lua: or 1, and 2, comparisons 3, .. 5 (right), + - 6, * / // % 7, unary 8, ^ 9 (right); atoms 100.
  struct Form {
    std::string op;      // Lua infix operator, or empty for a helper call
    std::string helper;  // helper name
    int prec = 100;
  };
  Form binForm(const Node& n) const {
    const Ty a = typeOf(*n.kids[0]), b = typeOf(*n.kids[1]);
    const std::string& op = n.text;
    if (op == "+") {
      if (a == Ty::Str || b == Ty::Str) return {"..", "", 5};
      if (isNum(a) || isNum(b)) return {"+", "", 6};
      return {"", "py_add", 100};
    }
    if (op == "-") return {"-", "", 6};
    if (op == "*") {
      if (isNoneSlots(*n.kids[0]) || isNoneSlots(*n.kids[1])) return {"", "py_slots", 100};
      if (a == Ty::Str || b == Ty::Str || a == Ty::List || b == Ty::List) return {"", "py_mul", 100};
      if ((isNum(a) && isNum(b)) || a == Ty::Float || b == Ty::Float) return {"*", "", 7};
      return {"", "py_mul", 100};
    }
    if (op == "/" || op == "//") return {op, "", 7};
    if (op == "%") {
      if (a == Ty::Str) return {"", "py_format", 100};
      if (isNum(a)) return {"%", "", 7};
      return {"", "py_mod", 100};
    }
    if (op == "**") {
      if (a == Ty::Float || b == Ty::Float) return {"^", "", 9};
      return {"", "py_pow", 100};
    }
    refuse(n, "the operator " + op + " is not supported");
  }
  bool plainEquality(const Node& n) const {
    for (std::size_t i = 0; i < n.kids.size(); ++i) {
      const Ty t = typeOf(*n.kids[i]);
      if (isScalar(t)) return true;
    }
    return false;
  }
  int precOf(const Node& n) const {
    switch (n.kind) {
      case K::String: return n.pieces.size() > 1 && nonEmptyPieces(n) > 1 ? 5 : 100;
      case K::BinOp: return binForm(n).prec;
      case K::Unary:
        if (n.text == "+") return precOf(*n.kids[0]);
        return 8;
      case K::BoolOp:
        if (typeOf(*n.kids[0]) == Ty::Bool && typeOf(*n.kids[1]) == Ty::Bool) return n.text == "and" ? 2 : 1;
        return 100;
      case K::Compare: {
        if (n.names.size() > 1) return 2;
        const std::string& op = n.names[0];
        if (op == "in") return 100;
        if (op == "notin") return 8;
        if ((op == "==" || op == "!=") && !plainEquality(n)) return op == "==" ? 100 : 8;
        return 3;
      }
      default: return 100;
    }
  }
  static int nonEmptyPieces(const Node& n) {
    int k = 0;
    for (const auto& p : n.pieces) k += !p.text.empty();
    return k;
  }

  // ---------------------------------------------------------------- expressions
  void expr(const Node& n, int minPrec = 0) {
    at(n.line);
    const bool paren = precOf(n) < minPrec;
    if (paren) put("(");
    exprBare(n);
    if (paren) put(")");
  }
  void stringLiteral(const Node& n) {
    bool first = true;
    int pieces = 0;
    for (const auto& p : n.pieces) {
      if (p.text.empty()) continue;
      if (!first) put(" ..");
      at(p.line);
      put(quoteSafe(p.text));
      first = false;
      ++pieces;
    }
    if (pieces == 0) put("''");
  }
  static std::string quoteSafe(const std::string& s) {
    std::string q = "'";
    for (std::size_t i = 0; i < s.size(); ++i) {
      const unsigned char c = static_cast<unsigned char>(s[i]);
      switch (c) {
        case '\\': q += "\\\\"; break;
        case '\'': q += "\\'"; break;
        case '\n': q += "\\n"; break;
        case '\r': q += "\\r"; break;
        case '\t': q += "\\t"; break;
        default:
          if (c < 32 || c == 127) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\%03d", c);
            q += buf;
          } else {
            q += static_cast<char>(c);
          }
      }
    }
    return q + "'";
  }

  void list(const std::vector<NodePtr>& kids, std::size_t from = 0) {
    for (std::size_t i = from; i < kids.size(); ++i) {
      if (i > from) put(", ");
      expr(*kids[i]);
    }
  }
  void tableOf(const Node& n) {
    put("{");
    for (std::size_t i = 0; i < n.kids.size(); ++i) {
      if (n.kids[i]->kind == K::None) refuse(*n.kids[i], "None inside a list or tuple is not supported (Lua tables end at nil)");
      if (i) put(", ");
      expr(*n.kids[i]);
    }
    put("}");
  }
  std::string key(const std::string& k) const {
    const bool ident = !k.empty() && (std::isalpha(static_cast<unsigned char>(k[0])) || k[0] == '_') &&
                       std::all_of(k.begin(), k.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
    if (ident && !kLuaKeywords.count(k)) return k;
    return "[" + quoteSafe(k) + "]";
  }

  void exprBare(const Node& n) {
    switch (n.kind) {
      case K::Name: return name(n);
      case K::Number: return put(n.text);
      case K::String: return stringLiteral(n);
      case K::True: return put("true");
      case K::False: return put("false");
      case K::None: return put("nil");
      case K::Tuple: case K::List: return tableOf(n);
      case K::Dict: {
        helper("py_dict");
        put("py_dict{");
        for (std::size_t i = 0; i + 1 < n.kids.size(); i += 2) {
          if (i) put(", ");
          const Node& k = *n.kids[i];
          at(k.line);
          if (k.kind == K::String) put(key(k.text));
          else refuse(k, "dictionary keys other than string literals are not supported");
          put(" = ");
          expr(*n.kids[i + 1]);
        }
        return put("}");
      }
      case K::Call: return call(n);
      case K::Attribute: return attribute(n);
      case K::Subscript: return subscript(n);
      case K::Slice: refuse(n, "a slice outside brackets");
      case K::BinOp: return binary(n);
      case K::Unary: {
        if (n.text == "+") return expr(*n.kids[0], 0);
        if (n.text == "-") {
          put("-");
          const Node& k = *n.kids[0];
          return expr(k, k.kind == K::Unary ? 9 : 8);
        }
        put("not ");
        return cond(*n.kids[0], 8);
      }
      case K::BoolOp: {
        const Ty a = typeOf(*n.kids[0]), b = typeOf(*n.kids[1]);
        if (a == Ty::Bool && b == Ty::Bool) {
          const int p = n.text == "and" ? 2 : 1;
          expr(*n.kids[0], p);
          put(" " + n.text + " ");
          return expr(*n.kids[1], p + 1);
        }
        // Python returns an operand, chosen by Python's truthiness; the right one lazily.
        const Node& r = *n.kids[1];
        const bool simple = r.kind == K::Name || r.kind == K::Number || r.kind == K::String || r.kind == K::True ||
                            r.kind == K::False || r.kind == K::None;
        const std::string h = std::string("py_") + n.text + (simple ? "" : "f");
        helper(h);
        put(h + "(");
        expr(*n.kids[0]);
        put(simple ? ", " : ", function() return ");
        expr(r);
        return put(simple ? ")" : " end)");
      }
      case K::Compare: return compare(n);
      case K::ListComp: {
        put("(function() local py_r = {}");
        const std::string prologue = forHeader(*n.kids[1], *n.kids[2], true);
        put(prologue);
        if (n.kids.size() > 3) {
          put(" if");
          cond(*n.kids[3]);
          put(" then");
        }
        put(" py_r[#py_r + 1] = ");
        expr(*n.kids[0]);
        if (n.kids.size() > 3) put(" end");
        return put(" end return py_r end)()");
      }
      case K::IfExp: {
        put("(");
        cond(*n.kids[1], 3);
        put(" and {");
        expr(*n.kids[0]);
        put("} or {");
        expr(*n.kids[2]);
        return put("})[1]");
      }
      default: refuse(n, "this expression is not supported");
    }
  }

  void name(const Node& n) {
    const std::string& s = n.text;
    if (foreign_.count(s) && !assigned(s)) refuse(n, "code_aster's Python API (" + s + ") is not supported");
    if (mathModules_.count(s) && !assigned(s)) refuse(n, "the module " + s + " used as a value");
    if (bareMath_.count(s) && !assigned(s)) {
      const MathName& m = mathNames().at(bareMath_.at(s));
      if (m.call) refuse(n, "math." + bareMath_.at(s) + " used as a value (only calls are translated)");
      return put(m.lua);
    }
    put(rename(s));
  }

  void compare(const Node& n) {
    if (n.names.size() > 1) {
      for (std::size_t i = 1; i + 1 < n.kids.size(); ++i) {
        const Node& m = *n.kids[i];
        if (m.kind != K::Name && m.kind != K::Number && m.kind != K::String)
          refuse(m, "a chained comparison with a computed middle operand is not supported");
      }
      for (std::size_t i = 0; i < n.names.size(); ++i) {
        if (i) put(" and ");
        compareOne(n.names[i], *n.kids[i], *n.kids[i + 1], 3);
      }
      return;
    }
    compareOne(n.names[0], *n.kids[0], *n.kids[1], 0);
  }
  void compareOne(const std::string& op, const Node& a, const Node& b, int minPrec) {
    if (op == "in" || op == "notin") {
      helper("py_in");
      put(op == "notin" ? "not py_in(" : "py_in(");
      expr(a);
      put(", ");
      expr(b);
      return put(")");
    }
    if ((op == "==" || op == "!=") && !isScalar(typeOf(a)) && !isScalar(typeOf(b))) {
      helper("py_eq");
      put(op == "!=" ? "not py_eq(" : "py_eq(");
      expr(a);
      put(", ");
      expr(b);
      return put(")");
    }
    const bool paren = minPrec > 3;
    if (paren) put("(");
    expr(a, 4);
    const std::string lua = op == "!=" || op == "isnot" ? "~=" : op == "is" ? "==" : op;
    put(" " + lua + " ");
    expr(b, 4);
    if (paren) put(")");
  }

  // A condition: Python's truthiness where the value is not a boolean.
  void cond(const Node& n, int minPrec = 0) {
    at(n.line);
    if (n.kind == K::BoolOp) {
      const int p = n.text == "and" ? 2 : 1;
      if (p < minPrec) put("(");
      cond(*n.kids[0], p);
      put(" " + n.text + " ");
      cond(*n.kids[1], p + 1);
      if (p < minPrec) put(")");
      return;
    }
    if (n.kind == K::Unary && n.text == "not") {
      if (8 < minPrec) put("(");
      put("not ");
      cond(*n.kids[0], 8);
      if (8 < minPrec) put(")");
      return;
    }
    if (typeOf(n) == Ty::Bool) return expr(n, minPrec);
    helper("py_truth");
    put("py_truth(");
    expr(n);
    put(")");
  }

  static bool isNoneSlots(const Node& n) {
    return (n.kind == K::List || n.kind == K::Tuple) && n.kids.size() == 1 && n.kids[0]->kind == K::None;
  }
  void binary(const Node& n) {
    if (n.text == "*" && (isNoneSlots(*n.kids[0]) || isNoneSlots(*n.kids[1]))) {
      // [None] * n: n empty slots, filled later by index; its length is n.
      helper("py_slots");
      put("py_slots(");
      expr(isNoneSlots(*n.kids[0]) ? *n.kids[1] : *n.kids[0]);
      return put(")");
    }
    const Form f = binForm(n);
    if (!f.helper.empty()) {
      helper(f.helper);
      put(f.helper + "(");
      expr(*n.kids[0]);
      put(", ");
      // 'fmt' % [a, b] formats the list as one value: only a tuple holds the arguments.
      const bool oneList = (f.helper == "py_format" || f.helper == "py_mod") && n.kids[1]->kind == K::List;
      if (oneList) put("{");
      expr(*n.kids[1]);
      if (oneList) put("}");
      return put(")");
    }
    const bool right = f.op == "^";
    const bool assoc = f.op == "..";
    expr(*n.kids[0], right ? f.prec + 1 : f.prec);
    put(" " + f.op + " ");
    expr(*n.kids[1], right || assoc ? f.prec : f.prec + 1);
  }

  // An expression indexed or called in Lua: a table constructor or a string literal
  // needs parentheses there ({1, 2}[1] is not Lua).
  void prefix(const Node& n) {
    const bool literal = n.kind == K::Tuple || n.kind == K::List || n.kind == K::Dict || n.kind == K::String;
    if (literal) {
      at(n.line);
      put("(");
      expr(n);
      put(")");
      return;
    }
    expr(n, 100);
  }

  void attribute(const Node& n) {
    const Node& obj = *n.kids[0];
    if (isMathModule(obj)) {
      const auto m = mathNames().find(n.text);
      if (m == mathNames().end()) refuse(n, "math." + n.text + " is not supported");
      if (m->second.call) refuse(n, "math." + n.text + " used as a value (only calls are translated)");
      at(obj.line);
      return put(m->second.lua);
    }
    if (obj.kind == K::Name && foreign_.count(obj.text) && !assigned(obj.text))
      refuse(n, "code_aster's Python API (" + obj.text + "." + n.text + ") is not supported");
    prefix(obj);
    const std::string k = key(n.text);
    put(k[0] == '[' ? k : "." + k);
  }

  void subscript(const Node& n) {
    const Node& obj = *n.kids[0];
    const Node& idx = *n.kids[1];
    if (idx.kind == K::Slice) {
      helper("py_slice");
      put("py_slice(");
      expr(obj);
      for (const auto& k : idx.kids) {
        put(", ");
        if (k) expr(*k);
        else put("nil");
      }
      return put(")");
    }
    if (idx.kind == K::Tuple) {  // T['PARA', row]: code_aster's tables count rows from 1, as aster-lite's
      if (idx.kids.size() != 2) refuse(n, "multi-dimensional indexing is not supported");
      prefix(obj);
      put(":get(");
      list(idx.kids);
      return put(")");
    }
    const Ty ot = typeOf(obj);
    if (idx.kind == K::String) {
      prefix(obj);
      const std::string k = key(idx.text);
      return put(k[0] == '[' ? k : "." + k);
    }
    if (ot == Ty::Dict) {
      prefix(obj);
      put("[");
      expr(idx);
      return put("]");
    }
    if (ot == Ty::List) {
      if (idx.kind == K::Number && !idx.isFloat) {
        prefix(obj);
        return put("[" + std::to_string(std::stoll(idx.text) + 1) + "]");
      }
      if (typeOf(idx) == Ty::Index) {
        prefix(obj);
        put("[");
        expr(idx, 6);
        return put(" + 1]");
      }
      if (obj.kind == K::Name && idx.kind == K::Unary && idx.text == "-" && idx.kids[0]->kind == K::Number &&
          !idx.kids[0]->isFloat) {
        const long long k = std::stoll(idx.kids[0]->text);
        prefix(obj);
        const std::string len = "#" + rename(obj.text);
        return put("[" + len + (k == 1 ? "" : " - " + std::to_string(k - 1)) + "]");
      }
    }
    helper("py_get");
    put("py_get(");
    expr(obj);
    put(", ");
    expr(idx);
    put(")");
  }

  // ---------------------------------------------------------------- calls
  static bool isCommandName(const std::string& s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
      return std::isupper(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) || c == '_';
    }) && std::isupper(static_cast<unsigned char>(s[0]));
  }
  static bool hasKeywords(const Node& call) {
    for (std::size_t i = 1; i < call.kids.size(); ++i)
      if (call.kids[i]->kind == K::Keyword) return true;
    return false;
  }
  static std::size_t positional(const Node& call) {
    std::size_t k = 0;
    for (std::size_t i = 1; i < call.kids.size(); ++i) k += call.kids[i]->kind != K::Keyword;
    return k;
  }
  void noKeywords(const Node& call, const std::string& what) {
    if (hasKeywords(call)) refuse(call, what + " with keyword arguments is not supported");
  }
  void args(const Node& call, std::size_t from = 1) {
    put("(");
    list(call.kids, from);
    put(")");
  }
  static bool hasUnpacking(const Node& call) {
    for (std::size_t i = 1; i < call.kids.size(); ++i)
      if (call.kids[i]->kind == K::Keyword && call.kids[i]->text == "**") return true;
    return false;
  }
  // The keywords of a command call as a table; with **d, the table and each d merged.
  void keywordTable(const Node& call) {
    const bool merge = hasUnpacking(call);
    if (merge) {
      helper("py_kwargs");
      put("py_kwargs(");
    }
    put("{");
    bool first = true;
    for (std::size_t i = 1; i < call.kids.size(); ++i) {
      const Node& kw = *call.kids[i];
      if (kw.kind != K::Keyword) refuse(kw, "a positional argument to a command (code_aster's commands take keywords)");
      if (kw.text == "**") continue;
      if (!first) put(", ");
      first = false;
      at(kw.line);
      put(key(kw.text) + " = ");
      expr(*kw.kids[0]);
    }
    put("}");
    if (!merge) return;
    for (std::size_t i = 1; i < call.kids.size(); ++i) {
      const Node& kw = *call.kids[i];
      if (kw.kind != K::Keyword || kw.text != "**") continue;
      put(", ");
      expr(*kw.kids[0]);
    }
    put(")");
  }

  // True when the call translates to a Lua function call (a valid statement).
  bool callIsLuaCall(const Node& n) const {
    const Node& f = *n.kids[0];
    if (f.kind == K::Name && !assigned(f.text)) {
      const std::string& b = f.text;
      if (b == "print" || b == "_F") return b == "print";
      if (kBuiltins.count(b) || bareMath_.count(b)) return false;
      return true;
    }
    if (f.kind == K::Attribute) {
      if (isMathModule(*f.kids[0])) return false;
      return f.text == "append" || f.text == "extend";
    }
    return true;
  }

  void call(const Node& n) {
    const Node& f = *n.kids[0];
    if (f.kind == K::Attribute) return methodCall(n);
    if (f.kind != K::Name) {
      noKeywords(n, "a computed function call");
      expr(f, 100);
      return args(n);
    }
    const std::string& s = f.text;
    if (const Node* def = userFunction(s)) return userCall(n, *def);
    if (assigned(s)) {
      noKeywords(n, "calling '" + s + "'");
      put(rename(s));
      return args(n);
    }
    if (s == "_F") {
      if (positional(n)) refuse(n, "_F takes keywords only");
      return keywordTable(n);
    }
    if (s == "INCLUDE") refuse(n, "INCLUDE is not supported");
    if (s == "EXEC_LOGICIEL") refuse(n, "EXEC_LOGICIEL is not supported");
    if (kRefusedCalls.count(s)) refuse(n, "the Python function " + s + "() is not supported");
    if (bareMath_.count(s)) return mathCall(n, bareMath_.at(s));
    if (kBuiltins.count(s)) return builtin(n, s);
    if (foreign_.count(s)) refuse(n, "code_aster's Python API (" + s + ") is not supported");
    const std::size_t pos = positional(n);
    if (hasKeywords(n) && pos) refuse(n, "'" + s + "' called with both positional and keyword arguments");
    if (hasKeywords(n) && !isCommandName(s))
      refuse(n, "keyword arguments to " + s + "(), which is neither a command nor a function of this file");
    if (hasKeywords(n) || (pos == 0 && isCommandName(s))) {
      put(rename(s));
      if (!hasUnpacking(n)) return keywordTable(n);
      put("(");
      keywordTable(n);
      return put(")");
    }
    put(rename(s));
    args(n);
  }

  void userCall(const Node& n, const Node& def) {
    if (hasUnpacking(n)) refuse(n, "** argument unpacking is only supported in command calls");
    put(rename(def.text));
    if (!hasKeywords(n)) {
      if (positional(n) > def.names.size()) refuse(n, def.text + "() given too many arguments");
      return args(n);
    }
    std::vector<const Node*> slot(def.names.size(), nullptr);
    std::size_t p = 0;
    for (std::size_t i = 1; i < n.kids.size(); ++i) {
      const Node& a = *n.kids[i];
      if (a.kind != K::Keyword) {
        if (p >= slot.size()) refuse(n, def.text + "() given too many arguments");
        slot[p++] = &a;
        continue;
      }
      const auto it = std::find(def.names.begin(), def.names.end(), a.text);
      if (it == def.names.end()) refuse(a, def.text + "() has no parameter " + a.text);
      const std::size_t k = static_cast<std::size_t>(it - def.names.begin());
      if (slot[k]) refuse(a, def.text + "() given " + a.text + " twice");
      slot[k] = a.kids[0].get();
    }
    std::size_t last = slot.size();
    while (last > 0 && !slot[last - 1]) --last;
    put("(");
    for (std::size_t k = 0; k < last; ++k) {
      if (k) put(", ");
      if (slot[k]) expr(*slot[k]);
      else put("nil");
    }
    put(")");
  }

  void mathCall(const Node& n, const std::string& m) {
    noKeywords(n, "math." + m);
    const auto it = mathNames().find(m);
    if (it == mathNames().end()) refuse(n, "math." + m + " is not supported");
    if (!it->second.call) refuse(n, "math." + m + " is not a function");
    if (m == "log10") {
      if (positional(n) != 1) refuse(n, "math.log10 takes one argument");
      put("math.log(");
      expr(*n.kids[1]);
      return put(", 10)");
    }
    if (m == "pow") {
      if (positional(n) != 2) refuse(n, "math.pow takes two arguments");
      put("(");
      expr(*n.kids[1], 10);
      put(" ^ ");
      expr(*n.kids[2], 9);
      return put(")");
    }
    const std::string lua = it->second.lua;
    if (lua.rfind("py_", 0) == 0) helper(lua);
    put(lua);
    args(n);
  }

  void builtin(const Node& n, const std::string& b) {
    const std::size_t argc = n.kids.size() - 1;
    if (hasUnpacking(n)) refuse(n, "** argument unpacking is only supported in command calls");
    if (b == "dict") {
      if (positional(n)) refuse(n, "dict() with positional arguments is not supported");
      helper("py_dict");
      put("py_dict");
      return keywordTable(n);
    }
    if (b == "print") {
      noKeywords(n, "print");
      helper("py_print");
      put("py_print");
      return args(n);
    }
    noKeywords(n, b + "()");
    auto need = [&](std::size_t lo, std::size_t hi) {
      if (argc < lo || argc > hi) refuse(n, b + "() takes " + std::to_string(lo) + (hi != lo ? " to " + std::to_string(hi) : "") + " argument" + (hi > 1 ? "s" : ""));
    };
    auto viaHelper = [&](const std::string& h) {
      helper(h);
      put(h);
      args(n);
    };
    if (b == "len") {
      need(1, 1);
      const Ty t = typeOf(*n.kids[1]);
      if (t == Ty::Str || t == Ty::List) {
        put("#");
        return expr(*n.kids[1], 100);
      }
      return viaHelper("py_len");
    }
    if (b == "abs") {
      need(1, 1);
      put("math.abs");
      return args(n);
    }
    if (b == "min" || b == "max") {
      if (argc == 0) refuse(n, b + "() needs arguments");
      bool nums = argc >= 2;
      for (std::size_t i = 1; i < n.kids.size(); ++i) nums = nums && isNum(typeOf(*n.kids[i]));
      if (nums) {
        put("math." + b);
        return args(n);
      }
      return viaHelper("py_" + b);
    }
    if (b == "int") { need(1, 1); return viaHelper("py_int"); }
    if (b == "float") { need(1, 1); return viaHelper("py_float"); }
    if (b == "str") {
      need(1, 1);
      if (typeOf(*n.kids[1]) == Ty::Str) return expr(*n.kids[1]);
      return viaHelper("py_str");
    }
    if (b == "repr") { need(1, 1); return viaHelper("py_repr"); }
    if (b == "bool") { need(1, 1); return viaHelper("py_truth"); }
    if (b == "round") { need(1, 2); return viaHelper("py_round"); }
    if (b == "range") { need(1, 3); return viaHelper("py_range"); }
    if (b == "list" || b == "tuple") { need(0, 1); return viaHelper("py_list"); }
    if (b == "sorted") { need(1, 1); return viaHelper("py_sorted"); }
    if (b == "sum") { need(1, 2); return viaHelper("py_sum"); }
    if (b == "pow") {
      need(2, 2);
      return viaHelper("py_pow");
    }
    refuse(n, b + "() is only supported as the iterable of a for loop");
  }

  void methodCall(const Node& n) {
    const Node& f = *n.kids[0];
    const Node& obj = *f.kids[0];
    const std::string& m = f.text;
    if (isMathModule(obj)) return mathCall(n, m);
    if (obj.kind == K::Name && foreign_.count(obj.text) && !assigned(obj.text))
      refuse(n, "code_aster's Python API (" + obj.text + "." + m + ") is not supported");
    const std::size_t argc = n.kids.size() - 1;
    if (hasUnpacking(n)) refuse(n, "** argument unpacking is only supported in command calls");
    if (m == "format") {
      helper("py_fmt");
      put("py_fmt(");
      expr(obj);
      put(", {");
      bool first = true;
      for (std::size_t i = 1; i < n.kids.size(); ++i) {
        if (n.kids[i]->kind == K::Keyword) continue;
        if (!first) put(", ");
        first = false;
        expr(*n.kids[i]);
      }
      put("}");
      if (hasKeywords(n)) {
        put(", ");
        keywordsOnly(n);
      }
      return put(")");
    }
    noKeywords(n, "." + m + "()");
    auto plain = [&](const std::string& h, std::size_t lo, std::size_t hi) {
      if (argc < lo || argc > hi) refuse(n, "." + m + "() with " + std::to_string(argc) + " arguments is not supported");
      if (h.rfind("py_", 0) == 0) helper(h);
      put(h + "(");
      expr(obj);
      for (std::size_t i = 1; i < n.kids.size(); ++i) {
        put(", ");
        expr(*n.kids[i]);
      }
      put(")");
    };
    if (m == "join") return plain("py_join", 1, 1);
    if (m == "upper") return plain("string.upper", 0, 0);
    if (m == "lower") return plain("string.lower", 0, 0);
    if (m == "strip") return plain("py_strip", 0, 0);
    if (m == "split") return plain("py_split", 0, 1);
    if (m == "replace") return plain("py_replace", 2, 2);
    if (m == "startswith") return plain("py_startswith", 1, 1);
    if (m == "endswith") return plain("py_endswith", 1, 1);
    if (m == "extend") return plain("py_extend", 1, 1);
    if (m == "append") {
      if (argc != 1) refuse(n, ".append() takes one argument");
      put("table.insert(");
      expr(obj);
      put(", ");
      expr(*n.kids[1]);
      return put(")");
    }
    refuse(n, "the method ." + m + "() is not supported");
  }
  void keywordsOnly(const Node& call) {
    put("{");
    bool first = true;
    for (std::size_t i = 1; i < call.kids.size(); ++i) {
      const Node& kw = *call.kids[i];
      if (kw.kind != K::Keyword) continue;
      if (!first) put(", ");
      first = false;
      put(key(kw.text) + " = ");
      expr(*kw.kids[0]);
    }
    put("}");
  }

  // ---------------------------------------------------------------- statements
  void block(const Node& b) {
    blocks_.emplace_back(&b, 0);
    for (std::size_t i = 0; i < b.kids.size(); ++i) {
      blocks_.back().second = i;
      statement(*b.kids[i], i + 1 == b.kids.size());
    }
    blocks_.pop_back();
  }
  void statement(const Node& s, bool last) {
    at(s.line);
    switch (s.kind) {
      case K::ExprStmt: return expressionStatement(s);
      case K::Assign: return assign(s);
      case K::AugAssign: return augAssign(s);
      case K::If: return ifStatement(s, false);
      case K::While: {
        put("while ");
        cond(*s.kids[0]);
        put(" do");
        loopBody(*s.kids[1]);
        return;
      }
      case K::For: return forStatement(s);
      case K::Def: return def(s);
      case K::Return: {
        if (!scope_->function) refuse(s, "return outside a function");
        put(last ? "return" : "do return");
        if (!s.kids.empty()) {
          put(" ");
          expr(*s.kids[0]);
        }
        if (!last) put(" end");
        return;
      }
      case K::Break:
        if (loops_.empty()) refuse(s, "break outside a loop");
        return put("break");
      case K::Continue:
        if (loops_.empty()) refuse(s, "continue outside a loop");
        loops_.back().hasContinue = true;
        return put("goto continue");
      case K::Pass: return;
      case K::Del:
        for (const auto& t : s.kids) {
          if (t->kind != K::Name) refuse(*t, "del of anything but a name is not supported");
          put(rename(t->text) + " = nil");
        }
        return;
      case K::Assert:
        put("assert(");
        cond(*s.kids[0]);
        if (s.kids.size() > 1) {
          put(", ");
          expr(*s.kids[1]);
        }
        return put(")");
      case K::Block:  // the handler of try: import ... except ImportError:
        at(s.line);
        put("do");
        block(s);
        return put("end");
      case K::Import: case K::ImportFrom:
        if (scope_->function) refuse(s, "imports inside a function are not supported");
        return;
      default: refuse(s, "this statement is not supported");
    }
  }

  void expressionStatement(const Node& s) {
    const Node& e = *s.kids[0];
    if (e.kind == K::String) {  // a docstring (or a string used as a block comment): its lines as comments
      const int last = std::min(lastLine(e), static_cast<int>(src_.size()));
      for (int l = e.line; l <= last; ++l) {
        const std::string& text = src_[l - 1];
        if (text.find_first_not_of(" \t") != std::string::npos) comments_[l] = " " + text;
      }
      return;
    }
    if (e.kind == K::Call && callIsLuaCall(e)) return expr(e);
    put("local _ = ");
    expr(e);
  }

  void assignTarget(const Node& t) {
    at(t.line);
    if (t.kind == K::Name) {
      if (foreign_.count(t.text) || mathModules_.count(t.text))
        refuse(t, "assigning to the imported name " + t.text + " is not supported");
      return put(rename(t.text));
    }
    if (t.kind == K::Attribute) return attribute(t);
    if (t.kind == K::Subscript) {
      const Node& obj = *t.kids[0];
      const Node& idx = *t.kids[1];
      if (idx.kind == K::Slice) refuse(t, "slice assignment is not supported");
      const Ty ot = typeOf(obj);
      if (idx.kind == K::String || ot == Ty::Dict) {
        prefix(obj);
        if (idx.kind == K::String) {
          const std::string k = key(idx.text);
          return put(k[0] == '[' ? k : "." + k);
        }
        put("[");
        expr(idx);
        return put("]");
      }
      if (ot == Ty::List && (typeOf(idx) == Ty::Index)) {
        prefix(obj);
        put("[");
        if (idx.kind == K::Number) {
          put(std::to_string(std::stoll(idx.text) + 1));
        } else {
          expr(idx, 6);
          put(" + 1");
        }
        return put("]");
      }
      refuse(t, "assignment to an element whose index may be negative or a string's (use a non-negative index on a list)");
    }
    refuse(t, "this expression cannot be assigned to");
  }
  // Assignments through py_set: an element of an unknown container or with any index.
  bool needsSet(const Node& t) const {
    if (t.kind != K::Subscript || t.kids[1]->kind == K::Slice) return false;
    const Ty ot = typeOf(*t.kids[0]);
    if (t.kids[1]->kind == K::String || ot == Ty::Dict) return false;
    return !(ot == Ty::List && typeOf(*t.kids[1]) == Ty::Index);
  }

  void assign(const Node& s) {
    const Node& value = *s.kids.back();
    const std::size_t targets = s.kids.size() - 1;
    if (targets > 1) {
      for (std::size_t i = 0; i < targets; ++i)
        if (s.kids[i]->kind != K::Name) refuse(s, "chained assignment to anything but names is not supported");
      assignOne(*s.kids[targets - 1], value);
      for (std::size_t i = 0; i + 1 < targets; ++i) put(" " + rename(s.kids[i]->text) + " = " + rename(s.kids[targets - 1]->text));
      return;
    }
    assignOne(*s.kids[0], value);
  }
  void assignOne(const Node& t, const Node& value) {
    if (needsSet(t)) {
      helper("py_set");
      put("py_set(");
      expr(*t.kids[0]);
      put(", ");
      expr(*t.kids[1]);
      put(", ");
      expr(value);
      return put(")");
    }
    if (t.kind == K::Tuple || t.kind == K::List) {
      for (std::size_t i = 0; i < t.kids.size(); ++i) {
        if (needsSet(*t.kids[i])) refuse(*t.kids[i], "unpacking into an element with a computed index is not supported");
        if (i) put(", ");
        assignTarget(*t.kids[i]);
      }
      put(" = ");
      if ((value.kind == K::Tuple || value.kind == K::List) ) {
        if (value.kids.size() != t.kids.size()) refuse(value, "unpacking " + std::to_string(value.kids.size()) + " values into " + std::to_string(t.kids.size()) + " names");
        return list(value.kids);
      }
      put("table.unpack(");
      expr(value);
      return put(")");
    }
    assignTarget(t);
    put(" = ");
    expr(value);
  }

  void augAssign(const Node& s) {
    const Node& t = *s.kids[0];
    if (t.kind != K::Name && !(t.kind == K::Subscript && !needsSet(t)) && t.kind != K::Attribute)
      refuse(s, "augmented assignment to an element with a computed index is not supported");
    // t op= v is t = t op v: the target read once more (a name or a plain element).
    Node op(K::BinOp, s.line);
    op.text = s.text;
    op.kids.push_back(clone(t));
    op.kids.push_back(clone(*s.kids[1]));
    assignTarget(t);
    put(" = ");
    expr(op);
  }
  static NodePtr clone(const Node& n) {
    auto c = std::make_unique<Node>(n.kind, n.line);
    c->text = n.text;
    c->isFloat = n.isFloat;
    c->pieces = n.pieces;
    c->names = n.names;
    c->names2 = n.names2;
    for (const auto& k : n.kids) c->kids.push_back(k ? clone(*k) : nullptr);
    return c;
  }

  static int lastLine(const Node& n) {
    int last = n.line;
    for (const auto& p : n.pieces) last = std::max(last, p.line);
    for (const auto& k : n.kids)
      if (k) last = std::max(last, lastLine(*k));
    return last;
  }
  // `if flag:` where every assignment of flag is False (sympy_available after
  // try: import sympy ... except ImportError): the block never runs, so it is kept
  // as comments, untranslated.
  bool neverRuns(const Node& condition) const {
    if (condition.kind != K::Name || scope_->function) return false;
    const auto f = module_.onlyFalse.find(condition.text);
    return f != module_.onlyFalse.end() && f->second;
  }

  void ifStatement(const Node& s, bool elif) {
    put(elif ? "elseif " : "if ");
    cond(*s.kids[0]);
    put(" then");
    if (neverRuns(*s.kids[0]) && !s.kids[1]->kids.empty()) {
      const int first = s.kids[1]->kids.front()->line;
      const int last = lastLine(*s.kids[1]);
      for (int l = first; l <= last && l <= static_cast<int>(src_.size()); ++l) {
        const std::string& text = src_[l - 1];
        if (text.find_first_not_of(" \t") == std::string::npos) continue;
        comments_[l] = " " + text;
      }
    } else {
      block(*s.kids[1]);
    }
    if (s.kids.size() > 2) {
      const Node& e = *s.kids[2];
      if (e.kind == K::If) {
        at(e.line);
        return ifStatement(e, true);
      }
      at(e.line);
      put("else");
      block(e);
    }
    put("end");
  }

  void loopBody(const Node& body, const std::string& prologue = "") {
    loops_.push_back(Loop{});
    const bool hasContinue = containsContinue(body);
    if (!prologue.empty()) put(prologue);
    if (hasContinue) put("do");
    block(body);
    if (hasContinue) put("end ::continue::");
    loops_.pop_back();
    put("end");
  }
  static bool containsContinue(const Node& b) {
    for (const auto& s : b.kids) {
      if (s->kind == K::Continue) return true;
      if (s->kind == K::If) {
        const Node* n = s.get();
        while (n) {
          if (containsContinue(*n->kids[1])) return true;
          if (n->kids.size() < 3) break;
          if (n->kids[2]->kind == K::Block) {
            if (containsContinue(*n->kids[2])) return true;
            break;
          }
          n = n->kids[2].get();
        }
      }
    }
    return false;
  }

  static void mentioned(const Node& n, std::size_t index, std::map<std::string, std::size_t>& last) {
    if (n.kind == K::Name) last[n.text] = index;
    for (const auto& k : n.kids)
      if (k) mentioned(*k, index, last);
  }
  // Whether a statement after the one being emitted, in this block or an enclosing one
  // (up to the function's body), names `name`. Each block's last mention of each name
  // is found once, so that many loops in a long file stay linear.
  bool usedAfter(const std::string& name) {
    for (auto b = blocks_.rbegin(); b != blocks_.rend(); ++b) {
      auto it = lastMention_.find(b->first);
      if (it == lastMention_.end()) {
        it = lastMention_.emplace(b->first, std::map<std::string, std::size_t>{}).first;
        for (std::size_t i = 0; i < b->first->kids.size(); ++i) mentioned(*b->first->kids[i], i, it->second);
      }
      const auto m = it->second.find(name);
      if (m != it->second.end() && m->second > b->second) return true;
      if (b->first == functionBody_) break;
    }
    return false;
  }

  void forStatement(const Node& s) {
    const std::string prologue = forHeader(*s.kids[0], *s.kids[1]);
    loopBody(*s.kids[2], prologue);
  }

  // "for ... do" of `for target in it`; returns what the body must start with (unpacking).
  std::string forHeader(const Node& target, const Node& it, bool comprehension = false) {
    // Python's loop variable outlives the loop, Lua's does not: when the code after
    // the loop reads it, the loop runs on a py_loop_ variable copied into it.
    std::string kept;
    auto loopVar = [&](const Node& name) {
      if (comprehension || !usedAfter(name.text)) return rename(name.text);
      kept += " " + rename(name.text) + " = py_loop_" + name.text;
      return "py_loop_" + name.text;
    };
    put("for ");
    if (isRangeCall(it)) {
      if (target.kind != K::Name) refuse(target, "unpacking a range() element");
      noKeywords(it, "range()");
      const std::size_t argc = it.kids.size() - 1;
      if (argc < 1 || argc > 3) refuse(it, "range() takes 1 to 3 arguments");
      const Node* step = argc == 3 ? it.kids[3].get() : nullptr;
      int sign = 1;
      if (step) {
        if (step->kind == K::Number && !step->isFloat && step->text != "0") sign = 1;
        else if (step->kind == K::Unary && step->text == "-" && step->kids[0]->kind == K::Number && !step->kids[0]->isFloat && step->kids[0]->text != "0") sign = -1;
        else sign = 0;
      }
      if (sign == 0) {  // step known only at run time
        helper("py_range");
        put("_, " + loopVar(target) + " in ipairs(py_range");
        args(it);
        put(") do");
        return kept;
      }
      put(loopVar(target) + " = ");
      if (argc == 1) put("0");
      else expr(*it.kids[1]);
      put(", ");
      const Node& stop = argc == 1 ? *it.kids[1] : *it.kids[2];
      // Python's end is exclusive: the last value is stop - 1 (stop + 1 going down).
      if (stop.kind == K::Number && !stop.isFloat) {
        at(stop.line);
        put(std::to_string(std::stoll(stop.text) - sign));
      } else {
        expr(stop, 7);
        put(sign > 0 ? " - 1" : " + 1");
      }
      if (step) {
        put(", ");
        expr(*step);
      }
      put(" do");
      return kept;
    }
    if (it.kind == K::Call && it.kids[0]->kind == K::Name && !assigned(it.kids[0]->text) &&
        (it.kids[0]->text == "enumerate" || it.kids[0]->text == "zip")) {
      const std::string& h = it.kids[0]->text;
      noKeywords(it, h + "()");
      if (target.kind != K::Tuple) refuse(target, "for over " + h + "() needs one name per value");
      for (std::size_t i = 0; i < target.kids.size(); ++i) {
        if (i) put(", ");
        put(loopVar(*target.kids[i]));
      }
      if (h == "enumerate" && target.kids.size() != 2) refuse(target, "for over enumerate() needs two names");
      helper("py_" + h);
      put(" in py_" + h);
      args(it);
      put(" do");
      return kept;
    }
    if (it.kind == K::Call && it.kids[0]->kind == K::Attribute &&
        (it.kids[0]->text == "items" || it.kids[0]->text == "keys" || it.kids[0]->text == "values"))
      refuse(it, "iteration over a dict is not supported (its order is not kept in Lua)");
    const bool knownList = it.kind == K::Tuple || it.kind == K::List || typeOf(it) == Ty::List;
    std::string prologue;
    if (target.kind == K::Name) {
      put("_, " + loopVar(target) + " in ");
    } else {
      put("_, py_item in ");
      bool outlives = false;
      for (const auto& k : target.kids) outlives = outlives || (!comprehension && usedAfter(k->text));
      prologue = outlives ? " " : " local ";
      for (std::size_t i = 0; i < target.kids.size(); ++i) prologue += (i ? ", " : "") + rename(target.kids[i]->text);
      prologue += " = table.unpack(py_item)";
    }
    if (knownList) {
      put("ipairs(");
      expr(it);
      put(")");
    } else {
      helper("py_iter");
      put("py_iter(");
      expr(it);
      put(")");
    }
    put(" do");
    return prologue + kept;
  }

  void def(const Node& s) {
    Scope scope;
    scope.function = true;
    scope.parent = scope_;
    for (const auto& p : s.names) scope.params.insert(p);
    const Node& body = *s.kids[0];
    infer(body, scope);
    std::string params;
    for (std::size_t i = 0; i < s.names.size(); ++i) params += (i ? ", " : "") + rename(s.names[i]);
    if (scope_->function) put(rename(s.text) + " = function(" + params + ")");
    else put("function " + rename(s.text) + "(" + params + ")");
    // Python's locals are the function's: declared at its top, whatever block assigns them.
    std::vector<std::string> locals;
    for (const auto& [name, _] : scope.types)
      if (!scope.params.count(name)) locals.push_back(rename(name));
    if (!locals.empty()) {
      std::string decl = " local ";
      for (std::size_t i = 0; i < locals.size(); ++i) decl += (i ? ", " : "") + locals[i];
      put(decl);
    }
    Scope* saved = scope_;
    scope_ = &scope;
    const Node* savedBody = functionBody_;
    functionBody_ = &body;
    std::vector<Loop> outerLoops;
    outerLoops.swap(loops_);
    for (std::size_t i = 0; i < s.names.size(); ++i) {
      const Node* d = s.kids[1 + i].get();
      if (!d) continue;
      put(" if " + rename(s.names[i]) + " == nil then " + rename(s.names[i]) + " = ");
      expr(*d);
      put(" end");
    }
    block(body);
    put("end");
    loops_.swap(outerLoops);
    functionBody_ = savedBody;
    scope_ = saved;
  }

  const std::vector<std::string>& src_;
  std::map<int, std::string> comments_;
  std::vector<std::string> out_;
  int cur_ = 1;
  std::set<std::string> used_;
  std::set<std::string> mathModules_, foreign_;
  std::map<std::string, std::string> bareMath_;  // name in the file -> math function
  Scope module_;
  Scope* scope_ = &module_;
  std::vector<Loop> loops_;
  std::vector<std::pair<const Node*, std::size_t>> blocks_;  // the blocks being emitted, and where
  const Node* functionBody_ = nullptr;                         // the body of the function being emitted
  std::map<const Node*, std::map<std::string, std::size_t>> lastMention_;  // usedAfter's index
};

}  // namespace

std::string emitLua(const Node& file, const std::vector<std::string>& sourceLines,
                    const std::map<int, std::string>& comments) {
  return Emitter(sourceLines, comments).run(file);
}

}  // namespace aster::comm
