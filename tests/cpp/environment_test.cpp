#include "vistrack/environment.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>

#include "test_data.hpp"
#include "vistrack/error.hpp"

namespace vistrack {
namespace {

namespace fs = std::filesystem;

using testing::expect_error;
using testing::TempDir;

Ring rectangle(double x0, double y0, double x1, double y1) {
  return {Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)};
}

double signed_volume(const TriangleMesh& mesh, Eigen::Index first_face = 0, Eigen::Index count = -1) {
  if (count < 0) count = mesh.faces.rows();
  double six_volume = 0.0;
  for (Eigen::Index f = first_face; f < first_face + count; ++f) {
    const Vec3 a = mesh.vertices.row(mesh.faces(f, 0)).transpose();
    const Vec3 b = mesh.vertices.row(mesh.faces(f, 1)).transpose();
    const Vec3 c = mesh.vertices.row(mesh.faces(f, 2)).transpose();
    six_volume += a.dot(b.cross(c));
  }
  return six_volume / 6.0;
}

// Closed and consistently oriented: every directed edge appears once and its reverse once
// (with manifold = false: as often as its reverse, for rings that touch at a corner).
void expect_closed_oriented(const TriangleMesh& mesh, bool manifold = true) {
  std::map<std::pair<int, int>, int> directed;
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) ++directed[{mesh.faces(f, k), mesh.faces(f, (k + 1) % 3)}];
  for (const auto& [edge, count] : directed) {
    if (!manifold) {
      const auto reverse = directed.find({edge.second, edge.first});
      ASSERT_TRUE(reverse != directed.end() && reverse->second == count) << edge.first << "-" << edge.second;
      continue;
    }
    ASSERT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second << " used twice in one direction";
    ASSERT_EQ(directed.count({edge.second, edge.first}), 1u)
        << "edge " << edge.first << "-" << edge.second << " has no opposite face";
  }
}

double roof_area(const TriangleMesh& mesh, double z) {
  double total = 0.0;
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f) {
    const Vec3 a = mesh.vertices.row(mesh.faces(f, 0)).transpose();
    const Vec3 b = mesh.vertices.row(mesh.faces(f, 1)).transpose();
    const Vec3 c = mesh.vertices.row(mesh.faces(f, 2)).transpose();
    if (a.z() == z && b.z() == z && c.z() == z) total += 0.5 * (b - a).cross(c - a).z();
  }
  return total;
}

TEST(Extrusion, BoxIsClosedOutwardWithExactVolume) {
  const Environment env = Environment::from_buildings({{{rectangle(0, 0, 10, 20), {}}, 30.0, 7}});
  EXPECT_EQ(env.num_triangles(), 12u);  // 2 roof + 2 floor + 8 wall
  EXPECT_EQ(env.mesh().vertices.rows(), 8);
  expect_closed_oriented(env.mesh());
  EXPECT_NEAR(signed_volume(env.mesh()), 10 * 20 * 30.0, 1e-9);
  EXPECT_DOUBLE_EQ(env.max_height(), 30.0);
  EXPECT_DOUBLE_EQ(env.ground_level(), 0.0);
  EXPECT_EQ(env.buildings()[0].id, 7);
}

TEST(Extrusion, ClockwiseInputIsNormalisedAndHoleHandled) {
  // Outer given clockwise and hole counter-clockwise: both are flipped.
  Polygon footprint{{Vec2(0, 0), Vec2(0, 40), Vec2(40, 40), Vec2(40, 0)}, {rectangle(10, 10, 30, 20)}};
  const Environment env = Environment::from_buildings({{footprint, 12.0, 0}});
  const Polygon& stored = env.buildings()[0].footprint;
  EXPECT_GT(signed_area(stored.outer), 0.0);
  EXPECT_LT(signed_area(stored.holes[0]), 0.0);
  expect_closed_oriented(env.mesh());
  EXPECT_NEAR(signed_volume(env.mesh()), (1600.0 - 200.0) * 12.0, 1e-9);
  EXPECT_NEAR(roof_area(env.mesh(), 12.0), 1400.0, 1e-9);  // no roof over the courtyard
}

TEST(Extrusion, HoleTouchingOuterRingAtACornerSharesTheVertex) {
  Polygon footprint{rectangle(0, 0, 30, 30), {{Vec2(0, 0), Vec2(10, 20), Vec2(20, 10)}}};
  const Environment env = Environment::from_buildings({{footprint, 5.0, 0}});
  EXPECT_EQ(env.mesh().vertices.rows(), 2 * 6);  // the corner (0, 0) is one vertex, not two
  // The vertical edge at the shared corner joins four walls (two pairs), every other edge two.
  expect_closed_oriented(env.mesh(), false);
  EXPECT_NEAR(signed_volume(env.mesh()), (900.0 - 150.0) * 5.0, 1e-9);
}

// Star-shaped random polygons (sorted angles, random radii) with a scaled copy as a hole.
TEST(Extrusion, RandomFootprintsAreClosedWithAreaTimesHeight) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    // Jittered even angles keep every gap below pi, so the polygon is star-shaped about its
    // centre and the scaled copy lies inside it.
    const int n = 4 + static_cast<int>(unit(rng) * 30);
    std::vector<double> angles;
    for (int i = 0; i < n; ++i) angles.push_back((i + 0.5 * unit(rng)) * kTwoPi / n);
    const Vec2 centre(unit(rng) * 1000 - 500, unit(rng) * 1000 - 500);
    Ring outer;
    std::vector<double> radii;
    for (double a : angles) {
      radii.push_back(5.0 + 50.0 * unit(rng));
      outer.push_back(centre + radii.back() * Vec2(std::cos(a), std::sin(a)));
    }
    if (!is_simple(outer)) continue;  // rare near-collinear draws
    Polygon footprint{outer, {}};
    if (trial % 2 == 0) {
      Ring hole;
      for (std::size_t i = angles.size(); i-- > 0;)
        hole.push_back(centre + 0.3 * radii[i] * Vec2(std::cos(angles[i]), std::sin(angles[i])));
      footprint.holes.push_back(hole);
    }
    const double height = 1.0 + 200.0 * unit(rng);
    const Environment env = Environment::from_buildings({{footprint, height, trial}});
    SCOPED_TRACE("trial " + std::to_string(trial));
    expect_closed_oriented(env.mesh());
    const double expected = area(env.buildings()[0].footprint) * height;
    EXPECT_NEAR(signed_volume(env.mesh()), expected, 1e-9 * expected);
  }
}

TEST(Buildings, BadFootprintsNameTheField) {
  auto one = [](Polygon footprint, double height) {
    return [footprint, height] { Environment::from_buildings({{footprint, height, 0}}); };
  };
  expect_error(one({{Vec2(0, 0), Vec2(1, 0)}, {}}, 5.0), {"buildings[0].footprint.outer", "at least 3"});
  expect_error(one({{Vec2(0, 0), Vec2(1, 0), Vec2(0, 0), Vec2(1, 0)}, {}}, 5.0), {"buildings[0].footprint.outer", "degenerate"});
  expect_error(one({{Vec2(0, 0), Vec2(10, 10), Vec2(10, 0), Vec2(0, 10)}, {}}, 5.0),
               {"buildings[0].footprint.outer", "edge 0", "edge 2", "self-intersecting"});
  expect_error(one({{Vec2(0, 0), Vec2(1, 0), Vec2(2, 0)}, {}}, 5.0), {"buildings[0].footprint.outer", "degenerate"});
  expect_error(one({{Vec2(0, 0), Vec2(10, 0), Vec2(10, 10), Vec2(10, 5)}, {}}, 5.0), {"footprint.outer", "self-intersecting"});
  expect_error(one({rectangle(0, 0, 10, 10), {}}, -3.0), {"buildings[0].height = -3", "[1e-06, 1e+07] m"});
  expect_error(one({rectangle(0, 0, 10, 10), {}}, 0.0), {"buildings[0].height = 0"});
  expect_error(one({rectangle(0, 0, 10, 10), {}}, std::nan("")), {"buildings[0].height = nan"});
  expect_error(one({rectangle(0, 0, 10, 10), {rectangle(5, 5, 15, 8)}}, 5.0),
               {"buildings[0].footprint.holes[0]", "inside the outer ring"});
  expect_error(one({rectangle(0, 0, 10, 10), {rectangle(20, 20, 25, 25)}}, 5.0), {"holes[0]", "inside the outer ring"});
  expect_error(one({rectangle(0, 0, 10, 10), {rectangle(1, 1, 5, 5), rectangle(4, 4, 6, 6)}}, 5.0),
               {"holes[1]", "overlaps buildings[0].footprint.holes[0]"});
  expect_error(one({{Vec2(0, 0), Vec2(std::nan(""), 0), Vec2(0, 1)}, {}}, 5.0), {"footprint.outer[1]", "finite"});
  expect_error([] { Environment::from_buildings({}); }, {"buildings", "at least one"});
}

TEST(Buildings, OverlapRules) {
  // Touching walls and a shared corner are fine.
  EXPECT_NO_THROW(Environment::from_buildings({{{rectangle(0, 0, 10, 10), {}}, 5.0, 0},
                                               {{rectangle(10, 0, 20, 10), {}}, 9.0, 1},
                                               {{rectangle(20, 10, 30, 20), {}}, 9.0, 2}}));
  // Approximate walls: a 0.01 m x 10 m sliver (0.1 m^2) is within the tolerance.
  EXPECT_NO_THROW(Environment::from_buildings({{{rectangle(0, 0, 10, 10), {}}, 5.0, 0},
                                               {{rectangle(9.99, 0, 20, 10), {}}, 5.0, 1}}));
  expect_error(
      [] {
        Environment::from_buildings({{{rectangle(0, 0, 10, 10), {}}, 5.0, 4}, {{rectangle(5, 5, 15, 15), {}}, 5.0, 9}});
      },
      {"buildings[0] (id 4) and buildings[1] (id 9) overlap", "shared area = 25", "disjoint interiors"});
  // A building part inside its outline adds nothing when it is not taller; a taller one would.
  EXPECT_NO_THROW(Environment::from_buildings({{{rectangle(0, 0, 10, 10), {}}, 20.0, 0},
                                               {{rectangle(2, 2, 5, 5), {}}, 20.0, 1}}));
  expect_error(
      [] {
        Environment::from_buildings({{{rectangle(0, 0, 10, 10), {}}, 20.0, 0}, {{rectangle(2, 2, 5, 5), {}}, 50.0, 1}});
      },
      {"overlap", "shared area = 9"});
  // A building standing in another's courtyard does not overlap it.
  EXPECT_NO_THROW(Environment::from_buildings({{{rectangle(0, 0, 30, 30), {rectangle(10, 10, 20, 20)}}, 20.0, 0},
                                               {{rectangle(12, 12, 18, 18), {}}, 50.0, 1}}));
}

TEST(Buildings, RaisedBaseIsASolidFromItsBaseToItsTop) {
  const Environment env = Environment::from_buildings({{{rectangle(0, 0, 10, 20), {}}, 30.0, 7, 18.0}});
  expect_closed_oriented(env.mesh());
  EXPECT_NEAR(signed_volume(env.mesh()), 10 * 20 * 12.0, 1e-9);
  EXPECT_DOUBLE_EQ(env.mesh().vertices.col(2).minCoeff(), 18.0);
  EXPECT_DOUBLE_EQ(env.ground_level(), 0.0);
  EXPECT_EQ(env.min_heights(), std::vector<double>{18.0});
  auto one = [](double base) { return [base] { Environment::from_buildings({{{rectangle(0, 0, 10, 10), {}}, 30.0, 0, base}}); }; };
  expect_error(one(-1.0), {"buildings[0].min_height = -1", ">= 0"});
  expect_error(one(std::nan("")), {"buildings[0].min_height = nan"});
  expect_error(one(30.0), {"buildings[0].min_height = 30", "below the top", "buildings[0].height = 30"});
  // Stacked parts share a footprint, not a volume; overlapping heights still overlap.
  EXPECT_NO_THROW(Environment::from_buildings({{{rectangle(0, 0, 10, 10), {}}, 18.0, 0},
                                               {{rectangle(0, 0, 10, 10), {}}, 30.0, 1, 18.0}}));
  expect_error([] {
    Environment::from_buildings({{{rectangle(0, 0, 10, 10), {}}, 20.0, 0}, {{rectangle(0, 0, 10, 10), {}}, 30.0, 1, 18.0}});
  }, {"overlap"});
}

TEST(Roads, OneWayEdgesAreDrivenTheirWayOnly) {
  // A square block driven counter-clockwise only: 0 -> 3 goes round, 3 -> 0 is one edge.
  RoadNetwork roads{{Vec2(0, 0), Vec2(100, 0), Vec2(100, 100), Vec2(0, 100)}, {{0, 1}, {1, 2}, {2, 3}, {3, 0}},
                    {true, true, true, true}};
  EXPECT_EQ(shortest_route(roads, 0, 3), (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(shortest_route(roads, 3, 0), (std::vector<int>{3, 0}));
  expect_error([&] { PoiPath::from_nodes(roads, {0, 3}, 5.0); }, {"nodes[1] = 3", "one-way the other way"});
  roads.oneway = {true, false, false, false};
  EXPECT_EQ(shortest_route(roads, 0, 3), (std::vector<int>{0, 3}));
  const RoadNetwork single{{Vec2(0, 0), Vec2(100, 0)}, {{0, 1}}, {true}};
  expect_error([&] { shortest_route(single, 1, 0); }, {"to = 0", "respects one-way streets"});
  expect_error([] { validate_road_network(RoadNetwork{{Vec2(0, 0), Vec2(1, 0)}, {{0, 1}}, {true, false}}); },
               {"roads.oneway", "one flag per edge (1)"});
}

std::string feature(const std::string& coordinates, const std::string& properties,
                    const std::string& type = "Polygon") {
  return R"({"type": "Feature", "properties": )" + properties + R"(, "geometry": {"type": ")" + type +
         R"(", "coordinates": )" + coordinates + "}}";
}

std::string collection(const std::vector<std::string>& features) {
  std::string text = R"({"type": "FeatureCollection", "features": [)";
  for (std::size_t i = 0; i < features.size(); ++i) text += (i ? ", " : "") + features[i];
  return text + "]}";
}

const std::string kSquare = "[[[0,0],[10,0],[10,10],[0,10],[0,0]]]";

TEST(GeoJson, ReadsHeightsLevelsIdsHolesAndMultiPolygons) {
  TempDir dir;
  const std::string path = dir.write(
      "city.geojson",
      collection({feature(kSquare, R"({"id": 40, "height": 12.5})"),
                  feature("[[[20,0],[20,10],[30,10],[30,0],[20,0]]]", R"({"building:levels": 4})"),  // clockwise
                  feature("[[[40,0],[70,0],[70,30],[40,30]], [[50,10],[60,10],[60,20],[50,20]]]", R"({"height": "7 m"})"),
                  feature("[[[[80,0],[90,0],[90,10],[80,10]]], [[[90,0],[100,0],[100,10],[90,10]]]]",
                          R"({"height": 3})", "MultiPolygon")}));
  const Environment env = Environment::from_geojson(path);
  ASSERT_EQ(env.num_buildings(), 5u);
  EXPECT_EQ(env.buildings()[0].id, 40);
  EXPECT_DOUBLE_EQ(env.buildings()[0].height, 12.5);
  EXPECT_EQ(env.buildings()[1].id, 1);  // feature index
  EXPECT_DOUBLE_EQ(env.buildings()[1].height, 12.0);
  EXPECT_GT(signed_area(env.buildings()[1].footprint.outer), 0.0);
  EXPECT_EQ(env.buildings()[0].footprint.outer.size(), 4u);  // closing repeat dropped
  EXPECT_DOUBLE_EQ(area(env.buildings()[2].footprint), 800.0);
  EXPECT_EQ(env.buildings()[3].id, 3);
  EXPECT_EQ(env.buildings()[4].id, 3);
  expect_closed_oriented(env.mesh());
  EXPECT_NEAR(signed_volume(env.mesh()), 100 * 12.5 + 100 * 12.0 + 800 * 7.0 + 200 * 3.0, 1e-9);
}

TEST(GeoJson, BadFilesNameTheFieldAndValue) {
  TempDir dir;
  auto load = [](const std::string& path) { return [path] { Environment::from_geojson(path); }; };
  expect_error(load(dir.write("missing/none.geojson", "")), {"path", "no such GeoJSON file"});
  expect_error(load((fs::temp_directory_path() / "vistrack_no_such_file.geojson").string()), {"no such GeoJSON file"});
  expect_error(load(dir.write("empty.geojson", "  \n")), {"empty"});
  expect_error(load(dir.write("broken.geojson", "{\"type\": ")), {"not valid JSON"});
  expect_error(load(dir.write("point.geojson", R"({"type": "Feature"})")), {"type = \"Feature\"", "FeatureCollection"});
  expect_error(load(dir.write("none.geojson", collection({}))), {"features", "no buildings"});
  expect_error(load(dir.write("h.geojson", collection({feature(kSquare, R"({"height": 5})"),
                                                      feature("[[[20,0],[30,0],[30,10]]]", R"({"height": -3})")}))),
               {"features[1].properties.height = -3"});
  expect_error(load(dir.write("nan.geojson", collection({feature(kSquare, R"({"height": "NaN"})")}))),
               {"features[0].properties.height = nan"});
  expect_error(load(dir.write("word.geojson", collection({feature(kSquare, R"({"height": "tall"})")}))),
               {"features[0].properties.height = \"tall\""});
  expect_error(load(dir.write("noh.geojson", collection({feature(kSquare, R"({"name": "x"})")}))),
               {"features[0].properties.height = missing"});
  expect_error(load(dir.write("lv.geojson", collection({feature(kSquare, R"({"building:levels": 0})")}))),
               {"features[0].properties.building:levels = 0"});
  expect_error(load(dir.write("two.geojson", collection({feature("[[[0,0],[1,1],[0,0]]]", R"({"height": 5})")}))),
               {"features[0].geometry.coordinates[0]", "at least 3"});
  expect_error(load(dir.write("bow.geojson", collection({feature("[[[0,0],[10,10],[10,0],[0,10]]]", R"({"height": 5})")}))),
               {"features[0].geometry.coordinates[0]", "self-intersecting"});
  expect_error(load(dir.write("hole.geojson",
                              collection({feature("[[[0,0],[10,0],[10,10],[0,10]], [[20,20],[25,20],[25,25]]]",
                                                  R"({"height": 5})")}))),
               {"features[0].geometry.coordinates[1]", "inside the outer ring"});
  expect_error(load(dir.write("mp.geojson", collection({feature("[[[[0,0],[10,0],[10,10]]], [[[0,0],[1,0]]]]",
                                                               R"({"height": 5})", "MultiPolygon")}))),
               {"features[0].geometry.coordinates[1][0]", "at least 3"});
  expect_error(load(dir.write("line.geojson", collection({feature("[[0,0],[1,1]]", R"({"height": 5})", "LineString")}))),
               {"features[0].geometry.type = \"LineString\""});
  expect_error(load(dir.write("ov.geojson", collection({feature(kSquare, R"({"height": 5, "id": 11})"),
                                                       feature("[[[5,5],[15,5],[15,15],[5,15]]]", R"({"height": 5})")}))),
               {"features[0] (id 11) and features[1] (id 1) overlap", "shared area = 25"});
  expect_error(load(dir.write("deg.geojson", collection({feature("[[[-80.8403,35.2249],[-80.8402,35.2249],[-80.8402,35.2250]]]",
                                                                R"({"height": 5})")}))),
               {"features[*].geometry.coordinates = longitude/latitude degrees", "no projection"});
}

// A stand-in projection for the plumbing (the real one is pyproj's, tested in Python): metres per
// degree of a sphere, east scaled by cos(latitude of the origin). Counts its calls.
struct SphereProjection {
  int* calls;
  Points2 operator()(const Points2& lon_lat, const GeodeticPoint& origin) const {
    ++*calls;
    const double metres_per_degree = 6371000.0 * kPi / 180.0;
    Points2 local(lon_lat.rows(), 2);
    local.col(0) = (lon_lat.col(0).array() - origin.longitude) * metres_per_degree * std::cos(origin.latitude * kPi / 180.0);
    local.col(1) = (lon_lat.col(1).array() - origin.latitude) * metres_per_degree;
    return local;
  }
};

TEST(GeoJson, LongitudeLatitudeIsProjectedAboutTheGivenOriginOrTheBoundingBoxCentre) {
  TempDir dir;
  // Two 0.0001-degree squares (about 9 m x 11 m in Charlotte) side by side, 0.0002 degree apart.
  const std::string path = dir.write(
      "lonlat.geojson",
      collection({feature("[[[-80.8404,35.2248],[-80.8403,35.2248],[-80.8403,35.2249],[-80.8404,35.2249],[-80.8404,35.2248]]]",
                          R"({"height": 20})"),
                  feature("[[[-80.8401,35.2248],[-80.8400,35.2248],[-80.8400,35.2249],[-80.8401,35.2249]]]",
                          R"({"height": 30})")}));
  int calls = 0;
  GeoJsonOptions options;
  options.project = SphereProjection{&calls};
  const Environment centred = Environment::from_geojson(path, options);
  EXPECT_EQ(calls, 1);  // every point in one call
  ASSERT_TRUE(centred.origin().has_value());
  EXPECT_DOUBLE_EQ(centred.origin()->longitude, -80.8402);
  EXPECT_DOUBLE_EQ(centred.origin()->latitude, 35.22485);
  EXPECT_DOUBLE_EQ(centred.origin()->altitude, 0.0);
  const double metres_per_degree = 6371000.0 * kPi / 180.0;
  EXPECT_NEAR(centred.bounds().min.x(), -0.0002 * metres_per_degree * std::cos(35.22485 * kPi / 180.0), 1e-6);
  EXPECT_NEAR(centred.bounds().max.y(), 0.00005 * metres_per_degree, 1e-6);
  EXPECT_EQ(centred.buildings()[0].footprint.outer.size(), 4u);  // closing repeat dropped after projecting

  options.origin = GeodeticPoint{35.2249, -80.8403, 230.0};
  const Environment anchored = Environment::from_geojson(path, options);
  EXPECT_DOUBLE_EQ(anchored.origin()->altitude, 230.0);
  EXPECT_NEAR(anchored.buildings()[0].footprint.outer[0].x(), -0.0001 * metres_per_degree * std::cos(35.2249 * kPi / 180.0), 1e-6);
  EXPECT_NEAR(anchored.bounds().max.y(), 0.0, 1e-6);
  EXPECT_EQ(calls, 2);
}

TEST(GeoJson, MetresKeepTheGivenOriginAndImplausibleCoordinatesAreErrors) {
  TempDir dir;
  int calls = 0;
  GeoJsonOptions options{GeodeticPoint{35.2249, -80.8403, 0.0}, SphereProjection{&calls}};
  const Environment metric = Environment::from_geojson(dir.write("m.geojson", collection({feature(kSquare, R"({"height": 5})")})), options);
  EXPECT_EQ(calls, 0);
  ASSERT_TRUE(metric.origin().has_value());
  EXPECT_DOUBLE_EQ(metric.origin()->latitude, 35.2249);
  EXPECT_DOUBLE_EQ(metric.bounds().max.x(), 10.0);
  EXPECT_FALSE(Environment::from_geojson(dir.write("n.geojson", collection({feature(kSquare, R"({"height": 5})")}))).origin());

  auto load = [&](const std::string& name, const std::string& coordinates) {
    return [&, name, coordinates] {
      Environment::from_geojson(dir.write(name, collection({feature(coordinates, R"({"height": 5})")})), options);
    };
  };
  // Under a unit wide but no longitude/latitude: neither.
  expect_error(load("small.geojson", "[[[500.1,0.1],[500.5,0.1],[500.5,0.5]]]"),
               {"features[*].geometry.coordinates = x in [500.1, 500.5]", "neither WGS84 longitude/latitude"});
  // UTM zone 17 metres around Charlotte: metres, but not a local frame.
  expect_error(load("utm.geojson", "[[[514500,3897900],[514600,3897900],[514600,3898000]]]"),
               {"x in [514500, 514600]", "neither", "UTM"});
  options.origin = GeodeticPoint{95.0, 0.0, 0.0};
  expect_error(load("m.geojson", kSquare), {"origin.latitude = 95", "[-90, 90]"});
  options.origin = GeodeticPoint{0.0, 181.0, 0.0};
  expect_error(load("m.geojson", kSquare), {"origin.longitude = 181"});
  // A projection that returns the wrong shape is caught.
  options.origin.reset();
  options.project = [](const Points2&, const GeodeticPoint&) { return Points2(1, 2); };
  expect_error(load("deg.geojson", "[[[-80.8403,35.2249],[-80.8402,35.2249],[-80.8402,35.2250]]]"),
               {"project = 1 rows", "one finite (east, north) row per input point (3)"});
}

TEST(GeoJson, Charlotte) {
  VISTRACK_REQUIRE_DATA(path, "charlotte/buildings.geojson");
  const Environment env = Environment::from_geojson(path);
  EXPECT_EQ(env.num_buildings(), 167u);
  EXPECT_NEAR(env.max_height(), 265.0, 1e-9);
  EXPECT_DOUBLE_EQ(env.ground_level(), 0.0);
  expect_closed_oriented(env.mesh());
  double expected = 0.0;
  for (const Building& b : env.buildings()) {
    EXPECT_GT(signed_area(b.footprint.outer), 0.0);
    expected += area(b.footprint) * b.height;
  }
  EXPECT_NEAR(signed_volume(env.mesh()), expected, 1e-9 * expected);
}

TEST(Mesh, Charlotte) {
  VISTRACK_REQUIRE_DATA(path, "charlotte/uptown_charlotte.obj");
  const Environment env = Environment::from_mesh(path, "y");
  EXPECT_GT(env.num_triangles(), 7800u);  // 7890 faces in the file, a few degenerate ones dropped
  EXPECT_LE(env.num_triangles(), 7890u);
  EXPECT_NEAR(env.max_height(), 265.0, 0.1);
  EXPECT_NEAR(env.ground_level(), 0.0, 1e-9);
  // North is -Z in the file: the OBJ's z range [-600, 600] becomes y.
  EXPECT_NEAR(env.bounds().min.y(), -600.0, 1.0);
  EXPECT_NEAR(env.bounds().max.y(), 600.0, 1.0);
  EXPECT_TRUE(env.buildings().empty());
}

TEST(Mesh, CampusHasTerrainBelowZero) {
  VISTRACK_REQUIRE_DATA(path, "campus/campus.obj");
  const Environment env = Environment::from_mesh(path, "y");
  EXPECT_GT(env.num_triangles(), 2000u);
  EXPECT_NEAR(env.ground_level(), -8.6, 0.1);  // terrain is not flat (data README)
  EXPECT_NEAR(env.bounds().max.z(), 31.4, 0.1);  // tree boxes up to about 31 m
}

TEST(Mesh, TriangulatesNonConvexFacesMergesPointsAndMapsYUp) {
  TempDir dir;
  // An L-shaped hexagon (area 75) as one face, then a triangle whose corners repeat points of
  // the hexagon under new indices, and a degenerate (collinear) triangle.
  const std::string obj =
      "v 0 0 0\nv 10 0 0\nv 10 5 0\nv 5 5 0\nv 5 10 0\nv 0 10 0\n"
      "v 10 0 0\nv 10 5 0\nv 10 0 7\nv 20 0 0\nv 30 0 0\n"
      "f 1 2 3 4 5 6\nf 7 9 8\nf 2 10 11\n";
  const std::string path = dir.write("l.obj", obj);
  const Environment env = Environment::from_mesh(path, "z");
  EXPECT_EQ(env.num_triangles(), 5u);  // 4 for the hexagon, 1 wall, the degenerate one dropped
  double area_z = 0.0;
  for (Eigen::Index f = 0; f < env.mesh().faces.rows(); ++f) {
    const Vec3 a = env.mesh().vertices.row(env.mesh().faces(f, 0)).transpose();
    const Vec3 b = env.mesh().vertices.row(env.mesh().faces(f, 1)).transpose();
    const Vec3 c = env.mesh().vertices.row(env.mesh().faces(f, 2)).transpose();
    area_z += 0.5 * (b - a).cross(c - a).z();  // counter-clockwise in the file: positive
  }
  EXPECT_NEAR(area_z, 75.0, 1e-12);
  // Duplicate points merged: the wall uses the hexagon's vertex indices.
  std::set<int> used;
  for (Eigen::Index f = 0; f < env.mesh().faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) used.insert(env.mesh().faces(f, k));
  EXPECT_EQ(used.size(), 7u);

  const Environment y_up = Environment::from_mesh(path, "y");
  // (x, y, z) -> (x, -z, y): the wall's top vertex (10, 0, 7) becomes (10, -7, 0).
  EXPECT_NEAR(y_up.bounds().min.y(), -7.0, 1e-12);
  EXPECT_NEAR(y_up.bounds().max.z(), 10.0, 1e-12);
}

TEST(Mesh, BadInputNamesTheField) {
  TempDir dir;
  const std::string good = dir.write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  expect_error([&] { Environment::from_mesh(good, "x"); }, {"up = \"x\"", "\"z\" or \"y\""});
  expect_error([&] { Environment::from_mesh(good, "Y-up"); }, {"up = \"Y-up\""});
  expect_error([&] { Environment::from_mesh(dir.write("e.obj", ""), "z"); }, {"empty"});
  expect_error([&] { Environment::from_mesh((fs::temp_directory_path() / "vistrack_none.obj").string(), "z"); },
               {"path", "no such mesh file"});
  expect_error([&] { Environment::from_mesh(dir.write("n.obj", "# nothing\nv 0 0 0\n"), "z"); }, {"path"});
  expect_error([&] { Environment::from_mesh(dir.write("t.xyz", "v 0 0 0\n"), "z"); }, {"cannot read"});
  expect_error([&] { Environment::from_mesh(dir.write("d.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n"), "z"); },
               {"degenerate"});
}

TEST(Demo, DeterministicDowntownWithClearRoads) {
  const Environment a = Environment::demo();
  const Environment b = Environment::demo();
  EXPECT_EQ(a.fingerprint(), b.fingerprint());
  EXPECT_GE(a.num_buildings(), 150u);
  double low = 1e9, high = 0.0;
  bool has_hole = false, has_l_shape = false;
  for (const Building& building : a.buildings()) {
    low = std::min(low, building.height);
    high = std::max(high, building.height);
    has_hole |= !building.footprint.holes.empty();
    has_l_shape |= building.footprint.outer.size() == 6;
  }
  EXPECT_DOUBLE_EQ(low, 10.0);
  EXPECT_DOUBLE_EQ(high, 150.0);
  EXPECT_TRUE(has_hole);
  EXPECT_TRUE(has_l_shape);
  EXPECT_NEAR(a.bounds().max.x() - a.bounds().min.x(), 800.0, 40.0);
  EXPECT_NEAR(a.bounds().max.y() - a.bounds().min.y(), 800.0, 40.0);
  expect_closed_oriented(a.mesh());
  // Independent oracle for the road check: sample every edge densely; no sample is inside a
  // footprint (the check itself runs in set_roads when the city is built).
  const RoadNetwork& roads = a.roads();
  EXPECT_EQ(roads.nodes.size(), 81u);
  EXPECT_EQ(roads.edges.size(), 144u);
  for (const auto& [i, j] : roads.edges) {
    const Vec2 p = roads.nodes[static_cast<std::size_t>(i)], q = roads.nodes[static_cast<std::size_t>(j)];
    for (int s = 0; s <= 200; ++s) {
      const Vec2 x = p + (q - p) * (s / 200.0);
      for (const Building& building : a.buildings())
        ASSERT_FALSE(contains(building.footprint, x)) << "edge " << i << "-" << j << " in building " << building.id;
    }
  }
}

TEST(Roads, EdgeThroughABuildingIsAnErrorAlongAWallIsNot) {
  Environment env = Environment::from_buildings({{{rectangle(0, 0, 10, 10), {}}, 5.0, 3},
                                                 {{rectangle(20, 0, 30, 10), {rectangle(22, 2, 28, 8)}}, 5.0, 8}});
  const std::uint64_t without_roads = env.fingerprint();
  RoadNetwork roads{{Vec2(-5, 5), Vec2(15, 5), Vec2(0, -5), Vec2(0, 20), Vec2(25, 5), Vec2(26, 6)}, {{0, 1}}};
  expect_error([&] { env.set_roads(roads); }, {"roads.edges[0] = (0, 1)", "building id 3", "buildings[0]"});
  roads.edges = {{2, 3}};  // runs along the wall x = 0
  EXPECT_NO_THROW(env.set_roads(roads));
  EXPECT_EQ(env.roads().edges.size(), 1u);
  EXPECT_NE(env.fingerprint(), without_roads);  // the roads are part of the content hash
  roads.edges = {{4, 5}};  // inside the courtyard
  EXPECT_NO_THROW(env.set_roads(roads));
  roads.edges = {{1, 4}};  // from outside into the courtyard through the wall
  expect_error([&] { env.set_roads(roads); }, {"roads.edges[0] = (1, 4)", "building id 8"});
  roads.edges = {{2, 2}};
  expect_error([&] { env.set_roads(roads); }, {"roads.edges[0] = (2, 2)", "two different nodes"});
  roads.edges = {{0, 9}};
  expect_error([&] { env.set_roads(roads); }, {"roads.edges[0] = (0, 9)", "out of range"});
  roads.nodes[0] = Vec2(std::nan(""), 0);
  expect_error([&] { env.set_roads(roads); }, {"roads.nodes[0][0] = nan"});
}

// Brute-force oracle: Floyd-Warshall distances on random graphs.
TEST(Roads, ShortestRouteMatchesFloydWarshall) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coordinate(0.0, 100.0);
  for (int trial = 0; trial < 50; ++trial) {
    RoadNetwork roads;
    const int n = 12;
    for (int i = 0; i < n; ++i) roads.nodes.emplace_back(coordinate(rng), coordinate(rng));
    std::vector<std::vector<double>> d(n, std::vector<double>(n, std::numeric_limits<double>::infinity()));
    for (int i = 0; i < n; ++i) d[static_cast<std::size_t>(i)][static_cast<std::size_t>(i)] = 0.0;
    for (int k = 0; k < 20; ++k) {
      const int a = static_cast<int>(rng() % n), b = static_cast<int>(rng() % n);
      if (a == b) continue;
      roads.edges.emplace_back(a, b);
      const double length = (roads.nodes[static_cast<std::size_t>(a)] - roads.nodes[static_cast<std::size_t>(b)]).norm();
      auto& ab = d[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)];
      ab = std::min(ab, length);
      d[static_cast<std::size_t>(b)][static_cast<std::size_t>(a)] = ab;
    }
    for (std::size_t k = 0; k < static_cast<std::size_t>(n); ++k)
      for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i)
        for (std::size_t j = 0; j < static_cast<std::size_t>(n); ++j) d[i][j] = std::min(d[i][j], d[i][k] + d[k][j]);
    for (int goal = 1; goal < n; ++goal) {
      if (!std::isfinite(d[0][static_cast<std::size_t>(goal)])) {
        expect_error([&] { shortest_route(roads, 0, goal); }, {"to = " + std::to_string(goal), "no road route"});
        continue;
      }
      const std::vector<int> route = shortest_route(roads, 0, goal);
      ASSERT_EQ(route.front(), 0);
      ASSERT_EQ(route.back(), goal);
      const PoiPath path = PoiPath::from_nodes(roads, route, 1.0);  // also checks edges exist
      EXPECT_NEAR(path.length(), d[0][static_cast<std::size_t>(goal)], 1e-9);
    }
  }
  expect_error([] { shortest_route(RoadNetwork{{Vec2(0, 0)}, {}}, 0, 3); }, {"to = 3"});
}

TEST(PoiPath, AnalyticPositionsVelocitiesAndHeadings) {
  Eigen::MatrixXd waypoints(4, 3);
  waypoints << 0, 0, 1, 30, 40, 1, 30, 40, 1, 30, 0, 2;  // a repeated point is dropped
  const PoiPath poi(waypoints, 5.0);
  EXPECT_EQ(poi.waypoints().rows(), 3);
  EXPECT_DOUBLE_EQ(poi.length(), 90.0);
  EXPECT_DOUBLE_EQ(poi.duration(), 18.0);
  EXPECT_NEAR((poi.position(5.0) - Vec3(15, 20, 1)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((poi.position(14.0) - Vec3(30, 20, 1.5)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((poi.position(-3.0) - Vec3(0, 0, 1)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((poi.position(99.0) - Vec3(30, 0, 2)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((poi.velocity(10.0) - Vec2(0, -5)).norm(), 0.0, 1e-12);  // right-continuous at t_1
  EXPECT_NEAR(poi.heading(2.0), std::atan2(4.0, 3.0), 1e-12);
  // Constant speed: finite differences of the position have norm v_g inside each segment.
  for (double t = 0.5; t < 18.0; t += 0.5) {
    if (std::abs(t - 10.0) < 0.01) continue;
    EXPECT_NEAR((poi.position(t + 1e-4) - poi.position(t - 1e-4)).head<2>().norm() / 2e-4, 5.0, 1e-6);
  }
}

TEST(PoiPath, FromNodesAndBadInput) {
  RoadNetwork roads{{Vec2(0, 0), Vec2(100, 0), Vec2(100, 50)}, {{0, 1}, {1, 2}}};
  const PoiPath poi = PoiPath::from_nodes(roads, {0, 1, 2}, 5.0);
  EXPECT_DOUBLE_EQ(poi.length(), 150.0);
  expect_error([&] { PoiPath::from_nodes(roads, {0, 2}, 5.0); }, {"nodes[1] = 2", "no road edge"});
  expect_error([&] { PoiPath::from_nodes(roads, {0, 7}, 5.0); }, {"nodes[1] = 7"});
  expect_error([&] { PoiPath::from_nodes(roads, {0}, 5.0); }, {"nodes = 1"});
  expect_error([&] { PoiPath::from_nodes(roads, {0, 1}, -1.0); }, {"speed = -1"});
}

TEST(PoiPath, CsvFilesIncludingNoTrailingNewline) {
  TempDir dir;
  const PoiPath a = PoiPath::from_csv(dir.write("a.csv", "x,y\n0,0\n3,4"), 1.0);  // header, no final newline
  EXPECT_EQ(a.waypoints().rows(), 2);
  EXPECT_DOUBLE_EQ(a.length(), 5.0);
  expect_error([&] { PoiPath::from_csv(dir.write("b.csv", "0,0\n0,0\n"), 1.0); }, {"waypoints", "two distinct"});
  expect_error([&] { PoiPath::from_csv(dir.write("c.csv", ""), 1.0); }, {"no waypoints"});
  expect_error([&] { PoiPath::from_csv(dir.write("d.csv", "0,0\n1,x\n"), 1.0); }, {"d.csv:2 = 'x'"});
}

TEST(PoiPath, RealPaths) {
  VISTRACK_REQUIRE_DATA(slow, "charlotte/paths/paper_slow.csv");
  const PoiPath poi = PoiPath::from_csv(slow, 5.0);  // the file has no trailing newline
  ASSERT_EQ(poi.waypoints().rows(), 3);
  EXPECT_NEAR((poi.waypoints().row(2) - Eigen::RowVector3d(20.0, -35.0, 0.5)).norm(), 0.0, 1e-12);
  const double expected = std::hypot(100.0, 90.0) + std::hypot(70.0, 80.0);
  EXPECT_NEAR(poi.length(), expected, 1e-9);
  for (const char* name : {"charlotte/paths/paper_small.csv", "charlotte/paths/3d.csv", "charlotte/paths/3d_dense.csv",
                           "campus/poi_path.csv", "campus/flight_test_path.csv"}) {
    const std::string path = testing::shared_data(name);
    if (path.empty()) continue;
    const PoiPath p = PoiPath::from_csv(path, 1.0);
    EXPECT_GE(p.waypoints().rows(), 2) << name;
    EXPECT_GT(p.length(), 0.0) << name;
  }
}

}  // namespace
}  // namespace vistrack
