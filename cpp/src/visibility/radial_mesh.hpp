// Pieces shared by the VV mesh builders (private to the library): the visible interval along one
// ray, the triangulated sphere of grid corners, and a mesh writer that sums the volume.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <vector>

#include "vistrack/visibility.hpp"

namespace vistrack::detail {

// Which surface ends a visible interval: the position of a mesh vertex on a band cap or on the
// ground gets that surface's exact z.
enum class Surface : unsigned char { radial, band_low, band_high, ground };

// Runs body(i) for i in [0, n): in parallel when asked (each i must touch its own data only).
template <class Body>
void for_each_index(bool parallel, int n, Body body) {
  if (!parallel) {
    for (int i = 0; i < n; ++i) body(i);
    return;
  }
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 8), [&](const tbb::blocked_range<int>& r) {
    for (int i = r.begin(); i < r.end(); ++i) body(i);
  });
}

struct Setup {
  Vec3 g;
  double d_max = 0.0;
  bool has_band = false;
  double low = 0.0;
  double high = 0.0;
  double ground = 0.0;
  bool poi_in_band = true;  // near = 0 along every ray (the VV is star-shaped about g)
};

struct Interval {
  double near = 0.0;
  double far = 0.0;
  Surface near_surface = Surface::radial;
  Surface far_surface = Surface::radial;
  // 1/near and 1/far without clamping (<= 0: the band is never entered). For a plane z = c the
  // inverse distance along g + t d is d.z / (c - g.z), linear in d: the shell mesh interpolates
  // these to find where the visible interval closes between two directions.
  double inv_near = 0.0;
  double inv_far = 0.0;
};

// The visible part of the ray g + t d (|d| = 1, d.z = sin_el) given the first obstacle hit.
Interval visible_interval(const Setup& s, double sin_el, double obstacle_hit);

// visible_interval's far end and its surface when the POI lies in the band (near = 0 on every
// ray), without the rest.
inline double star_far(const Setup& s, double sin_el, double obstacle_hit, Surface& surface) {
  double far = obstacle_hit < s.d_max ? obstacle_hit : s.d_max;
  surface = Surface::radial;
  if (sin_el < 0.0) {
    const double t_ground = std::max(0.0, (s.ground - s.g.z()) / sin_el);
    if (t_ground < far) {
      far = t_ground;
      surface = Surface::ground;
    }
  }
  if (s.has_band && sin_el != 0.0) {
    const double exit = ((sin_el > 0.0 ? s.high : s.low) - s.g.z()) / sin_el;
    if (exit < far) {
      far = exit;
      surface = sin_el > 0.0 ? Surface::band_high : Surface::band_low;
    }
  }
  return far;
}

// How far a ray with that elevation can see at most (ground, band, d_max), or 0 when the band
// leaves it nothing to see: rays are traced no farther.
inline double visible_far_bound(const Setup& s, double sin_el) {
  if (s.poi_in_band) {
    Surface surface;
    const double far = star_far(s, sin_el, s.d_max, surface);
    return far > 0.0 ? far : 0.0;
  }
  const Interval bound = visible_interval(s, sin_el, s.d_max);
  return bound.far > bound.near ? bound.far : 0.0;
}

// The point at distance t along unit direction d from g; on a band cap or the ground its z is
// that plane's exactly.
Vec3 point_on(const Setup& s, const Vec3& d, double t, Surface surface);

// The triangulated sphere of grid corners. Vertex rows i = 0..ne at elevations
// -pi/2 + i pi/ne (rows 0 and ne are the poles), columns j at azimuths j d_az. Quad (i, j) splits
// into Ta = [(i,j), (i,j+1), (i+1,j+1)] (absent at the south pole row) and
// Tb = [(i,j), (i+1,j+1), (i+1,j)] (absent at the north pole row), both outward oriented.
struct SphereGrid {
  int ne = 0;
  int na = 0;
  int num_vertices() const { return 2 + (ne - 1) * na; }
  int vertex(int i, int j) const {
    if (i <= 0) return 0;
    if (i >= ne) return num_vertices() - 1;
    return 1 + (i - 1) * na + wrap(j);
  }
  // Column index modulo na for j in [-1, na] (no division in the hot loops).
  int wrap(int j) const { return j < 0 ? j + na : (j >= na ? j - na : j); }
  int ta(int i, int j) const { return 2 * (i * na + wrap(j)); }
  int tb(int i, int j) const { return 2 * (i * na + wrap(j)) + 1; }
  int num_triangle_slots() const { return 2 * ne * na; }
  bool exists(int t) const {
    const int i = (t / 2) / na;
    return (t % 2 == 0) ? i >= 1 : i <= ne - 2;
  }
  // First vertex of row i, and one past its last (a pole row is one vertex).
  int row_first(int i) const { return i == 0 ? 0 : (i == ne ? num_vertices() - 1 : 1 + (i - 1) * na); }
  int row_end(int i) const { return row_first(i) + (i == 0 || i == ne ? 1 : na); }
  // The quads of row i: quad(j) gives the corners (i, j), (i, j+1), (i+1, j), (i+1, j+1) of quad
  // (i, j), j in [0, na), without vertex()'s branches per corner (the hot loops of the mesh).
  struct QuadRow {
    int lo, hi, na;
    bool south, north;  // the row touches the south (north) pole
    std::array<int, 4> quad(int j) const {
      const int jn = j + 1 == na ? 0 : j + 1;
      return {south ? lo : lo + j, south ? lo : lo + jn, north ? hi : hi + j, north ? hi : hi + jn};
    }
  };
  QuadRow quad_row(int i) const { return {row_first(i), row_first(i + 1), na, i == 0, i + 1 == ne}; }
  // Calls visit(i, t, v00, v01, v10, v11) for every quad in row-major order: row i, its Ta slot t
  // (Tb is t + 1) and its corner vertices (i, j), (i, j+1), (i+1, j), (i+1, j+1).
  template <class Visit>
  void for_each_quad(Visit visit) const {
    for (int i = 0; i < ne; ++i) {
      const QuadRow row = quad_row(i);
      for (int j = 0; j < na; ++j) {
        const auto [v00, v01, v10, v11] = row.quad(j);
        visit(i, 2 * (i * na + j), v00, v01, v10, v11);
      }
    }
  }
  std::array<int, 3> corners(int t) const;
  // The triangle across edge e (corner e to corner e+1) of triangle t.
  int neighbour(int t, int e) const;
  // Existing triangles around vertex v in cyclic order: their number, written to `out`; for a
  // pole, -1 and the ring in `pole_ring`.
  int ring(int v, std::array<int, 6>& out, std::vector<int>& pole_ring) const;
};

// Sine of the elevation of grid corner row i (DirectionGrid::corner): exactly -1, 0 and 1 at the
// poles and on the horizon.
double corner_sine(int row, int num_elevation);

// Unit directions of the sphere grid's corners, from trig tables.
struct Directions {
  const SphereGrid& sphere;
  std::vector<double> cos_el_corner, sin_el_corner, cos_az_corner, sin_az_corner;

  // sin_el_rows: sines of the mesh's vertex-row elevations, from -1 (south pole) to 1.
  Directions(const SphereGrid& s, const std::vector<double>& sin_el_rows);
  Vec3 corner(int v) const {
    if (v == 0) return {0.0, 0.0, -1.0};
    if (v == sphere.num_vertices() - 1) return {0.0, 0.0, 1.0};
    const int i = 1 + (v - 1) / sphere.na;
    const int j = (v - 1) % sphere.na;
    return {cos_el_corner[i] * cos_az_corner[j], cos_el_corner[i] * sin_az_corner[j], sin_el_corner[i]};
  }
};

// Writes vertices and faces straight into the mesh's arrays (grown geometrically, trimmed at the
// end) and sums the volume on the way: signed tetrahedra against g (divergence theorem).
class MeshBuilder {
 public:
  MeshBuilder(const Vec3& g, Eigen::Index expected_points, Eigen::Index expected_faces);
  int add(const Vec3& p) {
    if (num_points_ == mesh_.vertices.rows()) mesh_.vertices.conservativeResize(2 * num_points_ + 16, 3);
    mesh_.vertices.row(num_points_) = p.transpose();
    return static_cast<int>(num_points_++);
  }
  Vec3 point(int v) const { return mesh_.vertices.row(v).transpose(); }
  int num_faces() const { return static_cast<int>(num_faces_); }
  void face(int a, int b, int c);
  TriangleMesh finish(double& volume);

 private:
  Vec3 g_;
  TriangleMesh mesh_;
  Eigen::Index num_points_ = 0;
  Eigen::Index num_faces_ = 0;
  double six_volume_ = 0.0;
};

// The closed mesh of a VV whose POI lies outside the band (near > 0): outer and inner surfaces
// joined on the contour where the visible interval closes (see shell_mesh.cpp).
TriangleMesh build_shell_mesh(const Setup& s, const SphereGrid& sphere, const Directions& dirs,
                              const std::vector<Interval>& corner, double& volume);

}  // namespace vistrack::detail
