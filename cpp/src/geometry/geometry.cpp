#include "vistrack/geometry.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "vistrack/error.hpp"

namespace vistrack {

double wrap_to_pi(double angle) {
  if (!std::isfinite(angle)) detail::fail_field("angle", angle, "must be a finite number of radians");
  double wrapped = std::remainder(angle, kTwoPi);  // in [-pi, pi]
  if (wrapped <= -kPi) wrapped += kTwoPi;
  return wrapped;
}

double past_finish_line(const Vec2& p, const Vec2& from, const Vec2& to) {
  const Vec2 leg = to - from;
  const double length = leg.norm();
  return length > 0.0 ? (p - to).dot(leg) / length : 0.0;
}

double wrap_to_two_pi(double angle) {
  if (!std::isfinite(angle)) detail::fail_field("angle", angle, "must be a finite number of radians");
  double wrapped = std::fmod(angle, kTwoPi);
  if (wrapped < 0.0) wrapped += kTwoPi;
  if (wrapped >= kTwoPi) wrapped = 0.0;
  return wrapped;
}

double signed_area(const Ring& ring) {
  double twice_area = 0.0;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = ring[i];
    const Vec2& b = ring[(i + 1) % n];
    twice_area += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * twice_area;
}

double area(const Polygon& polygon) {
  double total = std::abs(signed_area(polygon.outer));
  for (const Ring& hole : polygon.holes) total -= std::abs(signed_area(hole));
  return total;
}

bool is_simple(const Ring& ring) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  if (ring.size() < 3) return false;
  CGAL::Polygon_2<Kernel> polygon;
  for (const Vec2& p : ring) polygon.push_back(Kernel::Point_2(p.x(), p.y()));
  // CGAL's test uses exact predicates; repeated consecutive points make it non-simple too.
  return polygon.is_simple();
}

void normalize_orientation(Polygon& polygon) {
  if (signed_area(polygon.outer) < 0.0) std::reverse(polygon.outer.begin(), polygon.outer.end());
  for (Ring& hole : polygon.holes)
    if (signed_area(hole) > 0.0) std::reverse(hole.begin(), hole.end());
}

namespace {

// Even-odd crossing test for one ring; boundary points are reported through on_boundary.
bool ring_crosses_odd(const Ring& ring, const Vec2& p, bool& on_boundary) {
  bool inside = false;
  const std::size_t n = ring.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2& a = ring[i];
    const Vec2& b = ring[j];
    const Vec2 ab = b - a;
    const Vec2 ap = p - a;
    const double cross = ab.x() * ap.y() - ab.y() * ap.x();
    const double dot = ab.dot(ap);
    if (cross == 0.0 && dot >= 0.0 && dot <= ab.squaredNorm()) on_boundary = true;
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x_cross = a.x() + (p.y() - a.y()) * ab.x() / ab.y();
      if (p.x() < x_cross) inside = !inside;
    }
  }
  return inside;
}

double distance_to_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double length_squared = ab.squaredNorm();
  double s = length_squared > 0.0 ? (p - a).dot(ab) / length_squared : 0.0;
  s = std::clamp(s, 0.0, 1.0);
  return (a + s * ab - p).norm();
}

double distance_to_ring(const Ring& ring, const Vec2& p) {
  double best = std::numeric_limits<double>::infinity();
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i)
    best = std::min(best, distance_to_segment(p, ring[i], ring[(i + 1) % n]));
  return best;
}

}  // namespace

bool contains(const Polygon& polygon, const Vec2& point) {
  bool on_boundary = false;
  bool inside = ring_crosses_odd(polygon.outer, point, on_boundary);
  for (const Ring& hole : polygon.holes)
    if (ring_crosses_odd(hole, point, on_boundary)) inside = !inside;
  return inside || on_boundary;
}

double distance_to_boundary(const Polygon& polygon, const Vec2& point) {
  double best = distance_to_ring(polygon.outer, point);
  for (const Ring& hole : polygon.holes) best = std::min(best, distance_to_ring(hole, point));
  return best;
}

Bounds2 bounds(const Ring& ring) {
  Bounds2 box{Vec2::Constant(std::numeric_limits<double>::infinity()),
              Vec2::Constant(-std::numeric_limits<double>::infinity())};
  for (const Vec2& p : ring) {
    box.min = box.min.cwiseMin(p);
    box.max = box.max.cwiseMax(p);
  }
  return box;
}

}  // namespace vistrack
