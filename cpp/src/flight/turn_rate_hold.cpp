// TurnRateHold: a guidance that holds the turn rate it was last given (flight.hpp).
#include "vistrack/error.hpp"
#include "vistrack/flight.hpp"

namespace vistrack {

void TurnRateHold::set_turn_rate(double turn_rate) {
  require_finite(turn_rate, "turn_rate");
  if (turn_rate != rate_) touch();  // continuous flight restarts its integrator on the new command
  rate_ = turn_rate;
}

GuidanceCommand TurnRateHold::command(const Configuration& state, double /*t*/) const {
  return {rate_, Vec2(state.x, state.y), -1};
}

}  // namespace vistrack
