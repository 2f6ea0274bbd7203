// Guidance (section V) and the orbit-following theory of section IV.A as tests. Each analytic
// check is against an independent computation (finite differences of the field, the Lyapunov
// identity of Lemma 7, brute-force maxima), so a typo in an implemented equation fails here.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "vistrack/error.hpp"
#include "vistrack/guidance.hpp"
#include "vistrack/ode.hpp"
#include "vistrack/orbit.hpp"

namespace vistrack {
namespace {

constexpr double kPiValue = 3.14159265358979323846;

// The orbit of a segment with g linear and R quadratic in time (constant R_ddot): the state at t.
OrbitState moving_orbit(const OrbitState& at0, double t) {
  OrbitState o = at0;
  o.center = at0.center + at0.center_velocity * t;
  o.radius = at0.radius + at0.radius_rate * t + 0.5 * at0.radius_acceleration * t * t;
  o.radius_rate = at0.radius_rate + at0.radius_acceleration * t;
  return o;
}

struct RandomCase {
  OrbitState orbit;
  GuidanceGains gains;
  Vec2 xi;
};

RandomCase random_case(std::mt19937& rng, Circulation direction) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  RandomCase c;
  c.gains.speed = 5.0 + 25.0 * unit(rng);
  c.gains.beta = 0.01 + 0.5 * unit(rng);
  c.gains.k_psi = 1.0 + 40.0 * unit(rng);
  c.gains.direction = direction;
  c.gains.max_turn_rate = 1e9;
  const double poi_speed = 0.8 * c.gains.speed * unit(rng);
  const double gamma = 2.0 * kPiValue * unit(rng);
  c.orbit.center = Vec2(200.0 * unit(rng) - 100.0, 200.0 * unit(rng) - 100.0);
  c.orbit.center_velocity = poi_speed * Vec2(std::cos(gamma), std::sin(gamma));
  c.orbit.radius = 20.0 + 150.0 * unit(rng);
  c.orbit.radius_rate = (2.0 * unit(rng) - 1.0) * 0.9 * (c.gains.speed - poi_speed);
  // Half the cases on the smooth locus (R_ddot != 0), half on the paper's (R_ddot = 0).
  if (unit(rng) < 0.5) c.orbit.radius_acceleration = (2.0 * unit(rng) - 1.0) * 3.0;
  const double r = c.orbit.radius * (0.3 + 2.5 * unit(rng));
  const double theta = 2.0 * kPiValue * unit(rng);
  c.xi = c.orbit.center + r * Vec2(std::cos(theta), std::sin(theta));
  return c;
}

TEST(SafeFunctions, LimitsAndAccuracyNearZero) {
  EXPECT_EQ(one_minus_cos_over_x(0.0), 0.0);
  EXPECT_EQ(sinc(0.0), 1.0);
  for (double x : {1e-12, -3e-9, 1e-6, 2e-4, -0.5, 1.0, 3.0, -kPiValue}) {
    // Series reference for small x, direct formula in long double elsewhere.
    const long double xl = x;
    const long double omc = std::abs(x) < 1e-3 ? xl / 2 - xl * xl * xl / 24 : (1.0L - std::cos(xl)) / xl;
    const long double sc = std::abs(x) < 1e-3 ? 1.0L - xl * xl / 6 + xl * xl * xl * xl / 120 : std::sin(xl) / xl;
    EXPECT_NEAR(one_minus_cos_over_x(x), static_cast<double>(omc), 1e-15 * std::abs(static_cast<double>(omc))) << x;
    EXPECT_NEAR(sinc(x), static_cast<double>(sc), 2e-16) << x;
  }
  // The naive (1 - cos x) / x loses every digit here; ours keeps them.
  EXPECT_NEAR(one_minus_cos_over_x(1e-9), 5e-10, 1e-24);
}

TEST(VectorField, ConstantMagnitudeAndCirculationSign) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 2000; ++trial) {
    const Circulation direction = trial % 2 == 0 ? Circulation::CounterClockwise : Circulation::Clockwise;
    const RandomCase c = random_case(rng, direction);
    const VectorField f = vector_field(c.xi, c.orbit, c.gains);
    EXPECT_NEAR(f.u.norm(), c.gains.speed, 1e-12 * c.gains.speed);  // ||u|| = v (72)
    EXPECT_GT(sign(direction) * f.u_theta, 0.0);
    EXPECT_NEAR(f.u.dot(f.e_r), f.u_r, 1e-9);
    EXPECT_NEAR(f.heading, std::atan2(f.u.y(), f.u.x()), 1e-15);
    // Attraction: the relative radial velocity u_r - g_dot.e_r - R_dot = -Phi' points to the orbit.
    const double relative = f.u_r - c.orbit.center_velocity.dot(f.e_r) - c.orbit.radius_rate;
    if (std::abs(f.radial_error) > 1e-6) {
      EXPECT_LT(relative * f.radial_error, 0.0);
    }
  }
}

TEST(VectorField, TangentOnAStillOrbitAndSafeAtTheCentre) {
  GuidanceGains gains;
  OrbitState orbit;
  orbit.center = Vec2(10.0, -5.0);
  orbit.radius = 100.0;
  const VectorField f = vector_field(orbit.center + Vec2(0.0, 100.0), orbit, gains);
  EXPECT_NEAR(f.u.x(), -gains.speed, 1e-12);  // counter-clockwise at the top of the circle
  EXPECT_NEAR(f.u.y(), 0.0, 1e-12);
  EXPECT_NEAR(f.heading_rate, gains.speed / orbit.radius, 1e-12);  // v / R on the circle
  // At the centre the frame comes from the heading hint; everything stays finite.
  const VectorField c = vector_field(orbit.center, orbit, gains, 0.3);
  EXPECT_NEAR(c.theta, 0.3, 1e-15);
  EXPECT_TRUE(std::isfinite(c.heading_rate));
  EXPECT_GT(c.u_r, 0.0);  // pushed outwards
}

// psi_d(xi, t) along the flow xi_dot = u, by central differences: checks (83), (84) and (85),
// with the R_ddot terms of the smooth locus (in (79) and in the gain of (68)) in half the cases.
TEST(VectorField, HeadingRateMatchesFiniteDifferencesAlongTheFlow) {
  std::mt19937 rng(11);
  int checked = 0;
  for (int trial = 0; trial < 500; ++trial) {
    const Circulation direction = trial % 2 == 0 ? Circulation::CounterClockwise : Circulation::Clockwise;
    const RandomCase c = random_case(rng, direction);
    const VectorField f = vector_field(c.xi, c.orbit, c.gains);
    if (std::abs(f.u_theta) < 0.05 * c.gains.speed || f.r < 0.5 * c.orbit.radius) continue;
    const double h = 1e-5;
    const VectorField fp = vector_field(c.xi + h * f.u, moving_orbit(c.orbit, h), c.gains);
    const VectorField fm = vector_field(c.xi - h * f.u, moving_orbit(c.orbit, -h), c.gains);
    const double fd_heading = wrap_to_pi(fp.heading - fm.heading) / (2 * h);
    const double fd_attraction = (fp.attraction - fm.attraction) / (2 * h);
    const double fd_theta = wrap_to_pi(fp.theta - fm.theta) / (2 * h);
    EXPECT_NEAR(f.heading_rate, fd_heading, 1e-6 * (1.0 + std::abs(fd_heading))) << trial;
    EXPECT_NEAR(f.attraction_rate, fd_attraction, 1e-6 * (1.0 + std::abs(fd_attraction))) << trial;
    EXPECT_NEAR(f.polar_rate, fd_theta, 1e-6 * (1.0 + std::abs(fd_theta))) << trial;
    ++checked;
  }
  EXPECT_GT(checked, 200);
}

// (93) against the derivative of r - R along the Dubins motion q_dot = v (cos psi, sin psi).
TEST(Steering, RadialErrorRateMatchesFiniteDifferences) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> angle(-kPiValue, kPiValue);
  for (int trial = 0; trial < 500; ++trial) {
    const RandomCase c = random_case(rng, trial % 2 == 0 ? Circulation::CounterClockwise : Circulation::Clockwise);
    const double psi = angle(rng);
    const VectorField f = vector_field(c.xi, c.orbit, c.gains);
    const double error = wrap_to_pi(psi - f.heading);
    const Vec2 velocity = c.gains.speed * Vec2(std::cos(psi), std::sin(psi));
    const double h = 1e-6;
    const auto radial = [&](double dt) {
      const OrbitState o = moving_orbit(c.orbit, dt);
      return (c.xi + dt * velocity - o.center).norm() - o.radius;
    };
    EXPECT_NEAR(radial_error_rate(f, c.orbit, error), (radial(h) - radial(-h)) / (2 * h), 1e-6);
  }
}

// Lemma 7: with (86), V2 = atan^2(beta r~)/pi + psi~^2/2 has
// V2_dot = K r~_dot + psi~ (u_psi - psi_d_dot) = -k psi~^2 - K Phi' cos psi~ (97), with
// K = (2/pi) beta atan(beta r~) / (1 + beta^2 r~^2). A sign or g-for-g_dot slip in (86) breaks it.
TEST(Steering, LyapunovIdentityOfLemma7) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> angle(-kPiValue, kPiValue);
  for (int trial = 0; trial < 2000; ++trial) {
    const RandomCase c = random_case(rng, trial % 2 == 0 ? Circulation::CounterClockwise : Circulation::Clockwise);
    const Vec3 q(c.xi.x(), c.xi.y(), angle(rng));
    const Steering s = steering(q, c.orbit, c.gains);
    ASSERT_FALSE(s.saturated);
    const double bt = c.gains.beta * s.field.radial_error;
    const double k = 2.0 / kPiValue * c.gains.beta * std::atan(bt) / (1.0 + bt * bt);
    const double e = s.heading_error;
    const double v2_dot = k * radial_error_rate(s.field, c.orbit, e) + e * (s.command - s.feed_forward);
    const double expected = -c.gains.k_psi * e * e - k * s.field.attraction * std::cos(e);
    EXPECT_NEAR(v2_dot, expected, 1e-9 * (1.0 + std::abs(expected))) << trial;
  }
}

// The integrator's lean command is the same law as steering(): random states, tiny heading errors,
// errors near +-pi, saturated and not.
TEST(Steering, LeanCommandEqualsTheFullLaw) {
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> angle(-kPiValue, kPiValue);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 20000; ++trial) {
    RandomCase c = random_case(rng, trial % 2 == 0 ? Circulation::CounterClockwise : Circulation::Clockwise);
    c.gains.max_turn_rate = trial % 3 == 0 ? 0.3 : 1e9;
    const double psi_d = vector_field(c.xi, c.orbit, c.gains).heading;
    double psi = angle(rng);
    if (trial % 4 == 1) psi = psi_d + 1e-9 * (unit(rng) - 0.5);
    if (trial % 4 == 2) psi = psi_d + kPiValue - 1e-7 * unit(rng);
    if (trial % 8 == 3) psi = psi_d;
    const Vec3 q(c.xi.x(), c.xi.y(), psi + 2 * kPiValue * std::floor(4 * unit(rng) - 2));
    const double full = steering(q, c.orbit, c.gains).command;
    const double lean = steering_command(q, std::cos(q.z()), std::sin(q.z()), c.orbit, c.gains);
    EXPECT_NEAR(lean, full, 1e-9 * (1.0 + std::abs(full))) << trial;
  }
}

TEST(Steering, ShortWayRoundAndSaturation) {
  GuidanceGains gains;  // v = 20, max turn rate 0.4
  OrbitState orbit;
  orbit.radius = 100.0;
  const Vec3 base(0.0, 150.0, 0.0);
  const double psi_d = vector_field(base.head<2>(), orbit, gains).heading;
  const Steering wrapped = steering(Vec3(0.0, 150.0, psi_d + 0.1 + 4 * kPiValue), orbit, gains);
  EXPECT_NEAR(wrapped.heading_error, 0.1, 1e-12);
  const Steering left = steering(Vec3(0.0, 150.0, psi_d + kPiValue - 0.01), orbit, gains);
  const Steering right = steering(Vec3(0.0, 150.0, psi_d - kPiValue + 0.01), orbit, gains);
  EXPECT_LT(left.unsaturated, 0.0);   // heading ahead of psi_d: turn clockwise back
  EXPECT_GT(right.unsaturated, 0.0);
  EXPECT_TRUE(left.saturated);
  EXPECT_EQ(left.command, -gains.max_turn_rate);
  EXPECT_EQ(right.command, gains.max_turn_rate);
}

// Theorem 1: started on the orbit with (38)-(40) and steered by u = v kappa_s of (31), the
// vehicle stays on the translating, morphing orbit.
TEST(OrbitTheory, Theorem1VehicleStaysOnTheOrbit) {
  struct Case { double v, vg, gamma, radius, rate; Circulation direction; double theta0; double accel; };
  constexpr Circulation ccw = Circulation::CounterClockwise, cw = Circulation::Clockwise;
  // The last three morph with R_ddot != 0 (the smooth locus): the curvature (R theta_dot^2 -
  // R_ddot) / (v u_theta) keeps the vehicle on them too; without the R_ddot term it drifts off.
  const Case cases[] = {{20.0, 5.0, 0.7, 158.0, 1.3, ccw, -3.14159265358979 / 2, 0.0},
                        {20.0, 5.0, -2.0, 120.0, -2.0, ccw, 0.3, 0.0},
                        {20.0, 5.0, 2.5, 85.9, 0.0, cw, 1.0, 0.0},
                        {3.0, 0.35, 0.2, 20.0, 0.1, cw, 2.0, 0.0},
                        {10.0, 5.0, -3.0 * 3.14159265358979 / 4, 40.0, -1.5, ccw, 4.0, 0.0},
                        {20.0, 5.0, 0.7, 158.0, 5.0, ccw, -1.0, -0.5},
                        {20.0, 5.0, -2.0, 120.0, -3.0, cw, 0.3, 0.4},
                        {3.0, 0.35, 0.2, 20.0, 0.5, ccw, 2.0, -0.04}};
  for (const Case& c : cases) {
    OrbitState orbit0;
    orbit0.center = Vec2(-150.0, -45.0);
    orbit0.center_velocity = c.vg * Vec2(std::cos(c.gamma), std::sin(c.gamma));
    orbit0.radius = c.radius;
    orbit0.radius_rate = c.rate;
    orbit0.radius_acceleration = c.accel;
    const double duration = 20.0;  // the radius stays positive over the segment in every case
    auto rhs = [&](double t, const OdeVector<3>& q, OdeVector<3>& dq) {
      const OrbitState o = moving_orbit(orbit0, t);
      const double theta = std::atan2(q.y() - o.center.y(), q.x() - o.center.x());
      dq << c.v * std::cos(q.z()), c.v * std::sin(q.z()), c.v * orbit_signed_curvature(theta, o, c.v, c.direction);
    };
    OdeOptions options;
    options.rtol = 1e-11;
    options.atol = 1e-11;
    std::vector<double> t_eval;
    for (int k = 0; k <= 200; ++k) t_eval.push_back(duration * k / 200.0);
    const Vec3 q0 = orbit_configuration(c.theta0, orbit0, c.v, c.direction);
    const auto sol = solve_ode<3>(rhs, 0.0, duration, q0, options, t_eval);
    double worst = 0.0;
    for (std::size_t k = 0; k < sol.t.size(); ++k) {
      const OrbitState o = moving_orbit(orbit0, sol.t[k]);
      worst = std::max(worst, std::abs((sol.y[k].head<2>() - o.center).norm() - o.radius));
    }
    EXPECT_LT(worst, 1e-6) << "v=" << c.v << " R=" << c.radius << " Rdot=" << c.rate;
    // (38)-(40) is the vector field's heading on the orbit, so the field agrees with Theorem 1.
    GuidanceGains gains;
    gains.speed = c.v;
    gains.direction = c.direction;
    EXPECT_NEAR(wrap_to_pi(vector_field(q0.head<2>(), orbit0, gains).heading - q0.z()), 0.0, 1e-12);
  }
}

// On the orbit (r = R, Phi' = 0) the field's heading rate (85) with R_ddot is the curvature of
// exact orbit following (31) with R_ddot times v: two derivations of the same turn rate.
TEST(OrbitTheory, FieldHeadingRateOnTheOrbitIsTheExactTurnRate) {
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 1000; ++trial) {
    const Circulation direction = trial % 2 == 0 ? Circulation::CounterClockwise : Circulation::Clockwise;
    RandomCase c = random_case(rng, direction);
    c.orbit.radius_acceleration = (2.0 * unit(rng) - 1.0) * 3.0;
    const double theta = 2.0 * kPiValue * unit(rng);
    const Vec2 xi = c.orbit.center + c.orbit.radius * Vec2(std::cos(theta), std::sin(theta));
    const VectorField f = vector_field(xi, c.orbit, c.gains);
    const double exact = c.gains.speed * orbit_signed_curvature(theta, c.orbit, c.gains.speed, direction);
    EXPECT_NEAR(f.heading_rate, exact, 1e-9 * (1.0 + std::abs(exact))) << trial;
  }
}

// Lemma 6: for R_dot = 0 the maximum over theta of (31) is (v_g + v)^2 / (R v^2), reached where
// the POI velocity is against the circulation (theta = gamma + pi/2 counter-clockwise, as the paper says).
TEST(OrbitTheory, Lemma6MaximumCurvature) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const double v = 1.0 + 30.0 * unit(rng);
    const double vg = v * 0.99 * unit(rng);
    const double gamma = 2 * kPiValue * unit(rng);
    const Circulation direction = trial % 2 == 0 ? Circulation::CounterClockwise : Circulation::Clockwise;
    OrbitState orbit;
    orbit.center_velocity = vg * Vec2(std::cos(gamma), std::sin(gamma));
    orbit.radius = 5.0 + 200.0 * unit(rng);
    double best = 0.0, at = 0.0;
    for (int k = 0; k < 20000; ++k) {
      const double theta = 2 * kPiValue * k / 20000.0;
      const double kappa = std::abs(orbit_signed_curvature(theta, orbit, v, direction));
      if (kappa > best) { best = kappa; at = theta; }
    }
    const double bound = lemma6_curvature_bound(orbit.radius, v, vg);
    EXPECT_NEAR(best, bound, 1e-6 * bound) << trial;
    EXPECT_NEAR(wrap_to_pi(at - (gamma + sign(direction) * kPiValue / 2)), 0.0, 2e-3) << trial;
    // The curvature on the orbit is (13) squared over the tangential speed: never above the bound.
    EXPECT_LE(best, bound * (1 + 1e-12));
  }
  // Corollary 1: v_g -> v gives 4 / R.
  EXPECT_NEAR(lemma6_curvature_bound(50.0, 10.0, 10.0), 4.0 / 50.0, 1e-15);
}

// (31) written twice, independently: here from an OrbitState at polar angle theta, and by the
// orbit area from (R, R_dot, a = theta - gamma, v, v_g) for Algorithm 1. They must agree.
TEST(OrbitTheory, CurvatureAgreesWithTheOrbitArea) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const double v = 1.0 + 30.0 * unit(rng), vg = 0.95 * v * unit(rng), gamma = 2 * kPiValue * unit(rng);
    OrbitState orbit;
    orbit.center_velocity = vg * Vec2(std::cos(gamma), std::sin(gamma));
    orbit.radius = 5.0 + 200.0 * unit(rng);
    orbit.radius_rate = (2 * unit(rng) - 1) * (v - vg);
    const double theta = 2 * kPiValue * unit(rng);
    const Circulation direction = trial % 2 == 0 ? Circulation::CounterClockwise : Circulation::Clockwise;
    const double theirs = orbit_curvature(orbit.radius, orbit.radius_rate, theta - gamma, v, vg, direction);
    const double ours = sign(direction) * orbit_signed_curvature(theta, orbit, v, direction);
    EXPECT_NEAR(ours, theirs, 1e-9 * theirs) << trial;
    EXPECT_NEAR(lemma6_curvature_bound(orbit.radius, v, vg), max_orbit_curvature(orbit.radius, v, vg), 1e-15);
  }
}

TEST(OrbitTheory, Lemma5ViolationIsAnError) {
  OrbitState orbit;
  orbit.center_velocity = Vec2(5.0, 0.0);
  orbit.radius = 100.0;
  orbit.radius_rate = 16.0;  // v - v_g = 15 at v = 20
  EXPECT_THROW(orbit_signed_curvature(0.0, orbit, 20.0, Circulation::CounterClockwise), Error);
  EXPECT_NO_THROW(orbit_signed_curvature(kPiValue, orbit, 20.0, Circulation::CounterClockwise));  // g_dot . e_r = -5 there
  try {
    orbit_polar_rate(0.0, orbit, 20.0, Circulation::CounterClockwise);
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("orbit.radius_rate"), std::string::npos);
  }
}

TEST(OrbitTheory, Lemma7Constants) {
  // eps_max of (98) and lambda_max of (106), against a brute-force maximum.
  double eps = 0.0, lambda = 0.0;
  for (int k = 0; k <= 400000; ++k) {
    const double x = 10.0 * k / 400000.0;
    eps = std::max(eps, std::atan(x) * std::atan(x) / (1 + x * x));
    lambda = std::max(lambda, std::atan(x) / (1 + x * x));
  }
  EXPECT_NEAR(epsilon_max(), eps, 1e-10);
  EXPECT_NEAR(lambda_max(), lambda, 1e-10);
  EXPECT_NEAR(epsilon_max(), 0.31483, 1e-5);  // the paper's values
  EXPECT_NEAR(lambda_max(), 0.41195, 1e-5);
  EXPECT_NEAR(lemma7_min_gain(20.0, 0.025), 20.0 * 0.025 * 4.0 / (kPiValue * kPiValue) * eps, 1e-10);
}

TEST(Guidance, InvalidInputsNameTheField) {
  GuidanceGains gains;
  gains.beta = -1.0;
  try {
    gains.validate();
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("gains.beta"), std::string::npos);
  }
  EXPECT_THROW(from_name<Circulation>("up"), Error);
  EXPECT_EQ(from_name<Circulation>("cw"), Circulation::Clockwise);
  EXPECT_EQ(to_string(from_name<Circulation>("CCW")), "ccw");
  Uav uav;
  uav.min_turn_radius = 5.0;
  Control control;
  control.direction = Circulation::Clockwise;
  const GuidanceGains from = GuidanceGains::from(uav, control);
  EXPECT_EQ(from.direction, Circulation::Clockwise);
  // The gains' defaults are the Uav's and the Control's (each default lives once, in its struct).
  const GuidanceGains defaults;
  const GuidanceGains derived = GuidanceGains::from(Uav{}, Control{});
  EXPECT_EQ(defaults.speed, derived.speed);
  EXPECT_EQ(defaults.beta, derived.beta);
  EXPECT_EQ(defaults.k_psi, derived.k_psi);
  EXPECT_EQ(defaults.direction, derived.direction);
  EXPECT_EQ(defaults.max_turn_rate, derived.max_turn_rate);
  EXPECT_DOUBLE_EQ(from.max_turn_rate, 4.0);
  EXPECT_THROW(lemma6_curvature_bound(-1.0, 1.0, 0.5), Error);
}

}  // namespace
}  // namespace vistrack

TEST(GuidanceGainsFrom, RollModelCapsTheHeadingGainAtHalfTheRollBandwidth) {
  using namespace vistrack;
  Uav uav;
  Control control;
  control.k_psi = 20.0;
  EXPECT_EQ(GuidanceGains::from(uav, control).k_psi, 20.0);  // Dubins: the paper's gain
  uav.dynamics = DynamicsModel::Roll;
  uav.roll_time_constant = 0.5;
  EXPECT_EQ(GuidanceGains::from(uav, control).k_psi, 1.0);   // 1 / (2 tau)
  control.k_psi = 0.3;
  EXPECT_EQ(GuidanceGains::from(uav, control).k_psi, 0.3);   // a gain already below it stays
}
