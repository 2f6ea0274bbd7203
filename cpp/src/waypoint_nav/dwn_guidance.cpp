// DWN as a flight guidance: law (5) (or L1) to the turning point, re-planned when it becomes unreachable.
#include <limits>

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

void DubinsWaypointGuidance::set_wind(const Vec2& mean_wind, double speed) {
  require_positive(speed, "speed");
  require_finite(mean_wind.x(), "wind.east");
  require_finite(mean_wind.y(), "wind.north");
  wind_ = mean_wind;
  airspeed_ = speed;
  air_law_ = law_;
  std::visit([](auto& law) { law.set_wind(Vec2::Zero()); }, air_law_);
  touch();
}

void DubinsWaypointGuidance::set_replan_interval(double interval) {
  require_non_negative(interval, "replan_interval");
  replan_interval_ = interval;
}

void DubinsWaypointGuidance::set_path_following(const PathFollowingGains& gains, double speed) {
  gains.validate();
  require_positive(speed, "speed");
  path_gains_ = gains;
  path_speed_ = speed;
  touch();
}

double DubinsWaypointGuidance::past_finish_line(const Vec2& p) const {
  return vistrack::past_finish_line(p, leg_start_, waypoints_.back());
}

void DubinsWaypointGuidance::follow(const Configuration& state, double t, const HorizonPath& air_path) {
  if (!path_gains_) return;
  follower_.emplace(horizon_pieces(state, air_path, turn_radius_, 2.0 * turn_radius_), path_speed_, turn_radius_,
                    *path_gains_);
  follower_planned_at_ = t;
  follower_->start(state, t);  // the air frame of this plan is the ground now
}

void DubinsWaypointGuidance::plan(const Configuration& state, double t) {
  bool skipped = false;  // a turning point planned in this call was already unreachable
  while (true) {
    TurningPointRecord record;
    record.t = t;
    record.waypoint = static_cast<int>(active_);
    record.pose = state;
    record.wind = wind_;
    if (active_ + 1 == waypoints_.size()) {
      // Beyond the horizon: the last waypoint is flown to directly, up to its finish line.
      record.direct = true;
      record.path.feasible = true;
      record.path.point = record.air_point = waypoints_.back();
      record.path.line_start = Vec2(state.x, state.y);
      record.path.first_straight = record.path.length = (record.path.point - record.path.line_start).norm();
      record.wind = Vec2::Zero();  // a ground point: it does not drift
      air_line_start_ = record.path.line_start;
      // The path followed so far ends along the last leg, unless its turning point was skipped as
      // unreachable: then the leg law flies straight to the last waypoint.
      if (skipped) follower_.reset();
    } else {
      // In calm air the air mass is the ground: the same turning point as turning_point's, to the bit.
      HorizonPath air;
      record.path = air_mass_turning_point(state, waypoints_[active_], waypoints_[active_ + 1], turn_radius_,
                                           airspeed_, wind_, weights_, &air);
      record.air_point = air.point;
      air_line_start_ = air.line_start;
      follow(state, t, air);
    }
    target_ = record.path.point;
    line_start_ = record.path.line_start;
    air_target_ = record.air_point;
    air_frame_ = !record.direct && wind_.norm() > 0.0;
    planned_at_ = t;
    const bool direct = record.direct;
    log_.push_back(record);
    touch();
    if (direct) {
      if (past_finish_line(Vec2(state.x, state.y)) >= 0.0) done_ = true;
      return;
    }
    if (!unreachable(state, air_target_, turn_radius_)) return;
    // Already unreachable from here (behind, or inside a turning circle): the next one.
    ++active_;
    skipped = true;
  }
}

void DubinsWaypointGuidance::start(const Configuration& state, double t) {
  active_ = 0;
  done_ = false;
  log_.clear();
  follower_.reset();
  leg_start_ = waypoints_.size() >= 2 ? waypoints_[waypoints_.size() - 2] : Vec2(state.x, state.y);
  plan(state, t);
}

GuidanceCommand DubinsWaypointGuidance::command(const Configuration& state, double t) const {
  GuidanceCommand c;
  c.target = target_;
  c.target_index = static_cast<int>(active_);
  if (follower_) {
    c.turn_rate = follower_->command(follower_frame(state, t), t).turn_rate;
  } else if (air_frame_) {
    const Vec2 drift = wind_ * (t - planned_at_);
    const Configuration air{state.x - drift.x(), state.y - drift.y(), state.psi};
    c.turn_rate = std::visit([&](const auto& law) { return law.turn_rate(air, air_line_start_, air_target_); },
                             air_law_);
  } else {
    c.turn_rate = std::visit([&](const auto& law) { return law.turn_rate(state, line_start_, target_); }, law_);
  }
  return c;
}

void DubinsWaypointGuidance::advance(const Configuration& state, double t) {
  if (done_) return;
  if (follower_) {
    const auto before = follower_->revision();
    follower_->advance(follower_frame(state, t), t);
    if (follower_->revision() != before) touch();  // the feed-forward's curvature changed
  }
  if (active_ + 1 == waypoints_.size()) {
    if (past_finish_line(Vec2(state.x, state.y)) >= 0.0) {
      done_ = true;
      touch();
    }
    return;
  }
  const Vec2 target = drifting_target(t);
  if (unreachable(state, target, turn_radius_)) {
    ++active_;
    plan(state, t);
    return;
  }
  if (!(replan_interval_ > 0.0 && t >= planned_at_ + replan_interval_ * (1.0 - 1e-9))) return;
  // Close to the turning point the horizon is ill-conditioned: the straight left to T_n is shorter
  // than a step's heading error can absorb, and the best path from a slightly deviated pose may be
  // a loop (seen re-planning every step in 0.3 v wind). Within 0.3 R of T_n (measured: from R on
  // the corrections for an unknown wind stop too early) the line to it is flown as planned.
  if ((target - Vec2(state.x, state.y)).norm() > 0.3 * turn_radius_) {
    log_.pop_back();  // the active waypoint's turning point, planned again from here
    plan(state, t);
  }
}

double DubinsWaypointGuidance::switching_function(const Configuration& state, double t) const {
  if (done_) return std::numeric_limits<double>::infinity();
  if (active_ + 1 == waypoints_.size()) return -past_finish_line(Vec2(state.x, state.y));
  return reachability(state, drifting_target(t), turn_radius_);
}

double DubinsWaypointGuidance::next_change_time(double t) const {
  if (done_ || replan_interval_ <= 0.0 || active_ + 1 == waypoints_.size())
    return std::numeric_limits<double>::infinity();
  const double due = planned_at_ + replan_interval_;
  return due > t ? due : std::numeric_limits<double>::infinity();
}

}  // namespace vistrack
