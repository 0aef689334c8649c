#include "lang/interpreter.hpp"

#include <lua.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <set>
#include <new>
#include <sstream>
#include <thread>
#include <type_traits>

#include "core/interrupt.hpp"
#include "core/messages.hpp"
#include "comm/translate.hpp"
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
  std::map<std::string, std::string> destroyed;  // variable unbound by DETRUIRE -> where
  // CO('name') boxes are numbered; a macro that makes the concept of a name
  // records it here with the last number given, so that a box made before
  // (code_aster's idiom: MA[1] = CO('MA_1'), the macro, then MA[1] used) stands
  // for the concept from then on.
  std::uint64_t newNameSerial = 0;
  std::map<std::string, std::pair<std::uint64_t, std::weak_ptr<Concept>>> madeForName;

  // Every <F> raised during the run, in order (the first kKeptFatals): one the
  // study catches (pcall, a coroutine) still ends the run with exit status 2.
  std::vector<std::string> fatals;
  std::size_t fatalCount = 0;
  // A stop the study cannot catch: FIN or os.exit() (Finish), os.exit(failure)
  // (Abort), Ctrl-C (Interrupt). Once set, the hook raises it again at every
  // instruction until the study is unwound.
  enum class Stop { None, Finish, Abort, Interrupt } stop = Stop::None;
  std::string stopMessage;  // the <F> of an Abort or an Interrupt
  // Sandbox: files the study's Lua code read (its inputs, never written from
  // Lua) and wrote (its own, which it may read back and rewrite), canonical.
  std::set<std::string> readFiles, writtenFiles;
  // Who ends the run: 1 the interpreter, 2 the watchdog (the study stuck after Ctrl-C).
  std::atomic<int> ending{0};
  std::function<void()> endFromWatchdog;
};

namespace {

const char* kConceptMeta = "aster.concept";
const char* kNewNameMeta = "aster.co";
const char* kStateKey = "aster.state";
using State = Interpreter::State;

Interpreter::State& stateOf(lua_State* L) {
  lua_getfield(L, LUA_REGISTRYINDEX, kStateKey);
  auto* s = static_cast<Interpreter::State*>(lua_touserdata(L, -1));
  lua_pop(L, 1);
  return *s;
}

// The userdata behind concepts and CO() names. Their metamethods can be called
// by hand on any value (getmetatable is protected, but --unsafe-lua has
// debug.getmetatable and debug.setmetatable), so a box is trusted only with its
// metatable, its size and a live tag; __gc leaves an empty, dead box behind.
constexpr std::uint32_t kLiveBox = 0x61737472;  // "astr"
struct ConceptBox {
  std::uint32_t tag = 0;
  ConceptPtr ptr;
};
struct NewNameBox {
  std::uint32_t tag = 0;
  std::string name;
  std::uint64_t serial = 0;  // State::newNameSerial when CO made it
};

template <class Box>
Box* liveBox(lua_State* L, int idx, const char* meta) {
  auto* box = static_cast<Box*>(luaL_testudata(L, idx, meta));
  if (!box || lua_rawlen(L, idx) != sizeof(Box) || box->tag != kLiveBox) return nullptr;
  return box;
}

void pushConcept(lua_State* L, ConceptPtr c) {
  void* mem = lua_newuserdatauv(L, sizeof(ConceptBox), 0);
  new (mem) ConceptBox{kLiveBox, std::move(c)};
  luaL_setmetatable(L, kConceptMeta);
}

ConceptBox* toConcept(lua_State* L, int idx) { return liveBox<ConceptBox>(L, idx, kConceptMeta); }

// Throws when the study uses a concept DETRUIRE destroyed.
void checkNotDestroyed(const Concept& c) {
  if (!c.destroyedAt.empty()) throw Error("'" + c.name + "' was destroyed by DETRUIRE at " + c.destroyedAt);
}

// Unbinds the global variables holding c (a local keeps it, marked destroyed);
// the concept's memory goes with the last holder.
void unbindDestroyed(lua_State* L, const Concept& c) {
  std::vector<std::string> names;
  lua_pushglobaltable(L);
  lua_pushnil(L);
  while (lua_next(L, -2)) {
    if (lua_type(L, -2) == LUA_TSTRING)
      if (auto* box = toConcept(L, -1); box && box->ptr.get() == &c) names.push_back(lua_tostring(L, -2));
    lua_pop(L, 1);
  }
  for (const auto& name : names) {
    lua_pushnil(L);
    lua_setfield(L, -2, name.c_str());
    stateOf(L).destroyed[name] = c.destroyedAt;
  }
  lua_pop(L, 1);
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
    const interrupt::Watch watched(true);  // the study's code again, called by a kernel
    lua_rawgeti(L_, LUA_REGISTRYINDEX, ref_);
    for (int i = 0; i < count; ++i) lua_pushnumber(L_, args[i]);
    if (lua_pcall(L_, count, 1, 0) != LUA_OK) {
      std::string msg = "(error object is not a string)";
      bool interrupted = false, finished = false;
      if (lua_isstring(L_, -1)) {
        msg = lua_tostring(L_, -1);
      } else if (lua_istable(L_, -1)) {  // an aster-lite error raised inside the function
        lua_getfield(L_, -1, "aster_interrupted");
        interrupted = lua_toboolean(L_, -1);
        lua_getfield(L_, -2, "aster_fin");
        finished = lua_toboolean(L_, -1);
        lua_getfield(L_, -3, "aster_fatal");
        if (lua_isstring(L_, -1)) {
          msg = lua_tostring(L_, -1);
          // It goes on as the <F> of the command that called the function, not as one of its own.
          auto& fatals = stateOf(L_).fatals;
          if (!interrupted && !fatals.empty() && fatals.back() == msg) {
            fatals.pop_back();
            --stateOf(L_).fatalCount;
          }
          if (msg.rfind("<F> <", 0) == 0 && msg.find("> ", 5) != std::string::npos) msg.erase(0, msg.find("> ", 5) + 2);
        }
        lua_pop(L_, 3);
      }
      lua_pop(L_, 1);
      if (interrupted) throw Interrupted("interrupted (SIGINT) in the study's Lua function");
      if (finished) throw StudyFinished{};
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
      if (auto* box = toConcept(L, idx)) {
        checkNotDestroyed(*box->ptr);
        return Value::ofConcept(box->ptr);
      }
      if (auto* co = liveBox<NewNameBox>(L, idx, kNewNameMeta)) {
        const auto& made = stateOf(L).madeForName;
        const auto it = made.find(co->name);
        if (it != made.end() && co->serial <= it->second.first)
          if (ConceptPtr c = it->second.second.lock()) {  // the concept a macro made under this name
            checkNotDestroyed(*c);
            return Value::ofConcept(c);
          }
        return Value::ofNewName(co->name);
      }
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

// The study's file:line of the innermost Lua function at or above `level`
// (1: the caller of the C function running; 0 in a hook: the function running).
std::string callSite(lua_State* L, int level = 1) {
  lua_Debug ar;
  for (; lua_getstack(L, level, &ar); ++level) {
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

// Error objects carried through lua_error to the top level. Every <F> is
// recorded: the study may catch it (pcall), the run still ends with exit status 2.
constexpr std::size_t kKeptFatals = 20;
void pushFatal(lua_State* L, const std::string& message) {
  State& st = stateOf(L);
  ++st.fatalCount;
  if (st.fatals.size() < kKeptFatals) st.fatals.push_back(message);
  lua_newtable(L);
  lua_pushstring(L, message.c_str());
  lua_setfield(L, -2, "aster_fatal");
}

State& stateOfThread(lua_State* L) { return **static_cast<State**>(lua_getextraspace(L)); }

constexpr int kHookCount = 1000;  // instructions between two checks of Ctrl-C
void stopHook(lua_State* L, lua_Debug*);

// The stop goes up to the top level: the hook raises it again at the next
// instruction of the running coroutine and of the main thread, whatever
// pcall caught it on the way.
void hurry(lua_State* L) {
  State& st = stateOfThread(L);
  lua_sethook(L, stopHook, LUA_MASKCOUNT, 1);
  if (L != st.L) lua_sethook(st.L, stopHook, LUA_MASKCOUNT, 1);
}

// Pushes the error object of the pending stop (a Ctrl-C not yet seen becomes
// one, with the study's line `level`).
void pushStop(lua_State* L, int level) {
  State& st = stateOfThread(L);
  if (st.stop == State::Stop::None) {
    st.stop = State::Stop::Interrupt;
    st.stopMessage = "<F> <LUA> " + callSite(L, level) + ": interrupted (SIGINT)";
  }
  lua_newtable(L);
  if (st.stop == State::Stop::Finish) {
    lua_pushboolean(L, 1);
    lua_setfield(L, -2, "aster_fin");
  } else {
    lua_pushstring(L, st.stopMessage.c_str());
    lua_setfield(L, -2, "aster_fatal");
    if (st.stop == State::Stop::Interrupt) {
      lua_pushboolean(L, 1);
      lua_setfield(L, -2, "aster_interrupted");
    }
  }
  hurry(L);
}

bool stopPending(lua_State* L) { return stateOfThread(L).stop != State::Stop::None || interrupt::requested(); }

// Every kHookCount instructions (every instruction once a stop is pending).
// Cheap: a flag and a field read when nothing is pending.
void stopHook(lua_State* L, lua_Debug*) {
  if (!stopPending(L)) return;
  pushStop(L, 0);
  lua_error(L);
}

std::string fatalText(const std::string& command, const std::string& where, const std::string& what) {
  return "<F> <" + command + "> " + where + ": " + what;
}

// Returns the number of results, or -1 with an error object pushed.
int commandImpl(lua_State* L, const CommandSpec& spec) {
  Session& session = *stateOf(L).session;
  if (stateOf(L).stop != State::Stop::None) {  // FIN, os.exit or Ctrl-C seen: nothing more runs
    pushStop(L, 1);
    return -1;
  }
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
    ConceptPtr result;
    {
      const interrupt::Watch safe(false);  // kernels stop at their own safe points
      result = (*op)(valid, session, reuse);
    }
    for (auto& [name, concept] : session.produced) {
      pushConcept(L, concept);
      lua_setglobal(L, name.c_str());
      stateOf(L).madeForName[name] = {stateOf(L).newNameSerial, concept};
    }
    session.produced.clear();
    for (const auto& c : session.destroyed) unbindDestroyed(L, *c);
    if (!session.destroyed.empty()) {  // what DETRUIRE is for: free the memory now
      lua_settop(L, 0);                 // the call's own table still holds the concepts
      lua_gc(L, LUA_GCCOLLECT);
    }
    session.destroyed.clear();
    if (!result) {
      if (spec.kind == CommandSpec::Kind::Oper) throw Error("internal error: the operator returned no concept");
      return 0;
    }
    if (std::find(spec.results.begin(), spec.results.end(), result->typeName()) == spec.results.end())
      throw Error("internal error: the operator returned a " + result->typeName() + ", the catalogue says " +
                  describeTypes(spec.results));
    if (result->assignedAs.empty()) result->assignedAs = session.assignedName;
    pushConcept(L, std::move(result));
    return 1;
  } catch (const ValidationError& e) {
    pushFatal(L, fatalText(spec.name, where, e.what()));
  } catch (const Interrupted& e) {
    State& st = stateOf(L);
    st.stop = State::Stop::Interrupt;
    st.stopMessage = fatalText(spec.name, where, e.what());
    pushStop(L, 1);
  } catch (const Error& e) {
    pushFatal(L, fatalText(spec.name, where, e.what()));
  } catch (const StudyFinished&) {
    stateOf(L).stop = State::Stop::Finish;
    pushStop(L, 1);
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
  new (mem) NewNameBox{kLiveBox, std::move(name), ++stateOf(L).newNameSerial};
  luaL_setmetatable(L, kNewNameMeta);
  return 1;
}

int callCO(lua_State* L) {  // CO('name'): a concept a macro-command will create
  if (coImpl(L) < 0) return lua_error(L);
  return 1;
}

// __gc: on anything but a live box of its kind (a second call, a call by hand
// on another value) it does nothing.
template <class Box>
int collect(lua_State* L) {
  const char* meta = std::is_same_v<Box, ConceptBox> ? kConceptMeta : kNewNameMeta;
  if (Box* box = liveBox<Box>(L, 1, meta)) {
    box->~Box();
    new (box) Box{};  // empty and dead: what reads it later finds no concept
  }
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
    checkNotDestroyed(*self->ptr);
    const Method* m = Operators::instance().findMethod(self->ptr->typeName(), method);
    if (!m) throw Error("internal error: method " + method + " vanished");
    std::vector<Value> args;
    for (int i = 2; i <= lua_gettop(L); ++i) {
      args.push_back(toValue(L, i));
      if (args.back().kind == Value::Kind::Text && args.back().text.find('\0') != std::string::npos)
        throw Error("argument " + std::to_string(i - 1) + " = " + args.back().describe() +
                    " contains a NUL byte ('\\0')");
    }
    Datum d;
    {
      const interrupt::Watch safe(false);
      d = (*m)(*self->ptr, args, *stateOf(L).session);
    }
    pushDatum(L, d);
    return 1;
  } catch (const Interrupted& e) {
    State& st = stateOf(L);
    st.stop = State::Stop::Interrupt;
    st.stopMessage = fatalText(self ? conceptLabel(L, *self->ptr) + ":" + method : method, where, e.what());
    pushStop(L, 1);
  } catch (const std::exception& e) {
    pushFatal(L, fatalText(self ? conceptLabel(L, *self->ptr) + ":" + method : method, where, e.what()));
  } catch (const StudyFinished&) {  // FIN in a Lua function the method evaluated
    stateOf(L).stop = State::Stop::Finish;
    pushStop(L, 1);
  }
  return -1;
}

int callMethod(lua_State* L) {
  const char* name = lua_tostring(L, lua_upvalueindex(1));
  const int n = methodImpl(L, name);
  if (n < 0) return lua_error(L);
  return n;
}

// A metamethod called by hand on something else than a live concept.
int pushNotAConcept(lua_State* L, const char* metamethod) {
  pushFatal(L, "<F> <LUA> " + callSite(L) + ": the concepts' " + metamethod + " was called on " +
                   (lua_isuserdata(L, 1) && luaL_testudata(L, 1, kConceptMeta) ? std::string("a released concept")
                                                                               : std::string("a ") + luaL_typename(L, 1)) +
                   ", not on a concept");
  return -1;
}

int conceptIndexImpl(lua_State* L) {
  ConceptBox* self = toConcept(L, 1);
  if (!self) return pushNotAConcept(L, "__index");
  const char* key = lua_tostring(L, 2);
  if (!self->ptr->destroyedAt.empty()) {
    pushFatal(L, fatalText(self->ptr->name, callSite(L),
                           "'" + self->ptr->name + "' was destroyed by DETRUIRE at " + self->ptr->destroyedAt));
    return -1;
  }
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
  const int n = toConcept(L, 1) ? methodImpl(L, "__call") : pushNotAConcept(L, "__call");
  if (n < 0) return lua_error(L);
  return n;
}

int conceptToStringImpl(lua_State* L) {
  ConceptBox* self = toConcept(L, 1);
  if (!self) return pushNotAConcept(L, "__tostring");
  const std::string s = "<" + self->ptr->typeName() + " " + conceptLabel(L, *self->ptr) + ">";
  lua_pushstring(L, s.c_str());
  return 1;
}

int conceptToString(lua_State* L) {
  const int n = conceptToStringImpl(L);
  if (n < 0) return lua_error(L);
  return n;
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
  while (lua_istable(L, 1) && lua_next(L, 1)) {  // (a table: the metamethod can be called by hand)
    if (lua_type(L, -2) == LUA_TSTRING) names.push_back(lua_tostring(L, -2));
    lua_pop(L, 1);
  }
  const std::string name = key ? key : "?";
  const auto& destroyed = stateOf(L).destroyed;
  if (const auto it = destroyed.find(name); it != destroyed.end()) {
    pushFatal(L, "<F> <LUA> " + callSite(L) + ": '" + name + "' was destroyed by DETRUIRE at " + it->second);
    return -1;
  }
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

// ---- The sandbox (docs/manual.md, "What a study may do") ----------------------

namespace fs = std::filesystem;

// Where a path leads: absolute, symbolic links resolved as far as it exists.
fs::path resolved(const fs::path& p) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(p, ec);
  if (ec) return p.lexically_normal();
  const fs::path r = fs::weakly_canonical(absolute, ec);
  return ec ? absolute.lexically_normal() : r;
}

// Files the study reads are its inputs: it may not write them later.
void recordRead(lua_State* L, int arg) {
  if (lua_type(L, arg) != LUA_TSTRING) return;
  try {
    const fs::path file = resolved(lua_tostring(L, arg));
    std::error_code ec;
    if (fs::exists(file, ec)) stateOf(L).readFiles.insert(file.string());
  } catch (const std::exception&) {  // only a record: a path it cannot resolve fails to open anyway
  }
}

// Why the study may not write `path` ("" when it may); `target` is then the
// file, resolved. Below the output folder only (a relative path is taken
// there), no hidden names, no links, no input.
std::string writeRefusal(const State& st, const std::string& path, fs::path& target) {
  if (path.empty()) return "an empty file name";
  std::error_code ec;
  const fs::path given = fs::absolute(st.session->outputDir / path, ec);
  if (ec) return "the path cannot be resolved (" + ec.message() + ")";
  const fs::path name = given.filename();
  if (name.empty() || name == "." || name == "..") return "it names a folder, not a file";
  target = resolved(given.parent_path()) / name;
  const fs::path out = resolved(st.session->outputDir);
  const fs::path below = target.lexically_relative(out);
  if (below.empty() || *below.begin() == ".." || *below.begin() == ".")
    return "a sandboxed study writes files only below its output folder " + out.string() +
           " (a relative path is taken from there)";
  for (const auto& part : below)
    if (part.string()[0] == '.')
      return "a sandboxed study writes no hidden file or folder (a name starting with '.': other programs read "
             "such files as their settings)";
  const auto status = fs::symlink_status(target, ec);
  if (fs::is_symlink(status)) return target.string() + " is a symbolic link (a sandboxed study does not write through links)";
  if (fs::is_regular_file(status) && fs::hard_link_count(target, ec) > 1)
    return target.string() + " has other hard links (names that may lie outside the output folder)";
  if (resolved(st.session->studyPath) == target) return target.string() + " is the study file itself";
  if (const std::string how = st.session->files.inputOf(target); !how.empty())
    return target.string() + " is an input of the study (" + how + ")";
  for (const auto& [unit, file] : st.session->units)
    if (resolved(file) == target)
      return target.string() + " is bound to unit " + std::to_string(unit) + " (the commands read and write it)";
  if (st.readFiles.count(target.string()) && !st.writtenFiles.count(target.string()))
    return target.string() + " is an input of the study (it read the file)";
  return "";
}

// Checks that argument `arg` names a file the study may write (create, replace,
// delete), then replaces it by the resolved path, so that what is opened is what
// was checked. Returns -1 with a <F> pushed when it may not.
int sandboxWriteImpl(lua_State* L, const char* function, const char* verb, int arg) {
  const std::string path = lua_tostring(L, arg);
  try {
    State& st = stateOf(L);
    fs::path target;
    const std::string why = writeRefusal(st, path, target);
    if (why.empty()) {
      st.session->outputFile("");  // the output folder exists from now on
      st.writtenFiles.insert(target.string());
      lua_pushstring(L, target.c_str());
      lua_replace(L, arg);
      return 0;
    }
    pushFatal(L, "<F> <LUA> " + callSite(L) + ": " + function + " cannot " + verb + " '" + path + "': " + why +
                     " (aster-lite --unsafe-lua lifts the sandbox)");
  } catch (const std::exception& e) {
    pushFatal(L, "<F> <LUA> " + callSite(L) + ": " + function + " cannot " + verb + " '" + path + "': " + e.what());
  }
  return -1;
}

// Calls the library's own function (upvalue 1) with the arguments as they now are.
int callOriginal(lua_State* L) {
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  lua_call(L, lua_gettop(L) - 1, LUA_MULTRET);
  return lua_gettop(L);
}

int sandboxedOpen(lua_State* L) {  // io.open(path [, mode])
  luaL_checkstring(L, 1);
  const char* mode = luaL_optstring(L, 2, "r");
  if (std::strpbrk(mode, "wa+")) {
    if (sandboxWriteImpl(L, "io.open", "write", 1) < 0) return lua_error(L);
  } else {
    recordRead(L, 1);
  }
  return callOriginal(L);
}

int sandboxedOutput(lua_State* L) {  // io.output([path | file]): a path is opened for writing
  if (lua_type(L, 1) == LUA_TSTRING && sandboxWriteImpl(L, "io.output", "write", 1) < 0) return lua_error(L);
  return callOriginal(L);
}

int sandboxedRead(lua_State* L) {  // io.input, io.lines: reading is free, recorded
  recordRead(L, 1);
  return callOriginal(L);
}

int sandboxedRemove(lua_State* L) {  // os.remove(path)
  luaL_checkstring(L, 1);
  if (sandboxWriteImpl(L, "os.remove", "delete", 1) < 0) return lua_error(L);
  return callOriginal(L);
}

int sandboxedRename(lua_State* L) {  // os.rename(from, to)
  luaL_checkstring(L, 1);
  luaL_checkstring(L, 2);
  if (sandboxWriteImpl(L, "os.rename", "move", 1) < 0 || sandboxWriteImpl(L, "os.rename", "replace", 2) < 0)
    return lua_error(L);
  return callOriginal(L);
}

int refusedImpl(lua_State* L, const char* what) {
  pushFatal(L, "<F> <LUA> " + callSite(L) + ": " + what + " (aster-lite --unsafe-lua lifts the sandbox)");
  return -1;
}

int sandboxedTmpname(lua_State* L) {
  refusedImpl(L, "os.tmpname is not available to a sandboxed study: it creates a file outside the output folder");
  return lua_error(L);
}

int sandboxedSetlocale(lua_State* L) {  // os.setlocale(): asking is free, changing is not
  if (lua_isnoneornil(L, 1)) return callOriginal(L);
  refusedImpl(L, "os.setlocale cannot change the locale of a sandboxed study: numbers would be printed and read "
                 "with another decimal separator in the results");
  return lua_error(L);
}

// os.exit([code]): ends the study as FIN does (plots drawn, checks counted, exit
// status of the checks); a failure code (false, non-zero) ends it with exit status 2.
void studyExitImpl(lua_State* L, const char* code) {
  State& st = stateOf(L);
  if (st.stop == State::Stop::None) {
    if (!code) {
      st.stop = State::Stop::Finish;
    } else {
      st.stop = State::Stop::Abort;
      st.stopMessage = "<F> <LUA> " + callSite(L) + ": the study called os.exit(" + code + "): it ends as a failure";
    }
  }
  pushStop(L, 1);
}

int studyExit(lua_State* L) {
  const char* failure = nullptr;
  if (lua_isboolean(L, 1)) {
    if (!lua_toboolean(L, 1)) failure = "false";
  } else if (luaL_optinteger(L, 1, 0) != 0) {
    failure = lua_tostring(L, 1);
  }
  studyExitImpl(L, failure);
  return lua_error(L);
}

// load, loadfile, dofile and require read text only: a binary chunk is
// bytecode, which Lua does not check and which can corrupt the memory.
constexpr int kPieceSlot = 5;  // load(reader): the reader's last piece, kept alive there

const char* readPiece(lua_State* L, void*, size_t* size) {
  luaL_checkstack(L, 2, "too many nested functions");
  lua_pushvalue(L, 1);
  lua_call(L, 0, 1);
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    *size = 0;
    return nullptr;
  }
  if (!lua_isstring(L, -1)) luaL_error(L, "reader function must return a string");
  lua_replace(L, kPieceSlot);
  return lua_tolstring(L, kPieceSlot, size);
}

// The chunk loaded (with `env`, a stack index or 0, as its _ENV), or fail and the message.
int loaded(lua_State* L, int status, int env) {
  if (status != LUA_OK) {
    luaL_pushfail(L);
    lua_insert(L, -2);
    return 2;
  }
  if (env != 0) {
    lua_pushvalue(L, env);
    if (!lua_setupvalue(L, -2, 1)) lua_pop(L, 1);
  }
  return 1;
}

int textLoad(lua_State* L) {  // load(chunk [, chunkname [, mode [, env]]]); mode is always 't'
  const int env = lua_isnone(L, 4) ? 0 : 4;
  if (lua_type(L, 1) == LUA_TSTRING) {
    size_t size = 0;
    const char* text = lua_tolstring(L, 1, &size);
    const char* name = luaL_optstring(L, 2, text);
    return loaded(L, luaL_loadbufferx(L, text, size, name, "t"), env);
  }
  luaL_checktype(L, 1, LUA_TFUNCTION);
  const char* name = luaL_optstring(L, 2, "=(load)");
  lua_settop(L, kPieceSlot);
  return loaded(L, lua_load(L, readPiece, nullptr, name, "t"), env);
}

int textLoadfile(lua_State* L) {  // loadfile([file [, mode [, env]]])
  const char* file = luaL_optstring(L, 1, nullptr);
  const int env = lua_isnone(L, 3) ? 0 : 3;
  recordRead(L, 1);
  return loaded(L, luaL_loadfilex(L, file, "t"), env);
}

int textDofile(lua_State* L) {  // dofile([file])
  const char* file = luaL_optstring(L, 1, nullptr);
  lua_settop(L, 1);
  recordRead(L, 1);
  if (luaL_loadfilex(L, file, "t") != LUA_OK) return lua_error(L);
  lua_call(L, 0, LUA_MULTRET);
  return lua_gettop(L) - 1;
}

// package.searchers[2]: a module found on package.path, loaded as text.
int textSearcher(lua_State* L) {
  const char* name = luaL_checkstring(L, 1);
  lua_getfield(L, lua_upvalueindex(1), "searchpath");
  lua_pushvalue(L, 1);
  lua_getfield(L, lua_upvalueindex(1), "path");
  lua_call(L, 2, 2);
  if (lua_isnil(L, -2)) return 1;  // the second result says where it looked
  lua_pop(L, 1);
  const char* file = lua_tostring(L, -1);
  recordRead(L, lua_gettop(L));
  if (luaL_loadfilex(L, file, "t") != LUA_OK)
    return luaL_error(L, "error loading module '%s' from file '%s':\n\t%s", name, file, lua_tostring(L, -1));
  lua_pushstring(L, file);
  return 2;
}

// Replaces table[field] with f; with `keep`, f gets the original as upvalue 1.
void replaceFunction(lua_State* L, const char* table, const char* field, lua_CFunction f, bool keep) {
  lua_getglobal(L, table);
  if (keep) {
    lua_getfield(L, -1, field);
    lua_pushcclosure(L, f, 1);
  } else if (f) {
    lua_pushcfunction(L, f);
  } else {
    lua_pushnil(L);
  }
  lua_setfield(L, -2, field);
  lua_pop(L, 1);
}

void openLibraries(lua_State* L, bool unsafe) {
  if (unsafe) {
    luaL_openlibs(L);
    return;
  }
  // Not the debug library: it reaches every upvalue and metatable.
  static const luaL_Reg libraries[] = {
      {LUA_GNAME, luaopen_base},       {LUA_LOADLIBNAME, luaopen_package}, {LUA_COLIBNAME, luaopen_coroutine},
      {LUA_TABLIBNAME, luaopen_table}, {LUA_IOLIBNAME, luaopen_io},        {LUA_OSLIBNAME, luaopen_os},
      {LUA_STRLIBNAME, luaopen_string}, {LUA_MATHLIBNAME, luaopen_math},  {LUA_UTF8LIBNAME, luaopen_utf8}};
  for (const auto& library : libraries) {
    luaL_requiref(L, library.name, library.func, 1);
    lua_pop(L, 1);
  }
}

// A study is data, not a program that may run other programs or change files
// outside its output folder (--unsafe-lua restores plain Lua).
void sandbox(lua_State* L) {
  replaceFunction(L, LUA_GNAME, "load", textLoad, false);
  replaceFunction(L, LUA_GNAME, "loadfile", textLoadfile, false);
  replaceFunction(L, LUA_GNAME, "dofile", textDofile, false);
  replaceFunction(L, LUA_STRLIBNAME, "dump", nullptr, false);
  replaceFunction(L, LUA_OSLIBNAME, "execute", nullptr, false);
  replaceFunction(L, LUA_IOLIBNAME, "popen", nullptr, false);
  replaceFunction(L, LUA_LOADLIBNAME, "loadlib", nullptr, false);
  replaceFunction(L, LUA_IOLIBNAME, "open", sandboxedOpen, true);
  replaceFunction(L, LUA_IOLIBNAME, "output", sandboxedOutput, true);
  replaceFunction(L, LUA_IOLIBNAME, "input", sandboxedRead, true);
  replaceFunction(L, LUA_IOLIBNAME, "lines", sandboxedRead, true);
  replaceFunction(L, LUA_OSLIBNAME, "remove", sandboxedRemove, true);
  replaceFunction(L, LUA_OSLIBNAME, "rename", sandboxedRename, true);
  replaceFunction(L, LUA_OSLIBNAME, "tmpname", sandboxedTmpname, false);
  replaceFunction(L, LUA_OSLIBNAME, "setlocale", sandboxedSetlocale, true);
  // require: package.preload, then Lua files as text; no C modules.
  lua_getglobal(L, LUA_LOADLIBNAME);
  lua_pushliteral(L, "");
  lua_setfield(L, -2, "cpath");
  lua_createtable(L, 2, 0);
  lua_getfield(L, -2, "searchers");
  lua_rawgeti(L, -1, 1);
  lua_rawseti(L, -3, 1);
  lua_pop(L, 1);
  lua_pushvalue(L, -2);
  lua_pushcclosure(L, textSearcher, 1);
  lua_rawseti(L, -2, 2);
  lua_setfield(L, -2, "searchers");
  lua_pop(L, 1);
}

}  // namespace

Interpreter::Interpreter(Session& session) : state_(std::make_unique<State>()), session_(session) {
  lua_State* L = luaL_newstate();
  state_->L = L;
  state_->memory.base = lua_getallocf(L, &state_->memory.baseData);
  state_->memory.L = L;
  lua_setallocf(L, watchedAlloc, &state_->memory);
  state_->session = &session;
  *static_cast<State**>(lua_getextraspace(L)) = state_.get();  // copied into every coroutine
  openLibraries(L, session.unsafeLua);
  lua_pushlightuserdata(L, state_.get());
  lua_setfield(L, LUA_REGISTRYINDEX, kStateKey);

  // getmetatable() gives a study a name, not the metamethods (which check what
  // they are called on all the same).
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
  lua_pushliteral(L, "aster-lite concept");
  lua_setfield(L, -2, "__metatable");
  lua_pop(L, 1);
  luaL_newmetatable(L, kNewNameMeta);
  lua_pushcfunction(L, collect<NewNameBox>);
  lua_setfield(L, -2, "__gc");
  lua_pushliteral(L, "aster-lite CO name");
  lua_setfield(L, -2, "__metatable");
  lua_pop(L, 1);

  for (const auto& [name, spec] : Catalogue::builtin().commands()) {
    lua_pushlightuserdata(L, const_cast<CommandSpec*>(&spec));
    lua_pushcclosure(L, callCommand, 1);
    lua_setglobal(L, name.c_str());
  }
  if (!session.unsafeLua) sandbox(L);
  // os.exit ends the study as FIN does: the plots are drawn, the checks counted.
  replaceFunction(L, LUA_OSLIBNAME, "exit", studyExit, false);
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

  // Ctrl-C, FIN and os.exit reach the study's Lua code through this hook.
  lua_sethook(L, stopHook, LUA_MASKCOUNT, kHookCount);

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
        if (auto* box = toConcept(L, -1))
          if (box->ptr.get() == &c) found = lua_tostring(L, -2);
      }
      lua_pop(L, 1);
    }
    lua_pop(L, 1);
    if (!found.empty()) return found;
    return c.assignedAs.empty() ? generatedName(c) : c.assignedAs;
  };

  // Ctrl-C while the study is stuck in one library call (no hook runs there):
  // the watchdog thread ends the run in its place, then the process.
  st->endFromWatchdog = [this, st] {
    int nobody = 0;
    if (!st->ending.compare_exchange_strong(nobody, 2)) return;  // the run is ending already
    std::fflush(stdout);
    std::fprintf(stderr,
                 "<F> <LUA> interrupted (SIGINT): the study did not stop within %g s; it was inside one call "
                 "to a Lua library function (a pattern search on a long string, a read from the terminal, a "
                 "finalizer...)\n",
                 interrupt::kWatchdogGrace);
    std::fflush(stderr);
    int status = kInterruptedStatus;
    try {
      status = finish(kInterruptedStatus);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "<F> <aster-lite> %s\n", e.what());
    }
    std::fflush(stdout);
    std::fflush(stderr);
    std::_Exit(status);
  };
  interrupt::setWatchdogHandler([](void* context) { static_cast<State*>(context)->endFromWatchdog(); }, st);
}

Interpreter::~Interpreter() {
  interrupt::setWatchdogHandler(nullptr, nullptr);
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
  if (!comm::isCommandFile(path)) return runString(text.str(), "@" + path);
  // A code_aster command file runs as its Lua translation, line for line: messages
  // quote the command file's own lines.
  const comm::Translation lua = comm::translateCommandFile(text.str(), path);
  if (!lua.ok) {
    Messages::emit(Severity::Fatal, "COMM", lua.error);
    return finish(2);
  }
  return runChunk(lua.lua, "@" + path, text.str());
}

int Interpreter::runString(const std::string& code, const std::string& chunkName) {
  return runChunk(code, chunkName, code);
}

// DEBUT and FIN are optional, as the catalogue of issue 2 wants: a study may
// end with its last command.
int Interpreter::runChunk(const std::string& code, const std::string& chunkName, const std::string& shown) {
  lua_State* L = state_->L;
  State& st = *state_;
  auto& lines = st.sources[chunkName];
  lines.clear();  // a chunk run again under the same name is read afresh
  std::istringstream text(shown);
  for (std::string line; std::getline(text, line);) lines.push_back(line);
  st.fatals.clear();
  st.fatalCount = 0;
  st.stop = State::Stop::None;
  st.stopMessage.clear();
  st.ending = 0;
  lua_sethook(L, stopHook, LUA_MASKCOUNT, kHookCount);
  int status;
  {
    const interrupt::Watch watched(true);
    // A sandboxed study is text: bytecode is not checked by Lua.
    status = luaL_loadbufferx(L, code.data(), code.size(), chunkName.c_str(), session_.unsafeLua ? nullptr : "t");
    if (status == LUA_OK) status = lua_pcall(L, 0, 0, 0);
  }
  // The watchdog may have taken over while the study was stuck after Ctrl-C: it
  // ends the run and the process, this thread waits for that.
  int nobody = 0;
  if (!st.ending.compare_exchange_strong(nobody, 1))
    for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));

  std::string message;  // the error that ended the study, if any
  bool finished = false;
  if (status == LUA_ERRMEM) {
    const std::string at = *st.memory.failedAt ? st.memory.failedAt
                                               : chunkName.substr(chunkName.rfind('@', 0) == 0 ? 1 : 0);
    message = "<F> <LUA> " + at + ": not enough memory (the study asks for more than the system gives it)";
    lua_pop(L, 1);
  } else if (status != LUA_OK) {
    if (lua_istable(L, -1)) {
      lua_getfield(L, -1, "aster_fin");
      finished = lua_toboolean(L, -1);
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
  }
  // A stop the study could not catch decides, whatever error reached the top.
  if (st.stop == State::Stop::Interrupt || st.stop == State::Stop::Abort) {
    message = st.stopMessage;
    finished = false;
  } else if (st.stop == State::Stop::Finish) {
    message.clear();
    finished = true;
  }
  if (finished || status == LUA_OK) message.clear();
  // The <F> the study caught (pcall, coroutine.resume) are fatal all the same.
  std::vector<std::string> caught;
  for (const auto& f : st.fatals)
    if (f != message) caught.push_back(f);
  std::size_t notKept = st.fatalCount - st.fatals.size();
  if (!message.empty() && caught.size() == st.fatals.size() && notKept > 0) --notKept;  // the one at the top
  const std::size_t caughtCount = caught.size() + notKept;
  std::fflush(stdout);
  for (const auto& f : caught) std::fprintf(stderr, "%s\n", f.c_str());
  if (caughtCount > 0)
    std::fprintf(stderr,
                 "<F> <LUA> the study went on after %zu fatal error%s (caught with pcall or in a coroutine%s): a "
                 "fatal error ends the run with exit status 2\n",
                 caughtCount, caughtCount == 1 ? "" : "s",
                 caughtCount > caught.size() ? "; the first ones are shown" : "");
  if (!message.empty()) std::fprintf(stderr, "%s\n", message.c_str());
  std::fflush(stderr);
  if (st.stop == State::Stop::Interrupt) return finish(kInterruptedStatus);
  return finish(!message.empty() || caughtCount > 0 ? 2 : 0);
}

int Interpreter::runFiles(const std::vector<std::string>& paths) {
  int status = 0;
  for (std::size_t i = 0; i < paths.size() && status == 0; ++i) {
    session_.continuesEarlierFile = i > 0;
    moreFilesFollow_ = i + 1 < paths.size();
    if (i > 0 && !std::ifstream(paths[i])) {  // the run still ends with the summary of what ran
      Messages::emit(Severity::Fatal, "aster-lite", "cannot open the study file " + paths[i]);
      moreFilesFollow_ = false;
      return finish(2);
    }
    status = runFile(paths[i]);
  }
  moreFilesFollow_ = false;
  return status;
}

int Interpreter::finish(int status) {
  if (moreFilesFollow_ && status == 0) return 0;  // the run ends with its last file
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
