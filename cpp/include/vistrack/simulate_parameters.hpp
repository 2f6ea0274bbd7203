// The closed-loop integration's tolerances and output spacing, with their defaults.
// Each validate() throws Error naming the field and its allowed range (vistrack/limits.hpp).
#pragma once

namespace vistrack {

// Closed-loop integration (section VI).
struct SimulationOptions {
  double rtol = 1e-6;
  double atol = 1e-8;
  double max_step = 1.0;      // s
  double output_step = 0.1;   // s between output samples
  void validate() const;
};

}  // namespace vistrack
