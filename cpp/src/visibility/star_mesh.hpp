// The mesh of a VV whose POI lies in the altitude band (private to the library); see star_mesh.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "visibility/radial_mesh.hpp"
#include "visibility/trace.hpp"

namespace vistrack::detail {

// An edge of the mesh's triangulation of the sphere (samples u < w: the grid's corners, then the
// points where edges were split) across which r jumps, bracketed by aimed rays or bisection: the ray at
// lambda_lo of the way from u to w is on u's side of the jump, the ray at lambda_hi on w's side.
struct Jump {
  int u = 0;
  int w = 0;
  int slot = 0;    // a triangle slot of the sphere grid holding the edge (its azimuth column)
  int edge = -1;   // an edge of the grid: its index in `slot`; else -1 (made by a split)
  int other = -1;  // the slot on the edge's other side (-1 for an edge inside a slot)
  double lambda_lo = 0.0;
  double lambda_hi = 1.0;
  double lo_far = 0.0;  // r just on u's side, and the surface that ends it
  double hi_far = 0.0;
  Surface lo_surface = Surface::radial;
  Surface hi_surface = Surface::radial;
  std::uint32_t lo_triangle = ~std::uint32_t{0};  // the obstacle triangle that ends r there, if any
  std::uint32_t hi_triangle = ~std::uint32_t{0};
  int aimed = 0;  // probes aimed at the occluder's edge so far
  bool confirmed = false;
  int split = -1;   // the sample where the edge was split (it held two jumps, or a building's foot)
  int vertex = -1;  // the two mesh vertices on the jump's ray (vertex: u's side, vertex + 1: w's)
  double gap() const { return hi_far > lo_far ? hi_far - lo_far : lo_far - hi_far; }
};

// A triangle of a complex slot (the slot itself, or a part of it cut by split edges): its samples
// in outward order, and the Jump on each edge (edge e from corners[e] to corners[e + 1]; -1: none).
struct SlotPiece {
  std::array<int, 3> corners;
  std::array<std::int32_t, 3> jump;
};

// Open-addressing map from an edge (two sample ids) to its Jump.
class EdgeMap {
 public:
  static std::uint64_t key(int a, int b) {
    const auto lo = static_cast<std::uint32_t>(a < b ? a : b), hi = static_cast<std::uint32_t>(a < b ? b : a);
    return (static_cast<std::uint64_t>(hi) << 32) | lo;
  }
  void reset(std::size_t expected);
  void insert(std::uint64_t k, std::int32_t value);
  std::int32_t find(std::uint64_t k) const;  // -1 when absent
  bool empty() const { return size_ == 0; }

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
  std::vector<std::uint64_t> keys_;
  std::vector<std::int32_t> values_;
  std::size_t mask_ = 0;
  std::size_t size_ = 0;
};

// The ray where an edge is split (its middle, or a building's foot): its direction, r there and the
// surface (and triangle) that ends it.
struct Middle {
  Vec3 direction = Vec3::Zero();
  double far = 0.0;
  Surface surface = Surface::radial;
  std::uint32_t triangle = ~std::uint32_t{0};
};

// One block of jumps being located: its active jumps and this round's rays (directions, lambdas,
// what each found, and whether it was aimed at a building's foot).
struct JumpBlock {
  std::vector<std::int32_t> active;
  std::vector<Vec3> direction;
  std::vector<double> probe, mid_far;
  std::vector<Surface> mid_surface;
  std::vector<std::uint32_t> mid_triangle;
  std::vector<std::uint8_t> kink_ray;
  std::vector<std::int32_t> traced;  // the probes handed to Embree (the others are predicted)
  std::vector<std::uint8_t> predicted;  // per probe: predicted (traced only when checked)
  std::size_t predictions = 0;          // over the block's rounds
  std::size_t prediction_misses = 0;    // checked: predicted and traced far differ by > 0.1 %
  double prediction_error = 0.0;        // checked: the largest |predicted / traced - 1| of far
};

// Buffers of one star mesh, kept between VVs so that a batch allocates them once.
struct StarMeshScratch {
  std::vector<std::uint8_t> alive, slot_flags, candidate;
  std::vector<std::vector<Jump>> chunk_jumps;        // the jump candidates found per chunk of rows
  std::vector<std::vector<double>> chunk_gap;  // per chunk of rows: which quads have a gap (0 or 1)
  std::vector<Jump> jumps;
  EdgeMap edges;
  // The ray where each jump of a first pass splits its edge (numbered after the pass).
  std::vector<Middle> middle;
  std::vector<JumpBlock> blocks;  // one per block of jumps (each block is located by one thread)
  // Samples past the corners: the points where edges were split.
  std::vector<Vec3> extra_direction;
  std::vector<double> extra_far;
  std::vector<Surface> extra_surface;
  std::vector<std::uint32_t> extra_triangle;
  std::vector<std::int32_t> extra_parent;  // the split edge's Jump
  std::vector<std::int32_t> extra_vertex;
  std::vector<std::int32_t> complex_slots;   // slots with a split or a jump, ascending
  std::vector<SlotPiece> slot_pieces;       // the complex slots' pieces, in slot order
  std::vector<std::int32_t> piece_of;        // per complex slot: its first piece << 3 | their count
  std::vector<std::int32_t> twist_visit, twist_next;  // slots the twist check visits in a pass, and the next's
  std::vector<std::int32_t> corner_vertex;   // mesh vertex of each used corner, else -1
  bool corner_identity = false;              // corner_vertex holds v -> v (every corner used)
  std::vector<std::int32_t> row_centroid;    // first centroid vertex of each sphere row
  std::vector<std::uint8_t> plain_row;       // sphere rows of plain slots only
  std::vector<std::uint8_t> row_border;      // sphere rows with a border fan to g
  std::vector<std::int32_t> row_faces;       // faces before each sphere row (rows counted in parallel)
  std::vector<double> row_volume;
  std::vector<int> pole_ring;
};

// The closed mesh of a VV whose POI lies in the band (near = 0 along every ray): the radial
// surface r = far over the live corners (far[v], surface[v] per corner of `sphere`, and the
// obstacle triangle triangle[v] that ended the corner's ray), with radial walls at the jumps of r
// located with more rays (aimed at the edge of the occluding triangle, else by bisection), and the grid's triangles split
// where an edge holds two jumps. Sets vv.mesh, vv.volume and vv.mesh_triangle_faces (the faces
// built over each triangle slot of `sphere`); without `with_mesh`, only vv.volume, the same value.
// check_predicted traces the rays it predicts too, into cost's predicted_misses and
// predicted_error (the mesh keeps the predictions).
void build_star_mesh(const Setup& s, const SphereGrid& sphere, const Directions& dirs, const std::vector<double>& far,
                     const std::vector<Surface>& surface, const std::vector<std::uint32_t>& triangle,
                     const TraceContext& tracer, StarMeshScratch& scratch, VisibilityVolume& vv, bool with_mesh = true,
                     VolumeCost* cost = nullptr, bool check_predicted = false);

}  // namespace vistrack::detail
