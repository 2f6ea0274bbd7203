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

}  // namespace vistrack::detail
