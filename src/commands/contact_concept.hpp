// char_contact: DEFI_CONTACT's definition, turned into solver terms once the
// mechanical system (and so the DOF numbering) exists.
#pragma once
#include <functional>
#include <memory>

#include "core/concept.hpp"
#include "analysis/additional_terms.hpp"
#include "analysis/mechanical_system.hpp"

namespace aster::lang {

class ContactConcept : public Concept {
 public:
  std::string typeName() const override { return "char_contact"; }
  std::function<std::unique_ptr<analysis::AdditionalTerms>(const analysis::MechanicalSystem&)> makeTerms;
  std::string formulation;  // DISCRETE or CONTINUE
};

}  // namespace aster::lang
