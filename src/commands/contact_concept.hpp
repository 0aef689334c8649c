// char_contact: DEFI_CONTACT's definition as plain data (zones and settings);
// STAT_NON_LINE turns it into solver terms once the mechanical system (and so
// the DOF numbering) exists (analysis::makeContactTerms).
#pragma once
#include <vector>

#include "core/concept.hpp"
#include "analysis/contact_terms.hpp"

namespace aster::lang {

class ContactConcept : public Concept {
 public:
  std::string typeName() const override { return "char_contact"; }
  std::vector<analysis::ContactZone> zones;
  analysis::ContactSettings settings;
};

}  // namespace aster::lang
