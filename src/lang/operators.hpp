// The registry that binds a catalogue command to its C++ operator, and concept
// types to the methods a study may call on them (mesh:getNumberOfNodes()).
// Operators see validated keywords and plain C++ values, never Lua.
#pragma once
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core/concept.hpp"
#include "lang/keywords.hpp"
#include "lang/session.hpp"

namespace aster::lang {

// What a method returns to the study: a number, a text, a concept or a list of them.
struct Datum {
  enum class Kind { Nil, Integer, Real, Text, Boolean, Concept, List, Map };
  Kind kind = Kind::Nil;
  long long integer = 0;
  double real = 0;
  bool boolean = false;
  std::string text;
  ConceptPtr concept;
  std::vector<Datum> list;
  std::vector<std::pair<std::string, Datum>> map;  // a Lua table with string keys

  static Datum ofInteger(long long i) { Datum d; d.kind = Kind::Integer; d.integer = i; return d; }
  static Datum ofReal(double r) { Datum d; d.kind = Kind::Real; d.real = r; return d; }
  static Datum ofText(std::string s) { Datum d; d.kind = Kind::Text; d.text = std::move(s); return d; }
  static Datum ofBoolean(bool b) { Datum d; d.kind = Kind::Boolean; d.boolean = b; return d; }
  static Datum ofConcept(ConceptPtr c) { Datum d; d.kind = Kind::Concept; d.concept = std::move(c); return d; }
  static Datum ofList(std::vector<Datum> l) { Datum d; d.kind = Kind::List; d.list = std::move(l); return d; }
  static Datum ofMap(std::vector<std::pair<std::string, Datum>> m) {
    Datum d; d.kind = Kind::Map; d.map = std::move(m); return d;
  }
};

// An operator returns the concept it made (nullptr for a PROC). `reuse` is the
// concept given with reuse=, or nullptr.
using Operator = std::function<ConceptPtr(const Keywords& keywords, Session& session, ConceptPtr reuse)>;
using Method = std::function<Datum(Concept& self, const std::vector<Value>& args, Session& session)>;
// Fields read with a dot (mms.FORCE_INTERNE): Nil when the concept has no such field.
using FieldGetter = std::function<Datum(Concept& self, const std::string& field)>;

class Operators {
 public:
  static Operators& instance();
  void add(const std::string& command, Operator op);
  const Operator* find(const std::string& command) const;
  void addMethod(const std::string& conceptType, const std::string& method, Method m);
  const Method* findMethod(const std::string& conceptType, const std::string& method) const;
  std::vector<std::string> methodNames(const std::string& conceptType) const;
  void setFieldGetter(const std::string& conceptType, FieldGetter g) { fields_[conceptType] = std::move(g); }
  const FieldGetter* findFieldGetter(const std::string& conceptType) const {
    auto it = fields_.find(conceptType);
    return it == fields_.end() ? nullptr : &it->second;
  }

 private:
  std::map<std::string, Operator> operators_;
  std::map<std::string, std::map<std::string, Method>> methods_;
  std::map<std::string, FieldGetter> fields_;
};

// Registers at start-up: `static RegisterOperator reg("LIRE_MAILLAGE", lireMaillage);`
struct RegisterOperator {
  RegisterOperator(const std::string& command, Operator op) { Operators::instance().add(command, std::move(op)); }
};
struct RegisterMethod {
  RegisterMethod(const std::string& type, const std::string& method, Method m) {
    Operators::instance().addMethod(type, method, std::move(m));
  }
};

}  // namespace aster::lang

namespace aster::lang {
// Thrown by FIN: the study ends here, normally.
struct StudyFinished {};
}  // namespace aster::lang
