// Validation of waypoint_nav's parameter structs (waypoint_nav_parameters.hpp).
#include <algorithm>
#include <cmath>

#include "vistrack/error.hpp"
#include "vistrack/geometry.hpp"
#include "vistrack/limits.hpp"
#include "vistrack/waypoint_nav_parameters.hpp"

namespace vistrack {

void FuelWeights::validate() const {
  require_positive(arc, "weights.arc");
  require_positive(straight, "weights.straight");
}

void WaypointNavOptions::validate() const {
  require_length(turn_radius, "turn_radius");
  require_speed(speed, "speed");
  require_positive(dt, "dt");
  const double psi_max = speed * dt / turn_radius;
  if (psi_max > 0.5 * kPi)
    detail::fail_field("dt", dt, "psi_max = v dt / R = " + detail::computed_text(psi_max) + " rad exceeds pi/2");
  gains.validate();
  weights.validate();
  if (waypoint_radius) {
    if (method == NavigationMethod::Dubins)
      detail::fail_field("waypoint_radius", *waypoint_radius, "DWN has no waypoint radius (it is for the WN methods)");
    require_non_negative(*waypoint_radius, "waypoint_radius");
  }
  if (max_time) require_positive(*max_time, "max_time");
  require_non_negative(replan_interval, "replan_interval");
  if (replan_interval > 0.0 && method != NavigationMethod::Dubins)
    detail::fail_field("replan_interval", replan_interval, "only DWN re-plans (it is for method 'dwn')");
  l1.validate();
  path_gains.validate();
  if (path_anticipation) require_in_range(*path_anticipation, 0.0, limits::kMaxRollTimeConstant, "s", "path_anticipation");
  if (dwn_tracking == DwnTracking::Path && method != NavigationMethod::Dubins)
    detail::fail_field("dwn_tracking", "path", "only DWN follows a planned path (it is for method 'dwn')");
  require_in_range(roll_time_constant, limits::kMinRollTimeConstant, limits::kMaxRollTimeConstant, "s",
                   "roll_time_constant");
  require_in_range(max_roll_rate_deg_s, limits::kMinRollRate, limits::kMaxRollRate, "deg/s", "max_roll_rate_deg_s");
}

Uav WaypointNavOptions::vehicle() const {
  Uav uav;
  uav.speed = speed;
  uav.min_turn_radius = turn_radius;
  uav.dynamics = dynamics;
  uav.roll_time_constant = roll_time_constant;
  uav.max_roll_rate_deg_s = max_roll_rate_deg_s;
  return uav;
}

DwnTracking WaypointNavOptions::resolved_tracking() const {
  if (dwn_tracking != DwnTracking::Auto) return dwn_tracking;
  return method == NavigationMethod::Dubins && dynamics != DynamicsModel::Dubins ? DwnTracking::Path
                                                                                : DwnTracking::Paper;
}

double WaypointNavOptions::roll_lag() const {
  if (dynamics == DynamicsModel::Dubins) return 0.0;
  const double max_bank = std::atan(speed * speed / (kStandardGravity * turn_radius));
  const double rate = max_roll_rate_deg_s * kPi / 180.0;
  const double tau = roll_time_constant;
  // The heading lag of the bank's response to a step command 0 -> phi_max, the turn rate taken
  // linear in the bank: D = integral of (1 - phi(t) / phi_max) dt. Without the rate limit
  // (phi_max <= p_max tau) the exponential gives tau; with it, a ramp at p_max to phi_1 = phi_max -
  // p_max tau over T = phi_1 / p_max, then the exponential from there.
  if (max_bank <= rate * tau) return tau;
  const double ramp_end = max_bank - rate * tau, ramp_time = ramp_end / rate;
  return ramp_time * (1.0 - 0.5 * ramp_end / max_bank) + rate * tau * tau / max_bank;
}

}  // namespace vistrack
