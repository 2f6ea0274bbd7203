// The Dubins vehicle every planner flies, with its defaults.
// Each validate() throws Error naming the field and its allowed range (vistrack/limits.hpp).
#pragma once

#include <cstdint>

#include "vistrack/error.hpp"

namespace vistrack {

// Standard gravity, m/s^2: the bank of a coordinated turn, the roll model.
constexpr double kStandardGravity = 9.80665;

// The vehicle model the flight layer integrates (flight.hpp), one switch for every planner.
//  * Dubins: the turn rate follows the guidance's command at once (the papers' vehicle).
//  * Roll: a reduced-order fixed wing (Beard & McLain, Small Unmanned Aircraft, 2012, ch. 9, the
//    guidance model with a first-order roll loop): the bank phi is a state,
//      phi_c = atan(v r_c / g)  (the coordinated bank of the commanded turn rate r_c),
//      phi_dot = clamp((phi_c - phi) / tau, -p_max, p_max),   |phi| <= phi_max = atan(v^2 / (g R)),
//      psi_dot = g tan(phi) / v.
//    g is in m/s^2: SI flights only.
enum class DynamicsModel : std::uint8_t { Dubins = 0, Roll = 1 };

template <>
struct EnumNames<DynamicsModel> {
  static constexpr const char* field = "uav.dynamics";
  static constexpr EnumName<DynamicsModel> names[] = {{"dubins", DynamicsModel::Dubins},
                                                      {"roll", DynamicsModel::Roll}};
};

// The vehicle (1): constant speed v, minimum turn radius r_min = v / u_psi_max, altitude, and how
// it turns. Roll defaults typical of small fixed-wing UAVs: ArduPlane's roll-loop time constant
// RLL2SRV_TCONST is 0.5 s (PX4's FW_R_TC 0.4 s); PX4 limits the roll rate to FW_R_RMAX = 70 deg/s.
struct Uav {
  double speed = 20.0;             // v, m/s
  double min_turn_radius = 50.0;   // r_min, m
  double altitude = 300.0;         // h_UAV: world z of the flight plane, m (height above a ground at z = 0)
  DynamicsModel dynamics = DynamicsModel::Dubins;
  double roll_time_constant = 0.5;     // tau, s (roll model)
  double max_roll_rate_deg_s = 70.0;   // p_max, deg/s (roll model)
  void validate() const;           // throws Error naming the field
};

}  // namespace vistrack
