// On-disk VV cache: bit-identical file round trip, the key, bad files as misses, a second planner
// on the same folder computing nothing, and concurrent use from TBB threads.
#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <regex>
#include <set>

#include "vistrack/error.hpp"
#include "vistrack/orbit.hpp"
#include "vistrack/visibility.hpp"

namespace vt = vistrack;
namespace fs = std::filesystem;

namespace {

vt::Polygon rectangle(double x0, double y0, double x1, double y1) {
  vt::Polygon p;
  p.outer = vt::Ring{vt::Vec2(x0, y0), vt::Vec2(x1, y0), vt::Vec2(x1, y1), vt::Vec2(x0, y1)};
  return p;
}

// Four blocks around a crossing: enough occlusion for non-trivial VVs and radii.
const vt::Environment& city() {
  static const vt::Environment env = vt::Environment::from_buildings({
      {rectangle(-60, -60, -15, -15), 40.0, 0},
      {rectangle(15, -60, 60, -15), 25.0, 1},
      {rectangle(-60, 15, -15, 60), 30.0, 2},
      {rectangle(15, 15, 60, 60), 55.0, 3},
  });
  return env;
}

constexpr double kResolution = 4.0;  // coarse grid: fast tests, same code paths

// A fresh, empty folder under the system temp dir, removed at the end of the test.
struct TempFolder {
  fs::path path;
  explicit TempFolder(const std::string& name) {
    path = fs::temp_directory_path() /
           (std::string("vistrack-") + name + "-" + std::to_string(std::random_device{}()));
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempFolder() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
  std::string file(const std::string& name) const { return (path / name).string(); }
  std::size_t count() const { return std::size_t(std::distance(fs::directory_iterator(path), fs::directory_iterator())); }
};

template <class T>
bool same_bytes(const T* a, const T* b, std::size_t n) {
  return std::memcmp(a, b, n * sizeof(T)) == 0;
}

void expect_bit_identical(const vt::VisibilityVolume& a, const vt::VisibilityVolume& b) {
  EXPECT_TRUE(same_bytes(a.poi.data(), b.poi.data(), 3));
  EXPECT_TRUE(same_bytes(&a.d_max, &b.d_max, 1));
  ASSERT_EQ(a.altitude_band.has_value(), b.altitude_band.has_value());
  if (a.altitude_band) {
    EXPECT_EQ(*a.altitude_band, *b.altitude_band);
  }
  EXPECT_EQ(a.grid.num_elevation, b.grid.num_elevation);
  EXPECT_EQ(a.grid.num_azimuth, b.grid.num_azimuth);
  ASSERT_EQ(a.near.size(), b.near.size());
  ASSERT_EQ(a.far.size(), b.far.size());
  EXPECT_TRUE(same_bytes(a.near.data(), b.near.data(), a.near.size()));
  EXPECT_TRUE(same_bytes(a.far.data(), b.far.data(), a.far.size()));
  ASSERT_EQ(a.mesh.vertices.rows(), b.mesh.vertices.rows());
  ASSERT_EQ(a.mesh.faces.rows(), b.mesh.faces.rows());
  EXPECT_TRUE(same_bytes(a.mesh.vertices.data(), b.mesh.vertices.data(), std::size_t(a.mesh.vertices.size())));
  EXPECT_TRUE(same_bytes(a.mesh.faces.data(), b.mesh.faces.data(), std::size_t(a.mesh.faces.size())));
  EXPECT_TRUE(same_bytes(&a.volume, &b.volume, 1));
  EXPECT_EQ(a.mesh_row_sines, b.mesh_row_sines);  // what the radial XOR path needs
  EXPECT_EQ(a.mesh_triangle_faces, b.mesh_triangle_faces);
}

std::vector<char> file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const std::string& path, const std::vector<char>& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), std::streamsize(bytes.size()));
}

void expect_error_naming(const std::function<void()>& f, const std::vector<std::string>& parts) {
  try {
    f();
    ADD_FAILURE() << "expected vistrack::Error";
  } catch (const vt::Error& e) {
    for (const auto& part : parts) EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

}  // namespace

TEST(VolumeFile, RoundTripIsBitIdentical) {
  const vt::VisibilityScene scene(city());
  TempFolder folder("roundtrip");
  const std::vector<std::optional<std::pair<double, double>>> bands = {std::nullopt, std::make_pair(20.0, 90.0)};
  for (const auto& band : bands) {
    const vt::VisibilityVolume vv = vt::visibility_volume(scene, vt::Vec3(0.3, -1.7, 1.5), 120.0, band, kResolution);
    ASSERT_GT(vv.mesh.faces.rows(), 0);
    const std::string path = folder.file(band ? "band.bin" : "plain.bin");
    vt::write_volume_file(vv, path);
    const std::optional<vt::VisibilityVolume> back = vt::read_volume_file(path);
    ASSERT_TRUE(back.has_value());
    expect_bit_identical(vv, *back);
    // Overwriting goes through a rename too.
    vt::write_volume_file(vv, path);
    expect_bit_identical(vv, *vt::read_volume_file(path));
  }
  EXPECT_EQ(folder.count(), 2u);  // no temporary files left behind
}

// Version 4 and 5 files (the same layout: walls bisected, then aimed, no split at a building's
// foot) are still read. The checksum is recomputed here as the format defines it: FNV-1a-64 over
// 8-byte little-endian words, then the tail byte by byte.
TEST(VolumeFile, OlderVersionsOfTheSameLayoutAreRead) {
  const vt::VisibilityScene scene(city());
  TempFolder folder("older");
  const vt::VisibilityVolume vv = vt::visibility_volume(scene, vt::Vec3(0.3, -1.7, 1.5), 120.0, std::nullopt, kResolution);
  for (const char older : {char(4), char(5)}) {
    const std::string path = folder.file("older.bin");
    vt::write_volume_file(vv, path);
    std::vector<char> bytes = file_bytes(path);
    ASSERT_EQ(bytes[8], char(vt::kVolumeFileVersion));
    bytes[8] = older;
    const std::size_t body = bytes.size() - 8;
    std::uint64_t h = 14695981039346656037ULL;
    std::size_t k = 0;
    for (; k + 8 <= body; k += 8) {
      std::uint64_t word = 0;
      for (int b = 0; b < 8; ++b) word |= std::uint64_t(static_cast<unsigned char>(bytes[k + std::size_t(b)])) << (8 * b);
      h = (h ^ word) * 1099511628211ULL;
    }
    for (; k < body; ++k) h = (h ^ static_cast<unsigned char>(bytes[k])) * 1099511628211ULL;
    for (int b = 0; b < 8; ++b) bytes[body + std::size_t(b)] = char((h >> (8 * b)) & 0xffU);
    write_bytes(path, bytes);
    const std::optional<vt::VisibilityVolume> back = vt::read_volume_file(path);
    ASSERT_TRUE(back.has_value());
    expect_bit_identical(vv, *back);
  }
}

TEST(VolumeFile, MissingIsNulloptAndBadFilesAreErrorsNamingThePath) {
  const vt::VisibilityScene scene(city());
  TempFolder folder("badfiles");
  EXPECT_FALSE(vt::read_volume_file(folder.file("absent.bin")).has_value());

  const std::string good = folder.file("good.bin");
  vt::write_volume_file(vt::visibility_volume(scene, vt::Vec3(0, 0, 1), 80.0, std::nullopt, kResolution), good);
  const std::vector<char> bytes = file_bytes(good);
  ASSERT_GT(bytes.size(), 1000u);

  auto bad = [&](const std::string& name, std::vector<char> content, const std::string& reason) {
    const std::string path = folder.file(name);
    write_bytes(path, content);
    expect_error_naming([&] { vt::read_volume_file(path); }, {path, reason});
    EXPECT_EQ(file_bytes(path), content) << "reading must not modify " << path;
  };
  bad("empty.bin", {}, "bad magic");
  bad("garbage.bin", std::vector<char>(4096, 'x'), "bad magic");
  for (std::size_t cut : {std::size_t(12), std::size_t(40), bytes.size() / 2, bytes.size() - 1}) {
    SCOPED_TRACE(cut);
    bad("truncated.bin", std::vector<char>(bytes.begin(), bytes.begin() + std::ptrdiff_t(cut)), "");
  }
  std::vector<char> flipped = bytes;
  flipped[bytes.size() / 2] = char(flipped[bytes.size() / 2] ^ 0x10);
  bad("flipped.bin", flipped, "checksum");
  std::vector<char> version = bytes;
  version[8] = char(vt::kVolumeFileVersion + 1);
  bad("version.bin", version, "format version");
  // Version 3 files (intervals per cell on rays of their own) are refused in one line naming it.
  version[8] = char(3);
  bad("version3.bin", version, "format version 3, this build reads versions 4 to 6 (version 3 kept intervals per cell");
  // Garbage after a valid magic and version.
  std::vector<char> tail(bytes.begin(), bytes.begin() + 12);
  tail.resize(5000, '\x7f');
  bad("tail.bin", tail, "");
}

TEST(VolumeCacheKey, ChangesWithEveryInputAndOnlyThen) {
  const std::uint64_t fp = 0x1234abcdULL;
  const vt::Vec3 g(10.0, -20.0, 1.5);
  const std::optional<std::pair<double, double>> none;
  const auto key = [](std::uint64_t f, const vt::Vec3& p, double d, std::optional<std::pair<double, double>> band,
                      double res) { return vt::volume_cache_key(f, p, d, band, res); };
  const std::uint64_t base = key(fp, g, 400.0, none, 1.0);
  EXPECT_EQ(base, key(fp, vt::Vec3(10.0, -20.0, 1.5), 400.0, none, 1.0));  // deterministic
  const double up = std::nextafter(10.0, 11.0);
  const std::vector<std::uint64_t> variants = {
      key(fp + 1, g, 400.0, none, 1.0),
      key(fp, vt::Vec3(up, -20.0, 1.5), 400.0, none, 1.0),
      key(fp, vt::Vec3(10.0, std::nextafter(-20.0, 0.0), 1.5), 400.0, none, 1.0),
      key(fp, vt::Vec3(10.0, -20.0, 1.6), 400.0, none, 1.0),
      key(fp, vt::Vec3(-20.0, 10.0, 1.5), 400.0, none, 1.0),  // swapped coordinates
      key(fp, g, 401.0, none, 1.0),
      key(fp, g, 400.0, std::make_pair(0.0, 0.0), 1.0),  // presence alone counts
      key(fp, g, 400.0, std::make_pair(50.0, 300.0), 1.0),
      key(fp, g, 400.0, std::make_pair(50.0, 301.0), 1.0),
      key(fp, g, 400.0, std::make_pair(51.0, 300.0), 1.0),
      key(fp, g, 400.0, none, 0.5),
  };
  std::set<std::uint64_t> distinct(variants.begin(), variants.end());
  distinct.insert(base);
  EXPECT_EQ(distinct.size(), variants.size() + 1);
  // A fixed value: the key must stay stable across runs, builds and hosts (files on disk).
  // Independently computed as FNV-1a-64 over struct.pack('<QQddddQd', 6, 0, 0, 0, 0, 400, 0, 1)
  // (6 = kVolumeFileVersion; versions 4 and 5 gave vv-e7100185431828dd.bin and vv-774b841f327369fc.bin).
  EXPECT_EQ(vt::volume_cache_file_name(key(0, vt::Vec3(0, 0, 0), 400.0, none, 1.0)), "vv-95dd72858c5bfb5b.bin");
  EXPECT_TRUE(std::regex_match(vt::volume_cache_file_name(base), std::regex("vv-[0-9a-f]{16}\\.bin")));
  EXPECT_EQ(vt::volume_cache_file_name(0x1fULL), "vv-000000000000001f.bin");
  // Randomized: different positions never collide in a few thousand draws.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1000.0, 1000.0);
  std::set<std::uint64_t> keys;
  for (int i = 0; i < 5000; ++i) keys.insert(key(fp, vt::Vec3(u(rng), u(rng), 1.5), 400.0, none, 1.0));
  EXPECT_EQ(keys.size(), 5000u);
}

TEST(DiskVolumeCache, BadFilesAreMissesAndGetReplaced) {
  const vt::VisibilityScene scene(city());
  TempFolder folder("misses");
  std::atomic<int> computed{0};
  const vt::VolumeFunction compute = [&](const vt::Vec3& g) {
    ++computed;
    return std::make_shared<const vt::VisibilityVolume>(
        vt::visibility_volume(scene, g, 100.0, std::nullopt, kResolution));
  };
  const vt::DiskVolumeCache disk(folder.path.string(), scene.fingerprint(), 100.0, std::nullopt, kResolution);
  const vt::VolumeFunction cached = disk.wrap(compute);
  const vt::Vec3 g(0.5, 0.25, 1.5);

  const vt::VolumePtr first = cached(g);
  EXPECT_EQ(computed.load(), 1);
  EXPECT_EQ(disk.misses(), 1u);
  EXPECT_TRUE(fs::exists(disk.path(g)));
  const vt::VolumePtr second = cached(g);
  EXPECT_EQ(computed.load(), 1);
  EXPECT_EQ(disk.hits(), 1u);
  expect_bit_identical(*first, *second);

  const std::vector<char> good = file_bytes(disk.path(g));
  const std::vector<std::vector<char>> bad_contents = {
      std::vector<char>(good.begin(), good.begin() + std::ptrdiff_t(good.size() / 3)),  // truncated
      std::vector<char>(777, '\0'),                                                       // garbage
  };
  for (const auto& content : bad_contents) {
    write_bytes(disk.path(g), content);
    const int before = computed.load();
    expect_bit_identical(*first, *cached(g));
    EXPECT_EQ(computed.load(), before + 1);
    EXPECT_EQ(file_bytes(disk.path(g)), good) << "the bad file is replaced by the good one";
  }
  // A valid file holding another position's VV (as after a key collision) is a miss too.
  vt::write_volume_file(*cached(vt::Vec3(3.0, 3.0, 1.5)), disk.path(g));
  const int before = computed.load();
  expect_bit_identical(*first, *cached(g));
  EXPECT_EQ(computed.load(), before + 1);
  EXPECT_EQ(folder.count(), 2u);
}

TEST(DiskVolumeCache, FolderIsCreatedAndAnUnusableOneIsAnErrorNamingCacheDir) {
  TempFolder folder("create");
  const std::string nested = (folder.path / "a" / "b").string();
  vt::Sensor sensor;
  sensor.d_max = 80.0;
  const vt::OrbitPlanner planner(city(), sensor, nested);
  EXPECT_TRUE(fs::is_directory(nested));
  EXPECT_EQ(planner.disk_hits() + planner.disk_misses(), 0u);

  const std::string file = folder.file("plain-file");
  write_bytes(file, {'x'});
  expect_error_naming([&] { vt::OrbitPlanner(city(), sensor, file); }, {"cache_dir", file});
  expect_error_naming([&] { vt::OrbitPlanner(city(), sensor, file + "/sub"); }, {"cache_dir"});
  EXPECT_EQ(file_bytes(file), std::vector<char>{'x'});
}

TEST(DiskVolumeCache, SecondPlannerOnTheSameFolderComputesNothing) {
  TempFolder folder("planner");
  const vt::PoiPath poi((Eigen::MatrixXd(3, 2) << -90, 0, 0, 0, 0, 90).finished(), 5.0);
  vt::Uav uav;
  uav.speed = 20.0;
  uav.min_turn_radius = 5.0;
  uav.altitude = 50.0;
  vt::Sensor sensor;
  sensor.d_max = 100.0;
  sensor.altitude_band = std::make_pair(20.0, 120.0);
  vt::Planning planning;
  planning.spacing = 30.0;
  planning.cutoff = 2e5;
  planning.resolution_deg = kResolution;

  vt::OrbitPlanner cold(city(), sensor, folder.path.string());
  const vt::VisibilityOrbitPlan a = cold.plan(poi, uav, planning);
  EXPECT_GT(a.times.size(), 7u);  // refined beyond the 7 initial samples
  EXPECT_EQ(cold.disk_hits(), 0u);
  EXPECT_EQ(cold.disk_misses(), a.samples.volumes.size());
  EXPECT_EQ(folder.count(), a.samples.volumes.size());

  vt::OrbitPlanner warm(city(), sensor, folder.path.string());
  const vt::VisibilityOrbitPlan b = warm.plan(poi, uav, planning);
  EXPECT_EQ(warm.disk_misses(), 0u);
  EXPECT_EQ(warm.disk_hits(), a.samples.volumes.size());
  EXPECT_EQ(a.times, b.times);
  EXPECT_EQ(a.radii, b.radii);
  EXPECT_EQ(a.max_radii, b.max_radii);
  EXPECT_EQ(a.samples.metric, b.samples.metric);
  for (std::size_t k = 0; k < a.samples.volumes.size(); ++k) expect_bit_identical(*a.samples.volumes[k], *b.samples.volumes[k]);

  // Another d_max misses every file and adds its own.
  vt::Sensor wider = sensor;
  wider.d_max = 110.0;
  vt::OrbitPlanner other(city(), wider, folder.path.string());
  other.plan(poi, uav, planning);
  EXPECT_EQ(other.disk_hits(), 0u);
  EXPECT_GT(other.disk_misses(), 0u);

  // The same plan through plan_orbits(..., cache_dir) hits every file too.
  const vt::VisibilityOrbitPlan c = vt::plan_orbits(city(), poi, uav, sensor, planning, {}, folder.path.string());
  EXPECT_EQ(c.radii, a.radii);
  EXPECT_EQ(c.samples.volumes_computed, a.samples.volumes_computed);  // computed by the memo, read from disk
}

TEST(DiskVolumeCache, ConcurrentUseFromTbbThreads) {
  const vt::VisibilityScene scene(city());
  TempFolder folder("parallel");
  const vt::VolumeFunction compute = [&](const vt::Vec3& g) {
    return std::make_shared<const vt::VisibilityVolume>(
        vt::visibility_volume(scene, g, 90.0, std::nullopt, kResolution));
  };
  // Two caches on one folder stand for two processes: both may write the same file at once.
  const vt::DiskVolumeCache one(folder.path.string(), scene.fingerprint(), 90.0, std::nullopt, kResolution);
  const vt::DiskVolumeCache two(folder.path.string(), scene.fingerprint(), 90.0, std::nullopt, kResolution);
  const vt::VolumeFunction f1 = one.wrap(compute), f2 = two.wrap(compute);
  constexpr int kPositions = 12, kCalls = 96;
  std::vector<vt::Vec3> positions;
  for (int i = 0; i < kPositions; ++i) positions.emplace_back(-80.0 + 13.0 * i, 0.5 * i - 3.0, 1.5);
  std::vector<vt::VolumePtr> results(kCalls);
  tbb::parallel_for(0, kCalls, [&](int call) {
    const vt::Vec3& g = positions[std::size_t(call % kPositions)];
    results[std::size_t(call)] = (call % 2 == 0 ? f1 : f2)(g);
  });
  EXPECT_EQ(one.hits() + one.misses() + two.hits() + two.misses(), std::size_t(kCalls));
  EXPECT_GE(one.misses() + two.misses(), std::size_t(kPositions));
  EXPECT_EQ(folder.count(), std::size_t(kPositions));  // no temporary files left
  for (int call = 0; call < kCalls; ++call) {
    const vt::Vec3& g = positions[std::size_t(call % kPositions)];
    expect_bit_identical(*results[std::size_t(call)], *compute(g));
    expect_bit_identical(*results[std::size_t(call)], *vt::read_volume_file(one.path(g)));
  }
}
