// LAC: mortar contact (DEFI_CONTACT FORMULATION='CONTINUE', ZONE ALGO_CONT='LAC'),
// frictionless, solved by a semi-smooth Newton method on nodal quantities.
//
// Unknowns: LAGS_C = lambda_j at every node j of the slave cells, the
// multiplier interpolated by the slave cells' own shape functions
// (lambda(xi) = sum_j N_j(xi) lambda_j: linear on a SEG2, quadratic on a
// SEG3; "standard" mortar multipliers), a normal traction per unit REFERENCE
// length, <= 0 in compression. Constraint: the nodal weighted gap
//   gt_j = sum over the pairs (slave cell, master segment) of G_j
// (contact/mortar.hpp: int N_j g dGamma_0 over the part of the slave facing
// the master, g measured along the slave normal). With D_j = int N_j dGamma_0,
// the mean gap of node j is gm_j = gt_j / D_j, and the contact conditions
//   lambda_j <= 0,  gt_j >= 0,  lambda_j gt_j = 0
// are the root of the complementarity function
//   C_j = lambda_j - min(0, lambda_j + c gm_j),   c = S / D_j
// (S the zone's stiffness scale, contact_base.hpp: c is a stiffness per unit
// length, so that the choice is scale-free; it changes the iterates, not the
// solution). Newton's method on C_j = 0, with the statuses chosen at every
// assembly from the current iterate (semi-smooth Newton, as code_aster's
// ALGO_RESO_CONT='NEWTON'): node j is ACTIVE when lambda_j + c gm_j <= 0, and
//   active:   equation gt_j = 0, and the force sum_j lambda_j dgt_j/du;
//   inactive: equation lambda_j = 0, and no force (lambda_j's next value is 0).
// The tangent is the exact derivative of these residuals for frozen statuses
// (lambda_j d2gt_j/du2, dgt_j/du: contact/mortar.hpp's exact derivatives), and
// it is symmetric. The first iteration of a computation takes its statuses
// from CONTACT_INIT: 'OUI' every paired node active, 'NON' none,
// 'INTERPENETRE' the nodes whose mean gap is closed (to round-off) or negative.
//
// Scaling as the other formulations (contact_base.hpp): the unknown is
// lambda / S and its equation S gt_j (or S (lambda / S) = lambda).
// Elements: one per pair, DOFs [slave cell DX, DY][master cell DX, DY]
// [LAGS_C of the slave cell's nodes], and one per LAGS_C (its diagonal).
#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "analysis/contact_base.hpp"
#include "contact/mortar.hpp"
#include "core/number_format.hpp"

namespace aster::analysis::detail {
namespace {

class MortarContact final : public ContactBase {
 public:
  MortarContact(const MechanicalSystem& system, std::vector<ContactZone> zones, const ContactSettings& settings)
      : ContactBase(system, std::move(zones), settings) {
    std::map<int, int> lagsIndex;
    for (std::size_t z = 0; z < zones_.size(); ++z) {
      contact::MortarOptions o;
      o.maxDistance = zones_[z].settings.maxDistance;
      options_.push_back(o);
      double extent = 0;
      for (const auto* cells : {&zones_[z].slaveCells, &zones_[z].masterCells})
        for (int c : *cells)
          for (int n : mesh_.cellNodes(c)) extent = std::max(extent, position(n, nullptr).cwiseAbs().maxCoeff());
      roundOff_.push_back(1e-12 * std::max(extent, 1e-300));
      for (int c : zones_[z].slaveCells) {
        const auto n = mesh_.cellNodes(c);
        SlaveCell sc{c, static_cast<int>(z), static_cast<int>(n.size()), {-1, -1, -1}, true};
        const auto shares = contact::slaveShares(slave(sc, nullptr));
        for (int a = 0; a < sc.nodes; ++a) {
          auto it = lagsIndex.find(n[a]);
          if (it == lagsIndex.end()) {
            it = lagsIndex.emplace(n[a], static_cast<int>(lags_.size())).first;
            lags_.push_back({n[a], static_cast<int>(z), 0.0, excluded_[z][n[a]] != 0});
          }
          sc.lags[a] = it->second;
          lags_[it->second].share += shares[a];
          sc.skip = sc.skip && excluded_[z][n[a]];
        }
        cells_.push_back(sc);
      }
    }
    for (const auto& l : lags_)
      if (!(l.share > 0)) throw Error("contact (LAC): slave node " + mesh_.nodeName(l.node) + " has no share of the slave length");
    gap_.assign(lags_.size(), 0.0);
    covered_.assign(lags_.size(), 0.0);
    active_.assign(lags_.size(), 0);
  }
  int unknownCount() const override { return static_cast<int>(lags_.size()); }
  void fixedUnknowns(std::vector<int>& dofs) const override {
    for (std::size_t k = 0; k < lags_.size(); ++k)
      if (lags_[k].excluded) dofs.push_back(first_ + static_cast<int>(k));
  }

  // The pairs: every master cell that a slave cell's normals meet, facing it,
  // among those whose bounding box, grown by the larger of the two cells'
  // sizes, meets the slave cell's.
  bool update(const Eigen::VectorXd& U) override {
    initialIteration_ = !started_;
    started_ = true;
    std::vector<std::vector<Box>> masterBoxes(zones_.size());
    for (std::size_t z = 0; z < zones_.size(); ++z)
      for (int c : zones_[z].masterCells) masterBoxes[z].push_back(box(segment(c, &U).x, mesh_.cellNodes(c).size()));
    std::vector<Pair> pairs;
    for (std::size_t i = 0; i < cells_.size(); ++i) {
      const auto& sc = cells_[i];
      if (sc.skip) continue;
      const auto s = slave(sc, &U);
      const Box sb = box(s.current, sc.nodes);
      const auto& masters = zones_[sc.zone].masterCells;
      for (std::size_t m = 0; m < masters.size(); ++m) {
        const Box& mb = masterBoxes[sc.zone][m];
        const double margin = std::max(sb.size(), mb.size());
        if (mb.lo.x() > sb.hi.x() + margin || sb.lo.x() > mb.hi.x() + margin || mb.lo.y() > sb.hi.y() + margin ||
            sb.lo.y() > mb.hi.y() + margin)
          continue;
        if (contact::mortarPaired(s, segment(masters[m], &U), options_[sc.zone]))
          pairs.push_back({static_cast<int>(i), static_cast<int>(m)});
      }
    }
    const bool changed = pairs != pairs_;
    pairs_ = std::move(pairs);
    return changed;
  }

  void elementDofs(fem::ElementDofs& out) const override {
    for (const auto& p : pairs_) out.add(pairDofs(p));
    for (std::size_t k = 0; k < lags_.size(); ++k) out.add({first_ + static_cast<int>(k)});
  }

  void assemble(const Eigen::VectorXd& U, Eigen::VectorXd& r, const fem::AssemblyPattern& pattern, int firstElement,
                linalg::SparseMatrix* K) const override {
    evaluate(U, initialIteration_);
    int e = firstElement;
    Eigen::VectorXd res;
    Eigen::MatrixXd Ke;
    for (std::size_t p = 0; p < pairs_.size(); ++p, ++e) {
      pairTerms(p, U, res, Ke);
      addLocal(pairDofs(pairs_[p]), res, r);
      if (K) pattern.addMatrix(e, Ke.data(), K->valuePtr());
    }
    for (std::size_t k = 0; k < lags_.size(); ++k, ++e) {
      // Inactive: lambda = 0, i.e. S * unknown = 0 (an excluded node's unknown is fixed at 0).
      const double S = scales_[lags_[k].zone];
      const double diag = active_[k] ? 0.0 : S;
      r(first_ + static_cast<int>(k)) += diag * U(first_ + static_cast<int>(k));
      if (K) pattern.addMatrix(e, &diag, K->valuePtr());
    }
  }

  // The statuses are chosen at every assembly (semi-smooth Newton): the
  // residual of the multipliers' equations already says whether they hold.
  bool updateStatus(const Eigen::VectorXd&) override { return false; }
  std::string statusText() const override {
    return std::to_string(std::count(active_.begin(), active_.end(), 1)) + " active nodes, residual " +
           format::scientific(residual_, 2);
  }
  void saveStatus() override { savedStarted_ = started_; }
  void restoreStatus() override { started_ = savedStarted_; }

  void extendDisplacement(const Eigen::VectorXd& U, mesh::NodalField& depl) const override {
    const int nc = static_cast<int>(depl.components.size());
    std::vector<double> values(static_cast<std::size_t>(nc + 1) * mesh_.nodeCount(), 0.0);
    for (int n = 0; n < mesh_.nodeCount(); ++n)
      for (int c = 0; c < nc; ++c) values[n * (nc + 1) + c] = depl.values[n * nc + c];
    for (std::size_t k = 0; k < lags_.size(); ++k) values[lags_[k].node * (nc + 1) + nc] = lambda(k, U);
    depl.components.push_back("LAGS_C");
    depl.values = std::move(values);
  }

  // CONT_NOEU: CONT the status, JEU the mean gap gt_j / (paired part of D_j),
  // RN = LAGS_C, RNX, RNY the nodal force.
  void outputFields(const Eigen::VectorXd& U, std::vector<mesh::NodalField>& fields) const override {
    mesh::NodalField f{"CONT_NOEU", kContNoeu, std::vector<double>(kContNoeu.size() * mesh_.nodeCount(), 0.0)};
    evaluate(U, false);
    Eigen::VectorXd r = Eigen::VectorXd::Zero(U.size()), res;
    Eigen::MatrixXd Ke;
    for (std::size_t p = 0; p < pairs_.size(); ++p) {
      pairTerms(p, U, res, Ke);
      addLocal(pairDofs(pairs_[p]), res, r);
    }
    for (std::size_t k = 0; k < lags_.size(); ++k) {
      double* v = &f.values[5 * lags_[k].node];
      v[0] = active_[k] ? 1.0 : 0.0;
      v[1] = covered_[k] > 0 ? gap_[k] / covered_[k] : 0.0;
      v[2] = lambda(k, U);
    }
    nodalForces(r, f);
    printNodalTable(f);
    fields.push_back(std::move(f));
  }

 private:
  struct SlaveCell {
    int cell;
    int zone;
    int nodes;
    int lags[3];  // the LAGS_C unknown of each node
    bool skip;    // every node excluded (SANS_GROUP_NO): no contact on the cell
  };
  struct Pair {
    int slave;   // in cells_
    int master;  // in the zone's master cells
    bool operator==(const Pair& o) const { return slave == o.slave && master == o.master; }
    bool operator!=(const Pair& o) const { return !(*this == o); }
  };
  struct Lags {
    int node;
    int zone;
    double share;  // D_j = int N_j dGamma_0 over the slave cells
    bool excluded;
  };

  struct Box {
    Eigen::Vector2d lo, hi;
    double size() const { return (hi - lo).maxCoeff(); }
  };
  static Box box(const contact::SegmentNodes& x, std::size_t nodes) {
    const auto rows = x.topRows(static_cast<Eigen::Index>(nodes));
    return {rows.colwise().minCoeff().transpose(), rows.colwise().maxCoeff().transpose()};
  }
  contact::MortarSlave slave(const SlaveCell& sc, const Eigen::VectorXd* U) const {
    contact::MortarSlave s;
    s.type = mesh_.cellType(sc.cell) == mesh::CellType::SEG3 ? fem::CellType::SEG3 : fem::CellType::SEG2;
    const auto n = mesh_.cellNodes(sc.cell);
    for (int a = 0; a < sc.nodes; ++a) {
      s.reference.row(a) = position(n[a], nullptr).transpose();
      s.current.row(a) = position(n[a], U).transpose();
    }
    return s;
  }
  std::vector<int> pairDofs(const Pair& p) const {
    const auto& sc = cells_[p.slave];
    std::vector<int> dofs;
    appendDofs(sc.cell, dofs);
    appendDofs(zones_[sc.zone].masterCells[p.master], dofs);
    for (int a = 0; a < sc.nodes; ++a) dofs.push_back(first_ + sc.lags[a]);
    return dofs;
  }
  double lambda(std::size_t k, const Eigen::VectorXd& U) const {
    return scales_[lags_[k].zone] * U(first_ + static_cast<int>(k));
  }
  double meanGap(std::size_t k) const {
    const double g = gap_[k] / lags_[k].share;
    return std::fabs(g) <= roundOff_[lags_[k].zone] ? 0.0 : g;
  }

  // The pairs' weighted gaps, the nodal ones, the statuses and the contact residual at U.
  void evaluate(const Eigen::VectorXd& U, bool initial) const {
    terms_.resize(pairs_.size());
    std::fill(gap_.begin(), gap_.end(), 0.0);
    std::fill(covered_.begin(), covered_.end(), 0.0);
    for (std::size_t p = 0; p < pairs_.size(); ++p) {
      const auto& sc = cells_[pairs_[p].slave];
      terms_[p] = contact::mortarPair(slave(sc, &U), segment(zones_[sc.zone].masterCells[pairs_[p].master], &U),
                                      options_[sc.zone]);
      for (int a = 0; a < sc.nodes; ++a) {
        gap_[sc.lags[a]] += terms_[p].weightedGap[a].v;
        covered_[sc.lags[a]] += terms_[p].pairedShare[a];
      }
    }
    residual_ = 0;
    for (std::size_t k = 0; k < lags_.size(); ++k) {
      const auto& l = lags_[k];
      const double g = meanGap(k);
      bool active = false;
      if (!l.excluded && covered_[k] > 0) {
        const auto init = zones_[l.zone].settings.initialStatus;
        if (initial && init == contact::ForcedStatus::Contact) active = true;
        else if (initial && init == contact::ForcedStatus::Separated) active = false;
        else if (initial) active = g <= 0;
        else active = lambda(k, U) + scales_[l.zone] / l.share * g <= 0;
      }
      active_[k] = active;
      if (l.excluded || covered_[k] == 0) continue;
      residual_ = std::max(residual_, active ? std::fabs(gap_[k]) / l.share : std::max(0.0, -g));
    }
  }

  // Residual and tangent of pair p (pairDofs layout) for the statuses of evaluate().
  void pairTerms(std::size_t p, const Eigen::VectorXd& U, Eigen::VectorXd& res, Eigen::MatrixXd& Ke) const {
    const auto& sc = cells_[pairs_[p].slave];
    const auto& t = terms_[p];
    const int q = 2 * (t.slaveNodes + t.masterNodes);
    const int m = q + sc.nodes;
    res.setZero(m);
    Ke.setZero(m, m);
    const double S = scales_[sc.zone];
    for (int a = 0; a < sc.nodes; ++a) {
      const int k = sc.lags[a];
      if (!active_[k]) continue;
      const auto& G = t.weightedGap[a];
      const double lam = lambda(k, U);
      res.head(q) += lam * G.g.head(q);
      Ke.topLeftCorner(q, q) += lam * G.h.topLeftCorner(q, q);
      Ke.col(q + a).head(q) = S * G.g.head(q);
      Ke.row(q + a).head(q) = S * G.g.head(q).transpose();
      res(q + a) = S * G.v;
    }
  }

  std::vector<contact::MortarOptions> options_;  // per zone
  std::vector<double> roundOff_;                 // per zone: a mean gap within it is closed
  std::vector<SlaveCell> cells_;
  std::vector<Lags> lags_;
  std::vector<Pair> pairs_;
  bool started_ = false, savedStarted_ = false, initialIteration_ = false;
  mutable std::vector<contact::MortarPair> terms_;  // per pair, of the last evaluate()
  mutable std::vector<double> gap_, covered_;       // per LAGS_C: gt_j, and the paired part of D_j
  mutable std::vector<char> active_;
  mutable double residual_ = 0;
};

}  // namespace

std::unique_ptr<AdditionalTerms> makeMortarContact(const MechanicalSystem& system, std::vector<ContactZone> zones,
                                                   const ContactSettings& settings) {
  return std::make_unique<MortarContact>(system, std::move(zones), settings);
}

}  // namespace aster::analysis::detail
