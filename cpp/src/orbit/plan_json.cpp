// Orbit plans as JSON: the reference R(t) ("vistrack.orbit_plan/1") and the plan with what it
// was made from ("vistrack.visibility_orbit_plan/1"; VVs are not stored).
#include <nlohmann/json.hpp>

#include "limits/json_input.hpp"
#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"
#include "vistrack/orbit.hpp"

namespace vistrack {

std::string to_json(const OrbitPlan& plan) {
  nlohmann::json out;
  out["format"] = "vistrack.orbit_plan/1";
  const Points3& w = plan.poi.waypoints();
  nlohmann::json waypoints = nlohmann::json::array();
  for (Eigen::Index i = 0; i < w.rows(); ++i) waypoints.push_back({w(i, 0), w(i, 1), w(i, 2)});
  out["poi"] = {{"waypoints", waypoints}, {"speed", plan.poi.speed()}};
  out["times"] = plan.times;
  out["radii"] = plan.radii;
  out["feasible"] = plan.feasible;
  out["infeasibility"] = plan.infeasibility;
  if (!plan.reference.times.empty())  // absent: piecewise linear through (times, radii)
    out["reference"] = {{"times", plan.reference.times}, {"radii", plan.reference.radii}, {"rates", plan.reference.rates}};
  return out.dump(1);
}

OrbitPlan orbit_plan_from_json(const std::string& text) {
  const nlohmann::json in = detail::parse_json(text, "orbit plan JSON");
  try {
    const auto& waypoints = in.at("poi").at("waypoints");
    if (!waypoints.is_array()) detail::fail_field("poi.waypoints", detail::json_preview(waypoints), "must be a list");
    Eigen::MatrixXd points(static_cast<Eigen::Index>(waypoints.size()), 3);
    for (std::size_t i = 0; i < waypoints.size(); ++i)
      for (std::size_t k = 0; k < 3; ++k)
        points(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) = waypoints.at(i).at(k).get<double>();
    OrbitPlan plan{PoiPath(points, in.at("poi").at("speed").get<double>()),
                   in.at("times").get<std::vector<double>>(),
                   in.at("radii").get<std::vector<double>>(),
                   in.value("feasible", true),
                   in.value("infeasibility", std::string()),
                   {}};
    if (in.contains("reference")) {
      const auto& r = in["reference"];
      plan.reference.times = r.at("times").get<std::vector<double>>();
      plan.reference.radii = r.at("radii").get<std::vector<double>>();
      plan.reference.rates = r.value("rates", std::vector<double>{});
      plan.reference.validate();
    }
    if (plan.times.size() != plan.radii.size() || plan.times.empty())
      detail::fail_field("radii", plan.radii.size(),
                         "must have one entry per time (" + std::to_string(plan.times.size()) + ")");
    for (std::size_t k = 0; k < plan.times.size(); ++k) {
      require_finite(plan.times[k], "times[" + std::to_string(k) + "]");
      // 0: the POI is not visible there (an infeasible plan).
      require_in_range(plan.radii[k], 0.0, limits::kMaxLength, "m", "radii[" + std::to_string(k) + "]");
      if (k > 0 && !(plan.times[k] > plan.times[k - 1]))
        detail::fail_field("times[" + std::to_string(k) + "]", plan.times[k], "times must increase");
    }
    return plan;
  } catch (const nlohmann::json::exception& error) {
    throw Error(std::string("orbit plan JSON: missing or wrong field: ") + error.what());
  }
}

namespace {

nlohmann::json ring_json(const Ring& ring) {
  nlohmann::json out = nlohmann::json::array();
  for (const Vec2& p : ring) out.push_back({p.x(), p.y()});
  return out;
}

Ring ring_from(const nlohmann::json& in, const std::string& field) {
  if (!in.is_array()) detail::fail_field(field, detail::json_preview(in), "a ring must be a list of [x, y]");
  Ring ring;
  for (std::size_t i = 0; i < in.size(); ++i) {
    const Vec2 p(in[i].at(0).get<double>(), in[i].at(1).get<double>());
    require_coordinate(p.x(), field + "[" + std::to_string(i) + "][0]");
    require_coordinate(p.y(), field + "[" + std::to_string(i) + "][1]");
    ring.push_back(p);
  }
  return ring;
}

// A per-sample list of the file: absent (empty) or `expected` entries.
template <class T>
void require_size(const std::vector<T>& values, std::size_t expected, const std::string& field) {
  if (!values.empty() && values.size() != expected)
    detail::fail_field(field, std::to_string(values.size()) + " entries", "must have " + std::to_string(expected));
}

}  // namespace

std::string to_json(const VisibilityOrbitPlan& plan) {
  nlohmann::json out = nlohmann::json::parse(to_json(static_cast<const OrbitPlan&>(plan)));
  out["format"] = "vistrack.visibility_orbit_plan/1";
  out["uav"] = {{"speed", plan.uav.speed}, {"min_turn_radius", plan.uav.min_turn_radius}, {"altitude", plan.uav.altitude}};
  out["sensor"] = {{"d_max", plan.sensor.d_max}};
  if (plan.sensor.altitude_band)
    out["sensor"]["altitude_band"] = {plan.sensor.altitude_band->first, plan.sensor.altitude_band->second};
  out["planning"] = {{"spacing", plan.planning.spacing},         {"cutoff", plan.planning.cutoff},
                     {"resolution_deg", plan.planning.resolution_deg}, {"min_spacing", plan.planning.min_spacing},
                     {"max_depth", plan.planning.max_depth}, {"rate_margin", plan.planning.rate_margin},
                     {"locus", to_string(plan.planning.locus)}, {"tracking_margin", plan.planning.tracking_margin},
                     {"check_spacing", plan.planning.check_spacing},
                     {"check_min_spacing", plan.planning.check_min_spacing}, {"turn_share", plan.planning.turn_share},
                     {"radius_smoothing", plan.planning.radius_smoothing},
                     {"max_volumes", plan.planning.max_volumes}};
  out["orbit_radii"] = plan.orbits.radii;  // Algorithm 1's, at the samples (radii: the reference there)
  const Discretization& samples = plan.samples;
  nlohmann::json centers = nlohmann::json::array();
  for (Eigen::Index k = 0; k < samples.points.rows(); ++k) centers.push_back({samples.points(k, 0), samples.points(k, 1)});
  out["centers"] = centers;
  out["arc_lengths"] = samples.arc_lengths;
  out["depths"] = samples.depths;
  out["metric"] = samples.metric;
  out["volumes_computed"] = samples.volumes_computed;
  out["max_radii"] = plan.max_radii;
  out["radius_rates"] = plan.orbits.radius_rates;
  out["min_feasible_radius"] = plan.orbits.min_feasible_radius;
  out["failing_samples"] = plan.orbits.failing_samples;
  nlohmann::json polygons = nlohmann::json::array();
  for (const auto& vp : plan.polygons) {
    nlohmann::json list = nlohmann::json::array();
    for (const Polygon& polygon : vp) {
      nlohmann::json holes = nlohmann::json::array();
      for (const Ring& hole : polygon.holes) holes.push_back(ring_json(hole));
      list.push_back({{"outer", ring_json(polygon.outer)}, {"holes", holes}});
    }
    polygons.push_back(list);
  }
  out["polygons"] = polygons;
  out["vv_volumes"] = nlohmann::json::array();
  for (const VolumePtr& v : samples.volumes) out["vv_volumes"].push_back(v ? v->volume : 0.0);
  if (plan.planning.locus == Locus::smooth) {
    const LocusCheck& c = plan.check;
    out["check"] = {{"arc_lengths", c.arc_lengths},
                    {"max_radii", c.max_radii},
                    {"ceiling_starts", c.ceiling.starts},
                    {"ceiling_ends", c.ceiling.ends},
                    {"slope_bounds", c.slope_bounds},
                    {"volumes_computed", c.volumes_computed},
                    {"rounds", c.rounds},
                    {"paper_violations", c.paper_violations},
                    {"paper_max_violation", c.paper_max_violation},
                    {"lowering", c.lowering},
                    {"max_lowering", c.max_lowering},
                    {"max_lowering_time", c.max_lowering_time},
                    {"min_clearance", c.min_clearance}};
  }
  return out.dump(1);
}

VisibilityOrbitPlan visibility_orbit_plan_from_json(const std::string& text) {
  VisibilityOrbitPlan plan(orbit_plan_from_json(text));
  const nlohmann::json in = detail::parse_json(text, "orbit plan JSON");  // parsed fine above
  try {
    if (in.contains("uav")) {
      plan.uav.speed = in["uav"].at("speed").get<double>();
      plan.uav.min_turn_radius = in["uav"].at("min_turn_radius").get<double>();
      plan.uav.altitude = in["uav"].at("altitude").get<double>();
      plan.uav.validate();
    }
    if (in.contains("sensor")) {
      plan.sensor.d_max = in["sensor"].at("d_max").get<double>();
      if (in["sensor"].contains("altitude_band"))
        plan.sensor.altitude_band = std::make_pair(in["sensor"]["altitude_band"].at(0).get<double>(),
                                                   in["sensor"]["altitude_band"].at(1).get<double>());
      plan.sensor.validate();
    }
    if (in.contains("planning")) {
      const auto& p = in["planning"];
      plan.planning.spacing = p.at("spacing").get<double>();
      plan.planning.cutoff = p.at("cutoff").get<double>();
      plan.planning.resolution_deg = p.at("resolution_deg").get<double>();
      plan.planning.min_spacing = p.at("min_spacing").get<double>();
      plan.planning.max_depth = p.at("max_depth").get<int>();
      plan.planning.rate_margin = p.value("rate_margin", 0.0);  // absent in files before it existed
      plan.planning.max_volumes = p.value("max_volumes", Planning{}.max_volumes);
      // Files before the smooth locus hold the paper's piecewise-linear one.
      plan.planning.locus = from_name<Locus>(p.value("locus", std::string("paper")), "planning.locus");
      plan.planning.tracking_margin = p.value("tracking_margin", Planning{}.tracking_margin);
      plan.planning.check_spacing = p.value("check_spacing", Planning{}.check_spacing);
      plan.planning.check_min_spacing = p.value("check_min_spacing", Planning{}.check_min_spacing);
      plan.planning.turn_share = p.value("turn_share", Planning{}.turn_share);
      // Files before the penalty hold the largest-area locus.
      plan.planning.radius_smoothing = p.value("radius_smoothing", 0.0);
      plan.planning.validate();
    }
    Discretization& samples = plan.samples;
    samples.times = plan.times;
    samples.arc_lengths = in.value("arc_lengths", std::vector<double>{});
    samples.depths = in.value("depths", std::vector<int>{});
    samples.metric = in.value("metric", std::vector<double>{});
    samples.volumes_computed = in.value("volumes_computed", std::size_t{0});
    const std::size_t n = plan.times.size();
    samples.points.resize(static_cast<Eigen::Index>(n), 3);
    for (std::size_t k = 0; k < n; ++k)
      samples.points.row(static_cast<Eigen::Index>(k)) = plan.poi.position(plan.times[k]).transpose();
    plan.max_radii = in.value("max_radii", std::vector<double>{});
    plan.orbits.radii = in.value("orbit_radii", plan.radii);
    if (plan.orbits.radii.size() != n)
      detail::fail_field("orbit_radii", plan.orbits.radii.size(), "must have one entry per time (" + std::to_string(n) + ")");
    plan.orbits.feasible = plan.feasible;
    plan.orbits.infeasibility = plan.infeasibility;
    // dR/dt is derived from the samples, never trusted from the file.
    for (std::size_t k = 0; k + 1 < n; ++k)
      plan.orbits.radius_rates.push_back((plan.orbits.radii[k + 1] - plan.orbits.radii[k]) /
                                         (plan.times[k + 1] - plan.times[k]));
    if (in.contains("check")) {
      const auto& c = in["check"];
      LocusCheck& check = plan.check;
      check.arc_lengths = c.at("arc_lengths").get<std::vector<double>>();
      for (double s : check.arc_lengths) check.times.push_back(s / plan.poi.speed());
      check.max_radii = c.at("max_radii").get<std::vector<double>>();
      check.ceiling.breaks = check.times;
      check.ceiling.starts = c.at("ceiling_starts").get<std::vector<double>>();
      check.ceiling.ends = c.at("ceiling_ends").get<std::vector<double>>();
      if (!check.times.empty()) check.ceiling.validate();
      check.slope_bounds = c.value("slope_bounds", std::vector<double>{});
      check.volumes_computed = c.value("volumes_computed", std::size_t{0});
      check.rounds = c.value("rounds", 0);
      check.paper_violations = c.value("paper_violations", std::size_t{0});
      check.paper_max_violation = c.value("paper_max_violation", 0.0);
      check.lowering = c.value("lowering", std::vector<double>{});
      check.max_lowering = c.value("max_lowering", 0.0);
      check.max_lowering_time = c.value("max_lowering_time", 0.0);
      check.min_clearance = c.value("min_clearance", 0.0);
      if (check.max_radii.size() != check.arc_lengths.size())
        detail::fail_field("check.max_radii", check.max_radii.size(), "must have one entry per check arc length");
    }
    plan.orbits.min_feasible_radius = in.value("min_feasible_radius", 0.0);
    plan.orbits.failing_samples = in.value("failing_samples", std::vector<std::size_t>{});
    if (in.contains("polygons")) {
      const auto& polygons = in["polygons"];
      for (std::size_t k = 0; k < polygons.size(); ++k) {
        const std::string field = "polygons[" + std::to_string(k) + "]";
        std::vector<Polygon> list;
        for (std::size_t j = 0; j < polygons[k].size(); ++j) {
          const auto& polygon = polygons[k][j];
          const std::string name = field + "[" + std::to_string(j) + "]";
          Polygon p;
          p.outer = ring_from(polygon.at("outer"), name + ".outer");
          const auto& holes = polygon.at("holes");
          for (std::size_t h = 0; h < holes.size(); ++h)
            p.holes.push_back(ring_from(holes[h], name + ".holes[" + std::to_string(h) + "]"));
          list.push_back(std::move(p));
        }
        plan.polygons.push_back(std::move(list));
      }
    }
    // Every per-sample list has one entry per sample (or is absent), and holds numbers in range:
    // figures and reports index them by sample.
    require_size(samples.arc_lengths, n, "arc_lengths");
    require_size(samples.depths, n, "depths");
    require_size(plan.max_radii, n, "max_radii");
    require_size(plan.polygons, n, "polygons");
    if (!samples.metric.empty() && samples.metric.size() + 1 != n)
      detail::fail_field("metric", std::to_string(samples.metric.size()) + " entries",
                         "must have one per pair of neighbouring samples (" + std::to_string(n - 1) + ")");
    for (std::size_t k = 0; k < samples.arc_lengths.size(); ++k)
      require_in_range(samples.arc_lengths[k], 0.0, 1e15, "m", "arc_lengths[" + std::to_string(k) + "]");
    for (std::size_t k = 0; k < samples.depths.size(); ++k)
      if (samples.depths[k] < 0 || samples.depths[k] > 30)
        detail::fail_field("depths[" + std::to_string(k) + "]", samples.depths[k], "must be in [0, 30]");
    for (std::size_t k = 0; k < plan.max_radii.size(); ++k)
      require_in_range(plan.max_radii[k], 0.0, limits::kMaxLength, "m", "max_radii[" + std::to_string(k) + "]");
    for (std::size_t k = 0; k < samples.metric.size(); ++k)
      require_in_range(samples.metric[k], 0.0, 1e30, "m^3", "metric[" + std::to_string(k) + "]");
    require_in_range(plan.orbits.min_feasible_radius, 0.0, limits::kMaxLength, "m", "min_feasible_radius");
    for (std::size_t k = 0; k < plan.orbits.failing_samples.size(); ++k)
      if (plan.orbits.failing_samples[k] >= n)
        detail::fail_field("failing_samples[" + std::to_string(k) + "]", plan.orbits.failing_samples[k],
                           "must be a sample index in [0, " + std::to_string(n) + ")");
  } catch (const nlohmann::json::exception& error) {
    throw Error(std::string("visibility orbit plan JSON: missing or wrong field: ") + error.what());
  }
  return plan;
}

}  // namespace vistrack
