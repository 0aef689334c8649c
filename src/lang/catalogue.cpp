#include "lang/catalogue.hpp"

#include <lua.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <set>

#include "core/error.hpp"

namespace aster::lang {
namespace {

// The catalogue's vocabulary (code_aster's): each constructor tags its table.
// KEYWORDS{...} is a list of keywords (a common group, commands/commons/) that
// the constructors splice in where it is placed.
const char* kPrelude = R"(
local function spliced(t)
  local out = {}
  for k, v in pairs(t) do if math.type(k) ~= 'integer' then out[k] = v end end
  for _, v in ipairs(t) do
    if type(v) == 'table' and v.__kind == 'KEYWORDS' then
      for _, w in ipairs(v) do out[#out + 1] = w end
    else
      out[#out + 1] = v
    end
  end
  return out
end
local function tagged(kind) return function(t) t = spliced(t); t.__kind = kind; return t end end
OPER, PROC, MACRO = tagged('OPER'), tagged('PROC'), tagged('MACRO')
SIMP, FACT, BLOC, KEYWORDS = tagged('SIMP'), tagged('FACT'), tagged('BLOC'), tagged('KEYWORDS')
local function rule(kind) return function(...) return {__kind = 'RULE', rule = kind, ...} end end
UN_PARMI, EXCLUS, AU_MOINS_UN = rule('UN_PARMI'), rule('EXCLUS'), rule('AU_MOINS_UN')
AU_PLUS_UN, PRESENT_PRESENT = rule('AU_PLUS_UN'), rule('PRESENT_PRESENT')
PRESENT_ABSENT, ENSEMBLE = rule('PRESENT_ABSENT'), rule('ENSEMBLE')
)";

struct LuaState {
  lua_State* L = luaL_newstate();
  ~LuaState() { lua_close(L); }
};

class Reader {
 public:
  Reader(lua_State* L, std::string file) : L(L), file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw Error("catalogue file commands/" + file_ + ".lua: " + where + ": " + what);
  }

  std::string fieldString(int idx, const char* key, const std::string& fallback = "") {
    lua_getfield(L, idx, key);
    std::string s = fallback;
    if (lua_type(L, -1) == LUA_TSTRING) s = lua_tostring(L, -1);
    lua_pop(L, 1);
    return s;
  }

  Value toValue(int idx, const std::string& where) {
    switch (lua_type(L, idx)) {
      case LUA_TNUMBER:
        if (lua_isinteger(L, idx)) return Value::ofInteger(lua_tointeger(L, idx));
        return Value::ofReal(lua_tonumber(L, idx));
      case LUA_TSTRING: return Value::ofText(lua_tostring(L, idx));
      default: fail(where, "values must be numbers or texts");
    }
  }

  // A field that is one value or a list of values.
  std::vector<Value> fieldValues(int idx, const char* key, const std::string& where) {
    std::vector<Value> out;
    lua_getfield(L, idx, key);
    const int t = lua_absindex(L, -1);
    if (lua_istable(L, t)) {
      const lua_Integer n = luaL_len(L, t);
      for (lua_Integer i = 1; i <= n; ++i) {
        lua_rawgeti(L, t, i);
        out.push_back(toValue(-1, where + "." + key));
        lua_pop(L, 1);
      }
    } else if (!lua_isnil(L, t)) {
      out.push_back(toValue(t, where + "." + key));
    }
    lua_pop(L, 1);
    return out;
  }

  int count(int idx, const char* key, int fallback, const std::string& where) {
    lua_getfield(L, idx, key);
    int n = fallback;
    if (lua_type(L, -1) == LUA_TSTRING) {
      if (std::string(lua_tostring(L, -1)) != "**") fail(where, std::string(key) + " must be a number or '**'");
      n = -1;
    } else if (lua_isinteger(L, -1)) {
      n = static_cast<int>(lua_tointeger(L, -1));
    } else if (!lua_isnil(L, -1)) {
      fail(where, std::string(key) + " must be a number or '**'");
    }
    lua_pop(L, 1);
    return n;
  }

  std::vector<Rule> rules(int idx, const std::string& where) {
    std::vector<Rule> out;
    lua_getfield(L, idx, "regles");
    const int t = lua_absindex(L, -1);
    if (lua_istable(L, t)) {
      const lua_Integer n = luaL_len(L, t);
      for (lua_Integer i = 1; i <= n; ++i) {
        lua_rawgeti(L, t, i);
        const int r = lua_absindex(L, -1);
        if (!lua_istable(L, r) || fieldString(r, "__kind") != "RULE") fail(where, "regles must list rules");
        static const std::map<std::string, Rule::Kind> kinds = {
            {"UN_PARMI", Rule::Kind::UnParmi},         {"EXCLUS", Rule::Kind::Exclus},
            {"AU_MOINS_UN", Rule::Kind::AuMoinsUn},    {"AU_PLUS_UN", Rule::Kind::AuPlusUn},
            {"PRESENT_PRESENT", Rule::Kind::PresentPresent},
            {"PRESENT_ABSENT", Rule::Kind::PresentAbsent}, {"ENSEMBLE", Rule::Kind::Ensemble}};
        Rule rule{kinds.at(fieldString(r, "rule")), {}};
        const lua_Integer m = luaL_len(L, r);
        for (lua_Integer j = 1; j <= m; ++j) {
          lua_rawgeti(L, r, j);
          rule.keys.push_back(luaL_checkstring(L, -1));
          lua_pop(L, 1);
        }
        if (rule.keys.size() < 2 && rule.kind != Rule::Kind::AuMoinsUn && rule.kind != Rule::Kind::UnParmi)
          fail(where, "rule " + rule.describe() + " needs at least two keywords");
        out.push_back(std::move(rule));
        lua_pop(L, 1);
      }
    }
    lua_pop(L, 1);
    return out;
  }

  // The array part of a FACT, BLOC or command table: its keywords.
  std::vector<KeywordSpec> children(int idx, int first, const std::string& where) {
    std::vector<KeywordSpec> out;
    std::set<std::string> seen;
    const lua_Integer n = luaL_len(L, idx);
    for (lua_Integer i = first; i <= n; ++i) {
      lua_rawgeti(L, idx, i);
      out.push_back(keyword(lua_absindex(L, -1), where));
      lua_pop(L, 1);
      const auto& k = out.back();
      if (k.kind != KeywordSpec::Kind::Block && !seen.insert(k.name).second)
        fail(where, "keyword " + k.name + " is declared twice");
    }
    return out;
  }

  KeywordSpec keyword(int t, const std::string& parent) {
    if (!lua_istable(L, t)) fail(parent, "expected SIMP{...}, FACT{...} or BLOC{...}");
    KeywordSpec k;
    const std::string kind = fieldString(t, "__kind");
    lua_rawgeti(L, t, 1);
    if (lua_type(L, -1) != LUA_TSTRING) fail(parent, "a " + kind + " needs its name first");
    k.name = lua_tostring(L, -1);
    lua_pop(L, 1);
    const std::string where = parent + "/" + k.name;
    k.doc = fieldString(t, "fr");
    const std::string statut = fieldString(t, "statut", "f");
    if (statut != "o" && statut != "f" && statut != "d") fail(where, "statut must be 'o', 'f' or 'd'");
    k.statut = statut[0];
    k.rules = rules(t, where);
    lua_getfield(L, t, "ignored");
    const int ignoredType = lua_type(L, -1);
    if (ignoredType == LUA_TSTRING) k.ignored = lua_tostring(L, -1);
    lua_pop(L, 1);
    if (ignoredType != LUA_TNIL) {
      if (kind == "BLOC") fail(where, "a BLOC cannot be ignored (mark its keywords)");
      if (ignoredType != LUA_TSTRING || k.ignored.empty())
        fail(where, "ignored = \"...\" gives the reason the keyword changes no result");
      if (k.statut == 'o') fail(where, "a mandatory keyword cannot be ignored");
    }
    if (kind == "SIMP") {
      k.kind = KeywordSpec::Kind::Simple;
      for (const auto& v : fieldValues(t, "typ", where)) k.types.push_back(v.text);
      if (k.types.empty()) fail(where, "typ is mandatory");
      k.defaults = fieldValues(t, "defaut", where);
      k.into = fieldValues(t, "into", where);
      k.min = count(t, "min", 1, where);
      k.max = count(t, "max", 1, where);
      lua_getfield(L, t, "val_min");
      if ((k.hasValMin = lua_isnumber(L, -1))) k.valMin = lua_tonumber(L, -1);
      lua_getfield(L, t, "val_max");
      if ((k.hasValMax = lua_isnumber(L, -1))) k.valMax = lua_tonumber(L, -1);
      lua_pop(L, 2);
      if (!k.defaults.empty() && k.statut == 'o') fail(where, "a mandatory keyword has no default");
      for (const auto& d : k.defaults) {
        if (k.into.empty()) continue;
        bool found = false;
        for (const auto& a : k.into)
          found |= (a.kind == Value::Kind::Text) ? a.text == d.text : (d.isNumber() && a.real == d.real);
        if (!found) fail(where, "default " + d.describe() + " is not among the allowed values");
      }
    } else if (kind == "FACT") {
      k.kind = KeywordSpec::Kind::Factor;
      k.minOcc = count(t, "min", k.statut == 'o' ? 1 : 0, where);
      k.maxOcc = count(t, "max", 1, where);
      k.children = children(t, 2, where);
    } else if (kind == "BLOC") {
      k.kind = KeywordSpec::Kind::Block;
      lua_getfield(L, t, "condition");
      const int c = lua_absindex(L, -1);
      if (!lua_istable(L, c)) fail(where, "a BLOC needs condition = {KEY = value(s)}");
      lua_pushnil(L);
      while (lua_next(L, c)) {
        if (lua_type(L, -2) != LUA_TSTRING) fail(where, "condition keys must be keyword names");
        std::string key = lua_tostring(L, -2);
        std::vector<Value> vals;
        if (lua_istable(L, -1)) {
          const lua_Integer n = luaL_len(L, -1);
          for (lua_Integer i = 1; i <= n; ++i) {
            lua_rawgeti(L, -1, i);
            vals.push_back(toValue(-1, where));
            lua_pop(L, 1);
          }
        } else if (lua_isboolean(L, -1)) {
          // KEY = true: present; KEY = false: absent.
          if (!lua_toboolean(L, -1)) {
            k.absent.push_back(key);
            lua_pop(L, 1);
            continue;
          }
        } else {
          vals.push_back(toValue(-1, where));
        }
        k.condition.emplace_back(key, std::move(vals));
        lua_pop(L, 1);
      }
      lua_pop(L, 1);
      std::sort(k.condition.begin(), k.condition.end(),
                [](const auto& a, const auto& b) { return a.first < b.first; });
      k.children = children(t, 2, where);
    } else {
      fail(parent, "expected SIMP{...}, FACT{...} or BLOC{...}, got " + (kind.empty() ? "a plain table" : kind));
    }
    return k;
  }

  CommandSpec command(int t) {
    CommandSpec c;
    const std::string kind = fieldString(t, "__kind");
    if (kind == "OPER") c.kind = CommandSpec::Kind::Oper;
    else if (kind == "PROC") c.kind = CommandSpec::Kind::Proc;
    else if (kind == "MACRO") c.kind = CommandSpec::Kind::Macro;
    else fail("top level", "the file must return OPER{...}, PROC{...} or MACRO{...}");
    c.name = fieldString(t, "nom");
    if (c.name != file_) fail("top level", "nom='" + c.name + "' differs from the file name");
    c.doc = fieldString(t, "fr");
    for (const auto& v : fieldValues(t, "sd_prod", c.name)) c.results.push_back(v.text);
    if (c.kind == CommandSpec::Kind::Oper && c.results.empty()) fail(c.name, "an OPER needs sd_prod");
    const std::string re = fieldString(t, "reentrant", "n");
    if (re != "n" && re != "o" && re != "f") fail(c.name, "reentrant must be 'n', 'o' or 'f'");
    c.reentrant = re[0];
    c.rules = rules(t, c.name);
    c.children = children(t, 1, c.name);
    lua_getfield(L, t, "autres_mots_cles");
    if (!lua_isnil(L, -1)) {
      const int o = lua_absindex(L, -1);
      if (!lua_istable(L, o) || fieldString(o, "__kind") != "SIMP") fail(c.name, "autres_mots_cles must be a SIMP{...}");
      c.others = keyword(o, c.name);
      if (c.others->max != 1 || c.others->statut != 'f' || !c.others->defaults.empty())
        fail(c.name, "autres_mots_cles: one optional value without default");
      for (const auto& k : c.children)
        if (k.name == c.others->name) fail(c.name, "autres_mots_cles: " + k.name + " is already a keyword");
    }
    lua_pop(L, 1);
    return c;
  }

 private:
  lua_State* L;
  std::string file_;
};

}  // namespace

std::string Rule::describe() const {
  static const char* names[] = {"UN_PARMI", "EXCLUS", "AU_MOINS_UN", "AU_PLUS_UN",
                                "PRESENT_PRESENT", "PRESENT_ABSENT", "ENSEMBLE"};
  std::string s = std::string(names[static_cast<int>(kind)]) + "(";
  for (std::size_t i = 0; i < keys.size(); ++i) s += (i ? ", '" : "'") + keys[i] + "'";
  return s + ")";
}

std::string KeywordSpec::describeCondition() const {
  std::string s;
  for (const auto& [key, vals] : condition) {
    if (!s.empty()) s += " and ";
    if (vals.empty()) {
      s += key + " is given";
      continue;
    }
    s += key + (vals.size() == 1 ? " = " : " in {");
    for (std::size_t i = 0; i < vals.size(); ++i) s += (i ? ", " : "") + vals[i].describe();
    if (vals.size() > 1) s += "}";
  }
  for (const auto& key : absent) s += (s.empty() ? "" : " and ") + key + " is absent";
  return s;
}

Catalogue Catalogue::fromSources(const std::vector<CatalogueSource>& sources,
                                 const std::vector<CatalogueSource>& commons) {
  Catalogue cat;
  for (const auto& src : sources) {
    LuaState state;
    lua_State* L = state.L;
    luaL_openlibs(L);
    if (luaL_dostring(L, kPrelude) != LUA_OK) throw Error(std::string("catalogue prelude: ") + lua_tostring(L, -1));
    for (const auto& common : commons) {
      const std::string chunk = std::string("@commands/commons/") + common.name + ".lua";
      if (luaL_loadbuffer(L, common.text, std::strlen(common.text), chunk.c_str()) != LUA_OK ||
          lua_pcall(L, 0, 0, 0) != LUA_OK)
        throw Error(std::string("catalogue file: ") + lua_tostring(L, -1));
      if (lua_getglobal(L, common.name) == LUA_TNIL)
        throw Error("catalogue file commands/commons/" + std::string(common.name) + ".lua: it must define " +
                    common.name);
      lua_pop(L, 1);
    }
    const std::string chunk = std::string("@commands/") + src.name + ".lua";
    if (luaL_loadbuffer(L, src.text, std::strlen(src.text), chunk.c_str()) != LUA_OK ||
        lua_pcall(L, 0, 1, 0) != LUA_OK)
      throw Error(std::string("catalogue file: ") + lua_tostring(L, -1));
    Reader reader(L, src.name);
    CommandSpec spec = reader.command(lua_absindex(L, -1));
    cat.commands_.emplace(spec.name, std::move(spec));
  }
  return cat;
}

const Catalogue& Catalogue::builtin() {
  static const Catalogue cat = fromSources(catalogueSources(), catalogueCommons());
  return cat;
}

const CommandSpec* Catalogue::find(const std::string& name) const {
  auto it = commands_.find(name);
  return it == commands_.end() ? nullptr : &it->second;
}

std::vector<std::string> Catalogue::names() const {
  std::vector<std::string> out;
  for (const auto& [name, spec] : commands_) out.push_back(name);
  return out;
}

std::string describeType(const std::string& type) {
  static const std::map<std::string, std::string> words = {
      {"R", "a real"},
      {"I", "an integer"},
      {"TXM", "a text"},
      {"grma", "a group of cells (GROUP_MA name)"},
      {"grno", "a group of nodes (GROUP_NO name)"},
      {"ma", "a cell name"},
      {"no", "a node name"},
      {"CO", "a new concept name CO('...')"},
      {"lua_function", "a Lua function"},
  };
  auto it = words.find(type);
  return it != words.end() ? it->second : "a " + type;
}

std::string describeTypes(const std::vector<std::string>& types) {
  std::string s;
  for (std::size_t i = 0; i < types.size(); ++i) {
    if (i) s += (i + 1 == types.size()) ? " or " : ", ";
    s += describeType(types[i]);
  }
  return s;
}

}  // namespace aster::lang
