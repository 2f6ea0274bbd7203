// The orbit planner on a real environment: Embree scene, VV cache, grid XOR metric, VP slicing.
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "vistrack/error.hpp"
#include "vistrack/orbit.hpp"
#include "vistrack/volume.hpp"

namespace vistrack {
namespace {

// The fast path of (56): VVs of one planner share a direction grid, compared in the POI frame.
double poi_frame_metric(const VisibilityVolume& a, const VisibilityVolume& b) {
  return xor_volume(a, b, XorFrame::poi, XorMethod::automatic);
}

// The folder exists (created when missing) and accepts a new file.
void prepare_cache_folder(const std::string& folder) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) detail::fail_field("cache_dir", folder, "cannot create the folder: " + error.message());
  if (!std::filesystem::is_directory(folder, error)) detail::fail_field("cache_dir", folder, "is not a folder");
  const std::string probe =
      (std::filesystem::path(folder) / (".write-test-" + std::to_string(::getpid()))).string();
  const bool writable = static_cast<bool>(std::ofstream(probe, std::ios::binary));
  std::remove(probe.c_str());
  if (!writable) detail::fail_field("cache_dir", folder, "is not writable");
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

struct DiskVolumeCache::State {
  std::string folder;
  std::uint64_t environment_fingerprint = 0;
  double d_max = 0.0;
  std::optional<std::pair<double, double>> altitude_band;
  double resolution_deg = 0.0;
  DirectionGrid grid;
  std::atomic<std::size_t> hits{0};
  std::atomic<std::size_t> misses{0};

  // A file read back must be the VV of exactly these inputs (guards against key collisions).
  bool matches(const VisibilityVolume& vv, const Vec3& g) const {
    const bool same_band = vv.altitude_band.has_value() == altitude_band.has_value() &&
                           (!altitude_band || (same_bits(vv.altitude_band->first, altitude_band->first) &&
                                               same_bits(vv.altitude_band->second, altitude_band->second)));
    return same_bits(vv.poi.x(), g.x()) && same_bits(vv.poi.y(), g.y()) && same_bits(vv.poi.z(), g.z()) &&
           same_bits(vv.d_max, d_max) && same_band && vv.grid.num_elevation == grid.num_elevation &&
           vv.grid.num_azimuth == grid.num_azimuth;
  }
};

DiskVolumeCache::DiskVolumeCache(std::string folder, std::uint64_t environment_fingerprint, double d_max,
                                 std::optional<std::pair<double, double>> altitude_band, double resolution_deg)
    : state_(std::make_shared<State>()) {
  if (folder.empty()) detail::fail_field("cache_dir", "''", "must name a folder");
  require_positive(resolution_deg, "resolution_deg");
  prepare_cache_folder(folder);
  state_->folder = std::move(folder);
  state_->environment_fingerprint = environment_fingerprint;
  state_->d_max = d_max;
  state_->altitude_band = altitude_band;
  state_->resolution_deg = resolution_deg;
  state_->grid = DirectionGrid::from_resolution(resolution_deg);
}

std::string DiskVolumeCache::path(const Vec3& poi) const {
  const std::uint64_t key = volume_cache_key(state_->environment_fingerprint, poi, state_->d_max,
                                             state_->altitude_band, state_->resolution_deg);
  return (std::filesystem::path(state_->folder) / volume_cache_file_name(key)).string();
}

VolumeFunction DiskVolumeCache::wrap(VolumeFunction compute) const {
  return [self = *this, compute = std::move(compute)](const Vec3& g) -> VolumePtr {
    const std::string file = self.path(g);
    try {
      if (std::optional<VisibilityVolume> stored = read_volume_file(file); stored && self.state_->matches(*stored, g)) {
        ++self.state_->hits;
        return std::make_shared<const VisibilityVolume>(std::move(*stored));
      }
    } catch (const Error&) {
      // Corrupt, truncated or another version: a miss; the file is replaced below.
    }
    VolumePtr vv = compute(g);
    write_volume_file(*vv, file);
    ++self.state_->misses;
    return vv;
  };
}

const std::string& DiskVolumeCache::folder() const { return state_->folder; }
std::size_t DiskVolumeCache::hits() const { return state_->hits.load(); }
std::size_t DiskVolumeCache::misses() const { return state_->misses.load(); }

namespace {

VolumeFunction planner_volume_function(const VisibilityScene& scene, const Sensor& sensor, double resolution_deg,
                                       const std::optional<DiskVolumeCache>& disk) {
  VolumeFunction compute = [scene, sensor, resolution_deg](const Vec3& g) {
    return std::make_shared<const VisibilityVolume>(
        visibility_volume(scene, g, sensor.d_max, sensor.altitude_band, resolution_deg));
  };
  VolumeFunction cached = disk ? disk->wrap(std::move(compute)) : std::move(compute);
  // A path's z under uneven terrain stands on the terrain (VisibilityScene::poi_on_surface).
  return [scene, cached = std::move(cached)](const Vec3& g) { return cached(scene.poi_on_surface(g)); };
}

std::optional<DiskVolumeCache> make_disk_cache(std::string cache_dir, const VisibilityScene& scene,
                                               const Sensor& sensor, double resolution_deg) {
  if (cache_dir.empty()) return std::nullopt;
  sensor.validate();
  return DiskVolumeCache(std::move(cache_dir), scene.fingerprint(), sensor.d_max, sensor.altitude_band,
                         resolution_deg);
}

}  // namespace

OrbitPlanner::OrbitPlanner(const Environment& env, const Sensor& sensor, double resolution_deg, std::string cache_dir)
    : scene_(env),
      sensor_(sensor),
      resolution_deg_(resolution_deg),
      disk_(make_disk_cache(std::move(cache_dir), scene_, sensor, resolution_deg)),
      cache_(planner_volume_function(scene_, sensor, resolution_deg, disk_)) {
  sensor.validate();
  require_positive(resolution_deg, "resolution_deg");
}

Discretization OrbitPlanner::adaptive(const PoiPath& poi, const Planning& planning, const ProgressFunction& progress) {
  return adaptive_discretization(poi, planning, cache_, poi_frame_metric, progress);
}

Discretization OrbitPlanner::fixed(const PoiPath& poi, double spacing, const ProgressFunction& progress) {
  return fixed_discretization(poi, spacing, cache_, poi_frame_metric, progress);
}

VisibilityOrbitPlan OrbitPlanner::plan(const PoiPath& poi, const Uav& uav, const Planning& planning,
                                       const ProgressFunction& progress) {
  planning.validate();
  if (planning.resolution_deg != resolution_deg_)
    detail::fail_field("planning.resolution_deg", planning.resolution_deg,
                       "differs from the planner's VV resolution " + detail::to_text(resolution_deg_));
  // h_UAV is the world z of the flight plane (the height above ground where the ground is at 0).
  if (!(uav.altitude > scene_.ground_level()))
    detail::fail_field("uav.altitude", uav.altitude,
                       "the flight plane must lie above the ground level " + detail::to_text(scene_.ground_level()));
  const SliceFunction slice = [](const VisibilityVolume& vv, double altitude) {
    return plane_visibility_polygon(vv, altitude);
  };
  return plan_orbits(poi, uav, sensor_, planning, cache_, poi_frame_metric, slice, progress);
}

VisibilityOrbitPlan plan_orbits(const Environment& env, const PoiPath& poi, const Uav& uav, const Sensor& sensor,
                                const Planning& planning, const ProgressFunction& progress,
                                const std::string& cache_dir) {
  uav.validate();
  planning.validate();
  OrbitPlanner planner(env, sensor, planning.resolution_deg, cache_dir);
  return planner.plan(poi, uav, planning, progress);
}

}  // namespace vistrack
