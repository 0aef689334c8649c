#include "analysis/line_search.hpp"

#include <cmath>
#include <limits>

namespace aster::analysis {

double admissibleRho(const LineSearchSettings& s, double rho) {
  rho = std::min(std::max(rho, s.rhoMin), s.rhoMax);
  if (std::fabs(rho) < s.rhoExcl) rho = rho >= 0 ? s.rhoExcl : -s.rhoExcl;
  return rho;
}

namespace {

// The trial of smallest |f| so far, and the test of convergence on it.
struct Best {
  double rho = 1, absF = std::numeric_limits<double>::infinity(), f = 0;
  bool consider(double rho, double f, double target) {
    if (std::fabs(f) >= absF) return false;
    this->rho = rho;
    this->f = f;
    absF = std::fabs(f);
    return absF < target;
  }
};

LineSearchOutcome corde(const LineSearchSettings& s, double f0, const LineFunctional& func, double target) {
  LineSearchOutcome out;
  Best best;
  double rhoPrev = 0, fPrev = f0, rho = 1;
  for (int i = 0; i <= s.iterLineMaxi; ++i) {
    double f = 0;
    if (!func(rho, f)) {
      out.failedTrial = true;
      break;
    }
    ++out.trials;
    if (best.consider(rho, f, target)) {
      out.converged = true;
      break;
    }
    // The secant through the last two trials; parallel ones: the bound f's slope points to.
    double next;
    if (std::fabs(f - fPrev) > std::numeric_limits<double>::epsilon() * std::max(std::fabs(f), std::fabs(fPrev)))
      next = admissibleRho(s, (f * rhoPrev - fPrev * rho) / (f - fPrev));
    else
      next = f * (rho - rhoPrev) * (f - fPrev) <= 0 ? s.rhoMax : s.rhoMin;
    rhoPrev = rho;
    fPrev = f;
    rho = next;
  }
  out.rho = best.rho;
  out.f = best.f;
  return out;
}

// Along the sense s (the one where f starts negative), x = rho / s > 0 and g(x) = s f(s x).
LineSearchOutcome mixte(const LineSearchSettings& s, double f0, const LineFunctional& func, double target) {
  LineSearchOutcome out;
  Best best;
  const double sense = f0 <= 0 ? 1.0 : -1.0;
  double xNeg = 0;                 // the largest x with g < 0
  double xPos = 0;                 // the smallest x with g >= 0, once found
  bool bracketed = false;
  double x0 = 0, g0 = sense * f0;  // the trial before the last
  double x = 1;
  for (int i = 0; i <= s.iterLineMaxi; ++i) {
    const double rho = sense * x;
    double f = 0;
    if (!func(rho, f)) {
      out.failedTrial = true;
      break;
    }
    ++out.trials;
    const double g = sense * f;
    if (g < 0) {
      xNeg = x;
    } else {
      xPos = x;
      bracketed = true;
    }
    if (best.consider(rho, f, target)) {
      out.converged = true;
      break;
    }
    double next;
    if (!bracketed) {
      next = 3 * x;  // no sign change yet: go further
    } else if (std::fabs(g) >= std::fabs(g0) || x == x0) {
      next = 0.5 * (xNeg + xPos);  // the last trial did not help: halve the bracket
    } else {
      next = x - g * (x - x0) / (g - g0);
      if (!(next > xNeg && next < xPos)) next = 0.5 * (xNeg + xPos);
    }
    const double nextRho = admissibleRho(s, sense * next);
    if (nextRho * sense <= 0 || nextRho == rho) break;  // the bounds leave nothing new to try
    x0 = x;
    g0 = g;
    x = nextRho * sense;
  }
  out.rho = best.rho;
  out.f = best.f;
  return out;
}

}  // namespace

LineSearchOutcome lineSearch(const LineSearchSettings& s, double f0, const LineFunctional& f) {
  if (f0 == 0 || !std::isfinite(f0)) return {};  // nothing to search: the full step
  const double target = std::fabs(s.resiLineRela * f0);
  return s.method == LineSearchSettings::Method::Corde ? corde(s, f0, f, target) : mixte(s, f0, f, target);
}

}  // namespace aster::analysis
