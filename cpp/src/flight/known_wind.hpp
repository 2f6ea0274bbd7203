// The mean wind a wind-aware law is told (LineFeedback::set_wind, L1Line::set_wind), checked once.
#pragma once

#include "vistrack/error.hpp"
#include "vistrack/geometry.hpp"

namespace vistrack::detail {

// The wind itself after checking it: finite and slower than the airspeed (a law cannot steer a
// course over the ground in a wind at or above it).
inline Vec2 known_wind(const Vec2& mean_wind, double airspeed) {
  require_finite(mean_wind.x(), "wind.east");
  require_finite(mean_wind.y(), "wind.north");
  if (!(mean_wind.norm() < airspeed))
    fail_field("wind", to_text(mean_wind.norm()), "the wind-aware law needs a wind below the airspeed");
  return mean_wind;
}

}  // namespace vistrack::detail
