// Controller tuning by grid search (section V.D, Fig. 9).
#include <algorithm>
#include <cmath>
#include <string>

#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"
#include "vistrack/simulate.hpp"

namespace vistrack {

void TuningGrid::validate() const {
  if (!(tau > 0.0 && tau <= 1.0)) detail::fail_field("grid.tau", tau, "must be in (0, 1] (Remark 6)");
  if (!(r_max_factor > tau && r_max_factor <= 1e6))
    detail::fail_field("grid.r_max_factor", r_max_factor, "must be greater than tau and at most 1e6");
  if (num_radii < 2) detail::fail_field("grid.num_radii", num_radii, "must be at least 2");
  if (num_angles < 4) detail::fail_field("grid.num_angles", num_angles, "must be at least 4");
  if (num_heading_errors < 3) detail::fail_field("grid.num_heading_errors", num_heading_errors, "must be at least 3");
  // The map holds num_radii x num_angles doubles; each point tries every heading error.
  const double points = static_cast<double>(num_radii) * num_angles;
  if (points > 1e8)
    detail::fail_field("grid.num_radii x grid.num_angles", points, "must be at most 1e8 (800 MB of map)");
  if (points * num_heading_errors > 1e9)
    detail::fail_field("grid.num_radii x num_angles x num_heading_errors", points * num_heading_errors,
                       "must be at most 1e9 evaluations (about a minute)");
}

TuningResult tune_turn_rate(double radius, double radius_rate, double speed, double poi_speed, double beta,
                            Circulation direction, const TuningGrid& grid) {
  require_length(radius, "radius");
  require_in_range(radius_rate, -limits::kMaxSpeed, limits::kMaxSpeed, "m/s", "radius_rate");
  require_speed(speed, "speed");
  require_in_range(poi_speed, 0.0, limits::kMaxSpeed, "m/s", "poi_speed");
  require_beta(beta, "beta");
  grid.validate();
  if (!(std::abs(radius_rate) <= speed - poi_speed))
    detail::fail_field("radius_rate", radius_rate,
                       "|dR/dt| must not exceed v - v_g = " + detail::computed_text(speed - poi_speed) + " (Lemma 5)");

  GuidanceGains gains;
  gains.speed = speed;
  gains.beta = beta;
  gains.direction = direction;
  gains.validate();
  // The answer is invariant under rotation, so the POI moves along +x and theta is measured
  // from its direction of motion.
  OrbitState orbit;
  orbit.center_velocity = Vec2(poi_speed, 0.0);
  orbit.radius = radius;
  orbit.radius_rate = radius_rate;

  TuningResult result;
  const double r_min = grid.tau * radius;
  const double r_max = grid.r_max_factor * radius;
  for (int i = 0; i < grid.num_radii; ++i)
    result.radii.push_back(r_min + (r_max - r_min) * i / (grid.num_radii - 1));
  for (int j = 0; j < grid.num_angles; ++j) result.angles.push_back(kTwoPi * j / grid.num_angles);
  std::vector<double> errors;
  for (int k = 0; k < grid.num_heading_errors; ++k)
    errors.push_back(-kPi + kTwoPi * k / (grid.num_heading_errors - 1));

  result.map.assign(result.radii.size() * result.angles.size(), 0.0);
  for (std::size_t i = 0; i < result.radii.size(); ++i) {
    for (std::size_t j = 0; j < result.angles.size(); ++j) {
      const double r = result.radii[i];
      const double theta = result.angles[j];
      const VectorField field = vector_field(Vec2(r * std::cos(theta), r * std::sin(theta)), orbit, gains);
      double best = 0.0;
      for (double e : errors) {
        const double value = std::abs(field.heading_rate + lyapunov_term(field, orbit, beta, e));
        if (value > best) {
          best = value;
          if (value > result.max_turn_rate) {
            result.max_turn_rate = value;
            result.at_r = r;
            result.at_theta = theta;
            result.at_heading_error = e;
          }
        }
      }
      result.map[i * result.angles.size() + j] = best;
    }
  }
  return result;
}

}  // namespace vistrack
