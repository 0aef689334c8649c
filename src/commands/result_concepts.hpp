// Concepts holding computed fields: cham_no_sdaster (one nodal field), cham_elem
// (one field on cells: at their Gauss points, ELGA, or at their nodes, ELNO) and
// the results evol_noli (STAT_NON_LINE's) and evol_elas (MECA_STATIQUE's): nodal
// and cell fields per instant. Nodal fields are stored per mesh node (node-major,
// components in order), the form the MED / GMSH / VTK writers take.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/concept.hpp"
#include "mesh/mesh.hpp"
#include "mesh/nodal_field.hpp"
#include "model/material.hpp"
#include "model/model.hpp"

namespace aster::lang {

class NodalFieldConcept : public Concept {
 public:
  NodalFieldConcept(std::shared_ptr<mesh::Mesh> m, mesh::NodalField f) : mesh(std::move(m)), field(std::move(f)) {}
  std::string typeName() const override { return "cham_no_sdaster"; }
  std::shared_ptr<mesh::Mesh> mesh;
  mesh::NodalField field;
  // Nodes where the field is defined (empty: every node of the mesh).
  std::vector<int> support;
};

// Where a cell field's values sit in each cell: at its Gauss points (ELGA, the
// model's integration points) or at its nodes, in the cell's node order (ELNO).
enum class CellLocation { GaussPoints, Nodes };

// Values per cell of the model (SIEF_ELGA, SIGM_ELNO, ...): `values` holds, for
// each cell of `cells` in order, points(k) * components.size() numbers, point
// after point (a point: a Gauss point, or a node of the cell).
struct CellField {
  std::string name;
  std::vector<std::string> components;
  std::vector<int> cells;
  std::vector<int> offsets;  // into values, per cell, size cells.size()+1
  std::vector<double> values;
  CellLocation location = CellLocation::GaussPoints;
};

// The number of points (Gauss points or nodes) of field.cells[k].
inline int pointsOf(const CellField& f, std::size_t k) {
  const std::size_t nc = f.components.size();
  return nc ? static_cast<int>((f.offsets[k + 1] - f.offsets[k]) / static_cast<int>(nc)) : 0;
}

// One field on cells, as resu:getField('SIEF_ELGA', inst) gives it:
// getValues() is `field.values` (cell after cell of field.cells, point after
// point, components in the order of getComponents()).
class CellFieldConcept : public Concept {
 public:
  CellFieldConcept(std::shared_ptr<mesh::Mesh> m, CellField f) : mesh(std::move(m)), field(std::move(f)) {}
  std::string typeName() const override { return "cham_elem"; }
  std::shared_ptr<mesh::Mesh> mesh;
  CellField field;
};

struct ResultInstant {
  int index = 0;      // NUME_ORDRE
  double time = 0.0;  // INST
  std::vector<mesh::NodalField> nodal;  // DEPL, REAC_NODA, ...
  std::vector<CellField> cells;         // SIEF_ELGA, SIGM_ELNO, ...
  // The nodes where a nodal field computed on part of the model (CALC_CHAMP's
  // GROUP_MA) is defined, sorted; a field not listed is defined at every node of the model.
  std::map<std::string, std::vector<int>> nodalSupport;
  int newtonIterations = 0;
  // Fields the computation was told not to store (STAT_NON_LINE's ARCHIVAGE/CHAM_EXCLU).
  std::vector<std::string> excluded;
};

// The physical quantity of a field of a result, as in TYPE_CHAM (ELNO_SIEF_R):
// SIEF for SIEF_*, SIGM_*, SIEQ_*; EPSI for EPSI_*, EPSG_*; VARI for VARI_*; DEPL
// for DEPL, FORC_NODA, REAC_NODA; "" for any other.
std::string quantityOfField(const std::string& name);

class ResultConcept : public Concept {
 public:
  // `type`: evol_noli or evol_elas; both hold the same fields and serve the same commands.
  explicit ResultConcept(std::shared_ptr<model::Model> m, std::string type = "evol_noli")
      : model(std::move(m)), type_(std::move(type)) {}
  std::string typeName() const override { return type_; }
  std::shared_ptr<model::Model> model;
  // The materials the result was computed with (CALC_CHAMP's default CHAM_MATER); may be null.
  std::shared_ptr<const model::MaterialField> materials;
  std::vector<ResultInstant> instants;
  // The laws' names of the internal variables V1, V2, ... (NOM_VARI: EPSPEQ, ...), when
  // the laws of the result share them; empty otherwise.
  std::vector<std::string> variableNames;
  // Computed in large strain (DEFORMATION='GROT_GDEP' on some cell).
  bool largeStrain = false;

  // The instant closest to `time` within `precision` (relative, as code_aster's
  // CRITERE='RELATIF'); throws aster::Error listing the instants otherwise.
  const ResultInstant& at(double time, double precision = 1e-6) const;
  const ResultInstant& last() const;
  // Throws, saying so, when `name` was excluded from the instant (ARCHIVAGE/CHAM_EXCLU).
  static void requireNotExcluded(const ResultInstant& i, const std::string& name);
  // A field of an instant by name; throws listing the available ones.
  static const mesh::NodalField& nodalField(const ResultInstant& i, const std::string& name);
  // A cell field (ELGA or ELNO) of an instant, or null.
  static const CellField* cellField(const ResultInstant& i, const std::string& name);
  // The nodes where a nodal field of an instant is defined: its nodalSupport entry,
  // or the nodes of the model.
  std::vector<int> nodalSupportOf(const ResultInstant& i, const std::string& name) const;

 private:
  std::string type_;
};

}  // namespace aster::lang
