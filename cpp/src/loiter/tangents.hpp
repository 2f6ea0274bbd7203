// Tangent constructions of the loiter planners (private to src/loiter and the tests).
#pragma once

#include <array>
#include <cmath>

#include "vistrack/geometry.hpp"

namespace vistrack::detail {

inline Vec2 unit_at(double angle) { return {std::cos(angle), std::sin(angle)}; }
inline Vec2 left_of(const Vec2& u) { return {-u.y(), u.x()}; }
inline Vec2 right_of(const Vec2& u) { return {u.y(), -u.x()}; }
inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }
inline double heading_of(const Vec2& v) { return std::atan2(v.y(), v.x()); }
inline Circulation opposite(Circulation d) {
  return d == Circulation::Clockwise ? Circulation::CounterClockwise : Circulation::Clockwise;
}
// Direction of travel at point p on a circle about c: the radius turned +90 deg (ccw) or -90 deg.
inline Vec2 tangent_direction(const Vec2& c, const Vec2& p, Circulation d) {
  const Vec2 radial = (p - c).normalized();
  return d == Circulation::CounterClockwise ? left_of(radial) : right_of(radial);
}

// The two points where lines from p touch the circle (c, R), eqs. (2)-(7):
//   w = p - c, D = w.w, Q = c + (R^2 / D) w, T = (R / D) sqrt(D - R^2) J w, points Q -/+ T.
// Two slips of the print are fixed here: (3) calls D "the distance" but it is the squared
// distance (the dot product), which is what (5) and (6) need; and (6) prints sqrt(D - r^2) with
// the turn radius r where the tangency to the AOI circle needs its radius R (the two agree only
// when R = r, as in the paper's runs). Requires |p - c| >= R (both points are p when equal).
std::array<Vec2, 2> tangent_points(const Vec2& p, const Vec2& c, double radius);

// The tangent point for arriving from p on a straight line and going on around the circle in
// direction d (the travel direction matches d there).
Vec2 entry_tangent_point(const Vec2& p, const Vec2& c, double radius, Circulation d);
// The tangent point for leaving the circle, travelling in direction d, on a straight line through q.
Vec2 exit_tangent_point(const Vec2& c, double radius, Circulation d, const Vec2& q);

// Inner (crossing) tangent between two circles of equal radius R, eqs. (8)-(12): departure from
// circle 1 travelling d1, entry onto circle 2 travelling the opposite way. The tangent crosses the
// centre line at its midpoint M; the departure point is at angle +-zeta from the direction c1 -> c2
// about c1, cos zeta = R / (d/2) (9), and the entry point is its mirror image through M.
// Derived with vectors and atan2: (8) takes theta = atan(|dy| / |dx|), which loses the quadrant,
// and (11)-(12) fix the signs for one arrangement of the two POIs (P2 up and to the right of P1);
// tests show the printed form off the circle's tangent elsewhere. Needs |c2 - c1| >= 2R.
struct InnerTangent {
  Vec2 departure;
  Vec2 entry;
};
InnerTangent inner_tangent(const Vec2& c1, const Vec2& c2, double radius, Circulation d1);

// Angle in [0, 2 pi) swept travelling from a to b on a circle about c in direction d. A sweep
// within 1e-9 rad of 2 pi is taken as 0 (the same point up to rounding).
double sweep_between(const Vec2& c, const Vec2& a, const Vec2& b, Circulation d);

}  // namespace vistrack::detail
