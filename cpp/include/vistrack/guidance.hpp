// Guidance for a Dubins vehicle circling a moving POI on an orbit of time-varying radius
// (section V of the visibility-volume paper): the constant-speed vector field u of eq. (74), the
// desired heading (77), its rate along the field (85) and the steering law (86); plus the exact
// orbit-following quantities of section IV.A (polar rate (13), curvature (31)) that Theorem 1 and
// Lemma 6 are about.
//
// Conventions: angles in radians counter-clockwise from +x; counter-clockwise circulation takes
// the "+" root of (72), clockwise the "-" root. All functions are pure and allocation free, and
// trust their arguments (they run inside the integrator): OrbitState::validate and
// GuidanceGains::validate check them where they enter (the Python bindings, the planners).
#pragma once

#include "vistrack/geometry.hpp"
#include "vistrack/dubins_parameters.hpp"
#include "vistrack/guidance_parameters.hpp"

namespace vistrack {

// The reference orbit at one instant: centre g, its velocity g_dot, radius R, its rate R_dot and
// its second derivative R_ddot. Within one plan segment g_dot is constant (Definition 1); R_dot is
// too on the paper's piecewise-linear locus (Definition 2, R_ddot = 0), while the smooth locus has
// a constant R_ddot per segment.
struct OrbitState {
  Vec2 center = Vec2::Zero();        // g
  Vec2 center_velocity = Vec2::Zero();  // g_dot, |g_dot| = v_g
  double radius = 1.0;               // R > 0
  double radius_rate = 0.0;          // R_dot
  double radius_acceleration = 0.0;  // R_ddot
  // Error naming the field outside the ranges of vistrack/limits.hpp: centre a coordinate, its
  // velocity and R_dot within the speed range, R a length, |R_ddot| <= 1e4 m/s^2.
  void validate() const;
};

// Parameters of the vector field and of the steering law: a Uav and a Control seen by the
// guidance (the defaults are theirs).
struct GuidanceGains {
  double speed = Uav{}.speed;                      // v, UAV speed (m/s)
  double beta = Control{}.beta;                    // circulation / attraction parameter of a_1 (59)
  double k_psi = Control{}.k_psi;                  // heading gain of (86); from(): at most 1 / (2 tau) on the roll model
  Circulation direction = Control{}.direction;
  double max_turn_rate = Uav{}.speed / Uav{}.min_turn_radius;  // v / r_min; the command is clamped to it
  void validate() const;
  static GuidanceGains from(const Uav& uav, const Control& control);
};

// Everything the vector field (74) gives at one point xi and time.
struct VectorField {
  double r = 0.0;            // |xi - g|
  double theta = 0.0;        // polar angle of xi about g (Definition 3)
  Vec2 e_r = Vec2::UnitX();  // radial unit vector
  Vec2 e_theta = Vec2::UnitY();
  double radial_error = 0.0; // r - R
  double attraction = 0.0;   // Phi' of (70)
  double u_r = 0.0;          // radial component of u (74)
  double u_theta = 0.0;      // circulation component of u (74), sign = sign(direction)
  Vec2 u = Vec2::Zero();     // the field in x, y (75); |u| = v
  double heading = 0.0;      // psi_d of (77), in (-pi, pi]
  double attraction_rate = 0.0;  // dPhi'/dt along the field (83), plus -sgn(R_dot) R_ddot (2/pi) atan(beta (r - R))
  double polar_rate = 0.0;       // theta_dot along the field (84)
  double heading_rate = 0.0;     // dpsi_d/dt along the field: (85) with R_ddot, (dPhi'/dt - R_ddot + r theta_dot^2) / u_theta
};

// The vector field (74) at position xi. `heading_hint` orients e_r when xi is exactly at the
// centre (section III.F: attracted towards the orbit point in the direction of the heading).
// Needs v - v_g - |R_dot| >= 0 (Lemma 5); for a plan that violates it, u_theta is clamped to 0.
VectorField vector_field(const Vec2& xi, const OrbitState& orbit, const GuidanceGains& gains,
                         double heading_hint = 0.0);

// The steering law (86) at configuration q = (x, y, psi).
struct Steering {
  VectorField field;
  double heading_error = 0.0;  // psi_tilde = q_psi - psi_d wrapped to (-pi, pi]
  double proportional = 0.0;   // k_psi (psi_d - q_psi)
  double feed_forward = 0.0;   // dpsi_d/dt (85)
  double lyapunov = 0.0;       // u_lyap, the last term of (86) (see (106))
  double unsaturated = 0.0;    // the sum of the three terms
  double command = 0.0;        // clamped to +-max_turn_rate (2)
  bool saturated = false;
};
Steering steering(const Vec3& q, const OrbitState& orbit, const GuidanceGains& gains);

// Only the clamped command of steering(q, ...), for the integrator's right-hand side: the same
// equations evaluated with fewer transcendental calls (the heading error from the dot and cross
// products of the heading and the field). cos_psi, sin_psi: cos and sin of q.z().
double steering_command(const Vec3& q, double cos_psi, double sin_psi, const OrbitState& orbit,
                        const GuidanceGains& gains);

// The Lyapunov term u_lyap of (86) given the field at the UAV and its heading error.
double lyapunov_term(const VectorField& field, const OrbitState& orbit, double beta,
                     double heading_error);

// d(r - R)/dt for the Dubins vehicle with heading error psi_tilde (93).
double radial_error_rate(const VectorField& field, const OrbitState& orbit, double heading_error);

// (1 - cos x) / x and sin(x) / x, with their limits at 0 and no loss of accuracy near it.
double one_minus_cos_over_x(double x);
double sinc(double x);

// Exact orbit following (section IV.A). At polar angle theta on the orbit:
// theta_dot of (13) and the signed curvature of the path, +-(31) (+ counter-clockwise), with
// R_ddot: (R theta_dot^2 - R_ddot) / (v u_theta) (Lemma 2 with d(x_dot . e_r)/dt = theta_dot g_dot . e_theta
// + R_ddot in (34)).
// Throws Error when v^2 < (g_dot . e_r + R_dot)^2, i.e. Lemma 5 is violated at theta.
double orbit_polar_rate(double theta, const OrbitState& orbit, double speed, Circulation direction);
double orbit_signed_curvature(double theta, const OrbitState& orbit, double speed, Circulation direction);

// Initial configuration (38)-(40) on the orbit at polar angle theta_0.
Vec3 orbit_configuration(double theta0, const OrbitState& orbit, double speed, Circulation direction);

// The curvature bound of Lemma 6, (v_g + v)^2 / (R v^2), and the gain bound of (87),
// v beta 4 / pi^2 eps_max, with eps_max the maximum of atan^2(x) / (1 + x^2).
double lemma6_curvature_bound(double radius, double speed, double poi_speed);
double lemma7_min_gain(double speed, double beta);
// eps_max ~ 0.31483 of (98) and lambda_max ~ 0.41195 of (106), solved to machine precision.
double epsilon_max();
double lambda_max();

}  // namespace vistrack
