#pragma once
// A FollowRun with one slot per flight sample, shared by the planner's run and the baseline.
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

}  // namespace vistrack::detail
