// DEFI_MATERIAU's data (ELAS, ECRO_LINE, TRACTION, PRAGER, ELAS_HYPER, VISC_DRUC_PRAG,
// LEMAITRE, VISC_ENDO, DRUCK_PRAGER) and
// AFFE_MATERIAU's assignment of materials to cells. The laws are built from it
// by model/behaviour.hpp.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mechanics/von_mises_plasticity.hpp"
#include "mechanics/visc_drucker_prager.hpp"

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

// LEMAITRE: Lemaitre's viscous flow, r' = ((sigma_eq - SY) / (K r^(1/M)))^N, K = 1/UN_SUR_K.
struct LemaitreData {
  double n = 0.0;       // N
  double unSurK = 0.0;  // UN_SUR_K
  double unSurM = 0.0;  // UN_SUR_M
};

// VISC_ENDO: the threshold and the damage of VISC_ENDO_LEMA.
struct ViscousDamageData {
  double yield = 0.0;  // SY
  double rD = 0.0;     // R_D
  double aD = 0.0;     // A_D
};

// DRUCK_PRAGER: the yield function and hardening of the Drucker-Prager laws.
struct DruckerPragerData {
  double alpha = 0.0, yield = 0.0, ultimateStrain = 0.0;  // ALPHA, SY, P_ULTM
  bool parabolic = false;                                 // ECROUISSAGE='PARABOLIQUE' (else LINEAIRE)
  double slope = 0.0;                                     // H (LINEAIRE)
  double ultimateYield = 0.0;                             // SY_ULTM (PARABOLIQUE)
  double dilatancy = 0.0;                                 // DILAT
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
  std::optional<mechanics::ViscDruckerPragerMaterial> viscDrucPrag;  // VISC_DRUC_PRAG
  std::optional<LemaitreData> lemaitre;              // LEMAITRE
  std::optional<ViscousDamageData> viscEndo;         // VISC_ENDO
  std::optional<DruckerPragerData> druckerPrager;    // DRUCK_PRAGER
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
