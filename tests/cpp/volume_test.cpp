// Closed-mesh checks and plane slicing (section IV: VPs from VVs).
#include "vistrack/volume.hpp"
#include "volume/points_inside.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "vistrack/error.hpp"
#include "vistrack/orbit.hpp"

namespace vistrack {
namespace {

// Axis-aligned box as an outward-oriented closed triangle mesh.
TriangleMesh box_mesh(const Vec3& lo, const Vec3& hi) {
  TriangleMesh m;
  m.vertices.resize(8, 3);
  for (int k = 0; k < 8; ++k)
    m.vertices.row(k) << ((k & 1) ? hi.x() : lo.x()), ((k & 2) ? hi.y() : lo.y()), ((k & 4) ? hi.z() : lo.z());
  m.faces.resize(12, 3);
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (int q = 0; q < 6; ++q) {
    m.faces.row(2 * q) << quads[q][0], quads[q][1], quads[q][2];
    m.faces.row(2 * q + 1) << quads[q][0], quads[q][2], quads[q][3];
  }
  return m;
}

TriangleMesh merge(const TriangleMesh& a, const TriangleMesh& b) {
  TriangleMesh m;
  m.vertices.resize(a.vertices.rows() + b.vertices.rows(), 3);
  m.vertices << a.vertices, b.vertices;
  m.faces.resize(a.faces.rows() + b.faces.rows(), 3);
  Faces shifted = b.faces.array() + static_cast<std::int32_t>(a.vertices.rows());
  m.faces << a.faces, shifted;
  return m;
}

TriangleMesh flipped(TriangleMesh m) {
  for (Eigen::Index f = 0; f < m.faces.rows(); ++f) std::swap(m.faces(f, 1), m.faces(f, 2));
  return m;
}

TEST(MeshCheck, AcceptsABoxAndNamesEachDefect) {
  const TriangleMesh box = box_mesh(Vec3(0, 0, 0), Vec3(2, 3, 4));
  MeshCheck ok = check_closed_mesh(box);
  EXPECT_TRUE(ok.valid()) << ok.problem;
  EXPECT_NEAR(ok.volume, 24.0, 1e-12);
  EXPECT_NEAR(mesh_volume(box), 24.0, 1e-12);

  EXPECT_EQ(check_closed_mesh(TriangleMesh{}).problem, "empty mesh");
  TriangleMesh open = box;
  open.faces.conservativeResize(11, 3);
  EXPECT_FALSE(check_closed_mesh(open).closed);
  EXPECT_FALSE(check_closed_mesh(open).valid());

  const MeshCheck inverted = check_closed_mesh(flipped(box));
  EXPECT_TRUE(inverted.closed);
  EXPECT_FALSE(inverted.outward);
  EXPECT_FALSE(inverted.valid());

  TriangleMesh one_flipped = box;
  std::swap(one_flipped.faces(0, 1), one_flipped.faces(0, 2));
  EXPECT_FALSE(check_closed_mesh(one_flipped).polygon_mesh);

  const MeshCheck overlapping = check_closed_mesh(merge(box, box_mesh(Vec3(1, 1, 1), Vec3(5, 5, 5))));
  EXPECT_TRUE(overlapping.self_intersecting);
  EXPECT_FALSE(overlapping.valid());

  // A box inside a bigger inverted box: a shell that bounds a volume (outer outward, inner inward).
  const MeshCheck shell = check_closed_mesh(merge(box_mesh(Vec3(-1, -1, -1), Vec3(3, 4, 5)), flipped(box)));
  EXPECT_TRUE(shell.valid()) << shell.problem;
  EXPECT_NEAR(shell.volume, 4 * 5 * 6 - 24.0, 1e-9);

  TriangleMesh bad_index = box;
  bad_index.faces(3, 2) = 99;
  EXPECT_FALSE(check_closed_mesh(bad_index).triangles_valid);
}

TEST(Slice, BoxSliceIsItsCrossSection) {
  const TriangleMesh box = box_mesh(Vec3(-1, -2, 0), Vec3(3, 5, 10));
  for (double z : {0.5, 5.0, 9.99}) {
    const std::vector<Polygon> polygons = nest_rings(slice_rings(box, z));
    ASSERT_EQ(polygons.size(), 1u);
    EXPECT_NEAR(area(polygons[0]), 28.0, 1e-9);
    EXPECT_GT(signed_area(polygons[0].outer), 0.0);
  }
  EXPECT_TRUE(slice_rings(box, 11.0).empty());
  EXPECT_THROW(slice_rings(box, std::nan("")), Error);
}

TEST(Slice, VertexHeightsAreNudged) {
  // Slicing exactly through the box's bottom vertices, and through the vertices of a mesh whose
  // side faces share vertices at the cut height (two stacked boxes fused along z = 5).
  const TriangleMesh box = box_mesh(Vec3(0, 0, 0), Vec3(4, 4, 10));
  TriangleMesh tower;
  tower.vertices.resize(12, 3);
  for (int level = 0; level < 3; ++level)
    for (int k = 0; k < 4; ++k)
      tower.vertices.row(4 * level + k) << ((k == 1 || k == 2) ? 4.0 : 0.0), (k >= 2 ? 4.0 : 0.0), 5.0 * level;
  std::vector<std::array<int, 3>> faces = {{0, 2, 1}, {0, 3, 2}, {8, 9, 10}, {8, 10, 11}};
  for (int level = 0; level < 2; ++level)
    for (int k = 0; k < 4; ++k) {
      const int a = 4 * level + k, b = 4 * level + (k + 1) % 4;
      faces.push_back({a, b, b + 4});
      faces.push_back({a, b + 4, a + 4});
    }
  tower.faces.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t f = 0; f < faces.size(); ++f) tower.faces.row(static_cast<Eigen::Index>(f)) << faces[f][0], faces[f][1], faces[f][2];
  ASSERT_TRUE(check_closed_mesh(tower).valid()) << check_closed_mesh(tower).problem;
  const std::vector<Polygon> at_joint = nest_rings(slice_rings(tower, 5.0));
  ASSERT_EQ(at_joint.size(), 1u);
  EXPECT_NEAR(area(at_joint[0]), 16.0, 1e-6);
  const std::vector<Polygon> at_bottom = nest_rings(slice_rings(box, 0.0));
  ASSERT_EQ(at_bottom.size(), 1u);
  EXPECT_NEAR(area(at_bottom[0]), 16.0, 1e-6);
}

TEST(Slice, NestingGivesHolesAndIslands) {
  // Three nested squares and a separate one: outer with a hole containing an island, plus a
  // second polygon.
  auto square = [](double c, double h) { return Ring{Vec2(c - h, c - h), Vec2(c + h, c - h), Vec2(c + h, c + h), Vec2(c - h, c + h)}; };
  Ring middle = square(0, 6);
  std::reverse(middle.begin(), middle.end());  // orientation of the input must not matter
  const std::vector<Polygon> polygons = nest_rings({square(0, 2), middle, square(0, 10), square(100, 1)});
  ASSERT_EQ(polygons.size(), 3u);
  double total = 0.0;
  int with_hole = 0;
  for (const Polygon& p : polygons) {
    total += area(p);
    with_hole += static_cast<int>(p.holes.size());
    EXPECT_GT(signed_area(p.outer), 0.0);
    for (const Ring& hole : p.holes) EXPECT_LT(signed_area(hole), 0.0);
  }
  EXPECT_EQ(with_hole, 1);
  EXPECT_NEAR(total, 400.0 - 144.0 + 16.0 + 4.0, 1e-9);
  // The VP rule: the polygon containing the centre; MaxRadius inside the island is 2.
  std::vector<Polygon> at_centre;
  for (const Polygon& p : polygons)
    if (contains(p, Vec2(0, 0))) at_centre.push_back(p);
  ASSERT_EQ(at_centre.size(), 1u);
  EXPECT_NEAR(max_inscribed_radius(at_centre, Vec2(0, 0)), 2.0, 1e-12);
  EXPECT_NEAR(max_inscribed_radius(polygons, Vec2(7, 0)), 1.0, 1e-12);   // in the ring between 6 and 10
  EXPECT_EQ(max_inscribed_radius(polygons, Vec2(4, 0)), 0.0);           // in the hole
}

TEST(Slice, ShellSliceHasAHoleAndPointsInsideAgree) {
  const TriangleMesh shell = merge(box_mesh(Vec3(-10, -10, 0), Vec3(10, 10, 10)), flipped(box_mesh(Vec3(-3, -3, 2), Vec3(3, 3, 8))));
  ASSERT_TRUE(check_closed_mesh(shell).valid());
  const std::vector<Polygon> polygons = nest_rings(slice_rings(shell, 5.0));
  ASSERT_EQ(polygons.size(), 1u);
  ASSERT_EQ(polygons[0].holes.size(), 1u);
  EXPECT_NEAR(area(polygons[0]), 400.0 - 36.0, 1e-9);
  // points_inside against the analytic solid, random points.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-12.0, 12.0);
  Points3 points(2000, 3);
  for (Eigen::Index k = 0; k < points.rows(); ++k) points.row(k) << u(rng), u(rng), u(rng);
  const std::vector<bool> inside = detail::points_inside(shell, points);
  for (Eigen::Index k = 0; k < points.rows(); ++k) {
    const Vec3 p = points.row(k).transpose();
    const bool in_outer = (p.array().abs().head<2>() < 10).all() && p.z() > 0 && p.z() < 10;
    const bool in_inner = (p.array().abs().head<2>() < 3).all() && p.z() > 2 && p.z() < 8;
    EXPECT_EQ(inside[static_cast<std::size_t>(k)], in_outer && !in_inner) << p.transpose();
  }
  EXPECT_THROW(detail::points_inside(TriangleMesh{}, points), Error);
}

TEST(VisibilityPolygon, KeepsThePartOverThePoiAndRespectsTheBand) {
  // A hand-made "VV": a box around the POI and a separate box elsewhere.
  VisibilityVolume vv;
  vv.poi = Vec3(0, 0, 0);
  vv.d_max = 100.0;
  vv.mesh = merge(box_mesh(Vec3(-5, -5, 0), Vec3(5, 5, 50)), box_mesh(Vec3(20, 20, 0), Vec3(30, 30, 50)));
  EXPECT_EQ(visibility_polygon(vv, 10.0).size(), 1u);
  EXPECT_NEAR(area(visibility_polygon(vv, 10.0)[0]), 100.0, 1e-9);
  EXPECT_EQ(visibility_polygon(vv, 10.0, true).size(), 2u);
  vv.poi = Vec3(10, 10, 0);  // over neither part
  EXPECT_TRUE(visibility_polygon(vv, 10.0).empty());
  EXPECT_EQ(max_inscribed_radius(visibility_polygon(vv, 10.0), vv.poi.head<2>()), 0.0);
  // On a band cap the slice is taken just inside the band; outside the band there is nothing.
  vv.poi = Vec3(0, 0, 0);
  vv.altitude_band = std::make_pair(0.0, 50.0);
  EXPECT_NEAR(area(visibility_polygon(vv, 50.0)[0]), 100.0, 1e-9);
  EXPECT_TRUE(visibility_polygon(vv, 60.0).empty());
  EXPECT_THROW(visibility_polygon(vv, std::nan("")), Error);
}

TEST(VisibilityPolygon, OpenFieldSliceIsACircle) {
  // One box far away; the POI on the ground: the VP at h is the circle of radius sqrt(d^2 - h^2).
  const TriangleMesh far_box = box_mesh(Vec3(5000, 5000, 0), Vec3(5010, 5010, 5));
  const Environment env = Environment::from_triangles(far_box.vertices, far_box.faces);
  const VisibilityVolume vv = visibility_volume(env, Vec3(0, 0, 0), 300.0, std::nullopt, 1.0);
  for (double h : {10.0, 100.0, 250.0}) {
    const std::vector<Polygon> vp = visibility_polygon(vv, h);
    ASSERT_EQ(vp.size(), 1u);
    const double radius = std::sqrt(300.0 * 300.0 - h * h);
    EXPECT_NEAR(area(vp[0]) / (kPi * radius * radius), 1.0, 0.002) << h;
    EXPECT_NEAR(max_inscribed_radius(vp, Vec2(0, 0)), radius, 0.002 * radius) << h;
  }
}

}  // namespace
}  // namespace vistrack
