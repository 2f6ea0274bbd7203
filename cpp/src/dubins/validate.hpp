// Range checks of the dubins area's inputs (vistrack/limits.hpp), shared by its entry points.
#pragma once

#include <algorithm>
#include <cmath>
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

// The solver's precision (dubins.hpp): coordinates at most kMaxCoordinateOverRho rho from the origin.
inline void require_dubins_scale(double max_coordinate, double rho, const std::string& field = "rho") {
  if (max_coordinate > limits::kMaxCoordinateOverRho * rho)
    fail_field(field, rho,
               "must be at least max|coordinate| / 1e6 = " + computed_text(max_coordinate / limits::kMaxCoordinateOverRho) +
                   " m: farther than 1e6 rho from the origin the solver's snapping tolerance eps = 1e-11 (1 + "
                   "max|coordinate| / rho) exceeds 1e-5 (translate the problem nearer the origin)");
}

// q0, q1 and the turn radius rho (a length) of one Dubins problem.
inline void require_dubins_problem(const Configuration& q0, const Configuration& q1, double rho) {
  require_configuration(q0, "q0");
  require_configuration(q1, "q1");
  require_length(rho, "rho");
  require_dubins_scale(std::max({std::abs(q0.x), std::abs(q0.y), std::abs(q1.x), std::abs(q1.y)}), rho);
}

}  // namespace vistrack::detail
