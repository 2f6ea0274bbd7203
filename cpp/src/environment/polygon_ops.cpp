// The CGAL side of the 2D footprint work: exact simplicity diagnosis, exact Boolean overlap
// areas, and constrained Delaunay triangulation of polygons with holes and of mesh faces.
#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <Eigen/Geometry>
#include <iterator>
#include <list>

#include "environment/detail.hpp"
#include "vistrack/error.hpp"

namespace vistrack::detail {

namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;

// Constrained Delaunay triangulation whose vertices carry the input index and whose faces
// carry their nesting depth (odd = inside the polygon), as in CGAL's polygon_triangulation
// example.
struct FaceInfo {
  int nesting_level = -1;
  bool in_domain() const { return nesting_level % 2 == 1; }
};
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, Epick>;
using Fbb = CGAL::Triangulation_face_base_with_info_2<FaceInfo, Epick>;
using Fb = CGAL::Constrained_triangulation_face_base_2<Epick, Fbb>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Epick, Tds, CGAL::Exact_predicates_tag>;

void mark_domain(Cdt& cdt, Cdt::Face_handle start, int level, std::list<Cdt::Edge>& border) {
  if (start->info().nesting_level != -1) return;
  std::list<Cdt::Face_handle> queue{start};
  while (!queue.empty()) {
    Cdt::Face_handle face = queue.front();
    queue.pop_front();
    if (face->info().nesting_level != -1) continue;
    face->info().nesting_level = level;
    for (int i = 0; i < 3; ++i) {
      Cdt::Face_handle next = face->neighbor(i);
      if (next->info().nesting_level != -1) continue;
      if (cdt.is_constrained(Cdt::Edge(face, i))) border.emplace_back(face, i);
      else queue.push_back(next);
    }
  }
}

// Faces reachable from the infinite face without crossing a constraint get level 0; each
// constraint crossed adds one.
void mark_domains(Cdt& cdt) {
  for (Cdt::Face_handle face : cdt.all_face_handles()) face->info().nesting_level = -1;
  std::list<Cdt::Edge> border;
  mark_domain(cdt, cdt.infinite_face(), 0, border);
  while (!border.empty()) {
    const Cdt::Edge edge = border.front();
    border.pop_front();
    Cdt::Face_handle next = edge.first->neighbor(edge.second);
    if (next->info().nesting_level == -1)
      mark_domain(cdt, next, edge.first->info().nesting_level + 1, border);
  }
}

void insert_ring(Cdt& cdt, const std::vector<Epick::Point_2>& points, int first_index) {
  std::vector<Cdt::Vertex_handle> handles;
  handles.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    Cdt::Vertex_handle handle = cdt.insert(points[i]);
    handle->info() = first_index + static_cast<int>(i);
    handles.push_back(handle);
  }
  for (std::size_t i = 0; i < handles.size(); ++i)
    if (handles[i] != handles[(i + 1) % handles.size()])
      cdt.insert_constraint(handles[i], handles[(i + 1) % handles.size()]);
}

// Triangles inside the constraints; false when the triangulation had to add points (the rings
// cross each other), which validated input never does.
bool domain_triangles(Cdt& cdt, std::vector<std::array<int, 3>>& triangles) {
  mark_domains(cdt);
  for (Cdt::Face_handle face : cdt.finite_face_handles()) {
    if (!face->info().in_domain()) continue;
    std::array<int, 3> triangle{};
    for (int k = 0; k < 3; ++k) {
      triangle[static_cast<std::size_t>(k)] = face->vertex(k)->info();
      if (triangle[static_cast<std::size_t>(k)] < 0) return false;
    }
    triangles.push_back(triangle);
  }
  return true;
}

CGAL::Polygon_2<Epeck> exact_ring(const Ring& ring) {
  CGAL::Polygon_2<Epeck> polygon;
  for (const Vec2& p : ring) polygon.push_back(Epeck::Point_2(p.x(), p.y()));
  return polygon;
}

CGAL::Polygon_with_holes_2<Epeck> exact_polygon(const Polygon& polygon) {
  CGAL::Polygon_with_holes_2<Epeck> result(exact_ring(polygon.outer));
  for (const Ring& hole : polygon.holes) result.add_hole(exact_ring(hole));
  return result;
}

}  // namespace

std::optional<std::pair<std::size_t, std::size_t>> find_self_intersection(const Ring& ring) {
  const std::size_t n = ring.size();
  if (is_simple(ring)) return std::nullopt;  // CGAL's sweep, exact predicates
  // Not simple: find the culprit for the message (quadratic, only on bad input).
  std::vector<Epick::Point_2> p;
  for (const Vec2& v : ring) p.emplace_back(v.x(), v.y());
  for (std::size_t i = 0; i < n; ++i)
    if (p[i] == p[(i + 1) % n]) return std::make_pair(i, i);
  for (std::size_t i = 0; i < n; ++i) {
    const Epick::Segment_2 a(p[i], p[(i + 1) % n]);
    for (std::size_t j = i + 1; j < n; ++j) {
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      if (adjacent) {
        // Adjacent edges share one corner; they are degenerate when they fold back onto
        // each other (a spike) or when the whole ring is one line.
        const std::size_t corner = j == i + 1 ? j : i;
        const Epick::Point_2& before = p[(corner + n - 1) % n];
        const Epick::Point_2& after = p[(corner + 1) % n];
        if (CGAL::collinear(before, p[corner], after) &&
            CGAL::angle(before, p[corner], after) == CGAL::ACUTE)
          return std::make_pair(i, j);
        continue;
      }
      if (CGAL::do_intersect(a, Epick::Segment_2(p[j], p[(j + 1) % n]))) return std::make_pair(i, j);
    }
  }
  return std::make_pair(std::size_t{0}, static_cast<std::size_t>(n > 1 ? 1 : 0));  // collinear ring
}

double intersection_area(const Polygon& a, const Polygon& b) {
  std::vector<CGAL::Polygon_with_holes_2<Epeck>> pieces;
  CGAL::intersection(exact_polygon(a), exact_polygon(b), std::back_inserter(pieces));
  Epeck::FT total = 0;
  for (const auto& piece : pieces) {
    total += piece.outer_boundary().area();
    for (auto hole = piece.holes_begin(); hole != piece.holes_end(); ++hole) total += hole->area();  // CW: negative
  }
  return CGAL::to_double(total);
}

std::vector<std::array<int, 3>> triangulate_polygon(const Polygon& polygon) {
  Cdt cdt;
  int next_index = 0;
  auto add = [&](const Ring& ring) {
    std::vector<Epick::Point_2> points;
    for (const Vec2& p : ring) points.emplace_back(p.x(), p.y());
    insert_ring(cdt, points, next_index);
    next_index += static_cast<int>(ring.size());
  };
  add(polygon.outer);
  for (const Ring& hole : polygon.holes) add(hole);
  std::vector<std::array<int, 3>> triangles;
  if (!domain_triangles(cdt, triangles))
    throw Error("footprint triangulation: rings cross each other (the polygon was not validated)");
  return triangles;
}

std::vector<std::array<int, 3>> triangulate_face(const std::vector<Vec3>& corners) {
  const std::size_t n = corners.size();
  if (n < 3) return {};
  // Newell's normal follows the winding of the face, so projecting onto a basis (u, v) with
  // u x v along it keeps counter-clockwise triangles counter-clockwise.
  Vec3 normal = Vec3::Zero();
  for (std::size_t i = 0; i < n; ++i) normal += corners[i].cross(corners[(i + 1) % n]);
  if (!(normal.norm() > 0.0)) return {};
  normal.normalize();
  if (n == 3) return {{0, 1, 2}};
  const Vec3 axis = std::abs(normal.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 u = axis.cross(normal).normalized();
  const Vec3 v = normal.cross(u);
  std::vector<Epick::Point_2> points;
  for (const Vec3& c : corners) points.emplace_back(c.dot(u), c.dot(v));
  Cdt cdt;
  insert_ring(cdt, points, 0);
  std::vector<std::array<int, 3>> triangles;
  if (domain_triangles(cdt, triangles) && !triangles.empty()) return triangles;
  // A face whose outline crosses itself in projection: a fan keeps its corners and winding.
  triangles.clear();
  for (std::size_t i = 1; i + 1 < n; ++i) triangles.push_back({0, static_cast<int>(i), static_cast<int>(i + 1)});
  return triangles;
}

}  // namespace vistrack::detail
