// Closest-point projection of a slave point on master segments (SEG2, SEG3),
// in the CURRENT configuration, 2D (XY plane).
//
// On one segment x_m(xi), the projection xi* minimises |x_s - x_m(xi)|^2 over
// xi in [-1,1]; inside the segment it solves the stationarity condition
//   r(xi) = (x_s - x_m(xi)) . dx_m/dxi = 0
// (a cubic in xi for a SEG3, linear for a SEG2). Method: the sign changes of
// r(xi) on a dense sampling of [-1,1] bracket the local minima; each is
// polished by a safeguarded Newton iteration (bisection when a Newton step
// leaves the bracket); both ends are candidates too; the nearest wins.
// The gap is g = (x_s - x_m(xi*)) . n_m(xi*) with the master normal
// n_m = (t_y, -t_x)/|t|: g > 0 separated, g < 0 penetration.
//
// When the nearest point is an END of the segment and the slave point lies
// beyond it (r pushes outward), the overshoot is measured in xi units as
// beyond = |r(end)| / |dx_m/dxi(end)|^2 (tangential distance past the end over
// the end's Jacobian). Up to ProjectionOptions::outsideTolerance the projection
// is CLAMPED to the end (xi is then held fixed at +-1 by the linearization);
// beyond it the point is OUTSIDE the segment (not paired). This plays the role
// of code_aster's TOLE_PROJ_EXT (default 0.50), here measured in xi units.
#pragma once
#include <vector>

#include <Eigen/Core>

#include "contact/segment.hpp"
#include "fem/edge_geometry.hpp"

namespace aster::contact {

enum class ProjectionStatus {
  Inside,   // stationary point of the distance in [-1,1]
  Clamped,  // past an end by at most outsideTolerance: held at the end
  Outside,  // past an end by more than outsideTolerance: not paired
};

const char* projectionStatusName(ProjectionStatus s);

struct ProjectionOptions {
  double outsideTolerance = 0.5;  // in xi units past an end (>= 0)
  double maxDistance = -1;        // DIST_APPA: farther points are not paired (< 0: no limit)
  int samples = 16;               // intervals of the bracketing sampling of a SEG3
  int maxIterations = 100;        // safeguarded Newton iterations
};

struct Projection {
  ProjectionStatus status = ProjectionStatus::Outside;
  double xi = 0;          // master parameter of the projection (an end when clamped or outside)
  fem::EdgeFrame master;  // point, tangent, normal, curvature of the master at xi
  double gap = 0;         // (x_s - x_m(xi)) . n_m(xi)
  double distance = 0;    // |x_s - x_m(xi)|
  double beyond = 0;      // overshoot past the end in xi units (0 when inside)
};

// Projection of xs on one segment.
Projection projectOnSegment(const Eigen::Vector2d& xs, const Segment& master, const ProjectionOptions& options = {});

struct MasterProjection {
  int segment = -1;  // index in the master list, -1 when outside every segment
  Projection projection;  // when segment == -1: the nearest (Outside) projection
  bool paired() const { return segment >= 0; }
};

// The closest valid (Inside, then Clamped) projection over several master
// segments: the smallest distance wins, an Inside projection beating a
// Clamped one at equal distance. segment = -1 when the point falls outside
// every segment, or when the closest valid projection is farther than
// options.maxDistance (>= 0). Throws when the list is empty.
MasterProjection projectOnMaster(const Eigen::Vector2d& xs, const std::vector<Segment>& masters,
                                 const ProjectionOptions& options = {});

}  // namespace aster::contact
