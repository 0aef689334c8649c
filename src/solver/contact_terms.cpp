#include "solver/contact_terms.hpp"

#include <algorithm>
#include <map>
#include <string>

#include "contact/discrete.hpp"
#include "contact/gap.hpp"
#include "contact/projection.hpp"
#include "core/error.hpp"

namespace aster::solver {
namespace {

// What both formulations need: current positions, segments, DOF lists.
class ContactBase : public AdditionalTerms {
 public:
  ContactBase(const MechanicalSystem& system, std::vector<ContactZone> zones, const ContactSettings& settings)
      : system_(system), mesh_(system.model().mesh()), zones_(std::move(zones)), settings_(settings) {
    projection_.outsideTolerance = settings.outsideTolerance;
    for (const auto& z : zones_) {
      for (int c : z.masterCells) checkSegment(c, "master");
      for (int c : z.slaveCells) checkSegment(c, "slave");
    }
  }
  void setFirstUnknown(int first) override { first_ = first; }

 protected:
  void checkSegment(int c, const char* role) const {
    const auto t = mesh_.cellType(c);
    if (t != mesh::CellType::SEG2 && t != mesh::CellType::SEG3)
      throw Error(std::string("contact ") + role + " cell " + mesh_.cellName(c) + " is a " + mesh::cellTypeName(t) +
                  "; contact surfaces are made of SEG2 or SEG3");
  }
  Eigen::Vector2d position(int node, const Eigen::VectorXd* U) const {
    const Eigen::Vector3d X = mesh_.node(node);
    Eigen::Vector2d x(X(0), X(1));
    if (U)
      for (int k = 0; k < 2; ++k) {
        const int d = system_.dof(node, k);
        if (d >= 0) x(k) += (*U)(d);
      }
    return x;
  }
  contact::Segment segment(int cell, const Eigen::VectorXd* U) const {
    const auto n = mesh_.cellNodes(cell);
    if (mesh_.cellType(cell) == mesh::CellType::SEG3)
      return contact::Segment::seg3(position(n[0], U), position(n[1], U), position(n[2], U));
    return contact::Segment::seg2(position(n[0], U), position(n[1], U));
  }
  void appendDofs(int cell, std::vector<int>& dofs) const {
    for (int n : mesh_.cellNodes(cell)) {
      dofs.push_back(system_.dof(n, 0));
      dofs.push_back(system_.dof(n, 1));
    }
  }
  std::vector<contact::Segment> masters(const ContactZone& z, const Eigen::VectorXd& U) const {
    std::vector<contact::Segment> out;
    for (int c : z.masterCells) out.push_back(segment(c, &U));
    return out;
  }
  static void addLocal(const std::vector<int>& dofs, const Eigen::VectorXd& res, Eigen::VectorXd& r) {
    for (std::size_t i = 0; i < dofs.size(); ++i)
      if (dofs[i] >= 0) r(dofs[i]) += res(static_cast<Eigen::Index>(i));
  }

  const MechanicalSystem& system_;
  const mesh::Mesh& mesh_;
  std::vector<ContactZone> zones_;
  ContactSettings settings_;
  contact::ProjectionOptions projection_;
  int first_ = 0;
};

// ---------------------------------------------------------------- DISCRETE
class DiscreteContact final : public ContactBase {
 public:
  DiscreteContact(const MechanicalSystem& system, std::vector<ContactZone> zones, const ContactSettings& settings)
      : ContactBase(system, std::move(zones), settings) {
    for (std::size_t z = 0; z < zones_.size(); ++z) {
      std::vector<char> seen(mesh_.nodeCount(), 0);
      for (int c : zones_[z].slaveCells)
        for (int n : mesh_.cellNodes(c))
          if (!seen[n]) {
            seen[n] = 1;
            nodes_.push_back({n, static_cast<int>(z), -1, contact::Projection{}});
          }
    }
    active_.assign(nodes_.size(), false);
  }
  int unknownCount() const override { return static_cast<int>(nodes_.size()); }

  bool update(const Eigen::VectorXd& U) override {
    bool changed = false;
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      auto& sn = nodes_[i];
      const auto m = masters(zones_[sn.zone], U);
      const auto p = contact::projectOnMaster(position(sn.node, &U), m, projection_);
      changed |= p.segment != sn.segment;
      sn.segment = p.segment;
      sn.projection = p.projection;
      // As code_aster's CONTACT_INIT='INTERPENETRE': nodes touching or
      // penetrating at the start are active from the first iteration.
      if (!started_ && p.paired() && p.projection.gap <= 0) active_[i] = true;
    }
    started_ = true;
    return changed;
  }

  void elementDofs(fem::ElementDofs& out) const override {
    for (std::size_t i = 0; i < nodes_.size(); ++i) out.add(nodeDofs(i));
  }

  void assemble(const Eigen::VectorXd& U, Eigen::VectorXd& r, const fem::AssemblyPattern& pattern, int firstElement,
                fem::SparseMatrix* K) const override {
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      const auto& sn = nodes_[i];
      const auto dofs = nodeDofs(i);
      const int m = static_cast<int>(dofs.size());
      const double lambda = U(first_ + static_cast<int>(i));
      Eigen::VectorXd res = Eigen::VectorXd::Zero(m);
      Eigen::MatrixXd Ke = Eigen::MatrixXd::Zero(m, m);
      if (sn.segment >= 0) {
        const auto seg = segment(zones_[sn.zone].masterCells[sn.segment], &U);
        const auto gap = contact::linearizeGap(position(sn.node, &U), seg, sn.projection);
        const auto t = contact::discreteNodeTerms(gap, lambda, active_[i]);
        const int q = m - 1;
        res.head(q) = t.residualU.head(q);
        res(q) = t.residualLambda;
        Ke.topLeftCorner(q, q) = t.tangentUU.topLeftCorner(q, q);
        Ke.col(q).head(q) = t.tangentULambda.head(q);
        Ke.row(q).head(q) = t.tangentULambda.head(q).transpose();
        Ke(q, q) = t.tangentLambdaLambda;
      } else {
        res(m - 1) = lambda;  // unpaired: lambda = 0
        Ke(m - 1, m - 1) = 1.0;
      }
      addLocal(dofs, res, r);
      if (K) pattern.addMatrix(firstElement + static_cast<int>(i), Ke.data(), K->valuePtr());
    }
  }

  bool updateStatus(const Eigen::VectorXd& U) override {
    std::vector<double> gaps(nodes_.size(), 1.0), lambdas(nodes_.size(), 0.0);
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      const auto& sn = nodes_[i];
      lambdas[i] = U(first_ + static_cast<int>(i));
      const auto p = contact::projectOnMaster(position(sn.node, &U), masters(zones_[sn.zone], U), projection_);
      gaps[i] = p.paired() ? p.projection.gap : 1.0;
    }
    return contact::updateActiveSet(gaps, lambdas, active_).changed();
  }

  std::string statusText() const override {
    return std::to_string(std::count(active_.begin(), active_.end(), true)) + " active";
  }
  void saveStatus() override { saved_ = active_; }
  void restoreStatus() override { active_ = saved_; }

  void outputFields(const Eigen::VectorXd& U, std::vector<mesh::NodalField>& fields) const override {
    mesh::NodalField f{"CONT_NOEU", {"CONT", "JEU", "RN"}, std::vector<double>(3 * mesh_.nodeCount(), 0.0)};
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      const int n = nodes_[i].node;
      const auto p = contact::projectOnMaster(position(n, &U), masters(zones_[nodes_[i].zone], U), projection_);
      f.values[3 * n] = active_[i] ? 1.0 : 0.0;
      f.values[3 * n + 1] = p.paired() ? p.projection.gap : 0.0;
      f.values[3 * n + 2] = U(first_ + static_cast<int>(i));
    }
    fields.push_back(std::move(f));
  }

 private:
  struct SlaveNode {
    int node;
    int zone;
    int segment;  // index in the zone's master cells, -1 when unpaired
    contact::Projection projection;
  };
  std::vector<int> nodeDofs(std::size_t i) const {
    const auto& sn = nodes_[i];
    std::vector<int> dofs = {system_.dof(sn.node, 0), system_.dof(sn.node, 1)};
    if (sn.segment >= 0) appendDofs(zones_[sn.zone].masterCells[sn.segment], dofs);
    dofs.push_back(first_ + static_cast<int>(i));
    return dofs;
  }
  std::vector<SlaveNode> nodes_;
  std::vector<bool> active_, saved_;
  bool started_ = false;
};

// ---------------------------------------------------------------- CONTINUE
class ContinueContact final : public ContactBase {
 public:
  ContinueContact(const MechanicalSystem& system, std::vector<ContactZone> zones, const ContactSettings& settings)
      : ContactBase(system, std::move(zones), settings) {
    options_.rho = settings.rho;
    options_.integration = settings.integration;
    options_.gaussPoints = settings.gaussPoints;
    options_.projection = projection_;
    options_.multiplierInterpolation = settings.multipliers;
    const bool quadratic = settings.multipliers == contact::MultiplierInterpolation::Quadratic;
    std::map<int, int> lagsIndex;
    for (std::size_t z = 0; z < zones_.size(); ++z)
      for (int c : zones_[z].slaveCells) {
        const auto n = mesh_.cellNodes(c);
        SlaveCell sc{c, static_cast<int>(z), 2, {}, {}};
        if (quadratic && mesh_.cellType(c) == mesh::CellType::SEG3) sc.count = 3;
        for (int v = 0; v < sc.count; ++v) {
          auto it = lagsIndex.find(n[v]);
          if (it == lagsIndex.end()) {
            it = lagsIndex.emplace(n[v], static_cast<int>(lagsNodes_.size())).first;
            lagsNodes_.push_back(n[v]);
          }
          sc.lags[v] = it->second;
        }
        cells_.push_back(sc);
      }
  }
  int unknownCount() const override { return static_cast<int>(lagsNodes_.size()); }

  // Candidate masters of a slave cell: the segments its nodes and midpoints
  // project on (the nearest one when none is paired).
  bool update(const Eigen::VectorXd& U) override {
    bool changed = false;
    for (auto& sc : cells_) {
      const auto& zone = zones_[sc.zone];
      const auto m = masters(zone, U);
      const auto slave = segment(sc.cell, &U);
      std::vector<int> cand;
      double nearest = 1e300;
      int nearestSeg = 0;
      for (int k = 0; k <= 8; ++k) {
        const double xi = -1.0 + k / 4.0;
        const auto sh = contact::segmentShape(slave.type, xi);
        const Eigen::Vector2d x = slave.x.transpose() * sh.N;
        const auto p = contact::projectOnMaster(x, m, projection_);
        if (p.paired()) {
          cand.push_back(p.segment);
        } else {
          for (std::size_t s = 0; s < m.size(); ++s) {
            const auto q = contact::projectOnSegment(x, m[s], projection_);
            if (q.distance < nearest) {
              nearest = q.distance;
              nearestSeg = static_cast<int>(s);
            }
          }
        }
      }
      if (cand.empty()) cand.push_back(nearestSeg);
      std::sort(cand.begin(), cand.end());
      cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
      changed |= cand != sc.candidates;
      sc.candidates = cand;
    }
    return changed;
  }

  void elementDofs(fem::ElementDofs& out) const override {
    for (const auto& sc : cells_) out.add(cellDofs(sc));
  }

  void assemble(const Eigen::VectorXd& U, Eigen::VectorXd& r, const fem::AssemblyPattern& pattern, int firstElement,
                fem::SparseMatrix* K) const override {
    active_ = 0;
    for (std::size_t i = 0; i < cells_.size(); ++i) {
      const auto& sc = cells_[i];
      contact::SlaveCell slave;
      const bool seg3 = mesh_.cellType(sc.cell) == mesh::CellType::SEG3;
      slave.type = seg3 ? fem::CellType::SEG3 : fem::CellType::SEG2;
      const auto nodes = mesh_.cellNodes(sc.cell);
      for (int a = 0; a < nodes.size(); ++a) {
        slave.reference.row(a) = position(nodes[a], nullptr).transpose();
        slave.current.row(a) = position(nodes[a], &U).transpose();
      }
      for (int v = 0; v < sc.count; ++v) slave.lagsC(v) = U(first_ + sc.lags[v]);
      std::vector<contact::Segment> m;
      for (int s : sc.candidates) m.push_back(segment(zones_[sc.zone].masterCells[s], &U));
      contact::continueCellTerms(slave, m, options_, terms_);
      for (const auto& p : terms_.points) active_ += p.status == contact::PointStatus::Contact;
      const auto dofs = cellDofs(sc);
      addLocal(dofs, terms_.residual, r);
      if (K) pattern.addMatrix(firstElement + static_cast<int>(i), terms_.tangent.data(), K->valuePtr());
    }
  }

  // The statuses are re-evaluated at every assembly (generalized Newton): a
  // small residual already means they are consistent.
  bool updateStatus(const Eigen::VectorXd&) override { return false; }
  std::string statusText() const override { return std::to_string(active_) + " points in contact"; }
  void saveStatus() override {}
  void restoreStatus() override {}

  // LAGS_C joins DEPL at its nodes; the middle node of a SEG3 slave whose
  // LAGS_C is linear shows the value of the linear pressure there.
  void extendDisplacement(const Eigen::VectorXd& U, mesh::NodalField& depl) const override {
    const int nc = static_cast<int>(depl.components.size());
    std::vector<double> values(static_cast<std::size_t>(nc + 1) * mesh_.nodeCount(), 0.0);
    for (int n = 0; n < mesh_.nodeCount(); ++n)
      for (int c = 0; c < nc; ++c) values[n * (nc + 1) + c] = depl.values[n * nc + c];
    for (const auto& sc : cells_) {
      const auto nodes = mesh_.cellNodes(sc.cell);
      if (sc.count == 2 && nodes.size() == 3)
        values[nodes[2] * (nc + 1) + nc] = 0.5 * (U(first_ + sc.lags[0]) + U(first_ + sc.lags[1]));
    }
    for (std::size_t k = 0; k < lagsNodes_.size(); ++k)
      values[lagsNodes_[k] * (nc + 1) + nc] = U(first_ + static_cast<int>(k));
    depl.components.push_back("LAGS_C");
    depl.values = std::move(values);
  }

 private:
  struct SlaveCell {
    int cell;
    int zone;
    int count;    // LAGS_C unknowns of the cell: 2 (vertices) or 3 (quadratic SEG3)
    int lags[3];  // their indices among this term's unknowns
    std::vector<int> candidates;
  };
  std::vector<int> cellDofs(const SlaveCell& sc) const {
    std::vector<int> dofs;
    appendDofs(sc.cell, dofs);
    for (int s : sc.candidates) appendDofs(zones_[sc.zone].masterCells[s], dofs);
    for (int v = 0; v < sc.count; ++v) dofs.push_back(first_ + sc.lags[v]);
    return dofs;
  }
  contact::ContinueOptions options_;
  std::vector<SlaveCell> cells_;
  std::vector<int> lagsNodes_;
  mutable contact::ContinueCellTerms terms_;
  mutable int active_ = 0;
};

}  // namespace

std::unique_ptr<AdditionalTerms> makeContactTerms(const MechanicalSystem& system, std::vector<ContactZone> zones,
                                                  const ContactSettings& settings) {
  if (settings.continueFormulation) return std::make_unique<ContinueContact>(system, std::move(zones), settings);
  return std::make_unique<DiscreteContact>(system, std::move(zones), settings);
}

}  // namespace aster::solver
