#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "vistrack/environment.hpp"
#include "vistrack/error.hpp"
#include "vistrack/simulate.hpp"
#include "vistrack/visibility.hpp"

namespace py = pybind11;

namespace vistrack::bindings {

namespace {

// A Python callable line_of_sight(from (n, 3), to (n, 3)) -> array (n,) of bools (or 0/1), called
// with the GIL. Anything else (NaN, 0.5, a string) is an Error naming the sample: a cast to bool
// would count NaN as visible.
LineOfSight python_line_of_sight(py::function function) {
  return [function](const Points3& from, const Points3& to) {
    py::gil_scoped_acquire acquire;
    py::array_t<double, py::array::c_style | py::array::forcecast> answer;
    try {
      answer = function(from, to).cast<py::array_t<double, py::array::c_style | py::array::forcecast>>();
    } catch (const py::cast_error&) {
      throw Error("line_of_sight: must return an array of bools (one per sample)");
    }
    std::vector<std::uint8_t> out(static_cast<std::size_t>(answer.size()));
    for (py::ssize_t i = 0; i < answer.size(); ++i) {
      const double value = answer.data()[i];
      if (value != 0.0 && value != 1.0)
        detail::fail_field("line_of_sight(...)[" + std::to_string(i) + "]", value, "must be True/False (or 1/0)");
      out[static_cast<std::size_t>(i)] = value == 1.0 ? 1 : 0;
    }
    return out;
  };
}

}  // namespace

void bind_simulate(py::module_& m) {
  py::class_<SimulationResult>(m, "SimulationResult", "Closed-loop trajectory and its errors (section VI).")
      .def_property_readonly("t", [](const SimulationResult& r) { return to_numpy(r.t); }, "output times (n,), s")
      .def_readonly("state", &SimulationResult::state, "(n, 3): x, y, psi (psi as integrated, unwrapped)")
      .def_property_readonly("desired_heading", [](const SimulationResult& r) { return to_numpy(r.desired_heading); },
                             "psi_d (77) at each sample, rad")
      .def_property_readonly("desired_heading_rate",
                             [](const SimulationResult& r) { return to_numpy(r.desired_heading_rate); },
                             "dpsi_d/dt along the field (85), rad/s")
      .def_property_readonly("radial_error", [](const SimulationResult& r) { return to_numpy(r.radial_error); },
                             "r - R, m")
      .def_property_readonly("heading_error", [](const SimulationResult& r) { return to_numpy(r.heading_error); },
                             "psi - psi_d wrapped to (-pi, pi], rad")
      .def_property_readonly("control", [](const SimulationResult& r) { return to_numpy(r.control); },
                             "turn rate u_psi commanded by (86) (clamped to +-v/r_min), rad/s; the Dubins "
                             "vehicle flies it at once")
      .def_property_readonly("turn_rate", [](const SimulationResult& r) { return to_numpy(r.turn_rate); },
                             "turn rate flown: u_psi (dubins) or g tan(phi) / v (roll), rad/s")
      .def_property_readonly("bank", [](const SimulationResult& r) { return to_numpy(r.bank); },
                             "bank (n,), rad: the roll model's state, or the coordinated bank of u_psi (dubins)")
      .def_property_readonly("control_unsaturated",
                             [](const SimulationResult& r) { return to_numpy(r.control_unsaturated); },
                             "the steering law (86) before the clamp, rad/s")
      .def_readonly("poi", &SimulationResult::poi, "(n, 3) POI position g(t)")
      .def_property_readonly("orbit_radius", [](const SimulationResult& r) { return to_numpy(r.orbit_radius); },
                             "R(t), m")
      .def_property_readonly("restart_times", [](const SimulationResult& r) { return to_numpy(r.restart_times); },
                             "segment boundaries where the integrator restarted, s")
      .def_property_readonly(
          "visible",
          [](const SimulationResult& r) -> py::object {
            if (r.visible.empty() && !r.visibility_fraction) return py::none();
            py::array_t<bool> out(static_cast<py::ssize_t>(r.visible.size()));
            for (std::size_t i = 0; i < r.visible.size(); ++i) out.mutable_data()[i] = r.visible[i] != 0;
            return std::move(out);
          },
          "line of sight UAV -> POI at each sample (bool array), or None when not evaluated")
      .def_readonly("visibility_fraction", &SimulationResult::visibility_fraction,
                    "fraction of samples with line of sight, or None")
      .def_readonly("statistics", &SimulationResult::statistics, "integrator work (all segments)")
      .def("to_csv", &trajectory_csv,
           "The trajectory as CSV text (header t,x,y,psi,psi_d,psi_d_rate,radial_error,heading_error,"
           "u_psi,u_psi_unsaturated,poi_x,poi_y,poi_z,orbit_radius[,visible]), as vistrack_sim writes it.");

  m.def(
      "simulate",
      [](const OrbitPlan& plan, const Uav& uav, const Vec3& x0, const Control& control, py::object env,
         const SimulationOptions& options, std::optional<py::function> line_of_sight, double fixed_step) {
        if (!env.is_none()) {
          if (line_of_sight) throw Error("line_of_sight: give either env or line_of_sight, not both");
          std::optional<VisibilityScene> scene;
          if (py::isinstance<VisibilityScene>(env)) {
            scene = env.cast<VisibilityScene>();
          } else if (py::isinstance<Environment>(env)) {
            const Environment& environment = env.cast<const Environment&>();
            py::gil_scoped_release release;
            scene.emplace(environment);
          } else {
            throw Error("env: expected an Environment or a VisibilityScene, got " +
                        std::string(py::str(py::type::of(env).attr("__name__"))));
          }
          py::gil_scoped_release release;
          return simulate(plan, uav, x0, control, options, *scene, fixed_step);
        }
        LineOfSight los;
        if (line_of_sight) los = python_line_of_sight(*line_of_sight);
        py::gil_scoped_release release;
        return simulate(plan, uav, x0, control, options, los, fixed_step);
      },
      py::arg("plan"), py::arg("uav"), py::arg("x0"), py::arg("control"), py::arg("env") = py::none(),
      py::arg("options") = SimulationOptions{}, py::kw_only(), py::arg("line_of_sight") = py::none(),
      py::arg("fixed_step") = 0.0,
      "Closed loop of section VI: the Dubins vehicle (1) from x0 = (x, y, psi) steered by (86) around "
      "the plan's time-varying orbit, Dormand-Prince 5(4) restarted at each segment boundary "
      "(options.rtol/atol/max_step; fixed_step > 0 for fixed steps), sampled every "
      "options.output_step. With env (an Environment or a VisibilityScene: Embree occlusion rays from "
      "the UAV at world z = uav.altitude to the POI, lifted onto the surface where its path z is "
      "underground) or a line_of_sight(from (n, 3), to (n, 3)) -> bool array callable (UAV at z = "
      "uav.altitude, POI at its path z), also the line of sight at every "
      "sample and the visibility fraction. Releases the GIL.");

  py::class_<TuningResult>(m, "TuningResult", "Grid search of max |dpsi_d/dt + u_lyap| (section V.D).")
      .def_readonly("max_turn_rate", &TuningResult::max_turn_rate, "max |dpsi_d/dt + u_lyap|, rad/s")
      .def_readonly("at_r", &TuningResult::at_r, "distance to the POI of the maximum, m")
      .def_readonly("at_theta", &TuningResult::at_theta, "polar angle of the maximum from the POI's motion, rad")
      .def_readonly("at_heading_error", &TuningResult::at_heading_error, "heading error of the maximum, rad")
      .def_property_readonly("radii", [](const TuningResult& r) { return to_numpy(r.radii); }, "grid radii, m")
      .def_property_readonly("angles", [](const TuningResult& r) { return to_numpy(r.angles); }, "grid angles, rad")
      .def_property_readonly(
          "map",
          [](const TuningResult& r) {
            py::array_t<double> out({static_cast<py::ssize_t>(r.radii.size()), static_cast<py::ssize_t>(r.angles.size())});
            std::copy(r.map.begin(), r.map.end(), out.mutable_data());
            return out;
          },
          "(num_radii, num_angles): max over heading errors at each grid point, rad/s");

  m.def(
      "tune_turn_rate",
      [](double radius, double radius_rate, double speed, double poi_speed, double beta, Circulation direction,
         double tau, double r_max_factor, int num_radii, int num_angles, int num_heading_errors) {
        TuningGrid grid{tau, r_max_factor, num_radii, num_angles, num_heading_errors};
        py::gil_scoped_release release;
        return tune_turn_rate(radius, radius_rate, speed, poi_speed, beta, direction, grid);
      },
      py::arg("radius"), py::arg("radius_rate"), py::arg("speed"), py::arg("poi_speed"), py::arg("beta"),
      py::kw_only(), py::arg("direction") = Circulation::CounterClockwise, py::arg("tau") = TuningGrid{}.tau,
      py::arg("r_max_factor") = TuningGrid{}.r_max_factor, py::arg("num_radii") = TuningGrid{}.num_radii,
      py::arg("num_angles") = TuningGrid{}.num_angles, py::arg("num_heading_errors") = TuningGrid{}.num_heading_errors,
      "Largest |dpsi_d/dt + u_lyap| (85), (106) over r in [tau R, r_max_factor R], all polar angles and "
      "heading errors, for orbit radius R, dR/dt, UAV speed v, POI speed v_g and beta (Fig. 9). "
      "Compare with v / r_min.");
  m.def("orbit_state", &orbit_state, py::arg("plan"), py::arg("segment_start"), py::arg("t"),
        "The reference orbit (g, g_dot, R, dR/dt, d2R/dt2) at t on the segment that starts at segment_start "
        "(one of segment_boundaries(plan)): what the closed loop steers around, for an outside vehicle model "
        "(vistrack.fdm) with steering().");
  m.def("segment_boundaries", &segment_boundaries, py::arg("plan"),
        "Times where dR/dt or the POI velocity may jump: plan samples and path nodes.");
}

}  // namespace vistrack::bindings
