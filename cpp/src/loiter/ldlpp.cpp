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

LdlppWalker::LdlppWalker(const LoiterProblem& problem, PathSink sink, std::vector<Circulation>* directions,
                         bool choose_direction)
    : WalkerBase(problem, sink, directions),
      entry_distance_(ldlpp_entry_distance(R_, r_)),
      turn_angle_(ldlpp_turn_angle(R_, r_)),
      choose_direction_(choose_direction),
      along_in_(Vec2::UnitX()) {}

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

// Transit to S. The entry turn is drawn on leaving, once the line out (and with it the loiter
// direction that loiters less) is known.
void LdlppWalker::enter(int aoi, const Vec2& along) {
  sink_.line(position_, poi(aoi) - entry_distance_ * along, SegmentRole::Transit, -1);
  along_in_ = along;
  pending_ = aoi;
}

// The visit of the pending AOI loitering in `direction`: counter-clockwise as printed (turns
// clockwise, their centres right of the lines), clockwise its mirror image about each line.
LdlppWalker::Visit LdlppWalker::plan_visit(const Vec2& along_out, Circulation direction) const {
  const Vec2& center = poi(pending_);
  const auto turn_center = [&](const Vec2& point, const Vec2& along) {
    return Vec2(point + r_ * (direction == Circulation::CounterClockwise ? right_of(along) : left_of(along)));
  };
  Visit v;
  v.entry_center = turn_center(center - entry_distance_ * along_in_, along_in_);
  v.entry = center + R_ * (v.entry_center - center).normalized();
  v.exit_center = turn_center(center + entry_distance_ * along_out, along_out);
  v.exit = center + R_ * (v.exit_center - center).normalized();
  v.sweep = loiter_sweep_ + sweep_between(center, v.entry, v.exit, direction);
  return v;
}

// The entry turn, the loiter until the exit point, then the exit turn onto the line `along` from
// the POI.
void LdlppWalker::leave(const Vec2& along) {
  const Vec2& center = poi(pending_);
  Circulation direction = Circulation::CounterClockwise;
  Visit v = plan_visit(along, direction);
  if (choose_direction_) {
    const Visit mirrored = plan_visit(along, Circulation::Clockwise);
    if (mirrored.sweep < v.sweep - 1e-12) {
      v = mirrored;
      direction = Circulation::Clockwise;
    }
  }
  const Circulation turn = opposite(direction);
  sink_.arc(v.entry_center, r_, turn, center - entry_distance_ * along_in_, turn_angle_, SegmentRole::Entry,
            pending_);
  sink_.arc(center, R_, direction, v.entry, v.sweep, SegmentRole::Loiter, pending_);
  sink_.arc(v.exit_center, r_, turn, v.exit, turn_angle_, SegmentRole::Exit, pending_);
  record_direction(pending_, direction);
  position_ = center + entry_distance_ * along;
}

}  // namespace detail
}  // namespace vistrack
