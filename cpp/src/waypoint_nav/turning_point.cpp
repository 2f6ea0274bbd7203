// DWN turning point: the horizon path of each case at a given theta, and the exact minimisation
// over theta (sampling, breakpoints, Brent on dF/dh), see waypoint_nav.hpp.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"
#include "vistrack/ode.hpp"
#include "vistrack/waypoint_nav.hpp"
#include "waypoint_nav/horizon.hpp"

namespace vistrack {

namespace {

using detail::HorizonEval;
using detail::HorizonProblem;

constexpr int kSamples = 16;          // uniform samples of h per case
constexpr double kRootTolerance = 1e-13;  // rad, on h

Vec2 unit(double angle) { return {std::cos(angle), std::sin(angle)}; }
Vec2 left_normal(double angle) { return {-std::sin(angle), std::cos(angle)}; }

void validate_horizon(const Configuration& pose, const Vec2& w_next, const Vec2& w_after, double turn_radius,
                      const FuelWeights& weights) {
  require_coordinate(pose.x, "pose.x");
  require_coordinate(pose.y, "pose.y");
  require_angle(pose.psi, "pose.psi");
  require_coordinate(w_next.x(), "w_next.x");
  require_coordinate(w_next.y(), "w_next.y");
  require_coordinate(w_after.x(), "w_after.x");
  require_coordinate(w_after.y(), "w_after.y");
  require_length(turn_radius, "turn_radius");
  weights.validate();
  // As the Dubins solver's limit (limits.hpp): beyond 1e6 R from the pose the turns are below the
  // rounding of the coordinates.
  const double reach = std::max((w_next - Vec2(pose.x, pose.y)).norm(), (w_after - Vec2(pose.x, pose.y)).norm());
  if (!(reach <= limits::kMaxCoordinateOverRho * turn_radius))
    detail::fail_field("turn_radius", turn_radius,
                       "is too small for waypoints " + detail::to_text(reach) +
                           " m away: at most 1e6 turn radii from the pose");
  if ((w_after - w_next).norm() < 1e-9 * turn_radius)
    detail::fail_field("w_after", "(" + detail::to_text(w_after.x()) + ", " + detail::to_text(w_after.y()) + ")",
                       "closer than 1e-9 R to w_next");
}

// Headings h where a tangent starts or stops existing for case (d1, d2): the LSR/RSL circles at
// distance 2 R, and W_{n+1} on the circle around W_n. Closed form: each is cos(h + pi/2 - gamma) = K.
int feasibility_edges(const HorizonProblem& P, int d1, int d2, std::array<double, 4>& out) {
  int count = 0;
  auto add = [&](const Vec2& point, double k) {  // d2 * n(h) . point = |point| cos(h + pi/2 - gamma) * d2 = k
    const double r = point.norm();
    if (r == 0.0) return;
    const double cosine = d2 * k / r;
    if (!(cosine > -1.0 && cosine < 1.0)) return;
    const double gamma = std::atan2(point.y(), point.x());
    const double spread = std::acos(cosine);
    out[static_cast<std::size_t>(count++)] = wrap_to_two_pi(gamma - detail::kHalfPi + spread);
    out[static_cast<std::size_t>(count++)] = wrap_to_two_pi(gamma - detail::kHalfPi - spread);
  };
  if (d1 != d2) {
    const Vec2 c1 = P.c + d1 * left_normal(P.psi);
    add(c1, 0.5 * (c1.squaredNorm() - 3.0));  // |d2 n(h) - c1|^2 = 4
  }
  const Vec2 q(P.qx, P.qy);
  add(q, 0.5 * q.squaredNorm());  // |q - d2 n(h)|^2 = 1
  return count;
}

struct Sample {  // trivially constructible, like HorizonEval
  double h;
  HorizonEval e;
};

struct Best {
  double value = std::numeric_limits<double>::infinity();
  double h = 0.0;
  int c = -1;
};

class Solver {
 public:
  explicit Solver(const HorizonProblem& problem) : P_(problem) {}

  HorizonEval eval(int d1, int d2, double h) {
    ++evaluations_;
    return detail::evaluate_horizon(P_, d1, d2, h);
  }
  void eval_cases(double h, HorizonEval* out) {
    evaluations_ += kTurnCaseCount;
    detail::evaluate_horizon_cases(P_, h, out);
  }
  double slope(int d1, int d2, double h) {
    ++evaluations_;
    return detail::horizon_slope(P_, d1, d2, h);
  }
  int evaluations() const { return evaluations_; }

  // Offer a feasible point; `value` is F there (with the arc at a wrap edge taken as 0).
  void offer(Best& best, double value, double h, int c) {
    if (value < best.value) best = {value, h, c};
  }

  // The wrap edge of quantity k (0 t, 1 q, 2 a) inside (a, b), where it passes through 0; the
  // point returned lies on the side where the arc is small. NaN when not bracketed.
  double wrap_edge(int d1, int d2, int k, const Sample& a, const Sample& b) {
    auto get = [k](const HorizonEval& e) { return k == 0 ? e.t : (k == 1 ? e.q : e.a); };
    auto f = [&](double h) {
      const HorizonEval e = eval(d1, d2, h);
      return e.ok ? wrap_to_pi(get(e)) : std::numeric_limits<double>::quiet_NaN();
    };
    const double fa = wrap_to_pi(get(a.e)), fb = wrap_to_pi(get(b.e));
    if (!(fa * fb < 0.0)) return std::numeric_limits<double>::quiet_NaN();
    double h = detail::brent_root(f, a.h, b.h, fa, fb, kRootTolerance);
    // Step onto the low side (the arc near 0, not near 2 pi) if the root landed just across.
    const double towards_low = get(a.e) < kPi ? -1.0 : 1.0;
    for (int tries = 0; tries < 8; ++tries) {
      const HorizonEval e = eval(d1, d2, h);
      if (e.ok && get(e) < kPi) return h;
      h += towards_low * kRootTolerance * (1 << tries);
    }
    return h;
  }

  // A smooth minimum of F on (a, b): dF/dh from - to +.
  void smooth_minimum(Best& best, int c, int d1, int d2, const Sample& a, const Sample& b) {
    if (!(a.e.slope < 0.0 && b.e.slope > 0.0)) return;
    auto f = [&](double h) { return slope(d1, d2, h); };
    const double h = detail::brent_root(f, a.h, b.h, a.e.slope, b.e.slope, kRootTolerance);
    const HorizonEval e = eval(d1, d2, h);
    if (e.ok) offer(best, e.value, h, c);
  }

 private:
  const HorizonProblem& P_;
  int evaluations_ = 0;
};

struct Bracket {  // samples i and i + 1 (cyclic: then b.h + 2 pi) of one case
  double bound;
  int c;
  std::uint8_t i;
  bool wraps;
};

}  // namespace

namespace {

// The path of case c with heading h at W_n, in world coordinates, from a prepared problem.
HorizonPath build_path(const HorizonProblem& P, const Configuration& pose, const Vec2& w_next, double R, TurnCase c,
                       double h, const FuelWeights& weights) {
  const int d1 = detail::first_direction(c), d2 = detail::second_direction(c);
  HorizonPath out;
  out.turn_case = c;
  out.theta = detail::theta_of_heading(h, d2);
  out.heading_at_waypoint = detail::heading_of_theta(out.theta, d2);
  out.circle_center = w_next + R * unit(out.theta);
  out.length = std::numeric_limits<double>::infinity();
  const HorizonEval e = detail::evaluate_horizon(P, d1, d2, h);
  if (!e.ok) return out;
  out.feasible = true;
  const Vec2 start(pose.x, pose.y);
  const double chi = pose.psi + d1 * e.t;  // heading along the first straight
  const Vec2 first_center = start + d1 * R * left_normal(pose.psi);
  out.line_start = first_center - d1 * R * left_normal(chi);
  out.point = out.line_start + e.p * R * unit(chi);
  const double exit_heading = out.heading_at_waypoint + d2 * e.a;
  out.exit_point = out.circle_center - d2 * R * left_normal(exit_heading);
  out.first_arc = R * e.t;
  out.first_straight = R * e.p;
  out.arc_to_waypoint = R * e.q;
  out.arc_from_waypoint = R * e.a;
  out.last_straight = R * e.s2;
  out.length = weights.arc * out.arcs() + weights.straight * out.straights();
  return out;
}

}  // namespace

HorizonPath horizon_path(const Configuration& pose, const Vec2& w_next, const Vec2& w_after, double R, TurnCase c,
                         double theta, const FuelWeights& weights) {
  validate_horizon(pose, w_next, w_after, R, weights);
  require_finite(theta, "theta");
  const HorizonProblem P(pose, w_next, w_after, R, weights);
  return build_path(P, pose, w_next, R, c, detail::heading_of_theta(wrap_to_two_pi(theta), detail::second_direction(c)),
                    weights);
}

TurningPoint turning_point(const Configuration& pose, const Vec2& w_next, const Vec2& w_after, double R,
                           const FuelWeights& weights) {
  validate_horizon(pose, w_next, w_after, R, weights);
  const HorizonProblem P(pose, w_next, w_after, R, weights);
  Solver solver(P);
  // With w_a = w_s, |dF/dh| <= 2 w_s (units of R): a lower bound of F between two samples.
  const bool lipschitz = weights.arc == weights.straight;
  const double slope_bound = 2.0 * weights.straight;

  // Fixed-size, uninitialised buffers: no allocation or clearing per solve.
  constexpr std::size_t kMaxSamples = kSamples + 8;
  std::array<Best, kTurnCaseCount> per_case{};
  std::array<Bracket, kTurnCaseCount * kMaxSamples> brackets;
  std::size_t bracket_count = 0;
  std::array<std::array<Sample, kMaxSamples>, kTurnCaseCount> samples;
  std::array<std::size_t, kTurnCaseCount> counts{};
  // The uniform samples, all four cases at once (they share the frame and the exit parts).
  for (int k = 0; k < kSamples; ++k) {
    const double h = kTwoPi * k / kSamples;
    std::array<HorizonEval, kTurnCaseCount> e;
    solver.eval_cases(h, e.data());
    for (std::size_t c = 0; c < kTurnCaseCount; ++c) samples[c][counts[c]++] = {h, e[c]};
  }
  auto pair = [&](const Bracket& br) {  // the bracket's two samples, the second unwrapped
    const auto& s = samples[static_cast<std::size_t>(br.c)];
    const std::size_t n = counts[static_cast<std::size_t>(br.c)];
    Sample a = s[br.i], b = s[(br.i + 1u) % n];
    if (br.i + 1u == n) b.h += kTwoPi;
    return std::make_pair(a, b);
  };
  for (int c = 0; c < kTurnCaseCount; ++c) {
    const auto tc = static_cast<TurnCase>(c);
    const int d1 = detail::first_direction(tc), d2 = detail::second_direction(tc);
    auto& mine = samples[static_cast<std::size_t>(c)];
    std::size_t& count = counts[static_cast<std::size_t>(c)];
    std::array<double, 4> edges{};
    const int edge_count = feasibility_edges(P, d1, d2, edges);
    // An edge sample on each side: the feasible one carries the boundary value.
    for (int k = 0; k < edge_count; ++k)
      for (double side : {-1e-12, 1e-12}) {
        const double h = wrap_to_two_pi(edges[static_cast<std::size_t>(k)] + side);
        mine[count++] = {h, solver.eval(d1, d2, h)};
      }
    if (edge_count > 0)
      for (std::size_t i = kSamples; i < count; ++i)  // insertion into the sorted uniform samples
        for (std::size_t j = i; j > 0 && mine[j].h < mine[j - 1].h; --j) std::swap(mine[j], mine[j - 1]);
    for (std::size_t i = 0; i < count; ++i)
      if (mine[i].e.ok) solver.offer(per_case[static_cast<std::size_t>(c)], mine[i].e.value, mine[i].h, c);
    for (std::size_t i = 0; i < count; ++i) {
      const Bracket probe{0.0, c, static_cast<std::uint8_t>(i), false};
      const auto [a, b] = pair(probe);
      if (!a.e.ok || !b.e.ok || b.h - a.h <= 0.0) continue;
      const int wrap_count = (std::abs(a.e.t - b.e.t) > kPi) + (std::abs(a.e.q - b.e.q) > kPi) +
                             (std::abs(a.e.a - b.e.a) > kPi);
      const bool wraps = wrap_count > 0;
      if (!wraps && !(a.e.slope < 0.0 && b.e.slope > 0.0)) continue;
      const double width = b.h - a.h;
      // Lipschitz bound on each smooth piece. One wrap: each piece touches a sample. Two or more
      // (e.g. T_n and the exit both crossing W_n): a middle piece can sit 2 pi w_a below both
      // samples (a loop lost by one arc before the other gains it): no bound, always refined.
      double bound = -std::numeric_limits<double>::infinity();
      if (lipschitz && wrap_count <= 1)
        bound = wraps ? std::min(a.e.value, b.e.value) - slope_bound * width
                      : 0.5 * (a.e.value + b.e.value) - 0.5 * slope_bound * width;
      brackets[bracket_count++] = {bound, c, static_cast<std::uint8_t>(i), wraps};
    }
  }
  Best best;
  for (const Best& b : per_case)
    if (b.value < best.value) best = b;
  const auto end = brackets.begin() + static_cast<std::ptrdiff_t>(bracket_count);
  std::sort(brackets.begin(), end, [](const Bracket& x, const Bracket& y) { return x.bound < y.bound; });
  for (auto it = brackets.begin(); it != end; ++it) {
    const Bracket& br = *it;
    if (br.bound >= best.value) break;
    const auto [a, b] = pair(br);
    const auto tc = static_cast<TurnCase>(br.c);
    const int d1 = detail::first_direction(tc), d2 = detail::second_direction(tc);
    Best& mine = per_case[static_cast<std::size_t>(br.c)];
    if (!br.wraps) {
      solver.smooth_minimum(mine, br.c, d1, d2, a, b);
    } else {
      // Wrap edges split the bracket into smooth pieces; F at an edge is the low side's limit.
      std::array<Sample, 5> cuts;
      std::size_t n_cuts = 0;
      cuts[n_cuts++] = a;
      for (int k = 0; k < 3; ++k) {
        const double h = solver.wrap_edge(d1, d2, k, a, b);
        if (std::isnan(h)) continue;
        const HorizonEval e = solver.eval(d1, d2, h);
        if (!e.ok) continue;
        solver.offer(mine, e.value, h, br.c);
        cuts[n_cuts++] = {h, e};
      }
      cuts[n_cuts++] = b;
      for (std::size_t i = 1; i < n_cuts; ++i)  // insertion sort of at most five
        for (std::size_t j = i; j > 0 && cuts[j].h < cuts[j - 1].h; --j) std::swap(cuts[j], cuts[j - 1]);
      for (std::size_t i = 0; i + 1 < n_cuts; ++i)
        if (cuts[i + 1].h > cuts[i].h) solver.smooth_minimum(mine, br.c, d1, d2, cuts[i], cuts[i + 1]);
    }
    if (mine.value < best.value) best = mine;
  }

  TurningPoint out;
  for (int c = 0; c < kTurnCaseCount; ++c) {
    const Best& b = per_case[static_cast<std::size_t>(c)];
    const int d2 = detail::second_direction(static_cast<TurnCase>(c));
    out.case_lengths[static_cast<std::size_t>(c)] = R * b.value;
    out.case_thetas[static_cast<std::size_t>(c)] =
        b.c < 0 ? std::numeric_limits<double>::quiet_NaN() : detail::theta_of_heading(b.h, d2);
  }
  if (best.c < 0)
    detail::fail_field("w_after", "(" + detail::to_text(w_after.x()) + ", " + detail::to_text(w_after.y()) + ")",
                       "no horizon path exists (W_{n+1} within R of every circle through W_n)");
  static_cast<HorizonPath&>(out) = build_path(P, pose, w_next, R, static_cast<TurnCase>(best.c), best.h, weights);
  out.evaluations = solver.evaluations();
  return out;
}

}  // namespace vistrack
