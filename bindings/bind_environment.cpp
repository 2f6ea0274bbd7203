#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "vistrack/environment.hpp"

namespace py = pybind11;

namespace vistrack::bindings {

void bind_environment(py::module_& m) {
  py::class_<Environment>(m, "Environment",
                          "Obstacles (2.5D buildings or a triangle mesh), ground and road network.")
      .def_static("from_triangles", &Environment::from_triangles, py::arg("vertices"), py::arg("faces"),
                  "Environment from triangles: vertices (n, 3) float in east-north-up metres, faces "
                  "(m, 3) int indexing them.")
      .def_property_readonly("num_triangles", &Environment::num_triangles,
                             "Number of obstacle triangles (the ground plane not counted).")
      .def_property_readonly("max_height", &Environment::max_height,
                             "Tallest obstacle point above the ground level, in metres.")
      .def_property_readonly("ground_level", &Environment::ground_level,
                             "Height of the ground plane in metres.")
      .def_property_readonly(
          "vertices", [](const Environment& e) { return e.mesh().vertices; },
          "Obstacle vertices, numpy array (n, 3).")
      .def_property_readonly(
          "faces", [](const Environment& e) { return e.mesh().faces; },
          "Obstacle triangles, numpy int32 array (m, 3) of vertex indices.");

  py::class_<PoiPath>(m, "PoiPath", "A point of interest moving at constant speed through waypoints.")
      .def(py::init<const Eigen::MatrixXd&, double>(), py::arg("waypoints"), py::arg("speed"),
           "Waypoints (n, 2) or (n, 3) in metres; speed in m/s (> 0).")
      .def_static("from_csv", &PoiPath::from_csv, py::arg("path"), py::arg("speed"),
                  "Read waypoints from a CSV file with lines x,y[,z].")
      .def("position", &PoiPath::position, py::arg("t"), "Position (3,) at time t (clamped to the path).")
      .def("velocity", &PoiPath::velocity, py::arg("t"), "Velocity (2,) of the segment containing t.")
      .def("heading", &PoiPath::heading, py::arg("t"), "Direction of the velocity at t, radians.")
      .def_property_readonly("node_times", &PoiPath::node_times, "Times t_i at each waypoint (s).")
      .def_property_readonly("waypoints", &PoiPath::waypoints, "Waypoints (n, 3) after dropping repeats.")
      .def_property_readonly("speed", &PoiPath::speed, "Speed v_g in m/s.")
      .def_property_readonly("duration", &PoiPath::duration, "Time to travel the whole path (s).")
      .def_property_readonly("length", &PoiPath::length, "Path length in metres.");
}

}  // namespace vistrack::bindings
