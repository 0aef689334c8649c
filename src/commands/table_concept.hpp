// table_sdaster: a post::Table (POST_ELEM, POST_ERREUR, POST_RELEVE_T, CREA_TABLE),
// and the FILTRE factor keyword that IMPR_TABLE, TEST_TABLE and RECU_FONCTION share.
#pragma once
#include <vector>

#include "core/concept.hpp"
#include "lang/keywords.hpp"
#include "post/table.hpp"

namespace aster::lang {

class TableConcept : public Concept {
 public:
  explicit TableConcept(post::Table t) : table(std::move(t)) {}
  std::string typeName() const override { return "table_sdaster"; }
  post::Table table;
};

inline std::vector<post::TableFilter> tableFiltersOf(const Keywords& k) {
  std::vector<post::TableFilter> filters;
  for (const auto& occ : k.factor("FILTRE")) {
    post::TableFilter f;
    f.column = occ.text("NOM_PARA");
    f.comparison = occ.text("CRIT_COMP");
    if (occ.has("VALE")) f.reals = occ.reals("VALE");
    if (occ.has("VALE_I")) f.reals = occ.reals("VALE_I");
    if (occ.has("VALE_K")) f.texts = occ.texts("VALE_K");
    if (occ.has("CRITERE")) {  // the tolerance of EQ and NE (the catalogue's block on CRIT_COMP)
      f.relative = occ.text("CRITERE") == "RELATIF";
      f.precision = occ.real("PRECISION");
    }
    filters.push_back(f);
  }
  return filters;
}

}  // namespace aster::lang
