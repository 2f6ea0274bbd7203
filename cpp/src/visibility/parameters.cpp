// Validation of the line-of-sight sensor (visibility_parameters.hpp).
#include "vistrack/visibility_parameters.hpp"

#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"

namespace vistrack {

void Sensor::validate(const std::string& prefix) const {
  require_length(d_max, prefix + "d_max");
  if (altitude_band) {
    require_coordinate(altitude_band->first, prefix + "altitude_band[0]");
    require_coordinate(altitude_band->second, prefix + "altitude_band[1]");
    if (!(altitude_band->first < altitude_band->second))
      detail::fail_field(prefix + "altitude_band",
                         detail::to_text(altitude_band->first) + ", " + detail::to_text(altitude_band->second),
                         "the lower altitude must be below the upper one");
  }
}

}  // namespace vistrack
