// Shortest path to a point on a circle with tangent heading (Section III) and the optimal
// intercept of a target moving on that circle (Section IV, Algorithm 1).
#include <algorithm>
#include <cmath>
#include <limits>

#include "dubins/kernel.hpp"
#include "dubins/validate.hpp"
#include "vistrack/dubins.hpp"
#include "vistrack/error.hpp"

namespace vistrack {

Configuration TargetCircle::configuration(double angle) const {
  const double c = std::cos(angle), s = std::sin(angle);
  // Clockwise travel: heading alpha - pi/2 (Section III); counter-clockwise: alpha + pi/2.
  const double heading = direction == CircleDirection::Clockwise ? angle - 0.5 * kPi : angle + 0.5 * kPi;
  return {center.x() + radius * c, center.y() + radius * s, heading};
}

void TargetCircle::validate() const {
  require_coordinate(center.x(), "center.x");
  require_coordinate(center.y(), "center.y");
  require_length(radius, "radius");
  if (direction != CircleDirection::Clockwise && direction != CircleDirection::CounterClockwise)
    detail::fail_field("direction", static_cast<int>(direction), "unknown direction");
}

DubinsPath dubins_path_to_circle(const Configuration& q0, double rho, const TargetCircle& circle,
                                 double angle) {
  circle.validate();
  require_angle(angle, "angle");
  const Configuration goal = circle.configuration(angle);
  try {
    detail::require_dubins_problem(q0, goal, rho);
  } catch (const Error& error) {
    throw Error(std::string("path to the circle's point at angle ") + detail::computed_text(angle) + ": " + error.what());
  }
  return dubins_shortest_path(q0, goal, rho);
}

double dubins_length_to_circle(const Configuration& q0, double rho, const TargetCircle& circle,
                               double angle) {
  return dubins_path_to_circle(q0, rho, circle, angle).length;
}

double dubins_csc_length_to_circle(const Configuration& q0, double rho, const TargetCircle& circle,
                                   double angle) {
  circle.validate();
  require_angle(angle, "angle");
  const auto lengths = dubins_word_lengths(q0, circle.configuration(angle), rho);
  return std::min(std::min(lengths[0], lengths[1]), std::min(lengths[2], lengths[3]));
}

bool four_rho_condition(const Vec2& p, double rho, const TargetCircle& circle) {
  // Nearest point of the circle to p is at | |p - C| - r | (the paper's assumption, Section I).
  const double gap = std::fabs((p - circle.center).norm() - circle.radius);
  return gap > 4.0 * rho;
}

void InterceptProblem::validate() const {
  detail::require_configuration(pursuer, "pursuer");
  require_length(rho, "rho");
  require_speed(pursuer_speed, "pursuer_speed");
  require_speed(target_speed, "target_speed");
  circle.validate();
  require_angle(target_angle0, "target_angle0");
  require_in_range(angle_tolerance, 1e-15, kPi, "rad", "angle_tolerance");
  // Every point of the circle is a goal: within the coordinate range, and the solver's scale holds
  // for the farthest one.
  for (int k = 0; k < 2; ++k)
    if (!(std::abs(circle.center[k]) + circle.radius <= limits::kMaxCoordinate))
      detail::fail_field("radius", circle.radius,
                         "puts points of the circle outside the coordinate range [-1e7, 1e7] m (centre " +
                             detail::to_text(circle.center[k]) + ")");
  detail::require_dubins_scale(std::max({std::abs(pursuer.x), std::abs(pursuer.y),
                                         std::abs(circle.center.x()) + circle.radius,
                                         std::abs(circle.center.y()) + circle.radius}),
                               rho);
  if (scan_samples < 16 || scan_samples > 10000000)
    detail::fail_field("scan_samples", scan_samples, "must lie in [16, 1e7]");
}

namespace {

// T_p(theta) - T_t(theta) as a function of the swept target angle theta >= 0.
struct TimeGap {
  const InterceptProblem& problem;
  double sign;  // +1 counter-clockwise, -1 clockwise

  double angle(double swept) const { return problem.target_angle0 + sign * swept; }
  double pursuer_time(double swept) const {
    return dubins_shortest_length(problem.pursuer, problem.circle.configuration(angle(swept)), problem.rho) /
           problem.pursuer_speed;
  }
  double target_time(double swept) const { return swept * problem.circle.radius / problem.target_speed; }
  double operator()(double swept) const { return pursuer_time(swept) - target_time(swept); }
};

// argmin over one period of D(alpha): dense scan, then golden section around the best sample.
double argmin_length(const InterceptProblem& problem) {
  const auto length = [&](double alpha) {
    return dubins_shortest_length(problem.pursuer, problem.circle.configuration(alpha), problem.rho);
  };
  const int n = problem.scan_samples;
  const double h = kTwoPi / n;
  int best = 0;
  double best_value = std::numeric_limits<double>::infinity();
  for (int k = 0; k < n; ++k) {
    const double value = length(k * h);
    if (value < best_value) {
      best_value = value;
      best = k;
    }
  }
  double lo = (best - 1) * h, hi = (best + 1) * h;
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = hi - ratio * (hi - lo), b = lo + ratio * (hi - lo);
  double fa = length(a), fb = length(b);
  for (int it = 0; it < 200 && hi - lo > 1e-13; ++it) {
    if (fa < fb) {
      hi = b;
      b = a;
      fb = fa;
      a = hi - ratio * (hi - lo);
      fa = length(a);
    } else {
      lo = a;
      a = b;
      fa = fb;
      b = lo + ratio * (hi - lo);
      fb = length(b);
    }
  }
  double alpha = 0.5 * (lo + hi);
  if (length(alpha) > best_value) alpha = best * h;  // keep the scan's best if refinement lost it
  return detail::mod2pi_snap(alpha, kDubinsSnap);
}

}  // namespace

InterceptResult intercept_circle(const InterceptProblem& problem) {
  problem.validate();
  const double sign = problem.circle.direction == CircleDirection::Clockwise ? -1.0 : 1.0;
  const TimeGap gap{problem, sign};
  InterceptResult result;
  result.four_rho_condition =
      four_rho_condition(Vec2(problem.pursuer.x, problem.pursuer.y), problem.rho, problem.circle);
  // D(alpha) depends on alpha only through cos(alpha) and sin(alpha): its period is exactly 2 pi
  // in alpha, hence 2 pi in the swept angle whatever the direction.
  result.period = kTwoPi;
  result.alpha_min = argmin_length(problem);

  const auto finish = [&](double swept) {
    result.swept_angle = swept;
    result.angle = gap.angle(swept);
    result.time = gap.target_time(swept);
    result.path = dubins_path_to_circle(problem.pursuer, problem.rho, problem.circle, result.angle);
    result.residual = result.path.length / problem.pursuer_speed - result.time;
    return result;
  };
  if (gap(0.0) <= 0.0) return finish(0.0);  // already on the target with its heading

  // Algorithm 1, lines 1-4: alpha_l = alpha_i, alpha_u = the first minimum of D after alpha_i;
  // shift both by one period until T_t(alpha_u) >= T_p(alpha_u). Every earlier window has
  // T_p >= D_min / v_p > T_t throughout, so no interception is missed by skipping it. The
  // number of shifts is computed directly (the loop then only confirms it).
  double upper = detail::mod2pi_snap(sign * (result.alpha_min - problem.target_angle0), kDubinsSnap);
  if (upper <= 0.0) upper = kTwoPi;
  const double d_min = dubins_shortest_length(problem.pursuer, problem.circle.configuration(result.alpha_min),
                                              problem.rho);
  const double swept_needed = d_min / problem.pursuer_speed * problem.target_speed / problem.circle.radius;
  if (!(swept_needed < 1e9))
    detail::fail_field("target_speed", problem.target_speed,
                       "the target would circle more than 1e8 times before the pursuer can reach the circle "
                       "(pursuer_speed = " + detail::to_text(problem.pursuer_speed) + ")");
  int windows = 0;
  if (swept_needed > upper) windows = static_cast<int>(std::floor((swept_needed - upper) / kTwoPi));
  double lower = windows > 0 ? upper + (windows - 1) * kTwoPi : 0.0;
  upper += windows * kTwoPi;
  while (gap(upper) > 0.0) {
    lower = upper;
    upper += kTwoPi;
    ++windows;
  }
  result.bracket_windows = windows;

  // The earliest crossing inside the window: scan for the first sign change, then bisect
  // (Algorithm 1, lines 5-12, stopping on the bracket width rather than on the sign of dt).
  const int n = std::max(16, static_cast<int>(std::ceil(problem.scan_samples * (upper - lower) / kTwoPi)));
  double lo = lower, hi = upper;
  for (int k = 1; k <= n; ++k) {
    const double swept = k == n ? upper : lower + (upper - lower) * k / n;
    if (gap(swept) <= 0.0) {
      hi = swept;
      break;
    }
    lo = swept;
  }
  int steps = 0;
  while (hi - lo > problem.angle_tolerance) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    if (gap(mid) > 0.0)
      lo = mid;
    else
      hi = mid;
    ++steps;
  }
  result.bisection_steps = steps;
  return finish(hi);  // T_p <= T_t at hi: the pursuer can be there in time
}

InterceptTimes intercept_travel_times(const InterceptProblem& problem, const std::vector<double>& swept_angles) {
  problem.validate();
  const double sign = problem.circle.direction == CircleDirection::Clockwise ? -1.0 : 1.0;
  const TimeGap gap{problem, sign};
  InterceptTimes times;
  for (std::size_t k = 0; k < swept_angles.size(); ++k) {
    const double swept = swept_angles[k];
    require_angle(swept, "swept_angles[" + std::to_string(k) + "]");
    times.angles.push_back(gap.angle(swept));
    times.pursuer.push_back(gap.pursuer_time(swept));
    times.target.push_back(gap.target_time(swept));
  }
  return times;
}

}  // namespace vistrack
