// Metrics of one navigation flight: miss distances, reached, overshoot/undershoot, swirls,
// path length, duration, fuel.
#include <algorithm>
#include <cmath>
#include <limits>

#include "vistrack/error.hpp"
#include "vistrack/waypoint_nav.hpp"

namespace vistrack {

namespace {

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Distance from p to the segment a-b and the clamped parameter of the nearest point.
double segment_distance(const Vec2& p, const Vec2& a, const Vec2& b, double* tau = nullptr) {
  const Vec2 d = b - a;
  const double len2 = d.squaredNorm();
  double t = len2 > 0.0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
  if (tau) *tau = t;
  return (a + t * d - p).norm();
}

}  // namespace

NavigationMetrics navigation_metrics(const FlightTrajectory& traj, const Vec2& start, const std::vector<Vec2>& waypoints,
                                     double speed, double turn_radius, const FuelWeights& weights) {
  require_positive(speed, "speed");
  require_positive(turn_radius, "turn_radius");
  weights.validate();
  if (waypoints.empty()) detail::fail_field("waypoints", 0, "at least one waypoint");
  if (traj.size() == 0) detail::fail_field("trajectory", 0, "an empty trajectory has no metrics");
  const std::size_t n = traj.size(), m = waypoints.size();
  NavigationMetrics out;
  auto position = [&](std::size_t i) { return Vec2(traj.x[i], traj.y[i]); };

  // Miss distance of W_k: closest approach of the flown polyline, searched from the closest
  // approach of W_{k-1} until W_{k+2} becomes the target (by then W_k is behind in WN and DWN).
  out.miss_distances.assign(m, std::numeric_limits<double>::infinity());
  out.closest_times.assign(m, traj.t.front());
  std::size_t from = 0;
  for (std::size_t k = 0; k < m; ++k) {
    std::size_t to = n;
    for (std::size_t i = from; i < n; ++i)
      if (traj.target_index[i] >= static_cast<int>(k) + 2) {
        to = i + 1;
        break;
      }
    std::size_t closest = from;
    for (std::size_t i = from; i < to; ++i) {
      const double d = i + 1 < to ? segment_distance(waypoints[k], position(i), position(i + 1))
                                  : (position(i) - waypoints[k]).norm();
      if (d < out.miss_distances[k]) {
        out.miss_distances[k] = d;
        closest = i;
      }
    }
    out.closest_times[k] = traj.t[closest];
    from = closest;
  }
  // The last waypoint: where the path crosses its finish line (the flight ends there), searched
  // from the previous waypoint's closest approach; without a crossing the closest approach stays.
  {
    const Vec2& w = waypoints.back();
    const Vec2 leg_start = m >= 2 ? waypoints[m - 2] : start;
    std::size_t i0 = 0;
    if (m >= 2) i0 = static_cast<std::size_t>(std::lower_bound(traj.t.begin(), traj.t.end(), out.closest_times[m - 2]) -
                                              traj.t.begin());
    auto along = [&](std::size_t i) { return past_finish_line(position(i), leg_start, w); };
    for (std::size_t i = std::min(i0, n - 1); i < n; ++i) {
      if (along(i) < 0.0) continue;
      Vec2 crossing = position(i);
      double time = traj.t[i];
      if (i > i0) {
        const double a = along(i - 1), b = along(i), f = b > a ? -a / (b - a) : 1.0;
        crossing = position(i - 1) + f * (position(i) - position(i - 1));
        time = traj.t[i - 1] + f * (traj.t[i] - traj.t[i - 1]);
      }
      out.miss_distances[m - 1] = (crossing - w).norm();
      out.closest_times[m - 1] = time;
      break;
    }
  }

  // Reached: the guidance moved past W_k (the last: the flight finished).
  out.reached.assign(m, 0);
  int highest = -1;
  for (int index : traj.target_index) highest = std::max(highest, index);
  for (std::size_t k = 0; k < m; ++k)
    out.reached[k] = (static_cast<int>(k) < highest || (k + 1 == m && traj.finished)) ? 1 : 0;
  out.all_reached = std::all_of(out.reached.begin(), out.reached.end(), [](std::uint8_t r) { return r != 0; });

  // Over- and undershoot against the legs start -> W_1 -> ... -> W_m: the nearest leg, and the
  // turn at its nearer end; outside = away from that turn (or past an end of the route).
  std::vector<Vec2> legs{start};
  legs.insert(legs.end(), waypoints.begin(), waypoints.end());
  std::vector<int> turn(legs.size(), 0);
  for (std::size_t i = 1; i + 1 < legs.size(); ++i) {
    const double c = cross(legs[i] - legs[i - 1], legs[i + 1] - legs[i]);
    turn[i] = c > 0.0 ? 1 : (c < 0.0 ? -1 : 0);
  }
  out.overshoots.assign(m, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 p = position(i);
    double best = std::numeric_limits<double>::infinity(), tau = 0.0;
    std::size_t leg = 0;
    for (std::size_t j = 0; j + 1 < legs.size(); ++j) {
      double t = 0.0;
      const double d = segment_distance(p, legs[j], legs[j + 1], &t);
      if (d < best) {
        best = d;
        tau = t;
        leg = j;
      }
    }
    const std::size_t corner = tau >= 0.5 ? leg + 1 : leg;
    const double side = cross(legs[leg + 1] - legs[leg], p - legs[leg]);
    const bool at_vertex = tau <= 0.0 || tau >= 1.0;
    const bool outside = at_vertex || turn[corner] == 0 || side * turn[corner] < 0.0;
    (outside ? out.overshoot : out.undershoot) = std::max(outside ? out.overshoot : out.undershoot, best);
    if (outside && corner >= 1) out.overshoots[corner - 1] = std::max(out.overshoots[corner - 1], best);  // legs[k + 1] = W_k
  }

  // Swirls: per stretch of one active waypoint, the bearing to it accumulated (the winding of the
  // flown path about it) and each full turn counted from where the last one ended, in either
  // direction: loops that alternate do not cancel (a heading excursion would let them).
  std::size_t begin = 0;
  for (std::size_t i = 1; i <= n; ++i) {
    if (i < n && traj.target_index[i] == traj.target_index[begin]) continue;
    const int k = traj.target_index[begin];
    if (k >= 0 && static_cast<std::size_t>(k) < m) {
      const Vec2& w = waypoints[static_cast<std::size_t>(k)];
      auto bearing = [&](std::size_t j) { return std::atan2(w.y() - traj.y[j], w.x() - traj.x[j]); };
      double previous = bearing(begin), winding = 0.0, counted = 0.0;
      for (std::size_t j = begin + 1; j < i; ++j) {
        const double b = bearing(j);
        winding += wrap_to_pi(b - previous);
        previous = b;
        if (std::abs(winding - counted) >= kTwoPi) {
          ++out.swirls;
          counted += winding > counted ? kTwoPi : -kTwoPi;
        }
      }
    }
    begin = i;
  }

  // Path length, duration, fuel (air distance weighted by how hard the vehicle turns).
  const double max_rate = speed / turn_radius;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    out.path_length += (position(i + 1) - position(i)).norm();
    const double dt = traj.t[i + 1] - traj.t[i];
    const double turning = std::min(1.0, std::abs(traj.command[i]) / max_rate);
    out.fuel += speed * dt * (weights.straight + (weights.arc - weights.straight) * turning);
  }
  out.duration = traj.t.back() - traj.t.front();
  return out;
}

}  // namespace vistrack
