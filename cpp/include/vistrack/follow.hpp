// Following a ground vehicle (the paper in ../shared/seeds/ground_vehicle_following.txt): sinusoidal mode with the amplitude from the
// speed ratio (section II, eqs. 1-10), loiter mode (circle or rose, Fig. 3) above a threshold
// with a hysteresis band, an offset vector, wind compensation (section III) and waypoints at 1 Hz
// (section V). The planner plans; the flight layer flies its waypoints (follow_run.cpp).
//
// The sinusoid (eq. 1) lies in a frame x2-y2 fixed on the ground whose x axis is the vehicle's
// direction of travel: y = A sin(2 pi x / D), D = v_g T. The UAV runs along it at its speed v_p,
// so x_dot = v_p / sqrt(1 + A'^2 cos^2(2 pi x / D)) (eq. 5, A' = 2 pi A / D), and covering one
// period in T = D / v_g gives sigma = v_p / v_g = (1/D) int_0^D sqrt(1 + A'^2 cos^2) dx
// = (2/pi) E(-A'^2) (eqs. 9-10, E the complete elliptic integral of the second kind in the
// parameter convention). The planner keeps the phase phi = 2 pi x / D as its state and writes
// the desired position relative to the offset point O(t) (the vehicle's position plus the offset
// vector), which the sinusoid visits once per period:
//   lead(phi) = x - v_g t = (D / 2 pi) phi - S(phi) / sigma,   lateral(phi) = A sin(phi),
// where S(phi) = (D / 2 pi) int_0^phi sqrt(1 + A'^2 cos^2 u) du is the arc length from the start
// of the period (so S(2 pi) = sigma D, t = S / v_p). With constant v_g this is exactly the
// paper's fixed sinusoid; when v_g or the heading changes, the pattern follows the vehicle with
// the phase continuous.
//
// Wind compensation (derived here; the paper only says the path "is offset at a ratio of the
// wind velocity vector"). The aircraft holds its airspeed v_a, so a path is flyable at constant
// airspeed exactly when it is planned in the air mass: there the UAV is a wind-free Dubins
// vehicle of speed v_a, and the offset point moves at v_O - w (w the wind estimate). The planner
// therefore plans the relative pattern with sigma = v_a / |v_O - w| along the direction of
// v_O - w, and maps it to the ground by adding the drift of the air mass: a point planned t - t0
// seconds ahead in the air moves by w (t - t0). Relative to the offset point both frames agree,
// so the desired ground position is O(t) + relative(t) and its airspeed is exactly v_a.
// Without compensation the planner ignores the wind: it plans on the ground with v_p = the
// airspeed and the direction of v_O, a path the UAV cannot fly at the planned rate in wind (the
// paper's Fig. 6). (The paper plans with the measured ground speed; planned so, sigma swings
// with the heading at every update and the path degrades further: see the README.)
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "vistrack/flight.hpp"
#include "vistrack/geometry.hpp"
#include "vistrack/guidance.hpp"
#include "vistrack/follow_parameters.hpp"
#include "vistrack/vehicle.hpp"
#include "vistrack/visibility.hpp"

namespace vistrack {

// ---- The sinusoid of section II ---------------------------------------------------------------

// sigma(A) of eqs. (9)-(10): (2/pi) E(-A'^2), A' = 2 pi A / D, by Boost.Math's ellint_2 through
// 1 + a^2 cos^2 u = (1 + a^2)(1 - m sin^2 u), m = a^2 / (1 + a^2) (derived; no negative
// parameter needed). amplitude >= 0, period_distance > 0.
double sinusoid_speed_ratio(double amplitude, double period_distance);
// The inverse: A >= 0 with sinusoid_speed_ratio(A, D) = speed_ratio, to 1e-12 relative
// (safeguarded Newton on the exact derivative). speed_ratio >= 1 (1 gives 0); below 1 no
// sinusoid is slow enough and Error names speed_ratio.
double sinusoid_amplitude(double speed_ratio, double period_distance);
// The slope amplitude a = A' = 2 pi A / D for a speed ratio (the shape does not depend on D).
double sinusoid_slope(double speed_ratio);

// The sinusoid the planner flies at a speed ratio: D = max(v_p T / sigma, 2 pi a rho) (the period
// T raised where the peak curvature a 2 pi / D would exceed 1 / rho, rho = turn_margin r_min), and
// A = a D / (2 pi) (eq. 10's a = A'). On the curvature floor A = a^2 rho, whatever T is: the
// `period` key then has no effect (issue 31).
struct SinusoidShape {
  double slope = 0.0;            // a = A'
  double period_distance = 0.0;  // D, m
  double amplitude = 0.0;        // A, m
  bool curvature_limited = false;  // D is the floor 2 pi a rho, not v_p T / sigma
};
// speed_ratio >= 1, uav_speed > 0, period > 0, turn_radius > 0 (the planned rho).
SinusoidShape sinusoid_shape(double speed_ratio, double uav_speed, double period, double turn_radius);
// eq. (5): the along-track rate x_dot = v_p / sqrt(1 + A'^2 cos^2(2 pi x / D)).
double sinusoid_along_track_rate(double x, double amplitude, double period_distance, double uav_speed);
// Arc length of y = A sin(2 pi x / D) from x = 0 to x (any real x; odd in x). Incomplete
// elliptic integral of the second kind (Boost.Math).
double sinusoid_arc_length(double x, double amplitude, double period_distance);
// The phase phi = 2 pi x / D at which the arc length from 0 is `arc` (any real arc), to 1e-13.
double sinusoid_phase_at_arc(double arc, double amplitude, double period_distance);

// ---- The ground vehicle -------------------------------------------------------------------------

// One leg of a driven route: heading (radians counter-clockwise from east), speed at the start
// and at the end (linear in between; 0 and 0 is a stop, the vehicle standing facing `heading`),
// duration. end_speed NaN: the same as speed.
struct VehicleLeg {
  double heading = 0.0;
  double speed = 0.0;
  double duration = 0.0;
  double end_speed = std::numeric_limits<double>::quiet_NaN();
};

// A ground vehicle as a piecewise-linear track (t_i, x_i, y_i): position interpolated, velocity
// of the segment (right-continuous), heading of the last segment that moves (the first moving
// one before it; legs give stops their own heading).
class GroundVehicle {
 public:
  // times strictly increasing, all finite, at least two samples. headings: per segment (size
  // n - 1) or empty (from the motion). Error names "track.t[i]", "track.x[i]", ...
  GroundVehicle(std::vector<double> times, Points2 positions, std::vector<double> headings = {});
  // Legs from `start` at time t0. A leg with a changing speed is sampled every `step` seconds.
  static GroundVehicle from_legs(const std::vector<VehicleLeg>& legs, const Vec2& start = Vec2::Zero(),
                                 double t0 = 0.0, double step = 0.1);
  // Along a polyline (a road path, (n, 2)) with the speed profile of `legs` (their headings are
  // ignored: the path gives them); stops where the legs stop. Legs longer than the road drive it
  // back and forth (a U-turn at each end).
  static GroundVehicle along_path(const Points2& path, const std::vector<VehicleLeg>& legs, double t0 = 0.0,
                                  double step = 0.1);

  Vec2 position(double t) const;  // clamped to [start, end]
  Vec2 velocity(double t) const;  // 0 outside [start, end)
  double heading(double t) const;
  double speed(double t) const { return velocity(t).norm(); }
  double start_time() const { return times_.front(); }
  double end_time() const { return times_.back(); }
  const std::vector<double>& times() const { return times_; }
  const Points2& positions() const { return positions_; }
  const std::vector<double>& headings() const { return headings_; }  // per segment
  double max_speed() const;

 private:
  // along_path on a polyline long enough for the legs (ends where the polyline ends).
  static GroundVehicle driven_along(const Points2& path, const std::vector<VehicleLeg>& legs, double t0, double step);
  std::size_t segment(double t) const;
  std::vector<double> times_;
  Points2 positions_;
  std::vector<double> headings_;
};

// ---- What the UAV knows of the vehicle (beyond the paper) -------------------------------------------

// The vehicle's reports, one per update period (section V's 1 Hz), as a radio link delivers them:
// Gaussian noise on position and velocity, a latency, and dropouts (seeded). All zero: the true
// state at each update, as the paper's simulation sends it.
struct VehicleReportOptions {
  double position_noise = 0.0;  // m, standard deviation per axis
  double velocity_noise = 0.0;  // m/s, per axis
  double latency = 0.0;         // s from measurement to reception
  double dropout = 0.0;         // probability that a report is lost, in [0, 1)
  double timeout = 5.0;         // s without a fresh report after which the vehicle is lost
  std::uint64_t seed = 1;
  void validate() const;
};

struct VehicleReport {
  double measured = 0.0;  // s
  double received = 0.0;  // s
  Vec2 position = Vec2::Zero();
  Vec2 velocity = Vec2::Zero();
  double heading = 0.0;
};

// The vehicle as known on board at time t: the newest report received, carried along its velocity
// (position + velocity (t - measured)). `lost`: no report younger than the timeout.
struct VehicleEstimate {
  Vec2 position = Vec2::Zero();
  Vec2 velocity = Vec2::Zero();
  double heading = 0.0;
  double age = 0.0;  // t - measured, s
  bool lost = false;
};

// Reports measured at t0 + k period up to t_end. The first (at t0) is always received at t0: the
// vehicle is acquired when the run starts.
class VehicleReports {
 public:
  VehicleReports(const GroundVehicle& vehicle, double t0, double t_end, double period,
                 const VehicleReportOptions& options = {});
  VehicleEstimate estimate(double t) const;
  const std::vector<VehicleReport>& reports() const { return reports_; }
  const VehicleReportOptions& options() const { return options_; }

 private:
  std::vector<VehicleReport> reports_;  // by reception time
  VehicleReportOptions options_;
};

// ---- Loiter patterns (Fig. 3) ---------------------------------------------------------------------

// Standoff: the tracking paper's vector field (74) about the offset point (beyond this paper).
enum class FollowMode : std::uint8_t { Sinusoid = 0, Loiter = 1, Straight = 2, Standoff = 3 };
template <>
struct EnumNames<FollowMode> {
  static constexpr const char* field = "mode";
  static constexpr EnumName<FollowMode> names[] = {{"sinusoid", FollowMode::Sinusoid}, {"loiter", FollowMode::Loiter},
      {"straight", FollowMode::Straight}, {"standoff", FollowMode::Standoff}};
};

// A closed or endless curve about the loiter centre, by arc length s >= 0: the circle of radius
// R, or the rose of Fig. 3 built from its description (waypoints along a line through the
// centre, the line rotated after each pass): a straight pass of length 2 l through the centre,
// then a turn of radius rho and angle pi + delta onto the next line, rotated by pi + delta.
// The turn is tangent to both lines, so l = rho / tan(delta / 2), and the pattern reaches
// rho + rho / sin(delta / 2) = extent from the centre: sin(delta / 2) = rho / (extent - rho),
// extent >= 2 rho (delta = pi: circles of radius rho through the centre).
struct LoiterShape {
  LoiterPattern pattern = LoiterPattern::Circle;
  double radius = 1.0;      // circle radius, or the rose's extent
  double turn_radius = 1.0; // rose: rho
  int direction = +1;       // +1 counter-clockwise turns
  double rotation = 0.0;    // rose: angle of the first line (radians from east)

  void validate() const;
  double delta() const;         // rose: rotation of the line per pass beyond pi
  double half_line() const;     // rose: l
  double piece_length() const;  // circle: 2 pi R; rose: 2 l + rho (pi + delta)
  Vec2 position(double s) const;  // relative to the centre
  Vec2 tangent(double s) const;   // unit
};

// ---- Camera ----------------------------------------------------------------------------------------

// How the camera is carried. "roll": a one-axis roll gimbal that rolls the camera towards the
// target as far as max_gimbal (the loiter area's model). "pan_tilt": a two-axis gimbal pointed at
// the target, its axis at most max_gimbal from the body's down axis (pan unlimited). "fixed": the
// paper's camera on the bottom of the plane (Fig. 12), along the body's down axis.
enum class CameraMount : std::uint8_t { Roll = 0, PanTilt = 1, Fixed = 2 };
template <>
struct EnumNames<CameraMount> {
  static constexpr const char* field = "camera.mount";
  static constexpr EnumName<CameraMount> names[] = {{"roll", CameraMount::Roll}, {"pan_tilt", CameraMount::PanTilt},
      {"fixed", CameraMount::Fixed}};
};

// A downward conic camera (a 74-degree cone) on its mount. The body banks as in a coordinated
// turn: phi = atan(v psi_dot / g). The vehicle is seen when the angle between the camera's axis
// and the line to it is at most fov / 2. A point test for the follow metric; the loiter area
// computes the footprint ellipse for its disks (peers: to be shared from a lower area).
struct DownwardCamera {
  double fov = 74.0 * kPi / 180.0;         // full angle, rad
  double max_gimbal = 25.0 * kPi / 180.0;  // rad: the roll range, or the pan-tilt's tilt range
  CameraMount mount = CameraMount::Roll;
  void validate() const;
};
// How far to the side of a level UAV at `altitude` the camera still sees a ground point: with
// the gimbal turned as far as it goes, w = altitude tan(fov / 2 + max_gimbal) (roll, pan-tilt),
// altitude tan(fov / 2) for the fixed camera (beyond the paper).
double camera_reach(const DownwardCamera& camera, double altitude);

// The threshold h the planner uses, and the numbers behind it. With follow.threshold "auto"
// (kAutoThreshold) h is the largest one whose sinusoid at the band's upper edge sigma_u = h + band / 2
// keeps its amplitude within the camera's reach: sinusoid_shape(sigma_u).amplitude <= w = camera_reach
// (on the curvature floor a(sigma_u)^2 rho <= w); found by bisection on the increasing amplitude. h is
// kept at least 1 + band / 2 + 0.01 (a loiter needs v_p > v_g): a camera too narrow for any sinusoid
// then loiters whenever the vehicle is slower than the UAV by that margin. With a user's h, the same
// numbers are reported, and `beyond_reach` says the amplitude exceeds w (a warning, not an error).
struct ThresholdChoice {
  double threshold = 0.0;       // h, the one used
  bool automatic = false;       // picked from the camera
  double upper_ratio = 0.0;     // sigma_u = h + band / 2
  double amplitude = 0.0;       // A at sigma_u (the largest the sinusoid flies), m
  double reach = 0.0;           // w, m
  bool beyond_reach = false;    // amplitude > reach
};
ThresholdChoice camera_threshold(const FollowParameters& parameters, const Uav& uav, const DownwardCamera& camera);

// Whether the ground point `target` (x, y, z) is inside the footprint of the camera on a UAV at
// `uav` (x, y, z) with heading psi and bank (positive: left wing down).
bool camera_sees(const DownwardCamera& camera, const Vec3& uav, double psi, double bank, const Vec3& target);

// ---- The planner ----------------------------------------------------------------------------------

// What the planner knows at an update: the vehicle's position and velocity (its 1 Hz report) and
// the UAV's position and heading.
struct FollowObservation {
  Vec2 vehicle_position = Vec2::Zero();
  Vec2 vehicle_velocity = Vec2::Zero();
  double vehicle_heading = 0.0;  // the offset's reference when it is "heading"
  Vec2 uav_position = Vec2::Zero();
  double uav_heading = 0.0;
  Vec2 offset_rate = Vec2::Zero();  // rate of change of the offset vector itself (a moving offset)
  // No fresh report for the timeout: orbit the vehicle's estimate (vehicle_position, the last known
  // position carried along its last velocity) without the offset (beyond the paper).
  bool lost = false;
};

// One 1 Hz update: the mode, the pattern's parameters and its state at time t.
struct FollowTick {
  double t = 0.0;
  FollowMode mode = FollowMode::Straight;
  double speed_ratio = 0.0;     // sigma used for the mode (+infinity when the offset point stands)
  double uav_speed = 0.0;       // v_p planned with (the airspeed)
  Vec2 frame_velocity = Vec2::Zero();  // velocity of the offset point in the planning frame
  double track_angle = 0.0;     // direction of the sinusoid's x axis (of frame_velocity)
  double amplitude = 0.0;       // A, m (sinusoid)
  double period_distance = 0.0; // D, m (sinusoid, after the curvature floor)
  double period = 0.0;          // D / |frame_velocity|, s (sinusoid)
  double phase = 0.0;           // sinusoid: phi at t
  double arc = 0.0;             // loiter: s along the pattern at t
  bool capturing = false;       // holding the entry point until the UAV is within one update's flight
  bool lost = false;            // orbiting the vehicle's estimate (FollowObservation::lost)
  double radius = 0.0;          // orbit_radius at the frame speed: the standoff's and the loiter circle's, m
  Vec2 uav_relative = Vec2::Zero();  // standoff: the UAV relative to the offset point at t, where the field starts
  double predicted_camera = -1.0;    // strategy auto: the chosen pattern's predicted camera fraction (-1: none)
  Vec2 offset_vector = Vec2::Zero();   // O - vehicle at t
  Vec2 offset_point = Vec2::Zero();    // O at t
  Vec2 offset_velocity = Vec2::Zero(); // O's velocity at t (the vehicle's plus the offset's rate)
  Vec2 waypoint = Vec2::Zero();        // the desired position update_period later, predicted
  Vec2 vehicle_predicted = Vec2::Zero();  // the vehicle update_period later, predicted (a gimbal's ROI)
};

// The follow planner of sections II-V. update() runs at every update_period.
class FollowPlanner {
 public:
  // wind_estimate: the constant wind the UAV estimates (used only with wind_compensation); camera:
  // what an "auto" threshold is picked for (camera_threshold).
  FollowPlanner(const FollowParameters& parameters, const Uav& uav, const Vec2& wind_estimate = Vec2::Zero(),
                const DownwardCamera& camera = DownwardCamera{});

  // The update at time t: the mode (with hysteresis), the pattern's state advanced from the
  // previous update, and the next waypoint.
  FollowTick update(double t, const FollowObservation& observation);

  // The offset vector for a vehicle heading (rotated with it when the reference is "heading").
  Vec2 offset_vector(double vehicle_heading) const;
  // Change the offset's distance and angle (Fig. 8 moves the loiter ahead of the stopped vehicle).
  void set_offset(double distance, double angle);
  // The desired position relative to the offset point, tau >= 0 seconds after `tick` (the
  // pattern of the tick's mode with its parameters held), and its velocity in the planning frame.
  Vec2 relative_position(const FollowTick& tick, double tau) const;
  // relative_position at increasing taus, in one pass (the loiter's arc integrated once).
  std::vector<Vec2> relative_positions(const FollowTick& tick, const std::vector<double>& taus) const;
  // The planned ground path from the tick on: O + O_dot tau + relative_position(tick, tau) at
  // tau = 0, step, ..., horizon (the vehicle predicted at its current velocity, as the waypoint is).
  std::vector<Vec2> planned_path(const FollowTick& tick, double horizon, double step) const;
  // The loiter shape in use and the speed ratio below which the planner enters the sinusoid.
  const LoiterShape& loiter_shape() const { return loiter_; }
  const FollowParameters& parameters() const { return parameters_; }
  const Uav& uav() const { return uav_; }
  const Vec2& wind_estimate() const { return wind_; }
  bool has_ticks() const { return has_previous_; }
  // The threshold in use (parameters().threshold is it, resolved when "auto") and its numbers.
  const ThresholdChoice& threshold_choice() const { return threshold_; }
  // The radius of every orbit the planner flies about the offset point: Lemma 6 of the tracking
  // paper, turn_margin r_min (1 + v_O / v)^2 for an offset point moving at frame_speed in the
  // planning frame (capped at v), renewed at every update for the standoff orbit and the loiter
  // circle (unless follow.loiter_radius is given); the rose's turns take it at the fastest offset
  // point a loiter keeps (sigma at the band's lower edge). The one place that chooses it (a city
  // mode picks it from the visibility polygon here).
  double orbit_radius(double frame_speed) const;
  // The standoff orbit's radius at this update: follow.standoff_radius when given (the baseline's
  // constant radius), else the tick's orbit_radius.
  double standoff_radius(const FollowTick& tick) const;
  // Strategy auto's prediction: the fraction of one steady cycle of the tick's pattern (its mode
  // and shape, sampled in time) in which the camera sees the vehicle, the vehicle predicted at the
  // offset point's velocity, the bank that of a coordinated turn on the planned air path.
  double predicted_camera(const FollowTick& tick) const;

  // The next mode from sigma with the hysteresis band (exposed for tests).
  FollowMode next_mode(FollowMode current, double speed_ratio) const;

 private:
  // ds/dt of the loiter pattern (take loiter_for(tick) once per loop: it builds the shape).
  double pattern_speed(const FollowTick& tick, const LoiterShape& shape, double s) const;
  double loiter_step(const FollowTick& tick, const LoiterShape& shape, double s, double h) const;  // RK4
  double advance_arc(const FollowTick& tick, double tau) const;
  double entry_cost(const Vec2& point, const Vec2& direction, const Vec2& uav_relative, double uav_heading) const;
  void enter_sinusoid(FollowTick& tick, const Vec2& uav_relative, double uav_heading) const;
  void enter_loiter(FollowTick& tick, const Vec2& uav_relative, double uav_heading) const;
  void set_sinusoid_shape(FollowTick& tick) const;
  Vec2 standoff_relative(const FollowTick& tick, double tau) const;
  LoiterShape loiter_for(const FollowTick& tick) const;  // the loiter shape of a tick (its circle's radius)
  FollowMode choose_mode(const FollowTick& tick, FollowMode paper_mode, double& predicted) const;

  FollowParameters parameters_;  // offset_distance / offset_angle: the current offset; threshold resolved
  Uav uav_;
  ThresholdChoice threshold_;
  Vec2 wind_;
  DownwardCamera camera_;
  GuidanceGains gains_;
  LoiterShape loiter_;
  FollowTick previous_;
  bool has_previous_ = false;
};

// ---- A follow run: the planner's waypoints flown by the flight layer ------------------------------

// Scores of one run. "Desired position": the offset point where the vehicle really is plus the
// pattern of the current update; "planned path": the curve of desired positions.
struct FollowMetrics {
  double duration = 0.0;               // s
  double mean_tracking_error = 0.0;    // distance from the planned path (within +-path_window), m
  double max_tracking_error = 0.0;
  double mean_along_track_lag = 0.0;   // (desired - UAV) . desired direction of travel, m (> 0 behind)
  double max_along_track_lag = 0.0;
  double final_along_track_lag = 0.0;
  double time_sinusoid = 0.0;          // s in each mode
  double time_loiter = 0.0;
  double time_straight = 0.0;
  double time_standoff = 0.0;
  double time_capturing = 0.0;         // s holding a pattern's entry point until the UAV reached it
  int mode_switches = 0;               // changes of mode between updates
  double camera_fraction = 0.0;        // of the time the vehicle is in the camera footprint
  double mean_vehicle_distance = 0.0;  // horizontal UAV - vehicle, m
  double mean_offset_distance = 0.0;   // horizontal UAV - offset point, m
  Vec2 mean_offset_error = Vec2::Zero();  // mean of UAV - offset point: how far off-centre, m
  // With imperfect reports: time with the vehicle lost (no report younger than the timeout), the
  // episodes, and the time from a fresh report after each until the camera sees the vehicle again.
  double lost_time = 0.0;              // s
  int lost_episodes = 0;
  double mean_reacquire_time = 0.0;    // s (0 without episodes)
  double max_reacquire_time = 0.0;     // s; an episode never reacquired counts to the end
};

// A change of the offset over time: (t, distance, angle) keys, linear in between, held outside.
struct OffsetKey {
  double t = 0.0;
  double distance = 0.0;
  double angle = 0.0;
};

struct FollowRunOptions {
  FollowFlight flight;
  DownwardCamera camera;
  // The UAV's start (x, y, psi). Unset: on the planned path at the first desired position,
  // heading along it.
  std::optional<Vec3> start;
  double path_window = 10.0;  // s either side within which the tracking error looks for the path
  std::vector<OffsetKey> offset_schedule;  // empty: the parameters' fixed offset
  VehicleReportOptions reports;  // what the UAV knows of the vehicle (default: the truth at 1 Hz)
  void validate() const;
};

struct FollowRun {
  // Per flight sample (every flight.dt).
  std::vector<double> t;
  Points3 state;                      // x, y, psi
  std::vector<double> turn_rate;      // applied, rad/s
  std::vector<double> bank;           // the flown bank (FlightTrajectory::bank), rad
  Points2 vehicle;                    // vehicle position
  Points2 offset_point;
  Points2 desired;                    // desired position
  Points2 target;                     // the waypoint being flown to
  std::vector<std::uint8_t> mode;     // FollowMode of the current update
  std::vector<std::uint8_t> capturing;  // the current update holds its entry point (empty: never)
  std::vector<std::uint8_t> in_view;  // vehicle in the camera footprint
  std::vector<std::uint8_t> lost;     // the vehicle is lost (empty: never)
  std::vector<double> tracking_error; // distance from the planned path
  std::vector<double> along_track_lag;
  Points2 wind;                       // the true wind at each sample
  // Per update (1 Hz): the planner's state and the waypoint it issued at that time.
  std::vector<FollowTick> ticks;
  ThresholdChoice threshold;          // the threshold the planner used (camera_threshold)
  FollowMetrics metrics;
  // The generated waypoints and when each was issued (what a mission export needs).
  Points2 waypoints() const;
  std::vector<double> waypoint_times() const;
};

// Flies the follow planner's waypoints with the flight layer: at every update the planner sees
// the vehicle (position, velocity, heading at that time) and the UAV, and issues the next
// waypoint to a WaypointFollower that always steers along the newest leg. true_wind: what the
// vehicle flies in (constant plus optional gusts); wind_estimate: what the planner compensates.
FollowRun follow(const GroundVehicle& vehicle, const Uav& uav, const FollowParameters& parameters,
                 const Wind& true_wind, const Vec2& wind_estimate, const FollowRunOptions& options = {});

// The metrics of a run's samples (fills run.tracking_error, along_track_lag, in_view, metrics).
void score_follow_run(FollowRun& run, const Uav& uav, const DownwardCamera& camera, double path_window);

// ---- Baseline: the tracking pipeline's vector field about the vehicle ------------------------------

// The guidance vector field (74) and steering law (86) of the visibility-volume tracking paper,
// orbiting the offset point at a constant radius, as a flight-layer guidance (what vistrack.simulate
// does with a PoiPath, here with stops, turns and wind). A fair comparison with the planner: it
// knows the vehicle only from the same reports (the estimate: the newest report carried along its
// velocity) and follows the same offset schedule; lost, it orbits the estimate. The target it
// reports is the (estimated) offset point.
class OrbitFollower : public FlightGuidance {
 public:
  OrbitFollower(const VehicleReports& reports, const FollowParameters& parameters,
                const std::vector<OffsetKey>& offset_schedule, const GuidanceGains& gains, double radius);
  // The orbit's centre and its velocity at t.
  OrbitState orbit(double t) const;
  // A new radius (the planner's standoff orbit renews it at each update).
  void set_radius(double radius);
  void start(const Configuration&, double) override {}
  GuidanceCommand command(const Configuration& state, double t) const override;
  void advance(const Configuration&, double) override {}
  bool done() const override { return false; }

 private:
  const VehicleReports& reports_;
  FollowParameters parameters_;
  std::vector<OffsetKey> schedule_;
  GuidanceGains gains_;
  double radius_;
};

// The offset vector at t: the schedule's (distance, angle) at t (the parameters' when it is empty),
// the angle from north or from `vehicle_heading` as the parameters' reference says.
Vec2 scheduled_offset_vector(const std::vector<OffsetKey>& schedule, const FollowParameters& parameters,
                             double vehicle_heading, double t);

// Flies the baseline like follow() flies the planner. In the result the desired position is the
// orbit's nearest point (the tracking error is |r - R|), the mode "loiter", and there are no
// updates; the offset comes from `parameters` (the rest of it is unused). start unset: on the
// orbit ahead of the offset point, heading along the field.
FollowRun orbit_follow(const GroundVehicle& vehicle, const Uav& uav, const Control& control, double radius,
                       const FollowParameters& parameters, const Wind& true_wind, const FollowRunOptions& options = {});

// ---- The horizon city follower ------------------------------------------------------------------
//
// Following over a city by receding-horizon dynamic programming (beyond every anchor: none of the
// papers follows through buildings; docs/following.md, "The horizon follower").
//
// Each second the follower predicts the vehicle over the next H seconds (the caller's prediction:
// positions at 0, 1, ..., H s) and plans the UAV's bank commands over them by backward induction:
//  * the UAV: airspeed v and the flight layer's vehicle model (Uav::dynamics: the roll model's
//    first-order, rate-limited bank, or the Dubins vehicle's bank at once), commanding one of five
//    banks held for a second: 0, +-phi_max / 2, +-phi_max, phi_max = atan(v^2 / (g r_min));
//  * its state: the position relative to the vehicle on a square grid (spacing, +-half_width), the
//    heading on a grid of heading_step_deg, the bank at the five levels (the level nearest the bank
//    a second's command ends at);
//  * a second's reward R_j: 1 where a ray from the grid point at the flight altitude reaches the
//    vehicle's predicted position at j s (vehicle_height above the surface under it) and the camera
//    sees it at that heading and bank (camera_sees), else 0;
//  * V_H = R_H, V_j = R_j + max over commands of V_{j+1} at the command's next state, read by linear
//    interpolation in heading and position (0 off the grid), planned in the air mass: the next
//    position relative to the vehicle is the command's second (from heading 0, still air) rotated to
//    the heading, plus the known wind's way, minus the vehicle's predicted way over that second.
// The choice: the command whose one-second flight from the UAV's actual state (exact, off the grid)
// ends where V_1 (read linearly between the bank levels too) is greatest; when V_1 is 0 at every
// command's end (the vehicle out of the grid's reach, or in sight nowhere over the horizon), the
// command that ends heading most nearly for the vehicle's position a second ahead.
// A second's flight is integrated as the flight layer's discrete update does (step dt: the bank
// first, by RollModel::step, then the heading at its turn rate, then the position).
struct HorizonOptions {
  int horizon = 24;                 // s of prediction, whole seconds (one command per second)
  double spacing = 20.0;            // m, the relative-position grid's step
  double half_width = 400.0;        // m: the grid spans +-half_width about the vehicle, east and north
  double heading_step_deg = 10.0;   // the heading grid's step (must divide 360)
  double vehicle_height = 0.5;      // m above the surface under the vehicle: where the rays end
  double dt = 0.02;                 // s, the integration step within a second (the flight layer's)
  void validate() const;
};

// One second flown with a bank command held.
struct HorizonSecond {
  Vec2 position = Vec2::Zero();
  double heading = 0.0;
  double bank = 0.0;
};

struct HorizonChoice {
  double bank_command = 0.0;        // rad, positive left wing down (a left turn)
  double turn_rate = 0.0;           // rad/s, g tan(bank_command) / v: what the guidance commands
  double value = 0.0;               // the seconds in sight the programme expects over the horizon
  bool heading_for_vehicle = false; // nothing in sight from any command's end: steering for the vehicle
  HorizonSecond next;               // the UAV a second later as the planner predicts it (known wind)
};

class HorizonPlanner {
 public:
  // flight_altitude: world z of the flight (ground level + uav.altitude). Error naming the field for
  // a bad option, UAV or camera.
  HorizonPlanner(const VisibilityScene& scene, const Uav& uav, const DownwardCamera& camera, double flight_altitude,
                 const HorizonOptions& options = {});

  // The best command now. vehicle: its predicted positions at 0, 1, ..., horizon s (horizon + 1
  // points); wind: the wind the follower knows (m/s); the UAV's position, heading and bank now.
  HorizonChoice choose(const std::vector<Vec2>& vehicle, const Vec2& wind, const Vec2& position, double heading,
                       double bank) const;
  // V_1 of the programme (bank level, heading index, grid point i * n + j; i east, j north), flat.
  std::vector<float> first_values(const std::vector<Vec2>& vehicle, const Vec2& wind) const;
  // The UAV's second with `bank_command` held from the given state in `wind`.
  HorizonSecond fly_second(const Vec2& position, double heading, double bank, double bank_command,
                           const Vec2& wind) const;
  // V_1 (first_values) at a continuous state: bank and heading linear, position bilinear, 0 off the grid.
  double value_at(const std::vector<float>& values, const Vec2& relative, double heading, double bank) const;

  const std::vector<double>& banks() const { return banks_; }   // the five bank levels, rad
  std::size_t grid_side() const { return side_; }                // n: grid points per axis
  std::size_t heading_count() const { return headings_; }
  const HorizonOptions& options() const { return options_; }
  const Uav& uav() const { return uav_; }

 private:
  struct Move {  // a second from heading 0 in still air: displacement, turn, bank level after
    Vec2 shift = Vec2::Zero();
    double turn = 0.0;
    std::size_t level_after = 0;
  };
  std::vector<float> rewards(const Vec2& vehicle) const;
  void add_best_next(std::vector<float>& now, const std::vector<float>& later, const Vec2& drift) const;
  Vec2 grid_offset(std::size_t m) const;  // grid point m (i * n + j) relative to the vehicle

  VisibilityScene scene_;
  Uav uav_;
  DownwardCamera camera_;
  double altitude_;
  HorizonOptions options_;
  RollModel roll_;
  std::vector<double> banks_;
  std::size_t side_ = 0, headings_ = 0;
  double half_ = 0.0;          // m: the grid's half-width, a whole number of steps
  double heading_step_ = 0.0;  // rad
  std::vector<unsigned char> camera_table_;  // (bank level, heading, grid point): the camera sees the vehicle
  std::vector<Move> moves_;                  // (level before, command level)
};

}  // namespace vistrack
