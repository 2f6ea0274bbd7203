// The closed loop: restarts at segment boundaries, convergence (Lemma 7), adaptive against fixed
// steps, line-of-sight plumbing, the tuning grid search, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "test_data.hpp"
#include "error_message.hpp"
#include "vistrack/error.hpp"
#include "vistrack/simulate.hpp"

using vistrack::testing::error_message;

namespace vistrack {
namespace {

PoiPath two_leg_path(double speed) {
  Eigen::MatrixXd w(3, 2);
  w << -150.0, -45.0, -50.0, 45.0, 20.0, -35.0;  // the paper's first example path
  return PoiPath(w, speed);
}

// A plan with a morphing radius: samples every 5 s, radius wiggling within Lemma 5.
OrbitPlan morphing_plan(const PoiPath& poi, const Uav& uav) {
  OrbitPlan plan = constant_radius_plan(poi, 120.0, uav);
  plan.times.clear();
  plan.radii.clear();
  for (double t = 0.0; t < poi.duration(); t += 5.0) {
    plan.times.push_back(t);
    plan.radii.push_back(130.0 + 25.0 * std::sin(0.3 * t));
  }
  plan.times.push_back(poi.duration());
  plan.radii.push_back(130.0);
  return plan;
}

// The paper's first example: the default vehicle and control around a POI on a two-leg path at 5 m/s.
class TwoLegPath : public ::testing::Test {
 protected:
  const Uav uav;
  const Control control;
  const PoiPath poi = two_leg_path(5.0);
};

TEST_F(TwoLegPath, SegmentBoundariesAreThePlanSamplesAndPathNodes) {
  const OrbitPlan plan = morphing_plan(poi, uav);
  const std::vector<double> b = segment_boundaries(plan);
  EXPECT_EQ(b.front(), 0.0);
  EXPECT_DOUBLE_EQ(b.back(), poi.duration());
  for (double t : plan.times) EXPECT_TRUE(std::any_of(b.begin(), b.end(), [&](double x) { return std::abs(x - t) < 1e-9; }));
  EXPECT_TRUE(std::any_of(b.begin(), b.end(), [&](double x) { return std::abs(x - poi.node_times()[1]) < 1e-12; }));
  EXPECT_TRUE(std::is_sorted(b.begin(), b.end()));
}

TEST_F(TwoLegPath, StartingOnTheOrbitStaysOnIt) {
  // On the orbit with psi = psi_d, the field's flow keeps r = R (r_dot - R_dot = -Phi' = 0).
  const OrbitPlan plan = constant_radius_plan(poi, 150.0, uav);
  OrbitState orbit = orbit_state(plan, 0.0, 0.0);
  const Vec3 x0 = orbit_configuration(1.0, orbit, uav.speed, Circulation::CounterClockwise);
  SimulationOptions options;
  options.rtol = 1e-10;
  options.atol = 1e-10;
  const SimulationResult r = simulate(plan, uav, x0, control, options);
  const double t_turn = poi.node_times()[1];
  for (std::size_t k = 0; k < r.t.size(); ++k) {
    if (r.t[k] < t_turn) {
      EXPECT_LT(std::abs(r.radial_error[k]), 1e-6) << r.t[k];
    }
    EXPECT_LT(std::abs(r.radial_error[k]), 5.0);  // the POI turn kicks it off a little (Remark 3)
  }
}

// A smooth plan by hand: R(t) = 140 + 20 sin(0.2 t) as C1 quadratic pieces (rates at the knots
// from the sine's derivative, radii integrated so that R stays continuous).
OrbitPlan smooth_plan(const PoiPath& poi, const Uav& uav) {
  OrbitPlan plan = constant_radius_plan(poi, 140.0, uav);
  RadiusProfile& p = plan.reference;
  for (double t = 0.0; t < poi.duration(); t += 0.7) p.times.push_back(t);
  p.times.push_back(poi.duration());
  p.radii.push_back(140.0);
  for (double t : p.times) p.rates.push_back(4.0 * std::cos(0.2 * t));
  for (std::size_t k = 0; k + 1 < p.times.size(); ++k)
    p.radii.push_back(p.radii[k] + 0.5 * (p.times[k + 1] - p.times[k]) * (p.rates[k] + p.rates[k + 1]));
  p.validate();
  for (std::size_t k = 0; k < plan.times.size(); ++k) plan.radii[k] = p.radius(plan.times[k]);
  return plan;
}

TEST_F(TwoLegPath, SmoothReferenceRestartsAtItsKnotsAndIsFollowed) {
  // Started on the smooth orbit with psi = psi_d, the field's flow keeps r = R: the R_ddot
  // feed-forward of (85) is exact.
  const OrbitPlan plan = smooth_plan(poi, uav);
  const std::vector<double> b = segment_boundaries(plan);
  for (double t : plan.reference.times)
    if (t < poi.duration()) {
      EXPECT_TRUE(std::any_of(b.begin(), b.end(), [&](double x) { return std::abs(x - t) < 1e-9; }));
    }
  OrbitState orbit = orbit_state(plan, 0.0, 0.0);
  EXPECT_DOUBLE_EQ(orbit.radius_acceleration, plan.radius_acceleration(0.0));
  const Vec3 x0 = orbit_configuration(1.0, orbit, uav.speed, Circulation::CounterClockwise);
  SimulationOptions options;
  options.rtol = 1e-10;
  options.atol = 1e-10;
  const SimulationResult r = simulate(plan, uav, x0, control, options);
  const double t_turn = poi.node_times()[1];
  for (std::size_t k = 0; k < r.t.size(); ++k) {
    EXPECT_NEAR(r.orbit_radius[k], plan.radius(r.t[k]), 1e-9);
    if (r.t[k] < t_turn) {
      EXPECT_LT(std::abs(r.radial_error[k]), 1e-6) << r.t[k];
    }
  }
}

// Lemma 7 (without the turn-rate bound): from several initial conditions outside the orbit the
// radial and heading errors converge, for a gain above (87).
TEST(Simulate, Lemma7ConvergenceFromOutsideTheOrbit) {
  Uav uav;
  uav.min_turn_radius = 1e-3;  // effectively no saturation: Lemma 7 ignores (2)
  Control control;
  control.beta = 0.05;
  control.k_psi = 2.0;
  ASSERT_GT(control.k_psi, lemma7_min_gain(uav.speed, control.beta));
  Eigen::MatrixXd w(2, 2);
  w << 0.0, 0.0, 600.0, 300.0;
  const PoiPath poi(w, 5.0);
  const OrbitPlan plan = constant_radius_plan(poi, 100.0, uav);
  for (const Circulation direction : {Circulation::CounterClockwise, Circulation::Clockwise}) {
    control.direction = direction;
    for (const Vec3& x0 : {Vec3(0.0, 300.0, -M_PI), Vec3(-250.0, -10.0, 0.3), Vec3(150.0, 150.0, 2.0),
                           Vec3(0.0, -400.0, M_PI / 2)}) {
      const SimulationResult r = simulate(plan, uav, x0, control);
      const std::size_t n = r.t.size();
      double late_radial = 0.0, late_heading = 0.0;
      for (std::size_t k = 0; k < n; ++k) {
        if (r.t[k] > r.t.back() - 30.0) {
          late_radial = std::max(late_radial, std::abs(r.radial_error[k]));
          late_heading = std::max(late_heading, std::abs(r.heading_error[k]));
        }
      }
      EXPECT_GT(std::abs(r.radial_error[0]), 50.0);
      EXPECT_LT(late_radial, 1e-3) << to_string(direction) << " " << x0.transpose();
      EXPECT_LT(late_heading, 1e-4) << to_string(direction) << " " << x0.transpose();
    }
  }
}

TEST_F(TwoLegPath, AdaptiveAgreesWithFineFixedSteps) {
  const OrbitPlan plan = morphing_plan(poi, uav);
  SimulationOptions options;
  options.rtol = 1e-10;
  options.atol = 1e-10;
  const Vec3 x0(0.0, 100.0, -M_PI);  // the paper's first start
  const SimulationResult adaptive = simulate(plan, uav, x0, control, options);
  const SimulationResult fixed = simulate(plan, uav, x0, control, options, {}, 1e-3);
  ASSERT_EQ(adaptive.t.size(), fixed.t.size());
  double worst = 0.0;
  for (Eigen::Index k = 0; k < adaptive.state.rows(); ++k)
    worst = std::max(worst, (adaptive.state.row(k) - fixed.state.row(k)).head<2>().norm());
  EXPECT_LT(worst, 1e-5);
  EXPECT_GT(fixed.statistics.accepted_steps, 10 * adaptive.statistics.accepted_steps);
  // Output samples every 0.1 s plus the end; restarts at every plan sample and the POI turn.
  EXPECT_NEAR(adaptive.t[1] - adaptive.t[0], 0.1, 1e-12);
  EXPECT_DOUBLE_EQ(adaptive.t.back(), poi.duration());
  EXPECT_EQ(adaptive.restart_times.size(), plan.times.size() + 1);
  // Outputs are consistent: the applied control is the clamp of the law; the radius is R(t).
  for (std::size_t k = 0; k < adaptive.t.size(); k += 37) {
    EXPECT_LE(std::abs(adaptive.control[k]), uav.speed / uav.min_turn_radius + 1e-15);
    EXPECT_NEAR(adaptive.orbit_radius[k], plan.radius(adaptive.t[k]), 1e-9);
    const Vec3 g = poi.position(adaptive.t[k]);
    const double r = (adaptive.state.row(static_cast<Eigen::Index>(k)).head<2>().transpose() - g.head<2>()).norm();
    EXPECT_NEAR(adaptive.radial_error[k], r - plan.radius(adaptive.t[k]), 1e-9);
  }
}

// The closed loop commutes with rigid motions, and a mirror image swaps the circulation: seeded
// random scenarios, so a sign slip in the clockwise branch or a frame error fails here.
TEST(Simulate, InvariantUnderRotationTranslationAndMirror) {
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  SimulationOptions options;
  options.rtol = 1e-10;
  options.atol = 1e-10;
  options.output_step = 0.5;
  for (int trial = 0; trial < 6; ++trial) {
    Uav uav;
    uav.speed = 10.0 + 20.0 * unit(rng);
    uav.min_turn_radius = 5.0 + 40.0 * unit(rng);
    Control control;
    control.beta = 0.02 + 0.3 * unit(rng);
    control.k_psi = 5.0 + 30.0 * unit(rng);
    control.direction = trial % 2 == 0 ? Circulation::CounterClockwise : Circulation::Clockwise;
    Eigen::MatrixXd w(3, 2);
    for (int i = 0; i < 3; ++i) w.row(i) << 300.0 * unit(rng) - 150.0, 300.0 * unit(rng) - 150.0;
    const double poi_speed = 0.5 * uav.speed * unit(rng);
    const double radius = uav.min_turn_radius * (4.5 + 3.0 * unit(rng));
    const Vec3 x0(w(0, 0) + 200.0 * unit(rng) - 100.0, w(0, 1) + 200.0 * unit(rng) - 100.0, 6.0 * unit(rng) - 3.0);
    const SimulationResult base = simulate(constant_radius_plan(PoiPath(w, poi_speed), radius, uav), uav, x0, control, options);

    const double a = 2 * M_PI * unit(rng);
    Eigen::Matrix2d rot;
    rot << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
    const Vec2 shift(500.0 * unit(rng) - 250.0, 500.0 * unit(rng) - 250.0);
    Eigen::MatrixXd w_moved(3, 2);
    for (int i = 0; i < 3; ++i) w_moved.row(i) = (rot * w.row(i).transpose() + shift).transpose();
    const Vec2 p_moved = rot * x0.head<2>() + shift;
    const SimulationResult moved = simulate(constant_radius_plan(PoiPath(w_moved, poi_speed), radius, uav), uav,
                                            Vec3(p_moved.x(), p_moved.y(), x0.z() + a), control, options);

    Eigen::MatrixXd w_mirror = w;
    w_mirror.col(1) *= -1.0;
    Control flipped = control;
    flipped.direction = control.direction == Circulation::CounterClockwise ? Circulation::Clockwise : Circulation::CounterClockwise;
    const SimulationResult mirror = simulate(constant_radius_plan(PoiPath(w_mirror, poi_speed), radius, uav), uav,
                                             Vec3(x0.x(), -x0.y(), -x0.z()), flipped, options);

    ASSERT_EQ(base.t.size(), moved.t.size());
    ASSERT_EQ(base.t.size(), mirror.t.size());
    double worst_moved = 0.0, worst_mirror = 0.0, worst_heading = 0.0;
    for (Eigen::Index k = 0; k < base.state.rows(); ++k) {
      const Vec2 p = base.state.row(k).head<2>().transpose();
      worst_moved = std::max(worst_moved, (rot * p + shift - moved.state.row(k).head<2>().transpose()).norm());
      worst_heading = std::max(worst_heading, std::abs(wrap_to_pi(base.state(k, 2) + a - moved.state(k, 2))));
      worst_mirror = std::max(worst_mirror, (Vec2(p.x(), -p.y()) - mirror.state.row(k).head<2>().transpose()).norm());
      EXPECT_NEAR(base.radial_error[static_cast<std::size_t>(k)], mirror.radial_error[static_cast<std::size_t>(k)], 1e-5);
    }
    EXPECT_LT(worst_moved, 1e-5) << trial;
    EXPECT_LT(worst_heading, 1e-6) << trial;
    EXPECT_LT(worst_mirror, 1e-5) << trial;
  }
}

TEST_F(TwoLegPath, LineOfSightAtEverySample) {
  const OrbitPlan plan = constant_radius_plan(poi, 150.0, uav);
  // An analytic occluder: visible only when the UAV is east of the POI.
  LineOfSight east = [](const Points3& from, const Points3& to) {
    EXPECT_EQ(from.rows(), to.rows());
    std::vector<std::uint8_t> out(static_cast<std::size_t>(from.rows()));
    for (Eigen::Index i = 0; i < from.rows(); ++i) out[static_cast<std::size_t>(i)] = from(i, 0) > to(i, 0);
    return out;
  };
  const SimulationResult r = simulate(plan, uav, Vec3(0.0, 100.0, -M_PI), Control{}, SimulationOptions{}, east);
  ASSERT_EQ(r.visible.size(), r.t.size());
  std::size_t count = 0;
  for (Eigen::Index i = 0; i < r.state.rows(); ++i) {
    EXPECT_EQ(r.visible[static_cast<std::size_t>(i)], r.state(i, 0) > r.poi(i, 0));
    count += r.state(i, 0) > r.poi(i, 0);
  }
  ASSERT_TRUE(r.visibility_fraction.has_value());
  EXPECT_DOUBLE_EQ(*r.visibility_fraction, static_cast<double>(count) / static_cast<double>(r.t.size()));
  EXPECT_GT(*r.visibility_fraction, 0.2);
  EXPECT_LT(*r.visibility_fraction, 0.8);
  // UAV at its altitude, POI at its path z.
  LineOfSight heights = [&](const Points3& from, const Points3& to) {
    for (Eigen::Index i = 0; i < from.rows(); ++i) {
      EXPECT_EQ(from(i, 2), uav.altitude);
      EXPECT_EQ(to(i, 2), 0.0);
    }
    return std::vector<std::uint8_t>(static_cast<std::size_t>(from.rows()), 1);
  };
  EXPECT_DOUBLE_EQ(*simulate(plan, uav, Vec3(0.0, 100.0, 0.0), Control{}, SimulationOptions{}, heights).visibility_fraction, 1.0);
  LineOfSight short_answer = [](const Points3&, const Points3&) { return std::vector<std::uint8_t>(3, 1); };
  EXPECT_THROW(simulate(plan, uav, Vec3(0.0, 100.0, 0.0), Control{}, SimulationOptions{}, short_answer), Error);
  EXPECT_FALSE(simulate(plan, uav, Vec3(0.0, 100.0, 0.0), Control{}).visibility_fraction.has_value());
}

// Line of sight on the real city against a brute-force oracle: points every 0.25 m along each
// UAV -> POI segment tested against every building footprint below its roof.
TEST(Simulate, VisibilityOnCharlotteMatchesBruteForce) {
  VISTRACK_REQUIRE_DATA(city, "charlotte/buildings.geojson");
  VISTRACK_REQUIRE_DATA(path, "charlotte/paths/paper_small.csv");
  const Environment env = Environment::from_geojson(city);
  const VisibilityScene scene(env);
  Uav uav;
  uav.speed = 20.0;
  uav.min_turn_radius = 5.0;
  uav.altitude = 50.0;
  Control control;
  control.beta = 0.5;
  control.k_psi = 40.0;
  const OrbitPlan plan = constant_radius_plan(PoiPath::from_csv(path, 5.0), 40.0, uav);
  SimulationOptions options;
  options.output_step = 0.5;
  const SimulationResult r = simulate(plan, uav, Vec3(-45.0, 450.0, 0.0), control, options, scene);
  ASSERT_EQ(r.visible.size(), r.t.size());
  ASSERT_TRUE(r.visibility_fraction.has_value());
  std::size_t agree = 0, visible = 0;
  for (Eigen::Index k = 0; k < r.state.rows(); ++k) {
    const Vec3 a(r.state(k, 0), r.state(k, 1), scene.ground_level() + uav.altitude);
    const Vec3 b = r.poi.row(k).transpose();
    bool blocked = false;
    const int n = static_cast<int>((a - b).norm() / 0.25);
    for (int i = 1; i < n && !blocked; ++i) {
      const Vec3 p = b + (a - b) * (static_cast<double>(i) / n);
      for (const Building& building : env.buildings())
        if (p.z() < building.height && contains(building.footprint, p.head<2>())) {
          blocked = true;
          break;
        }
    }
    agree += r.visible[static_cast<std::size_t>(k)] == !blocked;
    visible += r.visible[static_cast<std::size_t>(k)];
  }
  const double n = static_cast<double>(r.t.size());
  EXPECT_GE(static_cast<double>(agree) / n, 0.98);  // sampling can miss a grazing corner
  EXPECT_DOUBLE_EQ(*r.visibility_fraction, static_cast<double>(visible) / n);
  EXPECT_GT(*r.visibility_fraction, 0.0);
}

TEST_F(TwoLegPath, BadInputNamesTheField) {
  OrbitPlan plan = constant_radius_plan(poi, 150.0, uav);
  EXPECT_NE(error_message([&] { simulate(plan, uav, Vec3(std::nan(""), 0.0, 0.0), Control{}); }).find("x0[0]"),
            std::string::npos);
  // A direction is a Circulation: a bad one can only come from text, which names its field.
  EXPECT_NE(error_message([&] { from_name<Circulation>("sideways", "control.direction"); }).find("control.direction"),
            std::string::npos);
  Uav slow = uav;
  slow.speed = 4.0;
  EXPECT_NE(error_message([&] { simulate(plan, slow, Vec3::Zero(), Control{}); }).find("uav.speed"), std::string::npos);
  OrbitPlan steep = plan;
  steep.radii[1] = steep.radii[0] + 20.0 * (steep.times[1] - steep.times[0]);  // dR/dt = 20 > v - v_g
  EXPECT_NE(error_message([&] { simulate(steep, uav, Vec3::Zero(), Control{}); }).find("Lemma 5"), std::string::npos);
  SimulationOptions options;
  options.output_step = 0.0;
  EXPECT_NE(error_message([&] { simulate(plan, uav, Vec3::Zero(), Control{}, options); }).find("output_step"),
            std::string::npos);
  EXPECT_THROW(simulate(plan, uav, Vec3::Zero(), Control{}, SimulationOptions{}, {}, -1.0), Error);
}

TEST(Tuning, PaperFigure9Parameters) {
  // Section V.D: R = 85.9 m, R_dot = 1.30 m/s, v = 20 m/s, v_g = 5 m/s, beta = 0.025, r >= R.
  // The paper reports a maximum of 0.378 rad/s, below v / r_min = 0.4 rad/s.
  TuningGrid grid;
  grid.num_radii = 120;
  grid.num_angles = 240;
  grid.num_heading_errors = 61;
  const TuningResult t = tune_turn_rate(85.9, 1.30, 20.0, 5.0, 0.025, Circulation::CounterClockwise, grid);
  EXPECT_GT(t.max_turn_rate, 0.3);
  EXPECT_LT(t.max_turn_rate, 0.4);
  // The maximum is attained somewhere on the grid and is the map's maximum.
  EXPECT_DOUBLE_EQ(*std::max_element(t.map.begin(), t.map.end()), t.max_turn_rate);
  EXPECT_EQ(t.map.size(), 120u * 240u);
  // Brute-force re-evaluation at the reported arg-max.
  GuidanceGains gains;
  gains.beta = 0.025;
  OrbitState orbit;
  orbit.center_velocity = Vec2(5.0, 0.0);
  orbit.radius = 85.9;
  orbit.radius_rate = 1.30;
  const VectorField f = vector_field(t.at_r * Vec2(std::cos(t.at_theta), std::sin(t.at_theta)), orbit, gains);
  EXPECT_NEAR(std::abs(f.heading_rate + lyapunov_term(f, orbit, 0.025, t.at_heading_error)), t.max_turn_rate, 1e-12);
  // Larger beta attracts harder and turns harder.
  EXPECT_GT(tune_turn_rate(85.9, 1.30, 20.0, 5.0, 0.1, Circulation::CounterClockwise, grid).max_turn_rate, t.max_turn_rate);
  EXPECT_THROW(tune_turn_rate(85.9, 16.0, 20.0, 5.0, 0.025), Error);
  grid.tau = 0.0;
  EXPECT_THROW(tune_turn_rate(85.9, 1.3, 20.0, 5.0, 0.025, Circulation::CounterClockwise, grid), Error);
}

}  // namespace
}  // namespace vistrack
