// Orbits about the moving POI (section IV): the largest inscribed radius in a visibility
// polygon, Algorithm 1 (rate and curvature feasibility) and the orbit plan.
#pragma once

#include <string>
#include <vector>

#include "vistrack/environment.hpp"
#include "vistrack/geometry.hpp"
#include "vistrack/parameters.hpp"

namespace vistrack {

// The time-varying reference orbit O(theta, t) = g(t) + R(t) [cos theta, sin theta] of eq. (5):
// R is piecewise linear between the samples (times[k], radii[k]); g(t) is the POI path.
struct OrbitPlan {
  PoiPath poi;
  std::vector<double> times;         // t_k, increasing, times.front() = 0
  std::vector<double> radii;         // R(t_k) after Algorithm 1
  std::vector<double> max_radii;     // MaxRadius from the visibility polygons, before Algorithm 1
  std::vector<double> metric;        // XOR volume between neighbouring VVs (size n - 1), may be empty
  bool feasible = true;
  std::string infeasibility;         // which sample fails and why, when !feasible

  // R(t), clamped to [times.front(), times.back()].
  double radius(double t) const;
  // dR/dt on the segment containing t (right-continuous), 0 outside.
  double radius_rate(double t) const;
  // Segment index k with times[k] <= t < times[k+1] (the last segment at the end).
  std::size_t segment(double t) const;
};

// Radius of the largest circle centred at `center` inside the visibility polygon (the union of
// `polygons`, holes included): the distance to the nearest boundary of the polygon containing the
// centre, or 0 when no polygon contains it. Exact, not a sampled bisection (MaxRadius, sec. IV).
double max_inscribed_radius(const std::vector<Polygon>& polygons, const Vec2& center);

// JSON round trip of a plan (the POI path is stored as waypoints and speed).
std::string to_json(const OrbitPlan& plan);
OrbitPlan orbit_plan_from_json(const std::string& text);

// Orbits of one radius along the whole POI path (the paper's constant-radius baselines).
OrbitPlan constant_radius_plan(const PoiPath& poi, double radius, const Uav& uav);

}  // namespace vistrack
