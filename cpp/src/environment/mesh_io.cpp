// Environment::from_mesh: any polygon mesh file CGAL reads (OBJ, PLY, STL, OFF).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>

#include <filesystem>
#include <fstream>

#include "environment/detail.hpp"
#include "vistrack/error.hpp"

namespace vistrack {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
namespace PMP = CGAL::Polygon_mesh_processing;
}  // namespace

Environment Environment::from_mesh(const std::string& path, const std::string& up) {
  if (up != "z" && up != "y") detail::fail_field("up", "\"" + up + "\"", "must be \"z\" or \"y\"");
  {
    std::ifstream probe(path, std::ios::binary);
    if (!probe) detail::fail_field("path", path, "cannot open the mesh file for reading");
    if (probe.peek() == std::ifstream::traits_type::eof()) detail::fail_field("path", path, "the mesh file is empty");
  }
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  bool read = false;
  try {
    read = CGAL::IO::read_polygon_soup(path, points, polygons);
  } catch (const std::exception& error) {
    detail::fail_field("path", path, std::string("cannot parse the mesh file: ") + error.what());
  }
  if (!read)
    detail::fail_field("path", path,
                       "cannot read a mesh from this file (formats: .obj .ply .stl .off, chosen by extension)");
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(points[i][k]))
        detail::fail_field("vertices[" + std::to_string(i) + "]", points[i][k], "vertex coordinates must be finite");
  // Merge exactly repeated points, drop polygons with repeated or too few corners, duplicate
  // polygons and unused points, so that neighbouring faces share their vertices.
  PMP::repair_polygon_soup(points, polygons);
  if (polygons.empty()) detail::fail_field("path", path, "the mesh file has no faces");

  std::vector<std::array<int, 3>> triangles;
  std::vector<Vec3> corners;
  for (const auto& polygon : polygons) {
    corners.clear();
    for (std::size_t index : polygon) corners.emplace_back(points[index].x(), points[index].y(), points[index].z());
    for (const auto& t : detail::triangulate_face(corners)) {
      const Point& a = points[polygon[static_cast<std::size_t>(t[0])]];
      const Point& b = points[polygon[static_cast<std::size_t>(t[1])]];
      const Point& c = points[polygon[static_cast<std::size_t>(t[2])]];
      if (CGAL::collinear(a, b, c)) continue;  // degenerate: no area, no hit
      triangles.push_back({static_cast<int>(polygon[static_cast<std::size_t>(t[0])]),
                           static_cast<int>(polygon[static_cast<std::size_t>(t[1])]),
                           static_cast<int>(polygon[static_cast<std::size_t>(t[2])])});
    }
  }
  if (triangles.empty()) detail::fail_field("path", path, "the mesh file has only degenerate faces");

  Points3 vertices(static_cast<Eigen::Index>(points.size()), 3);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    if (up == "y") vertices.row(row) << points[i].x(), -points[i].z(), points[i].y();  // (east, north, up)
    else vertices.row(row) << points[i].x(), points[i].y(), points[i].z();
  }
  Faces faces(static_cast<Eigen::Index>(triangles.size()), 3);
  for (std::size_t i = 0; i < triangles.size(); ++i)
    faces.row(static_cast<Eigen::Index>(i)) << triangles[i][0], triangles[i][1], triangles[i][2];
  // A vertex used only by dropped triangles stays; it does not change the bounds of a mesh
  // whose faces span the same space (repair_polygon_soup removed isolated points).
  return from_triangles(std::move(vertices), std::move(faces));
}

}  // namespace vistrack
