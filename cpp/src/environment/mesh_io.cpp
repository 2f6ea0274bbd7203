// Environment::from_mesh: any polygon mesh file CGAL reads (OBJ, PLY, STL, OFF).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "environment/detail.hpp"
#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"

namespace vistrack {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
namespace PMP = CGAL::Polygon_mesh_processing;

std::string lower_extension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

// Why CGAL refused a Wavefront OBJ file, when a line says so: "path:line: reason" naming the first
// vertex that is not three finite numbers or the first face corner that names no vertex (OBJ
// counts from 1; negative indices count back from the last vertex read). Empty when no line is
// to blame (the caller then gives the general message).
std::string diagnose_obj(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  long long vertices = 0;
  for (long long number = 1; std::getline(in, line); ++number) {
    std::istringstream fields(line);
    std::string tag;
    fields >> tag;
    const std::string where = path + ":" + std::to_string(number);
    if (tag == "v") {
      double xyz[3];
      std::string token;
      for (double& c : xyz) {
        if (!(fields >> token)) return where + ": a vertex needs three coordinates x y z";
        try {
          std::size_t used = 0;
          c = std::stod(token, &used);
          if (used != token.size()) throw std::invalid_argument(token);
        } catch (const std::exception&) {
          return where + ": vertex coordinate " + detail::printable(token) + " is not a number";
        }
        if (!std::isfinite(c)) return where + ": vertex coordinate " + detail::printable(token) + " is not finite";
      }
      ++vertices;
    } else if (tag == "f") {
      std::string corner;
      while (fields >> corner) {
        const std::string index_text = corner.substr(0, corner.find('/'));
        long long index = 0;
        try {
          std::size_t used = 0;
          index = std::stoll(index_text, &used);
          if (used != index_text.size()) throw std::invalid_argument(index_text);
        } catch (const std::exception&) {
          return where + ": face corner " + detail::printable(corner) + " is not a vertex index";
        }
        if (index == 0 || index > vertices || index < -vertices)
          return where + ": face corner " + detail::printable(corner) + " names no vertex (" + std::to_string(vertices) +
                 " read so far; OBJ counts from 1)";
      }
    }
  }
  return {};
}
}  // namespace

Environment Environment::from_mesh(const std::string& path, const std::string& up) {
  if (up != "z" && up != "y") detail::fail_field("up", "\"" + up + "\"", "must be \"z\" or \"y\"");
  require_regular_file(path, "path", "mesh");
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
  if (!read) {
    const std::string why = lower_extension(path) == ".obj" ? diagnose_obj(path) : std::string();
    if (!why.empty()) detail::fail_field("path", path, "cannot read the mesh: " + why);
    detail::fail_field("path", path,
                       "cannot read a mesh from this file (formats: .obj .ply .stl .off, chosen by extension; "
                       "CGAL's reader refused it: a vertex that is not a finite number, a face naming no vertex "
                       "or a malformed header)");
  }
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 3; ++k)
      require_coordinate(points[i][k], "vertices[" + std::to_string(i) + "][" + std::to_string(k) + "]");
  for (std::size_t f = 0; f < polygons.size(); ++f)
    for (std::size_t index : polygons[f])
      if (index >= points.size())
        detail::fail_field("faces[" + std::to_string(f) + "]", index,
                           "vertex index out of range [0, " + std::to_string(points.size()) + ")");
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
