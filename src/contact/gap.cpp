// Gap linearization (formulas in gap.hpp). Everything is built on z = (q, xi):
// a = x_s - x_m(xi) and c = dx_m/dxi are bilinear in (y, xi-functions), so
// their z-derivatives are simple; G = a . Rc/|c| and r = a . c follow by the
// chain rule, with R the rotation (c_x, c_y) -> (c_y, -c_x).
#include "contact/gap.hpp"

#include <algorithm>
#include <sstream>

namespace aster::contact {

namespace {

template <int M>
struct GapLinearizer {
  static constexpr int N = 2 + 2 * M;  // q size
  static constexpr int Z = N + 1;      // z = (q, xi)
  using Vz = Eigen::Matrix<double, Z, 1>;
  using Mz = Eigen::Matrix<double, Z, Z>;
  using Az = Eigen::Matrix<double, 2, Z>;
  using Vq = Eigen::Matrix<double, N, 1>;
  using Mq = Eigen::Matrix<double, N, N>;

  const SegmentShape sh;
  // Adds sum_i w_i d2a_i/dz2 to H (a = x_s - sum N_a y_a: only y-xi and xi-xi terms).
  void addSecondA(const Eigen::Vector2d& w, const Eigen::Vector2d& d2x, Mz& H) const {
    for (int a = 0; a < M; ++a)
      for (int i = 0; i < 2; ++i) {
        const int k = 2 + 2 * a + i;
        H(k, N) -= w(i) * sh.dN(a);
        H(N, k) -= w(i) * sh.dN(a);
      }
    H(N, N) -= w.dot(d2x);
  }
  // Adds sum_i w_i d2c_i/dz2 to H (c = sum dN_a y_a; d3x/dxi3 = 0 for SEG2/SEG3).
  void addSecondC(const Eigen::Vector2d& w, Mz& H) const {
    for (int a = 0; a < M; ++a)
      for (int i = 0; i < 2; ++i) {
        const int k = 2 + 2 * a + i;
        H(k, N) += w(i) * sh.d2N(a);
        H(N, k) += w(i) * sh.d2N(a);
      }
  }

  void run(const Eigen::Vector2d& xs, const Segment& s, double xi, bool xiFixed, NodeGap& out) const {
    const auto Y = s.x.topRows<M>();
    const Eigen::Vector2d xm = Y.transpose() * sh.N.template head<M>();
    const Eigen::Vector2d c = Y.transpose() * sh.dN.template head<M>();
    const Eigen::Vector2d d2x = Y.transpose() * sh.d2N.template head<M>();
    const Eigen::Vector2d a = xs - xm;

    Az az = Az::Zero(), cz = Az::Zero();
    az.template block<2, 2>(0, 0).setIdentity();
    for (int k = 0; k < M; ++k) {
      az.template block<2, 2>(0, 2 + 2 * k) = -sh.N(k) * Eigen::Matrix2d::Identity();
      cz.template block<2, 2>(0, 2 + 2 * k) = sh.dN(k) * Eigen::Matrix2d::Identity();
    }
    az.col(N) = -c;
    cz.col(N) = d2x;

    Eigen::Matrix2d R;
    R << 0, 1, -1, 0;
    const double J = c.norm();
    const Eigen::Vector2d t = c / J, n = R * t, RTa = R.transpose() * a;
    const double G = a.dot(n);
    const Eigen::Matrix2d P = Eigen::Matrix2d::Identity() - t * t.transpose();
    const Eigen::Vector2d fa = n;
    const Eigen::Vector2d fc = (RTa - G * t) / J;
    const Eigen::Matrix2d fac = R * P / J;  // d n / d c
    const Eigen::Matrix2d fcc =
        -(RTa * t.transpose() + t * RTa.transpose() + G * (Eigen::Matrix2d::Identity() - 3 * t * t.transpose())) / (J * J);

    const Vz Gz = az.transpose() * fa + cz.transpose() * fc;
    Mz Gzz = az.transpose() * fac * cz;
    Gzz += Mz(Gzz.transpose());
    Gzz += cz.transpose() * fcc * cz;
    addSecondA(fa, d2x, Gzz);
    addSecondC(fc, Gzz);

    Vq gq, xq = Vq::Zero();
    Mq gqq, xqq = Mq::Zero();
    if (xiFixed) {
      gq = Gz.template head<N>();
      gqq = Gzz.template topLeftCorner<N, N>();
    } else {
      const Vz Rz = az.transpose() * c + cz.transpose() * a;
      Mz Rzz = az.transpose() * cz;
      Rzz += Mz(Rzz.transpose());
      addSecondA(c, d2x, Rzz);
      addSecondC(a, Rzz);
      const double rxi = Rz(N);
      if (!(rxi < 0)) {
        std::ostringstream m;
        m << "contact gap: degenerate projection of (" << xs(0) << ", " << xs(1) << ") at xi = " << xi
          << " (the distance is not minimal there: the point sits at a centre of curvature of the master)";
        throw Error(m.str());
      }
      const Vq dxi = -Rz.template head<N>() / rxi;
      const Vq rqxi = Rzz.template block<N, 1>(0, N);
      const Mq d2xi = -(Rzz.template topLeftCorner<N, N>() + rqxi * dxi.transpose() + dxi * rqxi.transpose() +
                        Rzz(N, N) * dxi * dxi.transpose()) / rxi;
      const Vq gqxi = Gzz.template block<N, 1>(0, N);
      gq = Gz.template head<N>() + Gz(N) * dxi;
      gqq = Gzz.template topLeftCorner<N, N>() + gqxi * dxi.transpose() + dxi * gqxi.transpose() +
            Gzz(N, N) * dxi * dxi.transpose() + Gz(N) * d2xi;
      xq = dxi;
      xqq = d2xi;
    }
    out.gap = G;
    out.gradient = gq;
    out.hessian = gqq;
    out.xiGradient = xq;
    out.xiHessian = xqq;
  }
};

}  // namespace

double gapRoundOff(const Eigen::Vector2d& xs, const Segment& master) {
  return 1e-12 * std::max(xs.lpNorm<Eigen::Infinity>(), master.x.topRows(master.nodes()).lpNorm<Eigen::Infinity>());
}

NodeGap linearizeGap(const Eigen::Vector2d& xs, const Segment& master, const Projection& projection) {
  checkSegmentType(master.type, "master");
  if (projection.status == ProjectionStatus::Outside) {
    std::ostringstream m;
    m << "contact gap: the slave point (" << xs(0) << ", " << xs(1) << ") projects outside the master segment ("
      << projection.beyond << " past its end in xi units)";
    throw Error(m.str());
  }
  NodeGap out;
  out.projection = projection;
  const bool fixed = projection.status == ProjectionStatus::Clamped;
  const SegmentShape sh = segmentShape(master.type, projection.xi);
  if (master.type == fem::CellType::SEG3) GapLinearizer<3>{sh}.run(xs, master, projection.xi, fixed, out);
  else GapLinearizer<2>{sh}.run(xs, master, projection.xi, fixed, out);
  return out;
}

NodeGap nodeToSegmentGap(const Eigen::Vector2d& xs, const Segment& master, const ProjectionOptions& options) {
  return linearizeGap(xs, master, projectOnSegment(xs, master, options));
}

}  // namespace aster::contact
