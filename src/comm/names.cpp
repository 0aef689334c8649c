#include "comm/names.hpp"

namespace aster::comm {

const std::set<std::string> kLuaReserved = {
    "and", "break", "do", "else", "elseif", "end", "false", "for", "function", "goto", "if", "in", "local",
    "nil", "not", "or", "repeat", "return", "then", "true", "until", "while", "table", "string", "ipairs",
    "pairs", "tostring", "tonumber", "select", "error", "setmetatable", "getmetatable", "next", "rawget",
    "rawset", "rawequal", "rawlen", "load", "require", "unpack", "utf8", "coroutine", "debug", "os", "io",
    "package", "_G", "_ENV", "pcall", "xpcall", "collectgarbage", "dofile", "loadfile", "type", "assert", "math"};
const std::set<std::string> kLuaKeywords = {"and", "break", "do", "else", "elseif", "end", "false", "for",
                                            "function", "goto", "if", "in", "local", "nil", "not", "or",
                                            "repeat", "return", "then", "true", "until", "while"};

const std::set<std::string> kBuiltins = {"len", "abs", "min", "max", "int", "float", "str", "round", "print",
                                         "range", "list", "tuple", "sorted", "sum", "bool", "repr", "enumerate",
                                         "zip", "dict", "pow"};
const std::set<std::string> kRefusedCalls = {
    "eval", "exec", "open", "input", "isinstance", "type", "getattr", "setattr", "hasattr", "globals", "locals",
    "vars", "dir", "__import__", "compile", "iter", "next", "map", "filter", "reduce", "set", "frozenset",
    "super", "object", "id", "hash", "callable", "divmod", "reversed", "any", "all", "chr", "ord", "format",
    "complex", "bytes", "bytearray", "hex", "oct", "bin", "help", "exit", "quit", "issubclass", "property",
    "staticmethod", "classmethod", "memoryview", "slice", "ascii", "delattr", "breakpoint"};

const std::map<std::string, MathName>& mathNames() {
  static const std::map<std::string, MathName> m = {
      {"pi", {"math.pi", false}},       {"e", {"math.exp(1)", false}},      {"inf", {"math.huge", false}},
      {"tau", {"(2 * math.pi)", false}}, {"sqrt", {"math.sqrt", true}},     {"sin", {"math.sin", true}},
      {"cos", {"math.cos", true}},       {"tan", {"math.tan", true}},       {"asin", {"math.asin", true}},
      {"acos", {"math.acos", true}},     {"atan", {"math.atan", true}},     {"atan2", {"math.atan", true}},
      {"exp", {"math.exp", true}},       {"log", {"math.log", true}},       {"floor", {"math.floor", true}},
      {"ceil", {"math.ceil", true}},     {"fmod", {"math.fmod", true}},     {"fabs", {"py_fabs", true}},
      {"degrees", {"math.deg", true}},   {"radians", {"math.rad", true}},   {"hypot", {"py_hypot", true}},
      {"sinh", {"py_sinh", true}},       {"cosh", {"py_cosh", true}},       {"tanh", {"py_tanh", true}},
      {"trunc", {"py_int", true}},       {"log10", {"", true}},             {"pow", {"", true}},
  };
  return m;
}

}  // namespace aster::comm
