// Visibility volumes (section III.D, eq. (4)) by Embree ray casting, and line-of-sight queries.
//
// From a POI g the points visible along one direction form a single interval of the ray (the
// first hit ends it, d_max and the altitude band cut it), so a VV is described exactly by that
// interval per direction of a fixed angular grid. The grid and the intervals are kept beside the
// mesh: the `volume` area computes XOR volumes per direction from them (its fast path).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vistrack/environment.hpp"
#include "vistrack/geometry.hpp"

namespace vistrack {

// The angular grid of a VV: cells of equal size in elevation and azimuth over the whole sphere.
// Row i covers elevations [-pi/2 + i*d_el, -pi/2 + (i+1)*d_el] with d_el = pi / num_elevation;
// column j covers azimuths [j*d_az, (j+1)*d_az] with d_az = 2 pi / num_azimuth (from +x,
// counter-clockwise). The ray of cell (i, j) goes through the cell's centre.
struct DirectionGrid {
  int num_elevation = 0;
  int num_azimuth = 0;
  double elevation(int row) const;       // centre elevation of row i, rad
  double azimuth(int column) const;      // centre azimuth of column j, rad
  double solid_angle(int row) const;     // steradians of each cell in row i (exact)
  Vec3 direction(int row, int column) const;  // unit vector through the cell centre
  std::size_t size() const { return static_cast<std::size_t>(num_elevation) * num_azimuth; }
  // A grid whose steps are about resolution_deg in both angles.
  static DirectionGrid from_resolution(double resolution_deg);
};

// alpha(g) of eq. (4), approximated on a direction grid.
struct VisibilityVolume {
  Vec3 poi;                                              // g
  double d_max = 0.0;
  std::optional<std::pair<double, double>> altitude_band;  // (h_lo, h_hi) or none
  DirectionGrid grid;
  // Visible interval [near[k], far[k]] (metres along the ray from g) of direction k = i *
  // num_azimuth + j; near[k] >= far[k] means nothing is visible along it.
  std::vector<double> near;
  std::vector<double> far;
  TriangleMesh mesh;        // closed, outward oriented, 2-manifold, no self-intersections
  double volume = 0.0;      // of the mesh (divergence theorem)
  // Sum over cells of solid_angle * (far^3 - near^3) / 3: the volume the grid represents.
  double grid_volume() const;
};

}  // namespace vistrack
