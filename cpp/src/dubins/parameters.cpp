// Validation of the Dubins vehicle (dubins_parameters.hpp).
#include "vistrack/dubins_parameters.hpp"

#include "vistrack/limits.hpp"

namespace vistrack {

void Uav::validate() const {
  require_speed(speed, "uav.speed");
  require_length(min_turn_radius, "uav.min_turn_radius");
  require_coordinate(altitude, "uav.altitude");
}

}  // namespace vistrack
