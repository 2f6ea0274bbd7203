// VV caches: an in-memory memo by POI position, and VV files on disk keyed by every input.
#include <unistd.h>

#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>

#include "vistrack/error.hpp"
#include "vistrack/visibility.hpp"

namespace vistrack {
namespace {

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

struct VolumeCache::State {
  VolumeFunction compute;
  std::mutex mutex;
  std::map<std::array<long long, 3>, VolumePtr> volumes;  // key: POI position in micrometres
};

VolumeCache::VolumeCache(VolumeFunction compute) : state_(std::make_shared<State>()) {
  if (!compute) throw Error("VolumeCache: compute function is empty");
  state_->compute = std::move(compute);
}

VolumePtr VolumeCache::at(const Vec3& g, bool* computed) {
  if (!g.allFinite()) detail::fail_field("g", g.transpose(), "must be finite");
  const std::array<long long, 3> key{std::llround(g.x() * 1e6), std::llround(g.y() * 1e6), std::llround(g.z() * 1e6)};
  {
    std::lock_guard<std::mutex> lock(state_->mutex);
    auto it = state_->volumes.find(key);
    if (it != state_->volumes.end()) {
      if (computed) *computed = false;
      return it->second;
    }
  }
  // Computed outside the lock so that several threads trace at once; a rare duplicate is harmless.
  VolumePtr volume = state_->compute(g);
  if (!volume) throw Error("VolumeCache: the volume function returned no volume at g = " + detail::to_text(g.transpose()));
  std::lock_guard<std::mutex> lock(state_->mutex);
  auto inserted = state_->volumes.emplace(key, std::move(volume));
  if (computed) *computed = inserted.second;
  return inserted.first->second;
}

std::size_t VolumeCache::size() const {
  std::lock_guard<std::mutex> lock(state_->mutex);
  return state_->volumes.size();
}

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

}  // namespace vistrack
