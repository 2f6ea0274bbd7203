// Volumes of visibility volumes with CGAL: closed-mesh validation and plane slicing into
// visibility polygons (section IV: the VP at h_UAV, sliced as in [24]).
// (The orbit helper appends the XOR-volume declarations at the end of this file.)
#pragma once

#include <string>
#include <vector>

#include "vistrack/environment.hpp"
#include "vistrack/geometry.hpp"
#include "vistrack/visibility.hpp"

namespace vistrack {

// What CGAL says about a triangle mesh that should bound a solid.
struct MeshCheck {
  bool triangles_valid = false;   // indices in range, no degenerate (repeated-index) faces
  bool polygon_mesh = false;      // the faces form an oriented 2-manifold (PMP::is_polygon_soup_a_polygon_mesh)
  bool closed = false;            // CGAL::is_closed: no border edges
  bool self_intersecting = true;  // PMP::does_self_intersect
  bool bounds_volume = false;     // PMP::does_bound_a_volume
  bool outward = false;           // PMP::is_outward_oriented
  double volume = 0.0;            // PMP::volume (0 unless closed)
  std::string problem;            // first failed property, empty when valid
  bool valid() const { return problem.empty(); }
};

// Checks a mesh with CGAL (Surface_mesh, exact predicates). An empty mesh is reported invalid.
MeshCheck check_closed_mesh(const TriangleMesh& mesh);

// For each row of `points`: inside the closed mesh (CGAL Side_of_triangle_mesh; boundary counts
// as inside). Throws Error when the mesh is not a closed 2-manifold.
std::vector<bool> points_inside(const TriangleMesh& mesh, const Points3& points);

// Polylines where the plane z = altitude cuts the mesh (CGAL Polygon_mesh_slicer), chained into
// closed rings (open pieces joined end to end, repeated points dropped). When `altitude` lies on
// a vertex height it is nudged by a few micrometres first.
std::vector<Ring> slice_rings(const TriangleMesh& mesh, double altitude);

// Closed rings nested into polygons with holes by containment depth (even depth: outer,
// odd: hole of the smallest enclosing outer). Orientation normalised.
std::vector<Polygon> nest_rings(const std::vector<Ring>& rings);

// The visibility polygon (VP) of a VV at world altitude z: the slice of its mesh, nested into
// polygons with holes. By default only the polygon(s) containing the POI's vertical (g.x, g.y)
// are kept (empty when none does: MaxRadius is then 0); all_parts keeps every part.
// Throws Error when the altitude is not finite.
std::vector<Polygon> visibility_polygon(const VisibilityVolume& vv, double altitude, bool all_parts = false);

}  // namespace vistrack
