// Integration of a Dubins path's segments, without snapping to the goal: DubinsPath::at uses
// it, and tests use it to check that the segments really end at the goal.
#pragma once

#include "vistrack/dubins.hpp"

namespace vistrack::detail {

// The configuration reached by integrating the path's segments to arc length s.
Configuration integrate(const DubinsPath& path, double s);

}  // namespace vistrack::detail
