// The baseline follower: the tracking paper's vector field (74) and steering law (86) about the
// offset point at a constant radius, flown by the flight layer.
#include <cmath>

#include "vistrack/error.hpp"
#include "vistrack/follow.hpp"
#include "run_samples.hpp"

namespace vistrack {

OrbitFollower::OrbitFollower(const GroundVehicle& vehicle, const FollowPlanner& offsets, const GuidanceGains& gains,
                             double radius)
    : vehicle_(vehicle), offsets_(offsets), gains_(gains), radius_(radius) {
  gains_.validate();
  require_positive(radius_, "radius");
}

GuidanceCommand OrbitFollower::command(const Configuration& state, double t) const {
  OrbitState orbit;
  orbit.center = vehicle_.position(t) + offsets_.offset_vector(vehicle_.heading(t));
  orbit.center_velocity = vehicle_.velocity(t);
  orbit.radius = radius_;
  GuidanceCommand c;
  c.turn_rate = steering(Vec3(state.x, state.y, state.psi), orbit, gains_).command;
  c.target = orbit.center;
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
  const FollowPlanner offsets(parameters, uav);  // only its offset vector
  const GuidanceGains gains = GuidanceGains::from(uav, control);
  OrbitFollower guidance(vehicle, offsets, gains, radius);
  // After the cheap checks: the field precomputes its gusts, and checks the wind against the airspeed.
  const WindField wind(true_wind, uav.speed, t0, duration);

  Configuration start;
  if (options.start) {
    start = {options.start->x(), options.start->y(), options.start->z()};
  } else {
    // On the orbit at the vehicle's heading, heading along the field there.
    const double heading = vehicle.heading(t0);
    const Vec2 center = vehicle.position(t0) + offsets.offset_vector(heading);
    const Vec2 p = center + radius * Vec2(std::cos(heading), std::sin(heading));
    OrbitState orbit{center, vehicle.velocity(t0), radius, 0.0};
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
  for (std::size_t i = 0; i < n; ++i) {
    const auto r = static_cast<Eigen::Index>(i);
    const double t = trajectory.t[i];
    const Vec2 g = vehicle.position(t);
    const Vec2 o = g + offsets.offset_vector(vehicle.heading(t));
    const Vec2 p(trajectory.x[i], trajectory.y[i]);
    const double d = (p - o).norm();
    run.state.row(r) << p.x(), p.y(), trajectory.psi[i];
    run.vehicle.row(r) = g.transpose();
    run.offset_point.row(r) = o.transpose();
    const Vec2 nearest = d > 0.0 ? Vec2(o + radius * (p - o) / d) : Vec2(o + Vec2(radius, 0.0));
    run.desired.row(r) = nearest.transpose();
    run.target.row(r) = o.transpose();
    run.wind.row(r) << trajectory.wind_east[i], trajectory.wind_north[i];
  }
  score_follow_run(run, uav, options.camera, options.path_window);
  return run;
}

}  // namespace vistrack
