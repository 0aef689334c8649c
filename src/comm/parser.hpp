// Parses the tokens of a command file into a Block of statements. Constructs
// outside the subset (classes, try, comprehensions, lambda...) are refused here
// with their line, by name.
#pragma once
#include "comm/ast.hpp"
#include "comm/lexer.hpp"

namespace aster::comm {

// Nesting deeper than this (brackets, operators, blocks) is refused, never a stack overflow.
constexpr int kMaxNesting = 200;

// Throws TranslateError.
NodePtr parse(const LexedFile& file);

}  // namespace aster::comm
