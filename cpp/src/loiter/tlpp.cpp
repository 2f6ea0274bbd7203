// Tangential Loitering Path Planner, TLPP (section 3.2).
//
// From the start straight to the tangent point of the first loiter circle (eqs. 1-7) on the side
// that enters it in the chosen direction; the direction of the first AOI is decided as in
// Fly-Through (the exit heading that points closer to the next POI), every later AOI is flown the
// other way round from the one before. At each AOI: `turns` full circles from the entry point,
// then on round to the departure point of the inner tangent to the next circle (eqs. 8-12), the
// straight tangent, and the entry there. From the last AOI the departure is the tangent point of
// the line through the end point.
#include <algorithm>

#include "loiter/tangents.hpp"
#include "loiter/walkers.hpp"

namespace vistrack::detail {

TlppWalker::TlppWalker(const LoiterProblem& problem, PathSink sink, std::vector<Circulation>* directions)
    : WalkerBase(problem, sink, directions) {}

TlppWalker::TlppWalker(const LoiterProblem& problem, PathSink sink, std::vector<Circulation>* directions,
                       Circulation first_direction)
    : WalkerBase(problem, sink, directions), forced_(true), first_direction_(first_direction) {}

TlppBothWalker::TlppBothWalker(const LoiterProblem& problem, PathSink sink)
    : ccw_(problem, sink, nullptr, Circulation::CounterClockwise), cw_(problem, sink, nullptr, Circulation::Clockwise) {}

double TlppBothWalker::length() const { return std::min(ccw_.length(), cw_.length()); }

double TlppWalker::per_aoi_minimum(const LoiterProblem& problem) {
  return kTwoPi * problem.parameters.turns * problem.parameters.aoi_radius;
}

bool TlppWalker::visit(int aoi) {
  if (pending_ >= 0) {
    if (first_) enter_first(poi(aoi));
    const InnerTangent tangent = inner_tangent(poi(pending_), poi(aoi), R_, direction_);
    loiter_until(tangent.departure);
    sink_.line(tangent.departure, tangent.entry, SegmentRole::Transit, -1);
    entry_ = tangent.entry;
    direction_ = opposite(direction_);
    first_ = false;
  }
  pending_ = aoi;
  record_direction(aoi, direction_);
  return true;
}

bool TlppWalker::finish() {
  if (pending_ >= 0) {
    if (first_) enter_first(problem_->end);
    const Vec2 departure = exit_tangent_point(poi(pending_), R_, direction_, problem_->end);
    loiter_until(departure);
    sink_.line(departure, problem_->end, SegmentRole::Transit, -1);
  } else {
    sink_.line(problem_->start, problem_->end, SegmentRole::Transit, -1);
  }
  pending_ = -1;
  return true;
}

void TlppWalker::enter_first(const Vec2& next) {
  const Vec2& center = poi(pending_);
  const Vec2 ccw = entry_tangent_point(problem_->start, center, R_, Circulation::CounterClockwise);
  const Vec2 cw = entry_tangent_point(problem_->start, center, R_, Circulation::Clockwise);
  // After the full loiters the aircraft is back at its entry point with the entry heading.
  direction_ = forced_ ? first_direction_ : towards(ccw, heading_of(tangent_direction(center, ccw, Circulation::CounterClockwise)), cw,
                       heading_of(tangent_direction(center, cw, Circulation::Clockwise)), next);
  entry_ = direction_ == Circulation::CounterClockwise ? ccw : cw;
  record_direction(pending_, direction_);
  sink_.line(problem_->start, entry_, SegmentRole::Transit, -1);
}

void TlppWalker::loiter_until(const Vec2& departure) {
  const Vec2& center = poi(pending_);
  const double sweep = loiter_sweep_ + sweep_between(center, entry_, departure, direction_);
  sink_.arc(center, R_, direction_, entry_, sweep, SegmentRole::Loiter, pending_);
}

}  // namespace vistrack::detail
