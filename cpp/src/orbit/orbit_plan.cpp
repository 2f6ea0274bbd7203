#include <algorithm>
#include <cmath>
#include <string>

#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"
#include "vistrack/orbit.hpp"

namespace vistrack {

std::size_t OrbitPlan::segment(double t) const {
  if (times.size() < 2) return 0;
  auto it = std::upper_bound(times.begin(), times.end(), t);
  std::size_t k = it == times.begin() ? 0 : static_cast<std::size_t>(it - times.begin()) - 1;
  return std::min(k, times.size() - 2);
}

double OrbitPlan::radius(double t) const {
  require_finite(t, "t");
  if (radii.empty()) throw Error("plan.radii: the orbit plan has no samples");
  if (times.size() < 2) return radii.front();
  t = std::clamp(t, times.front(), times.back());
  const std::size_t k = segment(t);
  const double span = times[k + 1] - times[k];
  const double s = span > 0.0 ? (t - times[k]) / span : 0.0;
  return (1.0 - s) * radii[k] + s * radii[k + 1];
}

Points2 OrbitPlan::centers() const {
  Points2 out(static_cast<Eigen::Index>(times.size()), 2);
  for (std::size_t k = 0; k < times.size(); ++k)
    out.row(static_cast<Eigen::Index>(k)) = poi.position(times[k]).head<2>().transpose();
  return out;
}

double OrbitPlan::radius_rate(double t) const {
  require_finite(t, "t");
  if (times.size() < 2 || t < times.front() || t > times.back()) return 0.0;
  const std::size_t k = segment(t);
  const double span = times[k + 1] - times[k];
  return span > 0.0 ? (radii[k + 1] - radii[k]) / span : 0.0;
}

OrbitPlan constant_radius_plan(const PoiPath& poi, double radius, const Uav& uav) {
  uav.validate();
  require_length(radius, "radius");
  if (!(uav.speed > poi.speed()))
    detail::fail_field("uav.speed", uav.speed,
                       "must exceed the POI speed " + detail::to_text(poi.speed()) + " to orbit it");
  OrbitPlan plan{poi, poi.node_times(), {}, true, {}};
  plan.radii.assign(plan.times.size(), radius);
  // Lemma 6 / Corollary 1: a constant orbit about a moving POI is flyable only from r_min (1 + v_g/v)^2.
  const double needed = min_feasible_radius(uav, poi.speed());
  if (radius < needed) {
    plan.feasible = false;
    plan.infeasibility = "radius " + detail::to_text(radius) + " m < r_min (1 + v_g/v)^2 = " + detail::to_text(needed) +
                         " m: the orbit's curvature exceeds 1/r_min (Lemma 6)";
  }
  return plan;
}

double max_inscribed_radius(const std::vector<Polygon>& polygons, const Vec2& center) {
  require_coordinate(center.x(), "center[0]");
  require_coordinate(center.y(), "center[1]");
  const auto check_ring = [](const Ring& ring, const std::string& field) {
    for (std::size_t i = 0; i < ring.size(); ++i)
      if (!(std::abs(ring[i].x()) <= limits::kMaxCoordinate && std::abs(ring[i].y()) <= limits::kMaxCoordinate))
        detail::fail_field(field + "[" + std::to_string(i) + "]",
                           "(" + detail::to_text(ring[i].x()) + ", " + detail::to_text(ring[i].y()) + ")",
                           "coordinates must be finite numbers in [-1e7, 1e7] m");
  };
  for (std::size_t k = 0; k < polygons.size(); ++k) {
    check_ring(polygons[k].outer, "polygons[" + std::to_string(k) + "].outer");
    for (std::size_t h = 0; h < polygons[k].holes.size(); ++h)
      check_ring(polygons[k].holes[h], "polygons[" + std::to_string(k) + "].holes[" + std::to_string(h) + "]");
  }
  for (const Polygon& polygon : polygons)
    if (contains(polygon, center)) return distance_to_boundary(polygon, center);
  return 0.0;
}

}  // namespace vistrack
