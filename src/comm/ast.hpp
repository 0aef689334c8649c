// The syntax tree of a command file: one node type, its kind says what the
// children are (see the comments on each kind).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "comm/lexer.hpp"

namespace aster::comm {

struct Node;
using NodePtr = std::unique_ptr<Node>;

struct Node {
  enum class Kind {
    // expressions
    Name,       // text
    Number,     // text (Lua-ready), isFloat
    String,     // text (value), pieces
    True, False, None,
    Tuple, List,  // kids: elements
    Dict,       // kids: key, value, key, value...
    Call,       // kids[0] callee, then arguments (Keyword nodes for K=v)
    Keyword,    // text name, kids[0] value
    Attribute,  // kids[0] object, text attribute
    Subscript,  // kids[0] object, kids[1] index or Slice
    Slice,      // kids: lower, upper, step (null when absent)
    BinOp,      // text operator (+ - * / // % **), kids[0..1]
    Unary,      // text (- + not), kids[0]
    BoolOp,     // text (and or), kids[0..1]
    Compare,    // names: operators (< > == != <= >= in notin is isnot), kids: operands
    IfExp,      // kids: value, condition, else value
    ListComp,   // kids: element, target, iterable, condition (optional): [e for t in it if c]
    // statements
    Block,      // kids: statements
    ExprStmt,   // kids[0]
    Assign,     // kids: targets..., value (last)
    AugAssign,  // text operator without '=', kids: target, value
    If,         // kids: condition, body, else (Block or If for elif; may be absent)
    While,      // kids: condition, body
    For,        // kids: target, iterable, body
    Def,        // text name, names parameters, kids: body, then defaults (null for none) per parameter
    Return,     // kids: value (absent for a bare return)
    Break, Continue, Pass,
    Del,        // kids: targets
    Assert,     // kids: condition, message (optional)
    Import,     // names: what it binds (module aliases); text the module
    ImportFrom, // text module, names: imported names ("*" for all), aliases in names2
  };
  Kind kind;
  int line = 0;
  std::string text;
  bool isFloat = false;
  std::vector<StringPiece> pieces;
  std::vector<std::string> names, names2;
  std::vector<NodePtr> kids;

  Node(Kind k, int l) : kind(k), line(l) {}
};

}  // namespace aster::comm
