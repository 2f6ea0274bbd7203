// Orbit feasibility (Lemmas 3, 5, 6), Algorithm 1 against its closed form and the printed typos,
// adaptive discretization and plan_orbits with synthetic VVs (Charlotte runs are in pytest).
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <random>

#include "vistrack/error.hpp"
#include "vistrack/orbit.hpp"
#include "vistrack/volume.hpp"
#include "test_data.hpp"

namespace vt = vistrack;

namespace {

vt::Uav uav(double speed, double r_min) {
  vt::Uav u;
  u.speed = speed;
  u.min_turn_radius = r_min;
  return u;
}

// Curvature of x(t) = g(t) + R(t) e_r(theta(t)) by finite differences, with theta integrated by
// RK4 from (13): an independent check of the closed form (31).
double flown_curvature(double R0, double Rdot, double a0, double v, double vg, bool ccw) {
  auto theta_rate = [&](double t, double theta) {
    const double R = R0 + Rdot * t;
    const double radial = vg * std::cos(theta) + Rdot;  // gamma = 0: a = theta
    const double root = std::sqrt(v * v - radial * radial);
    return (vg * std::sin(theta) + (ccw ? root : -root)) / R;
  };
  auto position = [&](double t) {
    // RK4 from 0 to t (t may be negative) in fine steps.
    const int steps = 400;
    const double h = t / steps;
    double theta = a0, s = 0.0;
    for (int i = 0; i < steps; ++i, s += h) {
      const double k1 = theta_rate(s, theta), k2 = theta_rate(s + h / 2, theta + h / 2 * k1),
                   k3 = theta_rate(s + h / 2, theta + h / 2 * k2), k4 = theta_rate(s + h, theta + h * k3);
      theta += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    const double R = R0 + Rdot * t;
    return vt::Vec2(vg * t + R * std::cos(theta), R * std::sin(theta));
  };
  const double h = 1e-3;
  const vt::Vec2 xm = position(-h), x0 = position(0.0), xp = position(h);
  const vt::Vec2 d1 = (xp - xm) / (2 * h), d2 = (xp - 2 * x0 + xm) / (h * h);
  return std::abs(d1.x() * d2.y() - d1.y() * d2.x()) / std::pow(d1.norm(), 3);
}

}  // namespace

TEST(OrbitCurvature, StillPoiAndConstantRadiusIsACircle) {
  EXPECT_NEAR(vt::orbit_curvature(80.0, 0.0, 0.3, 20.0, 0.0), 1.0 / 80.0, 1e-15);
  EXPECT_NEAR(vt::orbit_curvature(80.0, 0.0, 0.3, 20.0, 0.0, vt::Circulation::Clockwise), 1.0 / 80.0, 1e-15);
}

TEST(OrbitCurvature, ClosedForm31MatchesTheFlownPath) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 40; ++trial) {
    const double v = 20.0, vg = 1.0 + 8.0 * u(rng), R = 40.0 + 150.0 * u(rng);
    const double Rdot = (2 * u(rng) - 1) * 0.8 * (v - vg), a = vt::kTwoPi * u(rng);
    const bool ccw = trial % 2 == 0;
    const double closed = vt::orbit_curvature(R, Rdot, a, v, vg, ccw ? vt::Circulation::CounterClockwise : vt::Circulation::Clockwise);
    EXPECT_NEAR(flown_curvature(R, Rdot, a, v, vg, ccw), closed, 1e-4 * closed + 1e-7)
        << "R=" << R << " Rdot=" << Rdot << " a=" << a << " vg=" << vg;
  }
}

TEST(OrbitCurvature, Lemma6BoundIsTheMaximumOverAnglesAndAdmissibleRates) {
  for (double b : {0.05, 0.25, 0.5, 0.8, 0.95}) {
    const double v = 20.0, vg = b * v, R = 100.0;
    double best = 0.0;
    for (int i = 0; i <= 720; ++i)
      for (int j = 1; j < 200; ++j) {  // open interval: on Lemma 5's boundary (31) is 0/0
        const double a = -vt::kPi + vt::kTwoPi * i / 720, Rdot = (v - vg) * (-1.0 + 2.0 * j / 200);
        best = std::max(best, vt::orbit_curvature(R, Rdot, a, v, vg, vt::Circulation::CounterClockwise));
      }
    const double bound = vt::max_orbit_curvature(R, v, vg);
    EXPECT_NEAR(best, bound, 1e-9 * bound) << "b = " << b;
    EXPECT_NEAR(vt::orbit_curvature(R, 0.0, vt::kPi / 2, v, vg, vt::Circulation::CounterClockwise), bound, 1e-12);   // CCW at +pi/2
    EXPECT_NEAR(vt::orbit_curvature(R, 0.0, -vt::kPi / 2, v, vg, vt::Circulation::Clockwise), bound, 1e-12); // CW at -pi/2
    EXPECT_LE(bound, 4.0 / R);  // Corollary 1
  }
  // Beyond Lemma 5's rate no constant-speed motion stays on the orbit.
  EXPECT_TRUE(std::isinf(vt::orbit_curvature(100.0, 16.0, 0.0, 20.0, 5.0)));
}

TEST(CircularOrbits, ForwardPassBuildsTheLimitedRadiusFromItsNeighbour) {
  // v - v_g = 15 m/s, 1 s apart: 100 -> 300 is too fast; R_1 = 100 + 15 (the printed line 5
  // would give 15 m, below the rate-allowed radius and wrongly infeasible).
  const auto out = vt::circular_orbits({0.0, 1.0}, {100.0, 300.0}, uav(20.0, 10.0), 5.0);
  EXPECT_DOUBLE_EQ(out.radii[1], 115.0);
  EXPECT_DOUBLE_EQ(out.radius_rates[0], 15.0);
  EXPECT_TRUE(out.feasible);
}

TEST(CircularOrbits, BackwardPassBuildsTheLimitedRadiusFromItsNeighbour) {
  // 300 -> 100 shrinks too fast: R_0 = 100 + 15 (the printed line 11 would give -15 m).
  const auto out = vt::circular_orbits({0.0, 1.0}, {300.0, 100.0}, uav(20.0, 10.0), 5.0);
  EXPECT_DOUBLE_EQ(out.radii[0], 115.0);
  EXPECT_DOUBLE_EQ(out.radius_rates[0], -15.0);
}

TEST(CircularOrbits, IsTheLargestRateLimitedRadiusBelowMaxRadius) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 100; ++trial) {
    const int n = 2 + static_cast<int>(30 * u(rng));
    std::vector<double> t{0.0}, m;
    for (int k = 1; k < n; ++k) t.push_back(t.back() + 0.05 + 3 * u(rng));
    for (int k = 0; k < n; ++k) m.push_back(u(rng) < 0.1 ? 0.0 : 300 * u(rng));
    // Every other trial with a rate margin: the bound becomes (1 - margin)(v - v_g).
    const double margin = trial % 2 ? 0.0 : 0.5 * u(rng);
    const double v = 15 + 10 * u(rng), vg = 1 + 10 * u(rng), c = (1 - margin) * (v - vg);
    const auto out = vt::circular_orbits(t, m, uav(v, 20.0), vg, margin);
    for (int k = 0; k < n; ++k) {
      double envelope = m[k];
      for (int j = 0; j < n; ++j) envelope = std::min(envelope, m[j] + c * std::abs(t[k] - t[j]));
      EXPECT_NEAR(out.radii[k], envelope, 1e-9 * (1 + envelope));
      EXPECT_LE(out.radii[k], m[k]);
      if (k + 1 < n) {
        EXPECT_LE(std::abs(out.radius_rates[k]), c * (1 + 1e-12));
      }
    }
  }
}

TEST(CircularOrbits, CurvatureCheckFollowsLemma6) {
  // r_min 50, v 20, v_g 5: Lemma 6 needs R >= 50 * 1.25^2 = 78.125 m.
  const auto ok = vt::circular_orbits({0, 1, 2}, {100, 100, 100}, uav(20.0, 50.0), 5.0);
  EXPECT_TRUE(ok.feasible);  // the printed line 15 (R > 78.125 -> infeasible) would reject it
  EXPECT_DOUBLE_EQ(ok.min_feasible_radius, 78.125);
  const auto tight = vt::circular_orbits({0, 10, 20}, {100, 60, 100}, uav(20.0, 50.0), 5.0);
  EXPECT_FALSE(tight.feasible);  // ... and the printed test would accept R = 60 m
  ASSERT_EQ(tight.failing_samples, std::vector<std::size_t>{1});
  EXPECT_NE(tight.infeasibility.find("sample 1"), std::string::npos) << tight.infeasibility;
  EXPECT_NE(tight.infeasibility.find("Lemma 6"), std::string::npos) << tight.infeasibility;
  const auto edge = vt::circular_orbits({0, 1}, {78.125, 78.125}, uav(20.0, 50.0), 5.0);
  EXPECT_TRUE(edge.feasible);
}

TEST(CircularOrbits, InvisiblePoiIsReportedNotHidden) {
  const auto out = vt::circular_orbits({0, 20, 40, 60}, {200, 200, 0, 200}, uav(20.0, 50.0), 5.0);
  EXPECT_FALSE(out.feasible);
  EXPECT_EQ(out.radii[2], 0.0);
  EXPECT_EQ(out.failing_samples, (std::vector<std::size_t>{2}));
  EXPECT_NE(out.infeasibility.find("not visible"), std::string::npos) << out.infeasibility;
}

TEST(CircularOrbits, RejectsBadInput) {
  EXPECT_THROW(vt::circular_orbits({0, 1}, {100, 100}, uav(5.0, 10.0), 5.0), vt::Error);  // v = v_g
  try {
    vt::circular_orbits({0, 1}, {100, 100}, uav(4.0, 10.0), 5.0);
  } catch (const vt::Error& e) {
    EXPECT_NE(std::string(e.what()).find("uav.speed"), std::string::npos);
  }
  EXPECT_THROW(vt::circular_orbits({0, 1}, {100}, uav(20, 10), 5.0), vt::Error);
  EXPECT_THROW(vt::circular_orbits({0, 0}, {100, 100}, uav(20, 10), 5.0), vt::Error);
  EXPECT_THROW(vt::circular_orbits({0, 1}, {100, std::nan("")}, uav(20, 10), 5.0), vt::Error);
  EXPECT_THROW(vt::circular_orbits({0, 1}, {100, -1}, uav(20, 10), 5.0), vt::Error);
  EXPECT_THROW(vt::circular_orbits({}, {}, uav(20, 10), 5.0), vt::Error);
  for (double margin : {-0.1, 1.0, std::nan("")})
    EXPECT_THROW(vt::circular_orbits({0.0, 1.0}, {100.0, 100.0}, uav(20.0, 10.0), 5.0, margin), vt::Error);
  vt::Planning planning;
  planning.rate_margin = 1.0;
  EXPECT_THROW(planning.validate(), vt::Error);
}

namespace {

// A synthetic world: every VV is a ball of radius 50 m about its POI, except past x = 37 m
// where it is 60 m. Its VP at any altitude is a square of half-width equal to that radius.
vt::VolumeFunction step_world(std::atomic<int>& calls) {
  return [&calls](const vt::Vec3& g) {
    ++calls;
    auto v = std::make_shared<vt::VisibilityVolume>();
    v->poi = g;
    v->grid.num_elevation = 18;
    v->grid.num_azimuth = 36;
    v->near.assign(v->grid.size(), 0.0);
    v->far.assign(v->grid.size(), g.x() < 37.0 ? 50.0 : 60.0);
    return vt::VolumePtr(v);
  };
}

vt::Polygon square(const vt::Vec2& c, double w) {
  return {{c + vt::Vec2(-w, -w), c + vt::Vec2(w, -w), c + vt::Vec2(w, w), c + vt::Vec2(-w, w)}, {}};
}

const vt::MetricFunction grid_metric = [](const vt::VisibilityVolume& a, const vt::VisibilityVolume& b) {
  return vt::grid_xor_volume(a, b);
};

}  // namespace

TEST(AdaptiveDiscretization, RefinesWhereTheVolumesChangeAndStops) {
  std::atomic<int> calls{0};
  vt::VolumeCache cache(step_world(calls));
  Eigen::MatrixXd w(3, 2);
  w << 0, 0, 100, 0, 100, 30;
  const vt::PoiPath poi(w, 5.0);
  vt::Planning planning;
  planning.spacing = 20.0;
  planning.cutoff = 1000.0;
  planning.min_spacing = 0.5;
  planning.max_depth = 8;
  const auto d = vt::adaptive_discretization(poi, planning, cache, grid_metric);
  // Initial samples: 0, 20, ..., 100 and 100 + 20, 130 (node), then halvings around x = 37.
  ASSERT_EQ(d.metric.size() + 1, d.times.size());
  EXPECT_TRUE(std::is_sorted(d.arc_lengths.begin(), d.arc_lengths.end()));
  for (double s : {0.0, 20.0, 40.0, 60.0, 80.0, 100.0, 120.0, 130.0})
    EXPECT_NE(std::find(d.arc_lengths.begin(), d.arc_lengths.end(), s), d.arc_lengths.end()) << s;
  double jump_gap = 1e9;
  for (std::size_t k = 0; k + 1 < d.times.size(); ++k) {
    EXPECT_NEAR(d.times[k], d.arc_lengths[k] / 5.0, 1e-12);
    if (d.metric[k] > planning.cutoff) {
      jump_gap = d.arc_lengths[k + 1] - d.arc_lengths[k];
    } else {
      EXPECT_EQ(d.metric[k], 0.0);
    }
  }
  // Halved from 20 m while above the cutoff: 20 / 2^6 = 0.3125 < 0.5 stops at 0.625 m.
  EXPECT_NEAR(jump_gap, 0.625, 1e-12);
  EXPECT_EQ(d.volumes_computed, d.times.size());  // each VV computed once
  EXPECT_EQ(calls.load(), static_cast<int>(d.times.size()));
  // max_depth bounds the work too.
  planning.max_depth = 2;
  const auto shallow = vt::adaptive_discretization(poi, planning, cache, grid_metric);
  EXPECT_EQ(*std::max_element(shallow.depths.begin(), shallow.depths.end()), 2);
  EXPECT_EQ(shallow.volumes_computed, 0u);  // every VV came from the cache
}

TEST(AdaptiveDiscretization, FixedSpacingsNestAndReuseVolumes) {
  std::atomic<int> calls{0};
  vt::VolumeCache cache(step_world(calls));
  Eigen::MatrixXd w(2, 2);
  w << 0, 0, 100, 0;
  const vt::PoiPath poi(w, 5.0);
  const auto fine = vt::fixed_discretization(poi, 10.0, cache, grid_metric);
  EXPECT_EQ(fine.times.size(), 11u);
  const auto coarse = vt::fixed_discretization(poi, 50.0, cache, grid_metric);
  EXPECT_EQ(coarse.times.size(), 3u);
  EXPECT_EQ(coarse.volumes_computed, 0u);
  EXPECT_EQ(calls.load(), 11);
  EXPECT_THROW(vt::fixed_discretization(poi, 0.0, cache, grid_metric), vt::Error);
}

TEST(PlanOrbits, SyntheticWorldEndToEndAndJsonRoundTrip) {
  std::atomic<int> calls{0};
  vt::VolumeCache cache(step_world(calls));
  Eigen::MatrixXd w(2, 2);
  w << 0, 0, 100, 0;
  const vt::PoiPath poi(w, 5.0);
  vt::Planning planning;
  planning.cutoff = 1000.0;
  planning.min_spacing = 2.0;
  vt::Sensor sensor;
  const vt::SliceFunction slice = [](const vt::VisibilityVolume& v, double) {
    return std::vector<vt::Polygon>{square(v.poi.head<2>(), v.far[0])};
  };
  const auto plan = vt::plan_orbits(poi, uav(20.0, 10.0), sensor, planning, cache, grid_metric, slice);
  ASSERT_EQ(plan.radii.size(), plan.times.size());
  for (std::size_t k = 0; k < plan.times.size(); ++k)
    EXPECT_DOUBLE_EQ(plan.max_radii[k], plan.samples.arc_lengths[k] < 37.0 ? 50.0 : 60.0);
  EXPECT_TRUE(plan.feasible);
  EXPECT_EQ(plan.orbits.radius_rates.size() + 1, plan.times.size());
  for (double rate : plan.orbits.radius_rates) EXPECT_LE(std::abs(rate), 15.0 + 1e-12);
  const auto again = vt::visibility_orbit_plan_from_json(vt::to_json(plan));
  EXPECT_EQ(again.times, plan.times);
  EXPECT_EQ(again.radii, plan.radii);
  EXPECT_EQ(again.orbits.radius_rates, plan.orbits.radius_rates);
  EXPECT_EQ(again.samples.depths, plan.samples.depths);
  ASSERT_EQ(again.polygons.size(), plan.polygons.size());
  EXPECT_EQ(again.polygons[3][0].outer, plan.polygons[3][0].outer);
  EXPECT_DOUBLE_EQ(again.uav.speed, 20.0);
  EXPECT_DOUBLE_EQ(again.radius(again.times[2]), plan.radii[2]);
  // A UAV not faster than the POI is an error.
  EXPECT_THROW(vt::plan_orbits(poi, uav(5.0, 10.0), sensor, planning, cache, grid_metric, slice), vt::Error);
}

TEST(PlaneSlice, BoxAndOctahedronGiveTheirAnalyticSections) {
  vt::TriangleMesh box;
  box.vertices.resize(8, 3);
  for (int i = 0; i < 8; ++i) box.vertices.row(i) << ((i & 1) ? 2.0 : 0.0), ((i & 2) ? 3.0 : 0.0), ((i & 4) ? 2.0 : 0.0);
  box.faces.resize(12, 3);
  box.faces << 0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7,
      5;
  auto rings = vt::plane_slice_rings(box, 1.0);
  ASSERT_EQ(rings.size(), 1u);
  EXPECT_NEAR(std::abs(vt::signed_area(rings[0])), 6.0, 1e-12);
  EXPECT_TRUE(vt::plane_slice_rings(box, 2.5).empty());
  // On a vertex height the vertices count as below: the top face is not cut.
  EXPECT_TRUE(vt::plane_slice_rings(box, 2.0).empty());
  vt::TriangleMesh oct;
  oct.vertices.resize(6, 3);
  oct.vertices << 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1;
  oct.faces.resize(8, 3);
  oct.faces << 0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5;
  rings = vt::plane_slice_rings(oct, 0.25);  // |x| + |y| <= 0.75: area 2 * 0.75^2
  ASSERT_EQ(rings.size(), 1u);
  EXPECT_NEAR(std::abs(vt::signed_area(rings[0])), 2 * 0.75 * 0.75, 1e-12);
  auto open = box;
  open.faces.conservativeResize(11, 3);  // drops a side triangle cut by z = 1
  EXPECT_THROW(vt::plane_slice_rings(open, 1.0), vt::Error);
  EXPECT_THROW(vt::plane_slice_rings(box, std::nan("")), vt::Error);
}

TEST(PlanOrbits, PaperSlowExampleOnCharlotte) {
  VISTRACK_REQUIRE_DATA(city, "charlotte/uptown_charlotte.obj");
  VISTRACK_REQUIRE_DATA(path, "charlotte/paths/paper_slow.csv");
  const auto env = vt::Environment::from_mesh(city, "y");
  const auto poi = vt::PoiPath::from_csv(path, 5.0);
  vt::Uav u = uav(20.0, 50.0);
  u.altitude = 300.0;
  vt::Sensor sensor;
  sensor.d_max = 400.0;
  vt::Planning planning;  // spacing 20 m, cutoff 20e6 m^3, 1 degree
  std::size_t last_done = 0, last_total = 0;
  const auto plan = vt::plan_orbits(env, poi, u, sensor, planning, [&](std::size_t done, std::size_t total) {
    EXPECT_LE(done, total);
    last_done = done;
    last_total = total;
  });
  EXPECT_TRUE(plan.feasible) << plan.infeasibility;
  EXPECT_EQ(last_done, last_total);
  EXPECT_EQ(plan.samples.volumes_computed, plan.times.size());
  EXPECT_NEAR(plan.times.back(), poi.duration(), 1e-9);
  for (std::size_t k = 0; k < plan.times.size(); ++k) {
    EXPECT_LE(plan.radii[k], plan.max_radii[k] + 1e-9);
    EXPECT_GE(plan.radii[k], plan.orbits.min_feasible_radius);
    // MaxRadius is at most the sensor's reach at h_UAV: sqrt(d_max^2 - (h - g_z)^2).
    EXPECT_LE(plan.max_radii[k], std::sqrt(400.0 * 400.0 - 299.5 * 299.5) + 1e-6);
    EXPECT_EQ(plan.max_radii[k], vt::max_inscribed_radius(plan.polygons[k], poi.position(plan.times[k]).head<2>()));
  }
  for (std::size_t k = 0; k + 1 < plan.times.size(); ++k) {
    EXPECT_LE(std::abs(plan.orbits.radius_rates[k]), 15.0 + 1e-9);
    // The planner's metric is the radial (exact per-direction mesh) XOR of neighbouring VVs.
    EXPECT_EQ(plan.samples.metric[k], vt::radial_xor_volume(*plan.samples.volumes[k], *plan.samples.volumes[k + 1]));
  }
  // The paper reports 158 m -> 127 m (see README for why ours differs by ~4 %).
  EXPECT_NEAR(plan.radii.front(), 158.0, 0.1 * 158.0);
  EXPECT_NEAR(plan.radii.back(), 127.0, 0.1 * 127.0);
}

TEST(AdaptiveDiscretization, RandomWorldsKeepTheInvariants) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    // Far radius a random staircase of x: the metric between neighbours is known in closed form.
    std::vector<double> steps;
    for (int k = 0; k < 4; ++k) steps.push_back(200.0 * u(rng));
    std::atomic<int> calls{0};
    vt::VolumeCache cache([&](const vt::Vec3& g) {
      ++calls;
      auto v = std::make_shared<vt::VisibilityVolume>();
      v->poi = g;
      v->grid.num_elevation = 6;
      v->grid.num_azimuth = 12;
      double far = 40.0;
      for (double s : steps) far += g.x() > s ? 5.0 : 0.0;
      v->near.assign(v->grid.size(), 0.0);
      v->far.assign(v->grid.size(), far);
      return vt::VolumePtr(v);
    });
    Eigen::MatrixXd w(2, 2);
    w << 0, 0, 200, 0;
    const vt::PoiPath poi(w, 1.0 + 9.0 * u(rng));
    vt::Planning planning;
    planning.spacing = 5.0 + 60.0 * u(rng);
    planning.cutoff = 1e3;
    planning.min_spacing = 0.1 + 3.0 * u(rng);
    planning.max_depth = static_cast<int>(10 * u(rng));
    const auto d = vt::adaptive_discretization(poi, planning, cache, grid_metric);
    ASSERT_EQ(d.times.size(), d.volumes.size());
    ASSERT_EQ(d.metric.size() + 1, d.times.size());
    EXPECT_EQ(d.arc_lengths.front(), 0.0);
    EXPECT_NEAR(d.arc_lengths.back(), 200.0, 1e-9);
    EXPECT_EQ(calls.load(), static_cast<int>(d.times.size()));
    for (std::size_t k = 0; k + 1 < d.times.size(); ++k) {
      const double gap = d.arc_lengths[k + 1] - d.arc_lengths[k];
      EXPECT_GT(gap, 0.0);
      EXPECT_LE(gap, planning.spacing + 1e-9);
      EXPECT_NEAR(d.metric[k], vt::grid_xor_volume(*d.volumes[k], *d.volumes[k + 1]), 1e-9);
      const int depth = std::max(d.depths[k], d.depths[k + 1]);
      // Above the cutoff only where halving had to stop.
      if (d.metric[k] > planning.cutoff) {
        EXPECT_TRUE(gap / 2 < planning.min_spacing || depth >= planning.max_depth)
            << "gap " << gap << " depth " << depth;
      }
      EXPECT_LE(depth, planning.max_depth);
    }
  }
}
