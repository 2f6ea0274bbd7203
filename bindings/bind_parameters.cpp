#include <pybind11/stl.h>

#include "bindings.hpp"
#include "vistrack/error.hpp"
#include "vistrack/dubins_parameters.hpp"
#include "vistrack/guidance_parameters.hpp"
#include "vistrack/orbit_parameters.hpp"
#include "vistrack/simulate_parameters.hpp"
#include "vistrack/visibility_parameters.hpp"

namespace py = pybind11;

namespace vistrack::bindings {

void bind_parameters(py::module_& m) {
  const Uav uav_defaults;
  py::class_<Uav>(m, "Uav",
                  "The vehicle: constant speed, minimum turn radius, altitude, and how it turns: dynamics "
                  "'dubins' (the turn rate follows the guidance at once, the papers' vehicle) or 'roll' (the bank "
                  "a first-order, rate-limited state: Beard & McLain ch. 9; SI units only).")
      .def(py::init([](double speed, double min_turn_radius, double altitude, DynamicsModel dynamics,
                       double roll_time_constant, double max_roll_rate_deg_s) {
             return make_validated(
                 Uav{speed, min_turn_radius, altitude, dynamics, roll_time_constant, max_roll_rate_deg_s});
           }),
           py::kw_only(), py::arg("speed") = uav_defaults.speed,
           py::arg("min_turn_radius") = uav_defaults.min_turn_radius,
           py::arg("altitude") = uav_defaults.altitude, py::arg("dynamics") = uav_defaults.dynamics,
           py::arg("roll_time_constant") = uav_defaults.roll_time_constant,
           py::arg("max_roll_rate_deg_s") = uav_defaults.max_roll_rate_deg_s,
           "speed v (m/s), min_turn_radius r_min (m), altitude h_UAV (m), dynamics 'dubins' or 'roll', the roll "
           "model's time constant tau (s; ArduPlane RLL2SRV_TCONST 0.5) and maximum roll rate (deg/s; PX4 "
           "FW_R_RMAX 70).")
      .def_readwrite("speed", &Uav::speed, "v, m/s")
      .def_readwrite("min_turn_radius", &Uav::min_turn_radius, "r_min, m")
      .def_readwrite("altitude", &Uav::altitude, "h_UAV, m")
      .def_readwrite("dynamics", &Uav::dynamics, "'dubins' or 'roll'")
      .def_readwrite("roll_time_constant", &Uav::roll_time_constant, "tau of the roll model, s")
      .def_readwrite("max_roll_rate_deg_s", &Uav::max_roll_rate_deg_s, "the roll model's rate limit, deg/s")
      .def("validate", &Uav::validate, "Raise VistrackError naming the first invalid field.")
      .def("__repr__", [](const Uav& u) {
        Repr text("Uav");
        text.add("speed", u.speed).add("min_turn_radius", u.min_turn_radius).add("altitude", u.altitude);
        text.add("dynamics", u.dynamics);
        if (u.dynamics == DynamicsModel::Roll)
          text.add("roll_time_constant", u.roll_time_constant).add("max_roll_rate_deg_s", u.max_roll_rate_deg_s);
        return text.str();
      });

  const PoiMotion poi_defaults;
  py::class_<PoiMotion>(m, "PoiMotion", "The POI's defaults: its speed along the road path and its height above "
                                        "the surface where a point is given without z.")
      .def(py::init([](double speed, double height) {
             require_positive(speed, "poi.speed");
             require_non_negative(height, "poi.height");
             return PoiMotion{speed, height};
           }),
           py::kw_only(), py::arg("speed") = poi_defaults.speed, py::arg("height") = poi_defaults.height,
           "speed v_g (m/s), height (m above the surface).")
      .def_readonly("speed", &PoiMotion::speed, "v_g, m/s")
      .def_readonly("height", &PoiMotion::height, "m above the surface");

  const Sensor sensor_defaults;
  py::class_<Sensor>(m, "Sensor", "Line-of-sight sensor: range d_max and optional altitude band.")
      .def(py::init([](double d_max, std::optional<std::pair<double, double>> band) {
             return make_validated(Sensor{d_max, band});
           }),
           py::kw_only(), py::arg("d_max") = sensor_defaults.d_max, py::arg("altitude_band") = py::none(),
           "d_max (m); altitude_band (h_lo, h_hi) in m or None for no band.")
      .def_readwrite("d_max", &Sensor::d_max, "maximum viewing distance, m")
      .def_readwrite("altitude_band", &Sensor::altitude_band, "(h_lo, h_hi) in m, or None")
      .def("validate", [](const Sensor& s) { s.validate(); }, "Raise VistrackError naming the first invalid field.");

  const Planning planning_defaults;
  py::class_<Planning>(m, "Planning", "Adaptive placement of visibility volumes (section IV.B).")
      .def(py::init([](double spacing, double cutoff, double resolution_deg, double min_spacing,
                       int max_depth, double rate_margin, const std::string& locus, double tracking_margin,
                       double check_spacing, double check_min_spacing, double turn_share, std::size_t max_volumes,
                       double radius_smoothing) {
             return make_validated(Planning{spacing, cutoff, resolution_deg, min_spacing, max_depth, rate_margin,
                                            max_volumes, from_name<Locus>(locus), tracking_margin, check_spacing,
                                            check_min_spacing, turn_share, radius_smoothing});
           }),
           py::kw_only(), py::arg("spacing") = planning_defaults.spacing,
           py::arg("cutoff") = planning_defaults.cutoff,
           py::arg("resolution_deg") = planning_defaults.resolution_deg,
           py::arg("min_spacing") = planning_defaults.min_spacing,
           py::arg("max_depth") = planning_defaults.max_depth,
           py::arg("rate_margin") = planning_defaults.rate_margin,
           py::arg("locus") = to_string(planning_defaults.locus),
           py::arg("tracking_margin") = planning_defaults.tracking_margin,
           py::arg("check_spacing") = planning_defaults.check_spacing,
           py::arg("check_min_spacing") = planning_defaults.check_min_spacing,
           py::arg("turn_share") = planning_defaults.turn_share,
           py::arg("max_volumes") = planning_defaults.max_volumes,
           py::arg("radius_smoothing") = planning_defaults.radius_smoothing,
           "spacing (m), cutoff d_cutoff (m^3), resolution_deg, min_spacing (m), max_depth, rate_margin; "
           "locus 'smooth' (checked between samples, C1, the default) or 'paper' (Algorithm 1, piecewise linear); "
           "tracking_margin (m), check_spacing and check_min_spacing (m), turn_share (smooth locus only); "
           "max_volumes (the largest worst-case VV count a plan may ask for); radius_smoothing (smooth locus only).")
      .def_readwrite("spacing", &Planning::spacing, "initial spacing of VVs along the path, m")
      .def_readwrite("cutoff", &Planning::cutoff, "d_cutoff, m^3")
      .def_readwrite("resolution_deg", &Planning::resolution_deg, "VV ray grid step, degrees")
      .def_readwrite("min_spacing", &Planning::min_spacing, "smallest spacing inserted, m")
      .def_readwrite("max_depth", &Planning::max_depth, "most halvings of one initial interval")
      .def_readwrite("rate_margin", &Planning::rate_margin,
                     "Algorithm 1 keeps |dR/dt| <= (1 - rate_margin)(v - v_g); 0 = Lemma 5's limit (the paper)")
      .def_readwrite("max_volumes", &Planning::max_volumes,
                     "refuse, before computing any VV, a plan that may need more VVs than this (worst case: "
                     "about path length / min_spacing, ~4.7 MB each at 1 degree)")
      .def_property(
          "locus", [](const Planning& p) { return to_string(p.locus); },
          [](Planning& p, const std::string& text) { p.locus = from_name<Locus>(text); },
          "'smooth': R(t) checked against MaxRadius along the whole path, tracking_margin inside it, C1 with "
          "bounded d2R/dt2 (default); 'paper': Algorithm 1's piecewise-linear R(t) through the samples")
      .def_readwrite("tracking_margin", &Planning::tracking_margin,
                     "smooth locus: R(t) stays this far inside MaxRadius (m)")
      .def_readwrite("check_spacing", &Planning::check_spacing,
                     "smooth locus: MaxRadius is checked every check_spacing m of POI travel, then refined")
      .def_readwrite("check_min_spacing", &Planning::check_min_spacing,
                     "smooth locus: the check halves intervals where R(t) touches its bound down to this (m)")
      .def_readwrite("turn_share", &Planning::turn_share,
                     "smooth locus: share of the turn rate Lemma 6 leaves free that d2R/dt2 may use, in (0, 1)")
      .def_readwrite("radius_smoothing", &Planning::radius_smoothing,
                     "smooth locus, beyond the paper: weight of the d2R/dt2 penalty (holding the largest d2R/dt2 "
                     "costs radius_smoothing / 2 of the ceiling's top radius); 0 = the largest-area R(t)")
      .def("validate", &Planning::validate, "Raise VistrackError naming the first invalid field.");

  const Control control_defaults;
  py::class_<Control>(m, "Control", "Guidance gains (section V): beta, k_psi, direction.")
      .def(py::init([](double beta, double k_psi, Circulation direction) {
             return make_validated(Control{beta, k_psi, direction});
           }),
           py::kw_only(), py::arg("beta") = control_defaults.beta,
           py::arg("k_psi") = control_defaults.k_psi, py::arg("direction") = control_defaults.direction,
           "beta (circulation), k_psi (heading gain), direction 'ccw' or 'cw'.")
      .def_readwrite("beta", &Control::beta, "circulation parameter")
      .def_readwrite("k_psi", &Control::k_psi, "heading gain")
      .def_readwrite("direction", &Control::direction, "'ccw' or 'cw'")
      .def("validate", &Control::validate, "Raise VistrackError naming the first invalid field.");

  const SimulationOptions sim_defaults;
  py::class_<SimulationOptions>(m, "SimulationOptions", "Closed-loop integration settings.")
      .def(py::init([](double rtol, double atol, double max_step, double output_step) {
             return make_validated(SimulationOptions{rtol, atol, max_step, output_step});
           }),
           py::kw_only(), py::arg("rtol") = sim_defaults.rtol, py::arg("atol") = sim_defaults.atol,
           py::arg("max_step") = sim_defaults.max_step, py::arg("output_step") = sim_defaults.output_step,
           "rtol, atol, max_step (s), output_step (s).")
      .def_readwrite("rtol", &SimulationOptions::rtol, "relative tolerance")
      .def_readwrite("atol", &SimulationOptions::atol, "absolute tolerance")
      .def_readwrite("max_step", &SimulationOptions::max_step, "largest step, s")
      .def_readwrite("output_step", &SimulationOptions::output_step, "output sample spacing, s")
      .def("validate", &SimulationOptions::validate, "Raise VistrackError naming the first invalid field.");
}

}  // namespace vistrack::bindings
