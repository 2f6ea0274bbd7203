// The orbit planner on a real environment: Embree scene, VV cache, grid XOR metric, VP slicing.
#include "vistrack/error.hpp"
#include "vistrack/orbit.hpp"
#include "vistrack/volume.hpp"

namespace vistrack {
namespace {

// The fast path of (56): VVs of one planner share a direction grid, compared in the POI frame.
double poi_frame_metric(const VisibilityVolume& a, const VisibilityVolume& b) {
  return xor_volume(a, b, XorFrame::poi, XorMethod::automatic);
}

}  // namespace

OrbitPlanner::OrbitPlanner(const Environment& env, const Sensor& sensor, double resolution_deg)
    : scene_(env),
      sensor_(sensor),
      resolution_deg_(resolution_deg),
      cache_([scene = scene_, sensor, resolution_deg](const Vec3& g) {
        return std::make_shared<const VisibilityVolume>(
            visibility_volume(scene, g, sensor.d_max, sensor.altitude_band, resolution_deg));
      }) {
  sensor.validate();
  require_positive(resolution_deg, "resolution_deg");
}

Discretization OrbitPlanner::adaptive(const PoiPath& poi, const Planning& planning, const ProgressFunction& progress) {
  return adaptive_discretization(poi, planning, cache_, poi_frame_metric, progress);
}

Discretization OrbitPlanner::fixed(const PoiPath& poi, double spacing, const ProgressFunction& progress) {
  return fixed_discretization(poi, spacing, cache_, poi_frame_metric, progress);
}

VisibilityOrbitPlan OrbitPlanner::plan(const PoiPath& poi, const Uav& uav, const Planning& planning,
                                       const ProgressFunction& progress) {
  planning.validate();
  if (planning.resolution_deg != resolution_deg_)
    detail::fail_field("planning.resolution_deg", planning.resolution_deg,
                       "differs from the planner's VV resolution " + detail::to_text(resolution_deg_));
  const double ground = scene_.ground_level();
  const SliceFunction slice = [ground](const VisibilityVolume& vv, double altitude) {
    return plane_visibility_polygon(vv, ground + altitude);
  };
  return plan_orbits(poi, uav, sensor_, planning, cache_, poi_frame_metric, slice, progress);
}

VisibilityOrbitPlan plan_orbits(const Environment& env, const PoiPath& poi, const Uav& uav, const Sensor& sensor,
                                const Planning& planning, const ProgressFunction& progress) {
  uav.validate();
  planning.validate();
  OrbitPlanner planner(env, sensor, planning.resolution_deg);
  return planner.plan(poi, uav, planning, progress);
}

}  // namespace vistrack
