#include "lang/keywords.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/number_format.hpp"

namespace aster::lang {

std::string visibleText(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '\0')
      out += "\\0";
    else
      out += c;
  }
  return out;
}

std::string Value::describe() const {
  std::ostringstream s;
  switch (kind) {
    case Kind::Integer: s << integer; break;
    case Kind::Real:
      if (std::isnan(real))
        s << "nan";  // not "-nan", which 0/0 gives on x86
      else
        s << format::significant(real, 6);
      break;
    case Kind::Text: s << "'" << visibleText(text) << "'"; break;
    case Kind::Concept: s << "a " << (concept ? concept->typeName() : "null concept"); break;
    case Kind::Function: s << "a Lua function"; break;
    case Kind::NewName: s << "CO('" << visibleText(text) << "')"; break;
    case Kind::Other: s << text; break;
  }
  return s.str();
}

void Keywords::setSimple(const std::string& key, std::vector<Value> values) {
  if (!entries_.count(key)) order_.push_back(key);
  Entry& e = entries_[key];
  e.factor = false;
  e.values = std::move(values);
  e.occurrences.clear();
}

void Keywords::setFactor(const std::string& key, std::vector<Keywords> occurrences) {
  if (!entries_.count(key)) order_.push_back(key);
  Entry& e = entries_[key];
  e.factor = true;
  e.values.clear();
  e.occurrences = std::move(occurrences);
}

void Keywords::erase(const std::string& key) {
  entries_.erase(key);
  order_.erase(std::remove(order_.begin(), order_.end(), key), order_.end());
}

bool Keywords::has(const std::string& key) const { return entries_.count(key) != 0; }

bool Keywords::isFactor(const std::string& key) const {
  auto it = entries_.find(key);
  return it != entries_.end() && it->second.factor;
}

std::vector<std::string> Keywords::keys() const { return order_; }

const Keywords::Entry& Keywords::entry(const std::string& key) const {
  auto it = entries_.find(key);
  // Operators only read what the catalogue declares and the validator filled:
  // a miss here is a bug in aster-lite, not in the study.
  if (it == entries_.end())
    throw Error("internal error: keyword " + (path.empty() ? key : path + "/" + key) +
                " was read but is absent (check the catalogue's default or statut)");
  return it->second;
}

const std::vector<Value>& Keywords::values(const std::string& key) const { return entry(key).values; }

const Value& Keywords::value(const std::string& key) const {
  const auto& v = values(key);
  if (v.empty()) throw Error("internal error: keyword " + key + " has no value");
  return v.front();
}

double Keywords::real(const std::string& key) const { return value(key).real; }
long long Keywords::integer(const std::string& key) const {
  const Value& v = value(key);
  return v.kind == Value::Kind::Integer ? v.integer : static_cast<long long>(std::llround(v.real));
}
const std::string& Keywords::text(const std::string& key) const { return value(key).text; }

std::vector<double> Keywords::reals(const std::string& key) const {
  std::vector<double> out;
  if (!has(key)) return out;
  for (const auto& v : values(key)) out.push_back(v.real);
  return out;
}

std::vector<std::string> Keywords::texts(const std::string& key) const {
  std::vector<std::string> out;
  if (!has(key)) return out;
  for (const auto& v : values(key)) out.push_back(v.text);
  return out;
}

ConceptPtr Keywords::conceptPtr(const std::string& key) const {
  if (!has(key)) return nullptr;
  return value(key).concept;
}

std::vector<ConceptPtr> Keywords::concepts(const std::string& key) const {
  std::vector<ConceptPtr> out;
  if (!has(key)) return out;
  for (const auto& v : values(key)) out.push_back(v.concept);
  return out;
}

const std::vector<Keywords>& Keywords::factor(const std::string& key) const {
  static const std::vector<Keywords> none;
  auto it = entries_.find(key);
  if (it == entries_.end() || !it->second.factor) return none;
  return it->second.occurrences;
}

}  // namespace aster::lang
