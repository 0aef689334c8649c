// list_inst: DEFI_LIST_INST's instants and step-cutting rule.
#pragma once
#include <vector>

#include "core/concept.hpp"

namespace aster::lang {

class ListInstConcept : public Concept {
 public:
  std::string typeName() const override { return "list_inst"; }
  std::vector<double> times;
  int subdPas = 4;
  int subdNiveau = 3;  // 0: stop at the first failure (ACTION='ARRET')
  bool subdAuto = false;   // SUBD_METHODE='AUTO'
  double subdPasMini = 0;  // SUBD_PAS_MINI
};

}  // namespace aster::lang
