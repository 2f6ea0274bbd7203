#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "vistrack/error.hpp"
#include "vistrack/visibility.hpp"

namespace py = pybind11;

namespace vistrack::bindings {

namespace {

using Band = std::optional<std::pair<double, double>>;

py::array_t<double> per_corner(const VisibilityVolume& vv, const std::vector<double>& values) {
  if (values.size() != vv.grid.num_corners())
    detail::fail_field("near/far", values.size(), "need one interval per grid corner (" + std::to_string(vv.grid.num_corners()) + ")");
  py::array_t<double> out({vv.grid.num_elevation + 1, vv.grid.num_azimuth});
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

// str or os.PathLike (pathlib.Path) to a file name.
std::string fspath(const py::object& path) { return py::module_::import("os").attr("fspath")(path).cast<std::string>(); }

int checked_row(const DirectionGrid& grid, int row) {
  if (row < 0 || row >= grid.num_elevation)
    detail::fail_field("row", row, "must be a row index in [0, " + std::to_string(grid.num_elevation) + ")");
  return row;
}

int checked_corner_row(const DirectionGrid& grid, int row) {
  if (row < 0 || row > grid.num_elevation)
    detail::fail_field("row", row, "must be a corner row index in [0, " + std::to_string(grid.num_elevation) + "]");
  return row;
}

int checked_column(const DirectionGrid& grid, int column) {
  if (column < 0 || column >= grid.num_azimuth)
    detail::fail_field("column", column, "must be a column index in [0, " + std::to_string(grid.num_azimuth) + ")");
  return column;
}

Vec3 as_point(const Eigen::VectorXd& g, const char* field) {
  if (g.size() != 3) throw Error(std::string(field) + " must have 3 coordinates (x, y, z), got " + std::to_string(g.size()));
  return g;
}

}  // namespace

void bind_visibility(py::module_& m) {
  py::class_<DirectionGrid>(m, "DirectionGrid",
                            "Angular grid of a VV: num_elevation rows x num_azimuth columns of equal angular "
                            "size over the sphere; a VV samples its intervals at the cells' corners (corner).")
      .def_readonly("num_elevation", &DirectionGrid::num_elevation)
      .def_readonly("num_azimuth", &DirectionGrid::num_azimuth)
      .def("elevation", [](const DirectionGrid& g, int row) { return g.elevation(checked_row(g, row)); },
           py::arg("row"), "Centre elevation of row i (rad).")
      .def("azimuth", [](const DirectionGrid& g, int column) { return g.azimuth(checked_column(g, column)); },
           py::arg("column"), "Centre azimuth of column j (rad, from +x).")
      .def("solid_angle", [](const DirectionGrid& g, int row) { return g.solid_angle(checked_row(g, row)); },
           py::arg("row"), "Solid angle of each cell of row i (sr).")
      .def("corner",
           [](const DirectionGrid& g, int row, int column) {
             return g.corner(checked_corner_row(g, row), checked_column(g, column));
           },
           py::arg("row"), py::arg("column"),
           "Unit vector to corner (i, j), i in [0, num_elevation]: elevation -pi/2 + i*pi/num_elevation,\n"
           "azimuth j*2pi/num_azimuth (rows 0 and num_elevation are the poles). A VV's intervals are\n"
           "sampled on these rays.")
      .def("corner_weight", [](const DirectionGrid& g, int row) { return g.corner_weight(checked_corner_row(g, row)); },
           py::arg("row"), "Trapezoid weight of each corner of row i (sr): half a cell below plus half a cell above.")
      .def_property_readonly("num_corners", &DirectionGrid::num_corners, "Number of corners: (num_elevation + 1) * num_azimuth.")
      .def_property_readonly("size", &DirectionGrid::size, "Number of cells.")
      .def_static("from_resolution", &DirectionGrid::from_resolution, py::arg("resolution_deg"),
                  "Grid with steps of about resolution_deg degrees (an even number of rows).");

  py::class_<VisibilityVolume>(m, "VisibilityVolume",
                               "Visibility volume alpha(g) (eq. 4): per-direction visible intervals on a grid "
                               "and a closed, outward-oriented triangle mesh (left out with with_mesh=False: "
                               "has_mesh).")
      .def_readonly("poi", &VisibilityVolume::poi, "The POI g (3,).")
      .def_readonly("d_max", &VisibilityVolume::d_max, "Maximum viewing distance (m).")
      .def_readonly("altitude_band", &VisibilityVolume::altitude_band, "(h_lo, h_hi) in world z, or None.")
      .def_readonly("grid", &VisibilityVolume::grid, "The direction grid.")
      .def_property_readonly("near", [](const VisibilityVolume& vv) { return per_corner(vv, vv.near); },
                             "Start of the visible interval per grid corner, (num_elevation + 1, num_azimuth) metres.")
      .def_property_readonly("far", [](const VisibilityVolume& vv) { return per_corner(vv, vv.far); },
                             "End of the visible interval per grid corner (near >= far: nothing visible).")
      .def_property_readonly(
          "vertices",
          [](const VisibilityVolume& vv) {
            detail::require_mesh(vv, "vv.vertices");
            return vv.mesh.vertices;
          },
          "Mesh vertices (n, 3); VistrackError for a VV computed with with_mesh=False.")
      .def_property_readonly(
          "faces",
          [](const VisibilityVolume& vv) {
            detail::require_mesh(vv, "vv.faces");
            return vv.mesh.faces;
          },
          "Mesh triangles (m, 3) int32, outward oriented; VistrackError for a VV computed with with_mesh=False.")
      .def_readonly("volume", &VisibilityVolume::volume,
                    "Volume of the mesh (m^3); the same value when computed with with_mesh=False.")
      .def_readonly("has_mesh", &VisibilityVolume::has_mesh,
                    "False for a VV computed with with_mesh=False: its intervals and volume only (no vertices,\n"
                    "faces, slices or files; the XOR on the grid only).")
      .def_readonly("mesh_row_sines", &VisibilityVolume::mesh_row_sines,
                    "Star VVs (POI in the band): sines of the elevations of the mesh's vertex rows (grid row\n"
                    "boundaries plus the creases where d_max meets the ground or a band plane); empty otherwise,\n"
                    "and with with_mesh=False.")
      .def_readonly("mesh_triangle_faces", &VisibilityVolume::mesh_triangle_faces,
                    "Star VVs: faces[mesh_triangle_faces[t]:mesh_triangle_faces[t + 1]] are built over triangle slot\n"
                    "t of the sphere of grid corners (two per quad, row-major); what the radial XOR reads. Empty\n"
                    "otherwise, and with with_mesh=False.")
      .def("grid_volume", &VisibilityVolume::grid_volume,
           "Volume represented by the grid intervals: sum over corners of corner_weight * (far^3 - near^3) / 3.")
      .def("save", &VisibilityVolume::save, py::arg("path"),
           "Write the mesh to .obj or .ply (VistrackError for a VV computed with with_mesh=False).")
      .def(
          "save_binary",
          [](const VisibilityVolume& vv, const py::object& path) { write_volume_file(vv, fspath(path)); },
          py::arg("path"),
          "Write the whole VV (grid intervals, mesh, volume) to a binary VV file, the format of the on-disk "
          "VV cache (vv-<hex>.bin, written by OrbitPlanner(cache_dir=...)); atomic (temporary file renamed). "
          "VistrackError for a VV computed with with_mesh=False.")
      .def_static(
          "load",
          [](const py::object& path) {
            const std::string name = fspath(path);
            std::optional<VisibilityVolume> vv = read_volume_file(name);
            if (!vv) throw Error("VV file '" + name + "': does not exist");
            return std::move(*vv);
          },
          py::arg("path"),
          "The VV stored in a binary VV file (save_binary or the VV cache). VistrackError naming the file when "
          "it is missing, unreadable, truncated, corrupt (checksum) or of another format version.")
      .def("__repr__", [](const VisibilityVolume& vv) {
        Repr repr("VisibilityVolume");
        repr.add("poi", vv.poi).add("volume", vv.volume);
        if (vv.has_mesh) repr.add("faces", vv.mesh.faces.rows());
        else repr.item("has_mesh=False");
        return repr.str();
      });

  py::class_<VisibilityScene>(m, "VisibilityScene",
                              "Embree BVH of an environment (obstacles plus ground plane), built once and shared "
                              "by every visibility query; thread-safe.")
      .def(py::init<const Environment&>(), py::arg("env"), py::call_guard<py::gil_scoped_release>(),
           "Build the BVH (validates the triangles first).")
      .def_property_readonly("ground_level", &VisibilityScene::ground_level, "Ground plane height (m).")
      .def_property_readonly("num_triangles", &VisibilityScene::num_triangles, "Obstacle triangles in the BVH.")
      .def_property_readonly("fingerprint", &VisibilityScene::fingerprint, "Fingerprint of the source environment.")
      .def(
          "first_hits",
          [](const VisibilityScene& s, const Eigen::VectorXd& origin, const Points3& directions, double t_max) {
            const Vec3 o = as_point(origin, "origin");
            std::vector<double> hits;
            {
              py::gil_scoped_release release;
              hits = s.first_hits(o, directions, t_max);
            }
            return py::array_t<double>(static_cast<py::ssize_t>(hits.size()), hits.data());
          },
          py::arg("origin"), py::arg("directions"), py::arg("t_max") = 1e30,
          "Distance (m) to the first obstacle or ground hit along each direction (n, 3); inf when none.")
      .def(
          "line_of_sight",
          [](const VisibilityScene& s, const Points3& a, const Points3& b) {
            std::vector<bool> visible;
            {
              py::gil_scoped_release release;
              visible = s.line_of_sight(a, b);
            }
            return to_numpy(visible);
          },
          py::arg("a"), py::arg("b"), "Bool array: segment a[k]-b[k] is unobstructed (occlusion rays).")
      .def("surface_height", &VisibilityScene::surface_height, py::arg("xy"),
           "Height of the topmost surface (obstacle or ground) under the vertical through xy (2,).")
      .def(
          "poi_on_surface",
          [](const VisibilityScene& s, const Points3& points) {
            py::gil_scoped_release release;
            Points3 lifted(points.rows(), 3);
            for (Eigen::Index i = 0; i < points.rows(); ++i)
              lifted.row(i) = s.poi_on_surface(points.row(i).transpose()).transpose();
            return lifted;
          },
          py::arg("points"),
          "Where ground POIs stand: rows (x, y, h) of a POI path, h the height above the surface, "
          "become (x, y, surface_height(x, y) + h).")
      .def("inside_obstacle", [](const VisibilityScene& s, const Vec3& p) { return s.inside_obstacle(p); },
           py::arg("point"),
           "Whether a point lies inside an obstacle.");

  // Line of sight on the Environment class itself (bind_environment ran before this).
  py::reinterpret_borrow<py::class_<Environment>>(m.attr("Environment"))
      .def(
          "line_of_sight",
          [](const Environment& env, const Points3& a, const Points3& b) {
            std::vector<bool> visible;
            {
              py::gil_scoped_release release;
              visible = line_of_sight(env, a, b);
            }
            return to_numpy(visible);
          },
          py::arg("a"), py::arg("b"),
          "Bool array: segment a[k]-b[k] ((n, 3) each) is unobstructed by obstacles and ground. Builds a "
          "BVH per call: use VisibilityScene(env).line_of_sight for repeated queries.");

  m.def(
      "visibility_volume",
      [](const VisibilityScene& scene, const Eigen::VectorXd& g, double d_max, Band band, double resolution_deg,
         bool with_mesh) {
        const Vec3 p = as_point(g, "g");
        py::gil_scoped_release release;
        return visibility_volume(scene, p, d_max, band, resolution_deg, with_mesh);
      },
      py::arg("scene"), py::arg("g"), py::arg("d_max"), py::arg("altitude_band") = py::none(),
      py::arg("resolution_deg") = kDefaultResolutionDeg, py::arg("with_mesh") = true,
      "Visibility volume of POI g (3,) within d_max, inside the altitude band (h_lo, h_hi) of world z when "
      "given, on a grid of about resolution_deg degrees; with_mesh=False leaves the mesh out (the same "
      "intervals and volume, less work).");
  py::class_<VolumeCost>(m, "VolumeCost", "Where one VV's time and rays went (for benchmarks).")
      .def_readonly("bounds_s", &VolumeCost::bounds_s, "s: per-column bounds of the rays that can hit an obstacle")
      .def_readonly("trace_s", &VolumeCost::trace_s,
                    "s: corner rays (their first hits from the triangles' footprints) and the grid's intervals")
      .def_readonly("refine_s", &VolumeCost::refine_s, "s: locating the jumps of r and refining the mesh there")
      .def_readonly("mesh_s", &VolumeCost::mesh_s, "s: writing the mesh")
      .def_readonly("volume_s", &VolumeCost::volume_s,
                    "s: summing its volume (with_mesh=False: the whole volume pass, in place of mesh_s)")
      .def_readonly("candidates_s", &VolumeCost::candidates_s,
                    "s of refine_s (star VV): live corners, the search for jump candidates, the edge map")
      .def_readonly("first_pass_s", &VolumeCost::first_pass_s,
                    "s of refine_s (star VV): locating the grid edges' jumps")
      .def_readonly("second_pass_s", &VolumeCost::second_pass_s,
                    "s of refine_s (star VV): the split edges' new edges and their jumps")
      .def_readonly("untwist_s", &VolumeCost::untwist_s,
                    "s of refine_s (star VV): confirming the jumps (with the complex slots' pieces, which the mesh "
                    "reuses) and untwisting the walls")
      .def_readonly("count_s", &VolumeCost::count_s,
                    "s of mesh_s (star VV): numbering the vertices, counting the faces per slot")
      .def_readonly("vertices_s", &VolumeCost::vertices_s, "s of mesh_s (star VV): the vertices")
      .def_readonly("fill_s", &VolumeCost::fill_s, "s of mesh_s (star VV): the faces, with the volume")
      .def_readonly("rays_traced", &VolumeCost::rays_traced,
                    "corner rays handed to Embree (the grid's corner rows that are no mesh rows)")
      .def_readonly("rays_skipped", &VolumeCost::rays_skipped,
                    "corner rays decided without Embree (the triangle tests, or the bounds)")
      .def_readonly("corner_tests", &VolumeCost::corner_tests,
                    "(corner direction, obstacle triangle) tests of the corner rays' first hits")
      .def_readonly("refine_rays", &VolumeCost::refine_rays, "rays traced while refining")
      .def_readonly("refine_predicted", &VolumeCost::refine_predicted,
                    "refining rays decided without Embree: a ray just before an occluder's edge lies inside its "
                    "cone and meets it at its plane")
      .def_readonly("predicted_misses", &VolumeCost::predicted_misses,
                    "with check_predicted=True (each predicted ray traced as well, and counted in refine_rays; the VV "
                    "keeps the predictions): how many differ from Embree by more than 0.1 % in visible distance (where "
                    "the ray grazes the occluder's edge closer than Embree's float test resolves)")
      .def_readonly("predicted_error", &VolumeCost::predicted_error,
                    "with check_predicted=True: the largest |predicted / traced - 1| of those rays' visible distance")
      .def_readonly("embree_s", &VolumeCost::embree_s,
                    "s in Embree's rtcIntersect1M calls with their ray packing, per thread and summed over "
                    "threads: within trace_s + refine_s when parallel=False");
  m.def(
      "visibility_volume_cost",
      [](const VisibilityScene& scene, const Eigen::VectorXd& g, double d_max, Band band, double resolution_deg,
         bool parallel, bool check_predicted, bool with_mesh) {
        const Vec3 p = as_point(g, "g");
        VolumeCost cost;
        VisibilityVolume vv;
        {
          py::gil_scoped_release release;
          vv = visibility_volume_with_cost(scene, p, d_max, band, resolution_deg, cost, parallel, check_predicted,
                                           with_mesh);
        }
        return std::make_pair(std::move(vv), cost);
      },
      py::arg("scene"), py::arg("g"), py::arg("d_max"), py::arg("altitude_band") = py::none(),
      py::arg("resolution_deg") = kDefaultResolutionDeg, py::arg("parallel") = true, py::arg("check_predicted") = false,
      py::arg("with_mesh") = true,
      "visibility_volume and where its time and rays went: (vv, VolumeCost); parallel=False keeps it on the "
      "calling thread (as in a batch); check_predicted=True also traces the refining rays it predicts "
      "(VolumeCost.predicted_misses, predicted_error); with_mesh as in visibility_volume.");
  m.def(
      "visibility_volumes",
      [](const VisibilityScene& scene, const Points3& pois, double d_max, Band band, double resolution_deg,
         bool with_mesh) {
        py::gil_scoped_release release;
        return visibility_volumes(scene, pois, d_max, band, resolution_deg, with_mesh);
      },
      py::arg("scene"), py::arg("pois"), py::arg("d_max"), py::arg("altitude_band") = py::none(),
      py::arg("resolution_deg") = kDefaultResolutionDeg, py::arg("with_mesh") = true,
      "VVs for every row of pois (n, 3), in parallel over the points; with_mesh as in visibility_volume.");
  m.def("mesh_volume",
        [](const Points3& v, const Faces& f) {
          validate_triangle_mesh(v, f);
          return mesh_volume(TriangleMesh{v, f});
        },
        py::arg("vertices"), py::arg("faces"), "Volume of a closed, consistently oriented triangle mesh.");
}

}  // namespace vistrack::bindings
