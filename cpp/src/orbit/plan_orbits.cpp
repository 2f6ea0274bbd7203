// The orbit planner of section IV end to end: adaptive VVs, VPs at h_UAV, MaxRadius, Algorithm 1.
#include <nlohmann/json.hpp>

#include <tbb/parallel_for.h>

#include "vistrack/error.hpp"
#include "vistrack/orbit.hpp"

namespace vistrack {

VisibilityOrbitPlan plan_orbits(const PoiPath& poi, const Uav& uav, const Sensor& sensor, const Planning& planning,
                                VolumeCache& cache, const MetricFunction& metric, const SliceFunction& slice,
                                const ProgressFunction& progress) {
  uav.validate();
  sensor.validate();
  planning.validate();
  if (!(uav.speed > poi.speed()))
    detail::fail_field("uav.speed", uav.speed,
                       "must exceed the POI speed " + detail::to_text(poi.speed()) + " to orbit it (Lemma 5)");
  if (!slice) throw Error("plan_orbits: slice function is empty");

  Discretization samples = adaptive_discretization(poi, planning, cache, metric, progress);
  const std::size_t n = samples.times.size();

  VisibilityOrbitPlan plan(OrbitPlan{poi, {}, {}, {}, {}, true, {}});
  plan.uav = uav;
  plan.sensor = sensor;
  plan.planning = planning;
  plan.times = samples.times;
  plan.arc_lengths = samples.arc_lengths;
  plan.depths = samples.depths;
  plan.metric = samples.metric;
  plan.volumes = samples.volumes;
  plan.volumes_computed = samples.volumes_computed;

  // Line 1 of Algorithm 1: MaxRadius of each VP at h_UAV, centred on g_k.
  plan.polygons.resize(n);
  plan.max_radii.resize(n);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t k) {
    plan.polygons[k] = slice(*samples.volumes[k], uav.altitude);
    const Vec2 centre = samples.points.row(static_cast<Eigen::Index>(k)).head<2>().transpose();
    plan.max_radii[k] = max_inscribed_radius(plan.polygons[k], centre);
  });

  CircularOrbits orbits = circular_orbits(plan.times, plan.max_radii, uav, poi.speed(), planning.rate_margin);
  plan.radii = std::move(orbits.radii);
  plan.radius_rates = std::move(orbits.radius_rates);
  plan.min_feasible_radius = orbits.min_feasible_radius;
  plan.failing_samples = std::move(orbits.failing_samples);
  plan.feasible = orbits.feasible;
  plan.infeasibility = std::move(orbits.infeasibility);
  return plan;
}

namespace {

nlohmann::json ring_json(const Ring& ring) {
  nlohmann::json out = nlohmann::json::array();
  for (const Vec2& p : ring) out.push_back({p.x(), p.y()});
  return out;
}

Ring ring_from(const nlohmann::json& in) {
  Ring ring;
  for (const auto& p : in) ring.emplace_back(p.at(0).get<double>(), p.at(1).get<double>());
  return ring;
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
                     {"max_depth", plan.planning.max_depth}, {"rate_margin", plan.planning.rate_margin}};
  nlohmann::json centers = nlohmann::json::array();
  for (double t : plan.times) {
    const Vec3 g = plan.poi.position(t);
    centers.push_back({g.x(), g.y()});
  }
  out["centers"] = centers;
  out["arc_lengths"] = plan.arc_lengths;
  out["depths"] = plan.depths;
  out["radius_rates"] = plan.radius_rates;
  out["min_feasible_radius"] = plan.min_feasible_radius;
  out["failing_samples"] = plan.failing_samples;
  out["volumes_computed"] = plan.volumes_computed;
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
  for (const VolumePtr& v : plan.volumes) out["vv_volumes"].push_back(v ? v->volume : 0.0);
  return out.dump(1);
}

VisibilityOrbitPlan visibility_orbit_plan_from_json(const std::string& text) {
  VisibilityOrbitPlan plan(orbit_plan_from_json(text));
  const nlohmann::json in = nlohmann::json::parse(text);  // parsed fine above
  try {
    if (in.contains("uav")) {
      plan.uav.speed = in["uav"].at("speed").get<double>();
      plan.uav.min_turn_radius = in["uav"].at("min_turn_radius").get<double>();
      plan.uav.altitude = in["uav"].at("altitude").get<double>();
    }
    if (in.contains("sensor")) {
      plan.sensor.d_max = in["sensor"].at("d_max").get<double>();
      if (in["sensor"].contains("altitude_band"))
        plan.sensor.altitude_band = std::make_pair(in["sensor"]["altitude_band"].at(0).get<double>(),
                                                   in["sensor"]["altitude_band"].at(1).get<double>());
    }
    if (in.contains("uav")) plan.uav.validate();
    if (in.contains("sensor")) plan.sensor.validate();
    if (in.contains("planning")) {
      const auto& p = in["planning"];
      plan.planning.spacing = p.at("spacing").get<double>();
      plan.planning.cutoff = p.at("cutoff").get<double>();
      plan.planning.resolution_deg = p.at("resolution_deg").get<double>();
      plan.planning.min_spacing = p.at("min_spacing").get<double>();
      plan.planning.max_depth = p.at("max_depth").get<int>();
      plan.planning.rate_margin = p.value("rate_margin", 0.0);  // absent in files before it existed
      plan.planning.validate();
    }
    plan.arc_lengths = in.value("arc_lengths", std::vector<double>{});
    plan.depths = in.value("depths", std::vector<int>{});
    // dR/dt is derived from the samples, never trusted from the file.
    plan.radius_rates.clear();
    for (std::size_t k = 0; k + 1 < plan.times.size(); ++k)
      plan.radius_rates.push_back((plan.radii[k + 1] - plan.radii[k]) / (plan.times[k + 1] - plan.times[k]));
    plan.min_feasible_radius = in.value("min_feasible_radius", 0.0);
    plan.failing_samples = in.value("failing_samples", std::vector<std::size_t>{});
    plan.volumes_computed = in.value("volumes_computed", std::size_t{0});
    if (in.contains("polygons"))
      for (const auto& vp : in["polygons"]) {
        std::vector<Polygon> list;
        for (const auto& polygon : vp) {
          Polygon p;
          p.outer = ring_from(polygon.at("outer"));
          for (const auto& hole : polygon.at("holes")) p.holes.push_back(ring_from(hole));
          list.push_back(std::move(p));
        }
        plan.polygons.push_back(std::move(list));
      }
  } catch (const nlohmann::json::exception& error) {
    throw Error(std::string("visibility orbit plan JSON: missing or wrong field: ") + error.what());
  }
  if (!plan.radius_rates.empty() && plan.radius_rates.size() + 1 != plan.times.size())
    detail::fail_field("radius_rates", plan.radius_rates.size(), "must have one entry per segment");
  return plan;
}

}  // namespace vistrack
