// Validation of the flight layer's parameter structs (flight_parameters.hpp).
#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"
#include "vistrack/flight.hpp"
#include "vistrack/flight_parameters.hpp"

namespace vistrack {

void Gusts::validate() const {
  require_non_negative(intensity, "wind.gusts.intensity");
  require_positive(length_scale, "wind.gusts.length_scale");
  require_non_negative(sample_step, "wind.gusts.sample_step");
}

void Wind::validate() const {
  require_in_range(east, -limits::kMaxSpeed, limits::kMaxSpeed, "m/s", "wind.east");
  require_in_range(north, -limits::kMaxSpeed, limits::kMaxSpeed, "m/s", "wind.north");
  if (gusts) gusts->validate();
}

void FlightOptions::validate() const {
  require_positive(dt, "dt");
  require_positive(max_time, "max_time");
  if (max_time / dt > 1e8)
    detail::fail_field("max_time", max_time, "more than 1e8 steps of dt = " + detail::to_text(dt));
  require_tolerances(rtol, atol, "");
}

void PathFollowingGains::validate() const {
  require_positive(lookahead_radii, "gains.lookahead_radii");
  require_positive(heading_gain, "gains.heading_gain");
  require_in_range(anticipation, 0.0, limits::kMaxRollTimeConstant, "s", "gains.anticipation");
}

void L1Gains::validate() const {
  require_in_range(period, 1e-3, 1e4, "s", "gains.period");
  require_in_range(damping, 1e-3, 10.0, "", "gains.damping");
}

void LineFeedbackGains::validate() const {
  require_non_negative(g, "gains.g");
  require_non_negative(h, "gains.h");
}

LineFeedbackGains LineFeedbackGains::for_turn_radius(double turn_radius) {
  require_length(turn_radius, "turn_radius");
  constexpr double kPaperTurnRadius = 0.7;  // section 3 of the waypoint paper
  LineFeedbackGains gains;
  gains.g *= kPaperTurnRadius / turn_radius;
  gains.h *= kPaperTurnRadius / turn_radius;
  return gains;
}

}  // namespace vistrack
