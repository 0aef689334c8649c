#include "model/model.hpp"

#include "core/error.hpp"

namespace aster::model {

Model::Model(std::shared_ptr<mesh::Mesh> mesh)
    : mesh_(std::move(mesh)),
      assigned_(mesh_->cellCount(), 0),
      position_(mesh_->cellCount(), -1),
      byCell_(mesh_->cellCount(), Modelisation::PlaneStrain),
      nodeUsed_(mesh_->nodeCount(), false) {}

int Model::assign(const std::vector<int>& cells, Modelisation m) {
  int count = 0;
  for (int c : cells) {
    const int dim = mesh::topologicalDimension(mesh_->cellType(c));
    if (dim != 1 && dim != 2) continue;
    assigned_[c] = 1;
    byCell_[c] = m;
    ++count;
  }
  refresh();
  return count;
}

void Model::refresh() {
  cells_.clear();
  segments_.clear();
  modelisation_.clear();
  std::fill(nodeUsed_.begin(), nodeUsed_.end(), false);
  axisymmetric_ = false;
  for (int c = 0; c < mesh_->cellCount(); ++c) {
    position_[c] = -1;
    if (!assigned_[c]) continue;
    axisymmetric_ |= byCell_[c] == Modelisation::Axisymmetric;
    for (int n : mesh_->cellNodes(c)) nodeUsed_[n] = true;
    if (mesh::topologicalDimension(mesh_->cellType(c)) == 1) {
      segments_.push_back(c);
      continue;
    }
    position_[c] = static_cast<int>(cells_.size());
    cells_.push_back(c);
    modelisation_.push_back(byCell_[c]);
  }
}

void Model::checkCellsOnModel(const std::vector<int>& cells, const std::string& what) const {
  for (int c : cells)
    for (int n : mesh_->cellNodes(c))
      if (!nodeUsed_[n])
        throw Error(what + ": node " + mesh_->nodeName(n) + " of cell " + mesh_->cellName(c) +
                    " carries no element of the model (AFFE_MODELE covers it?)");
}

}  // namespace aster::model
