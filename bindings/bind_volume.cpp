// Closed-mesh checks, VP slicing (CGAL and edge-walking).
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "vistrack/error.hpp"
#include "vistrack/volume.hpp"

namespace py = pybind11;

namespace vistrack::bindings {

void bind_volume(py::module_& m) {
  py::class_<MeshCheck>(m, "MeshCheck", "CGAL's verdict on a mesh that should bound a solid.")
      .def_readonly("triangles_valid", &MeshCheck::triangles_valid)
      .def_readonly("polygon_mesh", &MeshCheck::polygon_mesh, "Faces form an oriented 2-manifold.")
      .def_readonly("closed", &MeshCheck::closed)
      .def_readonly("self_intersecting", &MeshCheck::self_intersecting)
      .def_readonly("bounds_volume", &MeshCheck::bounds_volume)
      .def_readonly("outward", &MeshCheck::outward)
      .def_readonly("volume", &MeshCheck::volume, "CGAL's volume (m^3).")
      .def_readonly("problem", &MeshCheck::problem, "First failed property, '' when valid.")
      .def_property_readonly("valid", &MeshCheck::valid)
      .def("__repr__", [](const MeshCheck& c) {
        return c.valid() ? Repr("MeshCheck").item("valid").str() : Repr("MeshCheck").add("problem", c.problem).str();
      });

  m.def(
      "check_closed_mesh",
      [](const Points3& vertices, const Faces& faces) {
        validate_triangle_mesh(vertices, faces);
        return check_closed_mesh(TriangleMesh{vertices, faces});
      },
      py::arg("vertices"), py::arg("faces"), py::call_guard<py::gil_scoped_release>(),
      "Check with CGAL that a triangle mesh is closed, 2-manifold, free of self-intersections, bounds a "
      "volume and is outward oriented.");
  m.def(
      "slice_mesh",
      [](const Points3& vertices, const Faces& faces, double altitude) {
        validate_triangle_mesh(vertices, faces);
        require_finite(altitude, "altitude");
        return nest_rings(slice_rings(TriangleMesh{vertices, faces}, altitude));
      },
      py::arg("vertices"), py::arg("faces"), py::arg("altitude"), py::call_guard<py::gil_scoped_release>(),
      "Polygons (with holes) where the plane z = altitude cuts a closed mesh (CGAL Polygon_mesh_slicer).");

  m.def("plane_visibility_polygon", &plane_visibility_polygon, py::arg("vv"), py::arg("altitude"),
        py::call_guard<py::gil_scoped_release>(),
        "VP of a VV at world altitude z by walking the mesh edges that cross the plane (what the orbit "
        "planner uses); the same polygons as vv.slice(z), which uses CGAL's slicer.");

  auto vv = py::reinterpret_borrow<py::class_<VisibilityVolume>>(m.attr("VisibilityVolume"));
  vv.def("slice", &visibility_polygon, py::arg("altitude"), py::arg("all_parts") = false,
         py::call_guard<py::gil_scoped_release>(),
         "Visibility polygon at world altitude z: list of Polygon. By default only the part(s) containing "
         "the POI's vertical; all_parts=True keeps every part. VistrackError for a VV computed with "
         "with_mesh=False.");
  vv.def(
      "check",
      [](const VisibilityVolume& v) {
        detail::require_mesh(v, "vv");
        return check_closed_mesh(v.mesh);
      },
      py::call_guard<py::gil_scoped_release>(),
      "check_closed_mesh on this VV's mesh (VistrackError for a VV computed with with_mesh=False).");
}

}  // namespace vistrack::bindings
