// Validation and extrusion of 2.5D buildings B_i = A_i x [b_i, h_i] (section III.B, with a base).
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "environment/detail.hpp"
#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"

namespace vistrack::detail {

namespace {

std::string point_text(const Vec2& p) { return "(" + to_text(p.x()) + ", " + to_text(p.y()) + ")"; }

void validate_ring(const Ring& ring, const std::string& field) {
  for (std::size_t i = 0; i < ring.size(); ++i)
    if (!(std::abs(ring[i].x()) <= limits::kMaxCoordinate && std::abs(ring[i].y()) <= limits::kMaxCoordinate))
      fail_field(field + "[" + std::to_string(i) + "]", point_text(ring[i]),
                 "coordinates must be finite numbers in [-1e7, 1e7] m");
  if (ring.size() < 3)
    fail_field(field, std::to_string(ring.size()) + " distinct points",
               "a footprint ring needs at least 3 distinct points");
  if (const auto bad = find_self_intersection(ring)) {
    const auto [i, j] = *bad;
    const std::size_t n = ring.size();
    const std::string edge_i = "edge " + std::to_string(i) + " " + point_text(ring[i]) + "-" + point_text(ring[(i + 1) % n]);
    const std::string edge_j = "edge " + std::to_string(j) + " " + point_text(ring[j]) + "-" + point_text(ring[(j + 1) % n]);
    const bool one_line = std::all_of(ring.begin(), ring.end(), [&](const Vec2& q) {
      const Vec2 u = ring[1] - ring[0], v = q - ring[0];
      return u.x() * v.y() - u.y() * v.x() == 0.0;
    });
    if (one_line)
      fail_field(field, "ring of " + std::to_string(n) + " points starting at " + point_text(ring[0]),
                 "degenerate footprint: all points on one line (zero area)");
    if (i == j) fail_field(field, edge_i, "degenerate footprint: zero-length edge");
    fail_field(field, edge_i + " and " + edge_j,
               "self-intersecting or degenerate footprint: these edges touch or cross");
  }
}

struct Box {
  Vec2 min, max;
  bool overlaps(const Box& other) const {
    return min.x() <= other.max.x() && other.min.x() <= max.x() && min.y() <= other.max.y() &&
           other.min.y() <= max.y();
  }
};

Box box_of(const Polygon& polygon) {
  const Bounds2 b = bounds(polygon.outer);
  return {b.min, b.max};
}

void check_overlaps(const std::vector<Building>& buildings, const std::vector<BuildingSource>& sources) {
  const std::size_t n = buildings.size();
  std::vector<Box> boxes(n);
  std::vector<double> areas(n);
  for (std::size_t i = 0; i < n; ++i) {
    boxes[i] = box_of(buildings[i].footprint);
    areas[i] = area(buildings[i].footprint);
  }
  // Sweep along x so that only boxes that overlap go to the exact Boolean operation.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return boxes[a].min.x() < boxes[b].min.x(); });
  for (std::size_t oi = 0; oi < n; ++oi) {
    const std::size_t i = order[oi];
    for (std::size_t oj = oi + 1; oj < n && boxes[order[oj]].min.x() <= boxes[i].max.x(); ++oj) {
      const std::size_t j = order[oj];
      if (!boxes[i].overlaps(boxes[j])) continue;
      const Building& a = buildings[i];
      const Building& b = buildings[j];
      // Stacked parts (one's base at or above the other's top) share no volume.
      if (a.height <= b.min_height || b.height <= a.min_height) continue;
      const double shared = intersection_area(a.footprint, b.footprint);
      if (shared <= kOverlapTolerance) continue;  // touching walls, drawn approximately
      // A building part drawn inside its building's outline and within its heights adds nothing
      // to the obstacle set, whose interiors stay disjoint: accepted (Charlotte has one).
      const std::size_t inner = areas[i] <= areas[j] ? i : j;
      const std::size_t outer = inner == i ? j : i;
      if (shared >= areas[inner] - kOverlapTolerance && buildings[inner].height <= buildings[outer].height &&
          buildings[inner].min_height >= buildings[outer].min_height)
        continue;
      const std::size_t first = std::min(i, j), second = std::max(i, j);
      throw Error(sources[first].name + " (id " + std::to_string(buildings[first].id) + ") and " +
                  sources[second].name + " (id " + std::to_string(buildings[second].id) +
                  ") overlap: shared area = " + to_text(shared) +
                  " m^2: building footprints must have disjoint interiors (touching walls are allowed)");
    }
  }
}

}  // namespace

Ring clean_ring(const Ring& ring) {
  Ring cleaned;
  cleaned.reserve(ring.size());
  for (const Vec2& p : ring)
    if (cleaned.empty() || p != cleaned.back()) cleaned.push_back(p);
  while (cleaned.size() > 1 && cleaned.front() == cleaned.back()) cleaned.pop_back();
  return cleaned;
}

std::vector<BuildingSource> sources_for_buildings(const std::vector<Building>& buildings) {
  std::vector<BuildingSource> sources;
  for (std::size_t i = 0; i < buildings.size(); ++i) {
    const std::string name = "buildings[" + std::to_string(i) + "]";
    BuildingSource source{name, name + ".height", name + ".footprint.outer", {}, name + ".min_height"};
    for (std::size_t h = 0; h < buildings[i].footprint.holes.size(); ++h)
      source.hole_fields.push_back(name + ".footprint.holes[" + std::to_string(h) + "]");
    sources.push_back(source);
  }
  return sources;
}

void validate_buildings(std::vector<Building>& buildings, const std::vector<BuildingSource>& sources) {
  for (std::size_t b = 0; b < buildings.size(); ++b) {
    Building& building = buildings[b];
    const BuildingSource& source = sources[b];
    require_length(building.height, source.height_field);
    if (!(building.min_height >= 0.0 && std::isfinite(building.min_height)))
      fail_field(source.min_height_field, building.min_height, "the base must be a finite height >= 0 m");
    if (!(building.min_height < building.height))
      fail_field(source.min_height_field, building.min_height,
                 "the base must lie below the top (" + source.height_field + " = " + to_text(building.height) + ")");
    Polygon& footprint = building.footprint;
    footprint.outer = clean_ring(footprint.outer);
    validate_ring(footprint.outer, source.outer_field);
    for (std::size_t h = 0; h < footprint.holes.size(); ++h) {
      footprint.holes[h] = clean_ring(footprint.holes[h]);
      validate_ring(footprint.holes[h], source.hole_fields[h]);
    }
    normalize_orientation(footprint);
    const Polygon outer_only{footprint.outer, {}};
    for (std::size_t h = 0; h < footprint.holes.size(); ++h) {
      const Polygon hole{footprint.holes[h], {}};
      Polygon hole_ccw = hole;
      normalize_orientation(hole_ccw);
      const double hole_area = std::abs(signed_area(hole.outer));
      if (intersection_area(outer_only, hole_ccw) < hole_area - 1e-9 * std::max(1.0, hole_area))
        fail_field(source.hole_fields[h], "hole starting at " + point_text(hole.outer[0]),
                   "a hole must lie inside the outer ring of its footprint");
      for (std::size_t k = 0; k < h; ++k) {
        Polygon other{footprint.holes[k], {}};
        normalize_orientation(other);
        if (intersection_area(hole_ccw, other) > 0.0)
          fail_field(source.hole_fields[h], "hole starting at " + point_text(hole.outer[0]),
                     "overlaps " + source.hole_fields[k] + ": holes must have disjoint interiors");
      }
    }
  }
  check_overlaps(buildings, sources);
}

TriangleMesh extrude(const std::vector<Building>& buildings) {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> faces;
  for (const Building& building : buildings) {
    const Polygon& footprint = building.footprint;
    // Vertex indices shared within the building, so that every edge joins two faces (Embree
    // leaks rays through unshared edges; a hole touching the outer ring shares the corner).
    std::map<std::pair<double, double>, int> index_of;
    std::vector<int> ring_index;  // footprint point (outer then holes) -> bottom vertex
    const int first = static_cast<int>(vertices.size());
    auto add_point = [&](const Vec2& p) {
      auto [it, inserted] = index_of.emplace(std::make_pair(p.x(), p.y()), 0);
      if (inserted) {
        it->second = static_cast<int>(vertices.size());
        vertices.emplace_back(p.x(), p.y(), building.min_height);
      }
      ring_index.push_back(it->second);
    };
    for (const Vec2& p : footprint.outer) add_point(p);
    for (const Ring& hole : footprint.holes)
      for (const Vec2& p : hole) add_point(p);
    const int count = static_cast<int>(vertices.size()) - first;
    for (int i = 0; i < count; ++i) {
      const Vec3 bottom = vertices[static_cast<std::size_t>(first + i)];
      vertices.emplace_back(bottom.x(), bottom.y(), building.height);
    }
    auto top = [&](int bottom_index) { return bottom_index + count; };
    // Roof counter-clockwise seen from above (normal +z), floor reversed (normal -z).
    for (const auto& t : triangulate_polygon(footprint)) {
      const int a = ring_index[static_cast<std::size_t>(t[0])];
      const int b = ring_index[static_cast<std::size_t>(t[1])];
      const int c = ring_index[static_cast<std::size_t>(t[2])];
      faces.push_back({top(a), top(b), top(c)});
      faces.push_back({a, c, b});
    }
    // Walls: the material lies left of each ring edge (outer CCW, holes CW), so the outward
    // normal (edge x up) points to its right.
    std::size_t offset = 0;
    auto add_walls = [&](const Ring& ring) {
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const int a = ring_index[offset + i];
        const int b = ring_index[offset + (i + 1) % ring.size()];
        faces.push_back({a, b, top(b)});
        faces.push_back({a, top(b), top(a)});
      }
      offset += ring.size();
    };
    add_walls(footprint.outer);
    for (const Ring& hole : footprint.holes) add_walls(hole);
  }
  TriangleMesh mesh;
  mesh.vertices.resize(static_cast<Eigen::Index>(vertices.size()), 3);
  for (std::size_t i = 0; i < vertices.size(); ++i) mesh.vertices.row(static_cast<Eigen::Index>(i)) = vertices[i].transpose();
  mesh.faces.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t i = 0; i < faces.size(); ++i)
    for (std::size_t k = 0; k < 3; ++k)
      mesh.faces(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) = faces[i][k];
  return mesh;
}

}  // namespace vistrack::detail
