// Visibility volumes (section III.D, eq. (4)) by Embree ray casting, and line-of-sight queries.
//
// From a POI g the points visible along one direction form a single interval of the ray (the
// first hit ends it, d_max and the altitude band cut it), so a VV is described exactly by that
// interval per direction of a fixed angular grid. The grid and the intervals are kept beside the
// mesh: the `volume` area computes XOR volumes per direction from them (its fast path).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vistrack/environment.hpp"
#include "vistrack/geometry.hpp"
#include "vistrack/visibility_parameters.hpp"

namespace vistrack {

// The angular grid of a VV: cells of equal size in elevation and azimuth over the whole sphere.
// Row i covers elevations [-pi/2 + i*d_el, -pi/2 + (i+1)*d_el] with d_el = pi / num_elevation;
// column j covers azimuths [j*d_az, (j+1)*d_az] with d_az = 2 pi / num_azimuth (from +x,
// counter-clockwise). A VV samples its intervals at the cells' corners: corner (i, j), i in
// [0, num_elevation], at elevation -pi/2 + i*d_el and azimuth j*d_az (rows 0 and num_elevation
// are the poles, repeated in every column). The same rays make the mesh, so nothing is traced
// twice (file format 4; before it, each cell had its own staggered ray).
struct DirectionGrid {
  int num_elevation = 0;
  int num_azimuth = 0;
  double elevation(int row) const;       // centre elevation of row i, rad
  double azimuth(int column) const;      // centre azimuth of column j, rad
  double solid_angle(int row) const;     // steradians of each cell in row i (exact)
  Vec3 corner(int row, int column) const;  // unit vector to corner (i, j), i in [0, num_elevation]
  // The trapezoid rule's weight of each corner of row i (sr): half the solid angle of a cell of
  // the row below plus half of one of the row above; sums to 4 pi over the corners.
  double corner_weight(int row) const;
  std::size_t size() const { return static_cast<std::size_t>(num_elevation) * num_azimuth; }
  std::size_t num_corners() const { return static_cast<std::size_t>(num_elevation + 1) * num_azimuth; }
  // A grid whose steps are about resolution_deg in both angles.
  static DirectionGrid from_resolution(double resolution_deg);
};

// alpha(g) of eq. (4), approximated on a direction grid.
struct VisibilityVolume {
  Vec3 poi;                                              // g
  double d_max = 0.0;
  std::optional<std::pair<double, double>> altitude_band;  // (h_lo, h_hi) or none
  DirectionGrid grid;
  // Visible interval [near[k], far[k]] (metres along the ray from g) at corner k = i *
  // num_azimuth + j of the grid (grid.num_corners() of them); near[k] >= far[k] means nothing is
  // visible along it.
  std::vector<double> near;
  std::vector<double> far;
  TriangleMesh mesh;        // closed, outward oriented, 2-manifold, no self-intersections (empty
                            // without has_mesh: read through what checks it, not directly)
  double volume = 0.0;      // of the mesh (divergence theorem)
  // False for a VV computed without its mesh (with_mesh = false): its intervals and its volume
  // (the mesh's, to the last bit) only; mesh, mesh_row_sines and mesh_triangle_faces are empty,
  // and what reads the mesh (slices, XOR, save, VV files) refuses it (detail::require_mesh).
  bool has_mesh = true;
  // When g lies in the band (near = 0: the mesh is a radial surface about g, walls and fans
  // aside), how the mesh covers the triangulated sphere of grid corners, for the exact XOR of two
  // meshes per direction: the sines of its vertex rows' elevations (the grid's row boundaries
  // plus the creases where d_max meets the ground or a band plane), and for each of its triangle
  // slots t (two per quad, row-major) the faces built over it, [triangle_faces[t],
  // triangle_faces[t + 1]). Empty otherwise.
  std::vector<double> mesh_row_sines;
  std::vector<std::int32_t> mesh_triangle_faces;
  // Sum over corners of corner_weight * (far^3 - near^3) / 3: the volume the grid represents
  // (the trapezoid rule over the cells).
  double grid_volume() const;

  // Writes the mesh as Wavefront OBJ (".obj") or ASCII PLY (".ply"), chosen by the extension.
  void save(const std::string& path) const;
  // The visible interval of direction k is empty (nothing visible along that ray).
  bool empty(std::size_t k) const { return !(far[k] > near[k]); }
};

namespace detail {
struct EmbreeScene;
// Error naming `field` when `vv` was computed without its mesh, for what reads the mesh.
void require_mesh(const VisibilityVolume& vv, const std::string& field);
}  // namespace detail

// An Embree BVH over an environment's obstacle triangles plus its ground plane (a square of
// half-size 1e6 m at ground_level()), built once and shared by every query. Copies share the
// same BVH; queries are thread-safe. Embree stays behind this pimpl.
class VisibilityScene {
 public:
  explicit VisibilityScene(const Environment& env);

  // Distance from `origin` along each row of `directions` (not necessarily unit; distances are
  // in metres) to the first obstacle or ground hit, or +infinity when none is closer than
  // t_max. Rays are traced in coherent batches (rtcIntersect1M).
  std::vector<double> first_hits(const Vec3& origin, const Points3& directions, double t_max) const;
  // For each pair (a[k], b[k]): true when the open segment between them meets no obstacle and
  // does not pass below the ground (occlusion rays; a and b themselves may lie on a surface).
  std::vector<bool> line_of_sight(const Points3& a, const Points3& b) const;
  // Whether p lies inside an obstacle: the footprint test for 2.5D buildings, else the parity of
  // the ray crossings (majority over three directions) for a mesh.
  bool inside_obstacle(const Vec3& p) const;

  // Height of the topmost surface (obstacle or ground) under the vertical through xy: where a
  // POI on uneven terrain stands.
  double surface_height(const Vec2& xy) const;
  // Where a ground POI stands: a POI path's z is the POI's height above the surface under it
  // (0.5 m in the data's paths), so on uneven terrain (the campus) it follows the ground:
  // (x, y, surface_height(x, y) + z). Caveat: under a canopy or an overhang the topmost surface
  // is the canopy's top. Error for a negative or NaN height.
  Vec3 poi_on_surface(const Vec3& g) const;

  double ground_level() const;
  Bounds3 bounds() const;                 // of the obstacle triangles
  std::size_t num_triangles() const;      // obstacle triangles, ground not counted
  std::uint64_t fingerprint() const;      // Environment::fingerprint() of the source

 private:
  friend struct detail::EmbreeScene;
  std::shared_ptr<const detail::EmbreeScene> impl_;
};

// alpha(g) of eq. (4): the points within d_max of g, inside the altitude band (h_lo, h_hi) of
// world z when given, with an unobstructed line of sight to g (obstacles and ground). One ray per
// grid corner gives near/far and the mesh (a piecewise-linear radial surface, band caps with
// exact z), with radial walls where the visible distance jumps (silhouettes, located by bisection
// with more rays). with_mesh = false leaves the mesh out (VisibilityVolume::has_mesh): the same
// intervals and volume, for a star VV (the POI in its band) about a fifth less CPU on Charlotte; a
// shell's volume still comes from its mesh (beyond the paper, issue 35). Throws
// Error naming the field for g below the ground or inside an obstacle, d_max <= 0, NaN, or a band
// with h_lo >= h_hi.
VisibilityVolume visibility_volume(const VisibilityScene& scene, const Vec3& g, double d_max,
                                   std::optional<std::pair<double, double>> altitude_band = std::nullopt,
                                   double resolution_deg = kDefaultResolutionDeg, bool with_mesh = true);
// Same, building a scene for this one call (prefer a shared VisibilityScene for many VVs).
VisibilityVolume visibility_volume(const Environment& env, const Vec3& g, double d_max,
                                   std::optional<std::pair<double, double>> altitude_band = std::nullopt,
                                   double resolution_deg = kDefaultResolutionDeg, bool with_mesh = true);
// Memory of one VV on a grid of resolution_deg degrees, estimated from above: its intervals (16 bytes
// per corner) and, with_mesh, its mesh (56 bytes per cell, plus its walls: 3000 sqrt(cells)).
double volume_bytes(double resolution_deg, bool with_mesh = true);
// VVs for many POI positions (rows of `pois`), in parallel over the points (TBB); refused naming
// pois when they would hold more than limits::kMaxWorkBytes (volume_bytes each).
std::vector<VisibilityVolume> visibility_volumes(const VisibilityScene& scene, const Points3& pois,
                                                 double d_max,
                                                 std::optional<std::pair<double, double>> altitude_band = std::nullopt,
                                                 double resolution_deg = kDefaultResolutionDeg, bool with_mesh = true);
// Where one VV's time and rays go (for benchmarks): seconds per phase and ray counts.
struct VolumeCost {
  double bounds_s = 0.0;  // per-column bounds of the rays that can hit an obstacle
  double trace_s = 0.0;   // corner rays (their first hits from the triangles' footprints)
  double refine_s = 0.0;  // locating the jumps of r (more rays) and refining the mesh there
  double mesh_s = 0.0;    // writing the mesh
  double volume_s = 0.0;  // summing its volume (with_mesh = false: the volume pass, no mesh_s)
  // refine_s of a star VV (the POI in its band) by stage: the jump candidates (live corners, the
  // search over the grid's edges, the edge map), the first pass over them (the grid edges' rays),
  // the second (the split edges' new edges), confirming the jumps (with the complex slots' pieces,
  // which the mesh reuses) and untwisting the walls.
  double candidates_s = 0.0, first_pass_s = 0.0, second_pass_s = 0.0, untwist_s = 0.0;
  // mesh_s of a star VV by stage: numbering the vertices and counting the faces per slot, the
  // vertices, the faces with the volume.
  double count_s = 0.0, vertices_s = 0.0, fill_s = 0.0;
  std::size_t rays_traced = 0;   // corner rays handed to Embree (grid rows that are no mesh rows)
  std::size_t rays_skipped = 0;  // corner rays decided without it (the triangle tests, the bounds)
  std::size_t corner_tests = 0;  // (corner direction, obstacle triangle) tests
  std::size_t refine_rays = 0;   // rays traced while refining (Embree)
  // Refining rays decided without Embree: a ray just before an occluder's edge lies inside its cone
  // and meets it at its plane (beyond the paper, issue 35).
  std::size_t refine_predicted = 0;
  // With check_predicted (each is traced as well, and counted in refine_rays; the VV keeps the
  // predicted value): how many disagree with Embree by more than 0.1 % in their visible distance,
  // and the largest |predicted / traced - 1|. They disagree where the ray grazes the occluder's
  // edge closer than Embree's float test resolves (2 of 42.6k in bench/visibility_bench.py).
  std::size_t predicted_misses = 0;
  double predicted_error = 0.0;
  // Seconds handing rays to Embree (rtcIntersect1M, with packing the 64-ray batches and reading the
  // hits): wall time per thread, summed over threads; within trace_s + refine_s when parallel = false.
  double embree_s = 0.0;
};
// visibility_volume, filling `cost`; parallel = false computes it on the calling thread only;
// check_predicted also traces the refining rays it predicts (see VolumeCost::predicted_error).
VisibilityVolume visibility_volume_with_cost(const VisibilityScene& scene, const Vec3& g, double d_max,
                                             std::optional<std::pair<double, double>> altitude_band,
                                             double resolution_deg, VolumeCost& cost, bool parallel = true,
                                             bool check_predicted = false, bool with_mesh = true);
// Line of sight for segment pairs, building a scene for this call.
std::vector<bool> line_of_sight(const Environment& env, const Points3& a, const Points3& b);

// Volume enclosed by a closed, consistently oriented triangle mesh (divergence theorem).
double mesh_volume(const TriangleMesh& mesh);

// ---------------------------------------------------------------------------------------------
// VV files for the on-disk cache: magic "VISTRKVV", uint32 format version, then little-endian
// int32 / uint64 / IEEE doubles (poi, d_max, band, grid, near, far, mesh, volume, mesh rows and
// triangle faces) and a 64-bit
// checksum of everything before it. Bump the version whenever the layout or the output of
// visibility_volume changes, so stale cache files miss instead of being reused.
// Version 4: near/far per grid corner (version 3 had them per cell, on rays of their own).
// Version 5: the same layout; the walls at the jumps are aimed at the occluder's edge (issue 35).
// Version 6: the same layout; edges from the ground to a wall are split at the building's foot.
// Versions 4 and 5 are still read as they are; the cache's keys name the current version, so a
// cache of older files misses and recomputes.
inline constexpr std::uint32_t kVolumeFileVersion = 6;
inline constexpr std::uint32_t kOldestReadableVolumeFileVersion = 4;

// Writes `vv` to `path` through a temporary file in the same folder renamed over `path`, so
// readers see the old file or the whole new one, never half a file. Error naming the path when
// it cannot be written.
void write_volume_file(const VisibilityVolume& vv, const std::string& path);
// The VV stored in `path`; nullopt when the file does not exist; Error naming the path when it
// is unreadable, truncated, corrupt (checksum) or of another format version.
std::optional<VisibilityVolume> read_volume_file(const std::string& path);

// Error naming `where` and the field when a VV (from a file, or built by hand) is not one
// visibility_volume could have made: coordinates and d_max within range, a grid from
// DirectionGrid::from_resolution, intervals within [0, d_max], mesh indices in range, a volume
// within the ball of radius d_max, and a consistent record of the mesh rows. read_volume_file
// applies it to every file.
void validate_volume(const VisibilityVolume& vv, const std::string& where = "vv");

// Stable 64-bit key (FNV-1a over the exact bits, independent of the host) of a VV's inputs:
// environment fingerprint, g, d_max, band, resolution and kVolumeFileVersion.
std::uint64_t volume_cache_key(std::uint64_t environment_fingerprint, const Vec3& g, double d_max,
                               const std::optional<std::pair<double, double>>& altitude_band,
                               double resolution_deg);
// "vv-<16 lower-case hex digits>.bin".
std::string volume_cache_file_name(std::uint64_t key);

// ---------------------------------------------------------------------------------------------
// VV caches: in memory (by POI position) and on disk (one VV file per input key).

using VolumePtr = std::shared_ptr<const VisibilityVolume>;
// The VV at a POI position. Called from several threads at once: must be thread-safe.
using VolumeFunction = std::function<VolumePtr(const Vec3& poi)>;
// Thread-safe memo of VVs by POI position, to reuse VVs across calls (e.g. several spacings).
class VolumeCache {
 public:
  explicit VolumeCache(VolumeFunction compute);
  // The VV at g (computed once per position, to the micrometre). `computed` is set when it was new.
  VolumePtr at(const Vec3& g, bool* computed = nullptr);
  std::size_t size() const;

 private:
  struct State;
  std::shared_ptr<State> state_;
};

// VVs on disk, one file per input (volume_cache_key) in `folder`, so a second run with the same
// environment, POI positions and parameters computes nothing. A missing, corrupt or stale file
// is a miss: the VV is computed and the file (re)written atomically. Copies share the counters.
class DiskVolumeCache {
 public:
  // Creates the folder when missing; Error naming cache_dir when it cannot be created or written.
  DiskVolumeCache(std::string folder, std::uint64_t environment_fingerprint, double d_max,
                  std::optional<std::pair<double, double>> altitude_band, double resolution_deg);
  // `compute` behind the disk: thread-safe when `compute` is.
  VolumeFunction wrap(VolumeFunction compute) const;
  std::string path(const Vec3& poi) const;   // the file of the VV at g
  const std::string& folder() const;
  std::size_t hits() const;    // VVs read from disk
  std::size_t misses() const;  // VVs computed (and written)

 private:
  struct State;
  std::shared_ptr<State> state_;
};

}  // namespace vistrack
