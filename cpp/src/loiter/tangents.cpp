#include "loiter/tangents.hpp"

#include <algorithm>

#include "vistrack/error.hpp"

namespace vistrack::detail {

std::array<Vec2, 2> tangent_points(const Vec2& p, const Vec2& c, double radius) {
  const Vec2 w = p - c;                 // (2)
  const double squared = w.squaredNorm();  // (3): D, a squared distance
  const double r2 = radius * radius;
  if (!(squared >= r2 * (1.0 - 1e-12)))
    fail_field("point", detail::to_text(p.x()) + ", " + detail::to_text(p.y()),
               "lies inside the circle it should touch (distance " + detail::computed_text(std::sqrt(squared)) +
                   " < radius " + detail::to_text(radius) + ")");
  const Vec2 q = c + (r2 / squared) * w;                                            // (5)
  const Vec2 jw(w.y(), -w.x());                                                    // J = [0 1; -1 0]
  const Vec2 t = (radius / squared) * std::sqrt(std::max(0.0, squared - r2)) * jw;  // (6), R for r
  return {q - t, q + t};                                                            // (7): T_L, T_R
}

Vec2 entry_tangent_point(const Vec2& p, const Vec2& c, double radius, Circulation d) {
  const auto points = tangent_points(p, c, radius);
  // Counter-clockwise travel has the velocity to the left of the radius: cross(radius, v) > 0.
  const double s0 = cross(points[0] - c, points[0] - p);
  return (s0 > 0.0) == (d == Circulation::CounterClockwise) ? points[0] : points[1];
}

Vec2 exit_tangent_point(const Vec2& c, double radius, Circulation d, const Vec2& q) {
  const auto points = tangent_points(q, c, radius);
  const double s0 = cross(points[0] - c, q - points[0]);
  return (s0 > 0.0) == (d == Circulation::CounterClockwise) ? points[0] : points[1];
}

InnerTangent inner_tangent(const Vec2& c1, const Vec2& c2, double radius, Circulation d1) {
  const Vec2 between = c2 - c1;
  const double distance = between.norm();
  if (!(distance >= 2.0 * radius * (1.0 - 1e-12)))
    fail_field("distance between loiter centres", distance,
               "inner tangents need at least 2 R = " + detail::computed_text(2.0 * radius));
  const double zeta = std::acos(std::min(1.0, radius / (0.5 * distance)));  // (9)
  const double axis = heading_of(between);                                  // (8), with atan2
  const Vec2 middle = 0.5 * (c1 + c2);
  InnerTangent best{};
  for (const double side : {+1.0, -1.0}) {
    const Vec2 departure = c1 + radius * unit_at(axis + side * zeta);  // (11)
    // Counter-clockwise departure: the line to M leaves to the left of the radius.
    const bool ccw = cross(departure - c1, middle - departure) > 0.0;
    best = {departure, 2.0 * middle - departure};  // (12): the mirror image through M
    if (ccw == (d1 == Circulation::CounterClockwise)) break;
  }
  return best;
}

double sweep_between(const Vec2& c, const Vec2& a, const Vec2& b, Circulation d) {
  const double from = heading_of(a - c), to = heading_of(b - c);
  double sweep = wrap_to_two_pi(static_cast<double>(sign(d)) * (to - from));
  if (sweep > kTwoPi - 1e-9) sweep = 0.0;
  return sweep;
}

}  // namespace vistrack::detail
