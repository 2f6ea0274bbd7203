// Visibility volumes (section III.D, eq. (4)): analytic volumes, a brute-force oracle for one box
// building, line-of-sight cross-checks, real-city meshes checked with CGAL.
#include "vistrack/visibility.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <random>
#include <sstream>
#include <string>

#include "simd/cpu.hpp"
#include "test_data.hpp"
#include "visibility/corner_scan.hpp"
#include "vistrack/error.hpp"
#include "vistrack/orbit.hpp"
#include "vistrack/volume.hpp"
#include "volume/points_inside.hpp"

namespace vistrack {
namespace {

struct Box {
  Vec3 lo;
  Vec3 hi;
};

void add_box(const Box& b, std::vector<Vec3>& v, std::vector<std::array<int, 3>>& f) {
  const int o = static_cast<int>(v.size());
  for (int k = 0; k < 8; ++k)
    v.emplace_back((k & 1) ? b.hi.x() : b.lo.x(), (k & 2) ? b.hi.y() : b.lo.y(), (k & 4) ? b.hi.z() : b.lo.z());
  // Outward triangles of the 6 faces (corner k: bit0 x, bit1 y, bit2 z).
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    f.push_back({o + q[0], o + q[1], o + q[2]});
    f.push_back({o + q[0], o + q[2], o + q[3]});
  }
}

Environment boxes_env(const std::vector<Box>& boxes) {
  std::vector<Vec3> v;
  std::vector<std::array<int, 3>> f;
  for (const Box& b : boxes) add_box(b, v, f);
  Points3 vertices(static_cast<Eigen::Index>(v.size()), 3);
  for (std::size_t k = 0; k < v.size(); ++k) vertices.row(static_cast<Eigen::Index>(k)) = v[k].transpose();
  Faces faces(static_cast<Eigen::Index>(f.size()), 3);
  for (std::size_t k = 0; k < f.size(); ++k) faces.row(static_cast<Eigen::Index>(k)) << f[k][0], f[k][1], f[k][2];
  return Environment::from_triangles(vertices, faces);
}

// An open field: one small box far outside every query (the environment needs a triangle).
Environment open_field() { return boxes_env({{Vec3(5000, 5000, 0), Vec3(5010, 5010, 5)}}); }

// Exact slab test: does the closed segment p-q meet the closed box?
bool segment_hits_box(const Vec3& p, const Vec3& q, const Box& b) {
  double t0 = 0.0, t1 = 1.0;
  for (int k = 0; k < 3; ++k) {
    const double d = q[k] - p[k];
    if (d == 0.0) {
      if (p[k] < b.lo[k] || p[k] > b.hi[k]) return false;
      continue;
    }
    double a = (b.lo[k] - p[k]) / d, c = (b.hi[k] - p[k]) / d;
    if (a > c) std::swap(a, c);
    t0 = std::max(t0, a);
    t1 = std::min(t1, c);
    if (t0 > t1) return false;
  }
  return true;
}

// Volume of {|p - g| <= r, lo <= z <= hi} for g = (0, 0, gz): integral of pi (r^2 - (z - gz)^2).
double ball_slab_volume(double r, double gz, double lo, double hi) {
  lo = std::max(lo, gz - r);
  hi = std::min(hi, gz + r);
  if (hi <= lo) return 0.0;
  auto primitive = [&](double z) { return r * r * (z - gz) - std::pow(z - gz, 3) / 3.0; };
  return kPi * (primitive(hi) - primitive(lo));
}

void expect_valid(const VisibilityVolume& vv, const std::string& what) {
  const MeshCheck check = check_closed_mesh(vv.mesh);
  EXPECT_TRUE(check.valid()) << what << ": " << check.problem;
  EXPECT_NEAR(check.volume, vv.volume, 1e-6 * std::max(1.0, vv.volume)) << what;
}

TEST(DirectionGrid, CellsTileTheSphere) {
  for (double res : {0.5, 1.0, 2.0, 7.0}) {
    const DirectionGrid grid = DirectionGrid::from_resolution(res);
    EXPECT_EQ(grid.num_elevation % 2, 0) << "a row boundary must lie on the horizon";
    double total = 0.0;
    for (int i = 0; i < grid.num_elevation; ++i) total += grid.solid_angle(i) * grid.num_azimuth;
    EXPECT_NEAR(total, 4.0 * kPi, 1e-9);
    double weights = 0.0;
    for (int i = 0; i <= grid.num_elevation; ++i) weights += grid.corner_weight(i) * grid.num_azimuth;
    EXPECT_NEAR(weights, 4.0 * kPi, 1e-9);
    EXPECT_NEAR(grid.corner(3, 5).norm(), 1.0, 1e-12);
    EXPECT_EQ(grid.num_corners(), grid.size() + static_cast<std::size_t>(grid.num_azimuth));
    EXPECT_NEAR(grid.elevation(0) + grid.elevation(grid.num_elevation - 1), 0.0, 1e-12);
  }
  EXPECT_THROW(DirectionGrid::from_resolution(0.0), Error);
  EXPECT_THROW(DirectionGrid::from_resolution(std::nan("")), Error);
  EXPECT_THROW(DirectionGrid::from_resolution(90.0), Error);
}

// The volume of a VV without a band by brute force, independent of the VV's code: one ray per
// cell of a 0.2-degree grid through a point staggered inside it (Weyl sequences), min(first hit,
// exact ground plane, d_max), summed with the cells' solid angles.
double fine_reference_volume(const VisibilityScene& scene, const Vec3& g, double d_max) {
  const DirectionGrid grid = DirectionGrid::from_resolution(0.2);
  const int ne = grid.num_elevation, na = grid.num_azimuth;
  Points3 dirs(static_cast<Eigen::Index>(grid.size()), 3);
  for (int i = 0; i < ne; ++i) {
    const double x = std::fmod(0.5 + 0.7548776662466927 * i, 1.0);
    const double lo = std::sin(-kPi / 2 + i * kPi / ne), hi = std::sin(-kPi / 2 + (i + 1) * kPi / ne);
    for (int j = 0; j < na; ++j) {
      const double sin_el = lo + std::fmod(0.5 + 0.5698402909980532 * j, 1.0) * (hi - lo);
      const double cos_el = std::sqrt(1.0 - sin_el * sin_el), az = (j + x) * kTwoPi / na;
      dirs.row(i * na + j) << cos_el * std::cos(az), cos_el * std::sin(az), sin_el;
    }
  }
  const std::vector<double> hits = scene.first_hits(g, dirs, d_max);
  double total = 0.0;
  for (int i = 0; i < ne; ++i)
    for (int j = 0; j < na; ++j) {
      const double dz = dirs(i * na + j, 2);
      double far = std::min(hits[static_cast<std::size_t>(i * na + j)], d_max);
      if (dz < 0.0) far = std::min(far, std::max(0.0, (scene.ground_level() - g.z()) / dz));
      total += grid.solid_angle(i) * far * far * far / 3.0;
    }
  return total;
}

// Corner (i, j) lies at elevation -pi/2 + i d_el and azimuth j d_az; the horizon and the poles exactly.
TEST(DirectionGrid, CornersLieOnTheCellBoundaries) {
  const DirectionGrid grid = DirectionGrid::from_resolution(1.0);
  const double d_el = kPi / grid.num_elevation, d_az = kTwoPi / grid.num_azimuth;
  for (int i : {1, 7, 90, 179}) {
    for (int j : {0, 13, 359}) {
      const Vec3 d = grid.corner(i, j);
      EXPECT_NEAR(d.norm(), 1.0, 1e-12);
      EXPECT_NEAR(std::asin(d.z()), -kPi / 2 + i * d_el, 1e-9);
      EXPECT_NEAR(std::atan2(d.y(), d.x()), std::remainder(j * d_az, kTwoPi), 1e-9);
    }
  }
  EXPECT_EQ(grid.corner(grid.num_elevation / 2, 17).z(), 0.0);
  EXPECT_EQ(grid.corner(0, 17), Vec3(0, 0, -1));
  EXPECT_EQ(grid.corner(grid.num_elevation, 17), Vec3(0, 0, 1));
}

TEST(CpuCheck, ScalarKernelsVariableTurnsAvx2Off) {
  // VISTRACK_SCALAR_KERNELS=1 keeps the plain loops (how the kernels are timed); unset or 0, the
  // AVX2 kernels run where the CPU has them.
  const char* saved = std::getenv("VISTRACK_SCALAR_KERNELS");
  const std::string kept = saved != nullptr ? saved : "";
  ::unsetenv("VISTRACK_SCALAR_KERNELS");
  const bool has_avx2 = detail::avx2_kernel_available();
  ::setenv("VISTRACK_SCALAR_KERNELS", "0", 1);
  EXPECT_EQ(detail::avx2_kernel_available(), has_avx2);
  ::setenv("VISTRACK_SCALAR_KERNELS", "1", 1);
  EXPECT_FALSE(detail::avx2_kernel_available());
  if (saved != nullptr) ::setenv("VISTRACK_SCALAR_KERNELS", kept.c_str(), 1);
  else ::unsetenv("VISTRACK_SCALAR_KERNELS");
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
  EXPECT_EQ(has_avx2, static_cast<bool>(__builtin_cpu_supports("avx2")));
#endif
}

TEST(CornerScan, Avx2KernelIsBitIdenticalToScalar) {
  // corner_hits scans runs of a row four columns per AVX2 instruction where the CPU has it; every
  // column must round and decide exactly as the scalar loop. Random triangles' coefficients over
  // runs of 1 to 23 columns (tails of every length), repeated runs (a tie keeps the earlier owner),
  // negative offsets, floors that cut some hits, and NaN coefficients (no hit).
  if (!detail::avx2_kernel_available()) GTEST_SKIP() << "this CPU has no AVX2: only the scalar loop runs";
  constexpr int kColumns = 360;
  std::vector<double> cos_az(kColumns), sin_az(kColumns);
  for (int j = 0; j < kColumns; ++j) {
    cos_az[static_cast<std::size_t>(j)] = std::cos(2.0 * kPi * j / kColumns);
    sin_az[static_cast<std::size_t>(j)] = std::sin(2.0 * kPi * j / kColumns);
  }
  std::mt19937_64 rng(35);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> column(0, kColumns - 1), length(1, 23);
  std::vector<double> w_scalar(kColumns, 0.0), w_avx2(kColumns, 0.0);
  std::vector<std::uint32_t> owner_scalar(kColumns, 7u), owner_avx2(kColumns, 7u);
  std::size_t taken = 0;
  for (std::uint32_t run = 0; run < 20000; ++run) {
    std::array<double, 4> a{}, b{}, c{};
    for (std::size_t e = 0; e < 4; ++e) {
      a[e] = unit(rng);
      b[e] = unit(rng);
      c[e] = 0.3 * unit(rng) + (e < 3 ? 0.2 : 0.0);
    }
    if (run % 97 == 0) a[run % 4] = std::numeric_limits<double>::quiet_NaN();
    const double inv_offset = 1.0 / (run % 5 == 0 ? -(1.0 + unit(rng)) : 1.0 + unit(rng) + 0.01);
    const double w_min = run % 3 == 0 ? 0.5 * std::abs(unit(rng)) : 0.0;
    const int first = column(rng), last = std::min(kColumns - 1, first + length(rng) - 1);
    for (int repeat = 0; repeat < (run % 11 == 0 ? 2 : 1); ++repeat) {
      const std::uint32_t owner = 2 * run + static_cast<std::uint32_t>(repeat);
      detail::scan_run(cos_az.data(), sin_az.data(), first, last, a.data(), b.data(), c.data(), inv_offset, w_min, owner,
                       w_scalar.data(), owner_scalar.data());
      detail::scan_run_avx2(cos_az.data(), sin_az.data(), first, last, a.data(), b.data(), c.data(), inv_offset, w_min,
                            owner, w_avx2.data(), owner_avx2.data());
    }
    for (int j = 0; j < kColumns; ++j) {
      const auto k = static_cast<std::size_t>(j);
      ASSERT_EQ(std::memcmp(&w_scalar[k], &w_avx2[k], sizeof(double)), 0) << "run " << run << " column " << j;
      ASSERT_EQ(owner_scalar[k], owner_avx2[k]) << "run " << run << " column " << j;
    }
    if (run % 500 == 499) {
      // Start over now and then, so that later runs still find columns to take.
      taken += static_cast<std::size_t>(std::count_if(w_scalar.begin(), w_scalar.end(), [](double w) { return w > 0.0; }));
      std::fill(w_scalar.begin(), w_scalar.end(), 0.0);
      std::fill(w_avx2.begin(), w_avx2.end(), 0.0);
    }
  }
  EXPECT_GT(taken, 1000u);  // the runs did take hits
}

// vv.far[k] is the distance along grid.corner(i, j): the VV computes its rays with trig tables,
// DirectionGrid::corner directly; a wall x = 40 facing g checks both angles.
TEST(VisibilityVolume, IntervalsLieAlongTheGridsCorners) {
  const VisibilityScene scene(boxes_env({{Vec3(40, -20, 0), Vec3(60, 20, 30)}}));
  const VisibilityVolume vv = visibility_volume(scene, Vec3(0, 0, 0.5), 200.0, std::nullopt, 1.0);
  int checked = 0;
  for (int i = 0; i <= vv.grid.num_elevation; ++i)
    for (int j = 0; j < vv.grid.num_azimuth; ++j) {
      const Vec3 d = vv.grid.corner(i, j);
      if (!(d.x() > 0.0)) continue;
      const double t = 40.0 / d.x();
      const Vec3 hit = Vec3(0, 0, 0.5) + t * d;
      if (std::abs(hit.y()) > 19.0 || hit.z() < 1.0 || hit.z() > 29.0) continue;  // well inside the face
      EXPECT_NEAR(vv.far[static_cast<std::size_t>(i) * vv.grid.num_azimuth + j], t, 1e-3) << i << ", " << j;
      ++checked;
    }
  EXPECT_GT(checked, 500);
}

// At a silhouette the corner mesh gets a radial wall where bisection puts the jump, and the crease
// where the ground meets the d_max sphere just below the horizon gets its own vertex row: the mesh
// then holds the same volume as a fine grid (without walls it held 0.5-1.4 % less here, and a
// Charlotte VV 0.2-2.4 % less; without the crease row 0.2 % less).
TEST(VisibilityVolume, WallsAndCreasesKeepTheMeshVolume) {
  const VisibilityScene scene(boxes_env({{Vec3(40, -20, 0), Vec3(60, 20, 30)},
                                         {Vec3(-50, 30, 0), Vec3(-10, 80, 70)},
                                         {Vec3(-80, -90, 0), Vec3(-20, -40, 15)}}));
  for (const Vec3& g : {Vec3(0, 0, 0.5), Vec3(10, -30, 2.0), Vec3(-30, 0, 0.5)}) {
    const double reference = fine_reference_volume(scene, g, 200.0);
    for (double res : {2.0, 1.0}) {
      const VisibilityVolume vv = visibility_volume(scene, g, 200.0, std::nullopt, res);
      expect_valid(vv, "walls");
      EXPECT_NEAR(vv.volume / reference, 1.0, 1e-3) << "g " << g.transpose() << " res " << res;
    }
  }
}

// with_mesh = false: the same intervals and volume to the bit (walls and split slots summed from
// points computed in place of stored), a star VV and a shell; what reads the mesh refuses it.
TEST(VisibilityVolume, VolumeWithoutMeshIsTheMeshs) {
  const VisibilityScene scene(boxes_env({{Vec3(40, -20, 0), Vec3(60, 20, 30)},
                                         {Vec3(-50, 30, 0), Vec3(-10, 80, 70)},
                                         {Vec3(-80, -90, 0), Vec3(-20, -40, 15)}}));
  for (const auto& band : {std::optional<std::pair<double, double>>{}, std::optional(std::make_pair(0.0, 40.0)),
                           std::optional(std::make_pair(20.0, 60.0))}) {
    for (const Vec3& g : {Vec3(0, 0, 0.5), Vec3(10, -30, 2.0)}) {
      const VisibilityVolume meshed = visibility_volume(scene, g, 200.0, band, 1.0);
      const VisibilityVolume bare = visibility_volume(scene, g, 200.0, band, 1.0, false);
      EXPECT_TRUE(meshed.has_mesh);
      EXPECT_FALSE(bare.has_mesh);
      EXPECT_GT(meshed.volume, 0.0);
      EXPECT_EQ(bare.volume, meshed.volume) << "g " << g.transpose();
      EXPECT_EQ(bare.far, meshed.far);
      EXPECT_EQ(bare.near, meshed.near);
      EXPECT_EQ(bare.mesh.faces.rows(), 0);
      EXPECT_TRUE(bare.mesh_triangle_faces.empty());
    }
  }
  const VisibilityVolume bare = visibility_volume(scene, Vec3(0, 0, 0.5), 200.0, std::nullopt, 1.0, false);
  try {
    (void)visibility_polygon(bare, 10.0);
    ADD_FAILURE() << "a VV without its mesh was sliced";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("vv: a VV computed without its mesh"), std::string::npos) << e.what();
  }
}

// Open field: the VV is the ball of radius d_max cut by the ground and the band (analytic).
TEST(VisibilityVolume, OpenFieldMatchesAnalyticVolume) {
  const VisibilityScene scene(open_field());
  struct Case {
    Vec3 g;
    std::optional<std::pair<double, double>> band;
  };
  const std::vector<Case> cases = {
      {Vec3(0, 0, 0), std::nullopt},             // POI on the ground: half ball
      {Vec3(0, 0, 0), std::make_pair(50.0, 200.0)},  // band above the POI: near > 0
      {Vec3(0, 0, 30), std::nullopt},            // POI above the ground: ball cut below
      {Vec3(0, 0, 0), std::make_pair(0.0, 100.0)},   // band from the ground
      {Vec3(0, 0, 20), std::make_pair(10.0, 250.0)},  // POI inside the band
      {Vec3(0, 0, 20), std::make_pair(10.0, 60.0)},   // a thin band around the POI
      {Vec3(0, 0, 100), std::make_pair(20.0, 60.0)},  // band below the POI
  };
  const double r = 400.0;
  double largest = 0.0;
  for (const Case& c : cases) {
    const VisibilityVolume vv = visibility_volume(scene, c.g, r, c.band, 1.0);
    const double lo = c.band ? c.band->first : 0.0;
    const double hi = c.band ? c.band->second : 1e9;
    const double exact = ball_slab_volume(r, c.g.z(), std::max(lo, 0.0), hi);
    const std::string what = "g.z " + std::to_string(c.g.z()) + (c.band ? " band " + std::to_string(c.band->first) : "");
    // The issue asks for 0.5%; the mesh (vertex rows on the caps' rims) does 0.1%. The grid's
    // trapezoid rule cuts rims across a cell, and for a POI on the ground gives the half row
    // below the horizon the horizon's d_max: 2.3 % with the band from the ground.
    EXPECT_NEAR(vv.volume / exact, 1.0, 0.001) << what;
    largest = std::max(largest, std::abs(vv.volume / exact - 1.0));
    EXPECT_NEAR(vv.grid_volume() / exact, 1.0, 0.03) << what;
    expect_valid(vv, what);
    EXPECT_EQ(vv.near.size(), vv.grid.num_corners());
    // Band caps carry exact z: every vertex lies inside the band and the ground.
    EXPECT_GE(vv.mesh.vertices.col(2).minCoeff(), std::max(lo, 0.0) - 1e-9) << what;
    EXPECT_LE(vv.mesh.vertices.col(2).maxCoeff(), std::min(hi, c.g.z() + r) + 1e-9) << what;
  }
  std::cout << "open field, 1 degree: largest |volume / exact - 1| = " << 100.0 * largest << " %\n";  // docs/tracking.md
}

TEST(VisibilityVolume, NearIsPositiveWhenTheBandStartsAboveThePoi) {
  const VisibilityVolume vv = visibility_volume(open_field(), Vec3(0, 0, 0), 300.0, std::make_pair(50.0, 100.0), 2.0);
  const int row = vv.grid.num_elevation - 1;  // looking nearly straight up: visible from z = 50 to 100
  const std::size_t k = static_cast<std::size_t>(row) * vv.grid.num_azimuth;
  const double s = vv.grid.corner(row, 0).z();
  EXPECT_NEAR(vv.near[k], 50.0 / s, 1e-9);
  EXPECT_NEAR(vv.far[k], 100.0 / s, 1e-9);
  // Looking down or along the ground: nothing.
  EXPECT_TRUE(vv.empty(0));
  EXPECT_TRUE(vv.empty(static_cast<std::size_t>(vv.grid.num_elevation / 2 - 1) * vv.grid.num_azimuth));
  EXPECT_TRUE(vv.empty(static_cast<std::size_t>(vv.grid.num_elevation / 2) * vv.grid.num_azimuth));
}

TEST(VisibilityVolume, BandOutOfReachGivesAnEmptyVolume) {
  const VisibilityVolume vv = visibility_volume(open_field(), Vec3(0, 0, 0), 100.0, std::make_pair(200.0, 300.0), 2.0);
  EXPECT_EQ(vv.mesh.faces.rows(), 0);
  EXPECT_EQ(vv.volume, 0.0);
  EXPECT_EQ(vv.grid_volume(), 0.0);
  EXPECT_TRUE(visibility_polygon(vv, 250.0).empty());
}

TEST(VisibilityVolume, BadInputNamesTheField) {
  const Box box{Vec3(40, -20, 0), Vec3(60, 20, 30)};
  const VisibilityScene scene(boxes_env({box}));
  auto message = [&](auto&& call) {
    try {
      call();
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message([&] { visibility_volume(scene, Vec3(50, 0, 10), 100.0); }).find("inside an obstacle"), std::string::npos);
  EXPECT_NE(message([&] { visibility_volume(scene, Vec3(0, 0, -1), 100.0); }).find("g[2]"), std::string::npos);
  EXPECT_NE(message([&] { visibility_volume(scene, Vec3(0, std::nan(""), 0), 100.0); }).find("g[1]"), std::string::npos);
  EXPECT_NE(message([&] { visibility_volume(scene, Vec3(0, 0, 0), 0.0); }).find("d_max"), std::string::npos);
  EXPECT_NE(message([&] { visibility_volume(scene, Vec3(0, 0, 0), std::nan("")); }).find("d_max"), std::string::npos);
  EXPECT_NE(message([&] { visibility_volume(scene, Vec3(0, 0, 0), 100.0, std::make_pair(50.0, 20.0)); }).find("altitude_band"),
            std::string::npos);
  EXPECT_NE(message([&] { visibility_volume(scene, Vec3(0, 0, 0), 100.0, std::make_pair(std::nan(""), 20.0)); })
                .find("altitude_band[0]"),
            std::string::npos);
  EXPECT_NE(message([&] { visibility_volume(scene, Vec3(0, 0, 0), 100.0, std::nullopt, -1.0); }).find("resolution_deg"),
            std::string::npos);
  Points3 pois(2, 3);
  pois << 0, 0, 0, 50, 0, 5;
  EXPECT_NE(message([&] { visibility_volumes(scene, pois, 100.0); }).find("pois[1]"), std::string::npos);
}

// One box building: the VP at an altitude against dense plane points tested exactly.
TEST(VisibilityVolume, BoxBuildingPolygonMatchesBruteForce) {
  const Box box{Vec3(40, -20, 0), Vec3(60, 20, 30)};
  const VisibilityScene scene(boxes_env({box}));
  const Vec3 g(0, 0, 0);
  const double d_max = 200.0;
  const VisibilityVolume vv = visibility_volume(scene, g, d_max, std::nullopt, 0.5);
  expect_valid(vv, "box");
  for (double h : {20.0, 50.0, 100.0}) {
    const std::vector<Polygon> vp = visibility_polygon(vv, h);
    ASSERT_EQ(vp.size(), 1u) << "h " << h;
    long both = 0, either = 0;
    for (double x = -d_max; x <= d_max; x += 1.0)
      for (double y = -d_max; y <= d_max; y += 1.0) {
        const Vec3 p(x + 0.37, y + 0.61, h);
        const bool truth = (p - g).norm() <= d_max && !segment_hits_box(g, p, box);
        const bool ours = contains(vp[0], p.head<2>());
        both += truth && ours;
        either += truth || ours;
      }
    const double iou = static_cast<double>(both) / static_cast<double>(either);
    EXPECT_GE(iou, 0.99) << "h " << h;
  }
  // MaxRadius: below the roof the nearest boundary is the wall x = 40; above it the shadow
  // starts where the ray over the near roof edge (40, y, 30) reaches h: x = 40 h / 30.
  const double cell = 0.5 * kPi / 180.0;
  EXPECT_NEAR(max_inscribed_radius(visibility_polygon(vv, 20.0), g.head<2>()), 40.0, 1e-3);
  for (double h : {50.0, 90.0}) {
    const double exact = 40.0 * h / 30.0;
    EXPECT_NEAR(max_inscribed_radius(visibility_polygon(vv, h), g.head<2>()), exact, exact * cell) << "h " << h;
  }
}

// A jump's wall is aimed at the occluding triangle's edge (two rays pin it to 1e-4 of a grid edge)
// instead of bisected to 1/64: the shadow of a box's vertical edge in a slice lies on the vertical
// plane through g and the edge, to 1e-5 rad at 1 degree (bisection left up to 1.4e-4 rad).
TEST(VisibilityVolume, WallsSitOnTheSilhouette) {
  const Box box{Vec3(40, -20, 0), Vec3(60, 20, 30)};
  const VisibilityScene scene(boxes_env({box}));
  const Vec3 g(0, 0, 0.5);
  const VisibilityVolume vv = visibility_volume(scene, g, 200.0, std::nullopt, 1.0);
  expect_valid(vv, "box");
  const std::vector<Polygon> vp = visibility_polygon(vv, 20.0);
  ASSERT_EQ(vp.size(), 1u);
  int on_shadow = 0;
  for (const Vec2& p : vp[0].outer) {
    const double distance = (p - g.head<2>()).norm(), azimuth = std::atan2(p.y() - g.y(), p.x() - g.x());
    if (distance < 50.0 || distance > 150.0) continue;  // past the near wall (44.7 m), short of d_max
    for (double edge : {std::atan2(20.0, 40.0), std::atan2(-20.0, 40.0)})
      if (std::abs(azimuth - edge) < 0.5 * kPi / 180.0) {
        EXPECT_NEAR(azimuth, edge, 1e-5) << "vertex " << p.transpose();
        ++on_shadow;
      }
  }
  EXPECT_GE(on_shadow, 2);  // both shadow lines were looked at
}

TEST(LineOfSight, MatchesExactSegmentBoxTest) {
  const std::vector<Box> boxes = {{Vec3(40, -20, 0), Vec3(60, 20, 30)}, {Vec3(-50, 30, 0), Vec3(-10, 80, 70)}};
  const Environment env = boxes_env(boxes);
  const VisibilityScene scene(env);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> xy(-120.0, 120.0), z(0.0, 100.0);
  const int n = 20000;
  Points3 a(n, 3), b(n, 3);
  for (int k = 0; k < n; ++k) {
    a.row(k) << xy(rng), xy(rng), z(rng);
    b.row(k) << xy(rng), xy(rng), z(rng);
  }
  const std::vector<bool> visible = scene.line_of_sight(a, b);
  const std::vector<bool> reverse = scene.line_of_sight(b, a);
  int checked = 0, agree = 0;
  for (int k = 0; k < n; ++k) {
    const Vec3 p = a.row(k).transpose(), q = b.row(k).transpose();
    bool blocked = false, inside_end = false;
    for (const Box& box : boxes) {
      blocked = blocked || segment_hits_box(p, q, box);
      for (const Vec3& e : {p, q})
        inside_end = inside_end || ((e.array() >= box.lo.array() - 1e-2).all() && (e.array() <= box.hi.array() + 1e-2).all());
    }
    if (inside_end) continue;  // endpoints inside a building: not a meaningful query
    ++checked;
    agree += visible[k] == !blocked;
    EXPECT_EQ(visible[k], reverse[k]) << k;
  }
  EXPECT_GT(checked, n / 2);
  // Grazing segments (touching an edge within float precision) may go either way.
  EXPECT_GE(agree, checked - 3);
  EXPECT_EQ(line_of_sight(env, a.topRows(100), b.topRows(100)), std::vector<bool>(visible.begin(), visible.begin() + 100));
  EXPECT_THROW(scene.line_of_sight(a.topRows(3), b.topRows(2)), Error);
}

// Points well inside or outside the VV (every neighbour one grid step away agrees) must agree with
// a direct line-of-sight query.
void cross_check_with_line_of_sight(const VisibilityScene& scene, const VisibilityVolume& vv, std::uint64_t seed,
                                    int samples) {
  const double step = kPi / vv.grid.num_elevation;
  const Vec3 g = vv.poi;
  const double ground = scene.ground_level();
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Vec3> points;
  while (static_cast<int>(points.size()) < samples) {
    const Vec3 p = g + vv.d_max * 1.05 * Vec3(unit(rng), unit(rng), unit(rng));
    if (p.z() >= ground) points.push_back(p);
  }
  auto truth_of = [&](const std::vector<Vec3>& ps) {
    Points3 a(static_cast<Eigen::Index>(ps.size()), 3), b(static_cast<Eigen::Index>(ps.size()), 3);
    for (std::size_t k = 0; k < ps.size(); ++k) {
      a.row(static_cast<Eigen::Index>(k)) = g.transpose();
      b.row(static_cast<Eigen::Index>(k)) = ps[k].transpose();
    }
    const std::vector<bool> los = scene.line_of_sight(a, b);
    std::vector<bool> truth(ps.size());
    for (std::size_t k = 0; k < ps.size(); ++k) {
      const bool band = !vv.altitude_band || (ps[k].z() >= vv.altitude_band->first && ps[k].z() <= vv.altitude_band->second);
      truth[k] = los[k] && (ps[k] - g).norm() <= vv.d_max && band && ps[k].z() >= ground;
    }
    return truth;
  };
  // Neighbours up to one step away: a 5 x 5 pattern of half steps in azimuth and elevation (thin
  // occluders such as canopy slabs fit between whole steps), and one step in range.
  std::vector<std::array<double, 3>> offsets = {{0, 0, 0}, {step, 0, 0}, {-step, 0, 0}};
  for (int a = -2; a <= 2; ++a)
    for (int e = -2; e <= 2; ++e)
      if (a != 0 || e != 0) offsets.push_back({0, 0.5 * a * step, 0.5 * e * step});
  std::vector<Vec3> neighbours;
  for (const Vec3& p : points) {
    const Vec3 d = p - g;
    const double r = d.norm(), az = std::atan2(d.y(), d.x()), el = std::asin(d.z() / r);
    for (const auto& [dr, daz, del] : offsets) {
      const double rr = r * (1.0 + dr), aa = az + daz, ee = std::clamp(el + del, -kPi / 2, kPi / 2);
      neighbours.push_back(g + rr * Vec3(std::cos(ee) * std::cos(aa), std::cos(ee) * std::sin(aa), std::sin(ee)));
    }
  }
  const std::vector<bool> truth = truth_of(neighbours);
  const std::size_t kNeighbours = offsets.size();
  Points3 query(static_cast<Eigen::Index>(points.size()), 3);
  for (std::size_t k = 0; k < points.size(); ++k) query.row(static_cast<Eigen::Index>(k)) = points[k].transpose();
  const std::vector<bool> inside = detail::points_inside(vv.mesh, query);
  int clear = 0, agree = 0, visible = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    bool same = true;
    for (std::size_t n = 1; n < kNeighbours; ++n) same = same && truth[kNeighbours * k + n] == truth[kNeighbours * k];
    if (!same) continue;
    ++clear;
    visible += truth[kNeighbours * k];
    agree += inside[k] == truth[kNeighbours * k];
    EXPECT_EQ(inside[k], truth[kNeighbours * k]) << "point " << points[k].transpose() << " poi " << g.transpose();
  }
  EXPECT_GT(clear, samples / 2);
  EXPECT_GT(visible, clear / 20);
  EXPECT_EQ(agree, clear);
}

TEST(VisibilityVolume, InsideTestAgreesWithLineOfSightBox) {
  const VisibilityScene scene(boxes_env({{Vec3(40, -20, 0), Vec3(60, 20, 30)}, {Vec3(-50, 30, 0), Vec3(-10, 80, 70)}}));
  cross_check_with_line_of_sight(scene, visibility_volume(scene, Vec3(0, 0, 0), 200.0, std::nullopt, 1.0), 1, 3000);
  cross_check_with_line_of_sight(scene, visibility_volume(scene, Vec3(0, 0, 0), 200.0, std::make_pair(20.0, 90.0), 1.0),
                                 2, 3000);
}

TEST(VisibilityVolume, BatchEqualsSingleAndIsDeterministic) {
  const VisibilityScene scene(boxes_env({{Vec3(40, -20, 0), Vec3(60, 20, 30)}}));
  Points3 pois(6, 3);
  pois << 0, 0, 0, 10, 50, 0, -30, -30, 2, 100, 0, 0.5, 0, 90, 0, -80, 10, 1;
  const auto batch = visibility_volumes(scene, pois, 150.0, std::make_pair(10.0, 80.0), 2.0);
  ASSERT_EQ(batch.size(), 6u);
  for (Eigen::Index k = 0; k < pois.rows(); ++k) {
    const VisibilityVolume one = visibility_volume(scene, pois.row(k).transpose(), 150.0, std::make_pair(10.0, 80.0), 2.0);
    EXPECT_EQ(one.volume, batch[static_cast<std::size_t>(k)].volume);
    EXPECT_EQ(one.far, batch[static_cast<std::size_t>(k)].far);
    EXPECT_TRUE(one.mesh.faces == batch[static_cast<std::size_t>(k)].mesh.faces);
  }
}

// One VV alone is spread over the TBB threads (rays in chunks of 64 at fixed offsets, mesh rows
// counted and then filled): the result must not depend on how many threads there are.
TEST(VisibilityVolume, ResultsDoNotDependOnTheThreadCount) {
  const VisibilityScene scene(boxes_env({{Vec3(40, -20, 0), Vec3(60, 20, 30)},
                                         {Vec3(-50, 30, 0), Vec3(-10, 80, 70)},
                                         {Vec3(-80, -90, 0), Vec3(-20, -40, 15)}}));
  const std::vector<Vec3> pois = {Vec3(0, 0, 0), Vec3(-30, 10, 1), Vec3(10, -60, 0.5)};
  for (const Vec3& g : pois)
    for (const auto& band : {std::optional<std::pair<double, double>>{}, std::optional(std::make_pair(5.0, 60.0)),
                             std::optional(std::make_pair(-1.0, 40.0))}) {
      const VisibilityVolume threads = visibility_volume(scene, g, 150.0, band, 1.0);
      VolumeCost cost;
      const VisibilityVolume serial = visibility_volume_with_cost(scene, g, 150.0, band, 1.0, cost, false);
      VisibilityVolume one_thread;
      {
        tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
        one_thread = visibility_volume(scene, g, 150.0, band, 1.0);
      }
      for (const VisibilityVolume* other : std::array<const VisibilityVolume*, 2>{&serial, &one_thread}) {
        EXPECT_EQ(threads.volume, other->volume);
        EXPECT_EQ(threads.near, other->near);
        EXPECT_EQ(threads.far, other->far);
        EXPECT_TRUE(threads.mesh.vertices == other->mesh.vertices);
        EXPECT_TRUE(threads.mesh.faces == other->mesh.faces);
      }
      EXPECT_GT(cost.rays_traced + cost.rays_skipped, 0u);
    }
}

TEST(VisibilityVolume, SavesObjAndPly) {
  const VisibilityVolume vv = visibility_volume(open_field(), Vec3(0, 0, 0), 100.0, std::nullopt, 10.0);
  const auto dir = std::filesystem::temp_directory_path();
  for (const std::string name : {"vistrack_vv_test.obj", "vistrack_vv_test.ply"}) {
    const std::string path = (dir / name).string();
    vv.save(path);
    const Environment back = Environment::from_mesh(path);
    EXPECT_EQ(back.num_triangles(), static_cast<std::size_t>(vv.mesh.faces.rows())) << name;
    std::filesystem::remove(path);
  }
  EXPECT_THROW(vv.save((dir / "vv.stl").string()), Error);
  EXPECT_THROW(vv.save("/nonexistent-dir/vv.obj"), Error);
}

// Oracle: every grid corner's interval equals the one brute-force ray casting (first_hits along
// DirectionGrid::corner, obstacles and ground, then d_max, the exact ground plane and the band)
// gives. A ray grazing a
// surface may go either way in floats: at most 0.3 % of the corners may differ.
void expect_brute_force_intervals(const VisibilityScene& scene, const VisibilityVolume& vv) {
  const DirectionGrid& grid = vv.grid;
  Points3 dirs(static_cast<Eigen::Index>(grid.num_corners()), 3);
  for (int i = 0; i <= grid.num_elevation; ++i)
    for (int j = 0; j < grid.num_azimuth; ++j) dirs.row(i * grid.num_azimuth + j) = grid.corner(i, j).transpose();
  const std::vector<double> hits = scene.first_hits(vv.poi, dirs, vv.d_max);
  const Vec3& g = vv.poi;
  const bool on_surface = std::abs(g.z() - scene.surface_height(g.head<2>())) < 1e-6;
  std::size_t differ = 0, compared = 0;
  for (std::size_t k = 0; k < grid.num_corners(); ++k) {
    const double dz = dirs(static_cast<Eigen::Index>(k), 2);
    if (on_surface && std::abs(dz) < 1e-9) continue;  // along the surface g stands on
    double near = 0.0, far = std::min(hits[k], vv.d_max);
    if (dz < 0.0) far = std::min(far, std::max(0.0, (scene.ground_level() - g.z()) / dz));  // exact ground plane
    if (vv.altitude_band) {
      const auto [lo, hi] = *vv.altitude_band;
      if (std::abs(g.z() - lo) < 1e-3 || std::abs(g.z() - hi) < 1e-3) continue;  // g on a band face
      if (dz != 0.0) {
        const double a = (lo - g.z()) / dz, b = (hi - g.z()) / dz;
        near = std::max(near, std::min(a, b));
        far = std::min(far, std::max(a, b));
      } else if (g.z() < lo || g.z() > hi) {
        far = 0.0;
      }
    }
    const bool empty = !(far > near);
    const double tolerance = 1e-3 + 1e-4 * vv.d_max;
    ++compared;
    if (empty != vv.empty(k) || (!empty && (std::abs(near - vv.near[k]) > tolerance || std::abs(far - vv.far[k]) > tolerance)))
      ++differ;
  }
  EXPECT_GT(compared, grid.num_corners() / 2);
  EXPECT_LE(static_cast<double>(differ), 0.003 * static_cast<double>(compared))
      << differ << " of " << compared << " corner intervals differ from brute force, g " << g.transpose();
}

// Seeded random POIs, bands (below, around and above the POI), ranges and resolutions: every VV
// mesh is valid, its volume is close to the grid's, and no visible interval exceeds d_max.
void random_volumes_are_valid(const Environment& env, int count, std::uint64_t seed) {
  const VisibilityScene scene(env);
  std::mt19937_64 rng(seed);
  const Bounds3 box = scene.bounds();
  std::uniform_real_distribution<double> x(box.min.x(), box.max.x()), y(box.min.y(), box.max.y()), unit(0.0, 1.0);
  const std::vector<double> lifts = {0.0, 0.5, 3.0, 20.0};
  const std::vector<double> resolutions = {2.0, 3.0, 5.0};
  int made = 0;
  while (made < count) {
    Vec3 g(x(rng), y(rng), 0.0);
    g.z() = scene.surface_height(g.head<2>()) + lifts[rng() % lifts.size()];
    if (scene.inside_obstacle(g)) continue;
    const double d_max = 30.0 + 470.0 * unit(rng);
    std::optional<std::pair<double, double>> band;
    if (unit(rng) > 0.3) band = std::make_pair(g.z() - 10.0 + 60.0 * unit(rng), g.z() + 60.0 + 240.0 * unit(rng));
    const double res = resolutions[rng() % resolutions.size()];
    const VisibilityVolume vv = visibility_volume(scene, g, d_max, band, res);
    ++made;
    for (double f : vv.far) ASSERT_LE(f, d_max);
    expect_brute_force_intervals(scene, vv);
    if (vv.mesh.faces.rows() == 0) continue;
    std::ostringstream what;
    what << "g " << g.transpose() << " d_max " << d_max << " band " << (band ? band->first : -1) << " "
         << (band ? band->second : -1);
    expect_valid(vv, what.str());
    // Two discretisations of one VV (the trapezoid rule vs the mesh): close, looser on coarse
    // grids where a thin band spans few cells.
    EXPECT_NEAR(vv.volume / vv.grid_volume(), 1.0, 0.05 * res) << what.str();
  }
}

// A crease (d_max meeting the ground, or a band plane) within a quarter step of a grid row takes
// that row's place among the mesh's vertex rows: the grid's corners there get rays of their own.
TEST(VisibilityVolume, GridRowsNextToACreaseAreTraced) {
  const VisibilityScene scene(boxes_env({{Vec3(40, -20, 0), Vec3(60, 20, 30)}, {Vec3(-50, 30, 0), Vec3(-10, 80, 70)}}));
  const double d_max = 400.0;
  for (const Vec3& g : {Vec3(0, 0, d_max * std::sin(0.9 * kPi / 180.0)), Vec3(0, 0, d_max * std::sin(3.1 * kPi / 180.0))}) {
    const VisibilityVolume vv = visibility_volume(scene, g, d_max, std::nullopt, 1.0);
    expect_brute_force_intervals(scene, vv);
    // The case this test is for: the mesh dropped a grid row next to the crease, so its intervals
    // came from rays of their own.
    int dropped = 0;
    for (int i = 0; i <= vv.grid.num_elevation; ++i) {
      const double row = std::sin(-0.5 * kPi + i * kPi / vv.grid.num_elevation);
      dropped += std::none_of(vv.mesh_row_sines.begin(), vv.mesh_row_sines.end(),
                              [&](double s) { return std::abs(s - row) < 1e-9; });
    }
    EXPECT_GE(dropped, 1) << "g.z = " << g.z();
    const VisibilityVolume banded = visibility_volume(scene, Vec3(0, 0, 0.5), d_max, std::make_pair(g.z() + 0.5, 300.0), 1.0);
    expect_brute_force_intervals(scene, banded);
  }
}

TEST(VisibilityVolume, RandomBoxCityVolumesAreValid) {
  random_volumes_are_valid(boxes_env({{Vec3(40, -20, 0), Vec3(60, 20, 30)},
                                      {Vec3(-50, 30, 0), Vec3(-10, 80, 70)},
                                      {Vec3(-80, -90, 0), Vec3(-20, -40, 15)}}),
                           40, 21);
}

TEST(VisibilityVolumeData, RandomCharlotteVolumesAreValid) {
  VISTRACK_REQUIRE_DATA(geojson, "charlotte/buildings.geojson");
  random_volumes_are_valid(Environment::from_geojson(geojson), 40, 22);
}

// Real data: VVs along the road paths are closed, valid meshes; the volume converges.
void check_city(const Environment& env, const std::string& path_csv, double d_max,
                std::pair<double, double> band, std::uint64_t seed) {
  const VisibilityScene scene(env);
  const PoiPath poi = PoiPath::from_csv(path_csv, 5.0);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> when(0.0, poi.duration());
  Points3 pois(50, 3);
  for (int k = 0; k < 50; ++k) pois.row(k) = poi.position(when(rng)).transpose();
  // On uneven terrain the path's z may lie under the surface: drape the POI 0.5 m above it.
  for (int k = 0; k < 50; ++k) pois(k, 2) = std::max(pois(k, 2), scene.surface_height(pois.row(k).head<2>().transpose()) + 0.5);
  const std::vector<double> resolutions = {4.0, 3.0, 2.5};
  for (int k = 0; k < 50; ++k) {
    const auto b = k % 2 ? std::optional(band) : std::nullopt;
    const VisibilityVolume vv = visibility_volume(scene, pois.row(k).transpose(), d_max, b, resolutions[k % 3]);
    expect_valid(vv, path_csv + " #" + std::to_string(k));
    EXPECT_GT(vv.volume, 0.0);
  }
  // Convergence at one point: successive differences shrink as the resolution halves.
  std::vector<double> volumes;
  for (double res : {4.0, 2.0}) volumes.push_back(visibility_volume(scene, pois.row(0).transpose(), d_max, std::nullopt, res).volume);
  const VisibilityVolume fine = visibility_volume(scene, pois.row(0).transpose(), d_max, std::nullopt, 1.0);
  expect_valid(fine, "1 degree");
  volumes.push_back(fine.volume);
  volumes.push_back(visibility_volume(scene, pois.row(0).transpose(), d_max, std::nullopt, 0.5).volume);
  EXPECT_LT(std::abs(volumes[3] - volumes[2]), std::abs(volumes[1] - volumes[0]));
  EXPECT_LT(std::abs(volumes[3] - volumes[2]) / volumes[3], 0.01);
  cross_check_with_line_of_sight(scene, fine, seed, 2000);
}

TEST(VisibilityVolumeData, CharlotteMesh) {
  VISTRACK_REQUIRE_DATA(obj, "charlotte/uptown_charlotte.obj");
  VISTRACK_REQUIRE_DATA(path, "charlotte/paths/3d_dense.csv");
  check_city(Environment::from_mesh(obj, "y"), path, 400.0, {60.0, 300.0}, 11);
}

TEST(VisibilityVolumeData, CharlotteGeoJson) {
  VISTRACK_REQUIRE_DATA(geojson, "charlotte/buildings.geojson");
  VISTRACK_REQUIRE_DATA(path, "charlotte/paths/paper_slow.csv");
  check_city(Environment::from_geojson(geojson), path, 400.0, {60.0, 300.0}, 12);
}

TEST(VisibilityVolumeData, Campus) {
  VISTRACK_REQUIRE_DATA(obj, "campus/campus.obj");
  VISTRACK_REQUIRE_DATA(path, "campus/poi_path.csv");
  check_city(Environment::from_mesh(obj, "y"), path, 100.0, {20.0, 60.0}, 13);
}

}  // namespace
}  // namespace vistrack
