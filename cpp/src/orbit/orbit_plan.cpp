#include <algorithm>

#include <nlohmann/json.hpp>

#include "vistrack/error.hpp"
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

double OrbitPlan::radius_rate(double t) const {
  require_finite(t, "t");
  if (times.size() < 2 || t < times.front() || t > times.back()) return 0.0;
  const std::size_t k = segment(t);
  const double span = times[k + 1] - times[k];
  return span > 0.0 ? (radii[k + 1] - radii[k]) / span : 0.0;
}

OrbitPlan constant_radius_plan(const PoiPath& poi, double radius, const Uav& uav) {
  uav.validate();
  require_positive(radius, "radius");
  if (!(uav.speed > poi.speed()))
    detail::fail_field("uav.speed", uav.speed,
                       "must exceed the POI speed " + detail::to_text(poi.speed()) + " to orbit it");
  OrbitPlan plan{poi, poi.node_times(), {}, {}, {}, true, {}};
  plan.radii.assign(plan.times.size(), radius);
  plan.max_radii = plan.radii;
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
  require_finite(center.x(), "center[0]");
  require_finite(center.y(), "center[1]");
  for (const Polygon& polygon : polygons)
    if (contains(polygon, center)) return distance_to_boundary(polygon, center);
  return 0.0;
}

std::string to_json(const OrbitPlan& plan) {
  nlohmann::json out;
  out["format"] = "vistrack.orbit_plan/1";
  const Points3& w = plan.poi.waypoints();
  nlohmann::json waypoints = nlohmann::json::array();
  for (Eigen::Index i = 0; i < w.rows(); ++i) waypoints.push_back({w(i, 0), w(i, 1), w(i, 2)});
  out["poi"] = {{"waypoints", waypoints}, {"speed", plan.poi.speed()}};
  out["times"] = plan.times;
  out["radii"] = plan.radii;
  out["max_radii"] = plan.max_radii;
  out["metric"] = plan.metric;
  out["feasible"] = plan.feasible;
  out["infeasibility"] = plan.infeasibility;
  return out.dump(1);
}

OrbitPlan orbit_plan_from_json(const std::string& text) {
  nlohmann::json in;
  try {
    in = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& error) {
    throw Error(std::string("orbit plan JSON: cannot parse: ") + error.what());
  }
  try {
    const auto& waypoints = in.at("poi").at("waypoints");
    Eigen::MatrixXd points(static_cast<Eigen::Index>(waypoints.size()), 3);
    for (std::size_t i = 0; i < waypoints.size(); ++i)
      for (std::size_t k = 0; k < 3; ++k)
        points(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) = waypoints.at(i).at(k).get<double>();
    OrbitPlan plan{PoiPath(points, in.at("poi").at("speed").get<double>()),
                   in.at("times").get<std::vector<double>>(),
                   in.at("radii").get<std::vector<double>>(),
                   in.value("max_radii", std::vector<double>{}),
                   in.value("metric", std::vector<double>{}),
                   in.value("feasible", true),
                   in.value("infeasibility", std::string())};
    if (plan.times.size() != plan.radii.size() || plan.times.empty())
      detail::fail_field("radii", plan.radii.size(),
                         "must have one entry per time (" + std::to_string(plan.times.size()) + ")");
    for (std::size_t k = 0; k < plan.times.size(); ++k) {
      require_finite(plan.times[k], "times[" + std::to_string(k) + "]");
      require_non_negative(plan.radii[k], "radii[" + std::to_string(k) + "]");  // 0: POI not visible (infeasible plan)
      if (k > 0 && !(plan.times[k] > plan.times[k - 1]))
        detail::fail_field("times[" + std::to_string(k) + "]", plan.times[k], "times must increase");
    }
    return plan;
  } catch (const nlohmann::json::exception& error) {
    throw Error(std::string("orbit plan JSON: missing or wrong field: ") + error.what());
  }
}

}  // namespace vistrack
