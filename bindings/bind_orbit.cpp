#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <optional>

#include "bindings.hpp"
#include "vistrack/error.hpp"
#include "vistrack/orbit.hpp"
#include "vistrack/visibility.hpp"
#include "vistrack/volume.hpp"

namespace py = pybind11;

namespace vistrack::bindings {
namespace {

using TimeArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

// f at every element of t, in an array of t's shape.
template <class F>
py::array_t<double> elementwise(const TimeArray& t, F f) {
  py::array_t<double> out(std::vector<py::ssize_t>(t.shape(), t.shape() + t.ndim()));
  const double* src = t.data();
  double* dst = out.mutable_data();
  for (py::ssize_t i = 0; i < t.size(); ++i) dst[i] = f(src[i]);
  return out;
}

}  // namespace

void bind_orbit(py::module_& m) {
  py::class_<RadiusProfile>(m, "RadiusProfile",
                            "R(t) as the guidance follows it: piecewise linear between the knots (times, radii) "
                            "when rates is empty (the paper's locus, Definition 2), else C1 piecewise quadratic with "
                            "dR/dt = rates at the knots (the smooth locus).")
      .def(py::init([](std::vector<double> times, std::vector<double> radii, std::vector<double> rates) {
             RadiusProfile p{std::move(times), std::move(radii), std::move(rates)};
             p.validate();
             return p;
           }),
           py::arg("times"), py::arg("radii"), py::arg("rates") = std::vector<double>{},
           "Knots, R at the knots, and dR/dt at the knots (empty: piecewise linear).")
      .def_readonly("times", &RadiusProfile::times, "Knot times (s).")
      .def_readonly("radii", &RadiusProfile::radii, "R at the knots (m).")
      .def_readonly("rates", &RadiusProfile::rates, "dR/dt at the knots (m/s); empty when piecewise linear.")
      .def_property_readonly("smooth", &RadiusProfile::smooth, "True for the C1 piecewise-quadratic form.")
      .def_property_readonly("min_radius", &RadiusProfile::min_radius, "The smallest R(t) (m).")
      .def("radius_at", [](const RadiusProfile& p, const TimeArray& t) { return elementwise(t, [&](double x) { return p.radius(x); }); },
           py::arg("t"), "R(t) at every element of t (numpy in, numpy out).")
      .def("rate_at", [](const RadiusProfile& p, const TimeArray& t) { return elementwise(t, [&](double x) { return p.rate(x); }); },
           py::arg("t"), "dR/dt at every element of t.")
      .def("acceleration_at",
           [](const RadiusProfile& p, const TimeArray& t) { return elementwise(t, [&](double x) { return p.acceleration(x); }); },
           py::arg("t"), "d2R/dt2 at every element of t (0 when piecewise linear).");

  py::class_<OrbitPlan>(m, "OrbitPlan",
                        "Time-varying reference orbit about the POI that the guidance follows (eq. 5): centred on "
                        "the POI path g(t), of radius R(t) = `reference` (piecewise linear through (times, radii) "
                        "for the paper's locus, C1 piecewise quadratic for the smooth one).")
      .def_readonly("poi", &OrbitPlan::poi, "The POI path g(t).")
      .def_readonly("times", &OrbitPlan::times, "Sample times t_k (s): the orbit centres g(t_k).")
      .def_readonly("radii", &OrbitPlan::radii, "R(t_k) on the reference (m).")
      .def_readonly("feasible", &OrbitPlan::feasible, "Whether the plan is flyable (Lemmas 5 and 6).")
      .def_readonly("infeasibility", &OrbitPlan::infeasibility, "Which sample or time fails and why.")
      .def_property_readonly("reference", &OrbitPlan::profile,
                             "R(t) as the guidance follows it (a RadiusProfile, the piecewise-linear default filled in).")
      .def_property_readonly("knot_times", &OrbitPlan::knot_times,
                             "Knots of the reference: where dR/dt or d2R/dt2 may jump (the closed loop restarts there).")
      .def_property_readonly("centers", &OrbitPlan::centers, "Orbit centres g(t_k), array (n, 2).")
      .def("radius", &OrbitPlan::radius, py::arg("t"), "R(t) of the reference.")
      .def("radius_rate", &OrbitPlan::radius_rate, py::arg("t"), "dR/dt of the reference (on the segment containing t).")
      .def("radius_acceleration", &OrbitPlan::radius_acceleration, py::arg("t"), "d2R/dt2 of the reference.")
      .def("radius_at",
           [](const OrbitPlan& plan, const TimeArray& t) {
             const RadiusProfile p = plan.profile();
             return elementwise(t, [&](double x) { return p.radius(x); });
           },
           py::arg("t"), "R(t) exactly as the controller follows it, at every element of t (numpy in, numpy out).")
      .def("radius_rate_at",
           [](const OrbitPlan& plan, const TimeArray& t) {
             const RadiusProfile p = plan.profile();
             return elementwise(t, [&](double x) { return p.rate(x); });
           },
           py::arg("t"), "dR/dt of the reference at every element of t.")
      .def("to_json", py::overload_cast<const OrbitPlan&>(&to_json), "The plan as JSON text.")
      .def_static("from_json", &orbit_plan_from_json, py::arg("text"), "A plan from JSON text.");

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

  py::class_<WorkEstimate>(m, "WorkEstimate", "The work a plan may ask for, known before any VV is computed.")
      .def_readonly("volumes", &WorkEstimate::volumes, "Worst-case number of VVs (every interval halved).")
      .def_readonly("bytes_per_volume", &WorkEstimate::bytes_per_volume, "Memory of one VV (bytes).")
      .def_readonly("initial_volumes", &WorkEstimate::initial_volumes,
                    "The VVs every plan computes (one every spacing, and every node).")
      .def_property_readonly("bytes", &WorkEstimate::bytes, "Memory of all of them (bytes).")
      .def_property_readonly("initial_bytes", &WorkEstimate::initial_bytes,
                             "Memory of the initial VVs (bytes): refused above limits.MAX_WORK_BYTES.")
      .def("__repr__", [](const WorkEstimate& w) {
        return Repr("WorkEstimate").add("volumes", w.volumes).add("bytes", w.bytes()).str();
      });
  m.def("volume_bytes", &volume_bytes, py::arg("resolution_deg"), py::arg("with_mesh") = true,
        "Memory of one VV on a grid of resolution_deg degrees, estimated from above (bytes; ~4.7 MB at 1 "
        "degree); with_mesh=False: its intervals only (~1 MB).");
  m.def(
      "check_work",
      [](const PoiPath& poi, const Planning& planning) {
        const WorkEstimate work = estimate_work(poi, planning);
        check_work(work, planning.max_volumes);
        return work;
      },
      py::arg("poi"), py::arg("planning"),
      "estimate_work, and VistrackError naming planning.resolution_deg or planning.spacing when the initial "
      "VVs would hold more than limits.MAX_WORK_BYTES, or planning.max_volumes when the worst case exceeds it "
      "(what the planner does before computing any VV); returns the estimate.");
  m.def("estimate_work", &estimate_work, py::arg("poi"), py::arg("planning"),
        "Worst case of plan_orbits / OrbitPlanner.plan on this path: VVs (every initial interval halved down "
        "to min_spacing or max_depth) and their memory; the planner refuses a worst case beyond "
        "planning.max_volumes before computing any VV.");

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

  const SmoothRadiusLimits limit_defaults;
  py::class_<SmoothRadiusLimits>(m, "SmoothRadiusLimits",
                                 "Bounds of a smooth R(t): |dR/dt| <= max_rate and |d2R/dt2| <= turn_share (v / r_min - "
                                 "v (1 + v_g/v)^2 / R_lo) sqrt(v^2 - (v_g + |dR/dt|)^2).")
      .def(py::init([](double uav_speed, double poi_speed, double min_turn_radius, double max_rate, double turn_share) {
             return make_validated(SmoothRadiusLimits{uav_speed, poi_speed, min_turn_radius, max_rate, turn_share});
           }),
           py::kw_only(), py::arg("uav_speed") = limit_defaults.uav_speed, py::arg("poi_speed") = limit_defaults.poi_speed,
           py::arg("min_turn_radius") = limit_defaults.min_turn_radius, py::arg("max_rate") = limit_defaults.max_rate,
           py::arg("turn_share") = limit_defaults.turn_share, "v, v_g, r_min, the rate bound (<= v - v_g), turn_share.")
      .def_readonly("uav_speed", &SmoothRadiusLimits::uav_speed)
      .def_readonly("poi_speed", &SmoothRadiusLimits::poi_speed)
      .def_readonly("min_turn_radius", &SmoothRadiusLimits::min_turn_radius)
      .def_readonly("max_rate", &SmoothRadiusLimits::max_rate)
      .def_readonly("turn_share", &SmoothRadiusLimits::turn_share)
      .def("max_acceleration", &SmoothRadiusLimits::max_acceleration, py::arg("r_lo"), py::arg("rate"),
           "The bound on |d2R/dt2| for R >= r_lo and dR/dt = rate.");
  py::class_<Ceiling>(m, "Ceiling",
                      "An upper bound on R(t), piecewise linear: from starts[j] to ends[j] on [breaks[j], breaks[j+1]] "
                      "(the smaller side at a break).")
      .def(py::init([](std::vector<double> breaks, std::vector<double> starts, std::optional<std::vector<double>> ends) {
             Ceiling c{std::move(breaks), starts, ends ? std::move(*ends) : starts};
             c.validate();
             return c;
           }),
           py::arg("breaks"), py::arg("starts"), py::arg("ends") = py::none(),
           "Break times, the ceiling at the start and at the end of each interval (ends=None: a step ceiling).")
      .def_readonly("breaks", &Ceiling::breaks, "Break times (s).")
      .def_readonly("starts", &Ceiling::starts, "Value at the start of each interval (m).")
      .def_readonly("ends", &Ceiling::ends, "Value at the end of each interval (m).")
      .def("at", [](const Ceiling& c, const TimeArray& t) { return elementwise(t, [&](double x) { return c.at(x); }); },
           py::arg("t"), "The ceiling at every element of t.");
  m.def(
      "smooth_radius",
      [](const Ceiling& ceiling, const SmoothRadiusLimits& limits, double knot_spacing, int passes,
         double smoothing) {
        py::gil_scoped_release release;
        return smooth_radius(ceiling, limits, knot_spacing, passes, smoothing);
      },
      py::arg("ceiling"), py::arg("limits"), py::arg("knot_spacing") = 0.0, py::arg("passes") = 2,
      py::arg("smoothing") = Planning{}.radius_smoothing,
      "The C1 quadratic spline on uniform knots (knot_spacing; <= 0: picked from the d2R/dt2 bound) under the "
      "ceiling that obeys `limits` with the largest integral of R(t) less the d2R/dt2 penalty "
      "(smoothing / 2) (top / A^2) integral of (d2R/dt2)^2 (top: the ceiling's largest value, A: the d2R/dt2 "
      "bound there; smoothing 0: the largest integral, a banded linear program): a log-barrier interior "
      "point method, re-solved passes - 1 times with the d2R/dt2 budget of the radii reached. A RadiusProfile.");
  m.def("smooth_radius_violation", &smooth_radius_violation, py::arg("profile"), py::arg("limits"),
        "Why a smooth RadiusProfile breaks `limits` (|dR/dt| at a knot, |d2R/dt2| on a segment against the bound at "
        "its smallest R), or '' when it keeps them all.");
  m.def(
      "visible_disk_radius",
      [](const VisibilityScene& scene, const Vec3& poi, double altitude, const Sensor& sensor, int azimuths, int rings) {
        py::gil_scoped_release release;
        return visible_disk_radius(scene, poi, altitude, sensor, azimuths, rings);
      },
      py::arg("scene"), py::arg("poi"), py::arg("altitude"), py::arg("sensor"), py::arg("azimuths") = 360,
      py::arg("rings") = 8,
      "MaxRadius by line of sight (the locus check's probe): the largest disk at world z = altitude centred above "
      "the POI (placed on the surface) every point of which sees it, by occlusion rays along `azimuths` directions "
      "on `rings` circles and then by bisection.");

  py::class_<LocusCheck>(m, "LocusCheck",
                         "The locus check of a smooth plan: MaxRadius along the whole POI path, the ceilings R(t) obeys "
                         "between check points, and how much lower than the paper's piecewise-linear R(t) it is.")
      .def_readonly("arc_lengths", &LocusCheck::arc_lengths, "s_j of the check points (m).")
      .def_readonly("times", &LocusCheck::times, "t_j of the check points (s).")
      .def_readonly("max_radii", &LocusCheck::max_radii, "MaxRadius at the check points (m).")
      .def_readonly("ceiling", &LocusCheck::ceiling,
                    "The bound R(t) obeys: the lower bound of MaxRadius between check points minus the tracking margin.")
      .def_readonly("slope_bounds", &LocusCheck::slope_bounds, "Per interval: the MaxRadius slope assumed (m per m).")
      .def_readonly("volumes_computed", &LocusCheck::volumes_computed, "VVs the check computed.")
      .def_readonly("rounds", &LocusCheck::rounds, "Refinement rounds.")
      .def_readonly("paper_violations", &LocusCheck::paper_violations,
                    "Check points where the paper's piecewise-linear R(t) exceeds MaxRadius.")
      .def_readonly("paper_max_violation", &LocusCheck::paper_max_violation, "By how much at most (m).")
      .def_readonly("lowering", &LocusCheck::lowering, "Paper R(t_j) - smooth R(t_j) per check point (m).")
      .def_readonly("max_lowering", &LocusCheck::max_lowering, "Its largest value (m).")
      .def_readonly("max_lowering_time", &LocusCheck::max_lowering_time, "Where (s).")
      .def_readonly("min_clearance", &LocusCheck::min_clearance, "min_j MaxRadius - smooth R (m).");

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
      .def_readonly("check", &VisibilityOrbitPlan::check, "The locus check (a LocusCheck; empty for the paper's locus).")
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
                             "dR/dt per sample segment of Algorithm 1's piecewise-linear R(t) (m/s).")
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
          [](OrbitPlanner& p, const PoiPath& poi, double spacing, double resolution_deg, const py::object& progress,
             std::size_t max_volumes) {
            const ProgressFunction report = progress_callback(progress);
            py::gil_scoped_release release;
            return p.fixed(poi, spacing, resolution_deg, report, max_volumes);
          },
          py::arg("poi"), py::arg("spacing"), py::arg("resolution_deg") = kDefaultResolutionDeg,
          py::arg("progress") = py::none(), py::arg("max_volumes") = Planning{}.max_volumes,
          "VVs every `spacing` m from each edge start plus every node, and the metric between neighbours; "
          "VistrackError before any work when that is more than max_volumes VVs.")
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
