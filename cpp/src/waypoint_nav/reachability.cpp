// The reachability zone of section 2.5 (Figure 7).
#include <algorithm>
#include <cmath>

#include "vistrack/waypoint_nav.hpp"

namespace vistrack {

double reachability(const Configuration& pose, const Vec2& point, double R) {
  const double c = std::cos(pose.psi), s = std::sin(pose.psi);
  const double dx = point.x() - pose.x, dy = point.y() - pose.y;
  const double x = c * dx + s * dy;   // ahead
  const double y = -s * dx + c * dy;  // left
  // Open turning circles: a point on a circle ahead is reached by turning, so it stays reachable.
  const double margin = 1e-9 * R;
  const double left = std::hypot(x, y - R) - R + margin;
  const double right = std::hypot(x, y + R) - R + margin;
  // Closed box behind the vehicle between the circles, up to their common rear tangent x = -R:
  // a point passed between the circles is caught even when a discrete step jumps over it.
  const double qx = std::abs(x + 0.5 * R) - 0.5 * R, qy = std::abs(y) - R;
  const double box = std::hypot(std::max(qx, 0.0), std::max(qy, 0.0)) + std::min(std::max(qx, qy), 0.0);
  return std::min({left, right, box});
}

}  // namespace vistrack
