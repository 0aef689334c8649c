// What the contact formulations share (contact_terms.cpp: DISCRETE and
// CONTINUE; mortar_contact.cpp: LAC): current positions and segments of the
// zones' cells, DOF lists, the slave nodes, the zones' stiffness scales, and
// CONT_NOEU's nodal forces and INFO=2 table. Internal to src/analysis.
#pragma once
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "analysis/additional_terms.hpp"
#include "analysis/contact_terms.hpp"
#include "analysis/mechanical_system.hpp"
#include "contact/projection.hpp"
#include "contact/segment.hpp"
#include "core/error.hpp"
#include "core/messages.hpp"
#include "fem/quadrature.hpp"

namespace aster::analysis::detail {

// The components of CONT_NOEU (contact_terms.hpp).
inline const std::vector<std::string> kContNoeu = {"CONT", "JEU", "RN", "RNX", "RNY"};

// What both formulations need: current positions, segments, DOF lists, the
// slave nodes of each zone.
class ContactBase : public AdditionalTerms {
 public:
  ContactBase(const MechanicalSystem& system, std::vector<ContactZone> zones, const ContactSettings& settings)
      : system_(system), mesh_(system.model().mesh()), zones_(std::move(zones)), settings_(settings) {
    std::vector<char> listed(mesh_.nodeCount(), 0);
    for (std::size_t z = 0; z < zones_.size(); ++z) {
      const auto& zs = zones_[z].settings;
      for (int c : zones_[z].masterCells) checkSegment(c, "master");
      for (int c : zones_[z].slaveCells) checkSegment(c, "slave");
      if (!(zs.outsideTolerance >= 0))
        throw Error("contact zone " + std::to_string(z + 1) + ": TOLE_PROJ_EXT must be >= 0, got " +
                    std::to_string(zs.outsideTolerance));
      contact::ProjectionOptions po;
      po.outsideTolerance = zs.outsideTolerance;
      po.maxDistance = zs.maxDistance;
      projections_.push_back(po);
      std::vector<char> ex(mesh_.nodeCount(), 0);
      for (int n : zs.excludedNodes) {
        if (n < 0 || n >= mesh_.nodeCount()) throw Error("contact: excluded node index out of range");
        ex[n] = 1;
      }
      excluded_.push_back(std::move(ex));
      for (int c : zones_[z].slaveCells)
        for (int n : mesh_.cellNodes(c))
          if (!listed[n]) {
            listed[n] = 1;
            slaveNodes_.push_back({n, static_cast<int>(z)});
          }
      scales_.push_back(stiffnessScale(zones_[z]));
    }
  }
  void setFirstUnknown(int first) override { first_ = first; }

 protected:
  struct ZoneNode {
    int node;
    int zone;
  };

  // S of a zone (contact_terms.hpp): the largest Young's modulus of the model's
  // 2D cells with a node on its slave or master cells, else of all the model's
  // cells, else 1.
  double stiffnessScale(const ContactZone& zone) const {
    const auto& materials = system_.problem().materials;
    if (!materials) return 1.0;
    std::vector<char> onZone(mesh_.nodeCount(), 0);
    for (const auto* cells : {&zone.slaveCells, &zone.masterCells})
      for (int c : *cells)
        for (int n : mesh_.cellNodes(c)) onZone[n] = 1;
    double near = 0, all = 0;
    for (int c : system_.model().cells()) {
      const model::ElasticMaterial* m = materials->at(c);
      if (!m || !(m->E > 0) || !std::isfinite(m->E)) continue;
      all = std::max(all, m->E);
      for (int n : mesh_.cellNodes(c))
        if (onZone[n]) {
          near = std::max(near, m->E);
          break;
        }
    }
    return near > 0 ? near : all > 0 ? all : 1.0;
  }
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
    system_.dofMap().appendNodeDofs(mesh_.cellNodes(cell).begin(), mesh_.cellNodes(cell).end(), 2, dofs);
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
  // int_cell f(a, xi) dGamma_0 for each local node a, added to out[a] (reference configuration).
  template <class F>
  void integrateOnSlave(int cell, F&& f, double* out) const {
    const contact::Segment s = segment(cell, nullptr);
    const auto& q = fem::gaussLegendre(6);
    for (int i = 0; i < q.size(); ++i) {
      const double xi = q.points[i](0);
      const auto sh = contact::segmentShape(s.type, xi);
      const double J = (s.x.transpose() * sh.dN).norm();
      for (int a = 0; a < 3; ++a) out[a] += q.weights[i] * J * f(a, xi);
    }
  }
  // DEPL with one more component, `name`, of the given (node, value) pairs (0 elsewhere).
  void appendComponent(mesh::NodalField& depl, const std::string& name,
                       const std::vector<std::pair<int, double>>& nodeValues) const {
    const int nc = static_cast<int>(depl.components.size());
    std::vector<double> values(static_cast<std::size_t>(nc + 1) * mesh_.nodeCount(), 0.0);
    for (int n = 0; n < mesh_.nodeCount(); ++n)
      for (int c = 0; c < nc; ++c) values[n * (nc + 1) + c] = depl.values[n * nc + c];
    for (const auto& [n, v] : nodeValues) values[n * (nc + 1) + nc] = v;
    depl.components.push_back(name);
    depl.values = std::move(values);
  }
  // The reaction of the terms at the slave nodes: RNX, RNY of CONT_NOEU.
  void nodalForces(const Eigen::VectorXd& r, mesh::NodalField& f) const {
    for (const auto& sn : slaveNodes_)
      for (int k = 0; k < 2; ++k) {
        const int d = system_.dof(sn.node, k);
        if (d >= 0) f.values[5 * sn.node + 3 + k] = 0.0 - r(d);  // no -0
      }
  }
  void printNodalTable(const mesh::NodalField& f) const {
    if (settings_.info < 2) return;
    std::string text = "DEFI_CONTACT (INFO=2): contact at the converged instant (CONT_NOEU)\n"
                       "    node          CONT   JEU          RN           RNX          RNY";
    for (const auto& sn : slaveNodes_) {
      char line[160];
      const double* v = &f.values[5 * sn.node];
      std::snprintf(line, sizeof line, "\n    %-12s  %d   %12.5E %12.5E %12.5E %12.5E", mesh_.nodeName(sn.node).c_str(),
                    static_cast<int>(v[0]), v[1], v[2], v[3], v[4]);
      text += line;
    }
    Messages::info(text);
  }

  const MechanicalSystem& system_;
  const mesh::Mesh& mesh_;
  std::vector<ContactZone> zones_;
  ContactSettings settings_;
  std::vector<contact::ProjectionOptions> projections_;  // per zone
  std::vector<std::vector<char>> excluded_;              // per zone, per mesh node
  std::vector<ZoneNode> slaveNodes_;                     // each slave node once (its first zone)
  std::vector<double> scales_;                           // per zone: S (multiplier = S * unknown)
  int first_ = 0;
};

// LAC: the mortar formulation (mortar_contact.cpp).
std::unique_ptr<AdditionalTerms> makeMortarContact(const MechanicalSystem& system, std::vector<ContactZone> zones,
                                                   const ContactSettings& settings);

}  // namespace aster::analysis::detail
