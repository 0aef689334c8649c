#include "lang/validator.hpp"

#include <cctype>
#include <cmath>
#include <limits>
#include <set>

#include "core/suggest.hpp"

namespace aster::lang {
namespace {

std::string joined(const std::string& path, const std::string& key) { return path.empty() ? key : path + "/" + key; }

bool sameValue(const Value& a, const Value& b) {
  if (a.kind == Value::Kind::Text || b.kind == Value::Kind::Text)
    return a.kind == b.kind && a.text == b.text;
  return a.isNumber() && b.isNumber() && a.real == b.real;
}

std::string listValues(const std::vector<Value>& vals) {
  std::string s;
  for (std::size_t i = 0; i < vals.size(); ++i) s += (i ? ", " : "") + vals[i].describe();
  return s;
}

bool isTextType(const std::string& t) {
  return t == "TXM" || t == "grma" || t == "grno" || t == "ma" || t == "no";
}

// Converts one item to the first of the keyword's types it fits; false when none.
bool convert(const Value& in, const std::vector<std::string>& types, Value& out) {
  for (const auto& t : types) {
    if (t == "R" && in.isNumber()) {
      out = Value::ofReal(in.real);
      return true;
    }
    if (t == "I" && in.kind == Value::Kind::Integer) {
      out = in;
      return true;
    }
    if (t == "I" && in.kind == Value::Kind::Real && std::floor(in.real) == in.real && std::fabs(in.real) < 9e15) {
      out = Value::ofInteger(static_cast<long long>(in.real));
      return true;
    }
    if (isTextType(t) && in.kind == Value::Kind::Text) {
      out = in;
      return true;
    }
    if (t == "CO" && in.kind == Value::Kind::NewName) {
      out = in;
      return true;
    }
    if (t == "lua_function" && in.kind == Value::Kind::Function) {
      out = in;
      return true;
    }
    if (in.kind == Value::Kind::Concept && in.concept && in.concept->typeName() == t) {
      out = in;
      return true;
    }
  }
  return false;
}

class LevelValidator {
 public:
  LevelValidator(const std::string& command, const std::string& path) : command_(command), path_(path) {}

  // others: the command's autres_mots_cles (top level only), or null.
  Keywords run(const std::vector<KeywordSpec>& specs, const std::vector<Rule>& rules, const Keywords& call,
               const std::string& owner, const KeywordSpec* others = nullptr) {
    // Keywords that apply: the level's own, then those of blocks whose condition
    // holds (conditions see the defaults of keywords already known to apply).
    std::vector<const KeywordSpec*> active;
    std::vector<const Rule*> activeRules;
    for (const auto& r : rules) activeRules.push_back(&r);
    std::vector<const KeywordSpec*> inactiveBlocks;
    Keywords view = call;  // the call plus defaults, for block conditions
    collect(specs, call, view, active, activeRules, inactiveBlocks);

    std::set<std::string> allowed;
    for (const auto* k : active) allowed.insert(k->name);
    Keywords extra;  // the values of autres_mots_cles
    for (const auto& key : call.keys()) {
      if (allowed.count(key)) continue;
      for (const auto* b : inactiveBlocks)
        for (const auto* k : flatten(*b))
          if (k->name == key)
            fail(key, "keyword " + key + " is only allowed when " + b->describeCondition());
      std::vector<std::string> names(allowed.begin(), allowed.end());
      const std::string hint = didYouMean(key, names);
      if (others) {
        other(*others, key, call, extra, hint.empty() ? "" : ";" + hint);
        continue;
      }
      fail(key, "keyword " + key + " is not a keyword of " + owner + (hint.empty() ? "" : ";" + hint) + " (allowed: " + joinNames(orderedNames(active)) + ")");
    }

    Keywords out;
    out.path = path_;
    if (others && !extra.keys().empty()) out.setFactor(others->name, {extra});
    for (const auto* k : active) {
      // An ignored keyword is checked as declared (a misspelt value is still an
      // error), then left out of the tree the operator reads.
      Keywords scratch;
      Keywords& into = k->ignored.empty() ? out : scratch;
      if (k->kind == KeywordSpec::Kind::Simple)
        simple(*k, call, into);
      else
        factor(*k, call, into);
    }
    for (const auto* r : activeRules) checkRule(*r, call);
    return out;
  }

 private:
  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    // Inside a factor keyword, say which occurrence: "AFFE[2]: keyword ...".
    throw ValidationError(joined(path_, key), path_.empty() ? what : path_ + ": " + what);
  }

  static bool isIdentifier(const std::string& s) {
    if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
    for (char c : s)
      if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
    return true;
  }

  // A keyword the catalogue does not declare, taken as one of the command's
  // autres_mots_cles: named like an identifier, one value of the declared types.
  void other(const KeywordSpec& spec, const std::string& key, const Keywords& call, Keywords& extra,
             const std::string& hint) {
    const std::string what = describeTypes(spec.types);
    if (!isIdentifier(key))
      fail(key, "keyword '" + key + "' is not a valid name: a value passed to the expression (" + spec.name +
                    ") is named by a letter or _ then letters, digits or _");
    Value v;
    const std::string as = "keyword " + key + " is not one of " + command_ + "'s own keywords, so it is a value passed to the expression (" +
                           spec.name + "): it must be " + what + ", got ";
    if (call.isFactor(key)) fail(key, as + "a table of keywords" + hint);
    const auto& given = call.values(key);
    if (given.size() != 1 || !convert(given.front(), spec.types, v))
      fail(key, as + (given.size() == 1 ? given.front().describe() : std::to_string(given.size()) + " values") + hint);
    KeywordSpec named = spec;
    named.name = key;
    simple(named, call, extra);
  }

  static std::vector<const KeywordSpec*> flatten(const KeywordSpec& block) {
    std::vector<const KeywordSpec*> out;
    for (const auto& c : block.children) {
      if (c.kind == KeywordSpec::Kind::Block) {
        auto sub = flatten(c);
        out.insert(out.end(), sub.begin(), sub.end());
      } else {
        out.push_back(&c);
      }
    }
    return out;
  }

  static std::vector<std::string> orderedNames(const std::vector<const KeywordSpec*>& specs) {
    std::vector<std::string> out;
    for (const auto* k : specs) out.push_back(k->name);
    return out;
  }

  static bool holds(const KeywordSpec& block, const Keywords& view) {
    for (const auto& [key, vals] : block.condition) {
      if (!view.has(key) || view.isFactor(key)) {
        if (view.isFactor(key) && vals.empty()) continue;
        return false;
      }
      if (vals.empty()) continue;
      const auto& given = view.values(key);
      if (given.size() != 1) return false;
      bool match = false;
      for (const auto& v : vals) match |= sameValue(v, given.front());
      if (!match) return false;
    }
    for (const auto& key : block.absent)
      if (view.has(key)) return false;
    return true;
  }

  void collect(const std::vector<KeywordSpec>& specs, const Keywords& call, Keywords& view,
               std::vector<const KeywordSpec*>& active, std::vector<const Rule*>& rules,
               std::vector<const KeywordSpec*>& inactive) {
    std::vector<const KeywordSpec*> blocks;
    for (const auto& k : specs) {
      if (k.kind == KeywordSpec::Kind::Block) {
        blocks.push_back(&k);
        continue;
      }
      active.push_back(&k);
      if (k.kind == KeywordSpec::Kind::Simple && !call.has(k.name) && !k.defaults.empty())
        view.setSimple(k.name, k.defaults);
    }
    for (const auto* b : blocks) {
      if (holds(*b, view)) {
        for (const auto& r : b->rules) rules.push_back(&r);
        collect(b->children, call, view, active, rules, inactive);
      } else {
        inactive.push_back(b);
      }
    }
  }

  void simple(const KeywordSpec& k, const Keywords& call, Keywords& out) {
    const std::string what = describeTypes(k.types);
    if (!call.has(k.name)) {
      if (k.mandatory()) fail(k.name, "keyword " + k.name + " is mandatory and missing (expected " + what + ")");
      if (!k.defaults.empty()) {
        std::vector<Value> typed;
        for (const auto& d : k.defaults) {
          Value v;
          if (!convert(d, k.types, v)) v = d;
          typed.push_back(v);
        }
        out.setSimple(k.name, typed);
      }
      return;
    }
    if (call.isFactor(k.name))
      fail(k.name, "keyword " + k.name + " expects " + what + ", got a table of keywords");
    const auto& given = call.values(k.name);
    if (static_cast<int>(given.size()) < k.min)
      fail(k.name, "keyword " + k.name + " needs at least " + std::to_string(k.min) + " value" +
                       (k.min > 1 ? "s" : "") + ", got " + std::to_string(given.size()));
    if (k.max >= 0 && static_cast<int>(given.size()) > k.max)
      fail(k.name, "keyword " + k.name + " takes at most " + std::to_string(k.max) + " value" +
                       (k.max > 1 ? "s" : "") + ", got " + std::to_string(given.size()));
    std::vector<Value> typed;
    for (std::size_t i = 0; i < given.size(); ++i) {
      const std::string item = given.size() > 1 ? " (value " + std::to_string(i + 1) + ")" : "";
      Value v;
      if (!convert(given[i], k.types, v))
        fail(k.name, "keyword " + k.name + item + " expects " + what + ", got " + given[i].describe());
      checkRepresentable(k, item, v);
      if (!k.into.empty()) {
        bool ok = false;
        for (const auto& a : k.into) ok |= sameValue(a, v);
        if (!ok) {
          std::string hint;
          if (v.kind == Value::Kind::Text) {
            std::vector<std::string> names;
            for (const auto& a : k.into) names.push_back(a.text);
            hint = didYouMean(v.text, names, true);
          }
          fail(k.name, "keyword " + k.name + item + " = " + v.describe() + " is not allowed; allowed values: " +
                           listValues(k.into) + (hint.empty() ? "" : ";" + hint));
        }
      }
      if (v.isNumber() && k.hasValMin && v.real < k.valMin)
        fail(k.name, "keyword " + k.name + item + " = " + v.describe() + " is below its minimum " +
                         Value::ofReal(k.valMin).describe());
      if (v.isNumber() && k.hasValMax && v.real > k.valMax)
        fail(k.name, "keyword " + k.name + item + " = " + v.describe() + " is above its maximum " +
                         Value::ofReal(k.valMax).describe());
      typed.push_back(v);
    }
    out.setSimple(k.name, typed);
  }

  // What operators cannot take as it is, refused here by keyword name rather than
  // found later with a misleading message: integers beyond the C++ int operators
  // read (they would be truncated), reals that are not finite (0/0, 1/0 or
  // math.huge in the study), texts with a NUL byte (C strings end there).
  void checkRepresentable(const KeywordSpec& k, const std::string& item, const Value& v) const {
    const std::string named = "keyword " + k.name + item + " = " + v.describe();
    if (v.kind == Value::Kind::Integer &&
        (v.integer < std::numeric_limits<int>::min() || v.integer > std::numeric_limits<int>::max()))
      fail(k.name, named + " is out of the range of integers (" + std::to_string(std::numeric_limits<int>::min()) +
                       " to " + std::to_string(std::numeric_limits<int>::max()) + ")");
    if (v.kind == Value::Kind::Real && !std::isfinite(v.real))
      fail(k.name, named + " is not a finite number (0/0, 1/0 or math.huge in the study?)");
    if ((v.kind == Value::Kind::Text || v.kind == Value::Kind::NewName) && v.text.find('\0') != std::string::npos)
      fail(k.name, named + " contains a NUL byte ('\\0')");
  }

  void factor(const KeywordSpec& k, const Keywords& call, Keywords& out) {
    std::vector<Keywords> given;
    if (call.has(k.name)) {
      if (call.isFactor(k.name)) {
        given = call.factor(k.name);
      } else if (call.values(k.name).empty()) {
        given.emplace_back();  // K = {} : one occurrence with every default
      } else {
        fail(k.name, "factor keyword " + k.name + " expects a table of keywords {KEY=value, ...} (or a list of "
                         "them), got " + call.values(k.name).front().describe());
      }
    } else if (k.statut == 'o') {
      fail(k.name, "factor keyword " + k.name + " is mandatory and missing");
    } else if (k.statut == 'd') {
      given.emplace_back();
    } else {
      return;
    }
    const int n = static_cast<int>(given.size());
    if (n < k.minOcc)
      fail(k.name, "factor keyword " + k.name + " is given " + std::to_string(n) + " time" + (n == 1 ? "" : "s") +
                       "; expected at least " + std::to_string(k.minOcc));
    if (k.maxOcc >= 0 && n > k.maxOcc)
      fail(k.name, "factor keyword " + k.name + " is given " + std::to_string(n) + " times; expected at most " +
                       std::to_string(k.maxOcc));
    std::vector<Keywords> typed;
    for (int i = 0; i < n; ++i) {
      const std::string sub = joined(path_, k.name) + (k.maxOcc == 1 ? "" : "[" + std::to_string(i + 1) + "]");
      LevelValidator child(command_, sub);
      typed.push_back(child.run(k.children, k.rules, given[i], k.name));
    }
    out.setFactor(k.name, std::move(typed));
  }

  void checkRule(const Rule& r, const Keywords& call) const {
    std::vector<std::string> present;
    for (const auto& key : r.keys)
      if (call.has(key)) present.push_back(key);
    const std::string keys = joinNames(r.keys);
    switch (r.kind) {
      case Rule::Kind::UnParmi:
        if (present.size() != 1)
          fail(present.empty() ? "" : present[1 % present.size()],
               "exactly one of " + keys + " is required, got " +
                   (present.empty() ? std::string("none") : joinNames(present)) + " (rule " + r.describe() + ")");
        break;
      case Rule::Kind::Exclus:
      case Rule::Kind::AuPlusUn:
        if (present.size() > 1)
          fail(present[1], "keywords " + joinNames(present) + " are mutually exclusive (rule " + r.describe() + ")");
        break;
      case Rule::Kind::AuMoinsUn:
        if (present.empty()) fail("", "at least one of " + keys + " is required (rule " + r.describe() + ")");
        break;
      case Rule::Kind::PresentPresent:
        if (call.has(r.keys[0]))
          for (std::size_t i = 1; i < r.keys.size(); ++i)
            if (!call.has(r.keys[i]))
              fail(r.keys[i], "keyword " + r.keys[i] + " is required when " + r.keys[0] + " is given (rule " +
                                  r.describe() + ")");
        break;
      case Rule::Kind::PresentAbsent:
        if (call.has(r.keys[0]))
          for (std::size_t i = 1; i < r.keys.size(); ++i)
            if (call.has(r.keys[i]))
              fail(r.keys[i], "keyword " + r.keys[i] + " is not allowed when " + r.keys[0] + " is given (rule " +
                                  r.describe() + ")");
        break;
      case Rule::Kind::Ensemble:
        if (!present.empty() && present.size() != r.keys.size())
          fail(present.front(), "keywords " + keys + " go together: give all or none (rule " + r.describe() + ")");
        break;
    }
  }

  std::string command_;
  std::string path_;
};

}  // namespace

Keywords validate(const CommandSpec& spec, const Keywords& call) {
  LevelValidator top(spec.name, "");
  return top.run(spec.children, spec.rules, call, spec.name, spec.others ? &*spec.others : nullptr);
}

}  // namespace aster::lang
