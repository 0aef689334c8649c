// Writes the Lua study of a parsed command file, line for line: Lua line N holds
// what source line N held, so messages with file:line point into the .comm.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "comm/ast.hpp"

namespace aster::comm {

// `sourceLines` gives each line's indentation to the output; `comments` are kept
// as Lua comments. Throws TranslateError on what it cannot translate.
std::string emitLua(const Node& file, const std::vector<std::string>& sourceLines,
                    const std::map<int, std::string>& comments);

}  // namespace aster::comm
