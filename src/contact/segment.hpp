// A contact segment (SEG2 or SEG3) given by the current coordinates of its
// nodes in the XY plane, with a run-time cell type, so that contact kernels
// need no mesh class.
// Conventions: isoparametric on xi in [-1,1]; node 1 at xi=-1, node 2 at
// xi=+1, node 3 (SEG3 only) the middle node at xi=0, with
//   SEG2: N1 = (1-xi)/2, N2 = (1+xi)/2
//   SEG3: N1 = xi(xi-1)/2, N2 = xi(xi+1)/2, N3 = 1-xi^2.
// A SEG3 is a curved (parabolic) segment and is always used as such.
// Normal: n = (t_y, -t_x)/|t| with t = dx/dxi (outward normal of a boundary
// walked counterclockwise).
#pragma once
#include <string>

#include <Eigen/Core>

#include "core/error.hpp"
#include "fem/cell_type.hpp"
#include "fem/edge_geometry.hpp"

namespace aster::contact {

// Node coordinates, one row per node; row 3 is unused for a SEG2.
using SegmentNodes = Eigen::Matrix<double, 3, 2>;

struct Segment {
  fem::CellType type = fem::CellType::SEG2;
  SegmentNodes x = SegmentNodes::Zero();

  int nodes() const { return type == fem::CellType::SEG3 ? 3 : 2; }

  static Segment seg2(const Eigen::Vector2d& p1, const Eigen::Vector2d& p2) {
    Segment s;
    s.type = fem::CellType::SEG2;
    s.x.row(0) = p1.transpose();
    s.x.row(1) = p2.transpose();
    return s;
  }
  // p3 is the middle node (xi = 0).
  static Segment seg3(const Eigen::Vector2d& p1, const Eigen::Vector2d& p2, const Eigen::Vector2d& p3) {
    Segment s;
    s.type = fem::CellType::SEG3;
    s.x.row(0) = p1.transpose();
    s.x.row(1) = p2.transpose();
    s.x.row(2) = p3.transpose();
    return s;
  }
};

// Throws unless the type is SEG2 or SEG3.
inline void checkSegmentType(fem::CellType t, const char* role) {
  if (t != fem::CellType::SEG2 && t != fem::CellType::SEG3)
    throw Error(std::string("contact: the ") + role + " cell must be a SEG2 or a SEG3, got " + fem::cellName(t));
}

// Shape functions padded to 3 entries (entry 3 is zero for a SEG2).
struct SegmentShape {
  Eigen::Vector3d N = Eigen::Vector3d::Zero();    // values
  Eigen::Vector3d dN = Eigen::Vector3d::Zero();   // d/dxi
  Eigen::Vector3d d2N = Eigen::Vector3d::Zero();  // d2/dxi2
};

inline SegmentShape segmentShape(fem::CellType t, double xi) {
  SegmentShape s;
  if (t == fem::CellType::SEG3) {
    s.N << 0.5 * xi * (xi - 1), 0.5 * xi * (xi + 1), 1 - xi * xi;
    s.dN << xi - 0.5, xi + 0.5, -2 * xi;
    s.d2N << 1, 1, -2;
  } else {
    checkSegmentType(t, "contact");
    s.N << 0.5 * (1 - xi), 0.5 * (1 + xi), 0;
    s.dN << -0.5, 0.5, 0;
  }
  return s;
}

// Point, tangent, normal and curvature of the segment at xi (fem's edge frame).
inline fem::EdgeFrame segmentFrame(const Segment& s, double xi) {
  if (s.type == fem::CellType::SEG3)
    return fem::edgeFrame<fem::CellType::SEG3>(s.x, xi);
  checkSegmentType(s.type, "contact");
  return fem::edgeFrame<fem::CellType::SEG2>(s.x.topRows<2>(), xi);
}

}  // namespace aster::contact
