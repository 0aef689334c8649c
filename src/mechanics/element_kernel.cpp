#include "mechanics/element_kernel.hpp"

#include "core/error.hpp"
#include "mechanics/plane_element.hpp"

namespace aster::mechanics {
namespace {

template <fem::CellType T>
class PlaneKernel final : public ElementKernel {
  using Element = mechanics::PlaneElement<T>;

 public:
  PlaneKernel(const mechanics::PlaneElasticity& m, mechanics::Kinematics k) : element_(m, k) {}
  int nodes() const override { return Element::nodes; }
  int gaussPoints() const override { return element_.gaussPointCount(); }
  void internalForce(const double* X, const double* u, double* f, double* K) const override {
    const Eigen::Map<const typename Element::Coords> x(X);
    const Eigen::Map<const typename Element::Vector> uu(u);
    typename Element::Vector fe;
    typename Element::Matrix Ke;
    element_.internalForce(x, uu, f ? &fe : nullptr, K ? &Ke : nullptr);
    if (f) {
      Eigen::Map<typename Element::Vector> out(f);
      out = fe;
    }
    if (K) {
      Eigen::Map<typename Element::Matrix> out(K);
      out = Ke;
    }
  }
  void stresses(const double* X, const double* u, double* out) const override {
    element_.gaussStresses(Eigen::Map<const typename Element::Coords>(X),
                           Eigen::Map<const typename Element::Vector>(u), out);
  }
  void gaussGeometry(const double* X, double* xy, double* weightDet) const override {
    element_.gaussGeometry(Eigen::Map<const typename Element::Coords>(X), xy, weightDet);
  }

 private:
  Element element_;
};

}  // namespace

std::unique_ptr<ElementKernel> makePlaneKernel(mesh::CellType type, const mechanics::PlaneElasticity& m,
                                               mechanics::Kinematics k) {
  using MT = mesh::CellType;
  using FT = fem::CellType;
  switch (type) {
    case MT::TRIA3: return std::make_unique<PlaneKernel<FT::TRIA3>>(m, k);
    case MT::TRIA6: return std::make_unique<PlaneKernel<FT::TRIA6>>(m, k);
    case MT::QUAD4: return std::make_unique<PlaneKernel<FT::QUAD4>>(m, k);
    case MT::QUAD8: return std::make_unique<PlaneKernel<FT::QUAD8>>(m, k);
    case MT::QUAD9: return std::make_unique<PlaneKernel<FT::QUAD9>>(m, k);
    default:
      throw Error("no plane element for a " + mesh::cellTypeName(type) +
                  " cell (aster-lite has TRIA3, TRIA6, QUAD4, QUAD8, QUAD9)");
  }
}

}  // namespace aster::mechanics
