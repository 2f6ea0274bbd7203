// Range checks of the dubins area's inputs (vistrack/limits.hpp), shared by its entry points.
#pragma once

#include <string>

#include "vistrack/dubins.hpp"
#include "vistrack/limits.hpp"

namespace vistrack::detail {

// x, y within the coordinate range, psi within the angle range.
inline void require_configuration(const Configuration& q, const std::string& name) {
  require_coordinate(q.x, name + ".x");
  require_coordinate(q.y, name + ".y");
  require_angle(q.psi, name + ".psi");
}

// q0, q1 and the turn radius rho (a length) of one Dubins problem.
inline void require_dubins_problem(const Configuration& q0, const Configuration& q1, double rho) {
  require_configuration(q0, "q0");
  require_configuration(q1, "q1");
  require_length(rho, "rho");
}

}  // namespace vistrack::detail
