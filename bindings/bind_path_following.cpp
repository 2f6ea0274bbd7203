// vistrack._core.flight.PathFollower: a guidance that follows a path of lines and arcs
// (flight.hpp, Path following). Registered into the flight submodule after bind_flight.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <vector>

#include "bindings.hpp"
#include "vistrack/error.hpp"
#include "vistrack/flight.hpp"

namespace py = pybind11;

namespace vistrack::bindings {

namespace {

using Rows5 = Eigen::Matrix<double, Eigen::Dynamic, 5, Eigen::RowMajor>;

std::vector<PathPiece> pieces_from_rows(const Rows5& rows) {
  std::vector<PathPiece> pieces;
  for (Eigen::Index k = 0; k < rows.rows(); ++k)
    pieces.push_back({Vec2(rows(k, 0), rows(k, 1)), rows(k, 2), rows(k, 3), rows(k, 4)});
  return pieces;
}

}  // namespace

void bind_path_following(py::module_& parent) {
  py::module_ m = parent.attr("flight").cast<py::module_>();
  const PathFollowingGains defaults;
  py::class_<PathFollower::Tracking>(m, "PathTracking", "Where a state is relative to the path.")
      .def_readonly("s", &PathFollower::Tracking::s, "progress along the path, m")
      .def_readonly("piece", &PathFollower::Tracking::piece, "index of the piece")
      .def_readonly("cross_track", &PathFollower::Tracking::cross_track, "m, positive to the left of the path")
      .def_readonly("heading_error", &PathFollower::Tracking::heading_error, "psi - psi_path, wrapped, rad")
      .def_readonly("along", &PathFollower::Tracking::along,
                    "signed distance ahead of the path point (non-zero only at the ends), m");
  py::class_<PathFollower, FlightGuidance>(
      m, "PathFollower",
      "Follows a path of lines and arcs: cross-track and heading feedback with curvature feed-forward, "
      "psi_d = psi_path - atan(e / (lookahead_radii R)), rate = v kappa cos(psi - psi_path) / (1 - kappa e) + "
      "heading_gain (v / R) wrap(psi_d - psi). Knows the heading, not the wind. Done at the path's end.")
      .def(py::init([](const Rows5& pieces, double speed, double turn_radius, double lookahead_radii,
                       double heading_gain, double anticipation) {
             PathFollowingGains gains{lookahead_radii, heading_gain, anticipation};
             return PathFollower(pieces_from_rows(pieces), speed, turn_radius, gains);
           }),
           py::arg("pieces"), py::arg("speed"), py::arg("turn_radius"),
           py::arg("lookahead_radii") = defaults.lookahead_radii, py::arg("heading_gain") = defaults.heading_gain,
           py::arg("anticipation") = defaults.anticipation,
           "pieces: (n, 5) rows x0, y0, heading, length, curvature (0 lines, +1/radius ccw, -1/radius cw), each "
           "starting where the one before ends; speed v and turn_radius R of the vehicle; anticipation (s): the "
           "curvature feed-forward reads the path v * anticipation ahead (a banking vehicle's roll lag; 0: none).")
      .def("track",
           [](const PathFollower& f, const Pose& state) { return f.track(configuration(state)); },
           py::arg("state"), "Projection of (x, y, psi) near the current progress (PathTracking).")
      .def_property_readonly("progress", &PathFollower::progress, "Arc length reached, m.")
      .def_property_readonly("length", &PathFollower::length, "Path length, m.");
}

}  // namespace vistrack::bindings
