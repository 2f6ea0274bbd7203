// Closed-loop simulation of section VI: the vehicle (1) under the steering law (86), turning at
// once (Dubins) or through its bank (the flight layer's roll model).
#include "vistrack/simulate.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "vistrack/error.hpp"
#include "vistrack/vehicle.hpp"
#include "vistrack/limits.hpp"

namespace vistrack {

namespace {

double plan_end(const OrbitPlan& plan) { return std::min(plan.times.back(), plan.poi.duration()); }

void validate_plan(const OrbitPlan& plan, const Uav& uav) {
  if (plan.times.size() < 2)
    detail::fail_field("plan.times", plan.times.size(), "a plan needs at least two samples");
  if (plan.radii.size() != plan.times.size())
    detail::fail_field("plan.radii", plan.radii.size(),
                       "must have one radius per time (" + std::to_string(plan.times.size()) + ")");
  for (std::size_t k = 0; k < plan.times.size(); ++k) {
    require_finite(plan.times[k], "plan.times[" + std::to_string(k) + "]");
    require_length(plan.radii[k], "plan.radii[" + std::to_string(k) + "]");
    if (k > 0 && !(plan.times[k] > plan.times[k - 1]))
      detail::fail_field("plan.times[" + std::to_string(k) + "]", plan.times[k], "times must increase");
  }
  if (!(plan_end(plan) > plan.times.front()))
    detail::fail_field("plan.times[0]", plan.times.front(), "the plan starts after the POI path ends");
  const double poi_speed = plan.poi.speed();
  if (!(uav.speed > poi_speed))
    detail::fail_field("uav.speed", uav.speed,
                       "must exceed the POI speed " + detail::to_text(poi_speed) + " to orbit it");
  // Lemma 5: |R_dot| <= v - v_g on every segment, or no constant-speed vehicle can follow it.
  const double limit = uav.speed - poi_speed;
  const RadiusProfile profile = plan.profile();
  if (profile.smooth()) {
    profile.validate();
    if (!(profile.min_radius() > 0.0))
      detail::fail_field("plan.reference.radii", profile.min_radius(), "the smooth R(t) must stay positive");
    // dR/dt is linear between knots: its largest magnitude is at a knot.
    for (std::size_t k = 0; k < profile.times.size(); ++k)
      if (std::abs(profile.rates[k]) > limit * (1.0 + 1e-9) + 1e-12)
        detail::fail_field("plan.reference.rates[" + std::to_string(k) + "]", profile.rates[k],
                           "exceeds v - v_g = " + detail::computed_text(limit) + " (Lemma 5)");
    return;
  }
  for (std::size_t k = 0; k + 1 < plan.times.size(); ++k) {
    const double rate = (plan.radii[k + 1] - plan.radii[k]) / (plan.times[k + 1] - plan.times[k]);
    if (std::abs(rate) > limit * (1.0 + 1e-9) + 1e-12)
      detail::fail_field("plan.radii[" + std::to_string(k + 1) + "]", plan.radii[k + 1],
                         "dR/dt = " + detail::computed_text(rate) + " on segment " + std::to_string(k) +
                             " exceeds v - v_g = " + detail::computed_text(limit) + " (Lemma 5)");
  }
}

std::vector<double> output_times(double t0, double t1, double step) {
  std::vector<double> times;
  const double count = std::floor((t1 - t0) / step + 1e-9);
  if (count > 5e7) detail::fail_field("simulation.output_step", step, "too many output samples for the span");
  const auto n = static_cast<std::size_t>(count);
  times.reserve(n + 2);
  for (std::size_t k = 0; k <= n; ++k) times.push_back(t0 + static_cast<double>(k) * step);
  if (t1 - times.back() > 1e-9 * step) times.push_back(t1);
  else times.back() = t1;
  return times;
}

// The integrated state: (x, y, psi), and the bank phi with the roll model (N = 4).
template <int N>
SimulationResult closed_loop(const OrbitPlan& plan, const Uav& uav, const Vec3& x0, const Control& control,
                             const SimulationOptions& options, double fixed_step) {
  using State = OdeVector<N>;
  uav.validate();
  control.validate();
  options.validate();
  if (fixed_step != 0.0) require_in_range(fixed_step, 1e-9, 1e9, "s (or 0: adaptive steps)", "fixed_step");
  require_coordinate(x0[0], "x0[0]");
  require_coordinate(x0[1], "x0[1]");
  require_angle(x0[2], "x0[2]");
  validate_plan(plan, uav);
  // The step count is known before the work starts: refuse what would hit the integrator's limit.
  const double span = plan_end(plan) - plan.times.front();
  const double smallest_step = fixed_step > 0.0 ? fixed_step : options.max_step;
  if (span / smallest_step > 1e8)
    detail::fail_field(fixed_step > 0.0 ? "fixed_step" : "simulation.max_step", smallest_step,
                       "takes more than 1e8 steps over the plan's " + detail::computed_text(span) + " s");
  const GuidanceGains gains = GuidanceGains::from(uav, control);
  const RollModel roll(uav);

  const std::vector<double> boundaries = segment_boundaries(plan);
  const std::vector<double> outputs = output_times(boundaries.front(), boundaries.back(), options.output_step);

  OdeOptions ode;
  ode.rtol = options.rtol;
  ode.atol = options.atol;
  ode.max_step = options.max_step;
  ode.fixed_step = fixed_step;

  SimulationResult result;
  result.restart_times = boundaries;
  std::vector<State> states;
  std::vector<double> sample_segment;  // segment start each sample was produced in
  states.reserve(outputs.size());
  result.t.reserve(outputs.size());

  State y = State::Zero();  // the roll model starts level
  y.template head<3>() = x0;
  auto next_output = outputs.begin();
  for (std::size_t i = 0; i + 1 < boundaries.size(); ++i) {
    const double a = boundaries[i];
    const double b = boundaries[i + 1];
    // Constant over the segment: POI velocity and d2R/dt2 (0 on the paper's locus); g linear and
    // R quadratic from their values at a.
    const Vec2 g_a = plan.poi.position(a).head<2>();
    const Vec2 g_dot = plan.poi.velocity(a);
    const double radius_a = plan.radius(a);
    const double radius_rate = plan.radius_rate(a);
    const double radius_acceleration = plan.radius_acceleration(a);
    const double v = uav.speed;
    auto rhs = [&](double t, const State& q, State& dq) {
      OrbitState orbit;
      const double dt = t - a;
      orbit.center = g_a + g_dot * dt;
      orbit.center_velocity = g_dot;
      orbit.radius = radius_a + (radius_rate + 0.5 * radius_acceleration * dt) * dt;
      orbit.radius_rate = radius_rate + radius_acceleration * dt;
      orbit.radius_acceleration = radius_acceleration;
      const double c = std::cos(q[2]);
      const double s = std::sin(q[2]);
      dq[0] = v * c;  // (1)
      dq[1] = v * s;
      const double command = steering_command(q.template head<3>(), c, s, orbit, gains);
      if constexpr (N == 4) {
        dq[2] = roll.turn_rate(q[3]);
        dq[3] = roll.bank_rate(q[3], roll.bank_command(command));
      } else {
        dq[2] = command;
      }
    };
    // Samples in this segment, and always its end b: the state there starts the next segment.
    std::vector<double> t_eval;
    while (next_output != outputs.end() && *next_output <= b) t_eval.push_back(*next_output++);
    const bool end_is_output = !t_eval.empty() && t_eval.back() == b;
    if (!end_is_output) t_eval.push_back(b);
    const OdeResult<N> segment = solve_ode<N>(rhs, a, b, y, ode, t_eval);
    y = segment.y.back();
    const std::size_t kept = end_is_output ? segment.t.size() : segment.t.size() - 1;
    for (std::size_t k = 0; k < kept; ++k) {
      result.t.push_back(segment.t[k]);
      states.push_back(segment.y[k]);
      sample_segment.push_back(a);
    }
    result.statistics += segment.statistics;
  }

  const std::size_t n = result.t.size();
  result.state.resize(static_cast<Eigen::Index>(n), 3);
  result.poi.resize(static_cast<Eigen::Index>(n), 3);
  result.desired_heading.resize(n);
  result.desired_heading_rate.resize(n);
  result.radial_error.resize(n);
  result.heading_error.resize(n);
  result.control.resize(n);
  result.control_unsaturated.resize(n);
  result.orbit_radius.resize(n);
  result.bank.resize(n);
  result.turn_rate.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const auto row = static_cast<Eigen::Index>(k);
    const OrbitState orbit = orbit_state(plan, sample_segment[k], result.t[k]);
    const Vec3 q = states[k].template head<3>();
    const Steering s = steering(q, orbit, gains);
    result.state.row(row) = q.transpose();
    if constexpr (N == 4) {
      result.bank[k] = states[k][3];
      result.turn_rate[k] = roll.turn_rate(states[k][3]);
    } else {
      result.bank[k] = coordinated_bank(uav.speed, s.command);
      result.turn_rate[k] = s.command;
    }
    result.poi.row(row) = plan.poi.position(result.t[k]).transpose();
    result.desired_heading[k] = s.field.heading;
    result.desired_heading_rate[k] = s.field.heading_rate;
    result.radial_error[k] = s.field.radial_error;
    result.heading_error[k] = s.heading_error;
    result.control[k] = s.command;
    result.control_unsaturated[k] = s.unsaturated;
    result.orbit_radius[k] = orbit.radius;
  }
  return result;
}

}  // namespace

std::vector<double> segment_boundaries(const OrbitPlan& plan) {
  const double t0 = plan.times.front();
  const double t1 = plan_end(plan);
  std::vector<double> times{t0, t1};
  for (double t : plan.knot_times())
    if (t > t0 && t < t1) times.push_back(t);
  for (double t : plan.poi.node_times())
    if (t > t0 && t < t1) times.push_back(t);
  std::sort(times.begin(), times.end());
  // Boundaries closer than this are one boundary (a plan sample placed on a path node).
  const double merge = 1e-9 * std::max(1.0, t1 - t0);
  std::vector<double> unique;
  for (double t : times)
    if (unique.empty() || t - unique.back() > merge) unique.push_back(t);
  if (unique.back() != t1) unique.back() = t1;
  return unique;
}

OrbitState orbit_state(const OrbitPlan& plan, double segment_start, double t) {
  // Within a segment g is exactly linear (Definition 1) and R linear (Definition 2) or quadratic
  // (the smooth locus), so they are evaluated from the segment start with the segment's rates: no
  // clamping or switching inside a step.
  const Vec2 g0 = plan.poi.position(segment_start).head<2>();
  const double s = t - segment_start;
  OrbitState orbit;
  orbit.center_velocity = plan.poi.velocity(segment_start);
  orbit.center = g0 + orbit.center_velocity * s;
  orbit.radius_acceleration = plan.radius_acceleration(segment_start);
  orbit.radius_rate = plan.radius_rate(segment_start) + orbit.radius_acceleration * s;
  orbit.radius = plan.radius(segment_start) + (plan.radius_rate(segment_start) + 0.5 * orbit.radius_acceleration * s) * s;
  return orbit;
}

namespace {

SimulationResult closed_loop_for(const OrbitPlan& plan, const Uav& uav, const Vec3& x0, const Control& control,
                                 const SimulationOptions& options, double fixed_step) {
  if (uav.dynamics == DynamicsModel::Roll) return closed_loop<4>(plan, uav, x0, control, options, fixed_step);
  return closed_loop<3>(plan, uav, x0, control, options, fixed_step);
}

// The scene's occlusion-ray line of sight as a LineOfSight.
LineOfSight scene_line_of_sight(const VisibilityScene& scene) {
  return [scene](const Points3& from, const Points3& to) {
    // The POI stands where the planner put it: on the surface where its path z is underground.
    Points3 poi(to.rows(), 3);
    for (Eigen::Index i = 0; i < to.rows(); ++i) poi.row(i) = scene.poi_on_surface(to.row(i).transpose()).transpose();
    const std::vector<bool> visible = scene.line_of_sight(from, poi);
    return std::vector<std::uint8_t>(visible.begin(), visible.end());
  };
}

// Fills result.visible / visibility_fraction: UAV at (x, y, uav_z), POI at g(t).
void evaluate_visibility(SimulationResult& result, double uav_z, const LineOfSight& line_of_sight) {
  require_finite(uav_z, "uav_z");
  if (!line_of_sight) throw Error("line_of_sight: no line-of-sight function given");
  const Eigen::Index n = result.state.rows();
  Points3 from(n, 3);
  from.leftCols<2>() = result.state.leftCols<2>();
  from.col(2).setConstant(uav_z);
  result.visible = line_of_sight(from, result.poi);
  if (result.visible.size() != static_cast<std::size_t>(n))
    detail::fail_field("line_of_sight", result.visible.size(),
                       "returned a different number of answers than the " + std::to_string(n) + " samples");
  std::size_t count = 0;
  for (std::uint8_t v : result.visible) count += v != 0;
  result.visibility_fraction = n > 0 ? static_cast<double>(count) / static_cast<double>(n) : 0.0;
}

}  // namespace

SimulationResult simulate(const OrbitPlan& plan, const Uav& uav, const Vec3& x0, const Control& control,
                          const SimulationOptions& options, const LineOfSight& line_of_sight,
                          double fixed_step) {
  SimulationResult result = closed_loop_for(plan, uav, x0, control, options, fixed_step);
  if (line_of_sight) evaluate_visibility(result, uav.altitude, line_of_sight);
  return result;
}

SimulationResult simulate(const OrbitPlan& plan, const Uav& uav, const Vec3& x0, const Control& control,
                          const SimulationOptions& options, const VisibilityScene& scene, double fixed_step) {
  uav.validate();
  // As the planner requires (OrbitPlanner::plan): a flight plane under the ground sees nothing.
  if (!(uav.altitude > scene.ground_level()))
    detail::fail_field("uav.altitude", uav.altitude,
                       "the flight plane must lie above the ground level " + detail::to_text(scene.ground_level()));
  SimulationResult result = closed_loop_for(plan, uav, x0, control, options, fixed_step);
  evaluate_visibility(result, uav.altitude, scene_line_of_sight(scene));
  return result;
}

}  // namespace vistrack
