// The line-of-sight sensor that bounds a visibility volume (section III.D), with its defaults.
// Each validate() throws Error naming the field and its allowed range (vistrack/limits.hpp).
#pragma once

#include <optional>
#include <string>
#include <utility>

namespace vistrack {

// The angular step of the VV ray grid (degrees), the default of Planning and of visibility_volume.
inline constexpr double kDefaultResolutionDeg = 1.0;

// The line-of-sight sensor (section III.D).
struct Sensor {
  double d_max = 400.0;                                 // maximum viewing distance, m
  std::optional<std::pair<double, double>> altitude_band;  // feasible airspace (h_lo, h_hi), m
  // The one check of d_max and the band; `prefix` is how the caller's input names them.
  void validate(const std::string& prefix = "sensor.") const;
};

}  // namespace vistrack
