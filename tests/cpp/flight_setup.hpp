#pragma once
// Shared setup of the flight layer's tests (flight_test.cpp, flight_dynamics_test.cpp).
#include "vistrack/flight.hpp"

namespace vistrack::flight_setup {

inline Uav vehicle(double speed, double radius, DynamicsModel dynamics = DynamicsModel::Dubins) {
  Uav uav;
  uav.speed = speed;
  uav.min_turn_radius = radius;
  uav.dynamics = dynamics;
  return uav;
}

inline FlightOptions options(FlightIntegration integration, double dt, double max_time) {
  FlightOptions o;
  o.integration = integration;
  o.dt = dt;
  o.max_time = max_time;
  return o;
}

}  // namespace vistrack::flight_setup
