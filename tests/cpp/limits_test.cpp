// The valid ranges of vistrack/limits.hpp, checked where input enters each area, and the C++ side
// of the hardening reproducers: no input crashes, none comes back as NaN or inf, every refusal is a
// vistrack::Error naming the field, the value and the range. Then 10^6 random Dubins and
// path-to-circle problems and 2 10^5 intercepts over the whole documented range: no NaN, every
// endpoint reached.
#include "vistrack/limits.hpp"

#include <gtest/gtest.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <stdexcept>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <limits>
#include <mutex>
#include <string>

#include "dubins/path_integration.hpp"
#include "test_data.hpp"
#include "vistrack/dubins.hpp"
#include "vistrack/environment.hpp"
#include "vistrack/flight.hpp"
#include "vistrack/ode.hpp"
#include "vistrack/orbit.hpp"
#include "vistrack/simulate.hpp"
#include "vistrack/visibility.hpp"
#include "vistrack/volume.hpp"

namespace vistrack {
namespace {

using testing::expect_error;
using testing::TempDir;

constexpr double kInf = std::numeric_limits<double>::infinity();
const double kNaN = std::nan("");

TEST(Limits, MessagesSayTheRange) {
  expect_error([] { require_length(0.0, "rho"); }, {"rho = 0", "[1e-06, 1e+07] m"});
  expect_error([] { require_coordinate(kNaN, "x"); }, {"x = nan", "[-1e+07, 1e+07] m"});
  expect_error([] { require_speed(kInf, "v"); }, {"v = inf", "m/s"});
  expect_error([] { require_angle(-1e10, "psi"); }, {"psi = -1e+10", "[-1e+09, 1e+09] rad"});
  expect_error([] { require_threads(100000, "threads"); }, {"threads = 100000", "[1, 1024]"});
  require_length(1e-6, "rho");  // the ends are inside
  require_length(1e7, "rho");
  require_coordinate(-1e7, "x");
  require_threads(0, "threads");
}

TEST(Limits, PrintableKeepsMessagesUtf8) {
  EXPECT_EQ(detail::printable("ab\xff\n"), "'ab\\xff\\x0a'");
  EXPECT_EQ(detail::printable(std::string(50, 'x')), "'" + std::string(40, 'x') + "...'");
}

// --- Issue 18's reproducers, C++ side ---------------------------------------------------------

TEST(Limits, DubinsBatchWithHugeThreadCountsRefusesInsteadOfCrashing) {
  Points3 q0 = Points3::Zero(4, 3), q1 = Points3::Ones(4, 3);
  expect_error([&] { dubins_shortest_lengths(q0, q1, 2.0, 100000); }, {"threads = 100000"});
  expect_error([&] { dubins_shortest_lengths(q0, q1, 2.0, -1); }, {"threads = -1"});
  const DubinsBatch many = dubins_shortest_lengths(q0, q1, 2.0, 1024);  // the largest accepted
  EXPECT_TRUE(std::isfinite(many.lengths[0]));
}

TEST(Limits, DubinsRefusesWhatWouldGiveNaNOrInf) {
  const Configuration a{0, 0, 0}, b{10, 5, 1.0};
  expect_error([&] { dubins_shortest_path(a, b, 5e-324); }, {"rho = 4.94", "[1e-06, 1e+07] m"});
  expect_error([&] { dubins_shortest_path(a, b, 1e-300); }, {"rho"});
  expect_error([&] { dubins_shortest_path(a, b, 1e308); }, {"rho = 1e+308"});
  expect_error([&] { dubins_shortest_path(a, {1e300, 5, 1}, 1.0); }, {"q1.x = 1e+300"});
  expect_error([&] { dubins_shortest_path(a, {0, 0, kInf}, 1.0); }, {"q1.psi = inf"});
  TargetCircle circle;
  circle.center = Vec2(10, 0);
  circle.radius = 1e300;
  expect_error([&] { dubins_path_to_circle(a, 1.0, circle, 0.5); }, {"radius = 1e+300"});
  InterceptProblem problem;
  problem.target_speed = 5e-324;
  expect_error([&] { intercept_circle(problem); }, {"target_speed"});
}

TEST(Limits, PoiPathAndGeometryRefuseHugeCoordinates) {
  Eigen::MatrixXd far(2, 2);
  far << -1e308, 0, 1e308, 0;
  expect_error([&] { PoiPath(far, 5.0); }, {"waypoints[0][0] = -1e+308", "[-1e+07, 1e+07] m"});
  Eigen::MatrixXd fine(2, 2);
  fine << 0, 0, 10, 0;
  expect_error([&] { PoiPath(fine, 1e-300); }, {"speed = 1e-300", "m/s"});
  expect_error([] { wrap_to_pi(kInf); }, {"angle = inf"});
  expect_error([] { wrap_to_two_pi(kNaN); }, {"angle = nan"});
  const Polygon huge{{Vec2(-1e308, -1e308), Vec2(1e308, -1e308), Vec2(1e308, 1e308), Vec2(-1e308, 1e308)}, {}};
  expect_error([&] { max_inscribed_radius({huge}, Vec2(0, 0)); }, {"polygons[0]", "1e+308"});
}

TEST(Limits, RoadNetworksAreCheckedWhenTheyEnter) {
  RoadNetwork roads;
  roads.nodes = {Vec2(kNaN, 0), Vec2(1, 1)};
  roads.edges = {{0, 1}};
  expect_error([&] { validate_road_network(roads, ""); }, {"nodes[0][0] = nan"});
  roads.nodes[0] = Vec2(0, 0);
  roads.edges = {{0, 5}};
  expect_error([&] { validate_road_network(roads, ""); }, {"edges[0] = (0, 5)", "out of range [0, 2)"});
  roads.edges = {{1, 1}};
  expect_error([&] { validate_road_network(roads, ""); }, {"two different nodes"});
}

TEST(Limits, LoadersRefuseFoldersAndNonFiles) {
  TempDir dir;
  expect_error([&] { Environment::from_geojson(dir.path()); }, {"is a folder, not a GeoJSON file"});
  expect_error([&] { Environment::from_mesh(dir.path() + "/", "z"); }, {"is a folder, not a mesh file"});
  expect_error([&] { PoiPath::from_csv(dir.path(), 1.0); }, {"is a folder, not a CSV file"});
  expect_error([&] { read_volume_file(dir.path()); }, {"is a folder, not a VV file"});
  expect_error([&] { PoiPath::from_csv("/dev/null", 1.0); }, {"not a regular CSV file"});
}

// Issue 29: a value nested 100,000 deep crashed the quote of it in the message (recursive copy and
// dump); every JSON document is now refused past kMaxDocumentDepth while it is parsed, and a
// message quotes at most 40 characters of a value, however large.
TEST(Limits, JsonDocumentsAreBoundedInDepthAndQuotedShort) {
  TempDir dir;
  const auto collection = [&](const std::string& height) {
    return R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"height": )" + height +
           R"(}, "geometry": {"type": "Polygon", "coordinates": [[[0,0],[10,0],[10,10],[0,10]]]}}]})";
  };
  const auto nested = [](int depth) { return std::string(depth, '[') + std::string(depth, ']'); };
  const auto message_of = [](const std::function<void()>& load) {
    try {
      load();
    } catch (const Error& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  for (const int depth : {101, 100000})
    expect_error([&] { Environment::from_geojson(dir.write("deep.geojson", collection(nested(depth)))); },
                 {"deep.geojson: nested deeper than 100 levels"});
  // At the limit (the height list is 96 deep under 4 levels): parsed, then refused as a height,
  // its quote cut.
  expect_error([&] { Environment::from_geojson(dir.write("d.geojson", collection(nested(96)))); },
               {"features[0].properties.height = [[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[...", "expected a number"});
  std::string many = "[1";
  for (int i = 0; i < 100000; ++i) many += ",1";
  const std::string wide = message_of([&] { Environment::from_geojson(dir.write("w.geojson", collection(many + "]"))); });
  EXPECT_NE(wide.find("height = [1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1...: expected a number"), std::string::npos)
      << wide;
  const std::string text = std::string(100000, 'x');
  const std::string string = message_of([&] { Environment::from_geojson(dir.write("s.geojson", collection("\"" + text + "\""))); });
  EXPECT_NE(string.find("height = \"xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx...: expected a number"), std::string::npos) << string;
  // nlohmann's parse error quotes the token it stopped at: here 100,000 digits, cut in the message.
  const std::string digits = message_of([&] {
    Environment::from_geojson(dir.write("n.geojson", collection(std::string(100000, '1') + ".5")));
  });
  EXPECT_NE(digits.find("n.geojson: not valid JSON ("), std::string::npos) << digits.substr(0, 400);
  EXPECT_LT(digits.size(), 400u);
  expect_error([&] { orbit_plan_from_json(nested(101)); }, {"orbit plan JSON: nested deeper than 100 levels"});
}

TEST(Limits, LoadersNameWhatIsWrongInTheFile) {
  TempDir dir;
  const std::string square = R"([[[0,0],[10,0],[10,10],[0,10]]])";
  const auto collection = [&](const std::string& height) {
    return R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"height": )" + height +
           R"(}, "geometry": {"type": "Polygon", "coordinates": )" + square + "}}]}";
  };
  // 1e999 overflows a double while parsing: a VistrackError, not nlohmann's out_of_range.
  expect_error([&] { Environment::from_geojson(dir.write("big.geojson", collection("1e999"))); },
               {"not valid JSON", "number overflow"});
  expect_error([&] { Environment::from_geojson(dir.write("h.geojson", collection("1e300"))); },
               {"features[0].properties.height = 1e+300", "[1e-06, 1e+07] m"});
  expect_error([&] { Environment::from_geojson(dir.write("t.geojson", R"({"type": 5})")); },
               {"type = 5", "expected a GeoJSON FeatureCollection"});
  expect_error([&] {
    Environment::from_geojson(dir.write("g.geojson", R"({"type": "FeatureCollection", "features": [{"properties":
      {"height": 3}, "geometry": {"type": 7, "coordinates": []}}]})"));
  }, {"unexpected GeoJSON structure"});
  // A number in the first field makes the first line data: "0.5abc" is an error, not a header.
  expect_error([&] { PoiPath::from_csv(dir.write("a.csv", "0,0,0.5abc\n10,0,0.5\n"), 1.0); },
               {"a.csv:1 = '0.5abc'", "not a number"});
  expect_error([&] { PoiPath::from_csv(dir.write("u.csv", "0,0\n\xff\xfe,1\n"), 1.0); }, {"'\\xff\\xfe'"});
  EXPECT_EQ(PoiPath::from_csv(dir.write("h.csv", "x,y,z\n0,0,0.5\n10,0,0.5\n"), 1.0).waypoints().rows(), 2);
  expect_error([&] { Environment::from_mesh(dir.write("n.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n"), "z"); },
               {"n.obj:2", "vertex coordinate 'nan' is not finite"});
  expect_error([&] { Environment::from_mesh(dir.write("f.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"), "z"); },
               {"f.obj:4", "face corner '9' names no vertex"});
  expect_error([&] { Environment::from_mesh(dir.write("b.obj", "v 0 0 0\nv 1e300 0 0\nv 0 1 0\nf 1 2 3\n"), "z"); },
               {"vertices[1][0] = 1e+300"});
}

TEST(Limits, VolumeFilesAreCheckedBehindTheirChecksum) {
  TempDir dir;
  const Environment env = Environment::demo();
  VisibilityVolume vv = visibility_volume(env, Vec3(-290.0, -210.0, 0.5), 200.0, std::nullopt, 30.0);
  const std::string good = dir.path() + "/good.bin";
  write_volume_file(vv, good);
  EXPECT_EQ(read_volume_file(good)->volume, vv.volume);
  vv.d_max = kNaN;  // a file whose checksum is right but whose content is not
  write_volume_file(vv, dir.path() + "/nan.bin");
  expect_error([&] { read_volume_file(dir.path() + "/nan.bin"); }, {"nan.bin", "d_max = nan"});
  vv.d_max = 200.0;
  vv.far[3] = 1e300;
  write_volume_file(vv, dir.path() + "/far.bin");
  expect_error([&] { read_volume_file(dir.path() + "/far.bin"); }, {"near/far[3]", "[0, d_max]"});
  vv.far[3] = 0.0;
  vv.grid.num_azimuth = 7;
  expect_error([&] { write_volume_file(vv, dir.path() + "/grid.bin"); }, {"vv.near.size()"});
}

TEST(Limits, VisibilityVolumesRefuseHugeRanges) {
  const Environment env = Environment::demo();
  expect_error([&] { visibility_volume(env, Vec3(-290.0, -210.0, 0.5), 1e300); }, {"d_max = 1e+300"});
  expect_error([&] { visibility_volume(env, Vec3(1e300, 0.0, 0.5), 100.0); }, {"g[0] = 1e+300"});
  const VisibilityScene scene(env);
  expect_error([&] { scene.poi_on_surface(Vec3(0.0, 0.0, kInf)); }, {"g[2]"});
}

TEST(Limits, XorPerturbationIsANudge) {
  const Environment env = Environment::demo();
  const VisibilityVolume a = visibility_volume(env, Vec3(-290.0, -210.0, 0.5), 100.0, std::nullopt, 30.0);
  MeshXorOptions options;
  options.perturbation = 1e300;
  expect_error([&] { xor_volume(a, a, XorFrame::poi, XorMethod::mesh, options); },
               {"options.perturbation = 1e+300", "[0, 0.001] rad"});
  options.perturbation = 0.0;
  options.time_limit = 1e300;  // past 1e6 s the deadline overflows the clock
  expect_error([&] { xor_volume(a, a, XorFrame::poi, XorMethod::mesh, options); }, {"options.time_limit"});
}

TEST(Limits, GainsAndTolerancesHaveOneRangeEverywhere) {
  // limits.hpp's ranges, whichever entry point takes the value.
  EXPECT_NO_THROW(require_beta(limits::kMinGain, "b"));
  EXPECT_NO_THROW(require_beta(limits::kMaxBeta, "b"));
  expect_error([] { require_beta(2 * limits::kMaxBeta, "b"); }, {"b = 2000", "[1e-09, 1000] 1/m"});
  expect_error([] { require_heading_gain(0.0, "k"); }, {"k = 0", "[1e-09, 1e+06] 1/s"});
  expect_error([] { require_heading_gain(kNaN, "k"); }, {"k = nan"});
  expect_error([] { require_tolerances(1e-14, 1e-8, "x."); }, {"x.rtol = 1e-14", "[1e-13, 1]"});
  expect_error([] { require_tolerances(1e-6, 1e7, "x."); }, {"x.atol = 1e+07", "[1e-15, 1e+06]"});
  Control control;
  control.beta = 0.0;
  expect_error([&] { control.validate(); }, {"control.beta = 0"});
  SimulationOptions simulation;
  simulation.atol = 1e7;
  expect_error([&] { simulation.validate(); }, {"simulation.atol = 1e+07"});
  FlightOptions flight;
  flight.rtol = 2.0;  // was any positive number
  expect_error([&] { flight.validate(); }, {"rtol = 2", "[1e-13, 1]"});
  flight.rtol = 1e-6;
  flight.atol = 1e7;
  expect_error([&] { flight.validate(); }, {"atol = 1e+07"});
  OdeOptions ode;
  ode.atol = 1e7;  // was accepted up to 1e15
  expect_error([&] { ode.validate(); }, {"ode.atol = 1e+07"});
}

TEST(Limits, OdeTolerancesAreNamed) {
  OdeOptions options;
  options.rtol = 1e-300;
  const auto decay = [](double, const OdeVector<1>& y, OdeVector<1>& dy) { dy = -y; };
  OdeVector<1> y0;
  y0 << 1.0;
  expect_error([&] { solve_ode<1>(decay, 0.0, 1.0, y0, options); }, {"ode.rtol = 1e-300", "[1e-13, 1]"});
  options.rtol = 1e-6;
  options.atol = 1e-300;
  expect_error([&] { solve_ode<1>(decay, 0.0, 1.0, y0, options); }, {"ode.atol = 1e-300"});
  options.atol = 1e-8;
  options.fixed_step = 1e-12;
  expect_error([&] { solve_ode<1>(decay, 0.0, 1e3, y0, options); }, {"ode.fixed_step", "ode.max_steps"});
}

// A plan whose worst case exceeds planning.max_volumes is refused before any VV is computed.
TEST(Limits, WorkIsEstimatedBeforeAnyVolume) {
  Eigen::MatrixXd w(3, 2);
  w << -150, -45, -50, 45, 20, -35;  // paper_slow
  const PoiPath poi(w, 5.0);
  Planning planning;
  const WorkEstimate usual = estimate_work(poi, planning);
  EXPECT_GT(usual.volumes, 13.0);  // 12 initial intervals plus the end
  EXPECT_LT(usual.volumes, 300.0);
  // 16 bytes per corner, 56 per cell and the walls' 3000 sqrt(cells) (volume_bytes).
  EXPECT_NEAR(usual.bytes_per_volume, 16.0 * 181 * 360 + 56.0 * 180 * 360 + 3000.0 * std::sqrt(180.0 * 360.0), 1.0);
  planning.spacing = 0.001;
  planning.min_spacing = 0.001;
  const WorkEstimate tiny = estimate_work(poi, planning);
  EXPECT_NEAR(tiny.volumes, poi.length() / 0.001, 5.0);
  std::atomic<int> computed{0};
  VolumeCache cache([&](const Vec3&) -> VolumePtr {
    ++computed;
    return std::make_shared<const VisibilityVolume>();
  });
  const MetricFunction metric = [](const VisibilityVolume&, const VisibilityVolume&) { return 0.0; };
  expect_error([&] { adaptive_discretization(poi, planning, cache, metric); },
               {"planning.max_volumes = 20000", "may need up to 240", "GB", "raise planning.max_volumes"});
  expect_error([&] { fixed_discretization(poi, 0.001, cache, metric); }, {"max_volumes = 20000"});
  EXPECT_EQ(computed.load(), 0);
  Eigen::MatrixXd long_path(2, 2);
  long_path << 0, 0, 1e7, 0;  // 10,000 km
  expect_error([&] { adaptive_discretization(PoiPath(long_path, 5.0), Planning{}, cache, metric); },
               {"planning.max_volumes"});
  EXPECT_EQ(computed.load(), 0);
}

TEST(Limits, SimulationRefusesAFlightPlaneUnderTheGround) {
  const Environment env = Environment::demo();
  Eigen::MatrixXd w(2, 2);
  w << -290, -210, -100, -210;
  const PoiPath poi(w, 5.0);
  Uav uav;
  const OrbitPlan plan = constant_radius_plan(poi, 120.0, uav);
  uav.altitude = -5.0;
  expect_error([&] { simulate(plan, uav, Vec3(-170, -210, 1.57), Control{}, SimulationOptions{}, VisibilityScene(env)); },
               {"uav.altitude = -5", "above the ground level 0"});
  uav.altitude = 300.0;
  expect_error([&] { simulate(plan, uav, Vec3(-170, -210, 1.57), Control{}, SimulationOptions{}, {}, 1e-300); },
               {"fixed_step = 1e-300"});
  expect_error([&] { simulate(plan, uav, Vec3(1e300, -210, 1.57), Control{}); }, {"x0[0] = 1e+300"});
}

// --- 10^6 random problems over the whole documented range -------------------------------------

// Problems per family; VISTRACK_RANDOM_CASES lowers it (the sanitizer job runs 10^5). A value that
// is not a positive count fails the tests rather than letting them check nothing.
std::size_t random_cases() {
  const char* text = std::getenv("VISTRACK_RANDOM_CASES");
  if (!text) return 1000000;
  char* end = nullptr;
  const unsigned long long n = std::strtoull(text, &end, 10);
  if (end == text || *end != '\0' || n < 5) throw std::invalid_argument("VISTRACK_RANDOM_CASES must be a count >= 5");
  return static_cast<std::size_t>(n);
}

// Log-uniform magnitudes so every decade of a range is tried, with a random sign for coordinates.
// SplitMix64, seeded per case: case k is the same problem on any number of threads.
struct Sampler {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  double uniform(double low, double high) { return low + (high - low) * static_cast<double>(next() >> 11) * 0x1.0p-53; }
  double log_uniform(double low, double high) { return std::exp(uniform(std::log(low), std::log(high))); }
  double coordinate(double scale) { return (uniform(0, 1) < 0.5 ? -1.0 : 1.0) * log_uniform(1e-9, 1.0) * scale; }
  double heading() { return uniform(0, 1) < 0.9 ? uniform(-kPi, kPi) : uniform(-1e3, 1e3); }
  double rho() { return log_uniform(limits::kMinLength, limits::kMaxLength); }
  // How far from the origin a problem of turn radius rho may lie (limits.hpp).
  static double extent(double rho) { return std::min(limits::kMaxCoordinate, limits::kMaxCoordinateOverRho * rho); }
  Configuration start(double rho) { return {coordinate(extent(rho)), coordinate(extent(rho)), heading()}; }
  // A configuration near `origin` on the scale of rho, within `extent` of the origin.
  Configuration near(const Configuration& origin, double rho, double extent) {
    const double reach = std::min(extent, rho * log_uniform(1e-3, 1e3));
    auto clamp = [extent](double v) { return std::clamp(v, -extent, extent); };
    return {clamp(origin.x + coordinate(reach)), clamp(origin.y + coordinate(reach)), heading()};
  }
};

// The snapping tolerance of dubins.hpp for this problem.
double snap(const Configuration& a, const Configuration& b, double rho) {
  const double scale = std::max({std::abs(a.x), std::abs(a.y), std::abs(b.x), std::abs(b.y)});
  return kDubinsSnap * (1.0 + scale / rho);
}

// Integrating the path's segments from its start reaches its goal: position within a few snaps
// of rho (plus rounding of the coordinates), heading within a few snaps (mod 2 pi).
::testing::AssertionResult reaches_goal(const DubinsPath& path) {
  if (!std::isfinite(path.length) || path.length < 0.0)
    return ::testing::AssertionFailure() << "length = " << path.length;
  const Configuration end = detail::integrate(path, path.length);
  const double eps = snap(path.start, path.goal, path.rho);
  const double scale = std::max({std::abs(path.goal.x), std::abs(path.goal.y), path.length});
  const double position = std::hypot(end.x - path.goal.x, end.y - path.goal.y);
  const double heading = std::abs(wrap_to_pi(end.psi - path.goal.psi));
  const double position_tolerance = 1e3 * eps * path.rho + 1e-12 * scale;
  const double heading_tolerance = 1e3 * eps + 1e-12 * (path.length / path.rho);
  if (position <= position_tolerance && heading <= heading_tolerance) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "from (" << path.start.x << ", " << path.start.y << ", " << path.start.psi
                                       << ") to (" << path.goal.x << ", " << path.goal.y << ", " << path.goal.psi
                                       << ") rho " << path.rho << " " << to_string(path.word) << ": misses by "
                                       << position << " m (tolerance " << position_tolerance << "), " << heading
                                       << " rad (tolerance " << heading_tolerance << ")";
}

// Runs `check(k, sampler)` for k < n in parallel; stops at the first failure and reports it.
template <class Check>
void for_random_cases(std::size_t n, std::uint64_t seed, Check check) {
  std::atomic<bool> failed{false};
  std::string first;
  std::mutex lock;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t k = r.begin(); k < r.end() && !failed; ++k) {
      Sampler sampler{seed * 0x100000000ULL + k};
      const ::testing::AssertionResult result = check(sampler);
      if (!result) {
        std::lock_guard<std::mutex> guard(lock);
        if (!failed.exchange(true)) first = "case " + std::to_string(k) + ": " + result.message();
      }
    }
  });
  EXPECT_FALSE(failed.load()) << first;
}

TEST(RandomCases, DubinsShortestPathsReachTheirGoal) {
  for_random_cases(random_cases(), 1, [](Sampler& s) {
    const double rho = s.rho();
    const Configuration a = s.start(rho);
    const Configuration b = s.near(a, rho, Sampler::extent(rho));
    const DubinsPath path = dubins_shortest_path(a, b, rho);
    const double batch = dubins_shortest_length(a, b, rho);
    if (!(std::abs(batch - path.length) <= 1e-9 * std::max(1.0, path.length)))
      return ::testing::AssertionFailure() << "kernel length " << batch << " vs path " << path.length;
    return reaches_goal(path);
  });
}

TEST(RandomCases, PathsToACircleReachItsPointWithTheTangentHeading) {
  for_random_cases(random_cases(), 2, [](Sampler& s) {
    const double rho = s.rho();
    const Configuration a = s.start(rho);
    TargetCircle circle;
    circle.radius = std::clamp(rho * s.log_uniform(1e-3, 1e3), limits::kMinLength, 0.5 * Sampler::extent(rho));
    const Configuration c = s.near(a, rho, Sampler::extent(rho) - circle.radius);  // the circle within range
    circle.center = Vec2(c.x, c.y);
    circle.direction = s.uniform(0, 1) < 0.5 ? Circulation::Clockwise : Circulation::CounterClockwise;
    const double angle = s.heading();
    const DubinsPath path = dubins_path_to_circle(a, rho, circle, angle);
    const Configuration target = circle.configuration(angle);
    if (std::hypot(path.goal.x - target.x, path.goal.y - target.y) > 0.0 || path.goal.psi != target.psi)
      return ::testing::AssertionFailure() << "goal is not the circle's point";
    return reaches_goal(path);
  });
}

TEST(RandomCases, InterceptsMeetTheTargetOnTime) {
  // Each intercept scans D(alpha) (scan_samples) and bisects, ~50 times a Dubins problem: a fifth
  // of the cases (2 10^5 by default, ~10 s on one core; VISTRACK_RANDOM_CASES=5000000 gives 10^6).
  // Speeds, radii and places are drawn over the documented ranges.
  for_random_cases(random_cases() / 5, 3, [](Sampler& s) {
    InterceptProblem p;
    p.rho = s.rho();
    p.pursuer = s.start(p.rho);
    p.circle.radius = std::clamp(p.rho * s.log_uniform(1e-2, 1e2), limits::kMinLength, 0.5 * Sampler::extent(p.rho));
    const Configuration c = s.near(p.pursuer, p.rho, Sampler::extent(p.rho) - p.circle.radius);
    p.circle.center = Vec2(c.x, c.y);
    p.circle.direction = s.uniform(0, 1) < 0.5 ? Circulation::Clockwise : Circulation::CounterClockwise;
    p.pursuer_speed = s.log_uniform(1e-3, 1e3);
    p.target_speed = p.pursuer_speed * s.log_uniform(1e-2, 1e1);
    p.target_angle0 = s.heading();
    p.scan_samples = 64;
    InterceptResult r;
    try {
      r = intercept_circle(p);
    } catch (const Error& error) {
      // The one refusal allowed: a target that circles more than 1e8 times first.
      if (std::string(error.what()).find("more than 1e8 times") != std::string::npos)
        return ::testing::AssertionSuccess();
      return ::testing::AssertionFailure() << error.what();
    }
    if (!std::isfinite(r.time) || !std::isfinite(r.angle) || !(r.residual <= 1e-9 * std::max(1.0, r.time)))
      return ::testing::AssertionFailure() << "time " << r.time << " angle " << r.angle << " residual " << r.residual;
    // The path ends where the target is at that time, with its heading.
    const Configuration target = p.circle.configuration(r.angle);
    if (std::hypot(r.path.goal.x - target.x, r.path.goal.y - target.y) > 0.0)
      return ::testing::AssertionFailure() << "the path does not end on the target";
    return reaches_goal(r.path);
  });
}

}  // namespace
}  // namespace vistrack
