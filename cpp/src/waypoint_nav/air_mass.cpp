// The turning point planned in the air mass of a known mean wind (wind-aware DWN, beyond the
// paper): the horizon of section 2.4 solved for the waypoints as the air sees them.
#include <cmath>

#include "vistrack/error.hpp"
#include "vistrack/waypoint_nav.hpp"

namespace vistrack {

TurningPoint air_mass_turning_point(const Configuration& pose, const Vec2& w_next, const Vec2& w_after,
                                    double turn_radius, double speed, const Vec2& wind, const FuelWeights& weights,
                                    HorizonPath* air_path) {
  require_positive(speed, "speed");
  require_finite(wind.x(), "wind.east");
  require_finite(wind.y(), "wind.north");
  if (wind.norm() >= speed)
    detail::fail_field("wind", wind.norm(), "the mean wind must be slower than the airspeed " + detail::to_text(speed));
  const Vec2 p(pose.x, pose.y);
  // tau_n, tau_{n+1}: when the path meets W_n and W_{n+1}; first guess straight lines at v.
  double to_next = (w_next - p).norm() / speed;
  double to_after = to_next + (w_after - w_next).norm() / speed;
  TurningPoint best = turning_point(pose, w_next - wind * to_next, w_after - wind * to_after, turn_radius, weights);
  if (wind.norm() > 0.0) {
    const double tolerance = 1e-12 * turn_radius / speed;
    for (int round = 0; round < 100 && best.feasible; ++round) {
      const double reach = best.first_arc + best.first_straight + best.arc_to_waypoint;  // C -> W_n, length
      const double next = reach / speed;
      const double after = (reach + best.arc_from_waypoint + best.last_straight) / speed;
      const bool settled = std::abs(next - to_next) <= tolerance && std::abs(after - to_after) <= tolerance;
      to_next = next;
      to_after = after;
      if (settled) break;
      best = turning_point(pose, w_next - wind * to_next, w_after - wind * to_after, turn_radius, weights);
    }
  }
  if (air_path) *air_path = best;
  if (!best.feasible || wind.norm() == 0.0) return best;
  // On the ground: each point moved by the air mass's drift until the vehicle is there.
  const double at_line = best.first_arc / speed;
  const double at_point = (best.first_arc + best.first_straight) / speed;
  const double at_exit = at_point + (best.arc_to_waypoint + best.arc_from_waypoint) / speed;
  best.line_start += wind * at_line;
  best.point += wind * at_point;
  best.circle_center += wind * to_next;
  best.exit_point += wind * at_exit;
  return best;
}

}  // namespace vistrack
