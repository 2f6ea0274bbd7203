// The baseline follower: the tracking paper's vector field (74) and steering law (86) about the
// offset point at a constant radius, flown by the flight layer.
#include <cmath>

#include "vistrack/error.hpp"
#include "vistrack/follow.hpp"
#include "run_samples.hpp"

namespace vistrack {

OrbitFollower::OrbitFollower(const VehicleReports& reports, const FollowParameters& parameters,
                             const std::vector<OffsetKey>& offset_schedule, const GuidanceGains& gains, double radius)
    : reports_(reports), parameters_(parameters), schedule_(offset_schedule), gains_(gains), radius_(radius) {
  gains_.validate();
  require_positive(radius_, "radius");
}

void OrbitFollower::set_radius(double radius) {
  require_positive(radius, "radius");
  if (radius != radius_) touch();
  radius_ = radius;
}

OrbitState OrbitFollower::orbit(double t) const {
  const VehicleEstimate e = reports_.estimate(t);
  OrbitState orbit;
  orbit.radius = radius_;
  orbit.center = e.position;
  orbit.center_velocity = e.velocity;
  if (!e.lost) {
    // The scheduled offset and its rate over the next update, as the planner is told them.
    const double period = parameters_.update_period;
    const Vec2 now = scheduled_offset_vector(schedule_, parameters_, e.heading, t);
    orbit.center += now;
    orbit.center_velocity += (scheduled_offset_vector(schedule_, parameters_, e.heading, t + period) - now) / period;
  }
  return orbit;
}

GuidanceCommand OrbitFollower::command(const Configuration& state, double t) const {
  const OrbitState o = orbit(t);
  GuidanceCommand c;
  c.turn_rate = steering(Vec3(state.x, state.y, state.psi), o, gains_).command;
  c.target = o.center;
  return c;
}

FollowRun orbit_follow(const GroundVehicle& vehicle, const Uav& uav, const Control& control, double radius,
                       const FollowParameters& parameters, const Wind& true_wind, const FollowRunOptions& options) {
  uav.validate();
  control.validate();
  options.validate();
  require_positive(radius, "radius");
  const double t0 = vehicle.start_time();
  const double duration = options.flight.max_time > 0.0 ? options.flight.max_time : vehicle.end_time() - t0;
  if (!(uav.speed > vehicle.max_speed()))
    detail::fail_field("uav.speed", uav.speed,
                       "must exceed the vehicle's top speed " + detail::to_text(vehicle.max_speed()) +
                           " m/s to orbit it (Lemma 5)");
  parameters.validate();
  const GuidanceGains gains = GuidanceGains::from(uav, control);
  const VehicleReports reports(vehicle, t0, vehicle.end_time(), parameters.update_period, options.reports);
  OrbitFollower guidance(reports, parameters, options.offset_schedule, gains, radius);
  // After the cheap checks: the field precomputes its gusts, and checks the wind against the airspeed.
  const WindField wind(true_wind, uav.speed, t0, duration);

  Configuration start;
  if (options.start) {
    start = {options.start->x(), options.start->y(), options.start->z()};
  } else {
    // On the orbit at the vehicle's heading, heading along the field there.
    const double heading = vehicle.heading(t0);
    const OrbitState orbit = guidance.orbit(t0);
    const Vec2 p = orbit.center + radius * Vec2(std::cos(heading), std::sin(heading));
    start = {p.x(), p.y(), vector_field(p, orbit, gains).heading};
  }
  FlightOptions flight;
  flight.integration = options.flight.integration;
  flight.dt = options.flight.dt;
  flight.max_time = duration;
  const FlightTrajectory trajectory = fly(uav, wind, guidance, start, flight, t0);

  FollowRun run;
  const std::size_t n = trajectory.size();
  detail::size_run_samples(run, trajectory);
  run.mode.assign(n, static_cast<std::uint8_t>(FollowMode::Loiter));
  run.lost.assign(n, 0);
  bool any_lost = false;
  for (std::size_t i = 0; i < n; ++i) {
    const auto r = static_cast<Eigen::Index>(i);
    const double t = trajectory.t[i];
    const Vec2 g = vehicle.position(t);
    const Vec2 o = g + scheduled_offset_vector(options.offset_schedule, parameters, vehicle.heading(t), t);
    const Vec2 c = guidance.orbit(t).center;  // where the baseline believes the offset point is
    const Vec2 p(trajectory.x[i], trajectory.y[i]);
    const double d = (p - c).norm();
    run.state.row(r) << p.x(), p.y(), trajectory.psi[i];
    run.vehicle.row(r) = g.transpose();
    run.offset_point.row(r) = o.transpose();
    const Vec2 nearest = d > 0.0 ? Vec2(c + radius * (p - c) / d) : Vec2(c + Vec2(radius, 0.0));
    run.desired.row(r) = nearest.transpose();
    run.target.row(r) = c.transpose();
    run.lost[i] = reports.estimate(t).lost ? 1 : 0;
    any_lost = any_lost || run.lost[i];
    run.wind.row(r) << trajectory.wind_east[i], trajectory.wind_north[i];
  }
  if (!any_lost) run.lost.clear();
  score_follow_run(run, uav, options.camera, options.path_window);
  return run;
}

}  // namespace vistrack
