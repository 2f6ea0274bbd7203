#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "vistrack/error.hpp"
#include "vistrack/geometry.hpp"
#include "vistrack/limits.hpp"

namespace py = pybind11;

namespace vistrack::bindings {

Ring ring_from_array(const Points2& points, const std::string& field) {
  Ring ring;
  ring.reserve(static_cast<std::size_t>(points.rows()));
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const Vec2 p = points.row(i).transpose();
    require_coordinate(p.x(), field + "[" + std::to_string(i) + "][0]");
    require_coordinate(p.y(), field + "[" + std::to_string(i) + "][1]");
    ring.push_back(p);
  }
  // A closing repeat of the first point is common in files; the ring stores it once.
  if (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
  return ring;
}

namespace {
const Vec2& checked_point(const Vec2& point) {
  require_coordinate(point.x(), "point[0]");
  require_coordinate(point.y(), "point[1]");
  return point;
}
}  // namespace

void bind_geometry(py::module_& m) {
  py::class_<Polygon>(m, "Polygon", "A simple polygon with optional holes, in metres.")
      .def(py::init([](const Points2& outer, const std::vector<Points2>& holes) {
             Polygon polygon{ring_from_array(outer, "outer"), {}};
             for (std::size_t h = 0; h < holes.size(); ++h)
               polygon.holes.push_back(ring_from_array(holes[h], "holes[" + std::to_string(h) + "]"));
             return polygon;
           }),
           py::arg("outer"), py::arg("holes") = std::vector<Points2>{},
           "outer: (n, 2) array; holes: list of (m, 2) arrays. A closing repeat is dropped.")
      .def_property_readonly("outer", [](const Polygon& p) { return to_array(p.outer); },
                             "Outer ring (n, 2), without a closing repeat.")
      .def_property_readonly(
          "holes",
          [](const Polygon& p) {
            std::vector<Points2> holes;
            for (const Ring& hole : p.holes) holes.push_back(to_array(hole));
            return holes;
          },
          "Holes, each (m, 2).")
      .def_property_readonly("area", [](const Polygon& p) { return area(p); }, "Area minus holes, m^2.")
      .def("contains", [](const Polygon& p, const Vec2& point) { return contains(p, checked_point(point)); },
           py::arg("point"), "Even-odd containment; boundary points count as inside.")
      .def("distance_to_boundary",
           [](const Polygon& p, const Vec2& point) { return distance_to_boundary(p, checked_point(point)); },
           py::arg("point"), "Distance from a point to the nearest edge of any ring.")
      .def("__repr__", [](const Polygon& p) {
        return Repr("Polygon").add("vertices", p.outer.size()).add("holes", p.holes.size()).str();
      });

  m.def("wrap_to_pi", &wrap_to_pi, py::arg("angle"), "Angle wrapped to (-pi, pi]; VistrackError when not finite.");

  py::module_ ranges = m.def_submodule(
      "limits",
      "The valid range of every numeric input (vistrack/limits.hpp; README, Hardening): coordinates "
      "|v| <= MAX_COORDINATE m, lengths in [MIN_LENGTH, MAX_LENGTH] m, speeds in [MIN_SPEED, MAX_SPEED] m/s, "
      "angles |a| <= MAX_ANGLE rad, origin altitudes |alt| <= MAX_ALTITUDE m, volumes in (0, MAX_VOLUME] m^3, "
      "threads in [0, MAX_THREADS], the guidance gains "
      "beta in [MIN_GAIN, MAX_BETA] 1/m and k_psi in [MIN_GAIN, MAX_HEADING_GAIN] 1/s, and ODE tolerances rtol in "
      "[MIN_RTOL, MAX_RTOL] and atol in [MIN_ATOL, MAX_ATOL]; input files of at most MAX_INPUT_BYTES bytes; "
      "documents (JSON, YAML) nested at most MAX_DOCUMENT_DEPTH levels, YAML ones of at most MAX_DOCUMENT_NODES values "
      "(YAML aliases expanded); one planned piece of work (VVs, a loiter coverage matrix) of at most MAX_WORK_BYTES "
      "bytes, estimated before it starts.");
  ranges.attr("MAX_COORDINATE") = limits::kMaxCoordinate;
  ranges.attr("MIN_LENGTH") = limits::kMinLength;
  ranges.attr("MAX_LENGTH") = limits::kMaxLength;
  ranges.attr("MIN_SPEED") = limits::kMinSpeed;
  ranges.attr("MAX_SPEED") = limits::kMaxSpeed;
  ranges.attr("MAX_ANGLE") = limits::kMaxAngle;
  ranges.attr("MAX_ALTITUDE") = limits::kMaxAltitude;
  ranges.attr("MAX_VOLUME") = limits::kMaxVolume;
  ranges.attr("MAX_THREADS") = limits::kMaxThreads;
  ranges.attr("MIN_GAIN") = limits::kMinGain;
  ranges.attr("MAX_BETA") = limits::kMaxBeta;
  ranges.attr("MAX_HEADING_GAIN") = limits::kMaxHeadingGain;
  ranges.attr("MIN_RTOL") = limits::kMinRelativeTolerance;
  ranges.attr("MAX_RTOL") = limits::kMaxRelativeTolerance;
  ranges.attr("MIN_ATOL") = limits::kMinAbsoluteTolerance;
  ranges.attr("MAX_ATOL") = limits::kMaxAbsoluteTolerance;
  ranges.attr("MAX_INPUT_BYTES") = limits::kMaxInputFileBytes;
  ranges.attr("MAX_DOCUMENT_DEPTH") = limits::kMaxDocumentDepth;
  ranges.attr("MAX_DOCUMENT_NODES") = limits::kMaxDocumentNodes;
  ranges.attr("MAX_WORK_BYTES") = limits::kMaxWorkBytes;
}

}  // namespace vistrack::bindings
