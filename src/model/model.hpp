// AFFE_MODELE's result: which cells of the mesh carry plane mechanical elements
// and with which modelisation. Assigned segments carry no stiffness but their
// nodes get DX, DY (loads and contact use them: a rigid contact master that is
// only a segment, like SSNP150's MAITRE, is held by AFFE_CHAR_CINE).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "mechanics/modelling.hpp"
#include "mesh/mesh.hpp"

namespace aster::model {

// D_PLAN, C_PLAN, AXIS: the element's hypothesis (mechanics/modelling.hpp).
using Modelisation = mechanics::PlaneHypothesis;

class Model {
 public:
  explicit Model(std::shared_ptr<mesh::Mesh> mesh);

  // Assigns the 2D cells and segments among `cells` (points are skipped); a later
  // assignment of the same cell replaces the earlier one, as in code_aster.
  // Returns the number of cells assigned.
  int assign(const std::vector<int>& cells, Modelisation m);

  const mesh::Mesh& mesh() const { return *mesh_; }
  const std::shared_ptr<mesh::Mesh>& meshPtr() const { return mesh_; }
  const std::vector<int>& cells() const { return cells_; }  // 2D cells, in mesh order
  const std::vector<int>& segments() const { return segments_; }  // assigned segments
  Modelisation modelisation(int k) const { return modelisation_[k]; }  // of cells()[k]
  // Whether the model is axisymmetric (AXIS): its loads are then per radian,
  // weighted by r. AFFE_MODELE does not mix AXIS with D_PLAN/C_PLAN.
  bool axisymmetric() const { return axisymmetric_; }
  bool hasCell(int meshCell) const { return position_[meshCell] >= 0; }
  bool nodeInModel(int node) const { return nodeUsed_[node]; }
  // Throws aster::Error naming the first node of `cells` that no element carries.
  void checkCellsOnModel(const std::vector<int>& cells, const std::string& what) const;

 private:
  void refresh();
  std::shared_ptr<mesh::Mesh> mesh_;
  std::vector<char> assigned_;  // per mesh cell
  std::vector<int> position_;   // mesh cell -> index in cells_, -1 when not a 2D cell of the model
  std::vector<Modelisation> byCell_;
  std::vector<int> cells_;
  std::vector<int> segments_;
  std::vector<Modelisation> modelisation_;
  std::vector<bool> nodeUsed_;
  bool axisymmetric_ = false;
};

}  // namespace aster::model
