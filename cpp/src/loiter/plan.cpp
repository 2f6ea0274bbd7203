// Plans: names, segment evaluation, assembly from a walker, sampling.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "loiter/tangents.hpp"
#include "loiter/walkers.hpp"
#include "vistrack/error.hpp"
#include "vistrack/loiter.hpp"

namespace vistrack {

namespace {

template <class Walker, class... Options>
void walk(const LoiterProblem& problem, const std::vector<int>& order, LoiterPlan& plan, Options... options) {
  Walker walker(problem, detail::PathSink(&plan.segments), &plan.directions, options...);
  for (const int aoi : order)
    if (!walker.visit(aoi)) walker.failure().raise(problem);
  if (!walker.finish()) walker.failure().raise(problem);
}

double total_length(const std::vector<LoiterSegment>& segments) {
  double length = 0.0;
  for (const LoiterSegment& s : segments) length += s.length;
  return length;
}

// TlppBest: TLPP with each first direction; the shorter plan (counter-clockwise on a tie).
void walk_tlpp_best(const LoiterProblem& problem, const std::vector<int>& order, LoiterPlan& plan) {
  LoiterPlan clockwise = plan;
  walk<detail::TlppWalker>(problem, order, plan, Circulation::CounterClockwise);
  walk<detail::TlppWalker>(problem, order, clockwise, Circulation::Clockwise);
  if (total_length(clockwise.segments) < total_length(plan.segments) * (1.0 - 1e-12)) plan = std::move(clockwise);
}

void require_permutation(const std::vector<int>& order, std::size_t n) {
  if (order.size() != n)
    detail::fail_field("order", "a list of " + std::to_string(order.size()) + " indices",
                       "must list each of the " + std::to_string(n) + " AOIs once");
  std::vector<bool> seen(n, false);
  for (std::size_t k = 0; k < order.size(); ++k) {
    const int aoi = order[k];
    if (aoi < 0 || static_cast<std::size_t>(aoi) >= n || seen[static_cast<std::size_t>(aoi)])
      detail::fail_field("order[" + std::to_string(k) + "]", aoi,
                         "must be an AOI index in [0, " + std::to_string(n) + ") not listed before");
    seen[static_cast<std::size_t>(aoi)] = true;
  }
}

}  // namespace

Configuration LoiterSegment::at(double s) const {
  if (kind == SegmentKind::Line) {
    const Vec2 p = start + s * detail::unit_at(start_heading);
    return {p.x(), p.y(), start_heading};
  }
  const double turn = static_cast<double>(sign(direction)) * s / radius;
  const Vec2 p = center + radius * detail::unit_at(detail::heading_of(start - center) + turn);
  return {p.x(), p.y(), start_heading + turn};
}

double LoiterSegment::curvature() const {
  return kind == SegmentKind::Line ? 0.0 : static_cast<double>(sign(direction)) / radius;
}

LoiterPlan plan_loiter_in_order(const LoiterProblem& problem, LoiterMethod method, const std::vector<int>& order) {
  problem.validate();
  require_permutation(order, problem.aois.size());
  LoiterPlan plan;
  plan.method = method;
  plan.problem = problem;
  plan.order = order;
  plan.directions.assign(problem.aois.size(), Circulation::CounterClockwise);
  switch (method) {
    case LoiterMethod::FlyThrough: walk<detail::FlyThroughWalker>(problem, order, plan); break;
    case LoiterMethod::Tlpp: walk<detail::TlppWalker>(problem, order, plan); break;
    case LoiterMethod::Ldlpp: walk<detail::LdlppWalker>(problem, order, plan); break;
    case LoiterMethod::TlppBest: walk_tlpp_best(problem, order, plan); break;
    case LoiterMethod::LdlppBest: walk<detail::LdlppWalker>(problem, order, plan, true); break;
  }
  plan.segment_offsets.reserve(plan.segments.size());
  plan.loiter_sweep.assign(problem.aois.size(), 0.0);
  double loiter_length = 0.0;
  for (const LoiterSegment& s : plan.segments) {
    plan.segment_offsets.push_back(plan.length);
    plan.length += s.length;
    if (s.role == SegmentRole::Loiter) {
      loiter_length += s.length;
      plan.loiter_sweep[static_cast<std::size_t>(s.aoi)] += s.sweep;
    }
  }
  const double v = problem.parameters.speed;
  plan.flight_time = plan.length / v;
  plan.loiter_time = loiter_length / v;
  plan.transit_time = plan.flight_time - plan.loiter_time;
  return plan;
}

LoiterPlan plan_loiter(const LoiterProblem& problem, LoiterMethod method, LoiterOrder order) {
  problem.validate();
  std::vector<int> visiting(problem.aois.size());
  std::iota(visiting.begin(), visiting.end(), 0);
  if (order == LoiterOrder::Best)
    visiting = best_loiter_order(problem, method, static_cast<int>(problem.aois.size()) <= kExactOrderLimit);
  return plan_loiter_in_order(problem, method, visiting);
}

std::size_t LoiterPlan::segment_at_time(double t) const {
  if (segments.empty()) return 0;
  const double s = t * problem.parameters.speed;
  const auto it = std::upper_bound(segment_offsets.begin(), segment_offsets.end(), s);
  const auto index = static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, (it - segment_offsets.begin()) - 1));
  return std::min(index, segments.size() - 1);
}

Configuration LoiterPlan::at_time(double t) const {
  if (!(t >= 0.0) || !(t <= flight_time))
    detail::fail_field("t", t, "must lie in [0, flight_time = " + detail::computed_text(flight_time) + "]");
  if (segments.empty()) return {problem.start.x(), problem.start.y(), 0.0};
  if (t == flight_time) {
    const LoiterSegment& last = segments.back();
    return {last.end.x(), last.end.y(), last.end_heading};
  }
  const std::size_t k = segment_at_time(t);
  const double s = std::min(t * problem.parameters.speed - segment_offsets[k], segments[k].length);
  return segments[k].at(s);
}

LoiterSamples LoiterPlan::sample_states(double dt, bool include_end) const {
  require_positive(dt, "dt");
  const double steps = std::floor(flight_time / dt * (1.0 + 1e-12));
  if (steps > 1e8) detail::fail_field("dt", dt, "gives more than 1e8 samples");
  const auto regular = static_cast<std::size_t>(steps) + 1;
  const bool append = include_end && flight_time - static_cast<double>(regular - 1) * dt > 1e-9 * dt;
  const std::size_t n = regular + (append ? 1 : 0);
  LoiterSamples out;
  out.t.resize(n);
  out.poses.resize(static_cast<Eigen::Index>(n), 3);
  out.turn_rate.resize(n);
  out.segment.resize(n);
  const double v = problem.parameters.speed;
  for (std::size_t k = 0; k < n; ++k) {
    const double t = (append && k + 1 == n) ? flight_time : std::min(flight_time, static_cast<double>(k) * dt);
    const Configuration q = at_time(t);
    const std::size_t segment = segment_at_time(t);
    out.t[k] = t;
    out.poses.row(static_cast<Eigen::Index>(k)) << q.x, q.y, q.psi;
    out.segment[k] = static_cast<int>(segment);
    out.turn_rate[k] = segments.empty() ? 0.0 : v * segments[segment].curvature();
  }
  return out;
}

}  // namespace vistrack
