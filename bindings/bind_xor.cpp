// The XOR volume metric (eq. 56) between visibility volumes or closed meshes.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <optional>

#include "bindings.hpp"
#include "vistrack/volume.hpp"

namespace py = pybind11;

namespace vistrack::bindings {

void bind_xor(py::module_& m) {
  m.def(
      "xor_volume",
      [](const VisibilityVolume& a, const VisibilityVolume& b, const std::string& frame, const std::string& method,
         double time_limit, std::optional<double> perturbation) {
        const XorFrame f = from_name<XorFrame>(frame);
        const XorMethod how = from_name<XorMethod>(method);
        MeshXorOptions options;
        options.time_limit = time_limit;
        options.perturbation = perturbation;
        py::gil_scoped_release release;
        return xor_volume(a, b, f, how, options);
      },
      py::arg("a"), py::arg("b"), py::arg("frame") = "poi", py::arg("method") = "auto",
      py::arg("time_limit") = MeshXorOptions{}.time_limit,
      py::arg("perturbation") = py::none(),
      "Volume (m^3) of the symmetric difference of two VVs, the metric d of eq. (56).\n\n"
      "frame: \"poi\" translates each VV by minus its POI first (open terrain gives 0), \"world\" compares\n"
      "them in place. method: \"radial\" is the exact XOR of the two meshes computed per direction\n"
      "(star VVs on one direction grid: what \"mesh\" gives, without CGAL); \"grid\" is\n"
      "the per-direction integral sum(corner_weight * |A xor B| measured in r^2 dr) over the grid corners'\n"
      "intervals of a shared direction grid (trapezoid rule); both need frame \"poi\" or equal POIs. \"mesh\" is CGAL corefinement\n"
      "of the closed meshes; \"auto\" takes radial, else grid, else mesh, as they apply.\n"
      "time_limit (s) aborts the mesh path with VistrackError. perturbation (rad): rotation of b's mesh\n"
      "about the axis (1,2,3) before the Boolean; default 1e-6 in the POI frame (identical sphere faces\n"
      "make CGAL pathologically slow), 0 in the world frame.");
  m.def(
      "mesh_xor_volume",
      [](const Points3& va, const Faces& fa, const Points3& vb, const Faces& fb, double time_limit,
         std::optional<double> perturbation, bool check_self_intersection) {
        MeshXorOptions options;
        options.time_limit = time_limit;
        options.perturbation = perturbation;
        options.check_self_intersection = check_self_intersection;
        if (fa.rows() > 0) validate_triangle_mesh(va, fa, "a");  // no faces: the empty set
        if (fb.rows() > 0) validate_triangle_mesh(vb, fb, "b");
        const TriangleMesh a{va, fa}, b{vb, fb};
        py::gil_scoped_release release;
        return mesh_xor_volume(a, b, options);
      },
      py::arg("vertices_a"), py::arg("faces_a"), py::arg("vertices_b"), py::arg("faces_b"),
      py::arg("time_limit") = MeshXorOptions{}.time_limit, py::arg("perturbation") = py::none(),
      py::arg("check_self_intersection") = MeshXorOptions{}.check_self_intersection,
      "vol(A) + vol(B) - 2 vol(A n B) of two closed triangle meshes ((n, 3) float vertices, (m, 3) int\n"
      "faces) by CGAL corefinement with exact predicates on copies; perturbation (rad, None: 0) rotates b\n"
      "as in xor_volume. VistrackError when a mesh is not\n"
      "closed, self-intersects, does not bound a volume, or time_limit (s) is exceeded.");
  m.def(
      "grid_xor_volume",
      [](const VisibilityVolume& a, const VisibilityVolume& b) {
        py::gil_scoped_release release;
        return grid_xor_volume(a, b);
      },
      py::arg("a"), py::arg("b"),
      "The XOR volume of two VVs on one direction grid, each about its own POI: per grid corner, trapezoid rule.");
  m.def("shares_direction_grid", &shares_direction_grid, py::arg("a"), py::arg("b"),
        "True when both VVs carry intervals on the same direction grid (the grid path applies).");
  m.def(
      "radial_xor_volume",
      [](const VisibilityVolume& a, const VisibilityVolume& b) {
        py::gil_scoped_release release;
        return radial_xor_volume(a, b);
      },
      py::arg("a"), py::arg("b"),
      "The XOR volume of two star VVs' meshes, each about its own POI, exact per direction (faces\n"
      "overlapped, |r_a^3 - r_b^3| / 3 integrated in closed form between planes). VistrackError unless\n"
      "shares_radial_mesh(a, b).");
  m.def("shares_radial_mesh", &shares_radial_mesh, py::arg("a"), py::arg("b"),
        "True when both VVs are star VVs (POI in the band) on the same direction grid, with the record of\n"
        "how their meshes cover the sphere of grid corners (the radial path applies; rows may differ).");
}

}  // namespace vistrack::bindings
