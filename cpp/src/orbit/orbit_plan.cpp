#include <algorithm>
#include <cmath>
#include <string>

#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"
#include "vistrack/orbit.hpp"

namespace vistrack {

namespace {

std::size_t segment_of(const std::vector<double>& times, double t) {
  if (times.size() < 2) return 0;
  auto it = std::upper_bound(times.begin(), times.end(), t);
  std::size_t k = it == times.begin() ? 0 : static_cast<std::size_t>(it - times.begin()) - 1;
  return std::min(k, times.size() - 2);
}

}  // namespace

std::size_t RadiusProfile::segment(double t) const { return segment_of(times, t); }

double RadiusProfile::radius(double t) const {
  require_finite(t, "t");
  if (radii.empty()) throw Error("plan.radii: the orbit plan has no samples");
  if (times.size() < 2) return radii.front();
  t = std::clamp(t, times.front(), times.back());
  const std::size_t k = segment(t);
  const double span = times[k + 1] - times[k];
  const double s = t - times[k];
  if (smooth()) return radii[k] + rates[k] * s + (rates[k + 1] - rates[k]) * s * s / (2.0 * span);
  const double u = span > 0.0 ? s / span : 0.0;
  return (1.0 - u) * radii[k] + u * radii[k + 1];
}

double RadiusProfile::rate(double t) const {
  require_finite(t, "t");
  if (times.size() < 2 || t < times.front() || t > times.back()) return 0.0;
  const std::size_t k = segment(t);
  const double span = times[k + 1] - times[k];
  if (smooth()) return rates[k] + (rates[k + 1] - rates[k]) * (t - times[k]) / span;
  return span > 0.0 ? (radii[k + 1] - radii[k]) / span : 0.0;
}

double RadiusProfile::acceleration(double t) const {
  require_finite(t, "t");
  if (!smooth() || times.size() < 2 || t < times.front() || t > times.back()) return 0.0;
  const std::size_t k = segment(t);
  return (rates[k + 1] - rates[k]) / (times[k + 1] - times[k]);
}

double RadiusProfile::min_radius() const {
  if (radii.empty()) throw Error("plan.radii: the orbit plan has no samples");
  double lowest = *std::min_element(radii.begin(), radii.end());
  if (smooth())
    for (std::size_t k = 0; k + 1 < times.size(); ++k)
      if (rates[k] < 0.0 && rates[k + 1] > 0.0) {  // a minimum inside the segment, where dR/dt = 0
        const double s = -rates[k] * (times[k + 1] - times[k]) / (rates[k + 1] - rates[k]);
        lowest = std::min(lowest, radii[k] + 0.5 * rates[k] * s);
      }
  return lowest;
}

void RadiusProfile::validate() const {
  if (times.empty()) detail::fail_field("reference.times", "[]", "need at least one knot");
  if (radii.size() != times.size())
    detail::fail_field("reference.radii", radii.size(), "must have one entry per knot (" + std::to_string(times.size()) + ")");
  if (!rates.empty() && rates.size() != times.size())
    detail::fail_field("reference.rates", rates.size(),
                       "must be empty (piecewise linear) or have one entry per knot (" + std::to_string(times.size()) + ")");
  double scale = 1.0;
  for (std::size_t k = 0; k < times.size(); ++k) {
    require_finite(times[k], "reference.times[" + std::to_string(k) + "]");
    require_finite(radii[k], "reference.radii[" + std::to_string(k) + "]");
    if (!rates.empty()) require_finite(rates[k], "reference.rates[" + std::to_string(k) + "]");
    if (k > 0 && !(times[k] > times[k - 1]))
      detail::fail_field("reference.times[" + std::to_string(k) + "]", times[k], "knot times must increase");
    scale = std::max(scale, std::abs(radii[k]));
  }
  if (smooth())
    for (std::size_t k = 0; k + 1 < times.size(); ++k) {
      const double end = radii[k] + 0.5 * (times[k + 1] - times[k]) * (rates[k] + rates[k + 1]);
      if (std::abs(end - radii[k + 1]) > 1e-9 * scale)
        detail::fail_field("reference.radii[" + std::to_string(k + 1) + "]", radii[k + 1],
                           "does not continue the quadratic segment before it (which ends at " + detail::to_text(end) +
                               "): R(t) would jump");
    }
}

RadiusProfile OrbitPlan::profile() const {
  if (!reference.times.empty()) return reference;
  return RadiusProfile{times, radii, {}};
}

double OrbitPlan::radius(double t) const {
  return reference.times.empty() ? RadiusProfile{times, radii, {}}.radius(t) : reference.radius(t);
}

double OrbitPlan::radius_rate(double t) const {
  return reference.times.empty() ? RadiusProfile{times, radii, {}}.rate(t) : reference.rate(t);
}

double OrbitPlan::radius_acceleration(double t) const { return reference.acceleration(t); }

std::size_t OrbitPlan::segment(double t) const { return segment_of(times, t); }

Points2 OrbitPlan::centers() const {
  Points2 out(static_cast<Eigen::Index>(times.size()), 2);
  for (std::size_t k = 0; k < times.size(); ++k)
    out.row(static_cast<Eigen::Index>(k)) = poi.position(times[k]).head<2>().transpose();
  return out;
}

OrbitPlan constant_radius_plan(const PoiPath& poi, double radius, const Uav& uav) {
  uav.validate();
  require_length(radius, "radius");
  if (!(uav.speed > poi.speed()))
    detail::fail_field("uav.speed", uav.speed,
                       "must exceed the POI speed " + detail::to_text(poi.speed()) + " to orbit it");
  OrbitPlan plan{poi, poi.node_times(), {}, true, {}, {}};
  plan.radii.assign(plan.times.size(), radius);
  // Lemma 6 / Corollary 1: a constant orbit about a moving POI is flyable only from r_min (1 + v_g/v)^2.
  const double needed = min_feasible_radius(uav, poi.speed());
  if (radius < needed) {
    plan.feasible = false;
    plan.infeasibility = "radius " + detail::to_text(radius) + " m < r_min (1 + v_g/v)^2 = " + detail::computed_text(needed) +
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
