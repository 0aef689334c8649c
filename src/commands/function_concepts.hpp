// Concepts of the function family: formulas (formule), tabulated and constant
// functions (fonction_sdaster) and lists of reals (listr8_sdaster).
#pragma once
#include <string>
#include <vector>

#include "core/concept.hpp"
#include "expr/constant.hpp"
#include "expr/function.hpp"
#include "expr/tabulated.hpp"
#include "lang/keywords.hpp"

namespace aster::lang {

class FunctionConcept : public Concept {
 public:
  FunctionConcept(std::string type, expr::FunctionPtr f) : function(std::move(f)), type_(std::move(type)) {}
  std::string typeName() const override { return type_; }
  expr::FunctionPtr function;

 private:
  std::string type_;
};

class RealListConcept : public Concept {
 public:
  explicit RealListConcept(std::vector<double> v) : values(std::move(v)) {}
  std::string typeName() const override { return "listr8_sdaster"; }
  std::vector<double> values;
};

// The function behind a keyword that takes a formule or a fonction_sdaster.
expr::FunctionPtr functionOf(const ConceptPtr& c);

// The keywords of C_INTERPOL_PROL (INTERPOL, PROL_GAUCHE, PROL_DROITE) as the
// options of a tabulated function.
expr::TabulatedOptions tabulatedOptionsOf(const Keywords& k);

}  // namespace aster::lang
