// Validation of the closed loop's integration options (simulate_parameters.hpp).
#include "vistrack/simulate_parameters.hpp"

#include "vistrack/limits.hpp"

namespace vistrack {

void SimulationOptions::validate() const {
  require_tolerances(rtol, atol, "simulation.");
  require_in_range(max_step, 1e-9, 1e9, "s", "simulation.max_step");
  require_in_range(output_step, 1e-6, 1e9, "s", "simulation.output_step");
}

}  // namespace vistrack
