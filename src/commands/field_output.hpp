// Cell fields of results (CellField) in the form the MED, gmsh and VTK writers
// take (mesh::CellValues): the values, and for fields at Gauss points the
// model's integration points per cell type (post::modelGaussPoints' rules:
// fem::fullSurfaceRule, fem::fullEdgeRule, code_aster's families) on code_aster's
// reference cells.
#pragma once
#include "commands/result_concepts.hpp"
#include "mesh/nodal_field.hpp"

namespace aster::lang {

// Throws aster::Error when a cell of a Gauss point field has another number of
// points than the model's rule for its type.
mesh::CellValues cellValuesOf(const mesh::Mesh& mesh, const CellField& f);

// VTK names the components of an array: the internal variables V1, V2, ... of a VARI_*
// field take the laws' names (`names`: EPSPEQ, INDIPLAS, ...) there; other fields, or
// no names, are left as they are.
void nameInternalVariables(const std::string& field, std::vector<std::string>& components,
                           const std::vector<std::string>& names);

// The fields of one instant of a result, nodal and on cells.
mesh::FieldInstant fieldInstantOf(const mesh::Mesh& mesh, const ResultInstant& instant);

}  // namespace aster::lang
