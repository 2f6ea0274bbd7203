// Loiter patterns about the offset point (Fig. 3): the circle and the rose of rotating lines.
#include <algorithm>
#include <cmath>

#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"
#include "vistrack/follow.hpp"

namespace vistrack {

namespace {

Vec2 rotate(const Vec2& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

}  // namespace

void LoiterShape::validate() const {
  require_length(radius, "loiter_radius");
  if (direction != 1 && direction != -1) detail::fail_field("loiter_direction", direction, "must be +1 or -1");
  require_finite(rotation, "rotation");
  if (pattern == LoiterPattern::Rose) {
    require_length(turn_radius, "turn_radius");
    if (!(radius >= 2.0 * turn_radius))
      detail::fail_field("loiter_radius", radius,
                         "a rose needs at least twice its turn radius " + detail::to_text(turn_radius) + " m");
  }
}

double LoiterShape::delta() const {
  if (pattern == LoiterPattern::Circle) return 0.0;
  return 2.0 * std::asin(std::min(1.0, turn_radius / (radius - turn_radius)));
}

double LoiterShape::half_line() const {
  if (pattern == LoiterPattern::Circle) return 0.0;
  const double d = delta();
  return turn_radius * std::cos(0.5 * d) / std::sin(0.5 * d);
}

double LoiterShape::piece_length() const {
  if (pattern == LoiterPattern::Circle) return kTwoPi * radius;
  return 2.0 * half_line() + turn_radius * (kPi + delta());
}

// Piece i of the rose is piece 0 rotated by i (pi + delta) (mirrored for clockwise turns).
// Piece 0: the line from (-l, 0) to (l, 0), then the turn about (l, rho) from angle -pi/2
// through pi + delta, ending at l (cos delta, sin delta) heading pi + delta.
Vec2 LoiterShape::position(double s) const {
  if (pattern == LoiterPattern::Circle) {
    const double angle = rotation + direction * s / radius;
    return radius * Vec2(std::cos(angle), std::sin(angle));
  }
  const double length = piece_length();
  const double piece = std::floor(s / length);
  const double u = s - piece * length;
  const double l = half_line();
  Vec2 local;
  if (u <= 2.0 * l) {
    local = Vec2(-l + u, 0.0);
  } else {
    const double theta = (u - 2.0 * l) / turn_radius;
    local = Vec2(l + turn_radius * std::sin(theta), turn_radius - turn_radius * std::cos(theta));
  }
  local.y() *= direction;
  return rotate(local, rotation + direction * piece * (kPi + delta()));
}

Vec2 LoiterShape::tangent(double s) const {
  if (pattern == LoiterPattern::Circle) {
    const double angle = rotation + direction * s / radius;
    return direction * Vec2(-std::sin(angle), std::cos(angle));
  }
  const double length = piece_length();
  const double piece = std::floor(s / length);
  const double u = s - piece * length;
  const double l = half_line();
  Vec2 local(1.0, 0.0);
  if (u > 2.0 * l) {
    const double theta = (u - 2.0 * l) / turn_radius;
    local = Vec2(std::cos(theta), std::sin(theta));
  }
  local.y() *= direction;
  return rotate(local, rotation + direction * piece * (kPi + delta()));
}

}  // namespace vistrack
