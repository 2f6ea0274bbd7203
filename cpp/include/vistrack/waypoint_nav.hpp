// Dubins waypoint navigation (DWN) against classical waypoint navigation (WN), after Silverberg &
// Xu, "Dubins Waypoint Navigation of Small-Class Unmanned Aerial Vehicles" (OJOp 2019; seeds/
// dubins_waypoint_navigation.txt). Both fly on the flight layer (flight.hpp) with the paper's
// feedback law (5); they differ in what the law steers to:
//  * WN: the active waypoint, switching to the next inside the waypoint radius R_WP
//    (flight.hpp's WaypointFollower);
//  * DWN: the turning point T_n of the 3-point horizon (current pose C, W_n, W_{n+1}), switching
//    when T_n enters the reachability zone; the last waypoint is flown to directly. Beyond the
//    paper, with the mean wind known, T_n is planned in the air mass (air_mass_turning_point), and
//    T_n may be re-planned more often (section 2.1's option, set_replan_interval).
// Every flight ends past the line through the last waypoint perpendicular to the last leg.
//
// The horizon path (section 2.4, Figure 6): an arc on the vehicle's turning circle (direction d1),
// the tangent straight to the circle of radius R through W_n (centre W_n + R (cos theta, sin theta),
// direction d2), ending at T_n; the arc on that circle from T_n through W_n to the exit tangent;
// straight to W_{n+1}. Fuel (1) F = w_a L_a + w_s L_s, length (2) for w_a = w_s = 1, minimised
// over theta for each of the four cases d1-d2. The paper fits theta off-line; we solve it.
//
// How: with h the heading at W_n (h = theta - d2 pi/2), the path up to W_n is the Dubins CSC word
// (d1, S, d2) from C to (W_n, h) (the kernel of dubins.hpp), the rest an arc and a tangent to a
// point. F(h) is smooth between breakpoints where a tangent stops existing (LSR/RSL circles
// overlapping, W_{n+1} inside the circle) or an arc wraps through 0 (the path gains or loses a
// loop: T_n = W_n, exit = W_n, no first arc). Its derivative is closed-form:
//   dF/dh = (w_a - w_s) [-(d1 - d2) sin(q) / p - d2 sin(a) / s2] + w_s d2 (cos a - cos q),
// q the arc T_n -> W_n, a the arc W_n -> exit, p and s2 the two straights (in units of R). For
// w_a = w_s it is d2 (cos a - cos q): the optimum puts W_n in the middle of its arc, and
// |dF/dh| <= 2 R, which bounds F between samples. The solver samples h, brackets the breakpoints
// (wraps by a root of the wrapped arc, feasibility edges by bisection) and the sign changes of
// dF/dh, and refines them (Brent) to 1e-12 rad; with unit weights, brackets whose Lipschitz lower
// bound cannot beat the best are skipped.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>
#include <variant>

#include "vistrack/dubins.hpp"
#include "vistrack/flight.hpp"
#include "vistrack/geometry.hpp"
#include "vistrack/waypoint_nav_parameters.hpp"

namespace vistrack {

// Turn directions (first arc at C, arc around W_n), in the paper's order.
enum class TurnCase : std::uint8_t { CcwCcw = 0, CcwCw = 1, CwCcw = 2, CwCw = 3 };
constexpr int kTurnCaseCount = 4;
template <>
struct EnumNames<TurnCase> {
  static constexpr const char* field = "case";
  static constexpr EnumName<TurnCase> names[] = {{"ccw-ccw", TurnCase::CcwCcw}, {"ccw-cw", TurnCase::CcwCw},
      {"cw-ccw", TurnCase::CwCcw}, {"cw-cw", TurnCase::CwCw}};
};

// The horizon path of one case at one orientation theta. Lengths are arc lengths (length units).
struct HorizonPath {
  bool feasible = false;       // false: a tangent does not exist at this theta
  TurnCase turn_case = TurnCase::CcwCcw;
  double theta = 0.0;          // in [0, 2 pi): centre of the circle around W_n at W_n + R e(theta)
  Vec2 point = Vec2::Zero();   // T_n: end of the first straight
  Vec2 line_start = Vec2::Zero();  // start of the first straight (end of the first arc)
  Vec2 exit_point = Vec2::Zero();  // where the path leaves the circle around W_n
  Vec2 circle_center = Vec2::Zero();
  double heading_at_waypoint = 0.0;  // h at W_n
  double first_arc = 0.0, first_straight = 0.0;
  double arc_to_waypoint = 0.0, arc_from_waypoint = 0.0, last_straight = 0.0;
  double arcs() const { return first_arc + arc_to_waypoint + arc_from_waypoint; }
  double straights() const { return first_straight + last_straight; }
  double length = 0.0;         // weighted: w_a arcs() + w_s straights() (infinity when infeasible)
};

// The horizon path of case c at theta (from pose C through W_n = w_next to W_{n+1} = w_after).
HorizonPath horizon_path(const Configuration& pose, const Vec2& w_next, const Vec2& w_after, double turn_radius,
                         TurnCase c, double theta, const FuelWeights& weights = {});

// The optimal turning point: the best horizon path over theta and the four cases.
struct TurningPoint : HorizonPath {
  std::array<double, kTurnCaseCount> case_lengths{};  // best weighted length of each case (inf: none)
  std::array<double, kTurnCaseCount> case_thetas{};
  int evaluations = 0;         // F(h) evaluations spent
};
TurningPoint turning_point(const Configuration& pose, const Vec2& w_next, const Vec2& w_after, double turn_radius,
                           const FuelWeights& weights = {});

// The reachability zone (section 2.5, Figure 7), fixed to the vehicle: its two turning circles
// (open disks of radius R at p +- R n) closed at the rear by their common tangent (the box
// -R <= x_h <= 0, |y_h| <= R in the heading frame). Returns a continuous function of the point that
// is <= 0 exactly when the point is in the zone (unreachable): min(d_left - R + eps R,
// d_right - R + eps R, box distance), eps = 1e-9 keeps points on the turning circles ahead reachable.
double reachability(const Configuration& pose, const Vec2& point, double turn_radius);
inline bool unreachable(const Configuration& pose, const Vec2& point, double turn_radius) {
  return reachability(pose, point, turn_radius) <= 0.0;
}

// One turning point chosen during a DWN flight (the future mission's waypoints).
struct TurningPointRecord {
  double t = 0.0;               // when it was planned
  int waypoint = 0;             // n: the waypoint index it belongs to
  Configuration pose;           // the vehicle's pose C when planned
  HorizonPath path;             // the horizon path; for the last waypoint (flown directly) only
                                // point = W_last, line_start = C, feasible, length = |W_last - C|
  bool direct = false;          // the last waypoint, flown to directly
  // Planned in the air mass (wind-aware DWN): the mean wind used (zero: planned in still air)
  // and the turning point as a point of the air mass at time t. That point drifts with the wind,
  // air_point + wind (t' - t), and is on the ground turning point `path.point` when the vehicle
  // is planned to be there; the reachability zone switches on the drifting point.
  Vec2 wind = Vec2::Zero();
  Vec2 air_point = Vec2::Zero();
};

// The turning point planned in the air mass (beyond the paper; the follow planner's wind
// compensation, follow.hpp): in the frame moving with the mean wind w the vehicle is a wind-free
// Dubins vehicle of airspeed v and a ground waypoint W moves at -w, so a path that meets W_n at
// time tau_n after `pose` was planned meets, in the air, the point W_n - w tau_n. The horizon
// (section 2.4) is solved there for W_n - w tau_n and W_{n+1} - w tau_{n+1}, the times taken from
// the path's own arc lengths (tau = s / v) by a fixed-point iteration (a contraction of ratio
// about |w| / v; at most 100 rounds, to 1e-12 R / v). The path returned is on the ground: each
// point of the air path is moved by w times the time the vehicle is planned to reach it (point:
// at tau_T, line_start: at the end of the first arc, circle_center: at tau_n, exit_point). With
// w = 0 it is turning_point(). `air_path` (if given) receives the path in the air frame of
// `pose` (the frame moving with w that coincides with the ground when `pose` is planned).
// The horizon path as PathFollower pieces from `pose` (its first arc, the straight to T_n, the
// arc through W_n, the straight to W_{n+1}; empty pieces dropped), then a straight of `extension`
// past W_{n+1}. Each piece starts where the one before ends.
std::vector<PathPiece> horizon_pieces(const Configuration& pose, const HorizonPath& path, double turn_radius,
                                      double extension);

TurningPoint air_mass_turning_point(const Configuration& pose, const Vec2& w_next, const Vec2& w_after,
                                    double turn_radius, double speed, const Vec2& wind,
                                    const FuelWeights& weights = {}, HorizonPath* air_path = nullptr);

// DWN as a flight guidance: the law (5) to T_n along the first straight; at the reachability
// switch, the next turning point from the current pose. Planned in the air mass (set_wind), the
// law flies the air frame's line from the vehicle's position in that frame (p - w (t - t_plan)),
// where the vehicle is wind-free (the law without wind), and the reachability zone switches
// there too; the last waypoint, a ground point, is flown by the law as given (wind-aware or not).
class DubinsWaypointGuidance : public FlightGuidance {
 public:
  DubinsWaypointGuidance(const LineFeedback& law, const std::vector<Vec2>& waypoints, double turn_radius,
                         const FuelWeights& weights = {});
  // The same with each leg to a turning point flown by L1 line tracking instead of the law (5).
  DubinsWaypointGuidance(const L1Line& law, const std::vector<Vec2>& waypoints, double turn_radius,
                         const FuelWeights& weights = {});

  void start(const Configuration& state, double t) override;
  GuidanceCommand command(const Configuration& state, double t) const override;
  void advance(const Configuration& state, double t) override;
  bool done() const override { return done_; }
  double switching_function(const Configuration& state, double t) const override;

  // Wind-aware (beyond the paper): plan every turning point in the air mass of the known mean
  // wind (air_mass_turning_point) at airspeed `speed`; switching on the turning point drifting
  // with it. Zero wind: the paper's planning.
  void set_wind(const Vec2& mean_wind, double speed);
  // The paper's option (section 2.1: "the trajectory may be updated more frequently than when the
  // turning point is updated (like under the conditions of high winds)"): every `interval`
  // seconds (> 0) the turning point of the active waypoint is planned again from the current
  // pose; 0 (the default) plans only at the reachability switch. Not within 0.3 R of the turning point
  // (there a step's heading error can make the best path a loop), nor on the direct flight to the
  // last waypoint (its line ends at the waypoint).
  void set_replan_interval(double interval);
  double replan_interval() const { return replan_interval_; }
  // Beyond the paper, for vehicles that bank (the roll model, a 6-DOF aircraft): each planned
  // horizon path (first arc, straight to T_n, the arc through W_n, the straight to W_{n+1}) is
  // flown by PathFollower (curvature feed-forward read gains.anticipation seconds ahead, so the
  // roll starts before the arc; cross-track and heading feedback), in the air frame when
  // wind-aware, instead of the leg law to T_n alone: the roll lag is corrected rather than
  // accumulated. The switch and the re-planning stay the paper's; the last waypoint is flown along
  // the tail of the last plan (its straight to W_last, extended 2 R past it). Unset: the paper's
  // law to T_n (the default).
  // speed: the vehicle's airspeed v (the feed-forward's v kappa, the anticipation's lead v t).
  void set_path_following(const PathFollowingGains& gains, double speed);
  bool path_following() const { return path_gains_.has_value(); }

  const std::vector<TurningPointRecord>& turning_points() const { return log_; }
  std::size_t active() const { return active_; }
  // The flight ends once the vehicle is past the line through the last waypoint perpendicular to
  // the route's last leg (from the previous waypoint, or the start for a single one).
  double past_finish_line(const Vec2& p) const;
  double next_change_time(double t) const override;

 private:
  void plan(const Configuration& state, double t);
  void follow(const Configuration& state, double t, const HorizonPath& air_path);
  void check() const;
  Vec2 drifting_target(double t) const { return air_target_ + wind_ * (t - planned_at_); }

  std::variant<LineFeedback, L1Line> law_;
  std::vector<Vec2> waypoints_;
  double turn_radius_;
  FuelWeights weights_;
  std::size_t active_ = 0;
  Vec2 target_ = Vec2::Zero(), line_start_ = Vec2::Zero();
  bool done_ = false;
  std::vector<TurningPointRecord> log_;
  Vec2 wind_ = Vec2::Zero();
  double airspeed_ = 1.0;
  double replan_interval_ = 0.0;
  double planned_at_ = 0.0;     // when the active turning point was planned
  Vec2 air_target_ = Vec2::Zero();  // its point in the air mass at planned_at_
  Vec2 air_line_start_ = Vec2::Zero();
  std::variant<LineFeedback, L1Line> air_law_;  // law_ without wind: the one flown in the air frame
  std::optional<PathFollowingGains> path_gains_;
  double path_speed_ = 1.0;
  std::optional<PathFollower> follower_;  // the active plan's path (path following)
  double follower_planned_at_ = 0.0;      // its air frame: the ground at that time
  Configuration follower_frame(const Configuration& state, double t) const {
    const Vec2 drift = wind_ * (t - follower_planned_at_);
    return {state.x - drift.x(), state.y - drift.y(), state.psi};
  }
  bool air_frame_ = false;  // the active line is flown in the air frame
  Vec2 leg_start_ = Vec2::Zero();   // the start of the route's last leg (finish line)
};

// ---- Metrics ----------------------------------------------------------------------------------

struct NavigationMetrics {
  // Closest approach of the flown path to each waypoint; for the last one, the distance from it
  // where the path crosses its finish line (through it, perpendicular to the last leg: where the
  // flight ends), or the closest approach when the path never crosses it (then not reached).
  std::vector<double> miss_distances;
  std::vector<double> closest_times;   // time of that closest approach (the sample starting its segment; the crossing), s
  std::vector<double> overshoots;      // per waypoint: the largest distance outside the turn there
  std::vector<std::uint8_t> reached;   // the guidance got past the waypoint (in order) in time
  bool all_reached = false;
  double overshoot = 0.0;    // largest distance from the planned legs on the outside of their turns
  double undershoot = 0.0;   // largest distance on the inside (cutting corners)
  // Loops around the active waypoint: the bearing from the vehicle to it, accumulated while it is
  // the target, and each full turn counted in either direction (one loop each way counts two).
  int swirls = 0;
  double path_length = 0.0;  // ground track
  double duration = 0.0;     // flight time
  double fuel = 0.0;         // sum of v dt (w_s + (w_a - w_s) |r| / (v / R)): w_a on full turns, w_s straight
};

// Metrics of a flight along `legs` = start position followed by the waypoints. The trajectory's
// target_index is the index into `waypoints` (0 = first waypoint after the start).
NavigationMetrics navigation_metrics(const FlightTrajectory& trajectory, const Vec2& start,
                                     const std::vector<Vec2>& waypoints, double speed, double turn_radius,
                                     const FuelWeights& weights = {});

// ---- One navigation flight ----------------------------------------------------------------------

struct NavigationResult {
  FlightTrajectory trajectory;
  NavigationMetrics metrics;
  std::vector<TurningPointRecord> turning_points;  // DWN only
  NavigationMethod method = NavigationMethod::Dubins;
  double waypoint_radius = 0.0;                    // WN only
  double max_time = 0.0;                           // the limit used
};

// Flies `waypoints` (all of them, in order) from `start`. Validates everything (errors name the
// field): at least one waypoint, none within 1e-9 R of the previous one, finite, R > 0, dt > 0
// with v dt / R <= pi/2, wind below the airspeed.
NavigationResult navigate(const std::vector<Vec2>& waypoints, const Configuration& start,
                          const WaypointNavOptions& options, const Wind& wind = {});

// The guidance navigate() flies, for any vehicle that flies a FlightGuidance (the 6-DOF aircraft
// too): DWN (DubinsWaypointGuidance) or WN (WaypointFollower, R_WP = waypoint_radius or R; past-line
// switching for wn_passed_line), each leg by the law (5) (its sign smoothed when the integration is
// continuous) or L1; with wind_aware the leg law, and DWN's planning, know `wind`'s constant part;
// DWN re-plans and follows its paths as the options say. Every flight ends past the last
// waypoint's line. Validates as navigate() does.
std::unique_ptr<FlightGuidance> navigation_guidance(const std::vector<Vec2>& waypoints, const Configuration& start,
                                                    const WaypointNavOptions& options, const Wind& wind = {});
// navigate()'s time limit: options.max_time, else 3 (route length from start + 2 pi R per waypoint) / v.
// Validates as navigate() does.
double navigation_time_limit(const std::vector<Vec2>& waypoints, const Configuration& start,
                             const WaypointNavOptions& options);

}  // namespace vistrack
