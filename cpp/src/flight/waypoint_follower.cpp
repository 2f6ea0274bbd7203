// Classical waypoint navigation: the law (5) (or L1 line tracking) to the active waypoint,
// switching inside R_WP (or, as ArduPlane does, past the finish line or inside the turn distance).
#include <algorithm>
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

void WaypointFollower::set_passed_line(bool enabled) {
  passed_line_ = enabled;
  update_acceptance();
  touch();
}

void WaypointFollower::set_finish_line(bool enabled) {
  finish_line_ = enabled;
  touch();
}

// Only the finish line counts at the last waypoint (set_finish_line).
bool WaypointFollower::on_finish_line_only() const {
  return finish_line_ && finish_at_last_ && active_ + 1 == waypoints_.size();
}

// Once per change of the active leg (not per step): the acceptance distance of the active waypoint.
void WaypointFollower::update_acceptance() {
  acceptance_ = acceptance_radius_;
  if (!passed_line_ || waypoints_.empty()) return;
  acceptance_ = 0.0;
  if (active_ + 1 >= waypoints_.size()) return;  // the last: done on its line
  const Vec2 in = waypoints_[active_] - line_start_;
  const Vec2 out = waypoints_[active_ + 1] - waypoints_[active_];
  if (in.norm() == 0.0 || out.norm() == 0.0) return;
  const double turn = std::abs(std::atan2(in.x() * out.y() - in.y() * out.x(), in.dot(out)));
  double distance = acceptance_radius_;
  if (const auto* l1 = std::get_if<L1Line>(&law_)) distance = std::min(distance, l1->distance());
  acceptance_ = distance * std::min(turn, 0.5 * kPi) / (0.5 * kPi);
}

double WaypointFollower::past_finish_line(const Vec2& p) const {
  return vistrack::past_finish_line(p, line_start_, waypoints_[active_]);
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
  update_acceptance();  // the active waypoint may have gained its next leg
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
  update_acceptance();
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
    const bool accept = on_finish_line_only()
                            ? past_finish_line(p) >= 0.0
                            : (p - waypoints_[active_]).norm() <= acceptance_distance() ||
                                  (passed_line_ && past_finish_line(p) >= 0.0);
    if (std::isnan(accepted_at_[active_]) && accept) accepted_at_[active_] = t;
    if (std::isnan(accepted_at_[active_])) return;
    if (next_available(t)) {
      line_start_ = waypoints_[active_];
      ++active_;
      update_acceptance();
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
  const Vec2 p(state.x, state.y);
  if (on_finish_line_only()) return -past_finish_line(p);
  const double inside = (p - waypoints_[active_]).norm() - acceptance_distance();
  // <= 0 once either condition holds: the smaller of the two distances to switching.
  return passed_line_ ? std::min(inside, -past_finish_line(p)) : inside;
}

double WaypointFollower::next_change_time(double t) const {
  for (std::size_t k = active_ + 1; k < waypoints_.size(); ++k)
    if (available_from_[k] > t) return available_from_[k];
  return std::numeric_limits<double>::infinity();
}

}  // namespace vistrack
