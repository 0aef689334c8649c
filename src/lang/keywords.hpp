// A keyword tree: one level of a command call (or of one occurrence of a factor
// keyword). The interpreter builds a raw tree from the study; the validator
// checks it against the catalogue and returns the tree operators read, with
// defaults filled and numbers typed. Operators read it through typed accessors.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "lang/value.hpp"

namespace aster::lang {

class Keywords {
 public:
  // ---- building (interpreter, validator) ----
  void setSimple(const std::string& key, std::vector<Value> values);
  void setFactor(const std::string& key, std::vector<Keywords> occurrences);
  void erase(const std::string& key);

  // ---- reading ----
  // A keyword with a catalogue default is always present after validation, so
  // there is no reading with a fallback: the catalogue is the one source of
  // defaults. A keyword without one is read after has().
  bool has(const std::string& key) const;
  bool isFactor(const std::string& key) const;
  std::vector<std::string> keys() const;  // in the order they were set

  const std::vector<Value>& values(const std::string& key) const;
  const Value& value(const std::string& key) const;  // the single value
  double real(const std::string& key) const;
  long long integer(const std::string& key) const;
  const std::string& text(const std::string& key) const;
  std::vector<double> reals(const std::string& key) const;
  std::vector<std::string> texts(const std::string& key) const;
  ConceptPtr conceptPtr(const std::string& key) const;
  template <class C>
  std::shared_ptr<C> concept(const std::string& key) const {
    return std::dynamic_pointer_cast<C>(conceptPtr(key));
  }
  std::vector<std::shared_ptr<Concept>> concepts(const std::string& key) const;
  const std::vector<Keywords>& factor(const std::string& key) const;  // empty when absent

  // Where this level comes from, for messages: "AFFE[2]" or "" for the command level.
  std::string path;

 private:
  struct Entry {
    bool factor = false;
    std::vector<Value> values;
    std::vector<Keywords> occurrences;
  };
  const Entry& entry(const std::string& key) const;
  std::vector<std::string> order_;
  std::map<std::string, Entry> entries_;
};

}  // namespace aster::lang
