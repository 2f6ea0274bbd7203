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

// Trivially constructible on purpose (the solver keeps arrays of them): create with {}.
struct HorizonEval {
  bool ok;
  double t, p, q;  // first arc, first straight, arc T_n -> W_n (angles / lengths in R)
  double a, s2;    // arc W_n -> exit, last straight
  double value;    // F / R (infinity when !ok)
  double slope;    // dF/dh / R
};

// The kernel's CSC word formulas (word_lsl, word_lsr, word_rsl, word_rsr in dubins/kernel.hpp),
// with its polynomial atan2 and wrap_small instead of std::atan2 and floor: this runs ~100 times
// per turning point. Same snapping; tests check it against the kernel. Also the direction of the
// straight in the start frame, (cos, sin) of chi - psi, which the slope needs.
struct CscWord {
  WordSegments w;
  double c_chi = 1.0, s_chi = 0.0;
};

VISTRACK_DUBINS_INLINE CscWord csc_word(const DubinsFrame& f, int d1, int d2) {
  CscWord out;
  WordSegments& r = out.w;
  if (d1 == d2) {
    // LSL, or RSR as its mirror image (v -> -v, phi -> -phi); the straight runs along w.
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
      out.c_chi = wx / r.p;
      out.s_chi = wy / r.p;
    }
    return out;
  }
  // Inner tangents: the straight along w rotated by atan2(2, p) (LSR) or -atan2(2, p) (RSL);
  // |w|^2 = p^2 + 4.
  const double wx = d1 > 0 ? f.u + f.s : f.u - f.s;
  const double wy = d1 > 0 ? f.v - f.c - 1.0 : f.v + f.c + 1.0;
  const double tmp = wx * wx + wy * wy - 4.0;
  if (tmp < -4.0 * f.snap) return out;
  r.ok = true;
  r.p = std::sqrt(std::max(tmp, 0.0));
  const double ex = d1 > 0 ? wx * r.p - 2.0 * wy : wx * r.p + 2.0 * wy;
  const double ey = d1 > 0 ? wy * r.p + 2.0 * wx : wy * r.p - 2.0 * wx;
  const double theta = fast_atan2(ey, ex);
  r.t = wrap_small(d1 * theta, f.snap);
  r.q = wrap_small(d1 > 0 ? theta - f.phi : f.phi - theta, f.snap);
  const double norm = r.p * r.p + 4.0;
  out.c_chi = ex / norm;
  out.s_chi = ey / norm;
  return out;
}

// What depends on h alone: the frame of the word, and cos h, sin h.
struct HeadingFrame {
  DubinsFrame f;
  double ch = 1.0, sh = 0.0;
};

VISTRACK_DUBINS_INLINE HeadingFrame heading_frame(const HorizonProblem& P, double h) {
  HeadingFrame hf;
  hf.f.u = P.u;
  hf.f.v = P.v;
  hf.f.snap = P.snap;
  hf.f.phi = wrap_small(h - P.psi, P.snap);
  const SinCos sp = sincos_poly(hf.f.phi);
  hf.f.c = sp.c;
  hf.f.s = sp.s;
  hf.ch = P.cos_psi * sp.c - P.sin_psi * sp.s;  // cos(psi + phi) = cos h
  hf.sh = P.sin_psi * sp.c + P.cos_psi * sp.s;
  return hf;
}

// From (W_n, h): the arc d2 then the tangent to W_{n+1}, in h's frame mirrored to a left turn.
struct ExitPart {
  bool ok = false;
  double a = 0.0, s2 = 0.0, ca = 1.0, sa = 0.0;  // arc angle, straight, cos a, sin a
};

VISTRACK_DUBINS_INLINE ExitPart exit_part(const HorizonProblem& P, const HeadingFrame& hf, int d2) {
  ExitPart x;
  const double u2 = hf.ch * P.qx + hf.sh * P.qy;
  const double v2 = d2 * (-hf.sh * P.qx + hf.ch * P.qy);
  const double ux = u2, uy = v2 - 1.0;  // W_{n+1} from the circle's centre (0, 1)
  const double d2sq = ux * ux + uy * uy;
  const double tmp = d2sq - 1.0;
  if (tmp < -2.0 * P.snap) return x;  // W_{n+1} inside the circle: no tangent
  x.ok = true;
  x.s2 = std::sqrt(std::max(tmp, 0.0));
  // Exit heading a: sin(a - beta) = 1 / D2, cos(a - beta) = s2 / D2 (beta the angle of U).
  x.ca = (ux * x.s2 - uy) / d2sq;
  x.sa = (uy * x.s2 + ux) / d2sq;
  x.a = wrap_small(fast_atan2(x.sa, x.ca), P.snap);
  return x;
}

VISTRACK_DUBINS_INLINE HorizonEval combine(const HorizonProblem& P, const HeadingFrame& hf, const CscWord& cw,
                                           const ExitPart& x, int d1, int d2) {
  HorizonEval e{};
  if (!cw.w.ok || !x.ok) {
    e.value = std::numeric_limits<double>::infinity();
    return e;
  }
  e.ok = true;
  e.t = cw.w.t;
  e.p = cw.w.p;
  e.q = cw.w.q;
  e.a = x.a;
  e.s2 = x.s2;
  e.value = P.wa * (e.t + e.q + e.a) + P.ws * (e.p + e.s2);
  // q is d2 (h - chi) mod 2 pi: its cos and sin from the straight's direction, no trig.
  const double cos_q = hf.f.c * cw.c_chi + hf.f.s * cw.s_chi;
  const double sin_q = d2 * (hf.f.s * cw.c_chi - hf.f.c * cw.s_chi);
  double slope = P.ws * d2 * (x.ca - cos_q);
  if (P.wa != P.ws) {
    double arcs = 0.0;
    if (d1 != d2) arcs -= (d1 - d2) * sin_q / e.p;
    arcs -= d2 * x.sa / e.s2;
    slope += (P.wa - P.ws) * arcs;
  }
  e.slope = slope;
  return e;
}

inline HorizonEval evaluate_horizon(const HorizonProblem& P, int d1, int d2, double h) {
  const HeadingFrame hf = heading_frame(P, h);
  const CscWord cw = csc_word(hf.f, d1, d2);
  if (!cw.w.ok) {
    HorizonEval e{};
    e.value = std::numeric_limits<double>::infinity();
    return e;
  }
  return combine(P, hf, cw, exit_part(P, hf, d2), d1, d2);
}

// dF/dh alone (no arc angles, so no atan2): what Brent needs while it looks for a root of it.
// NaN where the path does not exist.
inline double horizon_slope(const HorizonProblem& P, int d1, int d2, double h) {
  const HeadingFrame hf = heading_frame(P, h);
  const DubinsFrame& f = hf.f;
  double p, c_chi, s_chi;
  if (d1 == d2) {
    const double wx = d1 > 0 ? f.u - f.s : f.u + f.s;
    const double wy = d1 > 0 ? f.v + f.c - 1.0 : f.v - f.c + 1.0;
    p = std::sqrt(wx * wx + wy * wy);
    c_chi = p <= f.snap ? 1.0 : wx / p;
    s_chi = p <= f.snap ? 0.0 : wy / p;
  } else {
    const double wx = d1 > 0 ? f.u + f.s : f.u - f.s;
    const double wy = d1 > 0 ? f.v - f.c - 1.0 : f.v + f.c + 1.0;
    const double tmp = wx * wx + wy * wy - 4.0;
    if (tmp < -4.0 * f.snap) return std::numeric_limits<double>::quiet_NaN();
    p = std::sqrt(std::max(tmp, 0.0));
    const double norm = p * p + 4.0;
    c_chi = (d1 > 0 ? wx * p - 2.0 * wy : wx * p + 2.0 * wy) / norm;
    s_chi = (d1 > 0 ? wy * p + 2.0 * wx : wy * p - 2.0 * wx) / norm;
  }
  const double u2 = hf.ch * P.qx + hf.sh * P.qy;
  const double v2 = d2 * (-hf.sh * P.qx + hf.ch * P.qy);
  const double ux = u2, uy = v2 - 1.0;
  const double d2sq = ux * ux + uy * uy;
  if (d2sq - 1.0 < -2.0 * P.snap) return std::numeric_limits<double>::quiet_NaN();
  const double s2 = std::sqrt(std::max(d2sq - 1.0, 0.0));
  const double ca = (ux * s2 - uy) / d2sq, sa = (uy * s2 + ux) / d2sq;
  const double cos_q = f.c * c_chi + f.s * s_chi;
  double slope = P.ws * d2 * (ca - cos_q);
  if (P.wa != P.ws) {
    const double sin_q = d2 * (f.s * c_chi - f.c * s_chi);
    double arcs = 0.0;
    if (d1 != d2) arcs -= (d1 - d2) * sin_q / p;
    arcs -= d2 * sa / s2;
    slope += (P.wa - P.ws) * arcs;
  }
  return slope;
}

// The four cases at one h, in TurnCase order, sharing the frame and the two exit parts.
inline void evaluate_horizon_cases(const HorizonProblem& P, double h, HorizonEval* out) {
  const HeadingFrame hf = heading_frame(P, h);
  const ExitPart left = exit_part(P, hf, +1), right = exit_part(P, hf, -1);
  out[0] = combine(P, hf, csc_word(hf.f, +1, +1), left, +1, +1);
  out[1] = combine(P, hf, csc_word(hf.f, +1, -1), right, +1, -1);
  out[2] = combine(P, hf, csc_word(hf.f, -1, +1), left, -1, +1);
  out[3] = combine(P, hf, csc_word(hf.f, -1, -1), right, -1, -1);
}

}  // namespace vistrack::detail
