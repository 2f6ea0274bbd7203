// The flight layer: vehicle kinematics against closed forms (discrete and continuous), wind and
// Dryden gusts against their analytic statistics, the feedback law (5) by hand, the waypoint
// follower, switching only on accepted steps, timed and fed waypoints, bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <string>
#include <vector>

#include "vistrack/error.hpp"
#include "vistrack/flight.hpp"
#include "flight_setup.hpp"

using namespace vistrack;

namespace {

constexpr double kPiTest = 3.14159265358979323846;

// A guidance that asks for a constant turn rate and records every advance() call.
class ConstantTurn : public FlightGuidance {
 public:
  explicit ConstantTurn(double rate, double stop_time = 1e300) : rate_(rate), stop_time_(stop_time) {}
  void start(const Configuration&, double t) override { advanced.assign(1, t); }
  GuidanceCommand command(const Configuration&, double) const override { return {rate_, Vec2(1, 2), 7}; }
  void advance(const Configuration&, double t) override {
    advanced.push_back(t);
    if (t >= stop_time_) done_ = true;
  }
  bool done() const override { return done_; }
  std::vector<double> advanced;

 private:
  double rate_, stop_time_;
  bool done_ = false;
};

using flight_setup::options;
using flight_setup::vehicle;

void expect_error_names(const std::function<void()>& call, const std::string& field) {
  try {
    call();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    return;
  }
  ADD_FAILURE() << "no Error naming " << field;
}

}  // namespace

// ---- kinematics ------------------------------------------------------------------------------

TEST(FlightKinematics, StraightLineInConstantWindBothIntegrators) {
  Wind wind;
  wind.east = 0.1;
  wind.north = -0.05;
  for (auto integration : {FlightIntegration::Discrete, FlightIntegration::Continuous}) {
    ConstantTurn straight(0.0);
    const auto traj = fly(vehicle(0.8, 0.7), wind, straight, {1.0, 2.0, 0.5}, options(integration, 0.02, 3.0));
    ASSERT_FALSE(traj.finished);
    EXPECT_NEAR(traj.end_time, 3.0, 1e-12);
    const double t = traj.t.back();
    EXPECT_NEAR(traj.x.back(), 1.0 + t * (0.8 * std::cos(0.5) + 0.1), 1e-9);
    EXPECT_NEAR(traj.y.back(), 2.0 + t * (0.8 * std::sin(0.5) - 0.05), 1e-9);
    EXPECT_EQ(traj.target_index.front(), 7);
    EXPECT_DOUBLE_EQ(traj.wind_east.front(), 0.1);
  }
}

TEST(FlightKinematics, ContinuousFullTurnIsTheCircleOfRadiusR) {
  // Asking for more than v/R gives exactly v/R: a circle of radius R about (0, R).
  ConstantTurn turn(10.0);
  const double v = 0.8, R = 0.7;
  const auto traj = fly(vehicle(v, R), Wind{}, turn, {0, 0, 0}, options(FlightIntegration::Continuous, 0.05, 10.0));
  for (std::size_t k = 0; k < traj.size(); ++k) {
    EXPECT_NEAR(std::hypot(traj.x[k], traj.y[k] - R), R, 1e-7);
    EXPECT_NEAR(traj.psi[k], v / R * traj.t[k], 1e-7);
    EXPECT_DOUBLE_EQ(traj.command[k], v / R);
  }
}

TEST(FlightKinematics, DiscreteTurnIsTheChordPolygonOfTheClosedForm) {
  // Turn psi_max = v dt / R, then a chord v dt: the points lie on a circle of radius
  // (v dt / 2) / sin(psi_max / 2) (slightly more than R), starting at the origin.
  const double v = 0.8, R = 0.7, dt = 0.02;
  ConstantTurn turn(-10.0);
  const auto traj = fly(vehicle(v, R), Wind{}, turn, {0, 0, 0}, options(FlightIntegration::Discrete, dt, 5.0));
  const double psi_max = v * dt / R;
  const double rho = 0.5 * v * dt / std::sin(0.5 * psi_max);
  // Centre: the first chord goes from the origin at heading -psi_max; the centre lies on its
  // perpendicular bisector, to the right.
  const Vec2 p1(v * dt * std::cos(-psi_max), v * dt * std::sin(-psi_max));
  const Vec2 mid = 0.5 * p1, right(std::sin(-psi_max), -std::cos(-psi_max));
  const Vec2 centre = mid + right * std::sqrt(rho * rho - 0.25 * (v * dt) * (v * dt));
  ASSERT_EQ(traj.size(), 251u);
  for (std::size_t k = 0; k < traj.size(); ++k) {
    EXPECT_NEAR((Vec2(traj.x[k], traj.y[k]) - centre).norm(), rho, 1e-12);
    EXPECT_NEAR(traj.psi[k], -psi_max * static_cast<double>(k), 1e-12);
  }
}

TEST(FlightKinematics, StopsWhenTheGuidanceIsDone) {
  ConstantTurn turn(0.0, 1.0);
  const auto traj = fly(vehicle(1, 1), Wind{}, turn, {0, 0, 0}, options(FlightIntegration::Discrete, 0.1, 100.0));
  EXPECT_TRUE(traj.finished);
  EXPECT_NEAR(traj.end_time, 1.0, 1e-12);
  EXPECT_NEAR(traj.x.back(), 1.0, 1e-12);
}

TEST(FlightKinematics, AdvanceRunsOnAcceptedStepsOnly) {
  // Discrete: once per step, at t0 + k dt. Continuous: once per accepted step, in increasing
  // time, never at the trial times of rejected or intermediate stages.
  ConstantTurn d(0.3);
  fly(vehicle(1, 1), Wind{}, d, {0, 0, 0}, options(FlightIntegration::Discrete, 0.1, 1.0), 2.0);
  ASSERT_EQ(d.advanced.size(), 11u);
  for (std::size_t k = 0; k < d.advanced.size(); ++k) EXPECT_NEAR(d.advanced[k], 2.0 + 0.1 * static_cast<double>(k), 1e-12);

  ConstantTurn c(0.3);
  const auto traj = fly(vehicle(1, 1), Wind{}, c, {0, 0, 0}, options(FlightIntegration::Continuous, 0.1, 1.0));
  EXPECT_EQ(c.advanced.size(), traj.statistics.accepted_steps + 1);
  EXPECT_TRUE(std::is_sorted(c.advanced.begin(), c.advanced.end()));
  EXPECT_GT(traj.statistics.rhs_evaluations, 5 * traj.statistics.accepted_steps);
}

// ---- wind and gusts ----------------------------------------------------------------------------

TEST(FlightWind, WindAtOrAboveAirspeedIsAnErrorNamingTheField) {
  Wind wind;
  wind.north = 0.8;
  ConstantTurn g(0.0);
  expect_error_names([&] { fly(vehicle(0.8, 0.7), wind, g, {0, 0, 0}); }, "wind");
  wind.north = 0.5;
  wind.gusts = Gusts{};
  wind.gusts->intensity = 2.0;
  wind.gusts->length_scale = 10.0;
  expect_error_names([&] { WindField(wind, 0.8, 0.0, 100.0); }, "wind.gusts.intensity");
  wind.east = std::nan("");
  expect_error_names([&] { WindField(wind, 0.8, 0.0, 100.0); }, "wind.east");
}

TEST(FlightWind, AFieldMadeForAFasterVehicleIsCheckedAgainstThisOne) {
  Wind wind;
  wind.north = 0.9;
  const WindField field(wind, 2.0, 0.0, 10.0);  // fine for an airspeed of 2
  ConstantTurn g(0.0);
  expect_error_names([&] { fly(vehicle(0.8, 0.7), field, g, {0, 0, 0}); }, "wind");
  EXPECT_NO_THROW(fly(vehicle(1.0, 0.7), field, g, {0, 0, 0}, options(FlightIntegration::Discrete, 0.1, 1.0)));
}

TEST(FlightWind, MilF8785cLowAltitudeByHand) {
  // h = 50 m = 164.04 ft: 0.177 + 0.000823 h = 0.31200; W20 = 7.7 m/s (light, 15 kt).
  const DrydenLowAltitude m = dryden_low_altitude(50.0, 7.7);
  const double h = 50.0 / 0.3048, base = 0.177 + 0.000823 * h;
  EXPECT_NEAR(m.sigma_w, 0.77, 1e-15);
  EXPECT_NEAR(m.sigma_u, 0.77 / std::pow(base, 0.4), 1e-12);
  EXPECT_NEAR(m.sigma_u, 1.2269, 1e-4);
  EXPECT_NEAR(m.length_u, 202.29, 0.01);  // 663.7 ft
  EXPECT_NEAR(m.length_w, 50.0, 1e-12);
  const Gusts g = mil_f_8785c_gusts(50.0, 7.7, 3, 20.0, 20.0);
  EXPECT_NEAR(g.intensity, m.sigma_u / 20.0, 1e-15);
  EXPECT_NEAR(g.length_scale, m.length_u / 20.0, 1e-12);
  expect_error_names([] { dryden_low_altitude(400.0, 7.7); }, "altitude");
}

TEST(FlightWind, DrydenFiltersHaveTheSpectraVarianceAndExactDiscretization) {
  const double sigma = 1.3, T = 2.0, h = 0.1;
  for (bool lateral : {false, true}) {
    const auto f = detail::dryden_filter(sigma, T, h, lateral);
    EXPECT_NEAR(f.output * f.stationary * f.output.transpose(), sigma * sigma, 1e-12) << lateral;
    // Stationarity: Phi P Phi^T + Q = P.
    const Eigen::Matrix2d q = f.noise_root * f.noise_root.transpose();
    EXPECT_LT((f.transition * f.stationary * f.transition.transpose() + q - f.stationary).norm(), 1e-12);
  }
  // First order: Phi = e^{-h/T}, Q = (1 - e^{-2h/T}) T / 2 (closed form).
  const auto u = detail::dryden_filter(sigma, T, h, false);
  EXPECT_NEAR(u.transition(0, 0), std::exp(-h / T), 1e-14);
  EXPECT_NEAR(u.noise_root(0, 0) * u.noise_root(0, 0) + u.noise_root(0, 1) * u.noise_root(0, 1),
              (1.0 - std::exp(-2.0 * h / T)) * T / 2.0, 1e-14);
  // Double pole: Phi = e^{-h/T} [[1 + h/T, h], [-h/T^2, 1 - h/T]].
  const auto v = detail::dryden_filter(sigma, T, h, true);
  const double e = std::exp(-h / T);
  EXPECT_NEAR(v.transition(0, 0), e * (1 + h / T), 1e-14);
  EXPECT_NEAR(v.transition(0, 1), e * h, 1e-14);
  EXPECT_NEAR(v.transition(1, 0), -e * h / (T * T), 1e-14);
  EXPECT_NEAR(v.transition(1, 1), e * (1 - h / T), 1e-14);
}

TEST(FlightWind, DrydenSeriesMatchesTheAutocorrelations) {
  // 400k samples at h = T / 20 (20000 correlation times): variance and the autocorrelations
  // e^{-tau/T} and e^{-tau/T} (1 - tau / 2T) at tau = T/2, T, 2T within a few standard errors.
  const double sigma = 0.5, T = 1.0, h = T / 20.0;
  const std::size_t n = 400000;
  detail::NormalStream noise(42);
  for (bool lateral : {false, true}) {
    const auto s = detail::dryden_series(detail::dryden_filter(sigma, T, h, lateral), n, noise);
    const double mean = std::accumulate(s.begin(), s.end(), 0.0) / static_cast<double>(n);
    EXPECT_NEAR(mean, 0.0, 0.03);
    auto correlation = [&](std::size_t lag) {
      double sum = 0.0;
      for (std::size_t k = 0; k + lag < n; ++k) sum += s[k] * s[k + lag];
      return sum / static_cast<double>(n - lag);
    };
    EXPECT_NEAR(correlation(0), sigma * sigma, 0.04 * sigma * sigma) << lateral;
    for (std::size_t lag : {10u, 20u, 40u}) {
      const double tau = static_cast<double>(lag) * h;
      const double expected = sigma * sigma * std::exp(-tau / T) * (lateral ? 1.0 - tau / (2.0 * T) : 1.0);
      EXPECT_NEAR(correlation(lag), expected, 0.04 * sigma * sigma) << lateral << " lag " << lag;
    }
  }
}

TEST(FlightWind, GustsAreReproducibleFromTheSeedAndInterpolated) {
  Wind wind;
  wind.east = 0.05;
  wind.gusts = Gusts{};
  wind.gusts->seed = 7;
  wind.gusts->intensity = 0.05;
  wind.gusts->length_scale = 10.0;
  const WindField a(wind, 0.8, 1.0, 60.0), b(wind, 0.8, 1.0, 60.0);
  wind.gusts->seed = 8;
  const WindField c(wind, 0.8, 1.0, 60.0);
  EXPECT_NEAR(a.sample_step(), 10.0 / 0.8 / 20.0, 1e-15);
  double differs = 0.0;
  for (double t = 1.0; t < 61.0; t += 0.377) {
    EXPECT_EQ(a.at(t), b.at(t));
    differs = std::max(differs, (a.at(t) - c.at(t)).norm());
  }
  EXPECT_GT(differs, 0.01);
  // Linear between samples, exact at them.
  const double step = a.sample_step();
  EXPECT_DOUBLE_EQ(a.at(1.0 + 3 * step).x(), 0.05 + a.gust_east()[3]);
  const Vec2 mid = a.at(1.0 + 3.5 * step);
  EXPECT_NEAR(mid.y(), 0.5 * (a.gust_north()[3] + a.gust_north()[4]), 1e-15);
  // Along the mean wind (east): u is the east component.
  EXPECT_GT(a.max_speed(), 0.05);
}

TEST(FlightWind, ContinuousFlightSeesTheSameWindAsTheSeries) {
  // Straight flight: the drift is the integral of the piecewise linear wind (trapezoids).
  Wind wind;
  wind.gusts = Gusts{};
  wind.gusts->seed = 3;
  wind.gusts->intensity = 0.05;
  wind.gusts->length_scale = 4.0;
  wind.gusts->sample_step = 0.25;
  const WindField field(wind, 0.8, 0.0, 11.0);
  ConstantTurn straight(0.0);
  const auto traj = fly(vehicle(0.8, 0.7), field, straight, {0, 0, 0},
                        options(FlightIntegration::Continuous, 0.25, 10.0));
  double drift_x = 0.0, drift_y = 0.0;
  for (std::size_t k = 0; k < 40; ++k) {
    drift_x += 0.125 * (field.gust_east()[k] + field.gust_east()[k + 1]);
    drift_y += 0.125 * (field.gust_north()[k] + field.gust_north()[k + 1]);
  }
  EXPECT_NEAR(traj.x.back(), 8.0 + drift_x, 1e-9);
  EXPECT_NEAR(traj.y.back(), drift_y, 1e-9);
}

// ---- the feedback law (5) ----------------------------------------------------------------------

TEST(FlightLineFeedback, ByHand) {
  const LineFeedback law(0.8, 0.7, 0.02, {0.1, 5.25});
  const double psi_max = 0.8 * 0.02 / 0.7;
  EXPECT_NEAR(law.max_turn(), psi_max, 1e-16);
  // On the line, heading at the target: no turn.
  auto t = law.terms({1, 0, 0}, {0, 0}, {5, 0});
  EXPECT_EQ(t.turn, 0.0);
  EXPECT_EQ(t.cross_track, 0.0);
  // Target 90 degrees left: saturated left.
  t = law.terms({0, 0, 0}, {0, -5}, {0, 5});
  EXPECT_NEAR(t.target_angle, kPiTest / 2, 1e-15);
  EXPECT_TRUE(t.saturated);
  EXPECT_NEAR(t.turn, psi_max, 1e-16);
  // Small case: 0.05 right of the line y = 0 towards (10, 0), heading 0.001 rad.
  // phi_T = atan2(0.05, 10) - 0.001; s = -0.05; s_dot dt = 0.8 sin(0.001) 0.02;
  // phi_R = |0.1 (-0.05) + 5.25 s_dot dt| sign(phi_T).
  t = law.terms({0, -0.05, 0.001}, {-10, 0}, {10, 0});
  const double phi_t = std::atan2(0.05, 10.0) - 0.001;
  const double s_step = 0.8 * std::sin(0.001) * 0.02;
  const double phi_r = std::abs(0.1 * -0.05 + 5.25 * s_step);
  EXPECT_NEAR(t.target_angle, phi_t, 1e-15);
  EXPECT_NEAR(t.cross_track, -0.05, 1e-15);
  EXPECT_NEAR(t.cross_track_step, s_step, 1e-18);
  EXPECT_NEAR(t.reference_angle, phi_r, 1e-15);
  EXPECT_NEAR(t.turn, std::min(phi_t + phi_r, psi_max), 1e-15);
  EXPECT_NEAR(law.turn_rate({0, -0.05, 0.001}, {-10, 0}, {10, 0}), t.turn / 0.02, 1e-13);
  // Mirror image: everything changes sign.
  const auto m = law.terms({0, 0.05, -0.001}, {-10, 0}, {10, 0});
  EXPECT_NEAR(m.turn, -t.turn, 1e-16);
  // Smooth sign: phi_R scaled by phi_T / psi_max inside +-psi_max.
  const LineFeedback smooth(0.8, 0.7, 0.02, {0.1, 5.25}, true);
  const auto sm = smooth.terms({0, -0.05, 0.001}, {-10, 0}, {10, 0});
  EXPECT_NEAR(sm.reference_angle, phi_r * std::min(1.0, phi_t / psi_max), 1e-15);
}

TEST(FlightLineFeedback, StepTooLargeIsAnError) {
  // psi_max = v dt / R > pi/2.
  expect_error_names([] { LineFeedback(0.8, 0.7, 1.5, {}); }, "dt");
  expect_error_names([] { LineFeedback(0.8, 0.0, 0.02, {}); }, "turn_radius");
  expect_error_names([] { LineFeedback(0.8, 0.7, 0.02, {-1.0, 1.0}); }, "gains.g");
}

// ---- waypoint follower -------------------------------------------------------------------------

TEST(FlightWaypointFollower, FliesASquareAndSwitchesInsideTheRadius) {
  const std::vector<Vec2> square{{6, 0}, {6, 6}, {0, 6}, {0, 0}};
  for (auto integration : {FlightIntegration::Discrete, FlightIntegration::Continuous}) {
    // Continuous flight needs the smooth sign (the exact one makes a sliding mode).
    const LineFeedback law(0.8, 0.7, 0.02, {}, integration == FlightIntegration::Continuous);
    WaypointFollower wn(law, square, 0.35);
    const auto traj = fly(vehicle(0.8, 0.7), Wind{}, wn, {0, 0, 0}, options(integration, 0.02, 200.0));
    ASSERT_TRUE(traj.finished) << to_string(integration);
    EXPECT_EQ(wn.active(), 3u);
    for (std::size_t k = 0; k < 4; ++k) {
      ASSERT_FALSE(std::isnan(wn.accepted_at()[k]));
      if (k > 0) {
        EXPECT_GT(wn.accepted_at()[k], wn.accepted_at()[k - 1]);
      }
    }
    // Each accepted time is a sample where the distance is within the radius; in continuous
    // flight the switch is located on the dense output: exactly on the circle.
    for (std::size_t k = 0; k < 4; ++k) {
      const double t = wn.accepted_at()[k];
      const auto it = std::find(traj.t.begin(), traj.t.end(), t);
      ASSERT_NE(it, traj.t.end());
      const auto i = static_cast<std::size_t>(it - traj.t.begin());
      const double d = std::hypot(traj.x[i] - square[k].x(), traj.y[i] - square[k].y());
      EXPECT_LE(d, 0.35 + 1e-12);
      if (integration == FlightIntegration::Continuous) {
        EXPECT_NEAR(d, 0.35, 1e-9);
      }
      // A sample holds the target its command steers to from there on: already the next one.
      EXPECT_EQ(traj.target_index[i], static_cast<int>(std::min<std::size_t>(k + 1, 3)));
    }
    EXPECT_EQ(traj.switch_times.size(), 4u);
  }
}

TEST(FlightWaypointFollower, PassedLineAcceptsOnTheFinishLineAndAnticipatesTurns) {
  // ArduPlane's switching: the acceptance distance min(R_WP, L1) x min(turn, 90 deg) / 90 deg.
  const L1Line l1(0.8, {10.0, 0.75});  // L1 = 0.75 * 10 * 0.8 / pi = 1.91
  const double radius = 0.35;
  WaypointFollower right_angle(l1, {{6, 0}, {6, 6}}, radius);
  right_angle.set_passed_line(true);
  right_angle.start({0, 0, 0}, 0.0);
  EXPECT_NEAR(right_angle.acceptance_distance(), 0.35, 1e-15);  // 90 deg: the whole R_WP (< L1)
  WaypointFollower shallow(l1, {{6, 0}, {12, 6 * std::tan(0.3)}}, radius);
  shallow.set_passed_line(true);
  shallow.start({0, 0, 0}, 0.0);
  EXPECT_NEAR(shallow.acceptance_distance(), 0.35 * 0.3 / (0.5 * kPiTest), 1e-12);
  const LineFeedback law(0.8, 0.7, 0.02);
  WaypointFollower capped(l1, {{6, 0}, {6, 6}}, 5.0);
  capped.set_passed_line(true);
  capped.start({0, 0, 0}, 0.0);
  EXPECT_NEAR(capped.acceptance_distance(), l1.distance(), 1e-12);  // capped by L1, not by the law (5)
  WaypointFollower uncapped(law, {{6, 0}, {6, 6}}, 5.0);
  uncapped.set_passed_line(true);
  uncapped.start({0, 0, 0}, 0.0);
  EXPECT_NEAR(uncapped.acceptance_distance(), 5.0, 1e-15);
  // A vehicle passing 1 R_WP beside the waypoint: the paper's WN keeps the waypoint, the
  // passed-line one accepts it where it crosses x = 6, in both integrators (continuous: on the line).
  for (auto integration : {FlightIntegration::Discrete, FlightIntegration::Continuous}) {
    for (bool passed : {false, true}) {
      struct Straight : FlightGuidance {  // flies straight on, whatever the target
        WaypointFollower* inner;
        explicit Straight(WaypointFollower* w) : inner(w) {}
        void start(const Configuration& q, double t) override { inner->start(q, t); }
        GuidanceCommand command(const Configuration& q, double t) const override {
          GuidanceCommand c = inner->command(q, t);
          c.turn_rate = 0.0;
          return c;
        }
        void advance(const Configuration& q, double t) override { inner->advance(q, t); }
        bool done() const override { return inner->done(); }
        double switching_function(const Configuration& q, double t) const override {
          return inner->switching_function(q, t);
        }
      };
      WaypointFollower follower(law, {{6, 0.7}, {12, 0.7}}, radius);
      follower.set_passed_line(passed);
      Straight straight(&follower);
      const auto traj = fly(vehicle(0.8, 0.7), Wind{}, straight, {0, 0, 0}, options(integration, 0.02, 14.0));
      if (!passed) {
        EXPECT_TRUE(std::isnan(follower.accepted_at()[0])) << to_string(integration);
        continue;
      }
      ASSERT_FALSE(std::isnan(follower.accepted_at()[0])) << to_string(integration);
      // The finish line is perpendicular to the leg (0, 0) -> (6, 0.7): at y = 0 it is x = 6 + 0.49 / 6.
      const double crossing = (6.0 + 0.49 / 6.0) / 0.8;
      EXPECT_GE(follower.accepted_at()[0], crossing - 1e-9);
      EXPECT_LE(follower.accepted_at()[0], crossing + (integration == FlightIntegration::Continuous ? 1e-6 : 0.02));
    }
  }
}

TEST(FlightWaypointFollower, DiscreteAndContinuousFlyTheSamePath) {
  // Same law (smooth sign), same route: the two integrators' paths stay close (the discrete
  // update is first order in dt).
  const std::vector<Vec2> route{{5, 0}, {8, 4}, {4, 8}};
  const LineFeedback law(0.8, 0.7, 0.02, {}, true);
  WaypointFollower a(law, route, 0.7), b(law, route, 0.7);
  const auto d = fly(vehicle(0.8, 0.7), Wind{}, a, {0, 0, 0}, options(FlightIntegration::Discrete, 0.02, 60.0));
  const auto c = fly(vehicle(0.8, 0.7), Wind{}, b, {0, 0, 0}, options(FlightIntegration::Continuous, 0.02, 60.0));
  ASSERT_TRUE(d.finished && c.finished);
  EXPECT_NEAR(d.end_time, c.end_time, 0.1);
  double worst = 0.0;
  for (std::size_t k = 0; k < c.size(); ++k) {
    double best = 1e9;
    for (std::size_t j = 0; j < d.size(); ++j) best = std::min(best, std::hypot(c.x[k] - d.x[j], c.y[k] - d.y[j]));
    worst = std::max(worst, best);
  }
  EXPECT_LT(worst, 0.02);
}

TEST(FlightWaypointFollower, TimedWaypointsBecomeActiveAtTheirTime) {
  for (auto integration : {FlightIntegration::Discrete, FlightIntegration::Continuous}) {
    const LineFeedback law(1.0, 1.0, 0.05, {}, integration == FlightIntegration::Continuous);
    WaypointFollower wn(law, {{3, 0}}, 0.5, false);
    wn.add_waypoint({3, 10}, 5.0);
    const auto traj = fly(vehicle(1, 1), Wind{}, wn, {0, 0, 0}, options(integration, 0.05, 8.0));
    EXPECT_FALSE(traj.finished);
    EXPECT_EQ(wn.active(), 1u);
    // The target is waypoint 0 strictly before t = 5 and waypoint 1 from then on.
    for (std::size_t k = 0; k < traj.size(); ++k)
      EXPECT_EQ(traj.target_index[k], traj.t[k] < 5.0 - 1e-9 ? 0 : 1) << traj.t[k];
    EXPECT_NEAR(traj.switch_times.back(), 5.0, 1e-9);
  }
}

TEST(FlightWaypointFollower, FedFromTheStepCallbackOnceASecond) {
  // A planner feeding a waypoint each second ahead of a point moving east at 0.5 m/s.
  for (auto integration : {FlightIntegration::Discrete, FlightIntegration::Continuous}) {
    const LineFeedback law(1.0, 1.0, 0.02, {}, integration == FlightIntegration::Continuous);
    WaypointFollower wn(law, {{2, 0}}, 0.3, false);
    double next_feed = 1.0;
    const auto feed = [&](double t, const Configuration&) {
      if (t + 1e-9 < next_feed) return;
      wn.add_waypoint({2.0 + 0.5 * next_feed * 2.0, 0.0});
      next_feed += 1.0;
    };
    const auto traj = fly(vehicle(1, 1), Wind{}, wn, {0, 0, 0}, options(integration, 0.02, 10.5), 0.0, feed);
    EXPECT_EQ(wn.waypoints().size(), 11u);
    EXPECT_GT(wn.active(), 5u);
    EXPECT_NEAR(traj.y.back(), 0.0, 0.5);
  }
}

TEST(FlightWaypointFollower, BadInput) {
  const LineFeedback law(1.0, 1.0, 0.05);
  expect_error_names([&] { WaypointFollower(law, {{0, std::nan("")}}, 0.5); }, "waypoints[0].y");
  expect_error_names([&] { WaypointFollower(law, {{0, 1}}, -0.5); }, "waypoint_radius");
  WaypointFollower wn(law, {{0, 1}}, 0.5);
  wn.add_waypoint({1, 1}, 3.0);
  expect_error_names([&] { wn.add_waypoint({2, 1}, 2.0); }, "waypoints[2].available_from");
  ConstantTurn g(0.0);
  expect_error_names([&] { fly(vehicle(1, 1), Wind{}, g, {0, 0, 0}, options(FlightIntegration::Discrete, 2.0, 10)); },
                     "dt");
  expect_error_names([&] { fly(vehicle(1, 1), Wind{}, g, {0, std::nan(""), 0}); }, "start.y");
  expect_error_names([] { from_name<FlightIntegration>("rk4"); }, "integration");
}
