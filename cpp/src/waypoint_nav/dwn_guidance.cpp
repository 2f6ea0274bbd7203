// DWN as a flight guidance: law (5) (or L1) to the turning point, re-planned when it becomes unreachable.
#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"
#include "vistrack/waypoint_nav.hpp"

namespace vistrack {

DubinsWaypointGuidance::DubinsWaypointGuidance(const LineFeedback& law, const std::vector<Vec2>& waypoints,
                                               double turn_radius, const FuelWeights& weights)
    : law_(law), waypoints_(waypoints), turn_radius_(turn_radius), weights_(weights) {
  check();
}

DubinsWaypointGuidance::DubinsWaypointGuidance(const L1Line& law, const std::vector<Vec2>& waypoints,
                                               double turn_radius, const FuelWeights& weights)
    : law_(law), waypoints_(waypoints), turn_radius_(turn_radius), weights_(weights) {
  check();
}

void DubinsWaypointGuidance::check() const {
  require_positive(turn_radius_, "turn_radius");
  weights_.validate();
  if (waypoints_.empty()) detail::fail_field("waypoints", 0, "DWN needs at least one waypoint");
  for (std::size_t k = 0; k < waypoints_.size(); ++k) {
    require_coordinate(waypoints_[k].x(), "waypoints[" + std::to_string(k) + "].x");
    require_coordinate(waypoints_[k].y(), "waypoints[" + std::to_string(k) + "].y");
  }
}

void DubinsWaypointGuidance::plan(const Configuration& state, double t) {
  while (true) {
    TurningPointRecord record;
    record.t = t;
    record.waypoint = static_cast<int>(active_);
    record.pose = state;
    if (active_ + 1 == waypoints_.size()) {
      // Beyond the horizon: the last waypoint is flown to directly.
      record.direct = true;
      record.path.feasible = true;
      record.path.point = waypoints_.back();
      record.path.line_start = Vec2(state.x, state.y);
      record.path.first_straight = record.path.length = (record.path.point - record.path.line_start).norm();
    } else {
      record.path = turning_point(state, waypoints_[active_], waypoints_[active_ + 1], turn_radius_, weights_);
    }
    target_ = record.path.point;
    line_start_ = record.path.line_start;
    log_.push_back(record);
    touch();
    if (!unreachable(state, target_, turn_radius_)) return;
    // Already unreachable from here (behind, or inside a turning circle): the next one.
    if (active_ + 1 == waypoints_.size()) {
      done_ = true;
      return;
    }
    ++active_;
  }
}

void DubinsWaypointGuidance::start(const Configuration& state, double t) {
  active_ = 0;
  done_ = false;
  log_.clear();
  plan(state, t);
}

GuidanceCommand DubinsWaypointGuidance::command(const Configuration& state, double) const {
  GuidanceCommand c;
  c.target = target_;
  c.target_index = static_cast<int>(active_);
  c.turn_rate = std::visit([&](const auto& law) { return law.turn_rate(state, line_start_, target_); }, law_);
  return c;
}

void DubinsWaypointGuidance::advance(const Configuration& state, double t) {
  if (done_ || !unreachable(state, target_, turn_radius_)) return;
  if (active_ + 1 == waypoints_.size()) {
    done_ = true;
    touch();
    return;
  }
  ++active_;
  plan(state, t);
}

double DubinsWaypointGuidance::switching_function(const Configuration& state, double) const {
  return done_ ? std::numeric_limits<double>::infinity() : reachability(state, target_, turn_radius_);
}

}  // namespace vistrack
