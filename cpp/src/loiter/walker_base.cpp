#include <cmath>

#include "loiter/tangents.hpp"
#include "loiter/walkers.hpp"
#include "vistrack/error.hpp"

namespace vistrack::detail {

namespace {
std::string aoi_text(const LoiterProblem& p, int k) {
  const Vec2& a = p.aois[static_cast<std::size_t>(k)];
  return "(" + to_text(a.x()) + ", " + to_text(a.y()) + ")";
}
}  // namespace

void WalkFailure::raise(const LoiterProblem& problem) const {
  const std::string need = "LDLPP needs " + computed_text(needed) + " m (D_Entry = sqrt(R^2 + 2 R r) per turn) ";
  switch (kind) {
    case Kind::StartTooClose:
      fail_field("start", "(" + to_text(problem.start.x()) + ", " + to_text(problem.start.y()) + ")",
                 need + "to turn onto the loiter circle of the first AOI, aois[" + std::to_string(to) + "] = " +
                     aoi_text(problem, to) + ", which is " + computed_text(distance) + " m away");
    case Kind::AoisTooClose:
      fail_field("aois[" + std::to_string(to) + "]", aoi_text(problem, to),
                 need + "between consecutive AOI centres to exit one loiter and enter the next; aois[" +
                     std::to_string(from) + "] before it is " + computed_text(distance) + " m away");
    case Kind::EndTooClose:
      fail_field("end", "(" + to_text(problem.end.x()) + ", " + to_text(problem.end.y()) + ")",
                 need + "from the last AOI, aois[" + std::to_string(from) + "] = " + aoi_text(problem, from) +
                     ", to turn onto the line to the end; it is " + computed_text(distance) + " m away");
    case Kind::None:
      break;
  }
  throw Error("loiter plan: no failure to report");
}

WalkerBase::WalkerBase(const LoiterProblem& problem, PathSink sink, std::vector<Circulation>* directions)
    : problem_(&problem),
      sink_(sink),
      directions_(directions),
      r_(problem.parameters.turn_radius),
      R_(problem.parameters.aoi_radius),
      loiter_sweep_(kTwoPi * problem.parameters.turns),
      position_(problem.start) {}

Circulation WalkerBase::towards(const Vec2& exit_ccw, double heading_ccw, const Vec2& exit_cw, double heading_cw,
                                const Vec2& next) {
  const double change_ccw = std::abs(wrap_to_pi(heading_of(next - exit_ccw) - heading_ccw));
  const double change_cw = std::abs(wrap_to_pi(heading_of(next - exit_cw) - heading_cw));
  return change_cw < change_ccw - 1e-12 ? Circulation::Clockwise : Circulation::CounterClockwise;
}

}  // namespace vistrack::detail
