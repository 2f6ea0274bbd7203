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
#include "vistrack/dubins_parameters.hpp"
#include "vistrack/orbit_parameters.hpp"
#include "vistrack/visibility.hpp"
#include "vistrack/volume.hpp"

namespace vistrack {

// R(t) as the guidance follows it, on knots t_0 < ... < t_m. Piecewise linear between the knots
// (Definition 2, the paper's locus) when `rates` is empty; otherwise C1 piecewise quadratic with
// dR/dt = rates[k] at knot k, linear in t between knots (so d2R/dt2 is constant on each segment):
// R(t) = radii[k] + rates[k] s + (rates[k+1] - rates[k]) s^2 / (2 (t_k+1 - t_k)), s = t - t_k, and
// radii[k+1] = radii[k] + (t_k+1 - t_k)(rates[k] + rates[k+1]) / 2 (checked by validate()).
struct RadiusProfile {
  std::vector<double> times;
  std::vector<double> radii;
  std::vector<double> rates;  // empty: piecewise linear

  bool smooth() const { return !rates.empty(); }
  // Segment k with times[k] <= t < times[k+1] (the last segment at the end and beyond).
  std::size_t segment(double t) const;
  // R(t), dR/dt and d2R/dt2 with t clamped to [times.front(), times.back()] for R; outside that
  // span R is held, so dR/dt and d2R/dt2 are 0 there. At a knot of a piecewise-linear profile
  // dR/dt is that of the segment starting there (right-continuous), as is d2R/dt2 for a smooth one.
  double radius(double t) const;
  double rate(double t) const;
  double acceleration(double t) const;
  // Smallest R over [times.front(), times.back()] (a quadratic segment's minimum may lie inside it).
  double min_radius() const;
  // Error naming the field when the knots are empty, not increasing, or sizes differ, a value is
  // not finite, or (smooth) a segment's end misses the next knot's radius.
  void validate() const;
};

// The time-varying reference orbit O(theta, t) = g(t) + R(t) [cos theta, sin theta] of eq. (5)
// that the guidance follows: g(t) is the POI path, R(t) the `reference` profile.
struct OrbitPlan {
  PoiPath poi;
  std::vector<double> times;         // the sample times t_k, increasing, times.front() = 0
  std::vector<double> radii;         // R(t_k) on the reference
  bool feasible = true;
  std::string infeasibility;         // which sample or time fails and why, when !feasible
  // R(t). Without knots: piecewise linear through (times, radii), the paper's locus (every plan
  // before the smooth locus, and every plan file without a "reference").
  RadiusProfile reference;

  // The reference as the guidance follows it (the piecewise-linear default filled in).
  RadiusProfile profile() const;
  // R(t), dR/dt, d2R/dt2 of profile() (see RadiusProfile).
  double radius(double t) const;
  double radius_rate(double t) const;
  double radius_acceleration(double t) const;
  // The knots of the reference: where dR/dt (piecewise linear) or d2R/dt2 (smooth) may jump.
  const std::vector<double>& knot_times() const { return reference.times.empty() ? times : reference.times; }
  // Segment index k with times[k] <= t < times[k+1] of the samples (the last segment at the end).
  std::size_t segment(double t) const;
  // The orbit centres g(t_k), (n, 2).
  Points2 centers() const;
};

// Radius of the largest circle centred at `center` inside the visibility polygon (the union of
// `polygons`, holes included): the distance to the nearest boundary of the polygon containing the
// centre, or 0 when no polygon contains it. Exact, not a sampled bisection (MaxRadius, sec. IV).
double max_inscribed_radius(const std::vector<Polygon>& polygons, const Vec2& center);

// MaxRadius by line of sight: the radius of the largest disk at world z = altitude centred above
// the POI every point of which sees it (within d_max and the altitude band), probed with occlusion
// rays along `azimuths` directions: on `rings` circles out to d_max's reach, then by bisection to
// 1e-5 of that reach (1 mm at least) on the azimuths that can set the minimum. Along an azimuth
// the visible points of the plane form one interval from the centre for 2.5D obstacles; blocked
// bands narrower than reach / rings between two rings are not seen. The POI is placed on the
// surface (VisibilityScene::poi_on_surface), as the planner's VVs place it.
double visible_disk_radius(const VisibilityScene& scene, const Vec3& poi, double altitude, const Sensor& sensor,
                           int azimuths = 360, int rings = 8);

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
// A smooth reference under a ceiling (beyond the paper).

// What bounds a smooth R(t): |dR/dt| <= max_rate, and on every segment
// |d2R/dt2| <= turn_share (v / r_min - v (1 + v_g/v)^2 / R_lo) sqrt(v^2 - (v_g + |dR/dt|)^2),
// R_lo a lower bound of R on the segment. On the orbit the vehicle then turns at most
// v (1 + v_g/v)^2 / R (Lemma 6) plus |d2R/dt2| / |u_theta| (the d2R/dt2 term of (85) with R_dot in
// (13): |u_theta| >= sqrt(v^2 - (v_g + |R_dot|)^2)), i.e. at most v / r_min when R >= r_min (1 + v_g/v)^2.
struct SmoothRadiusLimits {
  double uav_speed = Uav{}.speed;              // v
  double poi_speed = 5.0;                      // v_g
  double min_turn_radius = Uav{}.min_turn_radius;
  double max_rate = Uav{}.speed - 5.0;         // Lemma 5: v - v_g (times 1 - rate_margin)
  double turn_share = Planning{}.turn_share;
  void validate() const;
  // The bound on |d2R/dt2| at radius >= r_lo and rate |dR/dt| (0 when r_lo fails Lemma 6).
  double max_acceleration(double r_lo, double rate) const;
};

// An upper bound on R(t), piecewise linear: from starts[j] to ends[j] on [breaks[j], breaks[j+1]]
// (it may jump at a break, where the smaller side counts).
struct Ceiling {
  std::vector<double> breaks;
  std::vector<double> starts;
  std::vector<double> ends;
  double at(double t) const;  // clamped to [breaks.front(), breaks.back()]
  void validate() const;      // Error naming the field: sizes, increasing breaks, finite values
};

// The largest smooth R(t) under a ceiling: of the C1 quadratic splines on uniform knots over
// [breaks.front(), breaks.back()] that obey `limits` and stay under the ceiling, the one with the
// largest integral of R (less the penalty below), by a log-barrier interior point method on the spline's control points (a
// banded linear program, solved to 1 cm of the optimal mean R), re-solved passes - 1 times with
// each segment's R_lo raised to the previous solution (so the d2R/dt2 bound of larger radii is
// used). knot_spacing <= 0 picks one from the d2R/dt2 bound.
// A ceiling under r_min (1 + v_g/v)^2 gives a profile that the caller must report infeasible (R
// there is below Lemma 6's bound).
// smoothing > 0 (Planning::radius_smoothing) subtracts the penalty (smoothing / 2) (top / A^2)
// integral of (d2R/dt2)^2 from the integral (top: the ceiling's largest value; A: the d2R/dt2 bound
// there): a banded quadratic program, solved by the same method.
RadiusProfile smooth_radius(const Ceiling& ceiling, const SmoothRadiusLimits& limits, double knot_spacing = 0.0,
                            int passes = 2, double smoothing = Planning{}.radius_smoothing);
// Why a smooth profile breaks `limits` (|dR/dt| at a knot, or |d2R/dt2| on a segment against the
// bound at the segment's smallest R), or "" when it keeps them all.
std::string smooth_radius_violation(const RadiusProfile& profile, const SmoothRadiusLimits& limits);

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
  double initial_volumes = 0.0;   // the VVs every plan computes (one every spacing, and every node)
  double spacing = 0.0;           // m, and the grid, for the messages
  double resolution_deg = 0.0;
  double bytes() const { return volumes * bytes_per_volume; }
  double initial_bytes() const { return initial_volumes * bytes_per_volume; }
};
WorkEstimate estimate_work(const PoiPath& poi, const Planning& planning);
// The VVs of fixed_discretization: one every `spacing` metres plus every node.
WorkEstimate estimate_fixed_work(const PoiPath& poi, double spacing, double resolution_deg);
// Error naming `field` (the limit the user may raise) when work.volumes exceeds max_volumes,
// then naming planning.resolution_deg or planning.spacing when the initial VVs would hold more
// than limits::kMaxWorkBytes (no limit raises that).
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

// The locus check of a smooth plan: MaxRadius along the POI path between the samples, and how
// far the smooth R(t) lies below the paper's piecewise-linear one.
struct LocusCheck {
  std::vector<double> arc_lengths;   // s_j of the check points (the samples among them), increasing
  std::vector<double> times;         // t_j = s_j / v_g
  std::vector<double> max_radii;     // MaxRadius of the VP at h_UAV centred on g(t_j)
  // The bound R(t) obeys, minus the tracking margin (breaks at the t_j). Where MaxRadius changes by
  // more than 1 m between two check points, the smaller value on the whole interval; elsewhere the
  // straight line between them lowered by the most a profile whose slope stays within
  // slope_bounds[j] (m per m of POI travel: the largest of this and the neighbouring intervals'
  // slopes, at least 0.1) can dip below it.
  Ceiling ceiling;
  std::vector<double> slope_bounds;
  std::size_t volumes_computed = 0;  // VVs the check computed (the others came from the cache)
  int rounds = 0;                    // refinement rounds
  // The paper's piecewise-linear R(t) through Algorithm 1's radii against the check points.
  std::size_t paper_violations = 0;  // check points where it exceeds MaxRadius
  double paper_max_violation = 0.0;  // by how much at most, m
  // paper R(t_j) - smooth R(t_j) per check point: > 0 where the smooth locus is lower.
  std::vector<double> lowering;
  double max_lowering = 0.0;         // m
  double max_lowering_time = 0.0;    // s
  double min_clearance = 0.0;        // min over check points of MaxRadius - smooth R, m
};

// A plan with everything it was made from. Its OrbitPlan part is the reference the guidance
// follows: Algorithm 1's radii at the samples, piecewise linear (Locus::paper), or the smooth
// R(t) under the locus check (Locus::smooth, with `check` filled); it runs wherever a plan does.
struct VisibilityOrbitPlan : OrbitPlan {
  explicit VisibilityOrbitPlan(OrbitPlan plan) : OrbitPlan(std::move(plan)) {}
  Uav uav;
  Sensor sensor;
  Planning planning;
  Discretization samples;                      // the VV samples along the path, their VVs and metric (56)
  std::vector<std::vector<Polygon>> polygons;  // the VPs at h_UAV, one list per sample
  std::vector<double> max_radii;               // MaxRadius per sample (line 1 of Algorithm 1)
  CircularOrbits orbits;                       // Algorithm 1 (lines 2-18) on max_radii
  LocusCheck check;                            // smooth locus only
};

// VP(s) of a VV at world altitude z (h_UAV: the flight plane).
using SliceFunction = std::function<std::vector<Polygon>(const VisibilityVolume&, double altitude)>;

// MaxRadius at a POI position for the locus check. Called from several threads.
using MaxRadiusFunction = std::function<double(const Vec3& poi)>;

// Section IV end to end with the given VV, metric and slice functions. The locus check (for
// Locus::smooth) measures MaxRadius between the samples with check_max_radius (at the samples too,
// keeping the smaller of it and the VP's), or without one through VVs from the same cache.
VisibilityOrbitPlan plan_orbits(const PoiPath& poi, const Uav& uav, const Sensor& sensor, const Planning& planning,
                                VolumeCache& cache, const MetricFunction& metric, const SliceFunction& slice,
                                const ProgressFunction& progress = {}, const MaxRadiusFunction& check_max_radius = {});
// The plan on given samples (no refinement): VPs by `slice`, MaxRadius, Algorithm 1, and for
// Locus::smooth the locus check and the smooth R(t). The check computes MaxRadius between the
// samples with `volume_at` (VVs at POI positions, called from several threads); without it, only
// the samples' MaxRadius and the slope rule of LocusCheck bound R(t) between them.
VisibilityOrbitPlan plan_on_samples(const PoiPath& poi, const Uav& uav, const Sensor& sensor,
                                    const Planning& planning, Discretization samples, const SliceFunction& slice,
                                    const VolumeFunction& volume_at = {});
// The plan on VVs computed elsewhere (saved VV files), placed at the given increasing arc lengths
// of `poi`: the metric (56) in the POI frame between neighbours, VPs by the edge-walking slicer,
// MaxRadius and Algorithm 1, with nothing inserted (and no VV between them for the locus check).
// The VVs must share d_max, band and grid.
VisibilityOrbitPlan plan_on_volumes(const PoiPath& poi, const Uav& uav, const Planning& planning,
                                    const std::vector<double>& arc_lengths, const std::vector<VolumePtr>& volumes);

// JSON round trips, the POI path stored as waypoints and speed ("vistrack.orbit_plan/1", and
// "vistrack.visibility_orbit_plan/1" with samples, VPs and Algorithm 1's numbers but no VVs).
// A smooth reference adds "reference" {times, radii, rates} (and a plan its "check"); files
// without one are read as the piecewise-linear locus they were written with.
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
  Discretization fixed(const PoiPath& poi, double spacing, double resolution_deg = kDefaultResolutionDeg,
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
