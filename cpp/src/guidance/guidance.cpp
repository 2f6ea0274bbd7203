// Section V of the visibility-volume paper. Equation numbers refer to that paper. Where the
// printed equations carry typos they were re-derived from the lemmas (see the notes inline);
// guidance_test.cpp holds the checks that would catch each of them.
#include "vistrack/guidance.hpp"

#include <algorithm>
#include <cmath>

#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"

namespace vistrack {

namespace {

constexpr double kTwoOverPi = 2.0 / kPi;

// Below this distance to the centre the polar frame is taken from the heading hint (sec. III.F).
constexpr double kCentreTolerance = 1e-12;

}  // namespace

void GuidanceGains::validate() const {
  require_speed(speed, "gains.speed");
  require_beta(beta, "gains.beta");
  require_heading_gain(k_psi, "gains.k_psi");
  // v / r_min over the speed and length ranges.
  require_in_range(max_turn_rate, limits::kMinSpeed / limits::kMaxLength, limits::kMaxSpeed / limits::kMinLength,
                   "rad/s", "gains.max_turn_rate");
}

void OrbitState::validate() const {
  require_coordinate(center.x(), "orbit.center[0]");
  require_coordinate(center.y(), "orbit.center[1]");
  for (int k = 0; k < 2; ++k)
    require_in_range(center_velocity[k], -limits::kMaxSpeed, limits::kMaxSpeed, "m/s",
                     "orbit.center_velocity[" + std::to_string(k) + "]");
  require_length(radius, "orbit.radius");
  require_in_range(radius_rate, -limits::kMaxSpeed, limits::kMaxSpeed, "m/s", "orbit.radius_rate");
  // 1e4 m/s^2 (about 1,000 g) is far beyond any airframe; the bound keeps (79)/(85) finite.
  require_in_range(radius_acceleration, -1e4, 1e4, "m/s^2", "orbit.radius_acceleration");
}

GuidanceGains GuidanceGains::from(const Uav& uav, const Control& control) {
  uav.validate();
  control.validate();
  GuidanceGains gains;
  gains.speed = uav.speed;
  gains.beta = control.beta;
  gains.k_psi = control.k_psi;
  // A banking vehicle turns only as fast as its roll loop: the heading loop of (86) closes at most
  // at half the roll loop's bandwidth 1 / tau (a cascade; the paper's k_psi = 20 /s assumes an
  // instant turn and makes the bank oscillate at the roll loop's limit).
  if (uav.dynamics == DynamicsModel::Roll) gains.k_psi = std::min(gains.k_psi, 0.5 / uav.roll_time_constant);
  gains.direction = control.direction;
  gains.max_turn_rate = uav.speed / uav.min_turn_radius;  // u_psi,max = v / r_min (2)
  return gains;
}

double one_minus_cos_over_x(double x) {
  // 1 - cos x = 2 sin^2(x/2) has no cancellation; the limit at 0 is 0.
  if (x == 0.0) return 0.0;
  const double s = std::sin(0.5 * x);
  return 2.0 * s * s / x;
}

double sinc(double x) {
  if (std::abs(x) < 1e-4) {
    const double x2 = x * x;
    return 1.0 - x2 / 6.0 + x2 * x2 / 120.0;
  }
  return std::sin(x) / x;
}

VectorField vector_field(const Vec2& xi, const OrbitState& orbit, const GuidanceGains& gains,
                         double heading_hint) {
  VectorField f;
  const Vec2 d = xi - orbit.center;
  f.r = d.norm();
  if (f.r > kCentreTolerance * std::max(1.0, orbit.radius)) {
    f.e_r = d / f.r;
  } else {
    f.e_r = Vec2(std::cos(heading_hint), std::sin(heading_hint));
  }
  f.e_theta = Vec2(-f.e_r.y(), f.e_r.x());
  f.theta = std::atan2(f.e_r.y(), f.e_r.x());

  const double v = gains.speed;
  const double beta = gains.beta;
  const double poi_speed = orbit.center_velocity.norm();
  const double r_dot = orbit.radius_rate;
  const double g_r = orbit.center_velocity.dot(f.e_r);      // g_dot . e_r
  const double g_theta = orbit.center_velocity.dot(f.e_theta);  // g_dot . e_theta

  f.radial_error = f.r - orbit.radius;
  // Attraction gain (68): v - v_g - |R_dot| >= 0 by Lemma 5; a plan violating it gets none.
  const double margin = std::max(0.0, v - poi_speed - std::abs(r_dot));
  const double bt = beta * f.radial_error;
  const double atan_bt = std::atan(bt);
  f.attraction = margin * kTwoOverPi * atan_bt;  // Phi' (70)
  f.u_r = -f.attraction + r_dot + g_r;            // (73), (74)
  f.u_theta = sign(gains.direction) * std::sqrt(std::max(0.0, v * v - f.u_r * f.u_r));
  f.u = f.u_r * f.e_r + f.u_theta * f.e_theta;    // (75)
  f.heading = std::atan2(f.u.y(), f.u.x());       // (77)

  // (80) with (82), r_dot - R_dot = -Phi', gives (83). The paper takes R_dot constant (R_ddot = 0,
  // Definition 2); on the smooth locus the gain v - v_g - |R_dot| of (68) changes too, by
  // -sgn(R_dot) R_ddot (while it is not clamped at 0).
  const double r_ddot = orbit.radius_acceleration;
  const double gain_rate = v - poi_speed - std::abs(r_dot) > 0.0 ? -(r_dot > 0.0 ? 1.0 : r_dot < 0.0 ? -1.0 : 0.0) * r_ddot : 0.0;
  f.attraction_rate = gain_rate * kTwoOverPi * atan_bt -
                      (4.0 / (kPi * kPi)) * atan_bt * beta * margin * margin / (1.0 + bt * bt);
  // (84): theta_dot = (u_theta - g_dot . e_theta) / r; r = 0 is the singularity of Remark 6.
  const double r_safe = std::max(f.r, kCentreTolerance * std::max(1.0, orbit.radius));
  f.polar_rate = (f.u_theta - g_theta) / r_safe;
  // (79) gains + R_ddot: d(u . e_r)/dt = -dPhi'/dt + R_ddot + theta_dot g_dot . e_theta, so (78) gives
  // (85) as dpsi_d/dt = (dPhi'/dt - R_ddot + r theta_dot^2) / u_theta. u_theta vanishes only when the
  // field is purely radial (margin = 0 at the worst angle); keep the result finite and signed there.
  double u_theta_safe = f.u_theta;
  if (std::abs(u_theta_safe) < 1e-12 * v) u_theta_safe = sign(gains.direction) * 1e-12 * v;
  f.heading_rate = (f.attraction_rate - r_ddot + r_safe * f.polar_rate * f.polar_rate) / u_theta_safe;
  return f;
}

double lyapunov_term(const VectorField& field, const OrbitState& orbit, double beta,
                     double heading_error) {
  // The last term of (86). The paper prints "g . e_r"; the proof of Lemma 7 ((94)-(97)) needs the
  // POI velocity g_dot . e_r: with it, V2_dot = -k psi~^2 - Phi' K cos psi~ exactly.
  const double bt = beta * field.radial_error;
  const double k = beta * kTwoOverPi * std::atan(bt) / (1.0 + bt * bt);
  const double g_r = orbit.center_velocity.dot(field.e_r);
  return ((g_r + orbit.radius_rate) * one_minus_cos_over_x(heading_error) +
          field.u_theta * sinc(heading_error)) *
         k;
}

double radial_error_rate(const VectorField& field, const OrbitState& orbit, double heading_error) {
  // (93)
  return field.u_r * std::cos(heading_error) - field.u_theta * std::sin(heading_error) -
         orbit.center_velocity.dot(field.e_r) - orbit.radius_rate;
}

Steering steering(const Vec3& q, const OrbitState& orbit, const GuidanceGains& gains) {
  Steering s;
  s.field = vector_field(q.head<2>(), orbit, gains, q.z());
  // The heading error the short way round (sec. VI), in (-pi, pi].
  s.heading_error = wrap_to_pi(q.z() - s.field.heading);
  s.proportional = -gains.k_psi * s.heading_error;  // k_psi (psi_d - q_psi)
  s.feed_forward = s.field.heading_rate;
  s.lyapunov = lyapunov_term(s.field, orbit, gains.beta, s.heading_error);
  s.unsaturated = s.proportional + s.feed_forward + s.lyapunov;
  s.command = std::clamp(s.unsaturated, -gains.max_turn_rate, gains.max_turn_rate);  // (2)
  s.saturated = s.command != s.unsaturated;
  return s;
}

double steering_command(const Vec3& q, double cos_psi, double sin_psi, const OrbitState& orbit,
                        const GuidanceGains& gains) {
  // The equations of vector_field() and steering() above, in the same order.
  const Vec2 d = q.head<2>() - orbit.center;
  const double r = d.norm();
  const double tiny = kCentreTolerance * std::max(1.0, orbit.radius);
  const Vec2 e_r = r > tiny ? Vec2(d / r) : Vec2(cos_psi, sin_psi);
  const Vec2 e_theta(-e_r.y(), e_r.x());
  const double v = gains.speed;
  const double beta = gains.beta;
  const double r_dot = orbit.radius_rate;
  const double g_r = orbit.center_velocity.dot(e_r);
  const double g_theta = orbit.center_velocity.dot(e_theta);
  const double margin = std::max(0.0, v - orbit.center_velocity.norm() - std::abs(r_dot));
  const double bt = beta * (r - orbit.radius);
  const double atan_bt = std::atan(bt);
  const double shape = 1.0 / (1.0 + bt * bt);
  const double u_r = -margin * kTwoOverPi * atan_bt + r_dot + g_r;                       // (74)
  const double u_theta = sign(gains.direction) * std::sqrt(std::max(0.0, v * v - u_r * u_r));
  const double r_safe = std::max(r, tiny);
  const double theta_dot = (u_theta - g_theta) / r_safe;                                // (84)
  double u_theta_safe = u_theta;
  if (std::abs(u_theta_safe) < 1e-12 * v) u_theta_safe = sign(gains.direction) * 1e-12 * v;
  const double r_ddot = orbit.radius_acceleration;
  const double gain_rate =
      v - orbit.center_velocity.norm() - std::abs(r_dot) > 0.0 ? -(r_dot > 0.0 ? 1.0 : r_dot < 0.0 ? -1.0 : 0.0) * r_ddot : 0.0;
  const double heading_rate = (gain_rate * kTwoOverPi * atan_bt -
                               (4.0 / (kPi * kPi)) * atan_bt * beta * margin * margin * shape - r_ddot +
                               r_safe * theta_dot * theta_dot) /
                              u_theta_safe;                                               // (83), (85) with R_ddot
  // psi~ = q_psi - psi_d from the heading h and the unit field u / |u|: cos = h.u, sin = u x h.
  const Vec2 u = u_r * e_r + u_theta * e_theta;
  const double norm_u = u.norm();
  const double c = (cos_psi * u.x() + sin_psi * u.y()) / norm_u;
  const double s = (u.x() * sin_psi - u.y() * cos_psi) / norm_u;
  // atan2(s, c) from atan alone: glibc's atan2 is several times slower and this runs per RHS call.
  double error;
  if (c >= std::abs(s)) {
    error = std::atan(s / c);
  } else if (-c >= std::abs(s)) {
    error = std::atan(s / c) + (s >= 0.0 ? kPi : -kPi);
  } else {
    error = (s > 0.0 ? 0.5 * kPi : -0.5 * kPi) - std::atan(c / s);
  }
  // (1 - cos e) / e and sin e / e from s and c without cancellation.
  double one_minus_cos = c > 0.0 ? s * s / (1.0 + c) : 1.0 - c;
  double omc = error == 0.0 ? 0.0 : one_minus_cos / error;
  double sin_over = error == 0.0 ? 1.0 : s / error;
  if (std::abs(error) < 1e-4) {  // series: s / e loses nothing, but keep the same limits
    omc = 0.5 * error;
    sin_over = 1.0 - error * error / 6.0;
  }
  const double lyapunov = beta * kTwoOverPi * atan_bt * shape * ((g_r + r_dot) * omc + u_theta * sin_over);  // (86)
  return std::clamp(-gains.k_psi * error + heading_rate + lyapunov, -gains.max_turn_rate, gains.max_turn_rate);
}

namespace {

// sqrt(v^2 - (g_dot . e_r + R_dot)^2), the tangential speed on the orbit; Lemma 5 makes it real.
double tangential_speed(double theta, const OrbitState& orbit, double speed) {
  require_positive(speed, "speed");
  require_positive(orbit.radius, "orbit.radius");
  const Vec2 e_r(std::cos(theta), std::sin(theta));
  const double radial = orbit.center_velocity.dot(e_r) + orbit.radius_rate;
  const double squared = speed * speed - radial * radial;
  if (squared < 0.0)
    detail::fail_field("orbit.radius_rate", orbit.radius_rate,
                       "the vehicle cannot stay on this orbit at theta = " + detail::computed_text(theta) +
                           ": |g_dot . e_r + R_dot| exceeds the speed (Lemma 5)");
  return std::sqrt(squared);
}

}  // namespace

double orbit_polar_rate(double theta, const OrbitState& orbit, double speed, Circulation direction) {
  const Vec2 e_theta(-std::sin(theta), std::cos(theta));
  // (13)
  return (-orbit.center_velocity.dot(e_theta) + sign(direction) * tangential_speed(theta, orbit, speed)) /
         orbit.radius;
}

double orbit_signed_curvature(double theta, const OrbitState& orbit, double speed, Circulation direction) {
  // (31) with the sign of the circulation. Re-derived from Lemma 2: a = g_dot . e_r + R_dot,
  // b = +-sqrt(v^2 - a^2), a_dot = theta_dot g_dot . e_theta + R_ddot ((34) without Definition 2's
  // R_ddot = 0), so kappa_s = (-a_dot / b + theta_dot) / v = (R theta_dot^2 - R_ddot) / (v b), using
  // b = g_dot . e_theta + R theta_dot. (The printed (45) has g_dot . e_theta inside the root; (13) and
  // (31) have g_dot . e_r.)
  const double theta_dot = orbit_polar_rate(theta, orbit, speed, direction);
  return sign(direction) * (orbit.radius * theta_dot * theta_dot - orbit.radius_acceleration) /
         (speed * tangential_speed(theta, orbit, speed));
}

Vec3 orbit_configuration(double theta0, const OrbitState& orbit, double speed, Circulation direction) {
  const Vec2 e_r(std::cos(theta0), std::sin(theta0));
  const Vec2 e_theta(-e_r.y(), e_r.x());
  const double theta_dot = orbit_polar_rate(theta0, orbit, speed, direction);
  // (38): velocity on the orbit; (39): its direction; (40): the point on the orbit.
  const Vec2 velocity = orbit.center_velocity + orbit.radius_rate * e_r + orbit.radius * theta_dot * e_theta;
  const Vec2 position = orbit.center + orbit.radius * e_r;
  return Vec3(position.x(), position.y(), std::atan2(velocity.y(), velocity.x()));
}

double lemma6_curvature_bound(double radius, double speed, double poi_speed) {
  require_length(radius, "radius");
  require_speed(speed, "speed");
  require_in_range(poi_speed, 0.0, limits::kMaxSpeed, "m/s", "poi_speed");
  // (53), the value (55) of the extremum at a = theta - gamma = +-pi/2 (ccw / cw: where the POI moves against
  // the circulation).
  return (poi_speed + speed) * (poi_speed + speed) / (radius * speed * speed);
}

namespace {
// Root of x atan(x) = c for x > 0 by Newton's method (monotone, convex: converges from x = 1).
double solve_x_atan_x(double c) {
  double x = 1.0;
  for (int i = 0; i < 100; ++i) {
    const double f = x * std::atan(x) - c;
    const double step = f / (std::atan(x) + x / (1.0 + x * x));
    x -= step;
    if (std::abs(step) < 1e-16 * x) break;
  }
  return x;
}
}  // namespace

double epsilon_max() {
  // Maximum of atan^2(x) / (1 + x^2) (98): at x atan x = 1 (100).
  const double x = solve_x_atan_x(1.0);
  return std::atan(x) * std::atan(x) / (1.0 + x * x);
}

double lambda_max() {
  // Maximum of atan(x) / (1 + x^2) (106): its derivative vanishes where 2 x atan x = 1.
  const double x = solve_x_atan_x(0.5);
  return std::atan(x) / (1.0 + x * x);
}

double lemma7_min_gain(double speed, double beta) {
  require_speed(speed, "speed");
  require_beta(beta, "beta");
  return speed * beta * 4.0 / (kPi * kPi) * epsilon_max();  // (87)
}

}  // namespace vistrack
