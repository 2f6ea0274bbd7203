// The DWN horizon path as a function of the heading h at W_n, in units of R with W_n at the
// origin: F(h), dF/dh and the pieces, for one case (d1, d2). Internal to waypoint_nav.
#pragma once

#include <cmath>

#include "dubins/kernel.hpp"
#include "vistrack/waypoint_nav.hpp"

namespace vistrack::detail {

inline int first_direction(TurnCase c) { return (c == TurnCase::CcwCcw || c == TurnCase::CcwCw) ? +1 : -1; }
inline int second_direction(TurnCase c) { return (c == TurnCase::CcwCcw || c == TurnCase::CwCcw) ? +1 : -1; }
// theta (centre of the circle about W_n) from the heading h at W_n: h = theta - d2 pi/2.
inline double theta_of_heading(double h, int d2) { return wrap_to_two_pi(h + d2 * kHalfPi); }
inline double heading_of_theta(double theta, int d2) { return theta - d2 * kHalfPi; }

// One solve's fixed data, normalised by R.
struct HorizonProblem {
  double u = 0.0, v = 0.0;     // W_n in the frame of C (origin C, x along C's heading) / R
  double psi = 0.0;            // C's heading
  double cos_psi = 1.0, sin_psi = 0.0;
  double qx = 0.0, qy = 0.0;   // (W_{n+1} - W_n) / R, world axes
  double snap = 0.0;           // the Dubins kernel's snapping tolerance for this geometry
  double wa = 1.0, ws = 1.0;
  Vec2 c = Vec2::Zero();       // C - W_n, / R

  HorizonProblem(const Configuration& pose, const Vec2& w_next, const Vec2& w_after, double R,
                 const FuelWeights& weights) {
    const double inv = 1.0 / R;
    c = Vec2(pose.x - w_next.x(), pose.y - w_next.y()) * inv;
    psi = wrap_to_two_pi(pose.psi);  // h - psi stays in (-2 pi, 4 pi): wrap_small applies
    cos_psi = std::cos(psi);
    sin_psi = std::sin(psi);
    u = -(cos_psi * c.x() + sin_psi * c.y());
    v = -(-sin_psi * c.x() + cos_psi * c.y());
    qx = (w_after.x() - w_next.x()) * inv;
    qy = (w_after.y() - w_next.y()) * inv;
    const double magnitude = std::max({std::abs(c.x()), std::abs(c.y()), std::abs(qx), std::abs(qy)});
    snap = kDubinsSnap * (1.0 + magnitude);
    wa = weights.arc;
    ws = weights.straight;
  }
};

struct HorizonEval {
  bool ok = false;
  double t = 0.0, p = 0.0, q = 0.0;  // first arc, first straight, arc T_n -> W_n (angles / lengths in R)
  double a = 0.0, s2 = 0.0;          // arc W_n -> exit, last straight
  double value = 0.0;                // F / R (infinity when !ok)
  double slope = 0.0;                // dF/dh / R
};

// The kernel's CSC word formulas (word_lsl, word_lsr, word_rsl, word_rsr in dubins/kernel.hpp),
// with its polynomial atan2 and wrap_small instead of std::atan2 and floor: this runs ~100 times
// per turning point. Same snapping; tests check it against the kernel.
VISTRACK_DUBINS_INLINE WordSegments csc_word(const DubinsFrame& f, int d1, int d2) {
  WordSegments r;
  if (d1 == d2) {
    // LSL, or RSR as its mirror image (v -> -v, phi -> -phi).
    const double wx = d1 > 0 ? f.u - f.s : f.u + f.s;
    const double wy = d1 > 0 ? f.v + f.c - 1.0 : f.v - f.c + 1.0;
    r.ok = true;
    r.p = std::sqrt(wx * wx + wy * wy);
    const double phi = d1 > 0 ? f.phi : wrap_small(-f.phi, f.snap);
    if (r.p <= f.snap) {  // the goal on the start's circle: one arc
      r.t = 0.0;
      r.q = phi;
    } else {
      const double theta = fast_atan2(d1 * wy, wx);
      r.t = wrap_small(theta, f.snap);
      r.q = wrap_small(phi - theta, f.snap);
    }
    return r;
  }
  if (d1 > 0) {  // LSR
    const double wx = f.u + f.s, wy = f.v - f.c - 1.0;
    const double tmp = wx * wx + wy * wy - 4.0;
    if (tmp < -4.0 * f.snap) return r;
    r.ok = true;
    r.p = std::sqrt(std::max(tmp, 0.0));
    const double theta = fast_atan2(wy * r.p + 2.0 * wx, wx * r.p - 2.0 * wy);
    r.t = wrap_small(theta, f.snap);
    r.q = wrap_small(theta - f.phi, f.snap);
    return r;
  }
  // RSL
  const double wx = f.u - f.s, wy = f.v + f.c + 1.0;
  const double tmp = wx * wx + wy * wy - 4.0;
  if (tmp < -4.0 * f.snap) return r;
  r.ok = true;
  r.p = std::sqrt(std::max(tmp, 0.0));
  const double theta = fast_atan2(wy * r.p - 2.0 * wx, wx * r.p + 2.0 * wy);
  r.t = wrap_small(-theta, f.snap);
  r.q = wrap_small(f.phi - theta, f.snap);
  return r;
}

inline HorizonEval evaluate_horizon(const HorizonProblem& P, int d1, int d2, double h) {
  HorizonEval e;
  e.value = std::numeric_limits<double>::infinity();
  // Up to W_n: the CSC word (d1, S, d2) from C to (W_n, h), in the Dubins kernel's frame.
  DubinsFrame f;
  f.u = P.u;
  f.v = P.v;
  f.snap = P.snap;
  f.phi = wrap_small(h - P.psi, P.snap);
  const SinCos sp = sincos_poly(f.phi);
  f.c = sp.c;
  f.s = sp.s;
  const WordSegments w = csc_word(f, d1, d2);
  if (!w.ok) return e;
  // From (W_n, h): arc d2 then the tangent to W_{n+1}, in h's frame mirrored to a left turn.
  const double ch = P.cos_psi * sp.c - P.sin_psi * sp.s;  // cos(psi + phi) = cos h
  const double sh = P.sin_psi * sp.c + P.cos_psi * sp.s;
  const double u2 = ch * P.qx + sh * P.qy;
  const double v2 = d2 * (-sh * P.qx + ch * P.qy);
  const double ux = u2, uy = v2 - 1.0;  // W_{n+1} from the circle's centre (0, 1)
  const double d2sq = ux * ux + uy * uy;
  const double tmp = d2sq - 1.0;
  if (tmp < -2.0 * P.snap) return e;  // W_{n+1} inside the circle: no tangent
  e.ok = true;
  e.s2 = std::sqrt(std::max(tmp, 0.0));
  // Exit heading a: sin(a - beta) = 1 / D2, cos(a - beta) = s2 / D2 (beta the angle of U).
  const double ca = (ux * e.s2 - uy) / d2sq, sa = (uy * e.s2 + ux) / d2sq;
  e.a = wrap_small(fast_atan2(sa, ca), P.snap);
  e.t = w.t;
  e.p = w.p;
  e.q = w.q;
  e.value = P.wa * (e.t + e.q + e.a) + P.ws * (e.p + e.s2);
  const SinCos sq = sincos_poly(e.q);
  double slope = P.ws * d2 * (ca - sq.c);
  if (P.wa != P.ws) {
    double arcs = 0.0;
    if (d1 != d2) arcs -= (d1 - d2) * sq.s / e.p;
    arcs -= d2 * sa / e.s2;
    slope += (P.wa - P.ws) * arcs;
  }
  e.slope = slope;
  return e;
}

}  // namespace vistrack::detail
