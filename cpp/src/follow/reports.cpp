// What the UAV knows of the vehicle: its 1 Hz reports with noise, latency and dropouts, and the
// estimate carried along the newest one's velocity (beyond the paper); the scheduled offset.
#include <algorithm>
#include <cmath>
#include <random>

#include "vistrack/error.hpp"
#include "vistrack/follow.hpp"
#include "vistrack/limits.hpp"
#include "run_samples.hpp"

namespace vistrack {

void VehicleReportOptions::validate() const {
  require_in_range(position_noise, 0.0, limits::kMaxLength, "m", "reports.position_noise");
  require_in_range(velocity_noise, 0.0, limits::kMaxSpeed, "m/s", "reports.velocity_noise");
  require_in_range(latency, 0.0, 3600.0, "s", "reports.latency");
  if (!(dropout >= 0.0 && dropout < 1.0))
    detail::fail_field("reports.dropout", dropout, "must be a probability in [0, 1)");
  if (!(timeout > 0.0) || !std::isfinite(timeout))
    detail::fail_field("reports.timeout", timeout, "must be a finite number of seconds > 0");
}

VehicleReports::VehicleReports(const GroundVehicle& vehicle, double t0, double t_end, double period,
                               const VehicleReportOptions& options)
    : options_(options) {
  options_.validate();
  require_finite(t0, "t0");
  require_positive(period, "follow.update_period");
  std::mt19937_64 random(options_.seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const auto count = static_cast<std::size_t>(std::max(0.0, std::floor((t_end - t0) / period + 1e-9))) + 1;
  reports_.reserve(count);
  for (std::size_t k = 0; k < count; ++k) {
    const double t = t0 + static_cast<double>(k) * period;
    // Every draw happens for every report, so a report's noise does not depend on the dropouts.
    const Vec2 dp(normal(random), normal(random));
    const Vec2 dv(normal(random), normal(random));
    const bool dropped = uniform(random) < options_.dropout;
    if (k > 0 && dropped) continue;
    VehicleReport r;
    r.measured = t;
    r.received = k == 0 ? t : t + options_.latency;
    r.position = vehicle.position(t) + (k == 0 ? Vec2::Zero() : Vec2(options_.position_noise * dp));
    r.velocity = vehicle.velocity(t) + (k == 0 ? Vec2::Zero() : Vec2(options_.velocity_noise * dv));
    r.heading = vehicle.heading(t);
    reports_.push_back(r);
  }
}

VehicleEstimate VehicleReports::estimate(double t) const {
  // The newest report received at or before t (the first is received at t0).
  auto it = std::upper_bound(reports_.begin(), reports_.end(), t + 1e-9,
                             [](double time, const VehicleReport& r) { return time < r.received; });
  const VehicleReport& r = it == reports_.begin() ? reports_.front() : *std::prev(it);
  VehicleEstimate e;
  e.age = std::max(0.0, t - r.measured);
  e.position = r.position + r.velocity * e.age;
  e.velocity = r.velocity;
  e.heading = r.heading;
  e.lost = e.age > options_.timeout + 1e-9;
  return e;
}

Vec2 scheduled_offset_vector(const std::vector<OffsetKey>& schedule, const FollowParameters& parameters,
                             double vehicle_heading, double t) {
  const auto [distance, angle] = detail::scheduled_offset(schedule, parameters, t);
  const double a = angle + (parameters.offset_reference == OffsetReference::Heading ? vehicle_heading : 0.0);
  return distance * Vec2(std::cos(a), std::sin(a));
}

}  // namespace vistrack
