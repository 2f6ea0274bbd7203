// Least Distance Loitering Path Planner, LDLPP (section 3.3).
//
// Geometry, derived (Figure 10): the transit follows the line from the previous POI (or the
// start) to the POI P, unit vector u. The clockwise entry turn of radius r starts at
// S = P - D_Entry u; its centre S + r right(u) is sqrt(D_Entry^2 + r^2) = R + r from P, so the turn
// touches the loiter circle (radius R) from outside, where clockwise travel on the turn is
// counter-clockwise travel on the loiter. The right triangle (P, S, turn centre) has the leg r
// opposite the angle at P, hence (14) alpha_ED = asin(r / (R + r)) and (15) D_Entry =
// (R + r) cos(alpha_ED). The turn ends at the contact point after turning the angle at the turn
// centre, pi/2 - alpha_ED. The paper's (16) ends the turn when the heading change equals alpha_ED
// instead: that leaves the aircraft off the loiter circle (tested), so we turn pi/2 - alpha_ED.
// The loiter is counter-clockwise, `turns` full circles and on to the exit point, the mirror image
// of the entry about the line to the next POI: there the clockwise exit turn of pi/2 - alpha_ED
// ends on that line, D_Entry past P. The paper's closing angle (17) is the angle at P between the
// aircraft and the next POI, atan2(|det(P3 - P2, F - P2)|, (P3 - P2).(F - P2)): printed, its
// determinant has one column, the vertex is P3 and atan loses angles beyond 90 deg; and
// |gamma| = alpha_ED holds on both sides of the line, only the right side leads into a clockwise
// exit turn. We place the exit point directly.
#include <algorithm>
#include <cmath>

#include "loiter/tangents.hpp"
#include "loiter/walkers.hpp"

namespace vistrack {

double ldlpp_entry_angle(double aoi_radius, double turn_radius) {
  return std::asin(turn_radius / (aoi_radius + turn_radius));  // (14)
}

double ldlpp_entry_distance(double aoi_radius, double turn_radius) {
  return (aoi_radius + turn_radius) * std::cos(ldlpp_entry_angle(aoi_radius, turn_radius));  // (15)
}

double ldlpp_turn_angle(double aoi_radius, double turn_radius) {
  return 0.5 * kPi - ldlpp_entry_angle(aoi_radius, turn_radius);
}

namespace detail {

LdlppWalker::LdlppWalker(const LoiterProblem& problem, PathSink sink, std::vector<Circulation>* directions)
    : WalkerBase(problem, sink, directions),
      entry_distance_(ldlpp_entry_distance(R_, r_)),
      turn_angle_(ldlpp_turn_angle(R_, r_)) {}

double LdlppWalker::per_aoi_minimum(const LoiterProblem& problem) {
  // The entry and exit turns count as transit in the order search's bound (they lie between circles).
  return kTwoPi * problem.parameters.turns * problem.parameters.aoi_radius;
}

bool LdlppWalker::visit(int aoi) {
  const Vec2& target = poi(aoi);
  if (pending_ < 0) {
    const double distance = (target - problem_->start).norm();
    if (distance < entry_distance_) {
      failure_ = {WalkFailure::Kind::StartTooClose, -1, aoi, distance, entry_distance_};
      return false;
    }
    enter(aoi, (target - problem_->start) / distance);
    return true;
  }
  const Vec2 between = target - poi(pending_);
  const double distance = between.norm();
  if (distance < 2.0 * entry_distance_) {
    failure_ = {WalkFailure::Kind::AoisTooClose, pending_, aoi, distance, 2.0 * entry_distance_};
    return false;
  }
  leave(between / distance);
  enter(aoi, between / distance);
  return true;
}

bool LdlppWalker::finish() {
  if (pending_ >= 0) {
    const Vec2 to_end = problem_->end - poi(pending_);
    const double distance = to_end.norm();
    if (distance < entry_distance_) {
      failure_ = {WalkFailure::Kind::EndTooClose, pending_, -1, distance, entry_distance_};
      return false;
    }
    leave(to_end / distance);
  }
  sink_.line(position_, problem_->end, SegmentRole::Transit, -1);
  pending_ = -1;
  return true;
}

// Transit to S, then the clockwise entry turn onto the loiter circle.
void LdlppWalker::enter(int aoi, const Vec2& along) {
  const Vec2& center = poi(aoi);
  const Vec2 turn_start = center - entry_distance_ * along;
  const Vec2 turn_center = turn_start + r_ * right_of(along);
  sink_.line(position_, turn_start, SegmentRole::Transit, -1);
  sink_.arc(turn_center, r_, Circulation::Clockwise, turn_start, turn_angle_, SegmentRole::Entry, aoi);
  entry_ = center + R_ * (turn_center - center).normalized();
  pending_ = aoi;
  record_direction(aoi, Circulation::CounterClockwise);
}

// The loiter until the exit point, then the clockwise exit turn onto the line `along` from the POI.
void LdlppWalker::leave(const Vec2& along) {
  const Vec2& center = poi(pending_);
  const Vec2 turn_end = center + entry_distance_ * along;
  const Vec2 turn_center = turn_end + r_ * right_of(along);
  const Vec2 exit = center + R_ * (turn_center - center).normalized();
  const double sweep = loiter_sweep_ + sweep_between(center, entry_, exit, Circulation::CounterClockwise);
  sink_.arc(center, R_, Circulation::CounterClockwise, entry_, sweep, SegmentRole::Loiter, pending_);
  sink_.arc(turn_center, r_, Circulation::Clockwise, exit, turn_angle_, SegmentRole::Exit, pending_);
  position_ = turn_end;
}

}  // namespace detail
}  // namespace vistrack
