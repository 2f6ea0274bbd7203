// A follow run: the planner's 1 Hz waypoints flown by the flight layer's waypoint follower.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

#include "vistrack/error.hpp"
#include "vistrack/flight.hpp"
#include "vistrack/follow.hpp"
#include "run_samples.hpp"

namespace vistrack {

namespace {

// The follower accepts a waypoint from any distance, so it switches to each new one as soon as
// the planner issues it: it always flies the newest leg (previous waypoint -> newest), never
// back to a stale one.
constexpr double kSwitchAtOnce = std::numeric_limits<double>::max();

// What the planner sees at t: the vehicle as the reports know it, and the UAV.
FollowObservation observe(const VehicleReports& reports, double t, const Vec2& uav, double psi) {
  const VehicleEstimate e = reports.estimate(t);
  FollowObservation o;
  o.vehicle_position = e.position;
  o.vehicle_velocity = e.velocity;
  o.vehicle_heading = e.heading;
  o.lost = e.lost;
  o.uav_position = uav;
  o.uav_heading = psi;
  return o;
}

FollowObservation observe(const GroundVehicle& vehicle, double t, const Vec2& uav, double psi) {
  FollowObservation o;
  o.vehicle_position = vehicle.position(t);
  o.vehicle_velocity = vehicle.velocity(t);
  o.vehicle_heading = vehicle.heading(t);
  o.uav_position = uav;
  o.uav_heading = psi;
  return o;
}

// On the planned path at the first desired position, heading (in the air) along it.
Configuration start_on_plan(const GroundVehicle& vehicle, const Uav& uav, const FollowParameters& parameters,
                            const Vec2& wind_estimate, const Vec2& wind, double t0, const DownwardCamera& camera) {
  FollowPlanner probe(parameters, uav, wind_estimate, camera);
  const double heading = vehicle.heading(t0);
  const Vec2 offset_point = vehicle.position(t0) + probe.offset_vector(heading);
  const FollowTick tick = probe.update(t0, observe(vehicle, t0, offset_point, heading));
  if (tick.mode == FollowMode::Standoff) {
    // On the orbit at the vehicle's heading, heading along the field (74) there: as the baseline.
    const OrbitState orbit{tick.offset_point, tick.offset_velocity, tick.radius, 0.0};
    const Vec2 p = orbit.center + tick.radius * Vec2(std::cos(heading), std::sin(heading));
    return {p.x(), p.y(), vector_field(p, orbit, GuidanceGains::from(uav, Control{})).heading};
  }
  const double h = 0.01;
  const Vec2 p0 = tick.offset_point + probe.relative_position(tick, 0.0);
  const Vec2 p1 = tick.offset_point + vehicle.velocity(t0) * h + probe.relative_position(tick, h);
  const Vec2 air = (p1 - p0) / h - wind;
  return {p0.x(), p0.y(), air.norm() > 0.0 ? std::atan2(air.y(), air.x()) : heading};
}

// The plan flown: the standoff orbit by the tracking paper's steering law (86) on its field (74)
// about the offset point as the reports know it (the baseline's law, OrbitFollower), every other
// pattern by the leg or path follower, which keeps its state throughout.
class PlanGuidance : public FlightGuidance {
 public:
  PlanGuidance(FlightGuidance& legs, OrbitFollower& orbit) : legs_(legs), orbit_(orbit) {}
  void fly_standoff(bool on, double radius) {
    if (on) orbit_.set_radius(radius);
    standoff_ = on;
    touch();
  }
  void start(const Configuration& state, double t) override { legs_.start(state, t); }
  GuidanceCommand command(const Configuration& state, double t) const override {
    return standoff_ ? orbit_.command(state, t) : legs_.command(state, t);
  }
  void advance(const Configuration& state, double t) override { legs_.advance(state, t); }
  bool done() const override { return legs_.done(); }
  double switching_function(const Configuration& state, double t) const override {
    return standoff_ ? std::numeric_limits<double>::infinity() : legs_.switching_function(state, t);
  }
  double next_change_time(double t) const override { return legs_.next_change_time(t); }

 private:
  FlightGuidance& legs_;
  OrbitFollower& orbit_;
  bool standoff_ = false;
};

}  // namespace

FollowRun follow(const GroundVehicle& vehicle, const Uav& uav, const FollowParameters& parameters,
                 const Wind& true_wind, const Vec2& wind_estimate, const FollowRunOptions& options) {
  uav.validate();
  parameters.validate();
  options.validate();
  const double t0 = vehicle.start_time();
  const double duration = options.flight.max_time > 0.0 ? options.flight.max_time : vehicle.end_time() - t0;
  const double period = parameters.update_period;
  if (!(duration / period <= 1e8))  // one tick per update: bound the work and the memory of the run
    detail::fail_field("follow.update_period", period,
                       "more than 1e8 planner updates over the " + detail::computed_text(duration) + " s flight");
  const WindField wind(true_wind, uav.speed, t0, duration);  // checks the wind against the airspeed
  const Vec2 steady(true_wind.east, true_wind.north);

  const Configuration start = options.start
                                  ? Configuration{options.start->x(), options.start->y(), options.start->z()}
                                  : start_on_plan(vehicle, uav, [&] {
                                      FollowParameters at_start = parameters;
                                      std::tie(at_start.offset_distance, at_start.offset_angle) =
                                          detail::scheduled_offset(options.offset_schedule, parameters, t0);
                                      return at_start;
                                    }(), wind_estimate, steady, t0, options.camera);
  FollowPlanner planner(parameters, uav, wind_estimate, options.camera);
  const VehicleReports reports(vehicle, t0, vehicle.end_time(), period, options.reports);
  FollowRun run;
  run.threshold = planner.threshold_choice();

  const LineFeedback law(uav.speed, uav.min_turn_radius, options.flight.dt,
                         LineFeedbackGains::for_turn_radius(uav.min_turn_radius));

  // The planner's update at t with the scheduled offset and its rate over the next update.
  const auto plan = [&](double t, const Vec2& p, double psi) {
    const auto [distance, angle] = detail::scheduled_offset(options.offset_schedule, parameters, t);
    planner.set_offset(distance, angle);
    FollowObservation o = observe(reports, t, p, psi);
    if (!options.offset_schedule.empty()) {
      const auto [d1, a1] = detail::scheduled_offset(options.offset_schedule, parameters, t + period);
      const double heading = o.vehicle_heading;
      const Vec2 now = planner.offset_vector(heading);
      planner.set_offset(d1, a1);
      o.offset_rate = (planner.offset_vector(heading) - now) / period;
      planner.set_offset(distance, angle);
    }
    run.ticks.push_back(planner.update(t, o));
  };
  const Vec2 start_position(start.x, start.y);
  plan(t0, start_position, start.psi);
  // The paper's: one waypoint a second, each leg by the law (5). L1: the planned path itself, three
  // L1 distances ahead, renewed at every update.
  const bool curve = options.flight.guidance == LegGuidance::L1;
  const double horizon = 3.0 * options.flight.l1.damping * options.flight.l1.period / kPi + 2.0 * period;
  const auto planned = [&] { return planner.planned_path(run.ticks.back(), horizon, 0.25); };
  std::optional<WaypointFollower> follower;
  std::optional<CurveL1> path_follower;
  if (curve) path_follower.emplace(uav.speed, planned(), options.flight.l1);
  else follower.emplace(law, std::vector<Vec2>{run.ticks.back().waypoint}, kSwitchAtOnce, false);
  FlightGuidance& legs = curve ? static_cast<FlightGuidance&>(*path_follower) : *follower;
  OrbitFollower orbit(reports, parameters, options.offset_schedule, GuidanceGains::from(uav, Control{}),
                      uav.min_turn_radius);
  PlanGuidance guidance(legs, orbit);
  const auto fly_tick = [&] {
    const FollowTick& tick = run.ticks.back();
    guidance.fly_standoff(tick.mode == FollowMode::Standoff && !tick.lost, tick.radius);
  };
  fly_tick();

  // Every update_period: observe, plan, issue the next waypoint (available at once).
  double next_update = t0 + period;
  const auto on_step = [&](double t, const Configuration& q) {
    if (t < next_update - 1e-9 || t >= vehicle.end_time() - 1e-9) return;  // no update once the track ends
    plan(t, Vec2(q.x, q.y), q.psi);
    if (curve) path_follower->set_path(planned());
    else follower->add_waypoint(run.ticks.back().waypoint, t);
    fly_tick();
    while (next_update <= t + 1e-9) next_update += period;
  };
  FlightOptions flight;
  flight.integration = options.flight.integration;
  flight.dt = options.flight.dt;
  flight.max_time = duration;
  const FlightTrajectory trajectory = fly(uav, wind, guidance, start, flight, t0, on_step);

  // Per sample: the vehicle, the offset point and the desired position of the current update.
  const std::size_t n = trajectory.size();
  detail::size_run_samples(run, trajectory);
  run.mode.resize(n);
  run.capturing.resize(n);
  run.lost.assign(n, 0);
  bool any_lost = false;
  // The pattern of each sample's update, relative to the offset point: one pass per update.
  std::vector<std::size_t> tick_of(n);
  std::vector<Vec2> relative(n);
  for (std::size_t i = 0, k = 0; i < n;) {
    while (k + 1 < run.ticks.size() && run.ticks[k + 1].t <= trajectory.t[i] + 1e-9) ++k;
    std::size_t end = i;
    std::vector<double> taus;
    while (end < n && (k + 1 >= run.ticks.size() || run.ticks[k + 1].t > trajectory.t[end] + 1e-9)) {
      tick_of[end] = k;
      taus.push_back(std::max(0.0, trajectory.t[end] - run.ticks[k].t));
      ++end;
    }
    const std::vector<Vec2> positions = planner.relative_positions(run.ticks[k], taus);
    std::copy(positions.begin(), positions.end(), relative.begin() + static_cast<std::ptrdiff_t>(i));
    i = end;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const auto r = static_cast<Eigen::Index>(i);
    const double t = trajectory.t[i];
    const FollowTick& tick = run.ticks[tick_of[i]];
    const Vec2 g = vehicle.position(t);
    const auto [distance, angle] = detail::scheduled_offset(options.offset_schedule, parameters, t);
    planner.set_offset(distance, angle);
    const Vec2 o = g + planner.offset_vector(vehicle.heading(t));
    run.state.row(r) << trajectory.x[i], trajectory.y[i], trajectory.psi[i];
    run.vehicle.row(r) = g.transpose();
    run.offset_point.row(r) = o.transpose();
    // The pattern about the true offset point; while lost, about the vehicle's estimate.
    const VehicleEstimate known = reports.estimate(t);
    const Vec2 centre = tick.lost ? known.position : o;
    run.desired.row(r) = (centre + relative[i]).transpose();
    run.lost[i] = known.lost ? 1 : 0;
    any_lost = any_lost || known.lost;
    run.target.row(r) << trajectory.target_x[i], trajectory.target_y[i];
    run.wind.row(r) << trajectory.wind_east[i], trajectory.wind_north[i];
    run.mode[i] = static_cast<std::uint8_t>(tick.mode);
    run.capturing[i] = tick.capturing ? 1 : 0;
  }
  if (!any_lost) run.lost.clear();
  score_follow_run(run, uav, options.camera, options.path_window);
  return run;
}

}  // namespace vistrack
