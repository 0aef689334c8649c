#include "mechanics/element_kernel.hpp"

#include "core/error.hpp"
#include "mechanics/isotropic_elasticity.hpp"
#include "mechanics/plane_element.hpp"

namespace aster::mechanics {
namespace {

template <fem::CellType T, class Law>
class PlaneKernel final : public ElementKernel {
  using Element = mechanics::PlaneElement<T, Law>;

 public:
  PlaneKernel(std::shared_ptr<const Law> law, Kinematics k) : element_(std::move(law), k) {}
  int nodes() const override { return Element::nodes; }
  int gaussPoints() const override { return element_.gaussPointCount(); }
  int internalVariables() const override { return element_.internalVariableCount(); }
  bool usesHistory() const override { return Law::kUsesHistory; }
  void internalForce(const double* X, const double* u, const ElementHistory& history, double* variables, double* f,
                     double* K) const override {
    const Eigen::Map<const typename Element::Coords> x(X);
    const Eigen::Map<const typename Element::Vector> uu(u);
    typename Element::Vector fe;
    typename Element::Matrix Ke;
    element_.internalForce(x, uu, history, variables, f ? &fe : nullptr, K ? &Ke : nullptr);
    if (f) {
      Eigen::Map<typename Element::Vector> out(f);
      out = fe;
    }
    if (K) {
      Eigen::Map<typename Element::Matrix> out(K);
      out = Ke;
    }
  }
  void stresses(const double* X, const double* u, const ElementHistory& history, double* out,
                double* variables, bool cauchy) const override {
    element_.gaussStresses(Eigen::Map<const typename Element::Coords>(X),
                           Eigen::Map<const typename Element::Vector>(u), history, out, variables, cauchy);
  }
  void gaussGeometry(const double* X, double* xy, double* weightDet) const override {
    element_.gaussGeometry(Eigen::Map<const typename Element::Coords>(X), xy, weightDet);
  }

 private:
  Element element_;
};

template <fem::CellType T>
std::unique_ptr<ElementKernel> makeKernel(std::shared_ptr<const BehaviourLaw> law, Kinematics k) {
  // GDEF_LOG wraps the law (plane_element.hpp): the BehaviourLaw element only.
  if (auto elastic = k == Kinematics::Logarithmic ? nullptr : std::dynamic_pointer_cast<const IsotropicElasticity>(law))
    return std::make_unique<PlaneKernel<T, IsotropicElasticity>>(std::move(elastic), k);
  return std::make_unique<PlaneKernel<T, BehaviourLaw>>(std::move(law), k);
}

}  // namespace

std::unique_ptr<ElementKernel> makePlaneKernel(mesh::CellType type, std::shared_ptr<const BehaviourLaw> law,
                                               Kinematics k) {
  using MT = mesh::CellType;
  using FT = fem::CellType;
  switch (type) {
    case MT::TRIA3: return makeKernel<FT::TRIA3>(std::move(law), k);
    case MT::TRIA6: return makeKernel<FT::TRIA6>(std::move(law), k);
    case MT::QUAD4: return makeKernel<FT::QUAD4>(std::move(law), k);
    case MT::QUAD8: return makeKernel<FT::QUAD8>(std::move(law), k);
    case MT::QUAD9: return makeKernel<FT::QUAD9>(std::move(law), k);
    default:
      throw Error("no plane element for a " + mesh::cellTypeName(type) +
                  " cell (aster-lite has TRIA3, TRIA6, QUAD4, QUAD8, QUAD9)");
  }
}

}  // namespace aster::mechanics
