// Algorithm 1 (section IV.C) with the feasibility conditions of section IV.A (Lemmas 3, 5, 6).
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"
#include "vistrack/orbit.hpp"

namespace vistrack {
namespace {

void require_poi_speed(double poi_speed, const std::string& field) {
  require_in_range(poi_speed, 0.0, limits::kMaxSpeed, "m/s", field);  // 0: a POI standing still
}

void require_faster_than_poi(const Uav& uav, double poi_speed) {
  require_speed(poi_speed, "poi.speed");
  if (!(uav.speed > poi_speed))
    detail::fail_field("uav.speed", uav.speed,
                       "must exceed the POI speed " + detail::to_text(poi_speed) +
                           " to stay on an orbit about it (Lemma 5 needs v - v_g > 0)");
}

}  // namespace

double orbit_curvature(double radius, double radius_rate, double relative_angle, double uav_speed,
                       double poi_speed, Circulation circulation) {
  require_length(radius, "radius");
  require_in_range(radius_rate, -limits::kMaxSpeed, limits::kMaxSpeed, "m/s", "radius_rate");
  require_angle(relative_angle, "relative_angle");
  require_speed(uav_speed, "uav_speed");
  require_poi_speed(poi_speed, "poi_speed");
  // g'.e_r = v_g cos a and g'.e_theta = -v_g sin a for a = theta - gamma (Definitions 1, 3).
  const double radial = poi_speed * std::cos(relative_angle) + radius_rate;
  const double under_root = uav_speed * uav_speed - radial * radial;
  if (!(under_root > 0.0)) return std::numeric_limits<double>::infinity();
  const double root = std::sqrt(under_root);
  // (13): theta' = (-g'.e_theta +- sqrt(v^2 - (g'.e_r + R')^2)) / R.
  const double theta_rate = (poi_speed * std::sin(relative_angle) + sign(circulation) * root) / radius;
  // (31): kappa = R theta'^2 / (v sqrt(v^2 - (g'.e_r + R')^2)).
  return radius * theta_rate * theta_rate / (uav_speed * root);
}

double max_orbit_curvature(double radius, double uav_speed, double poi_speed) {
  require_length(radius, "radius");
  require_speed(uav_speed, "uav_speed");
  require_poi_speed(poi_speed, "poi_speed");
  const double ratio = 1.0 + poi_speed / uav_speed;
  return ratio * ratio / radius;  // (53), (55)
}

double min_feasible_radius(const Uav& uav, double poi_speed) {
  uav.validate();
  require_poi_speed(poi_speed, "poi_speed");
  const double ratio = 1.0 + poi_speed / uav.speed;
  return uav.min_turn_radius * ratio * ratio;
}

CircularOrbits circular_orbits(const std::vector<double>& times, const std::vector<double>& max_radii,
                               const Uav& uav, double poi_speed, double rate_margin) {
  uav.validate();
  require_faster_than_poi(uav, poi_speed);
  if (!(rate_margin >= 0.0 && rate_margin < 1.0))
    detail::fail_field("rate_margin", rate_margin, "must be in [0, 1) (a fraction of v - v_g)");
  if (times.empty()) detail::fail_field("times", "[]", "need at least one sample");
  if (max_radii.size() != times.size())
    detail::fail_field("max_radii", max_radii.size(),
                       "must have one entry per time (" + std::to_string(times.size()) + ")");
  for (std::size_t k = 0; k < times.size(); ++k) {
    require_finite(times[k], "times[" + std::to_string(k) + "]");
    require_in_range(max_radii[k], 0.0, limits::kMaxLength, "m", "max_radii[" + std::to_string(k) + "]");
    if (k > 0 && !(times[k] > times[k - 1]))
      detail::fail_field("times[" + std::to_string(k) + "]", times[k], "times must increase");
  }

  CircularOrbits out;
  std::vector<double>& radius = out.radii;
  radius = max_radii;  // line 1: R_k = MaxRadius(VP_k at h_UAV)
  // Lemma 5, (52): |R'| <= v - v_g; a margin keeps the attraction of (68) away from zero.
  const double max_rate = (1.0 - rate_margin) * (uav.speed - poi_speed);
  const std::size_t n = radius.size();
  // Lines 2-7, forward: R_{k+1} - R_k <= (v - v_g)(t_{k+1} - t_k). The printed line 5 sets
  // R_{k+1} = (v - v_g) dt, which forgets R_k; (50) solved for R_{k+1} gives R_k + (v - v_g) dt.
  for (std::size_t k = 0; k + 1 < n; ++k)
    radius[k + 1] = std::min(radius[k + 1], radius[k] + max_rate * (times[k + 1] - times[k]));
  // Lines 8-13, backward: R_{k+1} - R_k >= -(v - v_g) dt, i.e. R_k <= R_{k+1} + (v - v_g) dt (the
  // printed line 11, R_k = (v_g - v) dt, would be negative). Lowering R_k keeps the forward bound
  // on its left and makes the bound on its right hold with equality, so after both passes every
  // segment obeys (50): R_k = min_j (MaxRadius_j + (v - v_g)|t_k - t_j|), the largest such R.
  for (std::size_t k = n - 1; k-- > 0;)
    radius[k] = std::min(radius[k], radius[k + 1] + max_rate * (times[k + 1] - times[k]));
  for (std::size_t k = 0; k + 1 < n; ++k)
    out.radius_rates.push_back((radius[k + 1] - radius[k]) / (times[k + 1] - times[k]));

  // Lines 14-18. Lemma 6 bounds the curvature on the orbit by (1 + v_g/v)^2 / R; the UAV can fly
  // it when that is <= kappa_max = 1/r_min, i.e. R >= r_min (1 + v_g/v)^2. (The printed line 15
  // flags R_k > (1 + v_g/v)^2 / kappa_max, the reverse.) R(t) is linear on a segment, so its
  // smallest value, where the bound is largest, is at a sample: checking samples suffices.
  out.min_feasible_radius = min_feasible_radius(uav, poi_speed);
  for (std::size_t k = 0; k < n; ++k)
    if (radius[k] < out.min_feasible_radius) out.failing_samples.push_back(k);
  out.feasible = out.failing_samples.empty();
  if (!out.feasible) {
    const std::size_t k = out.failing_samples.front();
    std::ostringstream why;
    why.precision(6);
    why << "sample " << k << " (t = " << times[k] << " s): ";
    if (max_radii[k] <= 0.0)
      why << "MaxRadius = 0: the POI is not inside its visibility polygon at h_UAV = " << uav.altitude
          << " m (not visible from that altitude), so no orbit can be centred on it";
    else
      why << "R = " << radius[k] << " m (MaxRadius " << max_radii[k] << " m"
          << (radius[k] < max_radii[k] ? (rate_margin > 0.0 ? ", lowered by the rate limit |dR/dt| <= (1 - rate_margin)(v - v_g)"
                                                            : ", lowered by the rate limit |dR/dt| <= v - v_g of Lemma 5")
                                       : "")
          << ") < r_min (1 + v_g/v)^2 = " << out.min_feasible_radius
          << " m: the orbit's curvature (1 + v_g/v)^2 / R = "
          << max_orbit_curvature(std::max(radius[k], 1e-300), uav.speed, poi_speed)
          << " 1/m exceeds kappa_max = 1/r_min = " << 1.0 / uav.min_turn_radius << " 1/m (Lemma 6)";
    why << "; " << out.failing_samples.size() << " of " << n << " samples fail";
    std::size_t invisible = 0;
    for (std::size_t j : out.failing_samples) invisible += max_radii[j] <= 0.0 ? 1 : 0;
    if (invisible > 0 && max_radii[k] > 0.0)
      why << " (" << invisible << " of them with MaxRadius = 0: POI not visible at h_UAV)";
    out.infeasibility = why.str();
  }
  return out;
}

}  // namespace vistrack
