// Orbits about the moving POI (section IV): the largest inscribed radius in a visibility
// polygon, Algorithm 1 (rate and curvature feasibility), the adaptive placement of VVs along the
// POI path, the orbit plan and its JSON form, and the planner on a real environment.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vistrack/environment.hpp"
#include "vistrack/geometry.hpp"
#include "vistrack/parameters.hpp"
#include "vistrack/visibility.hpp"
#include "vistrack/volume.hpp"

namespace vistrack {

// The time-varying reference orbit O(theta, t) = g(t) + R(t) [cos theta, sin theta] of eq. (5)
// that the guidance follows: R is piecewise linear between the knots (times[k], radii[k]); g(t)
// is the POI path.
struct OrbitPlan {
  PoiPath poi;
  std::vector<double> times;         // t_k, increasing, times.front() = 0
  std::vector<double> radii;         // R(t_k)
  bool feasible = true;
  std::string infeasibility;         // which sample fails and why, when !feasible

  // R(t), clamped to [times.front(), times.back()].
  double radius(double t) const;
  // dR/dt on the segment containing t (right-continuous), 0 outside.
  double radius_rate(double t) const;
  // Segment index k with times[k] <= t < times[k+1] (the last segment at the end).
  std::size_t segment(double t) const;
  // The orbit centres g(t_k), (n, 2).
  Points2 centers() const;
};

// Radius of the largest circle centred at `center` inside the visibility polygon (the union of
// `polygons`, holes included): the distance to the nearest boundary of the polygon containing the
// centre, or 0 when no polygon contains it. Exact, not a sampled bisection (MaxRadius, sec. IV).
double max_inscribed_radius(const std::vector<Polygon>& polygons, const Vec2& center);

// Orbits of one radius along the whole POI path (the paper's constant-radius baselines).
OrbitPlan constant_radius_plan(const PoiPath& poi, double radius, const Uav& uav);

// ---------------------------------------------------------------------------------------------
// Feasibility of a morphing orbit (section IV.A).

// Curvature (31) of the path flown while remaining on the orbit (Lemma 3), at the relative polar
// angle a = theta - gamma, radius R, radial rate dR/dt, UAV speed v and POI speed v_g, with
// theta' from (13) for the given circulation. +infinity when v^2 < (g'.e_r + R')^2 (no
// constant-speed motion stays on the orbit there, Lemma 5).
double orbit_curvature(double radius, double radius_rate, double relative_angle, double uav_speed,
                       double poi_speed, Circulation circulation = Circulation::CounterClockwise);

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

// The work a discretization may ask for, known before any VV is computed: the worst case has every
// initial interval halved until the halves reach min_spacing or max_depth (about path length /
// min_spacing VVs), and the VV cache holds every VV until the plan is done.
struct WorkEstimate {
  double volumes = 0.0;           // worst-case number of VVs (a double: it can exceed any integer type)
  double bytes_per_volume = 0.0;  // memory of one VV on the planning grid (~4.7 MB at 1 degree)
  double bytes() const { return volumes * bytes_per_volume; }
};
// Memory of one VV on a grid of resolution_deg degrees: its intervals and its mesh (72 bytes per cell).
double volume_bytes(double resolution_deg);
WorkEstimate estimate_work(const PoiPath& poi, const Planning& planning);
// The VVs of fixed_discretization: one every `spacing` metres plus every node.
WorkEstimate estimate_fixed_work(const PoiPath& poi, double spacing, double resolution_deg);
// Error naming `field` (the limit the user may raise) when work.volumes exceeds max_volumes.
void check_work(const WorkEstimate& work, std::size_t max_volumes, const std::string& field = "planning.max_volumes");

// Initial samples every planning.spacing metres from the start of each path edge, plus every
// node; then, recursively, a VV halfway between neighbours whose metric exceeds planning.cutoff,
// while the halves stay >= planning.min_spacing and the depth < planning.max_depth (so it always
// ends). VVs are computed in parallel (TBB), through `cache`. Refuses (check_work) a worst case
// beyond planning.max_volumes before computing any VV.
Discretization adaptive_discretization(const PoiPath& poi, const Planning& planning, VolumeCache& cache,
                                       const MetricFunction& metric, const ProgressFunction& progress = {});
// The same samples at a fixed spacing, without refinement (Figure 4's baselines); refuses more
// than max_volumes VVs before computing any.
Discretization fixed_discretization(const PoiPath& poi, double spacing, VolumeCache& cache,
                                    const MetricFunction& metric, const ProgressFunction& progress = {},
                                    std::size_t max_volumes = Planning{}.max_volumes);

// ---------------------------------------------------------------------------------------------
// The whole planner: adaptive VVs, VPs at h_UAV, MaxRadius, Algorithm 1.

// A plan with everything it was made from. Its OrbitPlan part is the reference the guidance
// follows (Algorithm 1's radii at the samples); it runs wherever a plan does.
struct VisibilityOrbitPlan : OrbitPlan {
  explicit VisibilityOrbitPlan(OrbitPlan reference) : OrbitPlan(std::move(reference)) {}
  Uav uav;
  Sensor sensor;
  Planning planning;
  Discretization samples;                      // the VV samples along the path, their VVs and metric (56)
  std::vector<std::vector<Polygon>> polygons;  // the VPs at h_UAV, one list per sample
  std::vector<double> max_radii;               // MaxRadius per sample (line 1 of Algorithm 1)
  CircularOrbits orbits;                       // Algorithm 1 (lines 2-18) on max_radii
};

// VP(s) of a VV at world altitude z (h_UAV: the flight plane).
using SliceFunction = std::function<std::vector<Polygon>(const VisibilityVolume&, double altitude)>;

// Section IV end to end with the given VV, metric and slice functions.
VisibilityOrbitPlan plan_orbits(const PoiPath& poi, const Uav& uav, const Sensor& sensor, const Planning& planning,
                                VolumeCache& cache, const MetricFunction& metric, const SliceFunction& slice,
                                const ProgressFunction& progress = {});
// The plan on given samples (no refinement): VPs by `slice`, MaxRadius, Algorithm 1.
VisibilityOrbitPlan plan_on_samples(const PoiPath& poi, const Uav& uav, const Sensor& sensor,
                                    const Planning& planning, Discretization samples, const SliceFunction& slice);
// The plan on VVs computed elsewhere (saved VV files), placed at the given increasing arc lengths
// of `poi`: the metric (56) in the POI frame between neighbours, VPs by the edge-walking slicer,
// MaxRadius and Algorithm 1, with nothing inserted. The VVs must share d_max, band and grid.
VisibilityOrbitPlan plan_on_volumes(const PoiPath& poi, const Uav& uav, const Planning& planning,
                                    const std::vector<double>& arc_lengths, const std::vector<VolumePtr>& volumes);

// JSON round trips, the POI path stored as waypoints and speed ("vistrack.orbit_plan/1", and
// "vistrack.visibility_orbit_plan/1" with samples, VPs and Algorithm 1's numbers but no VVs).
std::string to_json(const OrbitPlan& plan);
OrbitPlan orbit_plan_from_json(const std::string& text);
std::string to_json(const VisibilityOrbitPlan& plan);
VisibilityOrbitPlan visibility_orbit_plan_from_json(const std::string& text);

// Section IV on a real environment: one Embree scene built once, VVs through caches shared by
// every call (so several spacings or plans reuse them; one per grid resolution), the XOR metric
// (56) in the POI frame, and VPs sliced at world z = h_UAV by the edge-walking slicer.
class OrbitPlanner {
 public:
  // cache_dir: folder of the on-disk VV cache (created when missing); empty for none.
  OrbitPlanner(const Environment& env, const Sensor& sensor, std::string cache_dir = "");
  Discretization adaptive(const PoiPath& poi, const Planning& planning, const ProgressFunction& progress = {});
  Discretization fixed(const PoiPath& poi, double spacing, double resolution_deg = Planning{}.resolution_deg,
                       const ProgressFunction& progress = {}, std::size_t max_volumes = Planning{}.max_volumes);
  VisibilityOrbitPlan plan(const PoiPath& poi, const Uav& uav, const Planning& planning,
                           const ProgressFunction& progress = {});
  std::size_t cached_volumes() const;
  const VisibilityScene& scene() const { return scene_; }
  // VVs read from / computed into the disk cache so far (0 without one).
  std::size_t disk_hits() const;
  std::size_t disk_misses() const;

 private:
  struct Caches {
    std::optional<DiskVolumeCache> disk;
    VolumeCache memory;
  };
  Caches& caches(double resolution_deg);

  VisibilityScene scene_;
  Sensor sensor_;
  std::string cache_dir_;
  std::map<double, Caches> caches_;  // by resolution_deg; calls come from one thread at a time
};

// vt.plan_orbits: OrbitPlanner(env, sensor, cache_dir).plan(poi, uav, planning).
VisibilityOrbitPlan plan_orbits(const Environment& env, const PoiPath& poi, const Uav& uav, const Sensor& sensor,
                                const Planning& planning, const ProgressFunction& progress = {},
                                const std::string& cache_dir = "");

}  // namespace vistrack
