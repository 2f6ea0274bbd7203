// The flight layer: one Dubins vehicle in wind, flown by a guidance law. Every planner
// (waypoint_nav, loiter, follow) flies its plans here; none carries its own simulator.
//
// Vehicle: constant airspeed v, heading psi, turn rate |psi_dot| <= v / R; ground velocity
// v (cos psi, sin psi) + w(t). The wind w(t) is a constant plus optional Dryden gusts
// (WindField). The guidance never sees the wind: it gets the state (x, y, psi) and the time.
// Uav::dynamics chooses how the turn rate follows the guidance's command: at once (Dubins, the
// papers' vehicle) or through the bank angle, a state with a first-order, rate-limited response
// (Roll, RollModel of vehicle.hpp; the flight starts level).
//
// Two ways to fly (FlightOptions::integration):
//  * Discrete, the paper's update (Silverberg & Xu 2019, section 3.1): at t_i the guidance gives a
//    turn rate r_i; psi_{i+1} = psi_i + clamp(r_i, -v/R, v/R) dt (so |psi_turn| <= psi_max = v dt / R),
//    then the position moves over the step with the new heading:
//    p_{i+1} = p_i + dt (v (cos psi_{i+1}, sin psi_{i+1}) + w(t_i + dt/2)).
//    With the roll model the bank is advanced first, by RollModel::step (the exact response over
//    the step to the command held), and the step turns at the new bank's rate g tan(phi_{i+1}) / v.
//  * Continuous: (x, y, psi)' = (v cos psi + w_e(t), v sin psi + w_n(t), clamp(r(q, t))) by the
//    Dormand-Prince 5(4) of ode.hpp, steps no longer than dt, output every dt. With the roll model
//    the state is (x, y, psi, phi) and psi' = g tan(phi) / v, phi' = RollModel::bank_rate.
//
// Stateful guidance (switching waypoints) changes only between steps, never inside the trial
// right-hand-side evaluations of a step: FlightGuidance::command is const, and fly() calls
// FlightGuidance::advance after every accepted step (discrete: every step). In continuous flight
// a guidance may also name a switching function; its zero crossing (from > 0 to <= 0) is located
// on the step's dense output, the step is cut there, advance() runs, and the integrator restarts
// (the right-hand side jumps there). It also restarts whenever the guidance's revision() changes
// (after advance(), after on_step, or at a time given by next_change_time()).
//
// Feeding a guidance during flight (the follow planner's 1 Hz waypoints): WaypointFollower::
// add_waypoint(point, available_from) can be called before the flight with future availability
// times (a timed plan: the follower switches to a waypoint only from its time on, and continuous
// flight stops a step exactly there), or from the on_step callback of fly(), which runs after each
// accepted step with the time and state, so a planner can compute the next waypoint from where
// the vehicle and the ground target are.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <variant>
#include <vector>

#include "vistrack/dubins.hpp"
#include "vistrack/geometry.hpp"
#include "vistrack/ode.hpp"
#include "vistrack/dubins_parameters.hpp"
#include "vistrack/flight_parameters.hpp"
#include "vistrack/vehicle.hpp"

namespace vistrack {


// ---- Wind ------------------------------------------------------------------------------------
//
// Dryden turbulence, MIL-F-8785C (and MIL-HDBK-1797) low-altitude model, horizontal components
// only. Spectra over the spatial frequency Omega (rad per length unit), one-sided, each
// integrating to sigma^2:
//   longitudinal  Phi_u(Omega) = sigma_u^2 (2 L_u / pi) / (1 + (L_u Omega)^2)
//   lateral       Phi_v(Omega) = sigma_v^2 (L_v / pi) (1 + 3 (L_v Omega)^2) / (1 + (L_v Omega)^2)^2
// Taylor's frozen field turns them into time at the airspeed V (omega = Omega V, T = L / V):
// shaping filters driven by unit white noise
//   H_u(s) = sigma_u sqrt(2 T) / (1 + T s),   H_v(s) = sigma_v sqrt(T) (1 + sqrt(3) T s) / (1 + T s)^2,
// i.e. autocorrelations sigma^2 e^{-tau/T} and sigma^2 e^{-tau/T} (1 - tau / (2 T)).
// Low-altitude length scales and intensities (h in feet, 10 ft < h < 1000 ft, W20 the wind
// speed at 20 ft: light 15 kt, moderate 30 kt, severe 45 kt):
//   L_w = h,  L_u = L_v = h / (0.177 + 0.000823 h)^1.2,
//   sigma_w = 0.1 W20,  sigma_u = sigma_v = sigma_w / (0.177 + 0.000823 h)^0.4.
// The components are generated in a fixed frame: u along the mean wind (east when there is
// none), v 90 degrees to its left. Each filter is discretized exactly (zero-order-hold noise,
// transition and covariance by Van Loan's matrix exponential), started from its stationary
// distribution, and driven by a Box-Muller transform of std::mt19937_64 (both fully specified,
// so a seed gives the same gusts everywhere). The series is precomputed for the whole flight
// and interpolated linearly, so the integrator sees a deterministic, continuous w(t).

// Intensities and length scales of the MIL-F-8785C low-altitude model, SI.
struct DrydenLowAltitude {
  double sigma_u = 0.0;  // = sigma_v, m/s
  double sigma_w = 0.0;  // vertical, m/s (not used by the planar flight; reported)
  double length_u = 0.0; // = L_v, m
  double length_w = 0.0; // = h, m
};
// altitude in m (3.05-304.8 m, the model's 10-1000 ft), wind_speed_20ft W20 in m/s (>= 0).
DrydenLowAltitude dryden_low_altitude(double altitude, double wind_speed_20ft);
// Gusts of that model in the flight's units: speeds divided by speed_unit (m/s per unit), lengths
// by length_unit (m per unit); 1, 1 for SI flights.
Gusts mil_f_8785c_gusts(double altitude, double wind_speed_20ft, std::uint64_t seed, double length_unit = 1.0,
                        double speed_unit = 1.0);

// w(t) for one flight: the constant wind plus, with gusts, the precomputed series on
// [t0, t0 + duration] (held at the ends outside). Throws Error naming the field when the wind
// speed reaches the airspeed (the constant part: "wind"; with gusts, anywhere in the series:
// "wind.gusts.intensity").
class WindField {
 public:
  WindField() = default;  // calm
  WindField(const Wind& wind, double airspeed, double t0, double duration);

  Vec2 at(double t) const;
  // The first gust sample time after t (+infinity without gusts or past the series): w(t) has a
  // kink there, so continuous flight ends a step on it.
  double next_sample_time(double t) const;
  const Wind& wind() const { return wind_; }
  bool has_gusts() const { return !gust_east_.empty(); }
  double sample_step() const { return step_; }  // 0 without gusts
  // Largest |w| over the precomputed span (the constant speed without gusts).
  double max_speed() const { return max_speed_; }
  // The precomputed gust samples (without the constant part), at t0 + k * sample_step().
  const std::vector<double>& gust_east() const { return gust_east_; }
  const std::vector<double>& gust_north() const { return gust_north_; }

 private:
  Wind wind_;
  double t0_ = 0.0;
  double step_ = 0.0;
  double max_speed_ = 0.0;
  std::vector<double> gust_east_, gust_north_;
};

namespace detail {
// One Dryden component as an exact discrete Gauss-Markov recursion x_{k+1} = Phi x_k + noise,
// output y = C x (exposed for the tests: stationary output variance C P C^T = sigma^2).
struct DrydenFilter {
  Eigen::Matrix2d transition = Eigen::Matrix2d::Zero();   // Phi = exp(A h)
  Eigen::Matrix2d noise_root = Eigen::Matrix2d::Zero();   // Q^{1/2}, Q the step's noise covariance
  Eigen::Matrix2d stationary_root = Eigen::Matrix2d::Zero();  // P^{1/2}, A P + P A^T + B B^T = 0
  Eigen::RowVector2d output = Eigen::RowVector2d::Zero();    // C
  Eigen::Matrix2d stationary = Eigen::Matrix2d::Zero();       // P
};
// lateral = false: H_u; true: H_v. time_scale T = L / V, step h (s).
DrydenFilter dryden_filter(double sigma, double time_scale, double step, bool lateral);
// Standard normal draws from mt19937_64 by Box-Muller (portable, unlike std::normal_distribution).
class NormalStream {
 public:
  explicit NormalStream(std::uint64_t seed) : engine_(seed) {}
  double next();

 private:
  std::mt19937_64 engine_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};
// n stationary samples of one component, one sample per filter step.
std::vector<double> dryden_series(const DrydenFilter& filter, std::size_t n, NormalStream& noise);
}  // namespace detail

// ---- Guidance ---------------------------------------------------------------------------------

// What a guidance answers at one state and time: the turn rate it asks for (rad/s; the vehicle
// clamps it to +-v/R) and the target it is steering to.
struct GuidanceCommand {
  double turn_rate = 0.0;
  Vec2 target = Vec2::Zero();
  int target_index = -1;  // planner-defined (the waypoint index), -1: none
};

// A guidance law with optional discrete state. fly() calls start() once, then command() (any
// number of times, also at trial states: it must not change the object), and advance() after
// every accepted step. Implementations: WaypointFollower (here), the DWN guidance of waypoint_nav,
// path followers of the planners.
class FlightGuidance {
 public:
  virtual ~FlightGuidance() = default;

  // Reset the discrete state for a flight starting at `state`, time t (may switch at once).
  virtual void start(const Configuration& state, double t) = 0;
  virtual GuidanceCommand command(const Configuration& state, double t) const = 0;
  // The stateful logic (switch targets, finish), on an accepted state only.
  virtual void advance(const Configuration& state, double t) = 0;
  // True once the guidance has nothing more to fly: the flight stops.
  virtual bool done() const = 0;
  // Continuous flight: a function whose crossing from > 0 to <= 0 is where advance() will
  // change something (e.g. distance to the waypoint minus the acceptance radius); the crossing
  // is located on the dense output and the step cut there. +infinity: none.
  virtual double switching_function(const Configuration& /*state*/, double /*t*/) const {
    return std::numeric_limits<double>::infinity();
  }
  // The next time after t at which the guidance changes by itself (a timed waypoint becoming
  // available); continuous flight ends a step there. +infinity: none.
  virtual double next_change_time(double /*t*/) const { return std::numeric_limits<double>::infinity(); }
  // Counts changes of what command() returns for a given state (targets switched, waypoints
  // added). Continuous flight restarts its integrator when it changes.
  std::uint64_t revision() const { return revision_; }

 protected:
  void touch() { ++revision_; }

 private:
  std::uint64_t revision_ = 0;
};

// The paper's illustrative feedback law (5): steer towards the line whose end is the target
// (a waypoint in WN, a turning point in DWN). With phi_T the target angle (from the heading to
// the direction of the target, in (-pi, pi]) and s the cross-track distance to the line
// (positive to its left),
//   phi_R = |g s + h s_dot dt| sign(phi_T),   psi_turn = clamp(phi_T + phi_R, -psi_max, psi_max),
//   psi_max = v dt / R,
// a heading change per law step dt; the turn rate is psi_turn / dt (in discrete flight at the same
// dt this is exactly the paper's update). s_dot is the rate of s that the heading gives,
// v sin(psi - chi_line): the law does not know the wind. The paper prints "s_dot" next to
// h = 5.25: as a rate per second h s_dot would reach 4 rad against psi_max = 0.023 rad and
// saturate always, so we read it as the change of s over one step (s_dot dt), which puts both
// terms at the scale of psi_max.
struct LineFeedbackTerms {
  double target_angle = 0.0;     // phi_T
  double cross_track = 0.0;      // s
  double cross_track_step = 0.0; // s_dot dt
  double reference_angle = 0.0;  // phi_R
  double unsaturated = 0.0;      // phi_T + phi_R
  double turn = 0.0;             // psi_turn, clamped to +-psi_max
  bool saturated = false;
};

//
// smooth_sign replaces sign(phi_T) by clamp(phi_T / psi_max, -1, 1). For continuous flight: with
// the exact sign, phi_R jumps where phi_T crosses 0 and the integrator would have to resolve a
// sliding mode (the discrete law chatters there by +-phi_R around pure pursuit instead).
class LineFeedback {
 public:
  LineFeedback() = default;
  // speed v, turn_radius R, law step dt (psi_max = v dt / R must not exceed pi/2), gains.
  LineFeedback(double speed, double turn_radius, double dt, const LineFeedbackGains& gains = {},
               bool smooth_sign = false);

  // The law at state q for the line from line_start to target. A line shorter than 1e-12 times
  // the distance scale has no direction: s = 0 (pure pursuit of the target).
  LineFeedbackTerms terms(const Configuration& q, const Vec2& line_start, const Vec2& target) const;
  double turn_rate(const Configuration& q, const Vec2& line_start, const Vec2& target) const {
    return terms(q, line_start, target).turn / dt_;
  }
  double speed() const { return speed_; }
  double turn_radius() const { return turn_radius_; }
  double dt() const { return dt_; }
  double max_turn() const { return speed_ * dt_ / turn_radius_; }  // psi_max
  const LineFeedbackGains& gains() const { return gains_; }
  bool smooth_sign() const { return smooth_sign_; }
  // Wind-aware (beyond the paper): phi_T and s_dot from the course of the ground velocity
  // v (cos psi, sin psi) + w with the known mean wind w, instead of from the heading.
  void set_wind(const Vec2& mean_wind);
  bool wind_aware() const { return wind_aware_; }

 private:
  double speed_ = 1.0, turn_radius_ = 1.0, dt_ = 0.02;
  LineFeedbackGains gains_;
  bool smooth_sign_ = false;
  bool wind_aware_ = false;
  Vec2 wind_ = Vec2::Zero();
};

// L1 line tracking, as ArduPlane flies a leg (Park, Deyst & How, "A New Nonlinear Guidance Logic
// for Trajectory Tracking", 2004; ArduPilot's AP_L1_Control::update_waypoint). The reference point
// lies on the line from line_start to target, L1 = damping * period * v / pi ahead; with eta the
// angle from the velocity to it, the lateral acceleration is a = 4 damping^2 v^2 / L1 sin(eta)
// and the turn rate a / v. eta = Nu1 + Nu2: Nu2 the angle from the velocity to the line's
// direction, Nu1 = asin(-e / L1) (e the cross-track error, positive left; |sin Nu1| <= 0.7071,
// capture at 45 degrees at most), |eta| <= pi/2. Far behind the line's start (farther than L1,
// more than 45 degrees behind) it flies to the start; more than 3 v seconds past the target, to
// the target. Like every guidance here it uses the airspeed vector (it does not know the wind).
// Its command is continuous in the state: no chatter, one law for discrete and continuous flight.
class L1Line {
 public:
  L1Line() = default;
  explicit L1Line(double speed, const L1Gains& gains = {});
  double turn_rate(const Configuration& q, const Vec2& line_start, const Vec2& target) const;
  double distance() const { return distance_; }  // L1, length units
  const L1Gains& gains() const { return gains_; }
  // Wind-aware (beyond the paper, as ArduPlane flies L1): the known mean wind makes the law steer
  // the ground velocity v (cos psi, sin psi) + w instead of the heading, with L1 and the lateral
  // acceleration from the ground speed V_g (L1 = damping period V_g / pi, a = 4 damping^2 V_g^2 /
  // L1 sin(eta)) and the turn rate a / v. Without it (the default) the law sees no wind.
  void set_wind(const Vec2& mean_wind);
  bool wind_aware() const { return wind_aware_; }

 private:
  double speed_ = 1.0, distance_ = 1.0;
  L1Gains gains_;
  bool wind_aware_ = false;
  Vec2 wind_ = Vec2::Zero();
};

// L1 guidance on a curve (Park, Deyst & How 2004): the reference point is where the circle of
// radius L1 = damping * period * v / pi about the vehicle leaves the path ahead of the vehicle's
// closest point (beyond the path's end, along its last direction); farther than L1 from the path,
// the closest point itself. Turn rate 4 damping^2 v / L1 sin(eta), eta the angle from the
// airspeed vector to the reference point, |eta| <= pi/2. The path is a polyline that may be
// replaced during flight (set_path from fly()'s on_step: the follow planner's planned path at
// each update); the guidance is never done by itself.
class CurveL1 : public FlightGuidance {
 public:
  CurveL1(double speed, const std::vector<Vec2>& path, const L1Gains& gains = {});
  // At least one point (one: fly to it), within the coordinate range; consecutive duplicates are dropped.
  void set_path(const std::vector<Vec2>& path);

  void start(const Configuration&, double) override {}
  GuidanceCommand command(const Configuration& state, double t) const override;
  void advance(const Configuration&, double) override {}
  bool done() const override { return false; }

  Vec2 reference_point(const Vec2& position) const;
  double distance() const { return distance_; }  // L1
  const std::vector<Vec2>& path() const { return path_; }

 private:
  double speed_ = 1.0, distance_ = 1.0;
  L1Gains gains_;
  std::vector<Vec2> path_;
};

// Holds a commanded turn rate, set during flight from fly()'s on_step (the horizon follower's bank
// command as g tan(bank) / v, follow.hpp): the roll model banks towards atan(v rate / g),
// the Dubins vehicle turns at once. Never done by itself.
class TurnRateHold : public FlightGuidance {
 public:
  explicit TurnRateHold(double turn_rate = 0.0) { set_turn_rate(turn_rate); }
  // Finite (the vehicle clamps it to +-v/R); from the next step on.
  void set_turn_rate(double turn_rate);
  double turn_rate() const { return rate_; }

  void start(const Configuration&, double) override {}
  GuidanceCommand command(const Configuration& state, double t) const override;
  void advance(const Configuration&, double) override {}
  bool done() const override { return false; }

 private:
  double rate_ = 0.0;
};

// Classical waypoint navigation (WN) on the law (5) (or L1Line): fly the line from the previous waypoint
// (the start position for the first) to the active waypoint; switch to the next one when within
// the acceptance radius R_WP. With finish_at_last the guidance is done at the last waypoint;
// without, it keeps steering to the last accepted waypoint and goes on when more are added
// (the follow planner feeds it this way).
class WaypointFollower : public FlightGuidance {
 public:
  WaypointFollower(const LineFeedback& law, const std::vector<Vec2>& waypoints, double acceptance_radius,
                   bool finish_at_last = true);
  // The same switching with each leg flown by L1 line tracking instead of the law (5).
  WaypointFollower(const L1Line& law, const std::vector<Vec2>& waypoints, double acceptance_radius,
                   bool finish_at_last = true);

  // Switching as ArduPlane's verify_nav_wp (beyond the paper): a waypoint is also done once the
  // vehicle is past the line through it perpendicular to the leg, and the acceptance distance
  // anticipates the turn: min(R_WP, L1 distance) x min(|turn angle|, 90 deg) / 90 deg, the turn
  // angle between this leg and the next (AP_L1_Control::turn_distance; no L1 cap with the law (5);
  // 0 at the last waypoint, which is done on its line).
  void set_passed_line(bool enabled);
  bool passed_line() const { return passed_line_; }
  // With finish_at_last: the last waypoint is done only once the vehicle is past the line through
  // it perpendicular to its leg (not inside R_WP): the flight ends on that line (waypoint_nav's
  // flights, whose last miss is measured there). Off by default.
  void set_finish_line(bool enabled);
  bool finish_line() const { return finish_line_; }
  // The acceptance distance of the active waypoint (R_WP unless passed_line).
  double acceptance_distance() const { return acceptance_; }

  // Append a waypoint, usable from time available_from on (-infinity: at once). Allowed during
  // flight (from fly()'s on_step callback). Availability times must not decrease.
  void add_waypoint(const Vec2& point, double available_from = -std::numeric_limits<double>::infinity());

  void start(const Configuration& state, double t) override;
  GuidanceCommand command(const Configuration& state, double t) const override;
  void advance(const Configuration& state, double t) override;
  bool done() const override { return done_; }
  double switching_function(const Configuration& state, double t) const override;
  double next_change_time(double t) const override;

  const std::vector<Vec2>& waypoints() const { return waypoints_; }
  const std::vector<double>& available_from() const { return available_from_; }
  std::size_t active() const { return active_; }   // index of the active waypoint
  const Vec2& line_start() const { return line_start_; }
  double acceptance_radius() const { return acceptance_radius_; }
  // Time each waypoint was accepted (NaN while not yet).
  const std::vector<double>& accepted_at() const { return accepted_at_; }

 private:
  bool next_available(double t) const;
  // How far the vehicle is past the active waypoint's finish line along the leg (m, > 0 past it).
  double past_finish_line(const Vec2& p) const;
  bool on_finish_line_only() const;
  void update_acceptance();

  std::variant<LineFeedback, L1Line> law_;
  std::vector<Vec2> waypoints_;
  std::vector<double> available_from_;
  std::vector<double> accepted_at_;
  double acceptance_radius_;
  bool finish_at_last_;
  std::size_t active_ = 0;
  Vec2 line_start_ = Vec2::Zero();
  bool done_ = false;
  bool passed_line_ = false;
  bool finish_line_ = false;
  double acceptance_ = 0.0;  // acceptance_distance(), kept by update_acceptance()
};

// ---- Flying -----------------------------------------------------------------------------------

// One sample per output time: the state, the turn rate applied from there (rad/s, clamped;
// at the last sample the command there), the bank, the active target and the wind at that time.
// The bank: with the roll model the state's; with the Dubins model the coordinated bank of the
// turn rate applied from the sample (what the vehicle would bank to at once).
struct FlightTrajectory {
  std::vector<double> t, x, y, psi;  // psi as integrated (not wrapped)
  std::vector<double> command;
  std::vector<double> bank;          // rad, positive left wing down
  std::vector<double> bank_command;  // rad: the coordinated bank of the guidance's clamped command
  std::vector<double> target_x, target_y;
  std::vector<int> target_index;
  std::vector<double> wind_east, wind_north;
  bool finished = false;        // the guidance said done (else max_time was reached)
  double end_time = 0.0;
  std::vector<double> switch_times;  // where the guidance's revision changed (continuous: restarts)
  OdeStatistics statistics;     // continuous flights
  std::size_t size() const { return t.size(); }
};

// How smoothly a flight banks (issue 28's measures; a real aircraft does not chatter):
//  * bank_rms_deg: RMS of the bank about its moving mean over a centred window (5 s), degrees;
//  * roll_reversals_per_s: reversals of the bank with a deadband (1 degree: successive extrema at
//    least that far apart, so rounding noise in a steady turn counts nothing), per second of flight;
//  * max_roll_rate_deg_s: the largest |bank change / time| between successive samples.
struct FlightSmoothness {
  double bank_rms_deg = 0.0;
  double roll_reversals_per_s = 0.0;
  std::size_t roll_reversals = 0;
  double max_roll_rate_deg_s = 0.0;
};
// t increasing (equal times allowed: their bank change is not a rate), bank in rad, same length.
// Error naming the field on a length mismatch, fewer than 2 samples, non-finite values,
// decreasing times, window <= 0 or deadband < 0.
FlightSmoothness flight_smoothness(const std::vector<double>& t, const std::vector<double>& bank,
                                   double window = 5.0, double deadband_deg = 1.0);

using FlightCallback = std::function<void(double t, const Configuration& state)>;
using FlightProgress = std::function<void(std::size_t done, std::size_t total)>;

// Flies the vehicle (speed, min_turn_radius and dynamics of `vehicle`) from `start` at time t0 under the
// guidance until it is done or t0 + max_time. on_step runs after each accepted step (after
// guidance.advance); progress gets (elapsed, total) in per mille of max_time. The guidance is
// used by reference and left in its final state.
FlightTrajectory fly(const Uav& vehicle, const Wind& wind, FlightGuidance& guidance, const Configuration& start,
                     const FlightOptions& options = {}, double t0 = 0.0, const FlightCallback& on_step = {},
                     const FlightProgress& progress = {});
// Same with a wind field made for the vehicle's airspeed (WindField keeps the wind below it) whose span
// covers the flight.
FlightTrajectory fly(const Uav& vehicle, const WindField& wind, FlightGuidance& guidance, const Configuration& start,
                     const FlightOptions& options = {}, double t0 = 0.0, const FlightCallback& on_step = {},
                     const FlightProgress& progress = {});

// ---- Path following: a guidance that flies a path of lines and arcs ---------------
//
// PathFollower flies a given path of straight lines and circular arcs (the loiter plans; any
// planner's lines and arcs).
//
// Law: with s the progress along the path (the closest point near the previous progress), e the
// cross-track error (positive to the left of the path), psi_p and kappa the path's heading and
// curvature there,
//   psi_d = psi_p - atan(e / L),                              L = lookahead_radii * R
//   rate  = v kappa cos(psi - psi_p) / (1 - kappa e)  +  k wrap(psi_d - psi),   k = heading_gain * v / R,
// the first term the rate at which the path's heading turns under the vehicle (curvature
// feed-forward), the second heading feedback towards the line of approach. Like the rest of the
// flight layer it knows the heading, not the wind (no ground course): a constant wind leaves a
// tracking error, which is what flying a plan in unknown wind measures.

// One piece: from `start` with `heading`, `length` long, signed curvature (0 line, +1/radius
// counter-clockwise, -1/radius clockwise).
struct PathPiece {
  Vec2 start = Vec2::Zero();
  double heading = 0.0;
  double length = 0.0;
  double curvature = 0.0;
  Configuration at(double s) const;  // s in [0, length] (not clamped)
};

class PathFollower : public FlightGuidance {
 public:
  // pieces: consecutive (each starting where the one before ends); speed v and turn radius R of
  // the vehicle. Error naming the field on an empty path, a non-finite value, a piece of length
  // <= 0, a curvature tighter than 1 / R or a gap between pieces above 1e-6 (1 + |coordinates|).
  PathFollower(std::vector<PathPiece> pieces, double speed, double turn_radius, const PathFollowingGains& gains = {});

  void start(const Configuration& state, double t) override;
  GuidanceCommand command(const Configuration& state, double t) const override;
  void advance(const Configuration& state, double t) override;
  bool done() const override { return done_; }
  // The next piece boundary minus the progress at `state`: continuous flight cuts its steps there
  // (the curvature feed-forward jumps); at the last piece, -1 once the end is reached.
  double switching_function(const Configuration& state, double t) const override;

  // Where the state projects onto the path near the current progress.
  struct Tracking {
    double s = 0.0;              // progress, m
    std::size_t piece = 0;
    double cross_track = 0.0;    // m, positive to the left of the path
    double heading_error = 0.0;  // psi - psi_path, wrapped, rad
    double along = 0.0;          // signed distance ahead of the path point (non-zero only at the ends)
  };
  Tracking track(const Configuration& state) const;

  double progress() const { return progress_; }
  double length() const { return length_; }
  const std::vector<PathPiece>& pieces() const { return pieces_; }
  const PathFollowingGains& gains() const { return gains_; }

 private:
  std::size_t piece_at(double s) const;

  std::vector<PathPiece> pieces_;
  std::vector<double> offsets_;
  double length_ = 0.0;
  double speed_, turn_radius_;
  PathFollowingGains gains_;
  double progress_ = 0.0;
  bool done_ = false;
};

}  // namespace vistrack
