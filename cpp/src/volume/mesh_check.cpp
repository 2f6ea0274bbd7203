// Closed-mesh validation with CGAL: the properties a VV mesh must have before Booleans and slicing.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <vector>

#include "volume/cgal_mesh.hpp"
#include "volume/points_inside.hpp"
#include "vistrack/error.hpp"
#include "vistrack/volume.hpp"

namespace vistrack {

namespace PMP = CGAL::Polygon_mesh_processing;

namespace detail {

bool to_surface_mesh(const TriangleMesh& mesh, CgalMesh& out) {
  std::vector<CgalKernel::Point_3> points;
  points.reserve(static_cast<std::size_t>(mesh.vertices.rows()));
  for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i)
    points.emplace_back(mesh.vertices(i, 0), mesh.vertices(i, 1), mesh.vertices(i, 2));
  std::vector<std::array<std::size_t, 3>> polygons;
  polygons.reserve(static_cast<std::size_t>(mesh.faces.rows()));
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
    polygons.push_back({static_cast<std::size_t>(mesh.faces(f, 0)), static_cast<std::size_t>(mesh.faces(f, 1)),
                        static_cast<std::size_t>(mesh.faces(f, 2))});
  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) return false;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, out);
  return true;
}

}  // namespace detail

MeshCheck check_closed_mesh(const TriangleMesh& mesh) {
  MeshCheck check;
  const Eigen::Index nv = mesh.vertices.rows();
  if (mesh.faces.rows() == 0) {
    check.problem = "empty mesh";
    return check;
  }
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f) {
    const auto a = mesh.faces(f, 0), b = mesh.faces(f, 1), c = mesh.faces(f, 2);
    if (a < 0 || b < 0 || c < 0 || a >= nv || b >= nv || c >= nv || a == b || b == c || a == c) {
      check.problem = "face " + std::to_string(f) + " has an invalid or repeated vertex index";
      return check;
    }
  }
  check.triangles_valid = true;
  detail::CgalMesh sm;
  if (!detail::to_surface_mesh(mesh, sm)) {
    check.problem = "the faces are not an oriented 2-manifold (non-manifold edge or vertex, or inconsistent orientation)";
    return check;
  }
  check.polygon_mesh = true;
  check.closed = CGAL::is_closed(sm);
  if (!check.closed) {
    check.problem = "not closed (border edges)";
    return check;
  }
  check.volume = PMP::volume(sm);
  check.self_intersecting = PMP::does_self_intersect(sm);
  if (check.self_intersecting) {
    check.problem = "self-intersecting";
    return check;
  }
  check.bounds_volume = PMP::does_bound_a_volume(sm);
  if (!check.bounds_volume) {
    check.problem = "does not bound a volume (inconsistently nested components)";
    return check;
  }
  check.outward = PMP::is_outward_oriented(sm);
  if (!check.outward || !(check.volume > 0.0)) {
    check.problem = "not outward oriented";
    return check;
  }
  return check;
}

std::vector<bool> detail::points_inside(const TriangleMesh& mesh, const Points3& points) {
  detail::CgalMesh sm;
  if (mesh.faces.rows() == 0 || !detail::to_surface_mesh(mesh, sm) || !CGAL::is_closed(sm))
    throw Error("points_inside: the mesh is not a closed 2-manifold; check it with check_closed_mesh");
  const CGAL::Side_of_triangle_mesh<detail::CgalMesh, detail::CgalKernel> side(sm);
  std::vector<bool> inside(static_cast<std::size_t>(points.rows()));
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    inside[static_cast<std::size_t>(i)] =
        side(detail::CgalKernel::Point_3(points(i, 0), points(i, 1), points(i, 2))) != CGAL::ON_UNBOUNDED_SIDE;
  return inside;
}

}  // namespace vistrack
