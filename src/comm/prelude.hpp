// The run-time helpers a translation calls where Python's meaning depends on a
// type known only when the study runs (string + vs number +, % formatting vs
// modulo, truthiness, 0-based indexing with negative indices...). Each is a
// small Lua function with Python's semantics; only those used are emitted.
#pragma once
#include <set>
#include <string>

namespace aster::comm {

// True when `name` is a helper (so that a Python name never collides with one).
bool isHelperName(const std::string& name);

// The Lua definitions of `used` and of the helpers they call, on one line.
std::string prelude(const std::set<std::string>& used);

}  // namespace aster::comm
