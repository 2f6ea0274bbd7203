// Internals of the environment area shared by its .cpp files (CGAL stays in the .cpp files).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vistrack/environment.hpp"

namespace vistrack::detail {

// Footprints may overlap by at most this area (m^2): files draw touching walls approximately
// (Charlotte: 0.54 m^2 between two parts of one 90 m building, the rest below 0.02 m^2).
constexpr double kOverlapTolerance = 1.0;

// Where a building came from, so that a message names the field the user wrote.
struct BuildingSource {
  std::string name;          // "features[12]" or "buildings[3]"
  std::string height_field;  // "features[12].properties.height"
  std::string outer_field;   // "features[12].geometry.coordinates[0]"
  std::vector<std::string> hole_fields;
  std::string min_height_field;  // "features[12].properties.min_height"
};

// Drops a closing repeat and consecutive repeated points (both common in files).
Ring clean_ring(const Ring& ring);

// Indices (i, j) of the first two non-adjacent edges that touch, or of a zero-length edge
// (i == j), found with exact predicates; nothing when the ring is simple.
std::optional<std::pair<std::size_t, std::size_t>> find_self_intersection(const Ring& ring);

// Area of the intersection of two valid polygons (exact Boolean operation, rounded at the end).
double intersection_area(const Polygon& a, const Polygon& b);

// Constrained Delaunay triangulation of a valid polygon with holes. Points are numbered outer
// ring first, then each hole in order; triangles are counter-clockwise.
std::vector<std::array<int, 3>> triangulate_polygon(const Polygon& polygon);

// Triangulation of one (possibly non-convex, roughly planar) face of a mesh, given its corner
// points; triangles index the corners and keep the face's winding. Empty for a degenerate face.
std::vector<std::array<int, 3>> triangulate_face(const std::vector<Vec3>& corners);

// Validates and normalises the buildings (orientation, cleaned rings); throws Error naming the
// source fields. Checks overlaps between all pairs.
void validate_buildings(std::vector<Building>& buildings, const std::vector<BuildingSource>& sources);

// Walls, roof and floor of every building: closed, outward oriented, with vertices shared
// within each building.
TriangleMesh extrude(const std::vector<Building>& buildings);

// Default source names for from_buildings.
std::vector<BuildingSource> sources_for_buildings(const std::vector<Building>& buildings);

}  // namespace vistrack::detail
