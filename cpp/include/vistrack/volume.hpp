// Volumes of visibility volumes: closed-mesh validation (CGAL), plane slicing into visibility
// polygons (section IV: the VP at h_UAV, sliced as in [24]) by CGAL's slicer and by an
// edge-walking slicer, and the XOR volume of eq. (56).
#pragma once

#include <string>
#include <optional>
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

// Polylines where the plane z = altitude cuts the mesh (CGAL Polygon_mesh_slicer), chained into
// closed rings (open pieces joined end to end, repeated points dropped). When `altitude` lies on
// a vertex height it is nudged by a few micrometres first.
std::vector<Ring> slice_rings(const TriangleMesh& mesh, double altitude);

// Closed rings nested into polygons with holes by containment depth (even depth: outer,
// odd: hole of the smallest enclosing outer). Orientation normalised.
std::vector<Polygon> nest_rings(const std::vector<Ring>& rings);

// The height at which to slice a VV for the VP at `altitude`: none when the altitude lies
// outside the VV's band, else nudged strictly inside it (exactly on a cap the slicer returns the
// cap's edges). Shared by both slicers.
std::optional<double> visibility_slice_height(const VisibilityVolume& vv, double altitude);
// The visibility polygon (VP) of a VV at world altitude z: the slice of its mesh, nested into
// polygons with holes. By default only the polygon(s) containing the POI's vertical (g.x, g.y)
// are kept (empty when none does: MaxRadius is then 0); all_parts keeps every part.
// Throws Error when the altitude is not finite.
std::vector<Polygon> visibility_polygon(const VisibilityVolume& vv, double altitude, bool all_parts = false);

// Rings where the plane z = altitude cuts a closed 2-manifold triangle mesh, by walking the
// crossing edges (O(faces), no spatial tree; vertices on the plane count as below). Error when
// the mesh is not closed or not 2-manifold along the cut.
std::vector<Ring> plane_slice_rings(const TriangleMesh& mesh, double altitude);
// The VP of a VV at world altitude z from plane_slice_rings: the same polygons as
// visibility_polygon (CGAL slicer) at a fraction of the cost; the planner uses it.
std::vector<Polygon> plane_visibility_polygon(const VisibilityVolume& vv, double altitude);

// ---------------------------------------------------------------------------------------------
// XOR volume, the difference metric d(alpha_i, alpha_j) of eq. (56).

// "poi": each VV is first translated by minus its own POI (as the paper's public implementation
// does), so open terrain gives zero; "world": the VVs are compared where they are.
enum class XorFrame { poi, world };
template <>
struct EnumNames<XorFrame> {
  static constexpr const char* field = "frame";
  static constexpr EnumName<XorFrame> names[] = {{"poi", XorFrame::poi}, {"world", XorFrame::world}};
};

// "radial": exact per direction on the meshes of two star VVs built over one sphere (what "mesh"
// computes, without CGAL); "grid": per direction on the grid corners' intervals; "mesh": CGAL
// corefinement. "auto": radial when it applies (POI frame, shares_radial_mesh), else grid (POI
// frame, shares_direction_grid), else mesh.
enum class XorMethod { automatic, radial, grid, mesh };
template <>
struct EnumNames<XorMethod> {
  static constexpr const char* field = "method";
  static constexpr EnumName<XorMethod> names[] = {{"auto", XorMethod::automatic}, {"radial", XorMethod::radial},
      {"grid", XorMethod::grid}, {"mesh", XorMethod::mesh}};
};

// The rotation xor_volume's mesh path applies in frame "poi" unless told otherwise (rad).
inline constexpr double kPoiFramePerturbation = 1e-6;
// The largest perturbation accepted (rad).
inline constexpr double kMaxPerturbation = 1e-3;

struct MeshXorOptions {
  // CGAL corefinement cannot be bounded in advance (coplanar overlaps make it pathologically
  // slow, see notes/embree-cgal.md): past this many seconds it is aborted with an Error.
  double time_limit = 120.0;
  // Rotation (rad) of the second mesh about the axis (1, 2, 3)/|(1, 2, 3)| through the origin
  // before the Boolean. 0 = exact. A tiny value takes identical and coplanar faces (two VVs about
  // the same POI) out of CGAL's slow coincident-face branch; it moves a point at distance r by at
  // most angle * r, so it changes the XOR by at most about angle * r_max * (surface area of both
  // meshes). None: kPoiFramePerturbation for xor_volume in frame "poi" (where two VVs always
  // share identical sphere faces), 0 otherwise. In [0, kMaxPerturbation].
  std::optional<double> perturbation;
  // Check both meshes for self-intersections first (O(n log n); CGAL's Boolean requires none).
  bool check_self_intersection = true;
};

// volume(A xor B) = vol(A) + vol(B) - 2 vol(A n B) of two closed, outward oriented, 2-manifold
// triangle meshes without self-intersections, by CGAL corefinement with exact predicates
// (Epick; the inputs are copied). A mesh without faces is the empty set. Error when a mesh is
// not closed, not a valid triangle mesh, self-intersecting, does not bound a volume, or the time
// limit is exceeded.
double mesh_xor_volume(const TriangleMesh& a, const TriangleMesh& b, const MeshXorOptions& options = {});

// True when both VVs use the same direction grid with intervals for every grid corner.
bool shares_direction_grid(const VisibilityVolume& a, const VisibilityVolume& b);

// The XOR volume of two VVs described on one direction grid, each about its own POI (frame
// "poi"): both are then star-shaped about the origin, and along the ray of each grid corner the
// symmetric difference of the visible intervals has the measure integral r^2 dr = (f^3 - n^3)/3
// per piece. The trapezoid rule over the cells: sum over corners of corner_weight * that measure.
// Error unless shares_direction_grid(a, b).
double grid_xor_volume(const VisibilityVolume& a, const VisibilityVolume& b);

// True when both VVs are star VVs on the same direction grid whose meshes say how they cover the
// sphere of grid corners (VisibilityVolume::mesh_row_sines and mesh_triangle_faces); their vertex
// rows may differ.
bool shares_radial_mesh(const VisibilityVolume& a, const VisibilityVolume& b);

// The XOR volume of the two meshes, each about its own POI (frame "poi"), exact per direction:
// the faces of a and b are overlapped (clipping cones by planes through the POI; slot against slot
// when the vertex rows agree, across the rows of each column when not) and |r_a^3 - r_b^3| / 3 is
// integrated in closed form where both are planes. The same number as mesh_xor_volume on the translated meshes, without CGAL (5 ms
// instead of 16 s for a 1-degree Charlotte pair). Error unless shares_radial_mesh(a, b).
double radial_xor_volume(const VisibilityVolume& a, const VisibilityVolume& b);

// d(a, b) of eq. (56) for two VVs, in the given frame, by the chosen method. The mesh path in
// frame "poi" applies options.perturbation, by default kPoiFramePerturbation (see MeshXorOptions).
double xor_volume(const VisibilityVolume& a, const VisibilityVolume& b, XorFrame frame = XorFrame::poi,
                  XorMethod method = XorMethod::automatic, const MeshXorOptions& options = {});

}  // namespace vistrack
