// Fly-Through (section 3.1): the Pixhawk-like loiter the paper improves on.
//
// Straight to the POI; there, the loiter direction is the one whose exit heading points closer to
// the next POI (or the end). From the POI with the inbound heading h the aircraft turns at r in
// that direction and flies straight to the offset point O = POI - R (cos h, sin h) on the inbound
// line, arriving tangent to the loiter circle: the Dubins word RSR (clockwise) or LSL. When R = r
// this is exactly the paper's "three quarters of a full turn" and a line of length r; for R > r
// the same word reaches the circle's tangent at O. Then `turns` full circles at R, and a turn at r
// (the shorter side) until the next POI is straight ahead, and the line to it.
#include <cmath>
#include <limits>

#include "loiter/tangents.hpp"
#include "loiter/walkers.hpp"
#include "vistrack/dubins.hpp"

namespace vistrack::detail {

namespace {

// The loiter entry from the POI (inbound heading h) to the offset point, as a Dubins path.
DubinsPath entry_path(const Vec2& poi, double heading, double aoi_radius, double turn_radius, Circulation d) {
  const Vec2 offset = poi - aoi_radius * unit_at(heading);
  // The tangent heading at O: h - pi/2 counter-clockwise, h + pi/2 clockwise.
  const double tangent = heading - static_cast<double>(sign(d)) * 0.5 * kPi;
  return dubins_path({poi.x(), poi.y(), heading}, {offset.x(), offset.y(), tangent}, turn_radius,
                     d == Circulation::CounterClockwise ? DubinsWord::LSL : DubinsWord::RSR);
}

}  // namespace

FlyThroughWalker::FlyThroughWalker(const LoiterProblem& problem, PathSink sink, std::vector<Circulation>* directions)
    : WalkerBase(problem, sink, directions), heading_(std::numeric_limits<double>::quiet_NaN()) {}

double FlyThroughWalker::per_aoi_minimum(const LoiterProblem& problem) {
  const auto& p = problem.parameters;
  return entry_path(Vec2::Zero(), 0.0, p.aoi_radius, p.turn_radius, Circulation::CounterClockwise).length +
         kTwoPi * p.turns * p.aoi_radius;
}

bool FlyThroughWalker::visit(int aoi) {
  if (pending_ >= 0) loiter_and_leave(poi(aoi));
  go_to(poi(aoi));
  pending_ = aoi;
  return true;
}

bool FlyThroughWalker::finish() {
  if (pending_ >= 0) loiter_and_leave(problem_->end);
  go_to(problem_->end);
  pending_ = -1;
  return true;
}

void FlyThroughWalker::loiter_and_leave(const Vec2& next) {
  const Vec2& center = poi(pending_);
  const double inbound = heading_;
  const Vec2 offset = center - R_ * unit_at(inbound);
  // After the loiter the aircraft is back at O with the tangent heading of its direction.
  const double exit_ccw = inbound - 0.5 * kPi, exit_cw = inbound + 0.5 * kPi;
  const Circulation d = towards(offset, exit_ccw, offset, exit_cw, next);
  record_direction(pending_, d);
  sink_.dubins(entry_path(center, inbound, R_, r_, d), SegmentRole::Entry, pending_);
  sink_.arc(center, R_, d, offset, loiter_sweep_, SegmentRole::Loiter, pending_);
  position_ = offset;
  heading_ = d == Circulation::CounterClockwise ? exit_ccw : exit_cw;
}

// A turn at r on the shorter side until the target is straight ahead, then the line to it (the
// shortest turn-then-straight path to a point with a free final heading); from the start, whose
// heading is free, only the line.
void FlyThroughWalker::go_to(const Vec2& target) {
  if (std::isnan(heading_)) {
    sink_.line(position_, target, SegmentRole::Transit, -1);
    heading_ = heading_of(target - position_);
    position_ = target;
    return;
  }
  const Vec2 forward = unit_at(heading_);
  double best = std::numeric_limits<double>::infinity();
  Circulation best_d = Circulation::CounterClockwise;
  Vec2 best_center, best_leave;
  double best_sweep = 0.0;
  for (const Circulation d : {Circulation::CounterClockwise, Circulation::Clockwise}) {
    const Vec2 center = position_ + r_ * static_cast<double>(sign(d)) * left_of(forward);
    const double distance = (target - center).norm();
    if (distance < r_ * (1.0 - 1e-12)) continue;  // inside this turning circle: the other side
    const Vec2 leave = exit_tangent_point(center, r_, d, target);
    const double sweep = sweep_between(center, position_, leave, d);
    const double length = r_ * sweep + (target - leave).norm();
    if (length < best) {
      best = length;
      best_d = d;
      best_center = center;
      best_leave = leave;
      best_sweep = sweep;
    }
  }
  // With R = r, turning the loiter's way continues on the loiter circle: that counts as loiter.
  const bool on_loiter = pending_ >= 0 && std::abs(r_ - R_) <= 1e-12 * R_ && (best_center - poi(pending_)).norm() <= 1e-9 * R_;
  sink_.arc(best_center, r_, best_d, position_, best_sweep, on_loiter ? SegmentRole::Loiter : SegmentRole::Exit,
            pending_);
  sink_.line(best_leave, target, SegmentRole::Transit, -1);
  heading_ += static_cast<double>(sign(best_d)) * best_sweep;
  if ((target - best_leave).norm() > 0.0) heading_ = heading_of(target - best_leave);
  position_ = target;
}

}  // namespace vistrack::detail
