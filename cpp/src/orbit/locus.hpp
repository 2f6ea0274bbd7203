// The smooth locus (beyond the paper): the locus check between the samples and the smooth R(t).
#pragma once

#include <functional>

#include "vistrack/orbit.hpp"

namespace vistrack::detail {

// How the locus check measures MaxRadius between the samples.
struct CheckProbe {
  // MaxRadius at a POI position; sets `computed_volume` when that took a new VV. Called from
  // several threads. Empty: the samples' MaxRadius only.
  std::function<double(const Vec3& poi, bool& computed_volume)> max_radius;
  // Also probe the samples, taking the smaller of that and their VP's MaxRadius (for a probe
  // other than the samples' own VPs).
  bool at_samples = false;
};

// Given a plan with its samples, VPs, MaxRadius and Algorithm 1's result (and the paper's
// piecewise-linear reference), runs the locus check and replaces the reference by the smooth R(t):
// fills plan.check, plan.reference, plan.radii (R at the samples), feasible and infeasibility.
void smooth_locus(VisibilityOrbitPlan& plan, const CheckProbe& probe);

// plan_orbits and visible_disk_radius (orbit.hpp) for inputs validated where they entered the API
// (OrbitPlanner checks its sensor once, at construction, and the Uav and Planning per plan).
VisibilityOrbitPlan plan_orbits_of_valid(const PoiPath& poi, const Uav& uav, const Sensor& sensor,
                                         const Planning& planning, VolumeCache& cache, const MetricFunction& metric,
                                         const SliceFunction& slice, const ProgressFunction& progress,
                                         const MaxRadiusFunction& check_max_radius);
double visible_disk_radius_of_valid(const VisibilityScene& scene, const Vec3& poi, double altitude,
                                    const Sensor& sensor, int azimuths = 360, int rings = 8);

}  // namespace vistrack::detail
