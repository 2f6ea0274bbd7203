// The loiter planners' parameters, with their defaults.
// Each validate() throws Error naming the field and its allowed range (vistrack/limits.hpp).
#pragma once

#include "vistrack/dubins_parameters.hpp"

namespace vistrack {

// Wilhelm, Clem, Eberhart, "Direct Entry Minimal Path UAV Loitering Path Planning" (2017),
// section 4.1: Raven RQ-11B, turn radius 46 m at 12 m/s, AOI radius = turn radius, one loiter.

struct LoiterParameters {
  double turn_radius = 46.0;  // r, m: turns outside the loiter (minimum turn radius)
  double speed = 12.0;        // v, m/s (constant airspeed)
  double aoi_radius = 46.0;   // R, m: the loiter circle around each AOI centre (POI); R >= r
  int turns = 1;              // full loiters flown around each AOI (at least 1)
  void validate() const;      // throws Error naming the field
};

// The camera of section 2.2: a circular (conic) field of view, full angle fov_deg, on a one-axis
// (roll) gimbal of +-max_gimbal_deg. altitude: height above the AOIs' ground plane. 61 m is the
// height at which the paper's nadir footprint is 6,638 m^2 (pi (61 tan 37 deg)^2 = 6,637.9 m^2).
// levelled: the gimbal angle is measured from the vertical, as the paper states (a gimbal that
// also takes out the bank); false: a roll gimbal under the banked body, whose belly faces out of
// every turn, so the axis tilts by gimbal - bank (see camera_tilt in loiter.hpp).
struct LoiterCamera {
  double fov_deg = 74.0;
  double max_gimbal_deg = 25.0;
  double altitude = 61.0;
  bool levelled = true;
  void validate() const;
};

// Section 4.1's coverage rule: an AOI counts as covered at a time step when at least `threshold`
// of its disk lies in the footprint; time steps dt apart (the paper samples at 1 s).
struct LoiterCoverageOptions {
  double threshold = 0.75;
  double dt = 1.0;          // s
  double gravity = kStandardGravity; // m/s^2, for the bank angle of a coordinated turn
  void validate() const;
};

}  // namespace vistrack
