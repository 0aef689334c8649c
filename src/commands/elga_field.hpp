// Fields at the Gauss points of a model's cells (cham_elem, TYPE_CHAM ELGA_*):
// made by CREA_CHAMP (AFFE, DISC, EVAL, ASSE, EXTR of SIEF_ELGA), read by
// POST_ELEM NORME and TEST_RESU CHAM_ELEM.
//
// The points are the model's integration points (post::modelGaussPoints): the
// mechanics' full rule on surface cells, the segment's own rule on the edge
// cells the model carries. The field lives on some cells of the model
// (field.cells, in mesh order), each with its own number of points; a component
// may be absent on some of them (present == 0; its values are then 0).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "commands/result_concepts.hpp"
#include "expr/function.hpp"
#include "lang/keywords.hpp"
#include "model/model.hpp"

namespace aster::lang {

struct Session;

class ElgaFieldConcept : public CellFieldConcept {
 public:
  ElgaFieldConcept(std::shared_ptr<model::Model> m, std::string q, CellField f)
      : CellFieldConcept(m->meshPtr(), std::move(f)), model(std::move(m)), quantity(std::move(q)) {}
  std::shared_ptr<model::Model> model;
  std::string quantity;       // NEUT, DEPL, GEOM, SIEF
  std::vector<char> present;  // present[k * components + c]: component c is defined on field.cells[k]
  // ELGA_*_F: one function per cell and component, the same at every point of
  // the cell (null: zero); field.values stay zero.
  bool functionField = false;
  std::vector<expr::FunctionPtr> functions;
};

// A field taken from a result (resu:getField('SIEF_ELGA')) has every component
// on every cell.
inline bool componentPresent(const CellFieldConcept& f, std::size_t k, std::size_t c) {
  const auto* e = dynamic_cast<const ElgaFieldConcept*>(&f);
  return !e || e->present.empty() || e->present[k * f.field.components.size() + c];
}

// CREA_CHAMP towards TYPE_CHAM ELGA_<quantity>_<R|F> (crea_champ.cpp dispatches
// here): AFFE, DISC (from a nodal field), EVAL, ASSE, EXTR (SIEF_ELGA of a result).
ConceptPtr creaChampElga(const Keywords& k, Session& session, const std::string& typeCham,
                         const std::string& quantity, bool functions);

}  // namespace aster::lang
