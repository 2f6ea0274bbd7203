// Following a ground vehicle: the sinusoid's elliptic-integral relations against independent
// quadrature, the ground vehicle, the loiter patterns, the planner's modes and geometry, and the
// camera model.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "error_message.hpp"
#include "vistrack/error.hpp"
#include "vistrack/follow.hpp"

using vistrack::testing::error_message;

namespace vistrack {
namespace {

// Composite Simpson on [a, b] with n (even) intervals: an oracle that knows nothing of elliptic
// integrals.
double simpson(const std::function<double(double)>& f, double a, double b, int n = 20000) {
  const double h = (b - a) / n;
  double sum = f(a) + f(b);
  for (int i = 1; i < n; ++i) sum += f(a + i * h) * (i % 2 ? 4.0 : 2.0);
  return sum * h / 3.0;
}

// eq. (9): sigma = (1/D) int_0^D sqrt(1 + A'^2 cos^2(2 pi x / D)) dx, by quadrature.
double ratio_by_quadrature(double amplitude, double distance) {
  const double a = kTwoPi * amplitude / distance;
  return simpson([&](double x) { const double c = std::cos(kTwoPi * x / distance); return std::sqrt(1.0 + a * a * c * c); },
                 0.0, distance) / distance;
}

TEST(FollowSinusoid, SpeedRatioMatchesQuadratureOfEquation9) {
  for (double amplitude : {0.0, 1.0, 10.0, 37.5, 100.0, 400.0, 2500.0}) {
    const double D = 300.0;
    EXPECT_NEAR(sinusoid_speed_ratio(amplitude, D), ratio_by_quadrature(amplitude, D), 1e-11) << amplitude;
  }
}

TEST(FollowSinusoid, RatioNearModulusOneToTheLastDigits) {
  // A' = 0.99 / sqrt(1 - 0.99^2): the modulus of E is 0.99, where libstdc++'s comp_ellint_2 is off
  // by 4e-13. Reference: E(0.99) = 1.02847580902880400098... by a 50-digit AGM.
  const double a = 7.0179239295825254175778100773711322679192568079958;
  EXPECT_NEAR(sinusoid_speed_ratio(a, kTwoPi) / 4.6413857633209128541644930962455483220089786409948, 1.0, 4e-16);
}

TEST(FollowSinusoid, AmplitudeInvertsTheRatioTo1e12) {
  for (double sigma = 1.001; sigma <= 10.0; sigma *= 1.07) {
    for (double D : {1.0, 250.0, 4000.0}) {
      const double A = sinusoid_amplitude(sigma, D);
      ASSERT_GT(A, 0.0);
      // Round trip on sigma, and A against the quadrature ratio (an independent oracle).
      EXPECT_NEAR(sinusoid_speed_ratio(A, D), sigma, 1e-14 * sigma);
      EXPECT_NEAR(ratio_by_quadrature(A, D), sigma, 1e-11);
      // 1e-12 relative on A: sigma(A (1 +- 1e-12)) brackets sigma.
      EXPECT_LE(sinusoid_speed_ratio(A * (1.0 - 1e-12), D), sigma);
      EXPECT_GE(sinusoid_speed_ratio(A * (1.0 + 1e-12), D), sigma);
    }
  }
}

TEST(FollowSinusoid, RatioOneGivesZeroAndBelowOneIsAnError) {
  EXPECT_EQ(sinusoid_amplitude(1.0, 100.0), 0.0);
  EXPECT_NE(error_message([] { sinusoid_amplitude(0.8, 100.0); }).find("speed_ratio = 0.8"), std::string::npos);
  EXPECT_NE(error_message([] { sinusoid_amplitude(std::nan(""), 100.0); }).find("speed_ratio"), std::string::npos);
  EXPECT_NE(error_message([] { sinusoid_amplitude(2.0, 0.0); }).find("period_distance = 0"), std::string::npos);
  EXPECT_NE(error_message([] { sinusoid_speed_ratio(-1.0, 10.0); }).find("amplitude = -1"), std::string::npos);
}

TEST(FollowSinusoid, SmallAndLargeRatiosFollowTheirAsymptotes) {
  // sigma = 1 + a^2/4 + O(a^4) and sigma ~ (2/pi) a for large a.
  const double s = 1.0 + 1e-6;
  EXPECT_NEAR(sinusoid_slope(s), 2.0 * std::sqrt(1e-6), 1e-8);
  const double big = 1e4;
  EXPECT_NEAR(sinusoid_slope(big) / (0.5 * kPi * big), 1.0, 1e-4);
}

TEST(FollowSinusoid, Equation5TakesOnePeriodTimeToCrossOnePeriod) {
  // Integrate x_dot of eq. (5) (RK4) until x = D: the time is D / v_g = sigma D / v_p.
  const double vp = 22.0, vg = 10.0, D = 400.0;
  const double A = sinusoid_amplitude(vp / vg, D);
  const double h = 1e-3;
  double x = 0.0, t = 0.0;
  auto rate = [&](double at) { return sinusoid_along_track_rate(at, A, D, vp); };
  while (true) {
    const double k1 = rate(x), k2 = rate(x + 0.5 * h * k1), k3 = rate(x + 0.5 * h * k2), k4 = rate(x + h * k3);
    const double next = x + h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
    if (next >= D) {
      t += h * (D - x) / (next - x);
      break;
    }
    x = next;
    t += h;
  }
  EXPECT_NEAR(t, D / vg, 1e-6);
}

TEST(FollowSinusoid, ArcLengthAndItsInverse) {
  const double A = 120.0, D = 500.0;
  const double a = kTwoPi * A / D;
  for (double x : {-730.0, -10.0, 0.0, 3.0, 125.0, 250.0, 499.0, 1234.5}) {
    const double by_quadrature = simpson([&](double u) { const double c = std::cos(kTwoPi * u / D); return std::sqrt(1.0 + a * a * c * c); },
                                         0.0, x);
    const double arc = sinusoid_arc_length(x, A, D);
    EXPECT_NEAR(arc, by_quadrature, 1e-8 * (1.0 + std::abs(arc))) << x;
    EXPECT_NEAR(sinusoid_phase_at_arc(arc, A, D), kTwoPi * x / D, 1e-12 * (1.0 + std::abs(x))) << x;
  }
  // One period is sigma D long.
  EXPECT_NEAR(sinusoid_arc_length(D, A, D), sinusoid_speed_ratio(A, D) * D, 1e-9);
}

TEST(FollowVehicle, LegsWithStopAndTurn) {
  const double north = 0.5 * kPi;
  const GroundVehicle v = GroundVehicle::from_legs({{north, 8.0, 10.0}, {north, 0.0, 5.0}, {0.0, 8.0, 10.0}}, Vec2(1.0, 2.0));
  EXPECT_NEAR(v.end_time(), 25.0, 1e-12);
  EXPECT_TRUE(v.position(10.0).isApprox(Vec2(1.0, 82.0)));
  EXPECT_TRUE(v.position(13.0).isApprox(Vec2(1.0, 82.0)));
  EXPECT_NEAR(v.speed(12.0), 0.0, 1e-12);
  EXPECT_NEAR(v.heading(12.0), north, 1e-12);  // standing, facing north
  EXPECT_TRUE(v.velocity(20.0).isApprox(Vec2(8.0, 0.0)));
  EXPECT_TRUE(v.position(25.0).isApprox(Vec2(81.0, 82.0)));
  // A ramp: 0 -> 20 m/s over 10 s travels 100 m.
  const GroundVehicle ramp = GroundVehicle::from_legs({{0.0, 0.0, 10.0, 20.0}});
  EXPECT_NEAR(ramp.position(10.0).x(), 100.0, 1e-9);
  EXPECT_NEAR(ramp.position(5.0).x(), 25.0, 1e-9);
  EXPECT_NEAR(ramp.max_speed(), 20.0, 0.2);
}

TEST(FollowVehicle, BadTracksNameTheField) {
  Points2 p(3, 2);
  p << 0, 0, 1, 0, 2, 0;
  EXPECT_NE(error_message([&] { GroundVehicle({0.0, 2.0, 1.0}, p); }).find("track.t[2] = 1"), std::string::npos);
  EXPECT_NE(error_message([&] { GroundVehicle({0.0, 1.0, 1.0}, p); }).find("track.t[2]"), std::string::npos);
  Points2 q = p;
  q(1, 1) = std::nan("");
  EXPECT_NE(error_message([&] { GroundVehicle({0.0, 1.0, 2.0}, q); }).find("track.y[1]"), std::string::npos);
  EXPECT_NE(error_message([&] { GroundVehicle::from_legs({{0.0, -1.0, 10.0}}); }).find("legs[0].speed = -1"), std::string::npos);
}

TEST(FollowVehicle, AlongAPathWithTheLegsSpeeds) {
  Points2 path(3, 2);
  path << 0, 0, 100, 0, 100, 100;
  const GroundVehicle v = GroundVehicle::along_path(path, {{0.0, 10.0, 5.0}, {0.0, 0.0, 4.0}, {0.0, 10.0, 100.0}});
  EXPECT_TRUE(v.position(5.0).isApprox(Vec2(50.0, 0.0)));
  EXPECT_TRUE(v.position(9.0).isApprox(Vec2(50.0, 0.0)));
  EXPECT_TRUE(v.position(14.0).isApprox(Vec2(100.0, 0.0)));
  EXPECT_TRUE(v.position(19.0).isApprox(Vec2(100.0, 50.0)));
  EXPECT_NEAR(v.heading(20.0), 0.5 * kPi, 1e-12);
  // Past the end of the road it turns and drives back.
  EXPECT_TRUE(v.position(29.0).isApprox(Vec2(100.0, 50.0)));
  EXPECT_NEAR(v.heading(29.0), -0.5 * kPi, 1e-12);
  EXPECT_NEAR(v.end_time(), 109.0, 1e-9);
}

TEST(FollowLoiter, RoseIsContinuousUnitSpeedAndReachesItsExtent) {
  for (int direction : {+1, -1}) {
    LoiterShape rose;
    rose.pattern = LoiterPattern::Rose;
    rose.turn_radius = 60.0;
    rose.radius = 200.0;
    rose.direction = direction;
    rose.rotation = 0.3;
    rose.validate();
    const double total = 7.0 * rose.piece_length();
    double farthest = 0.0, nearest = 1e9;
    const double h = 1e-4;
    for (double s = 0.0; s < total; s += 0.37) {
      const Vec2 d = (rose.position(s + h) - rose.position(s - h)) / (2 * h);
      EXPECT_NEAR(d.norm(), 1.0, 1e-6) << s;                      // arc-length parameter
      EXPECT_NEAR((d - rose.tangent(s)).norm(), 0.0, 1e-6) << s;  // the tangent is the derivative
      farthest = std::max(farthest, rose.position(s).norm());
      nearest = std::min(nearest, rose.position(s).norm());
    }
    EXPECT_NEAR(farthest, 200.0, 1e-3);
    EXPECT_LT(nearest, 0.5);  // every pass goes through the centre
    // Turning sense: cross product of successive tangents on an arc.
    const double s = 2.0 * rose.half_line() + 10.0;
    const Vec2 t0 = rose.tangent(s), t1 = rose.tangent(s + 1.0);
    EXPECT_GT(direction * (t0.x() * t1.y() - t0.y() * t1.x()), 0.0);
  }
}

TEST(FollowLoiter, CircleAndRoseValidation) {
  LoiterShape rose;
  rose.pattern = LoiterPattern::Rose;
  rose.turn_radius = 60.0;
  rose.radius = 100.0;
  EXPECT_NE(error_message([&] { rose.validate(); }).find("loiter_radius = 100"), std::string::npos);
}

// The paper's method: h = 3 (the default is "auto", picked from the camera).
FollowParameters base_parameters() {
  FollowParameters p;
  p.threshold = 3.0;
  p.wind_compensation = true;
  return p;
}

FollowObservation moving(const Vec2& velocity, const Vec2& uav = Vec2::Zero()) {
  FollowObservation o;
  o.vehicle_velocity = velocity;
  o.vehicle_heading = std::atan2(velocity.y(), velocity.x());
  o.uav_position = uav;
  return o;
}

TEST(FollowPlannerTest, HysteresisBandSuppressesChattering) {
  FollowParameters p = base_parameters();
  p.threshold = 3.0;
  p.hysteresis = 0.6;  // loiter above 3.3, sinusoid below 2.7
  const Uav uav{21.0, 50.0, 100.0};
  FollowPlanner planner(p, uav);
  // sigma oscillating between 2.75 and 3.25, inside the band: no switch after the first update.
  int switches = 0;
  FollowMode last = FollowMode::Sinusoid;
  for (int k = 0; k < 200; ++k) {
    const double sigma = 3.0 + 0.25 * std::sin(0.7 * k);
    const FollowTick tick = planner.update(k, moving(Vec2(21.0 / sigma, 0.0)));
    if (k > 0 && tick.mode != last) ++switches;
    last = tick.mode;
  }
  EXPECT_EQ(switches, 0);
  // One crossing of the band (vehicle slows from sigma 2 to 4 and stays): exactly one switch.
  FollowPlanner second(p, uav);
  switches = 0;
  for (int k = 0; k < 200; ++k) {
    const double sigma = (k < 100 ? 2.0 + 0.01 * k : 4.0) + 0.2 * std::sin(1.3 * k);  // noisy ramp
    const FollowTick tick = second.update(k, moving(Vec2(21.0 / sigma, 0.0)));
    if (k > 0 && tick.mode != last) ++switches;
    last = tick.mode;
  }
  EXPECT_EQ(switches, 1);
  EXPECT_EQ(last, FollowMode::Loiter);
  // The same ramp without a band chatters.
  p.hysteresis = 0.0;
  FollowPlanner bare(p, uav);
  switches = 0;
  for (int k = 0; k < 200; ++k) {
    const double sigma = (k < 100 ? 2.0 + 0.01 * k : 4.0) + 0.2 * std::sin(1.3 * k);
    const FollowTick tick = bare.update(k, moving(Vec2(21.0 / sigma, 0.0)));
    if (k > 0 && tick.mode != last) ++switches;
    last = tick.mode;
  }
  EXPECT_GT(switches, 1);
}

// A follow scenario without a uav block flies the follower's default vehicle: a valid one.
TEST(FollowPlannerTest, DefaultUavIsValid) {
  static_assert(kFollowUav.speed > 0.0 && kFollowUav.min_turn_radius > 0.0);
  EXPECT_NO_THROW(kFollowUav.validate());
  EXPECT_NO_THROW(FollowPlanner(FollowParameters{}, kFollowUav));
}

TEST(FollowPlannerTest, ParametersNameTheField) {
  FollowParameters p;
  p.threshold = 3.0;
  p.hysteresis = 3.5;
  EXPECT_NE(error_message([&] { p.validate(); }).find("follow.hysteresis = 3.5"), std::string::npos);
  p = FollowParameters{};
  p.threshold = -1.0;
  EXPECT_NE(error_message([&] { p.validate(); }).find("follow.threshold = -1"), std::string::npos);
  p = FollowParameters{};
  p.period = -1.0;
  EXPECT_NE(error_message([&] { p.validate(); }).find("follow.period = -1"), std::string::npos);
  EXPECT_NE(error_message([&] { from_name<LoiterPattern>("square", "follow.loiter_pattern"); })
                .find("follow.loiter_pattern = 'square'"), std::string::npos);
  const Uav bad{0.0, 50.0, 100.0};
  EXPECT_NE(error_message([&] { FollowPlanner(FollowParameters{}, bad); }).find("uav.speed = 0"), std::string::npos);
  const Uav uav{20.0, 50.0, 100.0};
  EXPECT_NE(error_message([&] { FollowPlanner(FollowParameters{}, uav, Vec2(0.0, 20.0)); }).find("wind_estimate"),
            std::string::npos);
}

TEST(FollowPlannerTest, OffsetVectorInBothReferences) {
  FollowParameters p = base_parameters();
  p.offset_distance = 40.0;
  p.offset_angle = 0.5 * kPi;  // north on the map; to the left of the vehicle when relative
  p.offset_reference = OffsetReference::North;
  const Uav uav{20.0, 50.0, 100.0};
  const FollowPlanner cardinal(p, uav);
  EXPECT_TRUE(cardinal.offset_vector(0.0).isApprox(Vec2(0.0, 40.0)));
  EXPECT_TRUE(cardinal.offset_vector(1.234).isApprox(Vec2(0.0, 40.0)));
  p.offset_reference = OffsetReference::Heading;
  const FollowPlanner relative(p, uav);
  EXPECT_TRUE(relative.offset_vector(0.0).isApprox(Vec2(0.0, 40.0)));        // heading east: left is north
  EXPECT_TRUE(relative.offset_vector(0.5 * kPi).isApprox(Vec2(-40.0, 0.0))); // heading north: left is west
  EXPECT_TRUE(relative.offset_vector(-0.5 * kPi).isApprox(Vec2(40.0, 0.0))); // heading south: left is east
  // The planner's offset point and waypoint follow it: a vehicle heading south, offset 40 m ahead.
  p.offset_angle = 0.0;
  FollowPlanner ahead(p, uav);
  FollowObservation o = moving(Vec2(0.0, -10.0));
  o.vehicle_position = Vec2(5.0, 5.0);
  const FollowTick tick = ahead.update(0.0, o);
  EXPECT_TRUE(tick.offset_point.isApprox(Vec2(5.0, -35.0)));
}

TEST(FollowPlannerTest, SinusoidDesiredPointMovesAtTheUavSpeedAndClosesEachPeriod) {
  FollowParameters p = base_parameters();
  p.period = 40.0;
  const Uav uav{22.0, 40.0, 100.0};
  FollowPlanner planner(p, uav);
  const Vec2 v(3.0, -9.5);
  const FollowTick tick = planner.update(0.0, moving(v));
  ASSERT_EQ(tick.mode, FollowMode::Sinusoid);
  const double h = 1e-4;
  for (double tau = 0.05; tau < tick.period; tau += 0.77) {
    const Vec2 a = v * (tau - h) + planner.relative_position(tick, tau - h);
    const Vec2 b = v * (tau + h) + planner.relative_position(tick, tau + h);
    EXPECT_NEAR((b - a).norm() / (2 * h), 22.0, 1e-5) << tau;
  }
  // After one period the pattern is back where it started, relative to the offset point.
  EXPECT_NEAR((planner.relative_position(tick, tick.period) - planner.relative_position(tick, 0.0)).norm(), 0.0, 1e-6);
  // The ground path of one period is sigma D long (eq. 9): sum of the chords at a fine step.
  double length = 0.0;
  Vec2 prev = planner.relative_position(tick, 0.0);
  const int n = 20000;
  for (int i = 1; i <= n; ++i) {
    const double tau = tick.period * i / n;
    const Vec2 q = v * tau + planner.relative_position(tick, tau);
    length += (q - prev).norm();
    prev = q;
  }
  EXPECT_NEAR(length, tick.speed_ratio * tick.period_distance, 1e-6 * length);
  // Its peak curvature stays within the planned turn radius.
  EXPECT_LE(tick.amplitude * std::pow(kTwoPi / tick.period_distance, 2), 1.0 / (p.turn_margin * 40.0) * (1 + 1e-12));
}

TEST(FollowPlannerTest, LoiterPatternMovesAtTheUavSpeed) {
  for (LoiterPattern pattern : {LoiterPattern::Circle, LoiterPattern::Rose}) {
    FollowParameters p = base_parameters();
    p.loiter_pattern = pattern;
    const Uav uav{20.0, 30.0, 100.0};
    FollowPlanner planner(p, uav);
    const Vec2 v(2.0, 1.0);  // sigma ~ 8.9: loiter
    FollowTick tick = planner.update(0.0, moving(v, Vec2(600.0, 0.0)));
    ASSERT_EQ(tick.mode, FollowMode::Loiter) << to_string(pattern);
    ASSERT_TRUE(tick.capturing);  // 600 m from the centre: not on the pattern yet
    tick.capturing = false;       // the pattern itself
    const double h = 1e-3;
    for (double tau = 0.1; tau < 60.0; tau += 1.3) {
      const Vec2 a = v * (tau - h) + planner.relative_position(tick, tau - h);
      const Vec2 b = v * (tau + h) + planner.relative_position(tick, tau + h);
      EXPECT_NEAR((b - a).norm() / (2 * h), 20.0, 1e-4) << to_string(pattern) << " " << tau;
    }
  }
}

TEST(FollowPlannerTest, EnteringAPatternHoldsItsPointUntilTheUavIsClose) {
  FollowPlanner planner(base_parameters(), Uav{20.0, 50.0, 100.0});
  const Vec2 v(0.0, 10.0);  // sigma 2: sinusoid about the vehicle
  FollowObservation o = moving(v, Vec2(600.0, 0.0));
  FollowTick tick = planner.update(0.0, o);
  ASSERT_EQ(tick.mode, FollowMode::Sinusoid);
  ASSERT_TRUE(tick.capturing);
  // Held: the desired point moves with the offset point only.
  const Vec2 held = planner.relative_position(tick, 0.0);
  EXPECT_TRUE(planner.relative_position(tick, 0.7).isApprox(held));
  EXPECT_TRUE(tick.waypoint.isApprox(tick.offset_point + v * 1.0 + held));
  // Still far at the next update: held at the same phase.
  o.vehicle_position = v * 1.0;
  o.uav_position = Vec2(580.0, 10.0);
  FollowTick next = planner.update(1.0, o);
  EXPECT_TRUE(next.capturing);
  EXPECT_DOUBLE_EQ(next.phase, tick.phase);
  // Within one update's flight (20 m) of the held point: released, and from then on it runs.
  o.vehicle_position = v * 2.0;
  o.uav_position = o.vehicle_position + held + Vec2(5.0, 5.0);
  next = planner.update(2.0, o);
  EXPECT_FALSE(next.capturing);
  EXPECT_DOUBLE_EQ(next.phase, tick.phase);
  o.vehicle_position = v * 3.0;
  const FollowTick running = planner.update(3.0, o);
  EXPECT_GT(std::abs(running.phase - tick.phase), 1e-3);
}

TEST(FollowPlannerTest, SlowUavFliesStraightAtTheOffsetPoint) {
  FollowPlanner planner(base_parameters(), Uav{20.0, 50.0, 100.0});
  FollowObservation o = moving(Vec2(25.0, 0.0));
  const FollowTick tick = planner.update(0.0, o);
  EXPECT_EQ(tick.mode, FollowMode::Straight);
  EXPECT_NEAR(tick.speed_ratio, 0.8, 1e-15);
  EXPECT_TRUE(tick.waypoint.isApprox(Vec2(25.0, 0.0)));
  // Standing still: infinite ratio, loiter, nothing NaN.
  FollowPlanner still(base_parameters(), Uav{20.0, 50.0, 100.0});
  const FollowTick t2 = still.update(0.0, moving(Vec2(0.0, 0.0)));
  EXPECT_EQ(t2.mode, FollowMode::Loiter);
  EXPECT_TRUE(std::isinf(t2.speed_ratio));
  EXPECT_TRUE(t2.waypoint.allFinite());
}

TEST(FollowPlannerTest, CompensationPlansInTheAirMass) {
  // Vehicle north at 10 m/s, wind towards the north at 10 m/s: the vehicle stands in the air
  // mass, so the compensated planner loiters; the east leg's pattern axis is v_g - w.
  FollowParameters p = base_parameters();
  const Uav uav{22.0, 50.0, 100.0};
  FollowPlanner planner(p, uav, Vec2(0.0, 10.0));
  EXPECT_EQ(planner.update(0.0, moving(Vec2(0.0, 10.0))).mode, FollowMode::Loiter);
  FollowPlanner east(p, uav, Vec2(0.0, 10.0));
  const FollowTick tick = east.update(0.0, moving(Vec2(10.0, 0.0)));
  EXPECT_NEAR(tick.track_angle, -0.25 * kPi, 1e-12);
  EXPECT_NEAR(tick.speed_ratio, 22.0 / std::sqrt(200.0), 1e-12);
  // Its desired point moves at the airspeed relative to the air: ground velocity - wind.
  const double h = 1e-4;
  for (double tau = 0.1; tau < 30.0; tau += 0.9) {
    const Vec2 a = Vec2(10.0, 0.0) * (tau - h) + east.relative_position(tick, tau - h);
    const Vec2 b = Vec2(10.0, 0.0) * (tau + h) + east.relative_position(tick, tau + h);
    EXPECT_NEAR(((b - a) / (2 * h) - Vec2(0.0, 10.0)).norm(), 22.0, 1e-5);
  }
}

TEST(FollowCamera, ConeBankAndGimbal) {
  DownwardCamera fixed;
  fixed.max_gimbal = 0.0;  // the paper's camera on the bottom of the plane
  const Vec3 uav(0.0, 0.0, 100.0);
  const double edge = 100.0 * std::tan(37.0 * kPi / 180.0);
  EXPECT_TRUE(camera_sees(fixed, uav, 0.3, 0.0, Vec3(0.0, 0.0, 0.0)));
  for (double angle : {0.0, 0.7, 2.0, -2.5}) {  // a cone: a circle on the ground, any heading
    EXPECT_TRUE(camera_sees(fixed, uav, 1.1, 0.0, Vec3((edge - 0.01) * std::cos(angle), (edge - 0.01) * std::sin(angle), 0.0)));
    EXPECT_FALSE(camera_sees(fixed, uav, 1.1, 0.0, Vec3((edge + 0.01) * std::cos(angle), (edge + 0.01) * std::sin(angle), 0.0)));
  }
  // Banked 20 degrees left the belly looks right: a point to the left is 20 degrees further off.
  const double bank = 20.0 * kPi / 180.0;
  const double left_in = 100.0 * std::tan((37.0 - 20.0) * kPi / 180.0);
  EXPECT_TRUE(camera_sees(fixed, uav, 0.0, bank, Vec3(0.0, left_in - 0.01, 0.0)));
  EXPECT_FALSE(camera_sees(fixed, uav, 0.0, bank, Vec3(0.0, left_in + 0.01, 0.0)));
  // A 25-degree gimbal rolls back the bank and 5 degrees more towards the target.
  const DownwardCamera gimbal;
  const double reach = 100.0 * std::tan((37.0 + 5.0) * kPi / 180.0);
  EXPECT_TRUE(camera_sees(gimbal, uav, 0.0, bank, Vec3(0.0, reach - 0.01, 0.0)));
  EXPECT_FALSE(camera_sees(gimbal, uav, 0.0, bank, Vec3(0.0, reach + 0.01, 0.0)));
  // Level flight: 25 + 37 degrees either side, but no further along the track (roll only).
  const double side = 100.0 * std::tan(62.0 * kPi / 180.0);
  EXPECT_TRUE(camera_sees(gimbal, uav, 0.0, 0.0, Vec3(0.0, -(side - 0.01), 0.0)));
  EXPECT_FALSE(camera_sees(gimbal, uav, 0.0, 0.0, Vec3(0.0, -(side + 0.01), 0.0)));
  EXPECT_FALSE(camera_sees(gimbal, uav, 0.0, 0.0, Vec3(edge + 0.01, 0.0, 0.0)));
  EXPECT_NEAR(coordinated_bank(20.0, 20.0 / 50.0), std::atan(8.0 / 9.80665), 1e-15);
}

// The wind against the airspeed is the flight layer's one check (WindField): both runs reach it.
TEST(FollowRuns, WindAtTheAirspeedIsAnErrorNamingTheWind) {
  const GroundVehicle car = GroundVehicle::from_legs({VehicleLeg{0.0, 5.0, 20.0}});
  Uav uav;
  uav.speed = 20.0;
  uav.min_turn_radius = 50.0;
  Wind storm;
  storm.north = 20.0;
  const std::string planner = error_message([&] { follow(car, uav, FollowParameters{}, storm, Vec2::Zero()); });
  EXPECT_EQ(planner.rfind("wind", 0), 0u) << planner;
  const std::string orbit =
      error_message([&] { orbit_follow(car, uav, Control{}, 100.0, FollowParameters{}, storm); });
  EXPECT_EQ(orbit.rfind("wind", 0), 0u) << orbit;
}


// The auto threshold (issue 31): at the band's upper edge the sinusoid's amplitude is the camera's
// reach w = H tan(fov / 2 + gimbal); on the curvature floor A = a(sigma_u)^2 rho.
TEST(FollowThreshold, AutoPutsTheAmplitudeAtTheCameraReach) {
  const Uav uav{21.0, 50.0, 200.0};
  const DownwardCamera camera;
  FollowParameters p;  // threshold "auto"
  const double w = 200.0 * std::tan(37.0 * kPi / 180.0 + 25.0 * kPi / 180.0);
  EXPECT_NEAR(camera_reach(camera, 200.0), w, 1e-9);
  const ThresholdChoice c = camera_threshold(p, uav, camera);
  EXPECT_TRUE(c.automatic);
  EXPECT_FALSE(c.beyond_reach);
  EXPECT_NEAR(c.upper_ratio, c.threshold + 0.5 * p.hysteresis, 1e-12);
  const double rho = p.turn_margin * uav.min_turn_radius;
  const double a = sinusoid_slope(c.upper_ratio);
  EXPECT_NEAR(a * a * rho, w, 1e-6 * w);  // curvature-limited at these numbers
  EXPECT_NEAR(c.amplitude, w, 1e-6 * w);
  // A little above sigma_u the amplitude leaves the reach.
  EXPECT_GT(sinusoid_shape(c.upper_ratio + 0.01, uav.speed, p.period, rho).amplitude, w);
  // Higher flight sees farther: a larger h. A body-fixed camera (no gimbal): a smaller one.
  EXPECT_GT(camera_threshold(p, Uav{21.0, 50.0, 400.0}, camera).threshold, c.threshold);
  DownwardCamera fixed;
  fixed.max_gimbal = 0.0;
  EXPECT_LT(camera_threshold(p, uav, fixed).threshold, c.threshold);
  // The paper's h = 3 puts the amplitude beyond the reach: reported, with its numbers.
  p.threshold = 3.0;
  const ThresholdChoice paper = camera_threshold(p, uav, camera);
  EXPECT_FALSE(paper.automatic);
  EXPECT_TRUE(paper.beyond_reach);
  EXPECT_NEAR(paper.amplitude, std::pow(sinusoid_slope(3.25), 2) * rho, 1e-6);
  // The planner uses the resolved h.
  p.threshold = kAutoThreshold;
  EXPECT_NEAR(FollowPlanner(p, uav, Vec2::Zero(), camera).parameters().threshold, c.threshold, 1e-12);
}

// A camera too narrow for any sinusoid keeps the band's lower edge just above 1.
TEST(FollowThreshold, NarrowCameraLoitersAboveOne) {
  DownwardCamera narrow;
  narrow.fov = 5.0 * kPi / 180.0;
  narrow.max_gimbal = 0.0;
  FollowParameters p;
  const ThresholdChoice c = camera_threshold(p, Uav{21.0, 50.0, 100.0}, narrow);
  EXPECT_NEAR(c.threshold - 0.5 * p.hysteresis, 1.01, 1e-12);
  EXPECT_TRUE(c.beyond_reach);
}

// Reports (issue 31): perfect ones are the truth at each update, carried along its velocity in
// between; dropouts and latency age the estimate and lose the vehicle after the timeout.
TEST(FollowReports, EstimateIsTheNewestReportCarriedAlong) {
  const GroundVehicle car = GroundVehicle::from_legs({{0.0, 10.0, 20.0}, {0.5 * kPi, 10.0, 20.0}});
  const VehicleReports perfect(car, 0.0, 40.0, 1.0);
  EXPECT_EQ(perfect.reports().size(), 41u);
  const VehicleEstimate e = perfect.estimate(20.5);  // the report at 20 s, carried 0.5 s north
  EXPECT_TRUE(e.position.isApprox(car.position(20.0) + 0.5 * car.velocity(20.0)));
  EXPECT_NEAR(e.age, 0.5, 1e-12);
  EXPECT_FALSE(e.lost);
  VehicleReportOptions options;
  options.latency = 2.0;
  options.dropout = 0.7;
  options.timeout = 3.0;
  options.seed = 5;
  const VehicleReports lossy(car, 0.0, 40.0, 1.0, options);
  EXPECT_LT(lossy.reports().size(), 41u);
  bool lost = false;
  for (double t = 0.0; t <= 40.0; t += 0.5) lost = lost || lossy.estimate(t).lost;
  EXPECT_TRUE(lost);
  EXPECT_GE(lossy.estimate(1.0).age, 1.0);  // nothing received yet but the first report
  options.dropout = 1.0;
  EXPECT_NE(error_message([&] { options.validate(); }).find("reports.dropout = 1"), std::string::npos);
}

// Standoff: the field (74) from the UAV converges to the orbit of orbit_radius about the offset point.
TEST(FollowStandoff, ConvergesToTheLemma6Orbit) {
  FollowParameters p;
  p.strategy = FollowStrategy::Standoff;
  const Uav uav{21.0, 50.0, 200.0};
  FollowPlanner planner(p, uav);
  FollowObservation o = moving(Vec2(0.0, 6.0), Vec2(400.0, 0.0));
  const FollowTick tick = planner.update(0.0, o);
  EXPECT_EQ(tick.mode, FollowMode::Standoff);
  EXPECT_NEAR(tick.radius, 62.5 * std::pow(1.0 + 6.0 / 21.0, 2), 1e-9);
  EXPECT_TRUE(planner.relative_position(tick, 0.0).isApprox(Vec2(400.0, 0.0)));
  EXPECT_NEAR(planner.relative_position(tick, 200.0).norm(), tick.radius, 0.02 * tick.radius);
  // The UAV moves at v_p in the planning frame: |d(rel + v_f tau)/dtau| = v.
  const double h = 1e-3;
  const Vec2 a = planner.relative_position(tick, 100.0), b = planner.relative_position(tick, 100.0 + h);
  EXPECT_NEAR(((b - a) / h + Vec2(0.0, 6.0)).norm(), 21.0, 0.05);
}

// Camera mounts: a target ahead is seen by the pan-tilt and not by the roll gimbal; the fixed
// camera sees only its cone about the body's down axis.
TEST(FollowCamera, MountsSeeWhatTheirGeometrySays) {
  DownwardCamera roll, pan, fixed;
  pan.mount = CameraMount::PanTilt;
  fixed.mount = CameraMount::Fixed;
  const Vec3 uav(0.0, 0.0, 200.0);
  const Vec3 ahead(300.0, 0.0, 0.0), abeam(0.0, 300.0, 0.0), below(50.0, 0.0, 0.0);
  EXPECT_TRUE(camera_sees(pan, uav, 0.0, 0.0, ahead));
  EXPECT_FALSE(camera_sees(roll, uav, 0.0, 0.0, ahead));
  EXPECT_TRUE(camera_sees(roll, uav, 0.0, 0.0, abeam));
  EXPECT_FALSE(camera_sees(fixed, uav, 0.0, 0.0, abeam));
  EXPECT_TRUE(camera_sees(fixed, uav, 0.0, 0.0, below));
  EXPECT_NEAR(camera_reach(fixed, 200.0), 200.0 * std::tan(37.0 * kPi / 180.0), 1e-9);
  // Banked 30 degrees left, the fixed camera looks 30 degrees right.
  const Vec3 right(0.0, -200.0 * std::tan(30.0 * kPi / 180.0), 0.0);
  EXPECT_TRUE(camera_sees(fixed, uav, 0.0, 30.0 * kPi / 180.0, right));
}

// The waypoint's region of interest: the vehicle one update later at its reported velocity.
TEST(FollowPlannerTest, PredictsTheVehicleForTheGimbal) {
  FollowPlanner planner(base_parameters(), Uav{21.0, 50.0, 200.0});
  FollowObservation o = moving(Vec2(3.0, -4.0));
  o.vehicle_position = Vec2(10.0, 20.0);
  EXPECT_TRUE(planner.update(0.0, o).vehicle_predicted.isApprox(Vec2(13.0, 16.0)));
}

}  // namespace
}  // namespace vistrack
