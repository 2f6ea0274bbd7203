// The smooth locus (beyond the paper): the locus check between the samples and the smooth R(t).
#pragma once

#include <functional>

#include "vistrack/orbit.hpp"

namespace vistrack::detail {

// The VV at a POI position; sets `computed` when it was not cached. Called from several threads.
using CheckVolumeFunction = std::function<VolumePtr(const Vec3& poi, bool& computed)>;

// Given a plan with its samples, VPs, MaxRadius and Algorithm 1's result (and the paper's
// piecewise-linear reference), runs the locus check and replaces the reference by the smooth R(t):
// fills plan.check, plan.reference, plan.radii (R at the samples), feasible and infeasibility.
// Without volume_at the check has only the samples' MaxRadius.
void smooth_locus(VisibilityOrbitPlan& plan, const SliceFunction& slice, const CheckVolumeFunction& volume_at);

}  // namespace vistrack::detail
