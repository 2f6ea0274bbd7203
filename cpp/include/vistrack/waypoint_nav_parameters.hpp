// Dubins waypoint navigation's parameters, with their defaults.
// Each validate() throws Error naming the field and its allowed range (vistrack/limits.hpp).
#pragma once

#include <cstdint>
#include <optional>

#include "vistrack/dubins_parameters.hpp"
#include "vistrack/flight_parameters.hpp"

namespace vistrack {

// Fuel per unit length (1): w_a on arcs, w_s on straights; w_a = w_s = 1 is the shortest path (2).
struct FuelWeights {
  double arc = 1.0;       // w_a
  double straight = 1.0;  // w_s
  void validate() const;
};

// DWN, the paper's WN (a waypoint is done inside R_WP), and beyond the paper WN as ArduPlane flies
// it (also done once past the line through the waypoint perpendicular to the leg, and inside a
// turn distance that anticipates the turn: WaypointFollower::set_passed_line).
enum class NavigationMethod : std::uint8_t { Dubins = 0, Classical = 1, PassedLine = 2 };
template <>
struct EnumNames<NavigationMethod> {
  static constexpr const char* field = "method";
  static constexpr EnumName<NavigationMethod> names[] = {{"dwn", NavigationMethod::Dubins},
      {"wn", NavigationMethod::Classical}, {"wn_passed_line", NavigationMethod::PassedLine}};
};

// How DWN flies its plan (beyond the paper for "path"): the paper's leg law to the turning point
// T_n, the turns left to the law's saturation ("paper"), or the whole planned horizon path followed
// in closed loop with the roll anticipated (DubinsWaypointGuidance::set_path_following: "path").
// "auto": "paper" on the paper's instant-turn vehicle (dynamics dubins), "path" on a vehicle that
// banks (the roll model; vistrack.fdm's aircraft).
enum class DwnTracking : std::uint8_t { Auto = 0, Paper = 1, Path = 2 };
template <>
struct EnumNames<DwnTracking> {
  static constexpr const char* field = "dwn_tracking";
  static constexpr EnumName<DwnTracking> names[] = {{"auto", DwnTracking::Auto}, {"paper", DwnTracking::Paper},
                                                    {"path", DwnTracking::Path}};
};

// One navigation flight; the defaults are the paper's section 3 (R 0.7, v 0.8, dt 0.02, and the
// gains g 0.1, h 5.25 of LineFeedbackGains).
struct WaypointNavOptions {
  NavigationMethod method = NavigationMethod::Dubins;
  double turn_radius = 0.7;   // R: the vehicle's minimum turn radius and DWN's turning circles
  double speed = 0.8;         // v
  double dt = 0.02;           // the law's step (and the discrete flight's)
  LineFeedbackGains gains;
  std::optional<double> waypoint_radius;  // WN's R_WP; unset: R. DWN has none (set: an Error)
  FuelWeights weights;
  FlightIntegration integration = FlightIntegration::Discrete;
  std::optional<double> max_time;  // unset: 3 (route length + 2 pi R per waypoint) / v
  // The vehicle model (Uav::dynamics): the paper's instant turn, or the roll model with these
  // parameters, which needs the route in metres and seconds (it uses g).
  DynamicsModel dynamics = DynamicsModel::Dubins;
  // The law that flies each leg (to DWN's turning point, or WN's line to its waypoint): the
  // paper's law (5) with `gains`, or L1 line tracking with `l1`.
  LegGuidance guidance = LegGuidance::LineFeedback;
  L1Gains l1;
  // Beyond the paper: the leg law knows the mean wind (the wind's constant part, not its gusts)
  // and steers the course over the ground (L1Line::set_wind, LineFeedback::set_wind).
  // For DWN also: every turning point planned in the air mass of that wind
  // (air_mass_turning_point).
  bool wind_aware = false;
  // DWN: re-plan the active turning point every replan_interval seconds (section 2.1's option);
  // 0, the paper's flights: only when it becomes unreachable. WN methods: must be 0.
  double replan_interval = 0.0;
  // DWN: how the plan is flown (see DwnTracking); WN methods: "auto" or "paper" only.
  DwnTracking dwn_tracking = DwnTracking::Auto;
  // DWN "path": the follower's gains; anticipation unset: the roll model's lag (roll_lag()).
  PathFollowingGains path_gains;
  std::optional<double> path_anticipation;
  double roll_time_constant = Uav{}.roll_time_constant;     // tau, s
  double max_roll_rate_deg_s = Uav{}.max_roll_rate_deg_s;   // p_max, deg/s
  void validate() const;
  // The vehicle flown: speed v, r_min = R, the model and its roll parameters.
  Uav vehicle() const;
  // The tracking "auto" resolves to for this vehicle.
  DwnTracking resolved_tracking() const;
  // The roll model's lag as a lead time (s): the heading lost to the bank's response to a step
  // command 0 -> phi_max = atan(v^2 / (g R)), integral of (1 - phi(t) / phi_max) dt: tau without
  // the rate limit, more with it; 0 for dubins (parameters.cpp).
  double roll_lag() const;
};

}  // namespace vistrack
