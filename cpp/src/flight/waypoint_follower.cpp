// Classical waypoint navigation: the law (5) (or L1 line tracking) to the active waypoint,
// switching inside R_WP.
#include <cmath>
#include <limits>

#include "vistrack/error.hpp"
#include "vistrack/flight.hpp"

namespace vistrack {

WaypointFollower::WaypointFollower(const LineFeedback& law, const std::vector<Vec2>& waypoints,
                                   double acceptance_radius, bool finish_at_last)
    : law_(law), acceptance_radius_(acceptance_radius), finish_at_last_(finish_at_last) {
  require_non_negative(acceptance_radius, "waypoint_radius");
  for (const Vec2& w : waypoints) add_waypoint(w);
}

WaypointFollower::WaypointFollower(const L1Line& law, const std::vector<Vec2>& waypoints, double acceptance_radius,
                                   bool finish_at_last)
    : law_(law), acceptance_radius_(acceptance_radius), finish_at_last_(finish_at_last) {
  require_non_negative(acceptance_radius, "waypoint_radius");
  for (const Vec2& w : waypoints) add_waypoint(w);
}

void WaypointFollower::add_waypoint(const Vec2& point, double available_from) {
  const std::string field = "waypoints[" + std::to_string(waypoints_.size()) + "]";
  require_finite(point.x(), field + ".x");
  require_finite(point.y(), field + ".y");
  if (std::isnan(available_from) || available_from == std::numeric_limits<double>::infinity())
    detail::fail_field(field + ".available_from", available_from, "must be a time or -inf");
  if (!available_from_.empty() && available_from < available_from_.back())
    detail::fail_field(field + ".available_from", available_from,
                       "must not be earlier than the previous waypoint's " + detail::to_text(available_from_.back()));
  waypoints_.push_back(point);
  available_from_.push_back(available_from);
  accepted_at_.push_back(std::numeric_limits<double>::quiet_NaN());
  touch();
}

bool WaypointFollower::next_available(double t) const {
  return active_ + 1 < waypoints_.size() && available_from_[active_ + 1] <= t;
}

void WaypointFollower::start(const Configuration& state, double t) {
  if (waypoints_.empty()) detail::fail_field("waypoints", 0, "the follower needs at least one waypoint");
  active_ = 0;
  done_ = false;
  line_start_ = Vec2(state.x, state.y);
  for (double& a : accepted_at_) a = std::numeric_limits<double>::quiet_NaN();
  touch();
  advance(state, t);
}

GuidanceCommand WaypointFollower::command(const Configuration& state, double) const {
  GuidanceCommand c;
  c.target = waypoints_[active_];
  c.target_index = static_cast<int>(active_);
  c.turn_rate = std::visit([&](const auto& law) { return law.turn_rate(state, line_start_, c.target); }, law_);
  return c;
}

void WaypointFollower::advance(const Configuration& state, double t) {
  if (done_) return;
  const Vec2 p(state.x, state.y);
  while (true) {
    if (std::isnan(accepted_at_[active_]) && (p - waypoints_[active_]).norm() <= acceptance_radius_)
      accepted_at_[active_] = t;
    if (std::isnan(accepted_at_[active_])) return;
    if (next_available(t)) {
      line_start_ = waypoints_[active_];
      ++active_;
      touch();
      continue;
    }
    if (finish_at_last_ && active_ + 1 == waypoints_.size()) {
      done_ = true;
      touch();
    }
    return;  // the last one so far: hold on it until more arrive
  }
}

double WaypointFollower::switching_function(const Configuration& state, double) const {
  if (done_ || !std::isnan(accepted_at_[active_])) return std::numeric_limits<double>::infinity();
  return std::hypot(state.x - waypoints_[active_].x(), state.y - waypoints_[active_].y()) - acceptance_radius_;
}

double WaypointFollower::next_change_time(double t) const {
  for (std::size_t k = active_ + 1; k < waypoints_.size(); ++k)
    if (available_from_[k] > t) return available_from_[k];
  return std::numeric_limits<double>::infinity();
}

}  // namespace vistrack
