// Mortar (segment-to-segment) contact, 2D, frictionless: the weighted gaps of
// one slave cell against one master segment, with their exact first and
// second derivatives (code_aster's ALGO_CONT='LAC' family of methods).
//
// Slave cell x(xi) = sum_a N_a(xi) x_a (SEG2 or SEG3, current coordinates),
// its normal n(xi) = (t_y, -t_x)/|t|, t = dx/dxi (outward when the boundary
// is walked counterclockwise, as ORIE_PEAU orients it). A slave point is
// paired with the master point y(eta) met along its normal:
//   (y(eta) - x(xi)) . t(xi) = 0,
// and its gap is g(xi) = (y(eta) - x(xi)) . n(xi) (> 0 separated, < 0
// penetration). The weighted gap of slave node j, over the part of the slave
// cell facing the master segment (the overlap [lo, hi] in xi), is
//   G_j = int_lo^hi N_j(xi) g(xi) |dX/dxi| dxi,
// integrated on the REFERENCE slave cell (code_aster's TYPE_JACOBIEN='INITIAL'),
// so that the multipliers are pressures per unit reference length. The ends
// of the overlap are the slave cell's ends, or the points of the slave whose
// normal passes through a master end node; Gauss points are placed on the
// overlap itself, so that the integral has no kink inside (exact for the
// polynomial integrands of straight segments, and of the order of the Gauss
// rule otherwise).
//
// Everything is written in Jet arithmetic (jet.hpp) over the 2 (ns + nm)
// coordinates q = [x_1, .., x_ns, y_1, .., y_nm] (x, y of each node), so that
// dG_j/dq and d2G_j/dq2 are exact: they carry the motion of the overlap ends,
// of the Gauss points, of the projection and of the normal.
#pragma once
#include <array>

#include <Eigen/Core>

#include "contact/jet.hpp"
#include "contact/segment.hpp"

namespace aster::contact {

// q has at most 12 entries: a SEG3 slave and a SEG3 master.
inline constexpr int kMortarDofs = 12;
using MortarJet = Jet<kMortarDofs>;

struct MortarSlave {
  fem::CellType type = fem::CellType::SEG2;
  SegmentNodes reference = SegmentNodes::Zero();  // X_a, before deformation
  SegmentNodes current = SegmentNodes::Zero();    // x_a
  int nodes() const { return type == fem::CellType::SEG3 ? 3 : 2; }
};

struct MortarOptions {
  int gaussPoints = 6;  // on the overlap (code_aster's INTEGRATION='AUTO' for LAC is its own choice)
  // A pair whose gap at the middle of the overlap exceeds this (in absolute
  // value) is not a pair (< 0: no limit).
  double maxDistance = -1;
};

struct MortarPair {
  bool paired = false;
  double lo = 0, hi = 0;  // the overlap in slave xi
  int slaveNodes = 0, masterNodes = 0;
  // G_j of slave node j (local numbering), as Jets over q (unused entries 0).
  std::array<MortarJet, 3> weightedGap;
  // int_lo^hi N_j dGamma_0: the part of node j's share of the slave length
  // that faces this master segment.
  std::array<double, 3> pairedShare{0, 0, 0};
};

// The weighted gaps of `slave` against `master` (paired = false when the
// slave's normals do not meet the master, or when the two do not face each
// other: n_slave . n_master >= 0 at the middle of the overlap).
MortarPair mortarPair(const MortarSlave& slave, const Segment& master, const MortarOptions& options = {});

// Whether mortarPair() would pair them (the overlap alone, without the integrals).
bool mortarPaired(const MortarSlave& slave, const Segment& master, const MortarOptions& options = {});

// int_-1^1 N_j |dX/dxi| dxi of each node j of the reference slave cell.
std::array<double, 3> slaveShares(const MortarSlave& slave);

}  // namespace aster::contact
