// One WN or DWN flight on the flight layer, with its metrics.
#include <cmath>
#include <memory>

#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"
#include "vistrack/waypoint_nav.hpp"

namespace vistrack {

namespace {

void validate_route(const std::vector<Vec2>& waypoints, const Configuration& start, double R) {
  if (waypoints.empty()) detail::fail_field("waypoints", 0, "at least one waypoint to fly to is needed");
  for (std::size_t k = 0; k < waypoints.size(); ++k) {
    const std::string field = "waypoints[" + std::to_string(k) + "]";
    require_coordinate(waypoints[k].x(), field + ".x");
    require_coordinate(waypoints[k].y(), field + ".y");
    if (k > 0 && (waypoints[k] - waypoints[k - 1]).norm() < 1e-9 * R)
      detail::fail_field(field, "(" + detail::to_text(waypoints[k].x()) + ", " + detail::to_text(waypoints[k].y()) + ")",
                         "closer than 1e-9 R to waypoints[" + std::to_string(k - 1) + "]");
  }
  require_coordinate(start.x, "start.x");
  require_coordinate(start.y, "start.y");
  require_angle(start.psi, "start.psi");
}

// navigation_time_limit on inputs already validated.
double time_limit(const std::vector<Vec2>& waypoints, const Configuration& start, const WaypointNavOptions& options) {
  if (options.max_time) return *options.max_time;
  double route = (waypoints.front() - Vec2(start.x, start.y)).norm();
  for (std::size_t k = 1; k < waypoints.size(); ++k) route += (waypoints[k] - waypoints[k - 1]).norm();
  return 3.0 * (route + kTwoPi * options.turn_radius * static_cast<double>(waypoints.size())) / options.speed;
}

}  // namespace

std::unique_ptr<FlightGuidance> navigation_guidance(const std::vector<Vec2>& waypoints, const Configuration& start,
                                                    const WaypointNavOptions& options, const Wind& wind) {
  options.validate();  // the wind is checked by fly(), against the airspeed
  const double R = options.turn_radius;
  validate_route(waypoints, start, R);
  // Continuous flight smooths sign(phi_T) (see LineFeedback).
  LineFeedback law5(options.speed, R, options.dt, options.gains, options.integration == FlightIntegration::Continuous);
  L1Line l1(options.speed, options.l1);
  if (options.wind_aware) {
    const Vec2 mean(wind.east, wind.north);  // the known wind: its constant part, not the gusts
    law5.set_wind(mean);
    l1.set_wind(mean);
  }
  const bool by_l1 = options.guidance == LegGuidance::L1;
  if (options.method == NavigationMethod::Dubins) {
    auto dwn = by_l1 ? std::make_unique<DubinsWaypointGuidance>(l1, waypoints, R, options.weights)
                     : std::make_unique<DubinsWaypointGuidance>(law5, waypoints, R, options.weights);
    if (options.wind_aware) dwn->set_wind(Vec2(wind.east, wind.north), options.speed);
    dwn->set_replan_interval(options.replan_interval);
    if (options.resolved_tracking() == DwnTracking::Path) {
      PathFollowingGains gains = options.path_gains;
      gains.anticipation = options.path_anticipation.value_or(options.roll_lag());
      dwn->set_path_following(gains, options.speed);
    }
    return dwn;
  }
  const double acceptance = options.waypoint_radius.value_or(R);
  auto follower = by_l1 ? std::make_unique<WaypointFollower>(l1, waypoints, acceptance)
                        : std::make_unique<WaypointFollower>(law5, waypoints, acceptance);
  follower->set_passed_line(options.method == NavigationMethod::PassedLine);
  follower->set_finish_line(true);  // the flight ends past the last waypoint's line, as DWN's
  return follower;
}

double navigation_time_limit(const std::vector<Vec2>& waypoints, const Configuration& start,
                             const WaypointNavOptions& options) {
  options.validate();
  validate_route(waypoints, start, options.turn_radius);
  return time_limit(waypoints, start, options);
}

NavigationResult navigate(const std::vector<Vec2>& waypoints, const Configuration& start,
                          const WaypointNavOptions& options, const Wind& wind) {
  const std::unique_ptr<FlightGuidance> guidance = navigation_guidance(waypoints, start, options, wind);
  NavigationResult result;
  result.method = options.method;
  if (options.method != NavigationMethod::Dubins)
    result.waypoint_radius = options.waypoint_radius.value_or(options.turn_radius);
  result.max_time = time_limit(waypoints, start, options);  // validated by navigation_guidance
  FlightOptions flight;
  flight.integration = options.integration;
  flight.dt = options.dt;
  flight.max_time = result.max_time;
  result.trajectory = fly(options.vehicle(), wind, *guidance, start, flight);
  if (const auto* dwn = dynamic_cast<const DubinsWaypointGuidance*>(guidance.get()))
    result.turning_points = dwn->turning_points();
  result.metrics = navigation_metrics(result.trajectory, Vec2(start.x, start.y), waypoints, options.speed,
                                      options.turn_radius, options.weights);
  return result;
}

}  // namespace vistrack
