// The orbit planner on a real environment: Embree scene, VV caches, POI-frame XOR metric, VP slicing.
#include "locus.hpp"
#include "vistrack/error.hpp"
#include "vistrack/orbit.hpp"

namespace vistrack {
namespace {

// The fast path of (56): VVs of one planner share a direction grid, compared in the POI frame.
double poi_frame_metric(const VisibilityVolume& a, const VisibilityVolume& b) {
  return xor_volume(a, b, XorFrame::poi, XorMethod::automatic);
}

}  // namespace

OrbitPlanner::OrbitPlanner(const Environment& env, const Sensor& sensor, std::string cache_dir)
    : scene_(env), sensor_(sensor), cache_dir_(std::move(cache_dir)) {
  sensor_.validate();
  if (!cache_dir_.empty()) caches(kDefaultResolutionDeg);  // an unusable cache_dir fails here, at once
}

OrbitPlanner::Caches& OrbitPlanner::caches(double resolution_deg) {
  require_positive(resolution_deg, "resolution_deg");
  auto found = caches_.find(resolution_deg);
  if (found != caches_.end()) return found->second;
  std::optional<DiskVolumeCache> disk;
  if (!cache_dir_.empty())
    disk.emplace(cache_dir_, scene_.fingerprint(), sensor_.d_max, sensor_.altitude_band, resolution_deg);
  VolumeFunction compute = [scene = scene_, sensor = sensor_, resolution_deg](const Vec3& g) {
    return std::make_shared<const VisibilityVolume>(
        visibility_volume(scene, g, sensor.d_max, sensor.altitude_band, resolution_deg));
  };
  VolumeFunction cached = disk ? disk->wrap(std::move(compute)) : std::move(compute);
  // A path's z under uneven terrain stands on the terrain (VisibilityScene::poi_on_surface).
  VolumeCache memory([scene = scene_, cached = std::move(cached)](const Vec3& g) {
    return cached(scene.poi_on_surface(g));
  });
  return caches_.emplace(resolution_deg, Caches{std::move(disk), std::move(memory)}).first->second;
}

Discretization OrbitPlanner::adaptive(const PoiPath& poi, const Planning& planning, const ProgressFunction& progress) {
  planning.validate();
  return adaptive_discretization(poi, planning, caches(planning.resolution_deg).memory, poi_frame_metric, progress);
}

Discretization OrbitPlanner::fixed(const PoiPath& poi, double spacing, double resolution_deg,
                                   const ProgressFunction& progress, std::size_t max_volumes) {
  check_work(estimate_fixed_work(poi, spacing, resolution_deg), max_volumes, "max_volumes");
  return fixed_discretization(poi, spacing, caches(resolution_deg).memory, poi_frame_metric, progress, max_volumes);
}

VisibilityOrbitPlan OrbitPlanner::plan(const PoiPath& poi, const Uav& uav, const Planning& planning,
                                       const ProgressFunction& progress) {
  uav.validate();
  planning.validate();
  check_work(estimate_work(poi, planning), planning.max_volumes);  // before the scene does any work
  // h_UAV is the world z of the flight plane (the height above ground where the ground is at 0).
  if (!(uav.altitude > scene_.ground_level()))
    detail::fail_field("uav.altitude", uav.altitude,
                       "the flight plane must lie above the ground level " + detail::to_text(scene_.ground_level()));
  // The locus check probes the disk at h_UAV by line of sight (visible_disk_radius): about 20
  // times cheaper than a VV per point, within the VP mesh's error of the VV's MaxRadius.
  const MaxRadiusFunction check = [scene = scene_, sensor = sensor_, altitude = uav.altitude](const Vec3& g) {
    return detail::visible_disk_radius_of_valid(scene, g, altitude, sensor);
  };
  return detail::plan_orbits_of_valid(poi, uav, sensor_, planning, caches(planning.resolution_deg).memory,
                                      poi_frame_metric, plane_visibility_polygon, progress, check);
}

std::size_t OrbitPlanner::cached_volumes() const {
  std::size_t count = 0;
  for (const auto& entry : caches_) count += entry.second.memory.size();
  return count;
}

std::size_t OrbitPlanner::disk_hits() const {
  std::size_t count = 0;
  for (const auto& entry : caches_) count += entry.second.disk ? entry.second.disk->hits() : 0;
  return count;
}

std::size_t OrbitPlanner::disk_misses() const {
  std::size_t count = 0;
  for (const auto& entry : caches_) count += entry.second.disk ? entry.second.disk->misses() : 0;
  return count;
}

VisibilityOrbitPlan plan_orbits(const Environment& env, const PoiPath& poi, const Uav& uav, const Sensor& sensor,
                                const Planning& planning, const ProgressFunction& progress,
                                const std::string& cache_dir) {
  OrbitPlanner planner(env, sensor, cache_dir);
  return planner.plan(poi, uav, planning, progress);
}

}  // namespace vistrack
