// Scores of a follow run: distance from the planned path, along-track lag, time per mode, mode
// switches, and the time the vehicle is in the downward camera's footprint.
#include <algorithm>
#include <cmath>
#include <string>

#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"
#include "vistrack/follow.hpp"

namespace vistrack {

namespace {

double point_segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double f = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + f * ab)).norm();
}

}  // namespace

void FollowRunOptions::validate() const {
  flight.validate();
  camera.validate();
  reports.validate();
  require_positive(path_window, "path_window");
  for (std::size_t i = 0; i < offset_schedule.size(); ++i) {
    const std::string field = "offset_schedule[" + std::to_string(i) + "]";
    require_finite(offset_schedule[i].t, field + ".t");
    require_in_range(offset_schedule[i].distance, 0.0, limits::kMaxLength, "m", field + ".distance");
    require_finite(offset_schedule[i].angle, field + ".angle");
    if (i > 0 && !(offset_schedule[i].t > offset_schedule[i - 1].t))
      detail::fail_field(field + ".t", offset_schedule[i].t, "times must increase strictly");
  }
  if (start) {
    require_coordinate(start->x(), "start[0]");
    require_coordinate(start->y(), "start[1]");
    require_finite(start->z(), "start[2]");
  }
}

Points2 FollowRun::waypoints() const {
  Points2 w(static_cast<Eigen::Index>(ticks.size()), 2);
  for (std::size_t i = 0; i < ticks.size(); ++i) w.row(static_cast<Eigen::Index>(i)) = ticks[i].waypoint.transpose();
  return w;
}

std::vector<double> FollowRun::waypoint_times() const {
  std::vector<double> times;
  times.reserve(ticks.size());
  for (const FollowTick& tick : ticks) times.push_back(tick.t);
  return times;
}

void score_follow_run(FollowRun& run, const Uav& uav, const DownwardCamera& camera, double path_window) {
  const std::size_t n = run.t.size();
  FollowMetrics& m = run.metrics;
  m = FollowMetrics{};
  // run.bank is the flight's (size_run_samples): the camera looks from the bank flown.
  run.in_view.assign(n, 0);
  run.tracking_error.assign(n, 0.0);
  run.along_track_lag.assign(n, 0.0);
  if (n == 0) return;
  const auto row = [](const Points2& p, std::size_t i) -> Vec2 { return p.row(static_cast<Eigen::Index>(i)).transpose(); };

  // The planned path as a polyline of desired positions about every 0.2 s, broken where the
  // desired position jumps (a mode switch or a re-entry): no segment bridges a jump.
  const double dt = n > 1 ? (run.t.back() - run.t.front()) / static_cast<double>(n - 1) : 1.0;
  const std::size_t every = std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(0.2 / dt)));
  std::vector<std::size_t> nodes;
  for (std::size_t i = 0; i < n; i += every) nodes.push_back(i);
  if (nodes.back() != n - 1) nodes.push_back(n - 1);
  std::vector<bool> joined(nodes.size(), false);  // segment nodes[j] -> nodes[j + 1]
  const double fastest = 3.0 * uav.speed;
  for (std::size_t j = 0; j + 1 < nodes.size(); ++j) {
    const double span = run.t[nodes[j + 1]] - run.t[nodes[j]];
    joined[j] = (row(run.desired, nodes[j + 1]) - row(run.desired, nodes[j])).norm() <= fastest * span;
  }
  // Does the desired position jump between samples i and i + 1?
  const auto jumps = [&](std::size_t i) {
    return (row(run.desired, i + 1) - row(run.desired, i)).norm() > fastest * (run.t[i + 1] - run.t[i]);
  };

  std::size_t first = 0;
  double weight_sum = 0.0;
  Vec2 offset_sum = Vec2::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    const double w = i + 1 < n ? run.t[i + 1] - run.t[i] : 0.0;  // each sample holds until the next
    const Vec2 p(run.state(static_cast<Eigen::Index>(i), 0), run.state(static_cast<Eigen::Index>(i), 1));
    const Vec2 vehicle = row(run.vehicle, i);
    const Vec2 desired = row(run.desired, i);

    run.in_view[i] = camera_sees(camera, Vec3(p.x(), p.y(), uav.altitude), run.state(static_cast<Eigen::Index>(i), 2),
                                 run.bank[i], Vec3(vehicle.x(), vehicle.y(), 0.0))
                         ? 1
                         : 0;

    // Distance to the planned path within the time window.
    while (first + 1 < nodes.size() && run.t[nodes[first + 1]] < run.t[i] - path_window) ++first;
    double best = (p - row(run.desired, nodes[first])).norm();
    for (std::size_t j = first; j < nodes.size() && run.t[nodes[j]] <= run.t[i] + path_window; ++j) {
      best = std::min(best, (p - row(run.desired, nodes[j])).norm());
      if (j + 1 < nodes.size() && joined[j])
        best = std::min(best, point_segment_distance(p, row(run.desired, nodes[j]), row(run.desired, nodes[j + 1])));
    }
    run.tracking_error[i] = best;

    // Along-track lag: the error projected on the desired direction of travel.
    Vec2 direction = Vec2::Zero();
    if (i + 1 < n && !jumps(i)) direction = row(run.desired, i + 1) - desired;
    else if (i > 0 && !jumps(i - 1)) direction = desired - row(run.desired, i - 1);
    const double norm = direction.norm();
    run.along_track_lag[i] = norm > 0.0 ? (desired - p).dot(direction) / norm : 0.0;

    m.mean_tracking_error += w * best;
    m.max_tracking_error = std::max(m.max_tracking_error, best);
    m.mean_along_track_lag += w * run.along_track_lag[i];
    m.max_along_track_lag = std::max(m.max_along_track_lag, run.along_track_lag[i]);
    m.camera_fraction += w * run.in_view[i];
    m.mean_vehicle_distance += w * (p - vehicle).norm();
    m.mean_offset_distance += w * (p - row(run.offset_point, i)).norm();
    offset_sum += w * (p - row(run.offset_point, i));
    switch (static_cast<FollowMode>(run.mode[i])) {
      case FollowMode::Sinusoid: m.time_sinusoid += w; break;
      case FollowMode::Loiter: m.time_loiter += w; break;
      case FollowMode::Straight: m.time_straight += w; break;
      case FollowMode::Standoff: m.time_standoff += w; break;
    }
    if (!run.capturing.empty() && run.capturing[i]) m.time_capturing += w;
    weight_sum += w;
  }
  if (weight_sum > 0.0) {
    m.mean_tracking_error /= weight_sum;
    m.mean_along_track_lag /= weight_sum;
    m.camera_fraction /= weight_sum;
    m.mean_vehicle_distance /= weight_sum;
    m.mean_offset_distance /= weight_sum;
    m.mean_offset_error = offset_sum / weight_sum;
  }
  m.final_along_track_lag = run.along_track_lag.back();
  // Lost episodes: the time without a fresh report, and from the first fresh report after each
  // until the camera sees the vehicle again (to the end when it never does).
  if (!run.lost.empty()) {
    double reacquire_sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double w = i + 1 < n ? run.t[i + 1] - run.t[i] : 0.0;
      if (run.lost[i]) m.lost_time += w;
      if (i > 0 && run.lost[i - 1] && !run.lost[i]) {
        ++m.lost_episodes;
        std::size_t j = i;
        while (j + 1 < n && !run.in_view[j]) ++j;
        const double wait = run.t[j] - run.t[i];
        reacquire_sum += wait;
        m.max_reacquire_time = std::max(m.max_reacquire_time, wait);
      }
    }
    if (m.lost_episodes > 0) m.mean_reacquire_time = reacquire_sum / m.lost_episodes;
  }
  m.duration = run.t.back() - run.t.front();
  for (std::size_t k = 1; k < run.ticks.size(); ++k)
    if (run.ticks[k].mode != run.ticks[k - 1].mode) ++m.mode_switches;
}

}  // namespace vistrack
