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
#include <cstdint>
#include <limits>

#include "dubins/fast_math.hpp"
#include "vistrack/dubins.hpp"

namespace vistrack::detail {

// x mod 2 pi in [0, 2 pi), with values within `snap` of 2 pi taken as 0.
inline double mod2pi_snap(double x, double snap) {
  double r = x - kTwoPi * std::floor(x / kTwoPi);
  return (r >= kTwoPi - snap || r < 0.0) ? 0.0 : r;
}

// The relative heading psi1 - psi0 reduced and snapped; branch-free when in range.
// Headings within snap of each other modulo 2 pi (either side) are equal.
VISTRACK_DUBINS_INLINE double relative_heading_poly(double difference, double snap) {
  const double r = mod_two_pi_poly(difference);
  return (r >= kTwoPi - snap) | (r < snap) ? 0.0 : r;
}

struct DubinsFrame {
  double u = 0.0, v = 0.0;    // goal position in the start frame / rho
  double phi = 0.0;           // relative heading mod 2 pi, snapped
  double c = 1.0, s = 0.0;    // cos phi, sin phi
  double snap = 0.0;          // snapping tolerance: rad for arcs, units of rho for lengths
};

// The frame without range checks: |q0.psi| and |q1.psi - q0.psi| below kFastTrigLimit.
// Straight-line code, mirrored lane by lane in dubins_batch_avx2.cpp (keep the two in step:
// DubinsBatch.BitIdenticalToScalarKernel checks it).
VISTRACK_DUBINS_INLINE DubinsFrame make_frame_poly(const Configuration& q0, const Configuration& q1, double rho) {
  DubinsFrame f;
  const double inv = 1.0 / rho;
  const double dx = (q1.x - q0.x) * inv;
  const double dy = (q1.y - q0.y) * inv;
  const SinCos h0 = sincos_poly(q0.psi);
  f.u = h0.c * dx + h0.s * dy;
  f.v = -h0.s * dx + h0.c * dy;
  const double magnitude =
      std::max(std::max(std::fabs(q0.x), std::fabs(q0.y)), std::max(std::fabs(q1.x), std::fabs(q1.y)));
  f.snap = kDubinsSnap * (1.0 + magnitude * inv);
  f.phi = relative_heading_poly(q1.psi - q0.psi, f.snap);
  const SinCos hp = sincos_poly(f.phi);
  f.c = hp.c;
  f.s = hp.s;
  return f;
}

inline bool frame_in_poly_range(const Configuration& q0, const Configuration& q1) {
  return std::fabs(q0.psi) < kFastTrigLimit && std::fabs(q1.psi - q0.psi) < kFastTrigLimit;
}

inline DubinsFrame make_frame(const Configuration& q0, const Configuration& q1, double rho) {
  if (frame_in_poly_range(q0, q1)) return make_frame_poly(q0, q1, rho);
  // Huge headings: libm's exact argument reduction.
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
  f.phi = f.phi < f.snap ? 0.0 : f.phi;
  const SinCos hp = fast_sincos(f.phi);
  f.c = hp.c;
  f.s = hp.s;
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
// theta = angle(w) +/- atan2(2, p) = angle(w * (p +/- 2i)): one atan2 of the rotated vector.
inline WordSegments word_lsr(const DubinsFrame& f) {
  const double wx = f.u + f.s, wy = f.v - f.c - 1.0;
  const double tmp = wx * wx + wy * wy - 4.0;
  WordSegments r;
  if (tmp < -4.0 * f.snap) return r;  // (D - 2)(D + 2): overlap below snap is tangency
  r.ok = true;
  r.p = std::sqrt(std::max(tmp, 0.0));
  const double theta = std::atan2(wy * r.p + 2.0 * wx, wx * r.p - 2.0 * wy);
  r.t = mod2pi_snap(theta, f.snap);
  r.q = mod2pi_snap(theta - f.phi, f.snap);
  return r;
}

inline WordSegments word_rsl(const DubinsFrame& f) {
  const double wx = f.u - f.s, wy = f.v + f.c + 1.0;
  const double tmp = wx * wx + wy * wy - 4.0;
  WordSegments r;
  if (tmp < -4.0 * f.snap) return r;
  r.ok = true;
  r.p = std::sqrt(std::max(tmp, 0.0));
  const double theta = std::atan2(wy * r.p - 2.0 * wx, wx * r.p + 2.0 * wy);
  r.t = mod2pi_snap(-theta, f.snap);
  r.q = mod2pi_snap(f.phi - theta, f.snap);
  return r;
}

// acos on [0, 1] as atan2(sqrt((1 - x)(1 + x)), x): accurate near 1 as well.
inline double fast_acos(double x) { return fast_atan2(std::sqrt((1.0 - x) * (1.0 + x)), x); }

// CCC: centres of the outer circles at distance D <= 4, the middle circle at distance 2 from
// both; kappa = acos(D / 4) is the base angle of that isosceles triangle. The middle arc of
// the candidate kept is pi + 2 kappa >= pi (the other one, pi - 2 kappa, is never shortest).
inline WordSegments word_lrl(const DubinsFrame& f) {
  const double wx = f.u - f.s, wy = f.v + f.c - 1.0;
  const double quarter = 0.25 * std::sqrt(wx * wx + wy * wy);
  WordSegments r;
  if (quarter > 1.0 + 1e-12) return r;
  r.ok = true;
  const double kappa = fast_acos(std::min(quarter, 1.0));
  const double theta = fast_atan2(wy, wx);
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
  const double kappa = fast_acos(std::min(quarter, 1.0));
  const double theta = fast_atan2(wy, wx);
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

// ---- length-only kernel (the batch and the word choice of dubins_shortest_path) -------------

// x in (-4 pi, 4 pi) reduced to [0, 2 pi) without floor; within snap of 2 pi -> 0.
VISTRACK_DUBINS_INLINE double wrap_small(double x, double snap) {
  x = x < 0.0 ? x + kTwoPi : x;
  x = x < 0.0 ? x + kTwoPi : x;
  x = x >= kTwoPi ? x - kTwoPi : x;
  return x >= kTwoPi - snap ? 0.0 : x;
}

// Whether the direction of w (|w| = p) lies in the counter-clockwise wedge [0, phi] (widened
// by snap rad on both sides); (c, s) = (cos phi, sin phi), phi in [0, 2 pi).
VISTRACK_DUBINS_INLINE bool in_wedge(double wx, double wy, double p, double phi, double c, double s, double snap) {
  const double tol = snap * p;
  const bool narrow = (wy >= -tol) & ((wx * s - wy * c) >= -tol) & ((wx * (1.0 + c) + wy * s) >= 0.0);
  const bool outside_wide = ((c * wy - s * wx) > tol) & (-wy > tol);  // strictly inside (phi, 2 pi)
  return phi <= kPi ? narrow : !outside_wide;
}

// Shortest CSC length (units of rho) and its word code; whether a CCC word may be shorter
// (outer circles within 4 rho). LSL and RSR need no atan2: t + q = phi or phi + 2 pi, decided
// by whether the straight's direction lies in the wedge swept by the arcs. LSR and RSL take
// one atan2 each. Straight-line code; same snapping as the word formulas above; mirrored in
// dubins_batch_avx2.cpp.
struct CscChoice {
  double length;
  double code;       // word index as a double (keeps the batch loop in one type)
  bool needs_ccc;
};

VISTRACK_DUBINS_INLINE CscChoice shortest_csc(const DubinsFrame& f) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  // LSL
  const double lx = f.u - f.s, ly = f.v + f.c - 1.0;
  const double l2 = lx * lx + ly * ly, lp = std::sqrt(l2);
  const bool l_single = (lp <= f.snap) | in_wedge(lx, ly, lp, f.phi, f.c, f.s, f.snap);
  const double lsl = lp + f.phi + (l_single ? 0.0 : kTwoPi);
  // RSR: the mirror image of LSL, w -> (wx, -wy), phi -> -phi.
  const double rx = f.u + f.s, ry = f.v - f.c + 1.0;
  const double r2 = rx * rx + ry * ry, rp = std::sqrt(r2);
  const double phi_m = wrap_small(-f.phi, f.snap);
  const bool r_single = (rp <= f.snap) | in_wedge(rx, -ry, rp, phi_m, f.c, -f.s, f.snap);
  const double rsr = rp + phi_m + (r_single ? 0.0 : kTwoPi);
  // LSR
  const double ax = f.u + f.s, ay = f.v - f.c - 1.0;
  const double a_tmp = ax * ax + ay * ay - 4.0, ap = std::sqrt(std::max(a_tmp, 0.0));
  const double a_theta = fast_atan2(ay * ap + 2.0 * ax, ax * ap - 2.0 * ay);
  const double lsr = a_tmp < -4.0 * f.snap ? kInf
                                           : ap + wrap_small(a_theta, f.snap) + wrap_small(a_theta - f.phi, f.snap);
  // RSL
  const double bx = f.u - f.s, by = f.v + f.c + 1.0;
  const double b_tmp = bx * bx + by * by - 4.0, bp = std::sqrt(std::max(b_tmp, 0.0));
  const double b_theta = fast_atan2(by * bp - 2.0 * bx, bx * bp + 2.0 * by);
  const double rsl = b_tmp < -4.0 * f.snap ? kInf
                                           : bp + wrap_small(-b_theta, f.snap) + wrap_small(f.phi - b_theta, f.snap);
  double best = lsl, code = 0.0;
  code = lsr < best ? 1.0 : code;
  best = lsr < best ? lsr : best;
  code = rsl < best ? 2.0 : code;
  best = rsl < best ? rsl : best;
  code = rsr < best ? 3.0 : code;
  best = rsr < best ? rsr : best;
  constexpr double kCccLimit = 16.0 * (1.0 + 1e-12) * (1.0 + 1e-12);
  return {best, code, (r2 <= kCccLimit) || (l2 <= kCccLimit)};
}

// Completes a CSC choice with the CCC words (evaluated only when their circles are close).
inline double finish_with_ccc(const DubinsFrame& f, double best, std::uint8_t& word) {
  const WordSegments rlr_w = word_rlr(f);
  const double rlr = rlr_w.ok ? rlr_w.total() : std::numeric_limits<double>::infinity();
  if (rlr < best) {
    best = rlr;
    word = 4;
  }
  const WordSegments lrl_w = word_lrl(f);
  const double lrl = lrl_w.ok ? lrl_w.total() : std::numeric_limits<double>::infinity();
  if (lrl < best) {
    best = lrl;
    word = 5;
  }
  return best;
}

// Shortest length over the six words (units of rho) and its word.
inline double shortest_length_normalised(const DubinsFrame& f, std::uint8_t& word) {
  const CscChoice csc = shortest_csc(f);
  word = static_cast<std::uint8_t>(csc.code);
  return csc.needs_ccc ? finish_with_ccc(f, csc.length, word) : csc.length;
}

}  // namespace vistrack::detail
