// DEFI_MATERIAU's data (ELAS, ECRO_LINE, TRACTION, PRAGER, ELAS_HYPER) and
// AFFE_MATERIAU's assignment of materials to cells. The laws are built from it
// by model/behaviour.hpp.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mechanics/von_mises_plasticity.hpp"

namespace aster::model {

// ECRO_LINE: the uniaxial curve past the yield stress SY has the slope D_SIGM_EPSI.
struct LinearHardeningData {
  double slope = 0.0;  // D_SIGM_EPSI
  double yield = 0.0;  // SY
};

// ELAS_HYPER: C10, C01, C20 and the compressibility, given as K or as NU.
struct HyperelasticData {
  double c10 = 0.0, c01 = 0.0, c20 = 0.0;
  bool bulkGiven = false;  // K given, else NU
  double bulk = 0.0, poisson = 0.0;
  double rho = 0.0;
};

// LEMAITRE: the viscous flow of LEMAITRE and NORTON, dp/dt = (s_eq / (K p^(1/M)))^N.
struct LemaitreData {
  double n = 0.0;         // N
  double inverseK = 0.0;  // UN_SUR_K
  double inverseM = 0.0;  // UN_SUR_M
};

// A material of DEFI_MATERIAU: its keywords that were given.
struct ElasticMaterial {
  bool hasElas = true;  // ELAS given (E, NU, RHO below are ELAS's)
  double E = 0.0;
  double NU = 0.0;
  double RHO = 0.0;
  bool hasRho = false;
  // The Lame constants are the law's: mechanics::IsotropicElasticity.
  std::optional<LinearHardeningData> ecroLine;       // ECRO_LINE
  std::optional<mechanics::TractionCurve> traction;  // TRACTION
  std::optional<double> prager;                      // PRAGER's C
  std::optional<HyperelasticData> hyper;             // ELAS_HYPER
  std::optional<LemaitreData> lemaitre;              // LEMAITRE
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
  // The name of the cell's material in the study (its concept's), for messages; "" when unknown.
  const std::string& materialName(int cell) const {
    static const std::string none;
    return static_cast<std::size_t>(cell) < names_.size() ? names_[cell] : none;
  }
  void assignName(const std::vector<int>& cells, const std::string& name) {
    if (names_.size() < byCell_.size()) names_.resize(byCell_.size());
    for (int c : cells) names_[c] = name;
  }

 private:
  std::vector<MaterialPtr> byCell_;
  std::vector<std::string> names_;  // per cell: the name of its material's concept
};

}  // namespace aster::model
