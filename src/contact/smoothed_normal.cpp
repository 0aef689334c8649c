// Smoothed normals and their gap (definitions in the header). One template,
// evaluated with doubles for values and with second-order dual numbers for
// the derivatives, so that the two never disagree.
#include "contact/smoothed_normal.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "expr/dual.hpp"

namespace aster::contact {

namespace {

using std::sqrt;

double valueOf(double x) { return x; }
template <int N>
double valueOf(const expr::Dual2<N>& x) {
  return x.v;
}

// Coordinates of patch node j in the variables z: z[2 + 2j], z[3 + 2j]
// (z[0], z[1] are the slave point's).
template <class T>
void nodeNormal(const T* z, const NormalPatch& patch, int a, T& nx, T& ny) {
  T sx(0.0), sy(0.0);
  for (const auto& f : patch.facets[a]) {
    const SegmentShape sh = segmentShape(f.type, f.xi);
    const int nb = f.type == fem::CellType::SEG3 ? 3 : 2;
    T tx(0.0), ty(0.0);
    for (int b = 0; b < nb; ++b) {
      tx += sh.dN(b) * z[2 + 2 * f.node[b]];
      ty += sh.dN(b) * z[3 + 2 * f.node[b]];
    }
    const T len = sqrt(tx * tx + ty * ty);
    sx += ty / len;
    sy -= tx / len;
  }
  const T s = sqrt(sx * sx + sy * sy);
  // Unit normals summing to ~0: cells around the node oriented against each other.
  if (!(valueOf(s) > 1e-6))
    throw Error("contact LISSAGE: the master cells around a node have opposite normals (orient them alike, "
                "MODI_MAILLAGE ORIE_PEAU)");
  nx = sx / s;
  ny = sy / s;
}

template <class T>
struct GapTerms {
  T gap;       // (x_s - x_m(xi)) . n~(xi)
  T residual;  // (x_s - x_m(xi)) . dx_m/dxi, 0 at the closest point
  T nx, ny;    // n~(xi)
  T N[3];      // the segment's shape functions at xi
};

template <class T>
GapTerms<T> evaluate(const T* z, const Segment& segment, const NormalPatch& patch, const T& xi) {
  const int M = segment.nodes();
  T N[3], dN[3];
  if (segment.type == fem::CellType::SEG3) {
    N[0] = 0.5 * xi * (xi - 1.0), N[1] = 0.5 * xi * (xi + 1.0), N[2] = 1.0 - xi * xi;
    dN[0] = xi - 0.5, dN[1] = xi + 0.5, dN[2] = -2.0 * xi;
  } else {
    N[0] = 0.5 * (1.0 - xi), N[1] = 0.5 * (1.0 + xi);
    dN[0] = T(-0.5), dN[1] = T(0.5);
  }
  T ax = z[0], ay = z[1], cx(0.0), cy(0.0), mx(0.0), my(0.0);
  for (int a = 0; a < M; ++a) {
    ax -= N[a] * z[2 + 2 * a];
    ay -= N[a] * z[3 + 2 * a];
    cx += dN[a] * z[2 + 2 * a];
    cy += dN[a] * z[3 + 2 * a];
    T nx, ny;
    nodeNormal(z, patch, a, nx, ny);
    mx += N[a] * nx;
    my += N[a] * ny;
  }
  const T m = sqrt(mx * mx + my * my);
  GapTerms<T> t;
  t.nx = mx / m;
  t.ny = my / m;
  t.gap = ax * t.nx + ay * t.ny;
  t.residual = ax * cx + ay * cy;
  for (int a = 0; a < 3; ++a) t.N[a] = a < M ? N[a] : T(0.0);
  return t;
}

void checkPatch(const Segment& segment, const NormalPatch& patch) {
  checkSegmentType(segment.type, "master");
  const int P = static_cast<int>(patch.nodes.size());
  if (P < segment.nodes() || P > kMaxPatchNodes)
    throw Error("contact LISSAGE: a master segment's normal depends on " + std::to_string(P) +
                " nodes; it must be between its own nodes and " + std::to_string(kMaxPatchNodes) +
                " (a master line: at most two master cells at a node)");
  for (int a = 0; a < segment.nodes(); ++a) {
    if (patch.facets[a].empty()) throw Error("contact LISSAGE: a master node belongs to no master cell");
    for (const auto& f : patch.facets[a]) {
      checkSegmentType(f.type, "master");
      for (int b = 0; b < (f.type == fem::CellType::SEG3 ? 3 : 2); ++b)
        if (f.node[b] < 0 || f.node[b] >= P) throw Error("contact LISSAGE: patch node index out of range");
    }
  }
}

std::vector<double> values(const Eigen::Vector2d& xs, const NormalPatch& patch) {
  std::vector<double> z(2 + 2 * patch.nodes.size());
  z[0] = xs(0), z[1] = xs(1);
  for (std::size_t j = 0; j < patch.nodes.size(); ++j) z[2 + 2 * j] = patch.nodes[j](0), z[3 + 2 * j] = patch.nodes[j](1);
  return z;
}

// Variables z = (x_s, patch nodes, unused..., xi): xi is the last of NZ.
template <int NZ>
SmoothedGap linearize(const Eigen::Vector2d& xs, const Segment& segment, const NormalPatch& patch,
                      const Projection& projection) {
  using D = expr::Dual2<NZ>;
  const std::vector<double> v = values(xs, patch);
  const int nq = static_cast<int>(v.size()), ix = NZ - 1;
  std::vector<D> z(nq);
  for (int i = 0; i < nq; ++i) z[i] = D::variable(v[i], i);
  const GapTerms<D> t = evaluate(z.data(), segment, patch, D::variable(projection.xi, ix));
  const D& G = t.gap;
  const D& R = t.residual;
  SmoothedGap out;
  out.gap = G.v;
  out.gradient.resize(nq);
  out.hessian.resize(nq, nq);
  // The force direction: n~ at x_s, -N_a n~ at the segment's node a, 0 at the other patch nodes.
  std::vector<const D*> force(nq, nullptr);
  std::vector<D> owned;
  owned.reserve(2 * segment.nodes());
  force[0] = &t.nx;
  force[1] = &t.ny;
  for (int a = 0; a < segment.nodes(); ++a) {
    owned.push_back(-(t.N[a] * t.nx));
    owned.push_back(-(t.N[a] * t.ny));
  }
  for (int a = 0; a < segment.nodes(); ++a) force[2 + 2 * a] = &owned[2 * a], force[3 + 2 * a] = &owned[2 * a + 1];
  out.force.setZero(nq);
  out.forceJacobian.setZero(nq, nq);
  for (int i = 0; i < nq; ++i)
    if (force[i]) {
      out.force(i) = force[i]->v;
      for (int j = 0; j < nq; ++j) out.forceJacobian(i, j) = force[i]->g[j];
    }
  if (projection.status == ProjectionStatus::Clamped) {
    for (int i = 0; i < nq; ++i) {
      out.gradient(i) = G.g[i];
      for (int j = 0; j < nq; ++j) out.hessian(i, j) = G.h[i][j];
    }
    return out;
  }
  // xi*(q) from R(q, xi*) = 0 (gap.hpp's formulas).
  const double rxi = R.g[ix];
  if (!(rxi < 0)) {
    std::ostringstream m;
    m << "contact gap: degenerate projection of (" << xs(0) << ", " << xs(1) << ") at xi = " << projection.xi
      << " (the distance is not minimal there: the point sits at a centre of curvature of the master)";
    throw Error(m.str());
  }
  Eigen::VectorXd dxi(nq);
  for (int i = 0; i < nq; ++i) dxi(i) = -R.g[i] / rxi;
  for (int i = 0; i < nq; ++i)
    if (force[i])
      for (int j = 0; j < nq; ++j) out.forceJacobian(i, j) += force[i]->g[ix] * dxi(j);
  for (int i = 0; i < nq; ++i) out.gradient(i) = G.g[i] + G.g[ix] * dxi(i);
  for (int i = 0; i < nq; ++i)
    for (int j = 0; j < nq; ++j) {
      const double d2xi =
          -(R.h[i][j] + R.h[i][ix] * dxi(j) + dxi(i) * R.h[ix][j] + R.h[ix][ix] * dxi(i) * dxi(j)) / rxi;
      out.hessian(i, j) = G.h[i][j] + G.h[i][ix] * dxi(j) + dxi(i) * G.h[ix][j] + G.h[ix][ix] * dxi(i) * dxi(j) +
                          G.g[ix] * d2xi;
    }
  return out;
}

}  // namespace

Eigen::Vector2d smoothedNodeNormal(const NormalPatch& patch, int a) {
  if (a < 0 || a > 2 || patch.facets[a].empty()) throw Error("contact LISSAGE: no master cell around the node");
  const std::vector<double> z = values(Eigen::Vector2d::Zero(), patch);
  Eigen::Vector2d n;
  nodeNormal(z.data(), patch, a, n(0), n(1));
  return n;
}

Eigen::Vector2d smoothedNormal(const Segment& segment, const NormalPatch& patch, double xi) {
  checkPatch(segment, patch);
  const SegmentShape sh = segmentShape(segment.type, xi);
  Eigen::Vector2d m = Eigen::Vector2d::Zero();
  for (int a = 0; a < segment.nodes(); ++a) m += sh.N(a) * smoothedNodeNormal(patch, a);
  return m.normalized();
}

double smoothedGap(const Eigen::Vector2d& xs, const Segment& segment, const NormalPatch& patch, double xi) {
  checkPatch(segment, patch);
  const std::vector<double> z = values(xs, patch);
  return evaluate(z.data(), segment, patch, xi).gap;
}

SmoothedGap linearizeSmoothedGap(const Eigen::Vector2d& xs, const Segment& segment, const NormalPatch& patch,
                                 const Projection& projection) {
  checkPatch(segment, patch);
  if (projection.status == ProjectionStatus::Outside) {
    std::ostringstream m;
    m << "contact gap: the slave point (" << xs(0) << ", " << xs(1) << ") projects outside the master segment ("
      << projection.beyond << " past its end in xi units)";
    throw Error(m.str());
  }
  // Two sizes: a SEG2 line's patch (4 nodes) and any other (up to 7).
  if (patch.nodes.size() <= 4) return linearize<2 + 2 * 4 + 1>(xs, segment, patch, projection);
  return linearize<2 + 2 * kMaxPatchNodes + 1>(xs, segment, patch, projection);
}

}  // namespace aster::contact
