// Angles, points and planar polygons shared by every area.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "vistrack/error.hpp"

namespace vistrack {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;

// Row-major (n, 3) arrays: they map onto numpy arrays of shape (n, 3) without reordering.
using Points3 = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
using Points2 = Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor>;
using Faces = Eigen::Matrix<std::int32_t, Eigen::Dynamic, 3, Eigen::RowMajor>;

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;

// Direction of travel around a circle: orbits, loiters, turns, a target on a circle.
enum class Circulation : std::uint8_t { CounterClockwise = 0, Clockwise = 1 };
// +1 counter-clockwise, -1 clockwise: the sign of the turn rate along the circle.
constexpr int sign(Circulation circulation) { return circulation == Circulation::Clockwise ? -1 : +1; }
// "ccw" or "cw", the spelling at the Python boundary and in files.
template <>
struct EnumNames<Circulation> {
  static constexpr const char* field = "direction";
  static constexpr EnumName<Circulation> names[] = {{"ccw", Circulation::CounterClockwise},
      {"cw", Circulation::Clockwise}, {"counterclockwise", Circulation::CounterClockwise},
      {"counter-clockwise", Circulation::CounterClockwise}, {"anticlockwise", Circulation::CounterClockwise},
      {"clockwise", Circulation::Clockwise}};
};

// Angle in (-pi, pi]. Error for a non-finite angle (it has no direction).
double wrap_to_pi(double angle);
// Angle in [0, 2 pi); Error for a non-finite angle.
double wrap_to_two_pi(double angle);
// How far p lies past the finish line of the leg from -> to (the line through `to` perpendicular to
// the leg), along the leg: > 0 past it. 0 for a leg of no length (its end is where it starts).
double past_finish_line(const Vec2& p, const Vec2& from, const Vec2& to);

// A closed ring of points; the last point is not a repeat of the first.
using Ring = std::vector<Vec2>;

// A simple polygon with optional holes. Outer ring counter-clockwise, holes clockwise once
// normalised (see normalize_orientation).
struct Polygon {
  Ring outer;
  std::vector<Ring> holes;
};

struct Bounds2 {
  Vec2 min;
  Vec2 max;
};

struct Bounds3 {
  Vec3 min;
  Vec3 max;
};

// Shoelace signed area: positive for counter-clockwise rings.
double signed_area(const Ring& ring);
// Area of the outer ring minus the holes.
double area(const Polygon& polygon);
// True when no two non-adjacent edges touch and no edge has zero length (exact predicates).
bool is_simple(const Ring& ring);
// Outer ring counter-clockwise, holes clockwise.
void normalize_orientation(Polygon& polygon);
// Even-odd rule over the outer ring and the holes; points on the boundary count as inside.
bool contains(const Polygon& polygon, const Vec2& point);
// Euclidean distance from a point to the nearest edge of any ring of the polygon.
double distance_to_boundary(const Polygon& polygon, const Vec2& point);
Bounds2 bounds(const Ring& ring);

}  // namespace vistrack
