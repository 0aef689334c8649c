// AFFE_MODELE's result: which cells of the mesh carry plane mechanical elements
// and with which modelisation. Segments carry no stiffness; loads and contact
// use them as long as their nodes belong to the model.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace aster::model {

enum class Modelisation { PlaneStrain, PlaneStress };  // D_PLAN, C_PLAN

Modelisation modelisationFromName(const std::string& word);
const char* modelisationName(Modelisation m);

class Model {
 public:
  explicit Model(std::shared_ptr<mesh::Mesh> mesh);

  // Assigns the 2D cells among `cells` (segments and points are skipped); a later
  // assignment of the same cell replaces the earlier one, as in code_aster.
  // Returns the number of 2D cells assigned.
  int assign(const std::vector<int>& cells, Modelisation m);

  const mesh::Mesh& mesh() const { return *mesh_; }
  const std::shared_ptr<mesh::Mesh>& meshPtr() const { return mesh_; }
  const std::vector<int>& cells() const { return cells_; }  // 2D cells, in mesh order
  Modelisation modelisation(int k) const { return modelisation_[k]; }  // of cells()[k]
  bool hasCell(int meshCell) const { return position_[meshCell] >= 0; }
  bool nodeInModel(int node) const { return nodeUsed_[node]; }
  // Throws aster::Error naming the first node of `cells` that no element carries.
  void checkCellsOnModel(const std::vector<int>& cells, const std::string& what) const;

 private:
  void refresh();
  std::shared_ptr<mesh::Mesh> mesh_;
  std::vector<int> position_;  // mesh cell -> index in cells_, -1 when unassigned
  std::vector<Modelisation> byCell_;
  std::vector<int> cells_;
  std::vector<Modelisation> modelisation_;
  std::vector<bool> nodeUsed_;
};

}  // namespace aster::model
