// XOR volume (eq. 56): the CGAL mesh path on closed meshes with analytic answers, the
// per-direction grid path on hand-built VVs, the two against each other, and bad input.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <chrono>
#include <cmath>
#include <random>

#include "vistrack/error.hpp"
#include "vistrack/volume.hpp"

namespace vt = vistrack;

namespace {

vt::TriangleMesh box(const vt::Vec3& lo, const vt::Vec3& hi) {
  vt::TriangleMesh m;
  m.vertices.resize(8, 3);
  for (int i = 0; i < 8; ++i)
    m.vertices.row(i) << ((i & 1) ? hi.x() : lo.x()), ((i & 2) ? hi.y() : lo.y()), ((i & 4) ? hi.z() : lo.z());
  m.faces.resize(12, 3);
  m.faces << 0, 2, 1, 1, 2, 3,   // z = lo
      4, 5, 6, 5, 7, 6,          // z = hi
      0, 1, 4, 1, 5, 4,          // y = lo
      2, 6, 3, 3, 6, 7,          // y = hi
      0, 4, 2, 2, 4, 6,          // x = lo
      1, 3, 5, 3, 7, 5;          // x = hi
  return m;
}

// |x| + |y| + |z| <= r about c: volume 4/3 r^3.
vt::TriangleMesh octahedron(double r, const vt::Vec3& c = vt::Vec3::Zero()) {
  vt::TriangleMesh m;
  m.vertices.resize(6, 3);
  m.vertices << r, 0, 0, -r, 0, 0, 0, r, 0, 0, -r, 0, 0, 0, r, 0, 0, -r;
  m.vertices.rowwise() += c.transpose();
  m.faces.resize(8, 3);
  m.faces << 0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5;
  return m;
}

// A latitude-longitude sphere of radius r (poles shared), outward oriented.
vt::TriangleMesh uv_sphere(double r, int rows, int columns, const vt::Vec3& c = vt::Vec3::Zero()) {
  vt::TriangleMesh m;
  const int n = 2 + (rows - 1) * columns;
  m.vertices.resize(n, 3);
  m.vertices.row(0) << 0, 0, -r;
  m.vertices.row(1) << 0, 0, r;
  for (int i = 1; i < rows; ++i)
    for (int j = 0; j < columns; ++j) {
      const double el = -vt::kPi / 2 + vt::kPi * i / rows, az = vt::kTwoPi * j / columns;
      m.vertices.row(2 + (i - 1) * columns + j) << r * std::cos(el) * std::cos(az), r * std::cos(el) * std::sin(az),
          r * std::sin(el);
    }
  std::vector<std::array<int, 3>> f;
  auto v = [&](int i, int j) { return 2 + (i - 1) * columns + (j % columns); };
  for (int j = 0; j < columns; ++j) {
    f.push_back({0, v(1, j + 1), v(1, j)});
    f.push_back({1, v(rows - 1, j), v(rows - 1, j + 1)});
    for (int i = 1; i + 1 < rows; ++i) {
      f.push_back({v(i, j), v(i, j + 1), v(i + 1, j + 1)});
      f.push_back({v(i, j), v(i + 1, j + 1), v(i + 1, j)});
    }
  }
  m.faces.resize(static_cast<Eigen::Index>(f.size()), 3);
  for (std::size_t k = 0; k < f.size(); ++k) m.faces.row(static_cast<Eigen::Index>(k)) << f[k][0], f[k][1], f[k][2];
  for (Eigen::Index i = 0; i < n; ++i) m.vertices.row(i) += c.transpose();
  return m;
}

// A VV on a grid with the same interval [near, far] in every direction.
vt::VisibilityVolume uniform_vv(int rows, int columns, double near, double far, const vt::Vec3& poi = vt::Vec3::Zero()) {
  vt::VisibilityVolume v;
  v.poi = poi;
  v.grid.num_elevation = rows;
  v.grid.num_azimuth = columns;
  v.near.assign(v.grid.num_corners(), near);
  v.far.assign(v.grid.num_corners(), far);
  return v;
}

}  // namespace

TEST(MeshXor, OverlappingBoxesHaveTheAnalyticXor) {
  const auto a = box({0, 0, 0}, {2, 2, 2});
  EXPECT_NEAR(vt::mesh_xor_volume(a, box({1, 0, 0}, {3, 2, 2})), 8.0, 1e-9);   // 8 + 8 - 2*4
  EXPECT_NEAR(vt::mesh_xor_volume(a, box({1, 1, 1}, {3, 3, 3})), 14.0, 1e-9);  // 8 + 8 - 2*1
  EXPECT_NEAR(vt::mesh_xor_volume(a, box({5, 5, 5}, {6, 6, 7})), 10.0, 1e-9);  // disjoint
  EXPECT_NEAR(vt::mesh_xor_volume(box({0, 0, 0}, {4, 4, 4}), box({1, 1, 1}, {2, 2, 2})), 63.0, 1e-9);  // nested
  EXPECT_NEAR(vt::mesh_xor_volume(a, a), 0.0, 1e-9);  // identical faces
}

TEST(MeshXor, CubeAndOctahedronHaveTheAnalyticXor) {
  const auto cube = box({-1, -1, -1}, {1, 1, 1});
  // Octahedron inside: 8 - 4/3.
  EXPECT_NEAR(vt::mesh_xor_volume(cube, octahedron(1.0)), 8.0 - 4.0 / 3.0, 1e-9);
  // r = 1.5: six corner pyramids of volume 1/12 stick out, so |A n B| = 4.5 - 0.5 = 4.
  EXPECT_NEAR(vt::mesh_xor_volume(cube, octahedron(1.5)), 8.0 + 4.5 - 8.0, 1e-9);
  EXPECT_NEAR(vt::mesh_volume(octahedron(1.5)), 4.5, 1e-12);
}

TEST(MeshXor, SymmetricAndIndependentOfOrientation) {
  const auto cube = box({-1, -1, -1}, {1, 1, 1});
  const auto oct = octahedron(1.3, {0.2, -0.1, 0.05});
  const double ab = vt::mesh_xor_volume(cube, oct);
  EXPECT_NEAR(vt::mesh_xor_volume(oct, cube), ab, 1e-9);
  auto inward = oct;
  inward.faces.col(1).swap(inward.faces.col(2));  // closed but inside out: re-oriented
  EXPECT_NEAR(vt::mesh_xor_volume(cube, inward), ab, 1e-9);
}

TEST(MeshXor, NestedSpheresGiveTheDifferenceOfTheirVolumes) {
  const auto big = uv_sphere(10.0, 24, 48), small = uv_sphere(6.0, 18, 36, {1.0, -0.5, 0.3});
  EXPECT_NEAR(vt::mesh_xor_volume(big, small), vt::mesh_volume(big) - vt::mesh_volume(small), 1e-6);
}

TEST(MeshXor, PerturbationHandlesIdenticalSpheresAndStaysSmall) {
  // Two identical spheres about one centre (two VVs of open terrain in the POI frame): the
  // coincident-face case that makes CGAL slow. The documented nudge answers close to 0.
  const auto s = uv_sphere(100.0, 32, 64);
  vt::MeshXorOptions options;
  options.perturbation = 1e-6;
  const auto start = std::chrono::steady_clock::now();
  const double d = vt::mesh_xor_volume(s, s, options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(d, 1e-4 * vt::mesh_volume(s));
  RecordProperty("seconds", std::to_string(seconds));
  // And a real difference is kept: bigger sphere, same faces directions.
  const auto t = uv_sphere(110.0, 32, 64);
  EXPECT_NEAR(vt::mesh_xor_volume(s, t, options), vt::mesh_volume(t) - vt::mesh_volume(s),
              1e-4 * vt::mesh_volume(s));
}

TEST(MeshXor, EmptyMeshIsTheEmptySet) {
  const auto cube = box({0, 0, 0}, {1, 2, 3});
  EXPECT_NEAR(vt::mesh_xor_volume(cube, vt::TriangleMesh{}), 6.0, 1e-12);
  EXPECT_NEAR(vt::mesh_xor_volume(vt::TriangleMesh{}, vt::TriangleMesh{}), 0.0, 0.0);
}

TEST(MeshXor, RejectsMeshesThatDoNotBoundAVolume) {
  const auto cube = box({0, 0, 0}, {1, 1, 1});
  auto open = cube;
  open.faces.conservativeResize(11, 3);
  EXPECT_THROW(
      {
        try {
          vt::mesh_xor_volume(open, cube);
        } catch (const vt::Error& e) {
          EXPECT_NE(std::string(e.what()).find("not closed"), std::string::npos) << e.what();
          throw;
        }
      },
      vt::Error);
  // Two overlapping boxes in one mesh: closed, but self-intersecting.
  auto twice = cube;
  const auto other = box({0.5, 0.5, 0.5}, {1.5, 1.5, 1.5});
  twice.vertices.conservativeResize(16, 3);
  twice.vertices.bottomRows(8) = other.vertices;
  twice.faces.conservativeResize(24, 3);
  twice.faces.bottomRows(12) = other.faces.array() + 8;
  EXPECT_THROW(vt::mesh_xor_volume(twice, cube), vt::Error);
  auto bad_index = cube;
  bad_index.faces(3, 1) = 99;
  EXPECT_THROW(vt::mesh_xor_volume(bad_index, cube), vt::Error);
  auto nan = cube;
  nan.vertices(2, 0) = std::nan("");
  EXPECT_THROW(vt::mesh_xor_volume(nan, cube), vt::Error);
  vt::MeshXorOptions options;
  options.time_limit = -1.0;
  EXPECT_THROW(vt::mesh_xor_volume(cube, cube, options), vt::Error);
}

TEST(MeshXor, TimeLimitAbortsWithAnError) {
  const auto s = uv_sphere(100.0, 32, 64), t = uv_sphere(100.0, 32, 64, {3.0, 1.0, 0.5});
  vt::MeshXorOptions options;
  options.time_limit = 1e-9;
  try {
    vt::mesh_xor_volume(s, t, options);
    FAIL() << "expected a time-limit Error";
  } catch (const vt::Error& e) {
    EXPECT_NE(std::string(e.what()).find("time_limit"), std::string::npos) << e.what();
  }
}

TEST(GridXor, UniformIntervalsGiveTheSphericalShellVolumes) {
  const auto a = uniform_vv(90, 180, 0.0, 10.0), b = uniform_vv(90, 180, 5.0, 20.0);
  // Per steradian: |A| + |B| - 2|A n B| = (1000 + 7875 - 2 * 875) / 3, times 4 pi.
  EXPECT_NEAR(vt::grid_xor_volume(a, b), 4.0 * vt::kPi * (1000.0 + 7875.0 - 1750.0) / 3.0, 1e-6);
  EXPECT_NEAR(vt::grid_xor_volume(a, a), 0.0, 0.0);
  const auto empty = uniform_vv(90, 180, 3.0, 3.0);  // near >= far: nothing visible
  EXPECT_NEAR(vt::grid_xor_volume(a, empty), 4.0 * vt::kPi * 1000.0 / 3.0, 1e-6);
}

TEST(GridXor, IsAMetricOnRandomVolumes) {
  std::mt19937 rng(20240517);
  std::uniform_real_distribution<double> radius(0.0, 400.0);
  auto random_vv = [&] {
    auto v = uniform_vv(18, 36, 0.0, 0.0);
    for (std::size_t k = 0; k < v.grid.num_corners(); ++k) {
      const double r1 = radius(rng), r2 = radius(rng);
      v.near[k] = std::min(r1, r2) * (k % 3 == 0 ? 1.0 : 0.0);
      v.far[k] = std::max(r1, r2);
    }
    return v;
  };
  for (int trial = 0; trial < 50; ++trial) {
    const auto a = random_vv(), b = random_vv(), c = random_vv();
    const double ab = vt::grid_xor_volume(a, b), bc = vt::grid_xor_volume(b, c), ac = vt::grid_xor_volume(a, c);
    EXPECT_NEAR(ab, vt::grid_xor_volume(b, a), 1e-9 * ab);
    EXPECT_LE(ac, ab + bc + 1e-6 * (ab + bc));  // XOR volume is a metric (triangle inequality)
    EXPECT_GE(ab, 0.0);
  }
}

TEST(GridXor, MatchesTheMeshPathOnStarShapedVolumes) {
  // Two spheres about their own POIs: frame "poi" puts both at the origin. The mesh path sees
  // polyhedra, so compare within the polyhedral error of a 64 x 128 sphere (< 0.2%).
  auto a = uniform_vv(60, 120, 0.0, 100.0, {10, 20, 0}), b = uniform_vv(60, 120, 0.0, 120.0, {-40, 5, 0});
  a.mesh = uv_sphere(100.0, 64, 128, a.poi);
  b.mesh = uv_sphere(120.0, 64, 128, b.poi);
  const double grid = vt::xor_volume(a, b, vt::XorFrame::poi, vt::XorMethod::grid);
  const double mesh = vt::xor_volume(a, b, vt::XorFrame::poi, vt::XorMethod::mesh);
  EXPECT_NEAR(grid, 4.0 / 3.0 * vt::kPi * (120.0 * 120.0 * 120.0 - 1e6), 1e-6 * grid);
  EXPECT_NEAR(mesh, grid, 2e-3 * grid);
  EXPECT_NEAR(vt::xor_volume(a, b, vt::XorFrame::poi), grid, 0.0);  // auto picks the grid path
  // World frame: the spheres are apart; far apart they are disjoint.
  b.poi = {1000, 0, 0};
  b.mesh = uv_sphere(120.0, 64, 128, b.poi);
  EXPECT_NEAR(vt::xor_volume(a, b, vt::XorFrame::world),
              vt::mesh_volume(a.mesh) + vt::mesh_volume(b.mesh), 1e-6 * grid);
  EXPECT_THROW(vt::xor_volume(a, b, vt::XorFrame::world, vt::XorMethod::grid), vt::Error);
}

TEST(GridXor, RejectsDifferentGridsAndBadNames) {
  EXPECT_THROW(vt::grid_xor_volume(uniform_vv(90, 180, 0, 1), uniform_vv(180, 360, 0, 1)), vt::Error);
  auto broken = uniform_vv(9, 18, 0, 1);
  broken.far.pop_back();
  EXPECT_THROW(vt::grid_xor_volume(broken, broken), vt::Error);
  auto nan = uniform_vv(9, 18, 0, 1);
  nan.far[5] = std::nan("");
  EXPECT_THROW(vt::grid_xor_volume(nan, uniform_vv(9, 18, 0, 1)), vt::Error);
  EXPECT_THROW(vt::from_name<vt::XorFrame>("body"), vt::Error);
  EXPECT_THROW(vt::from_name<vt::XorMethod>("fast"), vt::Error);
  EXPECT_EQ(vt::from_name<vt::XorFrame>("world"), vt::XorFrame::world);
}

// ---------------------------------------------------------------------------------------------
// The radial path: the exact XOR of two star VV meshes per direction, against CGAL on the same
// meshes.

vt::Environment box_city() {
  const std::vector<std::pair<vt::Vec3, vt::Vec3>> boxes = {{{40, -20, 0}, {60, 20, 30}},
                                                            {{-50, 30, 0}, {-10, 80, 70}},
                                                            {{-80, -90, 0}, {-20, -40, 15}}};
  vt::Points3 vertices(8 * static_cast<Eigen::Index>(boxes.size()), 3);
  vt::Faces faces(12 * static_cast<Eigen::Index>(boxes.size()), 3);
  for (std::size_t k = 0; k < boxes.size(); ++k) {
    const vt::TriangleMesh m = box(boxes[k].first, boxes[k].second);
    vertices.block(8 * static_cast<Eigen::Index>(k), 0, 8, 3) = m.vertices;
    faces.block(12 * static_cast<Eigen::Index>(k), 0, 12, 3) = m.faces.array() + 8 * static_cast<int>(k);
  }
  return vt::Environment::from_triangles(vertices, faces);
}

double area(const vt::TriangleMesh& m) {
  double total = 0.0;
  for (Eigen::Index f = 0; f < m.faces.rows(); ++f) {
    const vt::Vec3 a = m.vertices.row(m.faces(f, 0)), b = m.vertices.row(m.faces(f, 1)), c = m.vertices.row(m.faces(f, 2));
    total += 0.5 * (b - a).cross(c - a).norm();
  }
  return total;
}

vt::TriangleMesh about_poi(const vt::VisibilityVolume& v) {
  vt::TriangleMesh m = v.mesh;
  m.vertices.rowwise() -= v.poi.transpose();
  return m;
}

TEST(RadialXor, EqualsCgalOnTheSameMeshes) {
  const vt::VisibilityScene scene(box_city());
  // Pairs 2-30 m apart, with walls at the boxes' silhouettes; the same resolution in a pair.
  const std::vector<std::pair<vt::Vec3, vt::Vec3>> pairs = {
      {{0, 0, 0.5}, {5, 3, 0.5}}, {{0, 0, 0.5}, {-20, -20, 0.5}}, {{10, -30, 0.5}, {12, -30, 0.5}}};
  for (double res : {4.0, 3.0}) {
    for (const auto& [ga, gb] : pairs) {
      const vt::VisibilityVolume a = vt::visibility_volume(scene, ga, 150.0, std::nullopt, res);
      const vt::VisibilityVolume b = vt::visibility_volume(scene, gb, 150.0, std::nullopt, res);
      ASSERT_TRUE(vt::shares_radial_mesh(a, b));
      const double radial = vt::radial_xor_volume(a, b);
      // CGAL needs the documented nudge here (identical sphere faces about the POIs are its slow
      // branch: minutes); it moves the XOR by less than 1e-6 rad x r x area, about 1e-6 of it.
      vt::MeshXorOptions nudge;
      nudge.perturbation = vt::kPoiFramePerturbation;
      const double cgal = vt::mesh_xor_volume(about_poi(a), about_poi(b), nudge);
      const double nudge_bound = *nudge.perturbation * 150.0 * (area(a.mesh) + area(b.mesh));
      EXPECT_NEAR(radial, cgal, nudge_bound) << ga.transpose() << " / " << gb.transpose() << " res " << res;
      EXPECT_LT(nudge_bound, 1e-3 * cgal);  // so the comparison is sharp
      EXPECT_GT(radial, 0.0);
      EXPECT_NEAR(vt::radial_xor_volume(b, a), radial, 1e-9 * radial);
      EXPECT_EQ(vt::xor_volume(a, b), radial);  // auto takes the radial path
      EXPECT_NEAR(vt::radial_xor_volume(a, a), 0.0, 1e-12 * a.volume);
    }
  }
}

TEST(RadialXor, IsAMetricAndZeroOnOpenTerrain) {
  const vt::VisibilityScene scene(box_city());
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> coordinate(-100.0, 100.0);
  std::vector<vt::VisibilityVolume> vvs;
  while (vvs.size() < 6) {
    const vt::Vec3 g(coordinate(rng), coordinate(rng), 0.5);
    if (!scene.inside_obstacle(g)) vvs.push_back(vt::visibility_volume(scene, g, 120.0, std::nullopt, 3.0));
  }
  for (std::size_t i = 0; i + 2 < vvs.size(); ++i) {
    const double ab = vt::radial_xor_volume(vvs[i], vvs[i + 1]);
    const double bc = vt::radial_xor_volume(vvs[i + 1], vvs[i + 2]);
    const double ac = vt::radial_xor_volume(vvs[i], vvs[i + 2]);
    EXPECT_LE(ac, ab + bc + 1e-9 * (ab + bc));
  }
  // Far from the boxes both VVs are the same half ball about their POIs.
  const vt::VisibilityVolume a = vt::visibility_volume(scene, {3000, 0, 0.5}, 100.0, std::nullopt, 3.0);
  const vt::VisibilityVolume b = vt::visibility_volume(scene, {3040, 10, 0.5}, 100.0, std::nullopt, 3.0);
  EXPECT_NEAR(vt::radial_xor_volume(a, b), 0.0, 1e-9 * a.volume);
}

TEST(RadialXor, MeshesOnDifferentVertexRowsAreOverlappedToo) {
  // POIs at different heights above the ground put the ground crease on different vertex rows
  // (the campus's terrain does this): faces are then overlapped across rows, still exactly.
  const vt::VisibilityScene scene(box_city());
  const vt::VisibilityVolume low = vt::visibility_volume(scene, {0, 0, 0.5}, 150.0, std::nullopt, 3.0);
  const vt::VisibilityVolume high = vt::visibility_volume(scene, {4, -3, 8.0}, 150.0, std::nullopt, 3.0);
  ASSERT_NE(low.mesh_row_sines, high.mesh_row_sines);
  ASSERT_TRUE(vt::shares_radial_mesh(low, high));
  const double radial = vt::radial_xor_volume(low, high);
  vt::MeshXorOptions nudge;
  nudge.perturbation = vt::kPoiFramePerturbation;
  const double cgal = vt::mesh_xor_volume(about_poi(low), about_poi(high), nudge);
  EXPECT_NEAR(radial, cgal, *nudge.perturbation * 150.0 * (area(low.mesh) + area(high.mesh)));
  EXPECT_NEAR(vt::radial_xor_volume(high, low), radial, 1e-9 * radial);
  EXPECT_EQ(vt::xor_volume(low, high), radial);  // auto
}

TEST(RadialXor, FallsBackWhenTheMeshesDoNotShareASphere) {
  const vt::VisibilityScene scene(box_city());
  const vt::VisibilityVolume low = vt::visibility_volume(scene, {0, 0, 0.5}, 150.0, std::nullopt, 3.0);
  // A POI below the band: a shell mesh (near > 0), not a radial surface about the POI.
  const vt::VisibilityVolume shell = vt::visibility_volume(scene, {0, 0, 0.5}, 150.0, std::make_pair(20.0, 60.0), 3.0);
  const vt::VisibilityVolume coarse = vt::visibility_volume(scene, {0, 0, 0.5}, 150.0, std::nullopt, 4.0);
  EXPECT_TRUE(shell.mesh_triangle_faces.empty());
  for (const vt::VisibilityVolume* other : {&shell, &coarse}) {
    EXPECT_FALSE(vt::shares_radial_mesh(low, *other));
    EXPECT_THROW(vt::radial_xor_volume(low, *other), vt::Error);
  }
  // auto: the grid path where the grids agree, CGAL where they do not.
  EXPECT_EQ(vt::xor_volume(low, shell), vt::grid_xor_volume(low, shell));
  // In the world frame two VVs about different POIs are not star-shaped about one point.
  const vt::VisibilityVolume moved = vt::visibility_volume(scene, {5, 0, 0.5}, 150.0, std::nullopt, 3.0);
  ASSERT_TRUE(vt::shares_radial_mesh(low, moved));
  EXPECT_THROW(vt::xor_volume(low, moved, vt::XorFrame::world, vt::XorMethod::radial), vt::Error);
  EXPECT_EQ(vt::from_name<vt::XorMethod>("radial"), vt::XorMethod::radial);
}
