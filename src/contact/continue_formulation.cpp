// CONTINUE contact terms of one slave cell (formulation in the header).
#include "contact/continue_formulation.hpp"

#include <cmath>
#include <sstream>

#include "contact/gap.hpp"
#include "contact/vertex_blend.hpp"
#include "fem/quadrature.hpp"

namespace aster::contact {

const char* pointStatusName(PointStatus s) {
  switch (s) {
    case PointStatus::Contact: return "contact";
    case PointStatus::Separated: return "separated";
    case PointStatus::Unpaired: return "unpaired";
  }
  return "?";
}

namespace {

struct PointRule {
  double xi[fem::kMaxGaussPoints];
  double w[fem::kMaxGaussPoints];
  int size = 0;
};

PointRule slaveRule(fem::CellType type, const ContinueOptions& o) {
  PointRule r;
  if (o.integration == ContactIntegration::Nodes) {
    // Newton-Cotes at the nodes, in node order (1 at -1, 2 at +1, 3 at 0).
    if (type == fem::CellType::SEG3) {
      r.size = 3;
      r.xi[0] = -1, r.xi[1] = 1, r.xi[2] = 0;
      r.w[0] = 1.0 / 3, r.w[1] = 1.0 / 3, r.w[2] = 4.0 / 3;
    } else {
      r.size = 2;
      r.xi[0] = -1, r.xi[1] = 1;
      r.w[0] = 1, r.w[1] = 1;
    }
    return r;
  }
  if (o.gaussPoints < 1 || o.gaussPoints > fem::kMaxGaussPoints)
    throw Error("CONTINUE contact: the number of Gauss points per slave cell must be in 1.." +
                std::to_string(fem::kMaxGaussPoints) + ", got " + std::to_string(o.gaussPoints));
  const auto& q = fem::gaussLegendre(o.gaussPoints);
  r.size = q.size();
  for (int i = 0; i < r.size; ++i) r.xi[i] = q.points[i](0), r.w[i] = q.weights[i];
  return r;
}

}  // namespace

int multiplierCount(const SlaveCell& slave, const ContinueOptions& options) {
  return options.multiplierInterpolation == MultiplierInterpolation::Quadratic && slave.type == fem::CellType::SEG3
             ? 3
             : 2;
}

void continueCellTerms(const SlaveCell& slave, const std::vector<Segment>& masters, const ContinueOptions& options,
                       ContinueCellTerms& out, const std::vector<NormalPatch>* patches) {
  checkSegmentType(slave.type, "slave");
  const bool penalised = options.penalty != 0;
  if (penalised && !(options.penalty > 0 && std::isfinite(options.penalty)))
    throw Error("CONTINUE contact: COEF_PENA_CONT must be > 0, got " + std::to_string(options.penalty));
  if (!penalised && !(options.rho > 0 && std::isfinite(options.rho)))
    throw Error("CONTINUE contact: COEF_CONT must be > 0, got " + std::to_string(options.rho));
  if (masters.empty()) throw Error("CONTINUE contact: no master segment given");
  if (patches && patches->size() != masters.size())
    throw Error("CONTINUE contact: LISSAGE needs one normal patch per master segment");
  const int ns = slave.type == fem::CellType::SEG3 ? 3 : 2;
  const int nm = multiplierCount(slave, options);
  if (nm == 3 && options.integration == ContactIntegration::Gauss && options.gaussPoints < 3)
    throw Error("CONTINUE contact: quadratic LAGS_C on a SEG3 slave needs at least 3 Gauss points, got " +
                std::to_string(options.gaussPoints));
  int n = 2 * ns;
  out.masterOffsets.resize(masters.size());
  for (std::size_t k = 0; k < masters.size(); ++k) {
    checkSegmentType(masters[k].type, "master");
    out.masterOffsets[k] = n;
    n += 2 * (patches ? static_cast<int>((*patches)[k].nodes.size()) : masters[k].nodes());
  }
  out.lagrangeOffset = n;
  n += nm;
  out.residual.setZero(n);
  out.tangent.setZero(n, n);
  out.points.clear();

  // The coefficient of the multiplier block -(lambda / c) dlambda, and of the
  // augmentation rho g dg (none with penalisation).
  const double c = penalised ? options.penalty : options.rho;
  const double rho = penalised ? 0.0 : options.rho;
  const int lo = out.lagrangeOffset;
  const PointRule rule = slaveRule(slave.type, options);
  for (int i = 0; i < rule.size; ++i) {
    const double xi = rule.xi[i];
    const SegmentShape sh = segmentShape(slave.type, xi);
    // (All three rows: a SEG2's third shape derivative is 0.)
    const Eigen::Vector2d dX = slave.reference.transpose() * sh.dN;
    const double J0 = dX.norm();
    if (!(J0 > 0)) throw Error("CONTINUE contact: degenerate slave cell (zero reference length)");
    const double W = rule.w[i] * J0;
    // Multiplier shape functions (the Linear ones exactly as before: bit-for-bit).
    Eigen::Vector3d L;
    double lambda;
    if (nm == 3) {
      L = segmentShape(fem::CellType::SEG3, xi).N;
      lambda = L.dot(slave.lagsC);
    } else {
      L << 0.5 * (1 - xi), 0.5 * (1 + xi), 0;
      lambda = L.head<2>().dot(slave.lagsC.head<2>());
    }

    ContactPointState st;
    st.xi = xi;
    st.weight = W;
    st.point = slave.current.topRows(ns).transpose() * sh.N.head(ns);
    st.pressure = lambda;

    const MasterProjection mp = projectOnMaster(st.point, masters, options.projection);
    NodeGap ng;
    SmoothedGap sg;
    VertexBlendGap vb;
    Projection partnerProjection;
    int partner = -1;         // a second segment at a kink (vertex_blend.hpp)
    int first = mp.segment;   // the segment whose nodes come first in the gap's variables
    // A point held at a vertex while both its segments still take its projection.
    const bool held = i < static_cast<int>(slave.held.size()) && slave.held[i][0] >= 0 &&
                      mp.paired() &&
                      projectOnSegment(st.point, masters[slave.held[i][0]], options.projection).status !=
                          ProjectionStatus::Outside &&
                      projectOnSegment(st.point, masters[slave.held[i][1]], options.projection).status !=
                          ProjectionStatus::Outside;
    if (held) {
      first = slave.held[i][0];
      partner = slave.held[i][1];
      vb = heldVertexGap(st.point, masters[first], masters[partner]);
      st.gap = vb.gap;
      st.masterSegment = mp.segment;
      st.masterXi = mp.projection.xi;
    } else if (mp.paired()) {
      if (patches) {
        sg = linearizeSmoothedGap(st.point, masters[mp.segment], (*patches)[mp.segment], mp.projection);
        st.gap = sg.gap;
      } else {
        ng = linearizeGap(st.point, masters[mp.segment], mp.projection);
        st.gap = ng.gap;
        partner = vertexPartner(st.point, masters, mp.segment, mp.projection, options.projection, partnerProjection);
        if (partner >= 0) {
          vb = blendVertexGaps(ng, linearizeGap(st.point, masters[partner], partnerProjection));
          st.gap = vb.gap;
        }
      }
      st.masterSegment = mp.segment;
      st.masterXi = mp.projection.xi;
    }
    // The criterion takes a gap within round-off as closed (gap.hpp).
    const double gc = mp.paired() && st.gap > 0 && gapIsClosed(st.gap, st.point, masters[mp.segment]) ? 0.0 : st.gap;
    st.augmented = penalised ? c * gc : lambda + rho * gc;
    st.status = !mp.paired() ? PointStatus::Unpaired
                             : (st.augmented <= 0 ? PointStatus::Contact : PointStatus::Separated);
    if (mp.paired() && options.forcedStatus != ForcedStatus::None)
      st.status = options.forcedStatus == ForcedStatus::Contact ? PointStatus::Contact : PointStatus::Separated;
    out.points.push_back(st);

    if (st.status != PointStatus::Contact) {
      // -(lambda/c) dlambda
      for (int v = 0; v < nm; ++v) {
        out.residual(lo + v) -= W * lambda / c * L(v);
        for (int w = 0; w < nm; ++w) out.tangent(lo + v, lo + w) -= W / c * L(v) * L(w);
      }
      continue;
    }
    // Map of the gap's DOFs q = (x_s, master or patch nodes) to cell DOFs: x_s = sum Ns_a x_a.
    // (At a kink, q = (x_s, the segment's nodes, its partner's nodes).)
    const bool blended = partner >= 0;
    const int nq = static_cast<int>(blended ? vb.gradient.size() : patches ? sg.gradient.size() : ng.gradient.size());
    // The force direction f: the gap's variation, or along the smoothed normal (smoothed_normal.hpp).
    auto dg = [&](int p) { return blended ? vb.gradient(p) : patches ? sg.gradient(p) : ng.gradient(p); };
    auto f = [&](int p) { return blended ? vb.gradient(p) : patches ? sg.force(p) : ng.gradient(p); };
    auto df = [&](int p, int r) {
      return blended ? vb.hessian(p, r) : patches ? sg.forceJacobian(p, r) : ng.hessian(p, r);
    };
    const int mo = out.masterOffsets[first];
    const int own = 2 * masters[first].nodes();  // the segment's entries of q after x_s
    auto scatter = [&](int p, auto&& f) {
      if (p < 2) {
        for (int a = 0; a < ns; ++a) f(2 * a + p, sh.N(a));
      } else if (!blended || p < 2 + own) {
        f(mo + p - 2, 1.0);
      } else {
        f(out.masterOffsets[partner] + p - 2 - own, 1.0);
      }
    };
    // The force factor of dg: lambda + rho g (augmented Lagrangian), lambda (penalisation).
    const double g = st.gap, aug = penalised ? lambda : lambda + rho * g;
    for (int p = 0; p < nq; ++p) {
      scatter(p, [&](int I, double wI) {
        out.residual(I) += W * aug * wI * f(p);
        for (int v = 0; v < nm; ++v) {
          out.tangent(I, lo + v) += W * wI * L(v) * f(p);
          out.tangent(lo + v, I) += W * wI * L(v) * dg(p);
        }
        for (int r = 0; r < nq; ++r) {
          const double k = W * (aug * df(p, r) + rho * f(p) * dg(r));
          scatter(r, [&](int Jd, double wJ) { out.tangent(I, Jd) += wI * wJ * k; });
        }
      });
    }
    for (int v = 0; v < nm; ++v) out.residual(lo + v) += W * g * L(v);
    if (penalised)
      for (int v = 0; v < nm; ++v) {
        out.residual(lo + v) -= W * lambda / c * L(v);
        for (int w = 0; w < nm; ++w) out.tangent(lo + v, lo + w) -= W / c * L(v) * L(w);
      }
  }
}

}  // namespace aster::contact
