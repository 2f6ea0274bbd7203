// The Dubins vehicle every planner flies, with its defaults.
// Each validate() throws Error naming the field and its allowed range (vistrack/limits.hpp).
#pragma once

namespace vistrack {

// The Dubins vehicle (1): constant speed v, minimum turn radius r_min = v / u_psi_max, altitude.
struct Uav {
  double speed = 20.0;             // v, m/s
  double min_turn_radius = 50.0;   // r_min, m
  double altitude = 300.0;         // h_UAV: world z of the flight plane, m (height above a ground at z = 0)
  void validate() const;           // throws Error naming the field
};

}  // namespace vistrack
