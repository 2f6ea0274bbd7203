// Validation of the guidance's control parameters (guidance_parameters.hpp).
#include "vistrack/guidance_parameters.hpp"

#include "vistrack/limits.hpp"

namespace vistrack {

void Control::validate() const {
  require_beta(beta, "control.beta");
  require_heading_gain(k_psi, "control.k_psi");
}

}  // namespace vistrack
