// LAC: mortar contact (DEFI_CONTACT FORMULATION='CONTINUE', ZONE ALGO_CONT='LAC';
// DEFI_CONT), frictionless, solved by a semi-smooth Newton method on the
// multipliers' weighted gaps.
//
// The multiplier: a normal traction per unit REFERENCE length, <= 0 in
// compression, lambda = sum_k lambda_k Phi_k over basis functions Phi_k of
// the slave surface, each a combination of the slave cells' shape functions,
// Phi_k = sum_j Phi_k(j) N_j (j the slave nodes). ESPACE_LAGS_C='NOEUD': one
// per slave node, Phi_k = N_k ("standard" mortar multipliers: linear on a
// SEG2, quadratic on a SEG3); 'PAIRE': one polynomial of the cells' degree
// over each pair of neighbouring cells (buildMultipliers()). LAGS_C, the
// nodal output, is lambda at the slave nodes.
// Constraint: with the nodal weighted gaps
//   gt_j = sum over the pairs (slave cell, master segment) of G_j
// (contact/mortar.hpp: int N_j g dGamma_0 over the part of the slave facing
// the master, g measured along the slave normal), multiplier k's weighted gap
// is gt_k = int Phi_k g dGamma_0 = sum_j Phi_k(j) gt_j, its mean gap
// gm_k = gt_k / D_k (D_k = int Phi_k dGamma_0), and the
// contact conditions
//   lambda_k <= 0,  gt_k >= 0,  lambda_k gt_k = 0
// are the root of the complementarity function
//   C_k = lambda_k - min(0, lambda_k + c gm_k),   c = S / D_k
// (S the zone's stiffness scale, contact_base.hpp: c is a stiffness per unit
// length, so that the choice is scale-free; DEFI_CONT's COEF_CONT replaces it;
// it changes the iterates, not the solution). Newton's method on C_k = 0, with
// the statuses chosen at every assembly from the current iterate (semi-smooth
// Newton, as code_aster's ALGO_RESO_CONT='NEWTON'): k is ACTIVE when
// lambda_k + c gm_k <= 0, and
//   active:   equation gt_k = 0, and the force lambda_k dgt_k/du;
//   inactive: equation lambda_k = 0, and no force (lambda_k's next value is 0).
// The tangent is the exact derivative of these residuals for frozen statuses
// (lambda_k d2gt_k/du2, dgt_k/du: contact/mortar.hpp's exact derivatives), and
// it is symmetric. The first iteration of a computation takes its statuses
// from CONTACT_INIT: 'OUI' every paired multiplier active, 'NON' none,
// 'INTERPENETRE' those whose mean gap is closed (to round-off) or negative.
//
// Scaling as the other formulations (contact_base.hpp): the unknown is
// lambda_k / S and its equation S gt_k (or S (lambda_k / S) = lambda_k).
// Elements: one per pair, DOFs [slave cell DX, DY][master cell DX, DY]
// [the slave cell's multipliers], and one per multiplier (its diagonal).
#include <algorithm>
#include <array>
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
    std::map<int, int> fineIndex;
    for (std::size_t z = 0; z < zones_.size(); ++z) {
      contact::MortarOptions o;
      o.maxDistance = zones_[z].settings.maxDistance;
      options_.push_back(o);
      double extent = 0;
      for (const auto* cells : {&zones_[z].slaveCells, &zones_[z].masterCells})
        for (int c : *cells)
          for (int n : mesh_.cellNodes(c)) extent = std::max(extent, position(n, nullptr).cwiseAbs().maxCoeff());
      roundOff_.push_back(1e-12 * std::max(extent, 1e-300));
      const std::size_t firstCell = cells_.size();
      for (int c : zones_[z].slaveCells) {
        const auto n = mesh_.cellNodes(c);
        SlaveCell sc{c, static_cast<int>(z), static_cast<int>(n.size()), {-1, -1, -1}, {}, {}, true};
        const auto shares = contact::slaveShares(slave(sc, nullptr));
        for (int a = 0; a < sc.nodes; ++a) {
          auto it = fineIndex.find(n[a]);
          if (it == fineIndex.end()) {
            it = fineIndex.emplace(n[a], static_cast<int>(fine_.size())).first;
            fine_.push_back({n[a], static_cast<int>(z), 0.0, excluded_[z][n[a]] != 0, {}});
          }
          sc.fine[a] = it->second;
          fine_[it->second].share += shares[a];
          sc.skip = sc.skip && excluded_[z][n[a]];
        }
        cells_.push_back(sc);
      }
      buildMultipliers(z, firstCell);
    }
    for (const auto& l : fine_)
      if (!(l.share > 0)) throw Error("contact (LAC): slave node " + mesh_.nodeName(l.node) + " has no share of the slave length");
    for (auto& m : lags_)
      if (!(m.share > 0))
        throw Error("contact (LAC): the LAGS_C of slave node " + mesh_.nodeName(m.node) + " has no share of the slave length");
    fineGap_.assign(fine_.size(), 0.0);
    fineCovered_.assign(fine_.size(), 0.0);
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
    solvedStatus_ = active_;
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
  // The active-set loop releases only: a multiplier active at U is released
  // when, at U + dU of the problem linearized at U (its weighted gap
  // gt_k + dgt_k/du . dU, lambda_k of U + dU), the criterion of evaluate()
  // makes it inactive; its equation becomes S (lambda_k / S) = 0, and its
  // column stays (the linearization of its force lambda_k dgt_k/du at
  // lambda_k + dlambda_k = 0; lambda_k d2gt_k/du2 stays in the tangent).
  // Activations are left to the next iteration's statuses, from the gaps
  // themselves: one from a linearized gap where the gap itself stays open
  // (a curved contact sliding, tests/program/ironing) would leave a
  // multiplier at U + dU that the next residual, inactive, leaves out; the
  // semi-smooth Newton then cycles or takes twice the iterations.
  bool linearizedStatusChanges(const Eigen::VectorXd& U, const Eigen::VectorXd& dU,
                               std::vector<StatusChange>& changes) override {
    std::vector<double> linear(gap_);
    for (std::size_t p = 0; p < pairs_.size(); ++p) {
      const auto& sc = cells_[pairs_[p].slave];
      const auto& t = terms_[p];
      const int q = 2 * (t.slaveNodes + t.masterNodes);
      const auto dofs = pairDofs(pairs_[p]);
      for (std::size_t m = 0; m < sc.multipliers.size(); ++m) {
        const int k = sc.multipliers[m];
        if (!active_[k]) continue;
        for (int a = 0; a < sc.nodes; ++a)
          if (sc.weight[m][a] != 0)
            for (int i = 0; i < q; ++i)
              if (dofs[i] >= 0) linear[k] += sc.weight[m][a] * t.weightedGap[a].g(i) * dU(dofs[i]);
      }
    }
    const Eigen::VectorXd next_U = U + dU;
    std::vector<char> next(active_);
    for (std::size_t k = 0; k < lags_.size(); ++k) {
      if (!active_[k]) continue;
      double g = linear[k] / lags_[k].share;
      if (std::fabs(g) <= roundOff_[lags_[k].zone]) g = 0;
      next[k] = lambda(k, next_U) + statusCoefficient(k) * g <= 0;
    }
    if (next == solvedStatus_) return false;
    for (std::size_t k = 0; k < lags_.size(); ++k) {
      if (next[k] == active_[k]) continue;
      const int unknown = first_ + static_cast<int>(k);
      const double S = scales_[lags_[k].zone];
      changes.push_back({unknown, {{unknown, S}}, -S * U(unknown), false});
    }
    solvedStatus_ = next;
    return true;
  }
  std::string statusText() const override {
    return std::to_string(std::count(active_.begin(), active_.end(), 1)) + " active nodes, residual " +
           format::scientific(residual_, 2);
  }
  void saveStatus() override { savedStarted_ = started_; }
  void restoreStatus() override { started_ = savedStarted_; }

  // LAGS_C at every slave node: the multiplier field's value there.
  void extendDisplacement(const Eigen::VectorXd& U, mesh::NodalField& depl) const override {
    std::vector<std::pair<int, double>> lagsC;
    for (std::size_t j = 0; j < fine_.size(); ++j) lagsC.push_back({fine_[j].node, nodalPressure(j, U)});
    appendComponent(depl, "LAGS_C", lagsC);
  }

  // CONT_NOEU at every slave node: CONT 1 when a multiplier whose basis
  // function is not 0 there is active, JEU the node's weighted gap over the
  // paired part of its share, RN = LAGS_C, RNX, RNY the nodal force.
  void outputFields(const Eigen::VectorXd& U, std::vector<mesh::NodalField>& fields) const override {
    mesh::NodalField f{"CONT_NOEU", kContNoeu, std::vector<double>(kContNoeu.size() * mesh_.nodeCount(), 0.0)};
    evaluate(U, false);
    Eigen::VectorXd r = Eigen::VectorXd::Zero(U.size()), res;
    Eigen::MatrixXd Ke;
    for (std::size_t p = 0; p < pairs_.size(); ++p) {
      pairTerms(p, U, res, Ke);
      addLocal(pairDofs(pairs_[p]), res, r);
    }
    for (std::size_t j = 0; j < fine_.size(); ++j) {
      double* v = &f.values[5 * fine_[j].node];
      for (const auto& [k, w] : fine_[j].multipliers) v[0] = v[0] > 0 || (w != 0 && active_[k]) ? 1.0 : 0.0;
      v[1] = fineCovered_[j] > 0 ? fineGap_[j] / fineCovered_[j] : 0.0;
      v[2] = nodalPressure(j, U);
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
    int fine[3];                 // the slave node (fine_) of each local node
    std::vector<int> multipliers;  // the LAGS_C unknowns whose basis functions are not 0 on the cell
    // weight[m][a]: multiplier m's basis function at local node a (the basis
    // function on the cell is sum_a weight[m][a] N_a).
    std::vector<std::array<double, 3>> weight;
    bool skip;  // every node excluded (SANS_GROUP_NO): no contact on the cell
  };
  struct Pair {
    int slave;   // in cells_
    int master;  // in the zone's master cells
    bool operator==(const Pair& o) const { return slave == o.slave && master == o.master; }
    bool operator!=(const Pair& o) const { return !(*this == o); }
  };
  // A node of the slave cells.
  struct SlaveNode {
    int node;
    int zone;
    double share;  // D_j = int N_j dGamma_0 over the slave cells
    bool excluded;
    std::vector<std::pair<int, double>> multipliers;  // (k, Phi_k at the node)
  };
  // A LAGS_C unknown, attached to a slave node.
  struct Lags {
    int node;
    int zone;
    double share;  // D_k = int Phi_k dGamma_0
    bool excluded;
  };

  // The LAGS_C unknowns of zone z and their basis functions on its slave
  // cells (cells_[first ..]). Standard: one at every slave node, the basis
  // function of node j being N_j on every cell (the cells' own shape
  // functions). In pairs: the cells are taken two by two along their lines
  // (cellPairs()), and the multiplier is a polynomial of the cells' degree
  // over each pair, in the pair's parameter (-1 to 0 on the first cell, 0 to
  // 1 on the second): quadratic on two SEG3, with LAGS_C unknowns at the
  // pair's three vertex nodes; linear on two SEG2, at its two ends. A cell
  // left alone keeps the standard functions.
  void buildMultipliers(std::size_t z, std::size_t first) {
    std::map<int, int> index;  // mesh node -> its LAGS_C unknown in this zone
    auto multiplierAt = [&](int node) {
      auto it = index.find(node);
      if (it == index.end()) {
        it = index.emplace(node, static_cast<int>(lags_.size())).first;
        lags_.push_back({node, static_cast<int>(z), 0.0, excluded_[z][node] != 0});
      }
      return it->second;
    };
    std::map<std::pair<int, int>, double> values;  // (unknown, slave node) -> basis function there
    auto attach = [&](SlaveCell& sc, int k, const std::array<double, 3>& w) {
      sc.multipliers.push_back(k);
      sc.weight.push_back(w);
      for (int a = 0; a < sc.nodes; ++a)
        if (w[a] != 0) values[{k, sc.fine[a]}] = w[a];
    };
    const bool pairs = zones_[z].settings.lacPairs;
    for (const auto& group : pairs ? cellPairs(first, cells_.size()) : singletons(first, cells_.size())) {
      if (group.size() == 1) {
        SlaveCell& sc = cells_[group[0]];
        const auto n = mesh_.cellNodes(sc.cell);
        for (int a = 0; a < sc.nodes; ++a) {
          std::array<double, 3> w{0, 0, 0};
          w[a] = 1;
          attach(sc, multiplierAt(n[a]), w);
        }
        continue;
      }
      SlaveCell& A = cells_[group[0]];
      SlaveCell& B = cells_[group[1]];
      const auto na = mesh_.cellNodes(A.cell), nb = mesh_.cellNodes(B.cell);
      const int shared = na[0] == nb[0] || na[0] == nb[1] ? na[0] : na[1];
      const int endA = na[0] == shared ? na[1] : na[0], endB = nb[0] == shared ? nb[1] : nb[0];
      const bool quadratic = A.nodes == 3 && B.nodes == 3;
      // The pair's parameter at each local node of a cell, and its basis polynomials.
      auto parameter = [&](const auto& n, int a, int end, double sign) {
        return n[a] == end ? sign : n[a] == shared ? 0.0 : 0.5 * sign;
      };
      std::vector<int> coarse = quadratic ? std::vector<int>{endA, shared, endB} : std::vector<int>{endA, endB};
      auto basis = [&](std::size_t c, double x) {
        if (!quadratic) return c == 0 ? 0.5 * (1 - x) : 0.5 * (1 + x);
        return c == 0 ? 0.5 * x * (x - 1) : c == 1 ? 1 - x * x : 0.5 * x * (x + 1);
      };
      for (int side = 0; side < 2; ++side) {
        SlaveCell& sc = side == 0 ? A : B;
        const auto& n = side == 0 ? na : nb;
        for (std::size_t c = 0; c < coarse.size(); ++c) {
          std::array<double, 3> w{0, 0, 0};
          for (int a = 0; a < sc.nodes; ++a)
            w[a] = basis(c, parameter(n, a, side == 0 ? endA : endB, side == 0 ? -1.0 : 1.0));
          attach(sc, multiplierAt(coarse[c]), w);
        }
      }
    }
    for (const auto& [key, w] : values) {
      fine_[key.second].multipliers.push_back({key.first, w});
      lags_[key.first].share += w * fine_[key.second].share;
    }
  }
  std::vector<std::vector<int>> singletons(std::size_t first, std::size_t last) const {
    std::vector<std::vector<int>> out;
    for (std::size_t i = first; i < last; ++i) out.push_back({static_cast<int>(i)});
    return out;
  }
  // The cells first .. last - 1 two by two along their lines (open lines from
  // an end, then closed ones); a line of an odd number of cells ends with a
  // cell alone. Every cell alone when a vertex is shared by more than two.
  std::vector<std::vector<int>> cellPairs(std::size_t first, std::size_t last) const {
    std::map<int, std::vector<int>> at;  // vertex node -> cells
    for (std::size_t i = first; i < last; ++i) {
      const auto n = mesh_.cellNodes(cells_[i].cell);
      for (int v = 0; v < 2; ++v) at[n[v]].push_back(static_cast<int>(i));
    }
    for (const auto& [v, cs] : at)
      if (cs.size() > 2) return singletons(first, last);
    std::vector<char> seen(cells_.size(), 0);
    std::vector<std::vector<int>> out;
    auto walk = [&](int start, int from) {
      std::vector<int> line;
      for (int c = start, v = from; c >= 0;) {
        line.push_back(c);
        seen[c] = 1;
        const auto n = mesh_.cellNodes(cells_[c].cell);
        const int exit = n[0] == v ? n[1] : n[0];
        int next = -1;
        for (int d : at[exit])
          if (!seen[d]) next = d;
        c = next;
        v = exit;
      }
      for (std::size_t i = 0; i + 1 < line.size(); i += 2) out.push_back({line[i], line[i + 1]});
      if (line.size() % 2) out.push_back({line.back()});
    };
    for (std::size_t i = first; i < last; ++i) {
      if (seen[i]) continue;
      const auto n = mesh_.cellNodes(cells_[i].cell);
      for (int v = 0; v < 2; ++v)
        if (at[n[v]].size() == 1) {
          walk(static_cast<int>(i), n[v]);
          break;
        }
    }
    for (std::size_t i = first; i < last; ++i)
      if (!seen[i]) walk(static_cast<int>(i), mesh_.cellNodes(cells_[i].cell)[0]);
    return out;
  }

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
    for (int k : sc.multipliers) dofs.push_back(first_ + k);
    return dofs;
  }
  double lambda(std::size_t k, const Eigen::VectorXd& U) const {
    return scales_[lags_[k].zone] * U(first_ + static_cast<int>(k));
  }
  // LAGS_C at slave node j: sum_k lambda_k Phi_k there.
  double nodalPressure(std::size_t j, const Eigen::VectorXd& U) const {
    double p = 0;
    for (const auto& [k, w] : fine_[j].multipliers) p += w * lambda(k, U);
    return p;
  }
  // c of node k's status criterion: the zone's, or S / D_k.
  double statusCoefficient(std::size_t k) const {
    const double c = zones_[lags_[k].zone].settings.statusCoefficient;
    return c > 0 ? c : scales_[lags_[k].zone] / lags_[k].share;
  }
  double meanGap(std::size_t k) const {
    const double g = gap_[k] / lags_[k].share;
    return std::fabs(g) <= roundOff_[lags_[k].zone] ? 0.0 : g;
  }

  // The pairs' weighted gaps, the nodal ones, the statuses and the contact residual at U.
  void evaluate(const Eigen::VectorXd& U, bool initial) const {
    terms_.resize(pairs_.size());
    std::fill(fineGap_.begin(), fineGap_.end(), 0.0);
    std::fill(fineCovered_.begin(), fineCovered_.end(), 0.0);
    for (std::size_t p = 0; p < pairs_.size(); ++p) {
      const auto& sc = cells_[pairs_[p].slave];
      terms_[p] = contact::mortarPair(slave(sc, &U), segment(zones_[sc.zone].masterCells[pairs_[p].master], &U),
                                      options_[sc.zone]);
      for (int a = 0; a < sc.nodes; ++a) {
        fineGap_[sc.fine[a]] += terms_[p].weightedGap[a].v;
        fineCovered_[sc.fine[a]] += terms_[p].pairedShare[a];
      }
    }
    // The multipliers' weighted gaps gt_k = sum_j Phi_k(j) gt_j.
    std::fill(gap_.begin(), gap_.end(), 0.0);
    std::fill(covered_.begin(), covered_.end(), 0.0);
    for (std::size_t j = 0; j < fine_.size(); ++j)
      for (const auto& [k, w] : fine_[j].multipliers) {
        gap_[k] += w * fineGap_[j];
        covered_[k] += w * fineCovered_[j];
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
        else active = lambda(k, U) + statusCoefficient(k) * g <= 0;
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
    const int m = q + static_cast<int>(sc.multipliers.size());
    res.setZero(m);
    Ke.setZero(m, m);
    const double S = scales_[sc.zone];
    for (std::size_t m = 0; m < sc.multipliers.size(); ++m) {
      const int k = sc.multipliers[m];
      if (!active_[k]) continue;
      // The pair's part of gt_k: sum_a Phi_k(a) G_a.
      contact::MortarJet G = contact::MortarJet::constant(0);
      for (int a = 0; a < sc.nodes; ++a)
        if (sc.weight[m][a] != 0) G += sc.weight[m][a] * t.weightedGap[a];
      const double lam = lambda(k, U);
      const int row = q + static_cast<int>(m);
      res.head(q) += lam * G.g.head(q);
      Ke.topLeftCorner(q, q) += lam * G.h.topLeftCorner(q, q);
      Ke.col(row).head(q) = S * G.g.head(q);
      Ke.row(row).head(q) = S * G.g.head(q).transpose();
      res(row) = S * G.v;
    }
  }

  std::vector<contact::MortarOptions> options_;  // per zone
  std::vector<double> roundOff_;                 // per zone: a mean gap within it is closed
  std::vector<SlaveCell> cells_;
  std::vector<SlaveNode> fine_;
  std::vector<Lags> lags_;
  std::vector<Pair> pairs_;
  bool started_ = false, savedStarted_ = false, initialIteration_ = false;
  mutable std::vector<contact::MortarPair> terms_;  // per pair, of the last evaluate()
  mutable std::vector<double> fineGap_, fineCovered_;  // per slave node: gt_j, and the paired part of D_j
  mutable std::vector<double> gap_, covered_;          // per LAGS_C: gt_k, and the paired part of D_k
  mutable std::vector<char> active_;
  mutable std::vector<char> solvedStatus_;  // the statuses the last correction was solved with
  mutable double residual_ = 0;
};

}  // namespace

std::unique_ptr<AdditionalTerms> makeMortarContact(const MechanicalSystem& system, std::vector<ContactZone> zones,
                                                   const ContactSettings& settings) {
  return std::make_unique<MortarContact>(system, std::move(zones), settings);
}

}  // namespace aster::analysis::detail
