// The names a translation knows: Lua's reserved words and globals (a Python name
// equal to one is renamed), Python's built-ins it maps or refuses, and math's
// functions with their Lua counterparts.
#pragma once
#include <map>
#include <set>
#include <string>

namespace aster::comm {

// Lua's names that Python may use freely: keywords and the globals a translation calls.
extern const std::set<std::string> kLuaReserved;
extern const std::set<std::string> kLuaKeywords;
// Python's built-in functions the translation maps; kRefusedCalls are refused by name.
extern const std::set<std::string> kBuiltins;
extern const std::set<std::string> kRefusedCalls;

// math: Lua's name when it has one, else a helper or a Lua expression.
struct MathName {
  const char* lua;
  bool call;  // a function (else a constant)
};
const std::map<std::string, MathName>& mathNames();

}  // namespace aster::comm
