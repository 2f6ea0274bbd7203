#pragma once
// A FollowRun with one slot per flight sample, shared by the planner's run and the baseline.
#include <utility>
#include <vector>

#include "vistrack/flight.hpp"
#include "vistrack/follow.hpp"

namespace vistrack::detail {

// Copies the flight's times, turn rates and bank into run and sizes the per-sample arrays that
// the caller fills (state, vehicle, offset point, desired position, target, wind).
inline void size_run_samples(FollowRun& run, const FlightTrajectory& trajectory) {
  const auto n = static_cast<Eigen::Index>(trajectory.size());
  run.t = trajectory.t;
  run.turn_rate = trajectory.command;
  run.bank = trajectory.bank;
  run.state.resize(n, 3);
  run.vehicle.resize(n, 2);
  run.offset_point.resize(n, 2);
  run.desired.resize(n, 2);
  run.target.resize(n, 2);
  run.wind.resize(n, 2);
}

// The offset (distance, angle) of the schedule at t, or the parameters' when it is empty: keys
// linear in between, held outside.
inline std::pair<double, double> scheduled_offset(const std::vector<OffsetKey>& keys, const FollowParameters& p,
                                                  double t) {
  if (keys.empty()) return {p.offset_distance, p.offset_angle};
  if (t <= keys.front().t) return {keys.front().distance, keys.front().angle};
  for (std::size_t i = 1; i < keys.size(); ++i) {
    if (t < keys[i].t) {
      const double f = (t - keys[i - 1].t) / (keys[i].t - keys[i - 1].t);
      return {keys[i - 1].distance + f * (keys[i].distance - keys[i - 1].distance),
              keys[i - 1].angle + f * (keys[i].angle - keys[i - 1].angle)};
    }
  }
  return {keys.back().distance, keys.back().angle};
}

}  // namespace vistrack::detail
