#include <cstdio>
#include <string>

#include "vistrack/simulate.hpp"

namespace vistrack {

std::string trajectory_csv(const SimulationResult& r) {
  std::string out =
      "t,x,y,psi,psi_d,psi_d_rate,radial_error,heading_error,u_psi,u_psi_unsaturated,poi_x,poi_y,poi_z,orbit_radius,bank";
  const bool with_visibility = !r.visible.empty();
  out += with_visibility ? ",visible\n" : "\n";
  char line[512];
  for (std::size_t k = 0; k < r.t.size(); ++k) {
    const auto i = static_cast<Eigen::Index>(k);
    std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g",
                  r.t[k], r.state(i, 0), r.state(i, 1), r.state(i, 2), r.desired_heading[k], r.desired_heading_rate[k],
                  r.radial_error[k], r.heading_error[k], r.control[k], r.control_unsaturated[k], r.poi(i, 0),
                  r.poi(i, 1), r.poi(i, 2), r.orbit_radius[k], r.bank[k]);
    out += line;
    if (with_visibility) out += r.visible[k] ? ",1" : ",0";
    out += '\n';
  }
  return out;
}

}  // namespace vistrack
