#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "vistrack/orbit.hpp"
#include "vistrack/visibility.hpp"
#include "vistrack/volume.hpp"

namespace py = pybind11;

namespace vistrack::bindings {

void bind_orbit(py::module_& m) {
  py::class_<OrbitPlan>(m, "OrbitPlan",
                        "Time-varying reference orbit about the POI that the guidance follows: R(t) piecewise "
                        "linear between the knots (times, radii), centred on the POI path g(t) (eq. 5).")
      .def_readonly("poi", &OrbitPlan::poi, "The POI path g(t).")
      .def_readonly("times", &OrbitPlan::times, "Knot times t_k (s).")
      .def_readonly("radii", &OrbitPlan::radii, "Orbit radii R(t_k) (m).")
      .def_readonly("feasible", &OrbitPlan::feasible, "Whether the plan is flyable (Lemmas 5 and 6).")
      .def_readonly("infeasibility", &OrbitPlan::infeasibility, "Which sample fails and why.")
      .def_property_readonly("centers", &OrbitPlan::centers, "Orbit centres g(t_k), array (n, 2).")
      .def("radius", &OrbitPlan::radius, py::arg("t"), "R(t), linear between samples.")
      .def("radius_rate", &OrbitPlan::radius_rate, py::arg("t"), "dR/dt on the segment containing t.")
      .def("to_json", py::overload_cast<const OrbitPlan&>(&to_json), "The plan as JSON text.")
      .def_static("from_json", &orbit_plan_from_json, py::arg("text"), "A plan from JSON text.")
      .def(
          "to_mission",
          // Missions and the georeference are Python (vistrack.mission, pyproj): delegate.
          [](const py::object& self, const py::object& georeference, const py::object& altitude,
             const std::string& direction, const py::object& speed, const py::object& start, const std::string& end,
             const std::string& firmware, const std::string& altitude_mode) {
            return py::module_::import("vistrack.mission")
                .attr("orbit_plan_mission")(self, georeference, altitude, py::arg("direction") = direction,
                                            py::arg("speed") = speed, py::arg("start") = start, py::arg("end") = end,
                                            py::arg("firmware") = firmware, py::arg("altitude_mode") = altitude_mode);
          },
          py::arg("georeference"), py::arg("altitude") = py::none(), py::kw_only(), py::arg("direction") = "ccw",
          py::arg("speed") = py::none(), py::arg("start") = py::none(), py::arg("end") = "loiter",
          py::arg("firmware") = "ardupilot", py::arg("altitude_mode") = "relative",
          "The plan as an autopilot mission (vistrack.mission.Mission; save it as .plan, .waypoints or "
          ".geojson): one NAV_LOITER_TIME per segment about the POI's position at the segment's middle, "
          "with R(t) there, after a waypoint at the tangent entry of the first orbit; then a loiter over "
          "the POI's last position (end='loiter'), 'rtl' or 'none'. georeference: vistrack.Georeference or "
          "(lat, lon[, alt]); altitude (m above the ground at the origin) and speed default to the plan's "
          "UAV when it has one. A companion computer flying the vector field tracks far better: the "
          "autopilot circles fixed centres one after the other. See vistrack.mission.orbit_plan_mission.");

  m.def("max_inscribed_radius", &max_inscribed_radius, py::arg("polygons"), py::arg("center"),
        "Radius of the largest circle centred at `center` inside the visibility polygon: the "
        "distance to the nearest boundary (holes included) of the polygon containing the centre, "
        "0 when none contains it.");
  m.def("constant_radius_plan", &constant_radius_plan, py::arg("poi"), py::arg("radius"), py::arg("uav"),
        "Baseline plan: orbits of one radius along the whole POI path.");
  m.def("orbit_curvature", &orbit_curvature, py::arg("radius"), py::arg("radius_rate"), py::arg("relative_angle"),
        py::arg("uav_speed"), py::arg("poi_speed"), py::arg("direction") = Circulation::CounterClockwise,
        "Curvature (31) of the path that stays on the orbit at a = theta - gamma, with theta' from (13) for the "
        "circulation 'ccw' or 'cw'; inf when (g'.e_r + R')^2 >= v^2 (Lemma 5).");
  m.def("max_orbit_curvature", &max_orbit_curvature, py::arg("radius"), py::arg("uav_speed"), py::arg("poi_speed"),
        "Lemma 6: (1 + v_g/v)^2 / R, the largest curvature (31) over angles and admissible dR/dt.");
  m.def("min_feasible_radius", &min_feasible_radius, py::arg("uav"), py::arg("poi_speed"),
        "r_min (1 + v_g/v)^2: the smallest orbit radius Lemma 6 allows (at most 4 r_min, Corollary 1).");

  py::class_<CircularOrbits>(m, "CircularOrbits", "Result of Algorithm 1 on given MaxRadius values.")
      .def_readonly("radii", &CircularOrbits::radii, "R_k after the forward and backward rate passes (m).")
      .def_readonly("radius_rates", &CircularOrbits::radius_rates, "dR/dt per segment (m/s).")
      .def_readonly("min_feasible_radius", &CircularOrbits::min_feasible_radius, "r_min (1 + v_g/v)^2 (m).")
      .def_readonly("feasible", &CircularOrbits::feasible, "Every sample passes Lemma 6.")
      .def_readonly("failing_samples", &CircularOrbits::failing_samples, "Samples that break Lemma 6.")
      .def_readonly("infeasibility", &CircularOrbits::infeasibility, "The first failing sample and why.");
  m.def("circular_orbits", &circular_orbits, py::arg("times"), py::arg("max_radii"), py::arg("uav"),
        py::arg("poi_speed"), py::arg("rate_margin") = Planning{}.rate_margin,
        "Algorithm 1 (lines 2-18): lower radii so that |dR/dt| <= (1 - rate_margin)(v - v_g) (Lemma 5 "
        "for rate_margin = 0), each limited radius built from its neighbour's, then check "
        "R_k >= r_min (1 + v_g/v)^2 (Lemma 6). VistrackError when the UAV is not faster than the POI.");

  py::class_<Discretization>(m, "Discretization", "VV samples along the POI path (section IV.B).")
      .def_readonly("arc_lengths", &Discretization::arc_lengths, "s_k along the path (m).")
      .def_readonly("times", &Discretization::times, "t_k = s_k / v_g (s).")
      .def_readonly("points", &Discretization::points, "g(t_k), (n, 3).")
      .def_readonly("depths", &Discretization::depths, "0 for initial samples, d for one inserted at halving d.")
      .def_readonly("metric", &Discretization::metric, "d(alpha_k, alpha_k+1) of eq. (56) (m^3), size n - 1.")
      .def_readonly("volumes_computed", &Discretization::volumes_computed, "VVs computed by this call.")
      .def_property_readonly("num_volumes", [](const Discretization& d) { return d.volumes.size(); },
                             "VVs held (none for a plan read from JSON).")
      .def("volume", [](const Discretization& d, std::size_t k) { return VisibilityVolume(*d.volumes.at(k)); },
           py::arg("k"), "A copy of VV k.");

  // The sample-wise fields read through to the parts the plan is composed of.
  py::class_<VisibilityOrbitPlan, OrbitPlan>(
      m, "VisibilityOrbitPlan",
      "An orbit plan with what it was made from: samples and VVs, VPs, MaxRadius, Algorithm 1's result.")
      .def_readonly("uav", &VisibilityOrbitPlan::uav)
      .def_readonly("sensor", &VisibilityOrbitPlan::sensor)
      .def_readonly("planning", &VisibilityOrbitPlan::planning)
      .def_readonly("discretization", &VisibilityOrbitPlan::samples, "The VV samples (a Discretization).")
      .def_readonly("orbits", &VisibilityOrbitPlan::orbits, "Algorithm 1's result (a CircularOrbits).")
      .def_readonly("max_radii", &VisibilityOrbitPlan::max_radii, "MaxRadius of each VP (m), line 1 of Algorithm 1.")
      .def_readonly("polygons", &VisibilityOrbitPlan::polygons, "VPs at h_UAV, one list of Polygon per sample.")
      .def_property_readonly("arc_lengths", [](const VisibilityOrbitPlan& p) { return p.samples.arc_lengths; },
                             "s_k of the samples (m).")
      .def_property_readonly("depths", [](const VisibilityOrbitPlan& p) { return p.samples.depths; },
                             "Refinement depth of each sample.")
      .def_property_readonly("metric", [](const VisibilityOrbitPlan& p) { return p.samples.metric; },
                             "XOR volume (56) between neighbouring VVs (m^3).")
      .def_property_readonly("volumes_computed", [](const VisibilityOrbitPlan& p) { return p.samples.volumes_computed; },
                             "VVs computed by this plan.")
      .def_property_readonly("num_volumes", [](const VisibilityOrbitPlan& p) { return p.samples.volumes.size(); },
                             "VVs held (none for a plan read from JSON).")
      .def("volume",
           [](const VisibilityOrbitPlan& p, std::size_t k) { return VisibilityVolume(*p.samples.volumes.at(k)); },
           py::arg("k"), "A copy of the VV of sample k (VVs are not stored in JSON).")
      .def_property_readonly("radius_rates", [](const VisibilityOrbitPlan& p) { return p.orbits.radius_rates; },
                             "dR/dt per segment (m/s).")
      .def_property_readonly("min_feasible_radius",
                             [](const VisibilityOrbitPlan& p) { return p.orbits.min_feasible_radius; },
                             "r_min (1 + v_g/v)^2 (m), Lemma 6.")
      .def_property_readonly("failing_samples", [](const VisibilityOrbitPlan& p) { return p.orbits.failing_samples; },
                             "Samples that break Lemma 6.")
      .def("to_json", py::overload_cast<const VisibilityOrbitPlan&>(&to_json), "The plan as JSON (without VVs).")
      .def_static("from_json", &visibility_orbit_plan_from_json, py::arg("text"), "A plan from its JSON text.");

  m.def(
      "plan_on_volumes",
      [](const PoiPath& poi, const Uav& uav, const Planning& planning, const std::vector<double>& arc_lengths,
         const std::vector<VisibilityVolume>& volumes) {
        std::vector<VolumePtr> shared;
        for (const VisibilityVolume& vv : volumes) shared.push_back(std::make_shared<const VisibilityVolume>(vv));
        py::gil_scoped_release release;
        return plan_on_volumes(poi, uav, planning, arc_lengths, shared);
      },
      py::arg("poi"), py::arg("uav"), py::arg("planning"), py::arg("arc_lengths"), py::arg("volumes"),
      "The plan on VVs computed elsewhere (e.g. saved VV files), placed at the given increasing arc lengths of "
      "the POI path: metric (56) in the POI frame, VPs at h_UAV, MaxRadius and Algorithm 1, nothing inserted.");

  py::class_<OrbitPlanner>(m, "OrbitPlanner",
                           "Section IV on one environment: an Embree scene built once, VV caches shared by every "
                           "call (spacings and plans reuse VVs; one per grid resolution), the XOR metric (56) in the "
                           "POI frame, VPs at world z = h_UAV.")
      .def(py::init([](const Environment& env, const Sensor& sensor, const py::object& cache_dir) {
             const std::string folder = path_string(cache_dir);
             py::gil_scoped_release release;
             return std::make_unique<OrbitPlanner>(env, sensor, folder);
           }),
           py::arg("env"), py::arg("sensor"), py::arg("cache_dir") = py::none(),
           "cache_dir (str or os.PathLike, created when missing): keep every VV on disk there, keyed by the "
           "environment fingerprint, the POI position, d_max, the altitude band and the resolution, so a "
           "later planner with the same inputs reads them instead of ray casting. None: no disk cache.")
      .def(
          "adaptive",
          [](OrbitPlanner& p, const PoiPath& poi, const Planning& planning, const py::object& progress) {
            const ProgressFunction report = progress_callback(progress);
            py::gil_scoped_release release;
            return p.adaptive(poi, planning, report);
          },
          py::arg("poi"), py::arg("planning"), py::arg("progress") = py::none(),
          "Adaptive discretization (IV.B): initial spacing, halving while the metric exceeds the cutoff. "
          "progress(done, total) is called as VVs are computed.")
      .def(
          "fixed",
          [](OrbitPlanner& p, const PoiPath& poi, double spacing, double resolution_deg, const py::object& progress) {
            const ProgressFunction report = progress_callback(progress);
            py::gil_scoped_release release;
            return p.fixed(poi, spacing, resolution_deg, report);
          },
          py::arg("poi"), py::arg("spacing"), py::arg("resolution_deg") = Planning{}.resolution_deg,
          py::arg("progress") = py::none(),
          "VVs every `spacing` m from each edge start plus every node, and the metric between neighbours.")
      .def(
          "plan",
          [](OrbitPlanner& p, const PoiPath& poi, const Uav& uav, const Planning& planning, const py::object& progress) {
            const ProgressFunction report = progress_callback(progress);
            py::gil_scoped_release release;
            return p.plan(poi, uav, planning, report);
          },
          py::arg("poi"), py::arg("uav"), py::arg("planning"), py::arg("progress") = py::none(),
          "Adaptive VVs, VPs at h_UAV, MaxRadius and Algorithm 1: a VisibilityOrbitPlan.")
      .def_property_readonly("cached_volumes", &OrbitPlanner::cached_volumes, "VVs held in the caches.")
      .def_property_readonly("disk_hits", &OrbitPlanner::disk_hits,
                             "VVs read from the disk cache so far (0 without cache_dir).")
      .def_property_readonly("disk_misses", &OrbitPlanner::disk_misses,
                             "VVs computed and written to the disk cache so far (0 without cache_dir).")
      .def_property_readonly("scene", &OrbitPlanner::scene, py::return_value_policy::reference_internal,
                             "The planner's Embree scene (for line-of-sight queries on the same city).");
  m.def(
      "plan_orbits",
      [](const Environment& env, const PoiPath& poi, const Uav& uav, const Sensor& sensor, const Planning& planning,
         const py::object& progress, const py::object& cache_dir) {
        const ProgressFunction report = progress_callback(progress);
        const std::string folder = path_string(cache_dir);
        py::gil_scoped_release release;
        return plan_orbits(env, poi, uav, sensor, planning, report, folder);
      },
      py::arg("env"), py::arg("poi"), py::arg("uav"), py::arg("sensor"), py::arg("planning"),
      py::arg("progress") = py::none(), py::arg("cache_dir") = py::none(),
      "Section IV end to end: adaptive VVs along the POI path (IV.B), VPs at h_UAV, MaxRadius, then "
      "Algorithm 1 (IV.C). cache_dir: as for OrbitPlanner. Returns a VisibilityOrbitPlan (an OrbitPlan); infeasible "
      "plans say which sample fails and why. VistrackError when the UAV is not faster than the POI.");
}

}  // namespace vistrack::bindings
