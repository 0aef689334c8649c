// DEFI_MATERIAU's ELAS and AFFE_MATERIAU's assignment of materials to cells.
#pragma once
#include <memory>
#include <string>
#include <vector>

namespace aster::model {

struct ElasticMaterial {
  double E = 0.0;
  double NU = 0.0;
  double RHO = 0.0;
  bool hasRho = false;
  // The Lame constants are the law's: mechanics::IsotropicElasticity.
};

using MaterialPtr = std::shared_ptr<const ElasticMaterial>;

// One material per mesh cell (null where none was assigned).
class MaterialField {
 public:
  explicit MaterialField(int cellCount) : byCell_(cellCount) {}
  void assign(const std::vector<int>& cells, MaterialPtr m) {
    for (int c : cells) byCell_[c] = m;
  }
  const ElasticMaterial* at(int cell) const { return byCell_[cell].get(); }

 private:
  std::vector<MaterialPtr> byCell_;
};

}  // namespace aster::model
