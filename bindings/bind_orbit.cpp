#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "vistrack/orbit.hpp"

namespace py = pybind11;

namespace vistrack::bindings {

void bind_orbit(py::module_& m) {
  py::class_<OrbitPlan>(m, "OrbitPlan",
                        "Time-varying reference orbit about the POI: R(t) piecewise linear between "
                        "samples (times, radii), centred on the POI path g(t) (eq. 5).")
      .def_readonly("poi", &OrbitPlan::poi, "The POI path g(t).")
      .def_readonly("times", &OrbitPlan::times, "Sample times t_k (s).")
      .def_readonly("radii", &OrbitPlan::radii, "Orbit radii R(t_k) after Algorithm 1 (m).")
      .def_readonly("max_radii", &OrbitPlan::max_radii, "MaxRadius from the visibility polygons (m).")
      .def_readonly("metric", &OrbitPlan::metric, "XOR volume between neighbouring VVs (m^3).")
      .def_readonly("feasible", &OrbitPlan::feasible, "Whether Algorithm 1 found the plan feasible.")
      .def_readonly("infeasibility", &OrbitPlan::infeasibility, "Which sample fails and why.")
      .def_property_readonly(
          "centers",
          [](const OrbitPlan& p) {
            Points2 centers(static_cast<Eigen::Index>(p.times.size()), 2);
            for (std::size_t k = 0; k < p.times.size(); ++k)
              centers.row(static_cast<Eigen::Index>(k)) = p.poi.position(p.times[k]).head<2>().transpose();
            return centers;
          },
          "Orbit centres g(t_k), array (n, 2).")
      .def("radius", &OrbitPlan::radius, py::arg("t"), "R(t), linear between samples.")
      .def("radius_rate", &OrbitPlan::radius_rate, py::arg("t"), "dR/dt on the segment containing t.")
      .def("to_json", [](const OrbitPlan& p) { return to_json(p); }, "The plan as JSON text.")
      .def_static("from_json", &orbit_plan_from_json, py::arg("text"), "A plan from JSON text.");

  m.def("max_inscribed_radius",
        [](const std::vector<Polygon>& polygons, const Vec2& center) {
          return max_inscribed_radius(polygons, center);
        },
        py::arg("polygons"), py::arg("center"),
        "Radius of the largest circle centred at `center` inside the visibility polygon: the "
        "distance to the nearest boundary (holes included) of the polygon containing the centre, "
        "0 when none contains it.");
  m.def("constant_radius_plan", &constant_radius_plan, py::arg("poi"), py::arg("radius"), py::arg("uav"),
        "Baseline plan: orbits of one radius along the whole POI path.");
}

}  // namespace vistrack::bindings
