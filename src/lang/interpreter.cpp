#include "lang/interpreter.hpp"

#include <lua.hpp>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <new>
#include <sstream>

#include "core/interrupt.hpp"
#include "core/messages.hpp"
#include "core/suggest.hpp"
#include "lang/catalogue.hpp"
#include "lang/operators.hpp"
#include "lang/validator.hpp"

// Lua is built as C here: lua_error() longjmps. Every C function below does its
// C++ work in a helper that returns before lua_error is called, so no C++ object
// is alive when the stack unwinds.

namespace aster::lang {

namespace {

// Lua's allocator, wrapped to remember where the study was when an allocation
// failed: Lua's "not enough memory" error carries no position.
struct MemoryWatch {
  lua_Alloc base = nullptr;
  void* baseData = nullptr;
  lua_State* L = nullptr;
  char failedAt[512] = "";  // file:line of the last failure (no std::string: memory is short then)
};

void* watchedAlloc(void* data, void* block, std::size_t oldSize, std::size_t newSize) {
  auto* w = static_cast<MemoryWatch*>(data);
  void* out = w->base(w->baseData, block, oldSize, newSize);
  if (!out && newSize > 0 && w->L) {
    lua_Debug ar;  // "Sl" reads the call stack only, it allocates nothing
    for (int level = 0; lua_getstack(w->L, level, &ar); ++level) {
      if (!lua_getinfo(w->L, "Sl", &ar) || ar.currentline <= 0) continue;
      const char* file = (ar.source && ar.source[0] == '@') ? ar.source + 1 : ar.short_src;
      std::snprintf(w->failedAt, sizeof w->failedAt, "%s:%d", file, ar.currentline);
      break;
    }
  }
  return out;
}

}  // namespace

struct Interpreter::State {
  lua_State* L = nullptr;
  MemoryWatch memory;
  Session* session = nullptr;
  std::shared_ptr<bool> alive = std::make_shared<bool>(true);
  std::map<std::string, std::vector<std::string>> sources;  // lines of each chunk run, by chunk name
};

namespace {

const char* kConceptMeta = "aster.concept";
const char* kNewNameMeta = "aster.co";
const char* kStateKey = "aster.state";

Interpreter::State& stateOf(lua_State* L) {
  lua_getfield(L, LUA_REGISTRYINDEX, kStateKey);
  auto* s = static_cast<Interpreter::State*>(lua_touserdata(L, -1));
  lua_pop(L, 1);
  return *s;
}

struct ConceptBox {
  ConceptPtr ptr;
};
struct NewNameBox {
  std::string name;
};

void pushConcept(lua_State* L, ConceptPtr c) {
  void* mem = lua_newuserdatauv(L, sizeof(ConceptBox), 0);
  new (mem) ConceptBox{std::move(c)};
  luaL_setmetatable(L, kConceptMeta);
}

ConceptBox* toConcept(lua_State* L, int idx) {
  return static_cast<ConceptBox*>(luaL_testudata(L, idx, kConceptMeta));
}

// A study function handed to a kernel (FORMULE{VALE=function(X, Y) ... end}).
class LuaCallable : public ScalarCallable {
 public:
  LuaCallable(lua_State* L, int idx, std::shared_ptr<bool> alive) : L_(L), alive_(std::move(alive)) {
    lua_pushvalue(L, idx);
    ref_ = luaL_ref(L, LUA_REGISTRYINDEX);
  }
  ~LuaCallable() override {
    if (*alive_) luaL_unref(L_, LUA_REGISTRYINDEX, ref_);
  }
  double call(const double* args, int count) const override {
    if (!*alive_) throw Error("the study's Lua function is no longer available");
    lua_rawgeti(L_, LUA_REGISTRYINDEX, ref_);
    for (int i = 0; i < count; ++i) lua_pushnumber(L_, args[i]);
    if (lua_pcall(L_, count, 1, 0) != LUA_OK) {
      std::string msg = "(error object is not a string)";
      if (lua_isstring(L_, -1)) {
        msg = lua_tostring(L_, -1);
      } else if (lua_istable(L_, -1)) {  // an aster-lite error raised inside the function
        lua_getfield(L_, -1, "aster_fatal");
        if (lua_isstring(L_, -1)) {
          msg = lua_tostring(L_, -1);
          if (msg.rfind("<F> <", 0) == 0 && msg.find("> ", 5) != std::string::npos) msg.erase(0, msg.find("> ", 5) + 2);
        }
        lua_pop(L_, 1);
      }
      lua_pop(L_, 1);
      throw Error("the study's Lua function failed: " + msg);
    }
    int isnum = 0;
    const double r = lua_tonumberx(L_, -1, &isnum);
    const std::string got = luaL_typename(L_, -1);
    lua_pop(L_, 1);
    if (!isnum) throw Error("the study's Lua function returned a " + got + ", expected a number");
    return r;
  }

 private:
  lua_State* L_;
  int ref_ = LUA_NOREF;
  std::shared_ptr<bool> alive_;
};

Value toValue(lua_State* L, int idx) {
  switch (lua_type(L, idx)) {
    case LUA_TNUMBER:
      if (lua_isinteger(L, idx)) return Value::ofInteger(lua_tointeger(L, idx));
      return Value::ofReal(lua_tonumber(L, idx));
    case LUA_TSTRING: {  // whole, NUL bytes included: the validator refuses those by keyword name
      std::size_t size = 0;
      const char* text = lua_tolstring(L, idx, &size);
      return Value::ofText(std::string(text, size));
    }
    case LUA_TBOOLEAN: return Value::other(lua_toboolean(L, idx) ? "true" : "false");
    case LUA_TFUNCTION:
      return Value::ofFunction(std::make_shared<LuaCallable>(L, idx, stateOf(L).alive));
    case LUA_TUSERDATA:
      if (auto* box = toConcept(L, idx)) return Value::ofConcept(box->ptr);
      if (auto* co = static_cast<NewNameBox*>(luaL_testudata(L, idx, kNewNameMeta))) return Value::ofNewName(co->name);
      return Value::other("an unknown userdata");
    case LUA_TTABLE: return Value::other("a table");
    default: return Value::other(std::string("a ") + luaL_typename(L, idx));
  }
}

bool isPlainTable(lua_State* L, int idx) { return lua_type(L, idx) == LUA_TTABLE; }

bool hasStringKeys(lua_State* L, int idx) {
  idx = lua_absindex(L, idx);
  lua_pushnil(L);
  while (lua_next(L, idx)) {
    if (lua_type(L, -2) == LUA_TSTRING) {
      lua_pop(L, 2);
      return true;
    }
    lua_pop(L, 1);
  }
  return false;
}

// code_aster's keyword trees are 3 tables deep (the call, a factor keyword, a
// list of its occurrences); a deeper or cyclic table is a mistake, and reading
// it would overflow the Lua and C stacks.
constexpr std::size_t kMaxKeywordDepth = 20;

// The tables being read, outermost first, with their keyword paths.
using OpenTables = std::vector<std::pair<const void*, std::string>>;

Keywords toKeywords(lua_State* L, int idx, const std::string& path, OpenTables& open);

// Fills `kw[key]` from the Lua value at idx: a scalar or list of scalars (simple
// keyword), a table of keywords or a list of them (factor keyword). Raw access
// only: a metamethod could raise a Lua error across these C++ frames.
void addEntry(lua_State* L, int idx, const std::string& key, const std::string& path, Keywords& kw,
              OpenTables& open) {
  idx = lua_absindex(L, idx);
  if (!isPlainTable(L, idx)) {
    kw.setSimple(key, {toValue(L, idx)});
    return;
  }
  const std::string sub = path.empty() ? key : path + "/" + key;
  if (hasStringKeys(L, idx)) {
    kw.setFactor(key, {toKeywords(L, idx, sub, open)});
    return;
  }
  const lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, idx));
  bool allTables = n > 0;
  for (lua_Integer i = 1; i <= n && allTables; ++i) {
    lua_rawgeti(L, idx, i);
    allTables = isPlainTable(L, -1);
    lua_pop(L, 1);
  }
  if (allTables) {
    std::vector<Keywords> occ;
    for (lua_Integer i = 1; i <= n; ++i) {
      lua_rawgeti(L, idx, i);
      occ.push_back(toKeywords(L, -1, sub + "[" + std::to_string(i) + "]", open));
      lua_pop(L, 1);
    }
    kw.setFactor(key, std::move(occ));
    return;
  }
  std::vector<Value> vals;
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_rawgeti(L, idx, i);
    vals.push_back(toValue(L, -1));
    lua_pop(L, 1);
  }
  kw.setSimple(key, std::move(vals));
}

Keywords toKeywords(lua_State* L, int idx, const std::string& path, OpenTables& open) {
  idx = lua_absindex(L, idx);
  const std::string where = path.empty() ? std::string("the command's table") : "keyword " + path;
  const void* self = lua_topointer(L, idx);
  for (const auto& [table, name] : open)
    if (table == self)
      throw ValidationError(path, where + " is " + (name.empty() ? std::string("the command's table") : name) +
                                      " again: a table of keywords cannot contain itself");
  if (open.size() >= kMaxKeywordDepth)
    throw ValidationError(path, where + " is nested " + std::to_string(open.size()) +
                                    " tables deep; a command's keywords are at most 3 deep");
  // A few slots per level stay on the Lua stack while the levels below are read.
  if (!lua_checkstack(L, 8)) throw ValidationError(path, where + ": the Lua stack is full");
  open.emplace_back(self, path);
  // Sorted keys: Lua's traversal order varies between runs, messages must not.
  std::vector<std::string> keys;
  lua_pushnil(L);
  while (lua_next(L, idx)) {
    if (lua_type(L, -2) != LUA_TSTRING) {
      lua_pop(L, 2);
      throw ValidationError(path, "expected KEYWORD = value entries" +
                                      (path.empty() ? std::string() : " in " + path) +
                                      ", got a value without a keyword name (a list where a table of keywords "
                                      "was expected?)");
    }
    std::size_t size = 0;
    const char* key = lua_tolstring(L, -2, &size);
    keys.emplace_back(key, size);
    if (keys.back().find('\0') != std::string::npos)
      throw ValidationError(path, "keyword name '" + visibleText(keys.back()) + "'" +
                                      (path.empty() ? std::string() : " in " + path) +
                                      " contains a NUL byte ('\\0')");
    lua_pop(L, 1);
  }
  std::sort(keys.begin(), keys.end());
  Keywords kw;
  kw.path = path;
  for (const auto& k : keys) {
    lua_pushlstring(L, k.data(), k.size());
    lua_rawget(L, idx);
    addEntry(L, -1, k, path, kw, open);
    lua_pop(L, 1);
  }
  open.pop_back();
  return kw;
}

Keywords toKeywords(lua_State* L, int idx, const std::string& path) {
  OpenTables open;
  return toKeywords(L, idx, path, open);
}

std::string callSite(lua_State* L) {
  lua_Debug ar;
  for (int level = 1; lua_getstack(L, level, &ar); ++level) {
    lua_getinfo(L, "Sl", &ar);
    if (ar.currentline <= 0) continue;
    // The study's path as given (short_src would cut a long path with "...").
    const std::string file = (ar.source && ar.source[0] == '@') ? ar.source + 1 : ar.short_src;
    return file + ":" + std::to_string(ar.currentline);
  }
  return "?";
}

// The variable the command's result is assigned to, read from the calling line
// as code_aster's supervisor reads the .comm file: "RESU = STAT_NON_LINE{" gives
// RESU (also with `local`, or after a `;`); anything else (a table field, an
// argument) gives "". A plain scan, linear in the line's length (std::regex
// recursion overflows the stack on long lines).
std::string assignedName(lua_State* L, const std::string& command) {
  lua_Debug ar;
  if (!lua_getstack(L, 1, &ar) || !lua_getinfo(L, "Sl", &ar) || ar.currentline <= 0 || !ar.source) return "";
  const auto& sources = stateOf(L).sources;
  const auto it = sources.find(ar.source);
  if (it == sources.end() || ar.currentline > static_cast<int>(it->second.size())) return "";
  const std::string& line = it->second[ar.currentline - 1];
  const auto space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  const auto nameChar = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; };
  const std::size_t n = line.size();
  // The first NAME at the start, after a blank or after ';', followed by `= COMMAND {` or `= COMMAND (`.
  for (std::size_t i = 0; i < n; ++i) {
    if (!nameChar(line[i]) || std::isdigit(static_cast<unsigned char>(line[i])) ||
        (i > 0 && line[i - 1] != ';' && !space(line[i - 1])))
      continue;
    std::size_t end = i;
    while (end < n && nameChar(line[end])) ++end;
    std::size_t k = end;
    while (k < n && space(line[k])) ++k;
    if (k == n || line[k] != '=') {
      i = end - 1;  // no name starts inside this one
      continue;
    }
    ++k;
    while (k < n && space(line[k])) ++k;
    if (line.compare(k, command.size(), command) != 0) {
      i = end - 1;
      continue;
    }
    k += command.size();
    while (k < n && space(line[k])) ++k;
    if (k < n && (line[k] == '{' || line[k] == '(')) return line.substr(i, end - i);
    i = end - 1;
  }
  return "";
}

// Error objects carried through lua_error to the top level.
void pushFatal(lua_State* L, const std::string& message) {
  lua_newtable(L);
  lua_pushstring(L, message.c_str());
  lua_setfield(L, -2, "aster_fatal");
}

std::string fatalText(const std::string& command, const std::string& where, const std::string& what) {
  return "<F> <" + command + "> " + where + ": " + what;
}

// Returns the number of results, or -1 with an error object pushed.
int commandImpl(lua_State* L, const CommandSpec& spec) {
  Session& session = *stateOf(L).session;
  const std::string where = callSite(L);
  try {
    Keywords call;
    if (lua_gettop(L) >= 1 && !lua_isnil(L, 1)) {
      if (!lua_istable(L, 1))
        throw ValidationError("", spec.name + " expects a table of keywords: " + spec.name + "{KEY=value, ...}, got " +
                                      toValue(L, 1).describe());
      call = toKeywords(L, 1, "");
    }
    ConceptPtr reuse;
    if (call.has("reuse")) {
      if (spec.reentrant == 'n') throw ValidationError("reuse", spec.name + " does not accept reuse=");
      const Value& r = call.value("reuse");
      if (r.kind != Value::Kind::Concept || std::find(spec.results.begin(), spec.results.end(),
                                                      r.concept->typeName()) == spec.results.end())
        throw ValidationError("reuse", "reuse= expects " + describeTypes(spec.results) + ", got " + r.describe());
      reuse = r.concept;
      call.erase("reuse");
    } else if (spec.reentrant == 'o') {
      throw ValidationError("reuse", spec.name + " modifies an existing concept: give it with reuse=");
    }
    const Keywords valid = validate(spec, call);
    const Operator* op = Operators::instance().find(spec.name);
    if (!op)
      throw Error("the keywords are valid, but " + spec.name + " has no kernel in aster-lite " +
                  std::string(ASTER_VERSION) + " yet; no result is produced");
    // Ctrl-C outside a long computation: the study stops before the next command.
    if (interrupt::requested()) throw Interrupted("interrupted (SIGINT) before " + spec.name);
    session.where = where;
    session.command = spec.name;
    session.assignedName = assignedName(L, spec.name);
    session.produced.clear();
    ConceptPtr result = (*op)(valid, session, reuse);
    for (auto& [name, concept] : session.produced) {
      pushConcept(L, concept);
      lua_setglobal(L, name.c_str());
    }
    session.produced.clear();
    if (!result) {
      if (spec.kind == CommandSpec::Kind::Oper) throw Error("internal error: the operator returned no concept");
      return 0;
    }
    if (std::find(spec.results.begin(), spec.results.end(), result->typeName()) == spec.results.end())
      throw Error("internal error: the operator returned a " + result->typeName() + ", the catalogue says " +
                  describeTypes(spec.results));
    pushConcept(L, std::move(result));
    return 1;
  } catch (const ValidationError& e) {
    pushFatal(L, fatalText(spec.name, where, e.what()));
  } catch (const Interrupted& e) {
    pushFatal(L, fatalText(spec.name, where, e.what()));
    lua_pushboolean(L, 1);
    lua_setfield(L, -2, "aster_interrupted");
  } catch (const Error& e) {
    pushFatal(L, fatalText(spec.name, where, e.what()));
  } catch (const StudyFinished&) {
    lua_newtable(L);
    lua_pushboolean(L, 1);
    lua_setfield(L, -2, "aster_fin");
  } catch (const std::bad_alloc&) {
    pushFatal(L, fatalText(spec.name, where, "not enough memory (the command asks for more than the system gives it)"));
  } catch (const std::exception& e) {
    pushFatal(L, fatalText(spec.name, where, std::string("internal error: ") + e.what()));
  }
  return -1;
}

int callCommand(lua_State* L) {
  const auto* spec = static_cast<const CommandSpec*>(lua_touserdata(L, lua_upvalueindex(1)));
  const int n = commandImpl(L, *spec);
  if (n < 0) return lua_error(L);
  return n;
}

int callF(lua_State* L) {  // _F{...} as in code_aster: a factor keyword occurrence
  luaL_checktype(L, 1, LUA_TTABLE);
  lua_settop(L, 1);
  return 1;
}

// Returns 1 with the new name pushed, or -1 with an error object pushed.
int coImpl(lua_State* L) {
  std::size_t size = 0;
  const char* text = lua_tolstring(L, 1, &size);
  std::string name = text ? std::string(text, size) : std::string();
  if (!text || name.find('\0') != std::string::npos) {
    pushFatal(L, fatalText("CO", callSite(L),
                           text ? "the name '" + visibleText(name) + "' contains a NUL byte ('\\0')"
                                : "CO expects the name of the concept to create, CO('NAME'), got " +
                                      toValue(L, 1).describe()));
    return -1;
  }
  void* mem = lua_newuserdatauv(L, sizeof(NewNameBox), 0);
  new (mem) NewNameBox{std::move(name)};
  luaL_setmetatable(L, kNewNameMeta);
  return 1;
}

int callCO(lua_State* L) {  // CO('name'): a concept a macro-command will create
  if (coImpl(L) < 0) return lua_error(L);
  return 1;
}

template <class Box>
int collect(lua_State* L) {
  static_cast<Box*>(lua_touserdata(L, 1))->~Box();
  return 0;
}

void pushDatum(lua_State* L, const Datum& d) {
  switch (d.kind) {
    case Datum::Kind::Nil: lua_pushnil(L); break;
    case Datum::Kind::Integer: lua_pushinteger(L, d.integer); break;
    case Datum::Kind::Real: lua_pushnumber(L, d.real); break;
    case Datum::Kind::Text: lua_pushlstring(L, d.text.data(), d.text.size()); break;
    case Datum::Kind::Boolean: lua_pushboolean(L, d.boolean); break;
    case Datum::Kind::Concept: pushConcept(L, d.concept); break;
    case Datum::Kind::List:
      lua_createtable(L, static_cast<int>(d.list.size()), 0);
      for (std::size_t i = 0; i < d.list.size(); ++i) {
        pushDatum(L, d.list[i]);
        lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
      }
      break;
    case Datum::Kind::Map:
      lua_createtable(L, 0, static_cast<int>(d.map.size()));
      for (const auto& [k, v] : d.map) {
        pushDatum(L, v);
        lua_setfield(L, -2, k.c_str());
      }
      break;
  }
}

std::string conceptLabel(lua_State* L, const Concept& c) {
  return stateOf(L).session->nameOf(c);
}

// Calls a registered method; self is argument 1 (mesh:getNumberOfNodes()).
int methodImpl(lua_State* L, const std::string& method) {
  ConceptBox* self = toConcept(L, 1);
  const std::string where = callSite(L);
  try {
    if (!self) throw Error("method " + method + " must be called with ':' (object:" + method + "(...))");
    const Method* m = Operators::instance().findMethod(self->ptr->typeName(), method);
    if (!m) throw Error("internal error: method " + method + " vanished");
    std::vector<Value> args;
    for (int i = 2; i <= lua_gettop(L); ++i) {
      args.push_back(toValue(L, i));
      if (args.back().kind == Value::Kind::Text && args.back().text.find('\0') != std::string::npos)
        throw Error("argument " + std::to_string(i - 1) + " = " + args.back().describe() +
                    " contains a NUL byte ('\\0')");
    }
    Datum d = (*m)(*self->ptr, args, *stateOf(L).session);
    pushDatum(L, d);
    return 1;
  } catch (const std::exception& e) {
    pushFatal(L, fatalText(self ? conceptLabel(L, *self->ptr) + ":" + method : method, where, e.what()));
  }
  return -1;
}

int callMethod(lua_State* L) {
  const char* name = lua_tostring(L, lua_upvalueindex(1));
  const int n = methodImpl(L, name);
  if (n < 0) return lua_error(L);
  return n;
}

int conceptIndexImpl(lua_State* L) {
  ConceptBox* self = toConcept(L, 1);
  const char* key = lua_tostring(L, 2);
  const std::string type = self->ptr->typeName();
  if (key && Operators::instance().findMethod(type, key)) {
    lua_pushstring(L, key);
    lua_pushcclosure(L, callMethod, 1);
    return 1;
  }
  const std::string name = key ? key : "?";
  if (const FieldGetter* getter = Operators::instance().findFieldGetter(type)) {
    Datum d = (*getter)(*self->ptr, name);
    if (d.kind != Datum::Kind::Nil) {
      pushDatum(L, d);
      return 1;
    }
  }
  auto methods = Operators::instance().methodNames(type);
  methods.erase(std::remove(methods.begin(), methods.end(), std::string("__call")), methods.end());
  pushFatal(L, fatalText(conceptLabel(L, *self->ptr), callSite(L),
                         "a " + type + " has no method '" + name + "'" +
                             (didYouMean(name, methods).empty() ? "" : ";" + didYouMean(name, methods)) +
                             " (methods: " + (methods.empty() ? std::string("none") : joinNames(methods)) + ")"));
  return -1;
}

int conceptIndex(lua_State* L) {
  const int n = conceptIndexImpl(L);
  if (n < 0) return lua_error(L);
  return n;
}

int conceptCall(lua_State* L) {  // F(0.3, 0.7): functions are callable
  const int n = methodImpl(L, "__call");
  if (n < 0) return lua_error(L);
  return n;
}

int conceptToString(lua_State* L) {
  ConceptBox* self = toConcept(L, 1);
  const std::string s = "<" + self->ptr->typeName() + " " + conceptLabel(L, *self->ptr) + ">";
  lua_pushstring(L, s.c_str());
  return 1;
}

int conceptEq(lua_State* L) {
  ConceptBox* a = toConcept(L, 1);
  ConceptBox* b = toConcept(L, 2);
  lua_pushboolean(L, a && b && a->ptr == b->ptr);
  return 1;
}

// Reading an undefined global is an error, as a NameError is in a .comm file.
int undefinedGlobalImpl(lua_State* L) {
  const char* key = lua_tostring(L, 2);
  std::vector<std::string> names;
  lua_pushnil(L);
  while (lua_next(L, 1)) {
    if (lua_type(L, -2) == LUA_TSTRING) names.push_back(lua_tostring(L, -2));
    lua_pop(L, 1);
  }
  const std::string name = key ? key : "?";
  pushFatal(L, "<F> <LUA> " + callSite(L) + ": '" + name + "' is not defined" +
                   (didYouMean(name, names).empty() ? std::string(": it is neither a command of the catalogue nor a variable")
                                                    : ";" + didYouMean(name, names)));
  return -1;
}

int undefinedGlobal(lua_State* L) {
  undefinedGlobalImpl(L);
  return lua_error(L);
}

std::string generatedName(const Concept& c) {
  std::ostringstream s;
  s << c.typeName() << "@" << static_cast<const void*>(&c);
  return s.str();
}

}  // namespace

Interpreter::Interpreter(Session& session) : state_(std::make_unique<State>()), session_(session) {
  lua_State* L = luaL_newstate();
  state_->L = L;
  state_->memory.base = lua_getallocf(L, &state_->memory.baseData);
  state_->memory.L = L;
  lua_setallocf(L, watchedAlloc, &state_->memory);
  state_->session = &session;
  luaL_openlibs(L);
  lua_pushlightuserdata(L, state_.get());
  lua_setfield(L, LUA_REGISTRYINDEX, kStateKey);

  luaL_newmetatable(L, kConceptMeta);
  lua_pushcfunction(L, collect<ConceptBox>);
  lua_setfield(L, -2, "__gc");
  lua_pushcfunction(L, conceptIndex);
  lua_setfield(L, -2, "__index");
  lua_pushcfunction(L, conceptCall);
  lua_setfield(L, -2, "__call");
  lua_pushcfunction(L, conceptToString);
  lua_setfield(L, -2, "__tostring");
  lua_pushcfunction(L, conceptEq);
  lua_setfield(L, -2, "__eq");
  lua_pop(L, 1);
  luaL_newmetatable(L, kNewNameMeta);
  lua_pushcfunction(L, collect<NewNameBox>);
  lua_setfield(L, -2, "__gc");
  lua_pop(L, 1);

  for (const auto& [name, spec] : Catalogue::builtin().commands()) {
    lua_pushlightuserdata(L, const_cast<CommandSpec*>(&spec));
    lua_pushcclosure(L, callCommand, 1);
    lua_setglobal(L, name.c_str());
  }
  if (!session.unsafeLua) {
    // A study is data, not a program that may run other programs: no shell,
    // no pipes, no binary chunks, no C modules (--unsafe-lua restores them).
    const char* sandbox = R"(
      os.execute, io.popen, package.loadlib = nil, nil, nil
      package.cpath = ''
      table.remove(package.searchers, 4); table.remove(package.searchers, 3)
      local load_, loadfile_ = load, loadfile
      load = function(chunk, name, mode, env) return load_(chunk, name, 't', env) end
      loadfile = function(file, mode, env) return loadfile_(file, 't', env) end
      dofile = function(file)
        local f, err = loadfile_(file, 't'); if not f then error(err, 2) end; return f()
      end
    )";
    if (luaL_dostring(L, sandbox) != LUA_OK) throw Error(std::string("Lua sandbox: ") + lua_tostring(L, -1));
  }
  lua_pushcfunction(L, callF);
  lua_setglobal(L, "_F");
  lua_pushcfunction(L, callCO);
  lua_setglobal(L, "CO");

  lua_pushglobaltable(L);
  lua_newtable(L);
  lua_pushcfunction(L, undefinedGlobal);
  lua_setfield(L, -2, "__index");
  lua_setmetatable(L, -2);
  lua_pop(L, 1);

  // Names come from the study's globals (MAIL = LIRE_MAILLAGE{...} is "MAIL").
  State* st = state_.get();
  session.nameOf = [st](const Concept& c) -> std::string {
    if (!c.name.empty()) return c.name;
    lua_State* L = st->L;
    std::string found;
    lua_pushglobaltable(L);
    lua_pushnil(L);
    while (lua_next(L, -2)) {
      if (lua_type(L, -2) == LUA_TSTRING) {
        if (auto* box = static_cast<ConceptBox*>(luaL_testudata(L, -1, kConceptMeta)))
          if (box->ptr.get() == &c) found = lua_tostring(L, -2);
      }
      lua_pop(L, 1);
    }
    lua_pop(L, 1);
    return found.empty() ? generatedName(c) : found;
  };
}

Interpreter::~Interpreter() {
  *state_->alive = false;
  session_.nameOf = [](const Concept& c) { return c.name.empty() ? c.typeName() : c.name; };
  lua_close(state_->L);
}

int Interpreter::runFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    Messages::emit(Severity::Fatal, "aster-lite", "cannot open the study file " + path);
    return 2;
  }
  std::stringstream text;
  text << in.rdbuf();
  return runString(text.str(), "@" + path);
}

// DEBUT and FIN are optional, as the catalogue of issue 2 wants: a study may
// end with its last command.
int Interpreter::runString(const std::string& code, const std::string& chunkName) {
  lua_State* L = state_->L;
  auto& lines = state_->sources[chunkName];
  lines.clear();  // a chunk run again under the same name is read afresh
  std::istringstream text(code);
  for (std::string line; std::getline(text, line);) lines.push_back(line);
  int status = luaL_loadbuffer(L, code.data(), code.size(), chunkName.c_str());
  if (status == LUA_OK) status = lua_pcall(L, 0, 0, 0);
  if (status == LUA_OK) return finish(0);

  std::string message;
  bool finished = false, interrupted = false;
  if (status == LUA_ERRMEM) {
    const std::string at = *state_->memory.failedAt ? state_->memory.failedAt
                                                    : chunkName.substr(chunkName.rfind('@', 0) == 0 ? 1 : 0);
    message = "<F> <LUA> " + at + ": not enough memory (the study asks for more than the system gives it)";
  } else if (lua_istable(L, -1)) {
    lua_getfield(L, -1, "aster_fin");
    finished = lua_toboolean(L, -1);
    lua_pop(L, 1);
    lua_getfield(L, -1, "aster_interrupted");
    interrupted = lua_toboolean(L, -1);
    lua_pop(L, 1);
    lua_getfield(L, -1, "aster_fatal");
    if (lua_isstring(L, -1)) message = lua_tostring(L, -1);
    lua_pop(L, 1);
  } else if (lua_isstring(L, -1)) {
    message = std::string("<F> <LUA> ") + lua_tostring(L, -1);
  } else {
    message = "<F> <LUA> a Lua error without a message";
  }
  lua_pop(L, 1);
  if (finished) return finish(0);
  std::fflush(stdout);
  std::fprintf(stderr, "%s\n", message.c_str());
  std::fflush(stderr);
  return finish(interrupted ? kInterruptedStatus : 2);
}

int Interpreter::finish(int status) {
  if (!session_.plots.empty() && session_.drawPlots) {
    const auto failures = session_.drawPlots(session_.plots);
    session_.plots.clear();
    std::fflush(stdout);
    for (const auto& f : failures) std::fprintf(stderr, "%s\n", f.c_str());
    std::fflush(stderr);
    if (!failures.empty() && status == 0) status = 2;
  }
  const std::string summary = session_.recordCheckSummary();
  if (!summary.empty()) Messages::info(summary);
  if (status == 0 && session_.checksNook > 0) return 1;
  return status;
}

}  // namespace aster::lang
