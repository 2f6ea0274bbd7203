#include <algorithm>

#include "vistrack/error.hpp"
#include "vistrack/orbit.hpp"

namespace vistrack {

std::size_t OrbitPlan::segment(double t) const {
  if (times.size() < 2) return 0;
  auto it = std::upper_bound(times.begin(), times.end(), t);
  std::size_t k = it == times.begin() ? 0 : static_cast<std::size_t>(it - times.begin()) - 1;
  return std::min(k, times.size() - 2);
}

double OrbitPlan::radius(double t) const {
  require_finite(t, "t");
  if (radii.empty()) throw Error("plan.radii: the orbit plan has no samples");
  if (times.size() < 2) return radii.front();
  t = std::clamp(t, times.front(), times.back());
  const std::size_t k = segment(t);
  const double span = times[k + 1] - times[k];
  const double s = span > 0.0 ? (t - times[k]) / span : 0.0;
  return (1.0 - s) * radii[k] + s * radii[k + 1];
}

double OrbitPlan::radius_rate(double t) const {
  require_finite(t, "t");
  if (times.size() < 2 || t < times.front() || t > times.back()) return 0.0;
  const std::size_t k = segment(t);
  const double span = times[k + 1] - times[k];
  return span > 0.0 ? (radii[k + 1] - radii[k]) / span : 0.0;
}

OrbitPlan constant_radius_plan(const PoiPath& poi, double radius, const Uav& uav) {
  uav.validate();
  require_positive(radius, "radius");
  if (!(uav.speed > poi.speed()))
    detail::fail_field("uav.speed", uav.speed,
                       "must exceed the POI speed " + detail::to_text(poi.speed()) + " to orbit it");
  OrbitPlan plan{poi, poi.node_times(), {}, {}, {}, true, {}};
  plan.radii.assign(plan.times.size(), radius);
  plan.max_radii = plan.radii;
  return plan;
}

}  // namespace vistrack
