// Orbits about the moving POI (section IV): the largest inscribed radius in a visibility
// polygon, Algorithm 1 (rate and curvature feasibility) and the orbit plan.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vistrack/environment.hpp"
#include "vistrack/geometry.hpp"
#include "vistrack/parameters.hpp"
#include "vistrack/visibility.hpp"

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

// ---------------------------------------------------------------------------------------------
// Feasibility of a morphing orbit (section IV.A).

// Curvature (31) of the path flown while remaining on the orbit (Lemma 3), at the relative polar
// angle a = theta - gamma, radius R, radial rate dR/dt, UAV speed v and POI speed v_g, with
// theta' from (13) for CCW (+) or CW (-) circulation. +infinity when v^2 < (g'.e_r + R')^2 (no
// constant-speed motion stays on the orbit there, Lemma 5).
double orbit_curvature(double radius, double radius_rate, double relative_angle, double uav_speed,
                       double poi_speed, bool counter_clockwise = true);

// Lemma 6: the largest curvature over every a and every rate allowed by Lemma 5,
// (1 + v_g/v)^2 / R, reached at a = +-pi/2 and R' = 0.
double max_orbit_curvature(double radius, double uav_speed, double poi_speed);

// The smallest radius Lemma 6 allows for a UAV of turn radius r_min: r_min (1 + v_g/v)^2
// (at most 4 r_min, Corollary 1).
double min_feasible_radius(const Uav& uav, double poi_speed);

// Algorithm 1, lines 2-18, on radii already bounded by MaxRadius (line 1).
struct CircularOrbits {
  std::vector<double> radii;              // R_k after the forward and backward rate passes
  std::vector<double> radius_rates;       // (R_{k+1} - R_k) / (t_{k+1} - t_k), size n - 1
  double min_feasible_radius = 0.0;       // r_min (1 + v_g/v)^2
  bool feasible = true;
  std::vector<std::size_t> failing_samples;  // every k that breaks Lemma 6
  std::string infeasibility;              // the first failing sample, and why
};

// Enforces Lemma 5 (|dR/dt| <= v - v_g, tightened to (1 - rate_margin)(v - v_g)) by lowering radii
// only (each limited radius is built from its neighbour's), so the result is the largest
// piecewise-linear R(t) <= max_radii that obeys the rate bound; then checks Lemma 6 at every
// sample. Error when v <= v_g, rate_margin is outside [0, 1), sizes differ, times do not increase,
// or a radius is negative or not finite.
CircularOrbits circular_orbits(const std::vector<double>& times, const std::vector<double>& max_radii,
                               const Uav& uav, double poi_speed, double rate_margin = 0.0);

// ---------------------------------------------------------------------------------------------
// Adaptive discretization of the POI path (section IV.B).

using VolumePtr = std::shared_ptr<const VisibilityVolume>;
// The VV at a POI position. Called from several threads at once: must be thread-safe.
using VolumeFunction = std::function<VolumePtr(const Vec3& poi)>;
// The difference metric (56) between two VVs. Called from several threads at once.
using MetricFunction = std::function<double(const VisibilityVolume&, const VisibilityVolume&)>;
// (VVs computed so far, VVs known to be needed so far); called on the calling thread.
using ProgressFunction = std::function<void(std::size_t, std::size_t)>;

struct Discretization {
  std::vector<double> arc_lengths;   // s_k along the path, increasing
  std::vector<double> times;         // t_k = s_k / v_g
  Points3 points;                    // g(t_k), (n, 3)
  std::vector<int> depths;           // 0 for initial samples, d for one inserted at halving d
  std::vector<VolumePtr> volumes;    // alpha(g_k)
  std::vector<double> metric;        // d(alpha_k, alpha_{k+1}), size n - 1
  std::size_t volumes_computed = 0;  // VVs this call computed (the rest came from the cache)
};

// Thread-safe memo of VVs by POI position, to reuse VVs across calls (e.g. several spacings).
class VolumeCache {
 public:
  explicit VolumeCache(VolumeFunction compute);
  // The VV at arc length s of `poi` (computed once). `computed` is set when it was new.
  VolumePtr at(const PoiPath& poi, double arc_length, bool* computed = nullptr);
  std::size_t size() const;

 private:
  struct State;
  std::shared_ptr<State> state_;
};

// VVs on disk, one file per input (volume_cache_key) in `folder`, so a second run with the same
// environment, POI positions and parameters computes nothing. A missing, corrupt or stale file
// is a miss: the VV is computed and the file (re)written atomically. Copies share the counters.
class DiskVolumeCache {
 public:
  // Creates the folder when missing; Error naming cache_dir when it cannot be created or written.
  DiskVolumeCache(std::string folder, std::uint64_t environment_fingerprint, double d_max,
                  std::optional<std::pair<double, double>> altitude_band, double resolution_deg);
  // `compute` behind the disk: thread-safe when `compute` is.
  VolumeFunction wrap(VolumeFunction compute) const;
  std::string path(const Vec3& poi) const;   // the file of the VV at g
  const std::string& folder() const;
  std::size_t hits() const;    // VVs read from disk
  std::size_t misses() const;  // VVs computed (and written)

 private:
  struct State;
  std::shared_ptr<State> state_;
};

// Initial samples every planning.spacing metres from the start of each path edge, plus every
// node; then, recursively, a VV halfway between neighbours whose metric exceeds planning.cutoff,
// while the halves stay >= planning.min_spacing and the depth < planning.max_depth (so it always
// ends). VVs are computed in parallel (TBB), through `cache`.
Discretization adaptive_discretization(const PoiPath& poi, const Planning& planning, VolumeCache& cache,
                                       const MetricFunction& metric, const ProgressFunction& progress = {});
// The same samples at a fixed spacing, without refinement (Figure 4's baselines).
Discretization fixed_discretization(const PoiPath& poi, double spacing, VolumeCache& cache,
                                    const MetricFunction& metric, const ProgressFunction& progress = {});

// ---------------------------------------------------------------------------------------------
// The whole planner: adaptive VVs, VPs at h_UAV, MaxRadius, Algorithm 1.

// A plan with everything it was made from. Derives from OrbitPlan so it runs wherever a plan does.
struct VisibilityOrbitPlan : OrbitPlan {
  explicit VisibilityOrbitPlan(OrbitPlan base) : OrbitPlan(std::move(base)) {}
  Uav uav;
  Sensor sensor;
  Planning planning;
  std::vector<double> arc_lengths;            // s_k of the samples
  std::vector<int> depths;                    // refinement depth of each sample
  std::vector<double> radius_rates;           // dR/dt per segment, size n - 1
  double min_feasible_radius = 0.0;           // r_min (1 + v_g/v)^2 (Lemma 6)
  std::vector<std::size_t> failing_samples;   // samples that break Lemma 6
  std::vector<VolumePtr> volumes;             // the VVs (not stored in JSON)
  std::vector<std::vector<Polygon>> polygons; // the VPs at h_UAV
  std::size_t volumes_computed = 0;
};

// VP(s) of a VV at an altitude above the ground.
using SliceFunction = std::function<std::vector<Polygon>(const VisibilityVolume&, double altitude)>;

// Section IV end to end with the given VV, metric and slice functions.
VisibilityOrbitPlan plan_orbits(const PoiPath& poi, const Uav& uav, const Sensor& sensor, const Planning& planning,
                                VolumeCache& cache, const MetricFunction& metric, const SliceFunction& slice,
                                const ProgressFunction& progress = {});

std::string to_json(const VisibilityOrbitPlan& plan);
VisibilityOrbitPlan visibility_orbit_plan_from_json(const std::string& text);

// Rings where the plane z = altitude cuts a closed 2-manifold triangle mesh, by walking the
// crossing edges (O(faces), no spatial tree; vertices on the plane count as below). Error when
// the mesh is not closed or not 2-manifold along the cut.
std::vector<Ring> plane_slice_rings(const TriangleMesh& mesh, double altitude);
// The VP of a VV at world altitude z from plane_slice_rings: the same polygons as
// visibility_polygon (CGAL slicer) at a fraction of the cost; the planner uses it.
std::vector<Polygon> plane_visibility_polygon(const VisibilityVolume& vv, double altitude);

// Section IV on a real environment: one Embree scene built once, VVs through a shared cache (so
// several spacings or plans reuse them), the grid XOR metric (56) in the POI frame, and VPs
// sliced at world z = ground level + h_UAV.
class OrbitPlanner {
 public:
  // cache_dir: folder of the on-disk VV cache (created when missing); empty for none.
  OrbitPlanner(const Environment& env, const Sensor& sensor, double resolution_deg = 1.0,
               std::string cache_dir = "");
  Discretization adaptive(const PoiPath& poi, const Planning& planning, const ProgressFunction& progress = {});
  Discretization fixed(const PoiPath& poi, double spacing, const ProgressFunction& progress = {});
  // Error when planning.resolution_deg differs from the planner's.
  VisibilityOrbitPlan plan(const PoiPath& poi, const Uav& uav, const Planning& planning,
                           const ProgressFunction& progress = {});
  std::size_t cached_volumes() const { return cache_.size(); }
  const VisibilityScene& scene() const { return scene_; }
  // VVs read from / computed into the disk cache so far (0 without one).
  std::size_t disk_hits() const { return disk_ ? disk_->hits() : 0; }
  std::size_t disk_misses() const { return disk_ ? disk_->misses() : 0; }

 private:
  VisibilityScene scene_;
  Sensor sensor_;
  double resolution_deg_;
  std::optional<DiskVolumeCache> disk_;
  VolumeCache cache_;
};

// vt.plan_orbits: OrbitPlanner(env, sensor, planning.resolution_deg, cache_dir).plan(poi, uav, planning).
VisibilityOrbitPlan plan_orbits(const Environment& env, const PoiPath& poi, const Uav& uav, const Sensor& sensor,
                                const Planning& planning, const ProgressFunction& progress = {},
                                const std::string& cache_dir = "");

}  // namespace vistrack
