// The vehicle's turning models (Uav::dynamics, dubins_parameters.hpp): the bank of a coordinated
// turn and the roll model, shared by the flight layer (flight.hpp) and the tracking closed loop
// (simulate.hpp).
#pragma once

#include "vistrack/dubins_parameters.hpp"

namespace vistrack {

// Bank angle of a coordinated turn at speed v and turn rate psi_dot: atan(v psi_dot / g) (rad,
// positive: left wing down, turning left).
double coordinated_bank(double speed, double turn_rate, double gravity = kStandardGravity);

// The roll model of Uav::dynamics (dubins_parameters.hpp) for one vehicle: a bank command from the
// guidance's turn rate, the bank's response to it, and the turn rate the bank gives.
class RollModel {
 public:
  explicit RollModel(const Uav& vehicle, double gravity = kStandardGravity);

  double max_bank() const { return max_bank_; }  // phi_max = atan(v^2 / (g R))
  double time_constant() const { return tau_; }
  double max_roll_rate() const { return max_rate_; }  // rad/s
  // phi_c = atan(v r / g), within +-phi_max (r within +-v/R gives exactly that range).
  double bank_command(double turn_rate) const;
  // phi_dot = clamp((phi_c - phi) / tau, -p_max, p_max).
  double bank_rate(double bank, double bank_command) const;
  // psi_dot = g tan(phi) / v.
  double turn_rate(double bank) const;
  // The bank after dt with the command held: the closed-form solution of phi_dot above (a ramp at
  // p_max while |phi_c - phi| > p_max tau, then the exponential approach).
  double step(double bank, double bank_command, double dt) const;

 private:
  double speed_, gravity_, tau_, max_rate_, max_bank_;
};

}  // namespace vistrack
