// The roll model (vehicle.hpp): the bank as a first-order, rate-limited
// response to the coordinated bank of the guidance's turn rate.
#include <algorithm>
#include <cmath>

#include "vistrack/error.hpp"
#include "vistrack/geometry.hpp"
#include "vistrack/vehicle.hpp"

namespace vistrack {

double coordinated_bank(double speed, double turn_rate, double gravity) {
  require_finite(speed, "speed");
  require_finite(turn_rate, "turn_rate");
  require_positive(gravity, "gravity");
  return std::atan(speed * turn_rate / gravity);
}

RollModel::RollModel(const Uav& vehicle, double gravity)
    : speed_(vehicle.speed),
      gravity_(gravity),
      tau_(vehicle.roll_time_constant),
      max_rate_(vehicle.max_roll_rate_deg_s * kPi / 180.0),
      max_bank_(std::atan(vehicle.speed * vehicle.speed / (gravity * vehicle.min_turn_radius))) {
  vehicle.validate();
  require_positive(gravity, "gravity");
}

double RollModel::bank_command(double turn_rate) const {
  return std::clamp(std::atan(speed_ * turn_rate / gravity_), -max_bank_, max_bank_);
}

double RollModel::bank_rate(double bank, double bank_command) const {
  return std::clamp((bank_command - bank) / tau_, -max_rate_, max_rate_);
}

double RollModel::turn_rate(double bank) const { return gravity_ * std::tan(bank) / speed_; }

double RollModel::step(double bank, double bank_command, double dt) const {
  const double error = bank_command - bank;
  const double direction = error < 0.0 ? -1.0 : 1.0;
  const double saturated_error = max_rate_ * tau_;  // beyond it the rate limit holds
  double remaining = dt;
  double next = bank;
  if (std::abs(error) > saturated_error) {
    const double ramp_time = (std::abs(error) - saturated_error) / max_rate_;
    if (dt <= ramp_time) return bank + direction * max_rate_ * dt;
    next = bank_command - direction * saturated_error;
    remaining = dt - ramp_time;
  }
  return bank_command - (bank_command - next) * std::exp(-remaining / tau_);
}

}  // namespace vistrack
