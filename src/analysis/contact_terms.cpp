#include "analysis/contact_terms.hpp"

#include "analysis/contact_base.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "contact/discrete.hpp"
#include "contact/gap.hpp"
#include "contact/projection.hpp"
#include "contact/smoothed_normal.hpp"
#include "contact/vertex_blend.hpp"
#include "core/error.hpp"
#include "core/messages.hpp"
#include "core/number_format.hpp"
#include "fem/quadrature.hpp"

namespace aster::analysis {
namespace {

using detail::ContactBase;
using detail::kContNoeu;

// ---------------------------------------------------------------- DISCRETE
// A slave node pressed into a GROOVE of the master (two master cells meeting
// at a vertex, the second rising towards the slave side of the first) sits on
// the vertex, and the master pushes it along any combination of the two
// normals. One condition against the nearest cell alone pushes it along that
// cell's normal, across the vertex, then along the other's, from one Newton
// iteration to the next: the nearest cell alternates and Newton's method
// cycles. So when a node's nearest cell goes back to the one before (A, B,
// A) and A and B form a groove at the vertex nearest to its projection, the
// node is held by both: a second condition against the other cell (the gap
// to its line past the vertex when clamped there), a second multiplier, each
// in the active set. It stays held while its nearest cell is A or B. A node
// held by both conditions keeps each cell in its slot (each multiplier stays
// the force of one cell); a node with one active condition moves it to the
// nearest cell, as with one condition per node. A node without a second cell
// has its second multiplier fixed to 0 (fixedUnknowns(), an element of its
// own): the system is then the one-condition system, iterate for iterate.
class DiscreteContact final : public ContactBase {
 public:
  DiscreteContact(const MechanicalSystem& system, std::vector<ContactZone> zones, const ContactSettings& settings)
      : ContactBase(system, std::move(zones), settings) {
    for (std::size_t z = 0; z < zones_.size(); ++z) {
      std::vector<double> share(mesh_.nodeCount(), 0.0);
      for (int c : zones_[z].slaveCells) {
        double a[3] = {0, 0, 0};
        const auto type = segment(c, nullptr).type;
        integrateOnSlave(c, [&](int k, double xi) { return contact::segmentShape(type, xi).N(k); }, a);
        const auto n = mesh_.cellNodes(c);
        for (int k = 0; k < static_cast<int>(n.size()); ++k) share[n[k]] += a[k];
      }
      std::vector<char> seen(mesh_.nodeCount(), 0);
      for (int c : zones_[z].slaveCells)
        for (int n : mesh_.cellNodes(c))
          if (!seen[n] && !excluded_[z][n]) {
            seen[n] = 1;
            if (!(share[n] > 0))
              throw Error("contact: slave node " + mesh_.nodeName(n) + " has no share of the slave length");
            nodes_.push_back({n, static_cast<int>(z), {-1, -1}, {}, share[n], {-1, -1}, {-1, -1}});
          }
      // Master cells meeting at each vertex (a line: two at most are neighbours).
      const auto& cells = zones_[z].masterCells;
      std::map<int, std::vector<int>> cellsAt;
      for (std::size_t s = 0; s < cells.size(); ++s)
        for (int e = 0; e < 2; ++e) cellsAt[mesh_.cellNodes(cells[s])[e]].push_back(static_cast<int>(s));
      std::vector<std::array<int, 2>> next(cells.size(), {-1, -1});
      for (std::size_t s = 0; s < cells.size(); ++s)
        for (int e = 0; e < 2; ++e) {
          const auto& around = cellsAt[mesh_.cellNodes(cells[s])[e]];
          if (around.size() == 2) next[s][e] = around[0] == static_cast<int>(s) ? around[1] : around[0];
        }
      neighbours_.push_back(std::move(next));
    }
    active_.assign(2 * nodes_.size(), false);
  }
  // Per slave node: the multiplier of slot 0, then (after all of them) of slot 1.
  int unknownCount() const override { return 2 * static_cast<int>(nodes_.size()); }
  void fixedUnknowns(std::vector<int>& dofs) const override {
    for (std::size_t i = 0; i < nodes_.size(); ++i)
      if (nodes_[i].segment[1] < 0) dofs.push_back(unknown(i, 1));
  }

  bool update(const Eigen::VectorXd& U) override {
    bool changed = false;
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      auto& sn = nodes_[i];
      const auto m = masters(zones_[sn.zone], U);
      const Eigen::Vector2d x = position(sn.node, &U);
      const auto p = contact::projectOnMaster(x, m, projections_[sn.zone]);
      std::array<int, 2> seg = {p.segment, -1};
      std::array<contact::Projection, 2> proj = {p.projection, {}};
      // The nearest cell going back to the one before (A, B, A): the node
      // is caught between A and B, which hold it together from now on.
      if (p.segment != sn.nearest[0]) {
        if (p.segment >= 0 && p.segment == sn.nearest[1]) sn.held = {p.segment, sn.nearest[0]};
        sn.nearest = {p.segment, sn.nearest[0]};
      }
      if (p.segment != sn.held[0] && p.segment != sn.held[1]) sn.held = {-1, -1};
      if (p.paired() && sn.held[0] >= 0) {
        seg[1] = grooveNeighbour(sn.zone, p.segment, p.projection.xi, m);
        if (seg[1] != sn.held[0] && seg[1] != sn.held[1]) seg[1] = -1;
        if (seg[1] >= 0) {
          proj[1] = contact::projectOnSegment(x, m[seg[1]], projections_[sn.zone]);
          if (proj[1].status == contact::ProjectionStatus::Outside) seg[1] = -1;
        }
      }
      // Which slot carries which cell: a node held by both conditions keeps
      // them in their slots while it stays between the same two cells; a node
      // held by one condition keeps it in its slot and moves it to the nearest
      // cell (sliding over a vertex, the force goes on from one cell to the next).
      const bool a0 = active_[slot(i, 0)], a1 = active_[slot(i, 1)];
      int follows = -1;  // the slot that follows the nearest cell with its multiplier
      if (a0 && a1 && p.paired() &&
          ((seg[0] == sn.segment[0] && seg[1] == sn.segment[1]) || (seg[0] == sn.segment[1] && seg[1] == sn.segment[0]))) {
        if (seg[0] != sn.segment[0]) {
          std::swap(seg[0], seg[1]);
          std::swap(proj[0], proj[1]);
        }
      } else if (a0 != a1 && p.paired()) {
        follows = a0 ? 0 : 1;
        if (follows == 1) {
          std::swap(seg[0], seg[1]);
          std::swap(proj[0], proj[1]);
        }
      }
      changed |= seg != sn.segment;
      // A cell that comes into slot 1 starts inactive there, unless slot 1 follows the nearest cell.
      if (seg[1] != sn.segment[1] && follows != 1) active_[slot(i, 1)] = false;
      if (seg[0] != sn.segment[0] && follows == 1) active_[slot(i, 0)] = false;
      sn.segment = seg;
      sn.projection = proj;
      // As code_aster's CONTACT_INIT='INTERPENETRE': nodes touching (to
      // round-off) or penetrating at the start are active from the first iteration.
      if (!started_ && p.paired() && contact::gapIsClosed(p.projection.gap, x, m[p.segment]))
        active_[slot(i, 0)] = true;
    }
    started_ = true;
    return changed;
  }

  // One element per node, then one per unused second multiplier (alone: its
  // fixed value 0 leaves the rest of the system as with one condition per node).
  void elementDofs(fem::ElementDofs& out) const override {
    for (std::size_t i = 0; i < nodes_.size(); ++i) out.add(nodeDofs(i));
    for (std::size_t i = 0; i < nodes_.size(); ++i)
      if (nodes_[i].segment[1] < 0) out.add(std::vector<int>{unknown(i, 1)});
  }

  void assemble(const Eigen::VectorXd& U, Eigen::VectorXd& r, const fem::AssemblyPattern& pattern, int firstElement,
                linalg::SparseMatrix* K) const override {
    residual_ = 0;
    Eigen::VectorXd res;
    Eigen::MatrixXd Ke;
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      const auto dofs = nodeDofs(i);
      double violation = 0;
      nodeTerms(i, U, res, Ke, violation);
      residual_ = std::max(residual_, violation);
      addLocal(dofs, res, r);
      if (K) pattern.addMatrix(firstElement + static_cast<int>(i), Ke.data(), K->valuePtr());
    }
    int e = firstElement + static_cast<int>(nodes_.size());
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      if (nodes_[i].segment[1] >= 0) continue;
      const double S = scales_[nodes_[i].zone];
      r(unknown(i, 1)) += S * U(unknown(i, 1));  // lambda = 0
      if (K) pattern.addMatrix(e, &S, K->valuePtr());
      ++e;
    }
  }

  bool updateStatus(const Eigen::VectorXd& U) override {
    const std::size_t n = nodes_.size();
    std::vector<double> gaps(2 * n, 1.0), lambdas(2 * n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      const auto& sn = nodes_[i];
      const auto m = masters(zones_[sn.zone], U);
      const Eigen::Vector2d x = position(sn.node, &U);
      for (int k = 0; k < 2; ++k) lambdas[slot(i, k)] = multiplier(i, k, U);
      if (sn.segment[1] < 0) {
        // One condition: against the nearest cell at U.
        const auto p = contact::projectOnMaster(x, m, projections_[sn.zone]);
        gaps[slot(i, 0)] = p.paired() ? p.projection.gap : 1.0;
        continue;
      }
      for (int k = 0; k < 2; ++k) {
        if (sn.segment[k] < 0) continue;
        const auto p = contact::projectOnSegment(x, m[sn.segment[k]], projections_[sn.zone]);
        if (p.status != contact::ProjectionStatus::Outside) gaps[slot(i, k)] = p.gap;
      }
    }
    return contact::updateActiveSet(gaps, lambdas, active_).changed();
  }

  std::string statusText() const override {
    int count = 0;
    for (std::size_t i = 0; i < nodes_.size(); ++i) count += active_[slot(i, 0)] || active_[slot(i, 1)];
    return std::to_string(count) + " active nodes, residual " + format::scientific(residual_, 2);
  }
  void saveStatus() override { saved_ = active_; }
  void restoreStatus() override { active_ = saved_; }

  void outputFields(const Eigen::VectorXd& U, std::vector<mesh::NodalField>& fields) const override {
    mesh::NodalField f{"CONT_NOEU", kContNoeu, std::vector<double>(kContNoeu.size() * mesh_.nodeCount(), 0.0)};
    Eigen::VectorXd r = Eigen::VectorXd::Zero(U.size()), res;
    Eigen::MatrixXd Ke;
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      double violation = 0;
      nodeTerms(i, U, res, Ke, violation);
      addLocal(nodeDofs(i), res, r);
    }
    // JEU on every slave node, excluded ones too; the rest on the nodes with a multiplier.
    for (const auto& sn : slaveNodes_) {
      const auto p = contact::projectOnMaster(position(sn.node, &U), masters(zones_[sn.zone], U), projections_[sn.zone]);
      f.values[5 * sn.node + 1] = p.paired() ? p.projection.gap : 0.0;
    }
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      const int n = nodes_[i].node;
      f.values[5 * n] = active_[slot(i, 0)] || active_[slot(i, 1)] ? 1.0 : 0.0;
      f.values[5 * n + 2] = (multiplier(i, 0, U) + multiplier(i, 1, U)) / nodes_[i].share;
    }
    nodalForces(r, f);
    printNodalTable(f);
    fields.push_back(std::move(f));
  }

 private:
  struct SlaveNode {
    int node;
    int zone;
    std::array<int, 2> segment;  // per slot: index in the zone's master cells, -1 when none
    std::array<contact::Projection, 2> projection;
    double share;  // int N_i dGamma_0 over the zone's slave cells
    std::array<int, 2> nearest{{-1, -1}};  // the nearest cell at the last update, and the one before it
    std::array<int, 2> held{{-1, -1}};     // the two cells of a groove that hold the node (-1: none)
  };
  std::size_t slot(std::size_t i, int k) const { return k * nodes_.size() + i; }
  int unknown(std::size_t i, int k) const { return first_ + static_cast<int>(slot(i, k)); }
  // The cell forming a groove with master cell s (zone z) at its end nearest
  // to xi: the neighbour there whose other vertex lies on the slave side of s
  // (beyond round-off of the angle); -1 when none.
  int grooveNeighbour(int z, int s, double xi, const std::vector<contact::Segment>& m) const {
    const int e = xi >= 0 ? 1 : 0;
    const int t = neighbours_[z][s][e];
    if (t < 0) return -1;
    const Eigen::Vector2d v = m[s].x.row(e).transpose();
    const Eigen::Vector2d n = contact::segmentFrame(m[s], e == 1 ? 1.0 : -1.0).normal;
    const int shared = m[t].x.row(0).transpose() == v ? 0 : 1;
    const Eigen::Vector2d far = m[t].x.row(1 - shared).transpose() - v;
    return n.dot(far) > 1e-8 * far.norm() ? t : -1;
  }
  std::vector<int> nodeDofs(std::size_t i) const {
    const auto& sn = nodes_[i];
    std::vector<int> dofs;
    system_.dofMap().appendNodeDofs(&sn.node, &sn.node + 1, 2, dofs);
    for (int k = 0; k < 2; ++k)
      if (sn.segment[k] >= 0) appendDofs(zones_[sn.zone].masterCells[sn.segment[k]], dofs);
    dofs.push_back(unknown(i, 0));
    if (sn.segment[1] >= 0) dofs.push_back(unknown(i, 1));
    return dofs;
  }
  // Node i's multiplier lambda of slot k (its unknown is lambda / S).
  double multiplier(std::size_t i, int k, const Eigen::VectorXd& U) const {
    return scales_[nodes_[i].zone] * U(unknown(i, k));
  }
  // Residual and tangent of node i (layout of nodeDofs), with respect to its
  // unknowns lambda / S and their equations times S (contact_terms.hpp), and
  // the violation of its contact conditions in length units (statusText()).
  void nodeTerms(std::size_t i, const Eigen::VectorXd& U, Eigen::VectorXd& res, Eigen::MatrixXd& Ke,
                 double& violation) const {
    const auto& sn = nodes_[i];
    const int m = static_cast<int>(nodeDofs(i).size());
    const double S = scales_[sn.zone];
    res.setZero(m);
    Ke.setZero(m, m);
    violation = 0;
    const int slots = sn.segment[1] >= 0 ? 2 : 1;  // an unused second multiplier has an element of its own
    int offset = 2;  // first entry of the slot's master nodes
    for (int k = 0; k < slots; ++k) {
      const int q = m - slots + k;  // the slot's multiplier entry
      const double lambda = multiplier(i, k, U);
      const bool active = active_[slot(i, k)];
      if (sn.segment[k] < 0) {
        res(q) = lambda;  // unpaired: lambda = 0
        Ke(q, q) = S;
        continue;
      }
      const auto seg = segment(zones_[sn.zone].masterCells[sn.segment[k]], &U);
      const auto gap = contact::linearizeGap(position(sn.node, &U), seg, sn.projection[k]);
      const double pk = zones_[sn.zone].settings.penalty * sn.share;
      const auto t = contact::discreteNodeTerms(gap, lambda, active, pk);
      // Gap variables (x_s, the cell's nodes) -> entries of the layout.
      const int nq = static_cast<int>(gap.gradient.size());
      auto entry = [&](int a) { return a < 2 ? a : offset + a - 2; };
      for (int a = 0; a < nq; ++a) {
        res(entry(a)) += t.residualU(a);
        for (int b = 0; b < nq; ++b) Ke(entry(a), entry(b)) += t.tangentUU(a, b);
      }
      if (active) {
        res(q) = S * t.residualLambda;
        for (int a = 0; a < nq; ++a) {
          Ke(entry(a), q) += S * t.tangentULambda(a);
          Ke(q, entry(a)) += S * t.tangentULambda(a);
        }
        Ke(q, q) = S * S * t.tangentLambdaLambda;
      } else {
        res(q) = t.residualLambda;  // lambda = 0, i.e. S * unknown = 0
        Ke(q, q) = S * t.tangentLambdaLambda;
      }
      violation = std::max(violation, active ? std::fabs(t.residualLambda) : std::max(0.0, -gap.gap));
      offset += nq - 2;
    }
  }
  std::vector<SlaveNode> nodes_;
  std::vector<std::vector<std::array<int, 2>>> neighbours_;  // per zone, per master cell, per end: the cell there
  std::vector<bool> active_, saved_;  // per slot (slot())
  bool started_ = false;
  mutable double residual_ = 0;
};

// ---------------------------------------------------------------- CONTINUE
class ContinueContact final : public ContactBase {
 public:
  ContinueContact(const MechanicalSystem& system, std::vector<ContactZone> zones, const ContactSettings& settings)
      : ContactBase(system, std::move(zones), settings) {
    std::map<int, int> lagsIndex;
    for (std::size_t z = 0; z < zones_.size(); ++z) {
      const auto& zs = zones_[z].settings;
      contact::ContinueOptions o;
      o.rho = zs.rho;  // COEF_CONT, absolute (a pressure per unit gap), as code_aster's
      o.penalty = zs.penalty;
      o.integration = zs.integration;
      o.gaussPoints = zs.gaussPoints;
      o.projection = projections_[z];
      o.multiplierInterpolation = zs.multipliers;
      options_.push_back(o);
      const bool quadratic = zs.multipliers == contact::MultiplierInterpolation::Quadratic;
      for (int c : zones_[z].slaveCells) {
        const auto n = mesh_.cellNodes(c);
        const bool seg3 = mesh_.cellType(c) == mesh::CellType::SEG3;
        SlaveCell sc{c, static_cast<int>(z), 2, {}, {}, true, {}, {}};
        if (quadratic && seg3) sc.count = 3;
        double a[3] = {0, 0, 0};
        integrateOnSlave(
            c,
            [&](int v, double xi) {
              if (sc.count == 3) return contact::segmentShape(fem::CellType::SEG3, xi).N(v);
              return v == 0 ? 0.5 * (1 - xi) : v == 1 ? 0.5 * (1 + xi) : 0.0;
            },
            a);
        for (int v = 0; v < sc.count; ++v) {
          auto it = lagsIndex.find(n[v]);
          if (it == lagsIndex.end()) {
            it = lagsIndex.emplace(n[v], static_cast<int>(lagsNodes_.size())).first;
            lagsNodes_.push_back(n[v]);
            lagsShare_.push_back(0.0);
            lagsScale_.push_back(scales_[z]);
            if (excluded_[z][n[v]]) fixedLags_.push_back(it->second);
          }
          sc.lags[v] = it->second;
          lagsShare_[it->second] += a[v];
          sc.skip = sc.skip && excluded_[z][n[v]];
        }
        cells_.push_back(sc);
      }
    }
    if (settings_.smoothNormals) buildPatches();
    lagsResidual_.assign(lagsNodes_.size(), 0.0);
    fixed_.assign(lagsNodes_.size(), 0);
    for (int k : fixedLags_) fixed_[k] = 1;
    // Where a slave node reads its pressure: its own LAGS_C, or the mean of
    // the ends of a SEG3 whose middle node carries none.
    pressureOf_.assign(mesh_.nodeCount(), {-1, -1});
    for (const auto& sc : cells_) {
      const auto n = mesh_.cellNodes(sc.cell);
      for (int v = 0; v < sc.count; ++v) pressureOf_[n[v]] = {sc.lags[v], sc.lags[v]};
    }
    for (const auto& sc : cells_) {
      const auto n = mesh_.cellNodes(sc.cell);
      if (sc.count == 2 && n.size() == 3 && pressureOf_[n[2]].first < 0) pressureOf_[n[2]] = {sc.lags[0], sc.lags[1]};
    }
  }
  int unknownCount() const override { return static_cast<int>(lagsNodes_.size()); }
  void fixedUnknowns(std::vector<int>& dofs) const override {
    for (int k : fixedLags_) dofs.push_back(first_ + k);
  }

  // Candidate masters of a slave cell: the segments its nodes and midpoints
  // project on (the nearest one when none is paired).
  bool update(const Eigen::VectorXd& U) override {
    recordNearest_ = true;
    initialIteration_ = !started_;
    started_ = true;
    bool changed = false;
    for (auto& sc : cells_) {
      if (sc.skip) continue;
      const auto& zone = zones_[sc.zone];
      const auto& po = projections_[sc.zone];
      const auto m = masters(zone, U);
      const auto slave = segment(sc.cell, &U);
      std::vector<int> cand;
      double nearest = 1e300;
      int nearestSeg = 0;
      for (int k = 0; k <= 8; ++k) {
        const double xi = -1.0 + k / 4.0;
        const auto sh = contact::segmentShape(slave.type, xi);
        const Eigen::Vector2d x = slave.x.transpose() * sh.N;
        const auto p = contact::projectOnMaster(x, m, po);
        if (p.paired()) {
          cand.push_back(p.segment);
        } else {
          for (std::size_t s = 0; s < m.size(); ++s) {
            const auto q = contact::projectOnSegment(x, m[s], po);
            if (q.distance < nearest) {
              nearest = q.distance;
              nearestSeg = static_cast<int>(s);
            }
          }
        }
      }
      if (cand.empty()) cand.push_back(nearestSeg);
      updateHolds(sc, lastNearest_.empty() ? nullptr : &lastNearest_[&sc - cells_.data()]);
      for (const auto& h : sc.held)
        if (h[0] >= 0) cand.insert(cand.end(), h.begin(), h.end());
      std::sort(cand.begin(), cand.end());
      cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
      changed |= cand != sc.candidates;
      sc.candidates = cand;
    }
    return changed;
  }

  void elementDofs(fem::ElementDofs& out) const override {
    for (const auto& sc : cells_)
      if (!sc.skip) out.add(cellDofs(sc));
  }

  void assemble(const Eigen::VectorXd& U, Eigen::VectorXd& r, const fem::AssemblyPattern& pattern, int firstElement,
                linalg::SparseMatrix* K) const override {
    pointsInContact_ = 0;
    std::fill(lagsResidual_.begin(), lagsResidual_.end(), 0.0);
    if (recordNearest_) lastNearest_.resize(cells_.size());
    int e = 0;
    for (const auto& sc : cells_) {
      if (sc.skip) continue;
      cellTerms(sc, U, initialIteration_);
      for (const auto& p : terms_.points) pointsInContact_ += p.status == contact::PointStatus::Contact;
      if (recordNearest_) {
        auto& n = lastNearest_[&sc - cells_.data()];
        n.clear();
        for (const auto& p : terms_.points) n.push_back(p.masterSegment >= 0 ? sc.candidates[p.masterSegment] : -1);
      }
      for (int v = 0; v < sc.count; ++v) lagsResidual_[sc.lags[v]] += terms_.residual(terms_.lagrangeOffset + v);
      scaleMultiplierRows(sc);
      addLocal(cellDofs(sc), terms_.residual, r);
      if (K) pattern.addMatrix(firstElement + e, terms_.tangent.data(), K->valuePtr());
      ++e;
    }
    recordNearest_ = false;
    residual_ = 0;
    for (std::size_t k = 0; k < lagsNodes_.size(); ++k)
      if (!fixed_[k]) residual_ = std::max(residual_, std::fabs(lagsResidual_[k]) / lagsShare_[k]);
    nodesInContact_ = 0;
    const auto states = nodalStates(U, initialIteration_);
    for (const auto& s : states) nodesInContact_ += s.contact;
  }

  // The statuses are re-evaluated at every assembly (generalized Newton): a
  // small residual already means they are consistent.
  bool updateStatus(const Eigen::VectorXd&) override { return false; }
  std::string statusText() const override {
    return std::to_string(pointsInContact_) + " points in contact, " + std::to_string(nodesInContact_) +
           " nodes, residual " + format::scientific(residual_, 2);
  }
  // CONTACT_INIT applies again when the first step is cut and restarted.
  // Holds at a vertex (updateHolds) last one step: its points are free again
  // at the next, until their nearest cell alternates again.
  void saveStatus() override {
    savedStarted_ = started_;
    for (auto& sc : cells_) {
      sc.nearest.clear();
      sc.held.clear();
    }
    lastNearest_.clear();
  }
  void restoreStatus() override { started_ = savedStarted_; }

  // LAGS_C joins DEPL at its nodes; the middle node of a SEG3 slave whose
  // LAGS_C is linear shows the value of the linear pressure there.
  void extendDisplacement(const Eigen::VectorXd& U, mesh::NodalField& depl) const override {
    std::vector<std::pair<int, double>> lagsC;
    for (const auto& sc : cells_) {
      const auto nodes = mesh_.cellNodes(sc.cell);
      if (sc.count == 2 && nodes.size() == 3)
        lagsC.push_back({nodes[2], 0.5 * (lags(sc.lags[0], U) + lags(sc.lags[1], U))});
    }
    for (std::size_t k = 0; k < lagsNodes_.size(); ++k) lagsC.push_back({lagsNodes_[k], lags(static_cast<int>(k), U)});
    appendComponent(depl, "LAGS_C", lagsC);
  }

  void outputFields(const Eigen::VectorXd& U, std::vector<mesh::NodalField>& fields) const override {
    mesh::NodalField f{"CONT_NOEU", kContNoeu, std::vector<double>(kContNoeu.size() * mesh_.nodeCount(), 0.0)};
    Eigen::VectorXd r = Eigen::VectorXd::Zero(U.size());
    for (const auto& sc : cells_) {
      if (sc.skip) continue;
      cellTerms(sc, U, false);
      addLocal(cellDofs(sc), terms_.residual, r);
    }
    const auto states = nodalStates(U, false);
    for (std::size_t i = 0; i < slaveNodes_.size(); ++i) {
      const int n = slaveNodes_[i].node;
      f.values[5 * n] = states[i].contact ? 1.0 : 0.0;
      f.values[5 * n + 1] = states[i].gap;
      f.values[5 * n + 2] = states[i].pressure;
    }
    nodalForces(r, f);
    printNodalTable(f);
    fields.push_back(std::move(f));
  }

 private:
  struct SlaveCell {
    int cell;
    int zone;
    int count;    // LAGS_C unknowns of the cell: 2 (vertices) or 3 (quadratic SEG3)
    int lags[3];  // their indices among this term's unknowns
    std::vector<int> candidates;
    bool skip;  // every LAGS_C node excluded (SANS_GROUP_NO): no contact on the cell
    // Per integration point (zone master indices): the nearest master cell at
    // the last two iterations where it changed, and the two cells that hold
    // the point at their vertex (-1: none; contact/vertex_blend.hpp).
    std::vector<std::array<int, 2>> nearest, held;
  };
  struct NodalState {
    bool contact = false;
    double gap = 0, pressure = 0;
  };
  // The mesh nodes of master cell s of a zone's smoothed-normal patch (its
  // own first), and the patch's facets (smoothed_normal.hpp).
  struct PatchTopology {
    std::vector<int> nodes;
    std::array<std::vector<contact::NormalPatch::Facet>, 3> facets;
  };
  void buildPatches() {
    patches_.resize(zones_.size());
    for (std::size_t z = 0; z < zones_.size(); ++z) {
      const auto& cells = zones_[z].masterCells;
      std::map<int, std::vector<int>> cellsAt;  // master node -> master cells (zone indices)
      for (std::size_t s = 0; s < cells.size(); ++s)
        for (int n : mesh_.cellNodes(cells[s])) cellsAt[n].push_back(static_cast<int>(s));
      for (int c : cells) {
        PatchTopology t;
        const auto own = mesh_.cellNodes(c);
        t.nodes.assign(own.begin(), own.end());
        auto index = [&](int node) {
          const auto it = std::find(t.nodes.begin(), t.nodes.end(), node);
          if (it != t.nodes.end()) return static_cast<int>(it - t.nodes.begin());
          t.nodes.push_back(node);
          return static_cast<int>(t.nodes.size()) - 1;
        };
        for (int a = 0; a < static_cast<int>(own.size()); ++a) {
          const auto& around = cellsAt[own[a]];
          if (around.size() > 2)
            throw Error("DEFI_CONTACT LISSAGE='OUI': master node " + mesh_.nodeName(own[a]) + " belongs to " +
                        std::to_string(around.size()) + " master cells; smoothing needs a master line (at most two)");
          for (int s : around) {
            const auto en = mesh_.cellNodes(cells[s]);
            contact::NormalPatch::Facet f;
            f.type = mesh_.cellType(cells[s]) == mesh::CellType::SEG3 ? fem::CellType::SEG3 : fem::CellType::SEG2;
            for (int b = 0; b < static_cast<int>(en.size()); ++b) {
              f.node[b] = index(en[b]);
              if (en[b] == own[a]) f.xi = b == 0 ? -1.0 : b == 1 ? 1.0 : 0.0;
            }
            t.facets[a].push_back(f);
          }
        }
        patches_[z].push_back(std::move(t));
      }
    }
  }
  // The patch of master cell s (zone index) at U.
  contact::NormalPatch patch(int zone, int s, const Eigen::VectorXd& U) const {
    const PatchTopology& t = patches_[zone][s];
    contact::NormalPatch p;
    for (int n : t.nodes) p.nodes.push_back(position(n, &U));
    p.facets = t.facets;
    return p;
  }
  std::vector<int> cellDofs(const SlaveCell& sc) const {
    std::vector<int> dofs;
    appendDofs(sc.cell, dofs);
    for (int s : sc.candidates) {
      if (settings_.smoothNormals) {
        const auto& n = patches_[sc.zone][s].nodes;
        system_.dofMap().appendNodeDofs(n.data(), n.data() + n.size(), 2, dofs);
      } else {
        appendDofs(zones_[sc.zone].masterCells[s], dofs);
      }
    }
    for (int v = 0; v < sc.count; ++v) dofs.push_back(first_ + sc.lags[v]);
    return dofs;
  }
  // A point whose nearest master cell goes back to the one before (A, B, A)
  // from one iteration to the next is held at the vertex of A and B (if they
  // share one) while its nearest cell is A or B (contact/vertex_blend.hpp):
  // near a kink its force would otherwise jump from one cell's normal to the
  // other's at every iteration.
  void updateHolds(SlaveCell& sc, const std::vector<int>* nearest) const {
    if (!nearest) return;
    const std::size_t n = nearest->size();
    sc.nearest.resize(n, {-1, -1});
    sc.held.resize(n, {-1, -1});
    const auto& cells = zones_[sc.zone].masterCells;
    for (std::size_t k = 0; k < n; ++k) {
      const int s = (*nearest)[k];
      auto& h = sc.nearest[k];
      auto& held = sc.held[k];
      if (s != h[0]) {
        if (s >= 0 && s == h[1] && h[0] >= 0 && shareVertex(cells[s], cells[h[0]])) held = {s, h[0]};
        h = {s, h[0]};
      }
      if (s != held[0] && s != held[1]) held = {-1, -1};
    }
  }
  bool shareVertex(int a, int b) const {
    const auto na = mesh_.cellNodes(a), nb = mesh_.cellNodes(b);
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        if (na[i] == nb[j]) return true;
    return false;
  }
  // LAGS_C of unknown k (stored as LAGS_C / S).
  double lags(int k, const Eigen::VectorXd& U) const { return lagsScale_[k] * U(first_ + k); }
  // terms_ (of cell sc) with respect to the unknowns LAGS_C / S, their equations times S.
  void scaleMultiplierRows(const SlaveCell& sc) const {
    const int lo = terms_.lagrangeOffset;
    for (int v = 0; v < sc.count; ++v) {
      const double S = lagsScale_[sc.lags[v]];
      terms_.residual(lo + v) *= S;
      terms_.tangent.row(lo + v) *= S;
      terms_.tangent.col(lo + v) *= S;
    }
  }
  contact::ForcedStatus forced(int zone, bool initial) const {
    return initial ? zones_[zone].settings.initialStatus : contact::ForcedStatus::None;
  }
  // terms_ of one cell at U (statuses forced by CONTACT_INIT when `initial`).
  void cellTerms(const SlaveCell& sc, const Eigen::VectorXd& U, bool initial) const {
    contact::SlaveCell slave;
    const bool seg3 = mesh_.cellType(sc.cell) == mesh::CellType::SEG3;
    slave.type = seg3 ? fem::CellType::SEG3 : fem::CellType::SEG2;
    const auto nodes = mesh_.cellNodes(sc.cell);
    for (int a = 0; a < static_cast<int>(nodes.size()); ++a) {
      slave.reference.row(a) = position(nodes[a], nullptr).transpose();
      slave.current.row(a) = position(nodes[a], &U).transpose();
    }
    for (int v = 0; v < sc.count; ++v) slave.lagsC(v) = lags(sc.lags[v], U);
    for (const auto& h : sc.held) {
      auto index = [&](int s) {
        const auto it = std::find(sc.candidates.begin(), sc.candidates.end(), s);
        return it == sc.candidates.end() ? -1 : static_cast<int>(it - sc.candidates.begin());
      };
      std::array<int, 2> k = {-1, -1};
      if (h[0] >= 0 && index(h[0]) >= 0 && index(h[1]) >= 0) k = {index(h[0]), index(h[1])};
      slave.held.push_back(k);
    }
    std::vector<contact::Segment> m;
    for (int s : sc.candidates) m.push_back(segment(zones_[sc.zone].masterCells[s], &U));
    contact::ContinueOptions o = options_[sc.zone];
    o.forcedStatus = forced(sc.zone, initial);
    if (!settings_.smoothNormals) {
      contact::continueCellTerms(slave, m, o, terms_);
      return;
    }
    std::vector<contact::NormalPatch> p;
    for (int s : sc.candidates) p.push_back(patch(sc.zone, s, U));
    contact::continueCellTerms(slave, m, o, terms_, &p);
  }
  // Per slave node (slaveNodes_ order): the criterion of the integration
  // points evaluated at the node, its gap and its pressure.
  std::vector<NodalState> nodalStates(const Eigen::VectorXd& U, bool initial) const {
    std::vector<NodalState> out(slaveNodes_.size());
    std::vector<std::vector<contact::Segment>> m(zones_.size());
    for (std::size_t z = 0; z < zones_.size(); ++z) m[z] = masters(zones_[z], U);
    for (std::size_t i = 0; i < slaveNodes_.size(); ++i) {
      const auto& sn = slaveNodes_[i];
      auto& s = out[i];
      const auto [a, b] = pressureOf_[sn.node];
      if (a >= 0) s.pressure = 0.5 * (lags(a, U) + lags(b, U));
      const auto p = contact::projectOnMaster(position(sn.node, &U), m[sn.zone], projections_[sn.zone]);
      const double gap = !p.paired() ? 0.0
                         : settings_.smoothNormals
                             ? contact::smoothedGap(position(sn.node, &U), m[sn.zone][p.segment],
                                                    patch(sn.zone, p.segment, U), p.projection.xi)
                             : contact::pairedGap(position(sn.node, &U), m[sn.zone], p, projections_[sn.zone]);
      if (!p.paired() || excluded_[sn.zone][sn.node]) {
        s.gap = gap;
        continue;
      }
      s.gap = gap;
      // A gap within round-off is closed, as at the integration points.
      const double g =
          s.gap > 0 && contact::gapIsClosed(s.gap, position(sn.node, &U), m[sn.zone][p.segment]) ? 0.0 : s.gap;
      const auto& o = options_[sn.zone];
      const auto f = forced(sn.zone, initial);
      if (f != contact::ForcedStatus::None)
        s.contact = f == contact::ForcedStatus::Contact;
      else
        s.contact = (o.penalty > 0 ? o.penalty * g : s.pressure + o.rho * g) <= 0;
    }
    return out;
  }

  std::vector<contact::ContinueOptions> options_;  // per zone
  std::vector<std::vector<PatchTopology>> patches_;  // LISSAGE: per zone, per master cell
  std::vector<SlaveCell> cells_;
  std::vector<int> lagsNodes_;
  std::vector<double> lagsShare_;  // int L_v dGamma_0
  std::vector<double> lagsScale_;  // S of the zone that made each LAGS_C unknown
  std::vector<int> fixedLags_;     // LAGS_C of excluded nodes: 0
  std::vector<char> fixed_;
  std::vector<std::pair<int, int>> pressureOf_;  // per mesh node: LAGS_C indices to average (-1: none)
  bool started_ = false, savedStarted_ = false, initialIteration_ = false;
  mutable bool recordNearest_ = false;                  // the next assemble() records each point's nearest cell
  mutable std::vector<std::vector<int>> lastNearest_;   // per cell, per point: zone master index (-1: none)
  mutable contact::ContinueCellTerms terms_;
  mutable std::vector<double> lagsResidual_;
  mutable int pointsInContact_ = 0, nodesInContact_ = 0;
  mutable double residual_ = 0;
};

}  // namespace

std::pair<int, int> inwardContactCell(const mesh::Mesh& mesh, const std::vector<int>& cells) {
  // Directed vertex edges of the 2D cells: a segment a -> b bounding a cell
  // whose (counterclockwise) vertex cycle goes a -> b has its normal (dy, -dx) outward.
  std::map<std::pair<int, int>, std::vector<int>> cellsOnEdge;
  for (int c = 0; c < mesh.cellCount(); ++c) {
    const auto t = mesh.cellType(c);
    if (mesh::topologicalDimension(t) != 2) continue;
    const int nv = mesh::vertexCount(t);
    const auto n = mesh.cellNodes(c);
    for (int i = 0; i < nv; ++i) cellsOnEdge[std::minmax(n[i], n[(i + 1) % nv])].push_back(c);
  }
  for (int s : cells) {
    const auto sn = mesh.cellNodes(s);
    if (sn.size() < 2) continue;
    const int a = sn[0], b = sn[1];
    const auto it = cellsOnEdge.find(std::minmax(a, b));
    if (it == cellsOnEdge.end() || it->second.size() != 1) continue;
    const int c = it->second[0];
    const int nv = mesh::vertexCount(mesh.cellType(c));
    const auto n = mesh.cellNodes(c);
    bool sameWay = false;
    double area = 0;
    for (int i = 0; i < nv; ++i) {
      if (n[i] == a && n[(i + 1) % nv] == b) sameWay = true;
      const auto p = mesh.node(n[i]), q = mesh.node(n[(i + 1) % nv]);
      area += p[0] * q[1] - q[0] * p[1];
    }
    if (sameWay != (area > 0)) return {s, c};
  }
  return {-1, -1};
}

std::unique_ptr<AdditionalTerms> makeContactTerms(const MechanicalSystem& system, std::vector<ContactZone> zones,
                                                  const ContactSettings& settings) {
  if (settings.mortar) return detail::makeMortarContact(system, std::move(zones), settings);
  if (settings.continueFormulation) return std::make_unique<ContinueContact>(system, std::move(zones), settings);
  return std::make_unique<DiscreteContact>(system, std::move(zones), settings);
}

}  // namespace aster::analysis
