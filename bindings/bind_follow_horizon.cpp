// vistrack._core.follow: the receding-horizon city follower's programme (follow.hpp, The horizon city follower).
// Registered into the follow submodule after bind_follow.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <vector>

#include "bindings.hpp"
#include "vistrack/follow.hpp"

namespace py = pybind11;

namespace vistrack::bindings {

void bind_follow_horizon(py::module_& parent) {
  py::module_ m = parent.attr("follow").cast<py::module_>();
  const HorizonOptions defaults;
  py::class_<HorizonOptions>(m, "HorizonOptions",
                             "The horizon follower's programme: horizon (s, whole), the relative-position grid "
                             "(spacing and half_width, m), heading_step_deg, vehicle_height (m above the surface, "
                             "where the rays end) and the integration step dt (s) of a second's flight.")
      .def(py::init([](int horizon, double spacing, double half_width, double heading_step_deg,
                       double vehicle_height, double dt) {
             return make_validated(HorizonOptions{horizon, spacing, half_width, heading_step_deg, vehicle_height, dt});
           }),
           py::kw_only(), py::arg("horizon") = defaults.horizon, py::arg("spacing") = defaults.spacing,
           py::arg("half_width") = defaults.half_width, py::arg("heading_step_deg") = defaults.heading_step_deg,
           py::arg("vehicle_height") = defaults.vehicle_height, py::arg("dt") = defaults.dt,
           "Every field by keyword; VistrackError naming a bad one.")
      .def_readonly("horizon", &HorizonOptions::horizon, "s of prediction")
      .def_readonly("spacing", &HorizonOptions::spacing, "m, the grid's step")
      .def_readonly("half_width", &HorizonOptions::half_width, "m, the grid's half-width about the vehicle")
      .def_readonly("heading_step_deg", &HorizonOptions::heading_step_deg, "degrees")
      .def_readonly("vehicle_height", &HorizonOptions::vehicle_height, "m above the surface")
      .def_readonly("dt", &HorizonOptions::dt, "s");

  py::class_<HorizonSecond>(m, "HorizonSecond", "The UAV after a second with a bank command held.")
      .def_readonly("position", &HorizonSecond::position, "(2,), m")
      .def_readonly("heading", &HorizonSecond::heading, "rad (not wrapped)")
      .def_readonly("bank", &HorizonSecond::bank, "rad");
  py::class_<HorizonChoice>(m, "HorizonChoice", "The horizon follower's command for the next second.")
      .def_readonly("bank_command", &HorizonChoice::bank_command, "rad, positive left wing down")
      .def_readonly("turn_rate", &HorizonChoice::turn_rate, "rad/s, g tan(bank_command) / v")
      .def_readonly("value", &HorizonChoice::value, "seconds in sight the programme expects over the horizon")
      .def_readonly("heading_for_vehicle", &HorizonChoice::heading_for_vehicle,
                    "nothing in sight from any command's end: the command steers for the vehicle")
      .def_readonly("next", &HorizonChoice::next, "the UAV a second later as planned (HorizonSecond)");

  py::class_<HorizonPlanner>(
      m, "HorizonPlanner",
      "Receding-horizon dynamic programming over bank commands (one per second, five levels) with the vehicle "
      "predicted over the horizon; a second scores when a ray reaches the vehicle and the camera sees it.")
      .def(py::init<const VisibilityScene&, const Uav&, const DownwardCamera&, double, const HorizonOptions&>(),
           py::arg("scene"), py::arg("uav"), py::arg("camera"), py::arg("flight_altitude"),
           py::arg("options") = HorizonOptions{},
           "flight_altitude: world z of the flight (ground level + uav.altitude). The camera table is built here.")
      .def(
          "choose",
          [](const HorizonPlanner& p, const InputArray& vehicle, const Vec2& wind, const Vec2& position,
             double heading, double bank) {
            std::vector<Vec2> points = to_points(vehicle, "vehicle");
            py::gil_scoped_release release;
            return p.choose(points, wind, position, heading, bank);
          },
          py::arg("vehicle"), py::arg("wind"), py::arg("position"), py::arg("heading"), py::arg("bank"),
          "The command for the next second (HorizonChoice). vehicle: (horizon + 1, 2), its predicted positions at "
          "0, 1, ..., horizon s; wind: (2,), the wind the follower knows; the UAV's position (2,), heading, bank.")
      .def(
          "first_values",
          [](const HorizonPlanner& p, const InputArray& vehicle, const Vec2& wind) {
            std::vector<Vec2> points = to_points(vehicle, "vehicle");
            std::vector<float> values;
            {
              py::gil_scoped_release release;
              values = p.first_values(points, wind);
            }
            const auto n = static_cast<py::ssize_t>(p.grid_side());
            py::array_t<float> out({static_cast<py::ssize_t>(p.banks().size()),
                                    static_cast<py::ssize_t>(p.heading_count()), n, n});
            std::copy(values.begin(), values.end(), out.mutable_data());
            return out;
          },
          py::arg("vehicle"), py::arg("wind"),
          "V_1: (bank level, heading index, east index, north index), the seconds in sight from each state a second "
          "ahead over the rest of the horizon.")
      .def(
          "value_at",
          [](const HorizonPlanner& p, const py::array_t<float, py::array::c_style | py::array::forcecast>& values,
             const Vec2& relative, double heading, double bank) {
            const std::vector<float> flat(values.data(), values.data() + values.size());
            return p.value_at(flat, relative, heading, bank);
          },
          py::arg("values"), py::arg("relative"), py::arg("heading"), py::arg("bank"),
          "first_values at a continuous state (relative: UAV - vehicle, (2,)): linear in bank and heading, bilinear "
          "in position, 0 off the grid.")
      .def("fly_second", &HorizonPlanner::fly_second, py::arg("position"), py::arg("heading"), py::arg("bank"),
           py::arg("bank_command"), py::arg("wind"),
           "The UAV's second with bank_command held (HorizonSecond), integrated as the flight layer's discrete step.")
      .def_property_readonly("banks", &HorizonPlanner::banks, "the five bank levels, rad")
      .def_property_readonly("grid_side", &HorizonPlanner::grid_side, "grid points per axis")
      .def_property_readonly("heading_count", &HorizonPlanner::heading_count, "headings on the grid")
      .def_property_readonly("options", &HorizonPlanner::options, "HorizonOptions");
}

}  // namespace vistrack::bindings
