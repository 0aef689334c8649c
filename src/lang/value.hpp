// One item of a simple keyword's value, as given in a study: a number, a text,
// a concept, a study function, or a name for a concept to be created (CO).
#pragma once
#include <string>

#include "core/callable.hpp"
#include "core/concept.hpp"

namespace aster::lang {

struct Value {
  enum class Kind { Integer, Real, Text, Concept, Function, NewName, Other };
  Kind kind = Kind::Other;
  long long integer = 0;
  double real = 0.0;
  std::string text;        // Text, NewName (CO('name')), or a description of Other
  ConceptPtr concept;      // Concept
  CallablePtr function;    // Function

  static Value ofInteger(long long i) { Value v; v.kind = Kind::Integer; v.integer = i; v.real = double(i); return v; }
  static Value ofReal(double r) { Value v; v.kind = Kind::Real; v.real = r; return v; }
  static Value ofText(std::string s) { Value v; v.kind = Kind::Text; v.text = std::move(s); return v; }
  static Value ofConcept(ConceptPtr c) { Value v; v.kind = Kind::Concept; v.concept = std::move(c); return v; }
  static Value ofFunction(CallablePtr f) { Value v; v.kind = Kind::Function; v.function = std::move(f); return v; }
  static Value ofNewName(std::string s) { Value v; v.kind = Kind::NewName; v.text = std::move(s); return v; }
  static Value other(std::string what) { Value v; v.kind = Kind::Other; v.text = std::move(what); return v; }

  bool isNumber() const { return kind == Kind::Integer || kind == Kind::Real; }
  // How the value reads in a message: 3, 0.5, 'ASTER', a maillage_sdaster, ...
  std::string describe() const;
};

// A text as a message shows it: NUL bytes (which Lua strings may hold) as \0.
std::string visibleText(const std::string& text);

}  // namespace aster::lang
