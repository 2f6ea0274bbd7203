// Validation of the Dubins vehicle (dubins_parameters.hpp).
#include "vistrack/dubins_parameters.hpp"

#include "vistrack/limits.hpp"

namespace vistrack {

void Uav::validate() const {
  require_speed(speed, "uav.speed");
  require_length(min_turn_radius, "uav.min_turn_radius");
  require_coordinate(altitude, "uav.altitude");
  require_in_range(roll_time_constant, limits::kMinRollTimeConstant, limits::kMaxRollTimeConstant, "s",
                   "uav.roll_time_constant");
  require_in_range(max_roll_rate_deg_s, limits::kMinRollRate, limits::kMaxRollRate, "deg/s",
                   "uav.max_roll_rate_deg_s");
}

}  // namespace vistrack
