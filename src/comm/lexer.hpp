// Tokens of the Python subset code_aster command files are written in: names,
// numbers (with Fortran exponents 1.D-3), string literals of every kind, operators,
// and the NEWLINE / INDENT / DEDENT structure. Comments are kept by line.
#pragma once
#include <map>
#include <string>
#include <vector>

namespace aster::comm {

// A piece of a string literal on one source line: a literal spanning lines (triple
// quotes, adjacent literals) is emitted piece by piece to keep the line numbers.
struct StringPiece {
  std::string text;
  int line = 0;
};

struct Token {
  enum class Kind { Name, Number, String, Op, Newline, Indent, Dedent, End };
  Kind kind = Kind::End;
  std::string text;  // name, operator, number as written; a string's whole value
  int line = 0;
  bool isFloat = false;              // Number
  std::vector<StringPiece> pieces;   // String
};

struct LexedFile {
  std::vector<Token> tokens;
  std::map<int, std::string> comments;  // line -> text after '#'
};

// Throws TranslateError on a malformed or refused literal.
LexedFile lex(const std::string& text);

}  // namespace aster::comm
