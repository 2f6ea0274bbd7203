// Rays that certainly meet no obstacle, found without tracing them (private to the library).
//
// A ray from g at elevation el (tau = tan el) reaches horizontal distance rho at height
// g.z + rho tau. It can only hit a triangle whose height range [z_min, z_max] it passes through
// over the triangle's horizontal distance range [rho_min, rho_max] about g: for rays going up,
// tau <= (z_max - g.z) / rho_min; going down, tau >= (z_min - g.z) / rho_min (rho_max where the
// triangle lies wholly below, resp. above, g). Per azimuth column of the direction grid, the hull
// of these tau ranges over the triangles that reach into the column bounds every ray that can hit
// anything: the rays above it (the open sky over the roofs) and below it (the ground near g) have
// the interval the ground, the band and d_max give, exactly what tracing them would return.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "vistrack/geometry.hpp"

namespace vistrack::detail {

// The obstacle triangles in buckets of a square xy grid, for the per-POI bounds (built once per
// scene; coordinates relative to the scene's local origin).
struct ObstacleIndex {
  double cell = 1.0;
  double x0 = 0.0, y0 = 0.0;  // corner of bucket (0, 0)
  int nx = 0, ny = 0;
  std::vector<std::int32_t> bucket_start;  // triangles of bucket b: [bucket_start[b], bucket_start[b + 1])
  std::vector<double> bucket_z_min, bucket_z_max;  // height range of each bucket's triangles
  // Per triangle, ordered by bucket (a triangle sits in the bucket of its centroid; buckets grow
  // by `overhang`, the largest distance from a centroid to its triangle's corners).
  std::vector<double> ax, ay, bx, by, cx, cy, z_min, z_max;
  std::vector<std::uint32_t> face;  // its row in the faces given (Embree's primID)
  double overhang = 0.0;

  ObstacleIndex() = default;
  // vertices relative to the local origin; faces index them. Triangles no higher than
  // `ground` are left out: a ray from above the ground meets the ground plane there anyway.
  ObstacleIndex(const Points3& vertices, const Faces& faces, double ground);
  std::size_t size() const { return ax.size(); }
};

// A triangle within reach of g and the directions from g its rays can lie in: sines of
// elevation [sin_lo, sin_hi] and azimuths [az_lo, az_hi] (radians, az_lo may be negative and
// az_hi above 2 pi: the span wraps), or every azimuth; with the bounds' slack.
struct Footprint {
  std::uint32_t face = 0;
  bool every = false;
  double sin_lo = 0.0, sin_hi = 0.0, az_lo = 0.0, az_hi = 0.0;
};

// Per azimuth column j (azimuths [j, j + 1] * 2 pi / na, closed), the sines of elevation between
// which a ray may hit an obstacle: a ray in column j with sin_el > sin_hi[j] or sin_el < sin_lo[j]
// meets none. A column no triangle reaches has sin_lo = +2 and sin_hi = -2 (every ray is clear).
struct Clearance {
  int num_azimuth = 0;
  std::vector<double> sin_lo, sin_hi;
  std::vector<double> half_lo, half_hi;  // the second thread's columns when computed in parallel
  std::vector<Footprint> footprints;     // every triangle within reach (compute; none: empty)
  std::array<std::vector<Footprint>, 2> split_footprints;  // per thread when computed in parallel
  std::array<std::vector<std::uint32_t>, 2> split_row_ends;  // the count after each of its rows
  bool clear(double sin_el, int column) const {
    return sin_el > sin_hi[static_cast<std::size_t>(column)] || sin_el < sin_lo[static_cast<std::size_t>(column)];
  }
  // The bounds for rays from g (relative to the local origin) that end within `reach` of it, on
  // na columns. Reuses the vectors' storage. `parallel`: alternate rows of buckets on two of TBB's
  // threads (min and max merge exactly, the footprints are joined in row order: the same result
  // either way).
  void compute(const ObstacleIndex& index, const Vec3& g, double reach, int na, bool parallel = false);
  // Every ray traced (no bounds): the result then equals tracing everything.
  void none(int na);
};

}  // namespace vistrack::detail
