// The orbit plan of section IV from VV samples: VPs at h_UAV, MaxRadius, Algorithm 1.
#include <tbb/parallel_for.h>

#include "locus.hpp"
#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"
#include "vistrack/orbit.hpp"

namespace vistrack {
namespace {

// The locus check's MaxRadius from VVs: the VP of each VV at h_UAV, as at the samples.
detail::CheckProbe volume_probe(std::function<VolumePtr(const Vec3&, bool&)> volume_at, const SliceFunction& slice,
                                double altitude) {
  detail::CheckProbe probe;
  probe.max_radius = [volume_at = std::move(volume_at), slice, altitude](const Vec3& g, bool& computed) {
    const VolumePtr volume = volume_at(g, computed);
    return max_inscribed_radius(slice(*volume, altitude), g.head<2>());
  };
  return probe;
}

VisibilityOrbitPlan plan_with_check(const PoiPath& poi, const Uav& uav, const Sensor& sensor, const Planning& planning,
                                    Discretization samples, const SliceFunction& slice,
                                    const detail::CheckProbe& probe) {
  if (!slice) throw Error("plan_on_samples: slice function is empty");
  const std::size_t n = samples.times.size();
  if (n == 0 || samples.volumes.size() != n) detail::fail_field("samples", n, "need one VV per sample, at least one");

  VisibilityOrbitPlan plan(OrbitPlan{poi, {}, {}, true, {}, {}});
  plan.uav = uav;
  plan.sensor = sensor;
  plan.planning = planning;
  // Line 1 of Algorithm 1: MaxRadius of each VP at h_UAV, centred on g_k.
  plan.polygons.resize(n);
  plan.max_radii.resize(n);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t k) {
    plan.polygons[k] = slice(*samples.volumes[k], uav.altitude);
    const Vec2 centre = samples.points.row(static_cast<Eigen::Index>(k)).head<2>().transpose();
    plan.max_radii[k] = max_inscribed_radius(plan.polygons[k], centre);
  });
  plan.orbits = circular_orbits(samples.times, plan.max_radii, uav, poi.speed(), planning.rate_margin);
  plan.samples = std::move(samples);
  // The reference the guidance follows: Algorithm 1's radii at the sample times.
  plan.times = plan.samples.times;
  plan.radii = plan.orbits.radii;
  plan.feasible = plan.orbits.feasible;
  plan.infeasibility = plan.orbits.infeasibility;
  // Beyond the paper: the locus check between the samples and the smooth R(t).
  if (planning.locus == Locus::smooth) detail::smooth_locus(plan, probe);
  return plan;
}

void validate(const Uav& uav, const Sensor& sensor, const Planning& planning) {
  uav.validate();
  sensor.validate();
  planning.validate();
}

}  // namespace

VisibilityOrbitPlan detail::plan_orbits_of_valid(const PoiPath& poi, const Uav& uav, const Sensor& sensor,
                                                 const Planning& planning, VolumeCache& cache,
                                                 const MetricFunction& metric, const SliceFunction& slice,
                                                 const ProgressFunction& progress,
                                                 const MaxRadiusFunction& check_max_radius) {
  if (!(uav.speed > poi.speed()))
    detail::fail_field("uav.speed", uav.speed,
                       "must exceed the POI speed " + detail::to_text(poi.speed()) + " to orbit it (Lemma 5)");
  // The VVs reach d_max from every POI position and their slices are checked as coordinates: a
  // sensor that reaches past the coordinate range is named here, not a vertex of a slice later.
  for (const double t : poi.node_times()) {
    const Vec3 g = poi.position(t);
    const double reach = std::max(std::abs(g.x()), std::abs(g.y())) + sensor.d_max;
    if (!(reach <= limits::kMaxCoordinate))
      detail::fail_field("sensor.d_max", sensor.d_max,
                         "reaches " + detail::to_text(reach) + " m from the origin around the POI at (" +
                             detail::to_text(g.x()) + ", " + detail::to_text(g.y()) +
                             "), beyond the coordinate limit " + detail::to_text(limits::kMaxCoordinate) + " m");
  }
  detail::CheckProbe probe;
  if (check_max_radius) {
    probe.max_radius = [check_max_radius](const Vec3& g, bool&) { return check_max_radius(g); };
    probe.at_samples = true;
  } else {
    probe = volume_probe([&cache](const Vec3& g, bool& computed) { return cache.at(g, &computed); }, slice,
                         uav.altitude);
  }
  return plan_with_check(poi, uav, sensor, planning, adaptive_discretization(poi, planning, cache, metric, progress),
                         slice, probe);
}

VisibilityOrbitPlan plan_orbits(const PoiPath& poi, const Uav& uav, const Sensor& sensor, const Planning& planning,
                                VolumeCache& cache, const MetricFunction& metric, const SliceFunction& slice,
                                const ProgressFunction& progress, const MaxRadiusFunction& check_max_radius) {
  validate(uav, sensor, planning);
  return detail::plan_orbits_of_valid(poi, uav, sensor, planning, cache, metric, slice, progress, check_max_radius);
}

VisibilityOrbitPlan plan_on_samples(const PoiPath& poi, const Uav& uav, const Sensor& sensor,
                                    const Planning& planning, Discretization samples, const SliceFunction& slice,
                                    const VolumeFunction& volume_at) {
  validate(uav, sensor, planning);
  detail::CheckProbe probe;
  if (volume_at)
    probe = volume_probe(
        [volume_at](const Vec3& g, bool& computed) {
          computed = true;
          return volume_at(g);
        },
        slice, uav.altitude);
  return plan_with_check(poi, uav, sensor, planning, std::move(samples), slice, probe);
}

VisibilityOrbitPlan plan_on_volumes(const PoiPath& poi, const Uav& uav, const Planning& planning,
                                    const std::vector<double>& arc_lengths, const std::vector<VolumePtr>& volumes) {
  const std::size_t n = arc_lengths.size();
  if (n == 0 || volumes.size() != n)
    detail::fail_field("volumes", volumes.size(), "need one VV per arc length (" + std::to_string(n) + "), at least one");
  for (std::size_t k = 0; k < n; ++k) {
    if (!volumes[k]) detail::fail_field("volumes[" + std::to_string(k) + "]", "None", "must be a VV");
    detail::require_mesh(*volumes[k], "volumes[" + std::to_string(k) + "]");
    require_finite(arc_lengths[k], "arc_lengths[" + std::to_string(k) + "]");
    if (k > 0 && !(arc_lengths[k] > arc_lengths[k - 1]))
      detail::fail_field("arc_lengths[" + std::to_string(k) + "]", arc_lengths[k], "must increase");
  }
  const VisibilityVolume& first = *volumes.front();
  Sensor sensor;
  sensor.d_max = first.d_max;
  sensor.altitude_band = first.altitude_band;
  Discretization samples;
  samples.arc_lengths = arc_lengths;
  samples.points.resize(static_cast<Eigen::Index>(n), 3);
  for (std::size_t k = 0; k < n; ++k) {
    samples.times.push_back(arc_lengths[k] / poi.speed());
    samples.points.row(static_cast<Eigen::Index>(k)) = volumes[k]->poi.transpose();
  }
  samples.depths.assign(n, 0);
  samples.volumes = volumes;
  samples.metric.resize(n - 1);
  tbb::parallel_for(std::size_t{0}, n - 1, [&](std::size_t k) {
    samples.metric[k] = xor_volume(*volumes[k], *volumes[k + 1], XorFrame::poi, XorMethod::automatic);
  });
  return plan_on_samples(poi, uav, sensor, planning, std::move(samples), plane_visibility_polygon);
}

}  // namespace vistrack
