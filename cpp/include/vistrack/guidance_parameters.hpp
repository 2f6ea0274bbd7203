// The guidance's control parameters, with their defaults.
// Each validate() throws Error naming the field and its allowed range (vistrack/limits.hpp).
#pragma once

#include "vistrack/geometry.hpp"

namespace vistrack {

// Guidance (section V): circulation beta, heading gain k_psi, direction of travel.
struct Control {
  double beta = 0.025;
  double k_psi = 20.0;
  Circulation direction = Circulation::CounterClockwise;
  void validate() const;
};

}  // namespace vistrack
