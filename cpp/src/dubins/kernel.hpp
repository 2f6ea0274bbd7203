// The Dubins word formulas in the start frame, lengths in units of rho. Shared by the path
// solver, the batch kernel and the circle/intercept code; internal (vistrack::detail).
//
// Frame: start at the origin heading +x; goal at (u, v) with heading phi. Turning-circle
// centres: start left (0, 1), start right (0, -1), goal left (u - sin phi, v + cos phi), goal
// right (u + sin phi, v - cos phi). Each word follows from the vector w between its two
// circles (tangent lines for CSC, the isosceles triangle of centres for CCC).
#pragma once

#include <algorithm>
#include <cmath>

#include "vistrack/dubins.hpp"

namespace vistrack::detail {

// x mod 2 pi in [0, 2 pi), with values within `snap` of 2 pi taken as 0.
inline double mod2pi_snap(double x, double snap) {
  double r = x - kTwoPi * std::floor(x / kTwoPi);
  return (r >= kTwoPi - snap || r < 0.0) ? 0.0 : r;
}

struct DubinsFrame {
  double u = 0.0, v = 0.0;    // goal position in the start frame / rho
  double phi = 0.0;           // relative heading mod 2 pi, snapped
  double c = 1.0, s = 0.0;    // cos phi, sin phi
  double snap = 0.0;          // snapping tolerance: rad for arcs, units of rho for lengths
};

inline DubinsFrame make_frame(const Configuration& q0, const Configuration& q1, double rho) {
  DubinsFrame f;
  const double inv = 1.0 / rho;
  const double dx = (q1.x - q0.x) * inv;
  const double dy = (q1.y - q0.y) * inv;
  const double c0 = std::cos(q0.psi), s0 = std::sin(q0.psi);
  f.u = c0 * dx + s0 * dy;
  f.v = -s0 * dx + c0 * dy;
  const double magnitude =
      std::max(std::max(std::fabs(q0.x), std::fabs(q0.y)), std::max(std::fabs(q1.x), std::fabs(q1.y)));
  f.snap = kDubinsSnap * (1.0 + magnitude * inv);
  f.phi = mod2pi_snap(q1.psi - q0.psi, f.snap);
  f.c = std::cos(f.phi);
  f.s = std::sin(f.phi);
  return f;
}

// Normalised segment parameters: t and q arc angles, p straight length (CSC) or middle arc
// angle (CCC). ok == false when the word does not exist.
struct WordSegments {
  double t = 0.0, p = 0.0, q = 0.0;
  bool ok = false;
  double total() const { return t + p + q; }
};

constexpr double kHalfPi = 0.5 * kPi;

inline WordSegments word_lsl(const DubinsFrame& f) {
  const double wx = f.u - f.s, wy = f.v + f.c - 1.0;
  WordSegments r;
  r.ok = true;
  r.p = std::sqrt(wx * wx + wy * wy);
  if (r.p <= f.snap) {  // goal on the start's left circle: one arc
    r.t = 0.0;
    r.q = f.phi;
  } else {
    const double theta = std::atan2(wy, wx);
    r.t = mod2pi_snap(theta, f.snap);
    r.q = mod2pi_snap(f.phi - theta, f.snap);
  }
  return r;
}

inline WordSegments word_rsr(const DubinsFrame& f) {
  const double wx = f.u + f.s, wy = f.v - f.c + 1.0;
  WordSegments r;
  r.ok = true;
  r.p = std::sqrt(wx * wx + wy * wy);
  if (r.p <= f.snap) {  // goal on the start's right circle
    r.t = 0.0;
    r.q = mod2pi_snap(-f.phi, f.snap);
  } else {
    const double theta = std::atan2(wy, wx);
    r.t = mod2pi_snap(-theta, f.snap);
    r.q = mod2pi_snap(theta - f.phi, f.snap);
  }
  return r;
}

// Inner tangents: w = p e(theta) -/+ 2 e(theta + pi/2) for LSR/RSL, so
// theta = angle(w) +/- atan2(2, p).
inline WordSegments word_lsr(const DubinsFrame& f) {
  const double wx = f.u + f.s, wy = f.v - f.c - 1.0;
  const double tmp = wx * wx + wy * wy - 4.0;
  WordSegments r;
  if (tmp < -4.0 * f.snap) return r;  // (D - 2)(D + 2): overlap below snap is tangency
  r.ok = true;
  r.p = std::sqrt(std::max(tmp, 0.0));
  const double theta = std::atan2(wy, wx) + std::atan2(2.0, r.p);
  r.t = mod2pi_snap(theta, f.snap);
  r.q = mod2pi_snap(theta - f.phi, f.snap);
  return r;
}

inline WordSegments word_rsl(const DubinsFrame& f) {
  const double wx = f.u - f.s, wy = f.v + f.c + 1.0;
  const double tmp = wx * wx + wy * wy - 4.0;
  WordSegments r;
  if (tmp < -4.0 * f.snap) return r;  // (D - 2)(D + 2): overlap below snap is tangency
  r.ok = true;
  r.p = std::sqrt(std::max(tmp, 0.0));
  const double theta = std::atan2(wy, wx) - std::atan2(2.0, r.p);
  r.t = mod2pi_snap(-theta, f.snap);
  r.q = mod2pi_snap(f.phi - theta, f.snap);
  return r;
}

// CCC: centres of the outer circles at distance D <= 4, the middle circle at distance 2 from
// both; kappa = acos(D / 4) is the base angle of that isosceles triangle. The middle arc of
// the candidate kept is pi + 2 kappa >= pi (the other one, pi - 2 kappa, is never shortest).
inline WordSegments word_lrl(const DubinsFrame& f) {
  const double wx = f.u - f.s, wy = f.v + f.c - 1.0;
  const double quarter = 0.25 * std::sqrt(wx * wx + wy * wy);
  WordSegments r;
  if (quarter > 1.0 + 1e-12) return r;
  r.ok = true;
  const double kappa = std::acos(std::min(quarter, 1.0));
  const double theta = std::atan2(wy, wx);
  r.t = mod2pi_snap(theta + kappa + kHalfPi, f.snap);
  r.p = kPi + 2.0 * kappa;
  r.q = mod2pi_snap(f.phi - theta + kappa + kHalfPi, f.snap);
  return r;
}

inline WordSegments word_rlr(const DubinsFrame& f) {
  const double wx = f.u + f.s, wy = f.v - f.c + 1.0;
  const double quarter = 0.25 * std::sqrt(wx * wx + wy * wy);
  WordSegments r;
  if (quarter > 1.0 + 1e-12) return r;
  r.ok = true;
  const double kappa = std::acos(std::min(quarter, 1.0));
  const double theta = std::atan2(wy, wx);
  r.t = mod2pi_snap(-theta + kappa + kHalfPi, f.snap);
  r.p = kPi + 2.0 * kappa;
  r.q = mod2pi_snap(-f.phi + theta + kappa + kHalfPi, f.snap);
  return r;
}

inline WordSegments word_segments(const DubinsFrame& f, DubinsWord word) {
  switch (word) {
    case DubinsWord::LSL: return word_lsl(f);
    case DubinsWord::LSR: return word_lsr(f);
    case DubinsWord::RSL: return word_rsl(f);
    case DubinsWord::RSR: return word_rsr(f);
    case DubinsWord::RLR: return word_rlr(f);
    case DubinsWord::LRL: return word_lrl(f);
  }
  return {};
}

}  // namespace vistrack::detail
