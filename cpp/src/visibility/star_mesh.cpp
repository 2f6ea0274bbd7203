// The mesh of a VV whose POI lies in the altitude band (near = 0 on every ray): the radial
// surface r = far over the sphere of grid corners, with radial walls where r jumps.
//
// Why walls: at a silhouette (an occluder in front of what lies behind it) r(w) jumps from r1 to
// r2. A mesh edge that crosses the jump and interpolates r linearly holds
// (r1 + r2)(r1 - r2)^2 / 4 less of r^3 than the step does, so a plain corner mesh of a Charlotte
// VV holds 0.2-2.4 % less volume than the per-direction intervals. Each such edge gets more rays
// until the jump is pinned to at most 1/2^kBisections of the edge, and the triangles on both sides
// share a radial wall there. The rays are aimed where they can be: the nearer side's ray ended on
// an obstacle triangle, and the jump sits where the edge's rays leave that triangle's cone from g
// (in closed form, cone_exit), so a ray just past that point and one just before it pin the jump
// to 2 kAimStep of the edge (a ray past it that still meets the occluder, on its next triangle,
// aims again from there); otherwise the bracket is bisected (beyond the paper, issue 35: 6.6k
// rays per 1-degree Charlotte VV instead of 10.2k). A bisected jump between two radial surfaces stops earlier once the volume
// its bracket can misplace, |r_lo^3 - r_hi^3| / 3 per unit solid angle times the bracket's width,
// is no more than the largest possible jump's (0 to d_max) after all rounds: a jump between two
// near surfaces holds little volume and needs fewer rays (a fifth fewer on a Charlotte VV).
//
// Refinement: an edge whose middle ray differs from both ends holds two jumps (a gap between two
// buildings, a thin tower in front of the sky; 0.01-0.03 % of a Charlotte VV went missing there),
// and one wall can hold only one. Such an edge is split at its middle ray, which becomes a vertex,
// the triangles on both sides are split with it (into at most four pieces each: every piece stays
// inside its triangle slot, whose faces the radial XOR overlaps), and the new edges get walls in
// turn. An edge from the ground to a building's wall is split where it crosses the building's
// foot instead (beyond the paper, issue 35): r = min(ground, wall) bends there, and the edge's
// straight interpolation cut the corner between ground and wall (around a box's foot seen from
// 0.5 m the mesh held 17 % too little; 0.02-0.04 % of paper_small's Charlotte VVs went missing
// there, bench/vv_error_sources.py). The foot's place on the edge is closed-form (the wall
// triangle's plane meets the ground plane on a line) and one ray there confirms that nothing
// stands in front of it; that ray replaces the edge's middle ray.
//
// Cost: most slots are plain (three live corners, no jump): they are written in one pass over
// the rows with their volume r_a r_b r_c det(d_a, d_b, d_c) / 6 (the determinant depends on the
// row only); the few slots with walls or splits go through the general path. The mesh is written
// in two passes over the rows (count, then fill at the counted offsets), so rows can be written in
// parallel and the output does not depend on the number of threads.
#include "visibility/star_mesh.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>

namespace vistrack::detail {

namespace {

constexpr double kJumpCandidate = 0.1;   // relative gap |r_u - r_w| / max(r_u, r_w) worth bisecting
constexpr double kJumpConfirmed = 0.05;  // relative gap still left after bisection: a jump
constexpr int kBisections = 6;
const double kSettledStake = std::ldexp(1.0, -kBisections);  // see settled() in build_star_mesh
const double kBracketWidth = std::ldexp(1.0, -kBisections);  // a jump is located once its bracket is this narrow
// Aimed probes: a ray this far (in lambda) past the edge of the occluding triangle's cone, then
// one as far before it, pin the jump to a bracket of 2 kAimStep with two rays (1e-4 of a 1-degree
// edge: 1 mm at 400 m; smaller steps change no volume in bench/accuracy.py's fourth digit).
const double kAimStep = std::ldexp(1.0, -12);
constexpr int kMaxAimed = 4;  // per jump (each miss walks to the next triangle of the occluder)
constexpr std::uint32_t kNoTriangle = EmbreeScene::kNoTriangle;
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr std::size_t kJumpBlock = 128;  // jumps located together (two chunks of rays per early round)
constexpr int kPendingSplit = -2;        // Jump::split of an edge to split, before it is numbered

// slot_flags bits
constexpr std::uint8_t kLive = 1;     // all three corners see something
constexpr std::uint8_t kComplex = 2;  // a split edge or a confirmed jump: the general path
constexpr int kSplitShift = 2;        // bits 2..4: edge e of the slot is split

bool is_plane(Surface s) { return s != Surface::radial; }

// r differs enough between two rays to look for a jump between them: the one criterion of the
// vectorized pre-filter (mark_gaps) and the exact test (differ).
inline bool gap_between(double x, double y) { return std::abs(x - y) > kJumpCandidate * std::max(x, y); }

// The pre-filter of one row of quads between the poles, without branches (most quads have no gap):
// gap[j] = 1 (else 0) when quad j (lower corners lo[j], lo[j + 1], upper hi[j], hi[j + 1]) has a
// gap on its bottom, left or diagonal edge, for j < count. A function of its own with restrict
// pointers and doubles for flags, so that GCC vectorizes it (a byte flag in the lambda kept it
// scalar: the iterations could not be counted, and no vector holds doubles and bytes alike).
void mark_gaps(const double* __restrict lo, const double* __restrict hi, int count, double* __restrict gap) {
  for (int j = 0; j < count; ++j) {
    const double a = lo[j], b = lo[j + 1], c = hi[j], d = hi[j + 1];
    const bool any = gap_between(a, d) | gap_between(a, b) | gap_between(a, c);
    gap[j] = any ? 1.0 : 0.0;
  }
}

// r differs enough between two rays to look for a jump between them (two hits on one plane are
// joined exactly by the flat triangle between them).
bool differ(double a, Surface sa, double b, Surface sb) {
  return gap_between(a, b) && !(sa == sb && is_plane(sa));
}

// Distance along unit d to the surface that ended an interval measured on a nearby ray: the exact
// plane distance for the ground and the band caps, the measured distance otherwise.
double distance_on(const Setup& s, double far, Surface surface, const Vec3& d) {
  double z = 0.0;
  if (surface == Surface::ground) z = s.ground;
  else if (surface == Surface::band_low) z = s.low;
  else if (surface == Surface::band_high) z = s.high;
  else return far;
  const double t = (z - s.g.z()) / d.z();
  return std::isfinite(t) && t > 0.0 ? std::min(t, s.d_max) : far;
}

double six_volume_of(const Vec3& g, const Vec3& a, const Vec3& b, const Vec3& c) {
  return (a - g).dot((b - g).cross(c - g));
}

using Triangle = std::array<int, 3>;

// Where the rays d(lambda) = (1 - lambda) a + lambda b from g leave the cone from g over the
// triangle t (9 floats, g's frame offset by g_local), moving from lambda `from` (inside it: the
// ray there hit t) toward `to`: the first lambda strictly between them on one of its edges'
// planes through g; NaN when the rays stay inside (or `from` is not inside, by rounding).
double cone_exit(const float* t, const Vec3& g_local, const Vec3& a, const Vec3& b, double from, double to) {
  const std::array<Vec3, 3> p = {Vec3(t[0], t[1], t[2]) - g_local, Vec3(t[3], t[4], t[5]) - g_local,
                                 Vec3(t[6], t[7], t[8]) - g_local};
  double exit = std::numeric_limits<double>::quiet_NaN(), nearest = 1.0;
  for (std::size_t e = 0; e < 3; ++e) {
    Vec3 n = p[e].cross(p[(e + 1) % 3]);
    const double third = n.dot(p[(e + 2) % 3]);
    if (!(std::abs(third) > 1e-12 * n.norm() * p[(e + 2) % 3].norm())) return std::numeric_limits<double>::quiet_NaN();
    if (third < 0.0) n = -n;  // n . d >= 0 inside the cone
    const double fa = n.dot(a), slope = n.dot(b) - fa;
    if (fa + from * slope < -1e-9 * n.norm()) return std::numeric_limits<double>::quiet_NaN();
    if ((to - from) * slope >= 0.0) continue;  // this edge's plane does not come nearer
    const double along = (-fa / slope - from) / (to - from);  // 0 at from, 1 at to
    if (along > 0.0 && along < nearest) nearest = along, exit = from + along * (to - from);
  }
  return exit;
}

// The plane of triangle t (9 floats, g's frame offset by g_local) relative to g: the points x
// (from g) with normal . x = offset; a ray along d meets it at offset / normal . d.
struct TrianglePlane {
  Vec3 normal;
  double offset = 0.0;
};

TrianglePlane plane_of(const float* t, const Vec3& g_local) {
  const Vec3 p0(t[0], t[1], t[2]), p1(t[3], t[4], t[5]), p2(t[6], t[7], t[8]);
  const Vec3 n = (p1 - p0).cross(p2 - p0);
  return {n, n.dot(p0 - g_local)};
}

// The triangles of a slot with corners c (outward order; edge e runs from c[e] to c[e + 1]) and
// the split points m[e] of its split edges (bit e of `split`), in outward order: at most four.
int pieces(const Triangle& c, int split, const Triangle& m, std::array<Triangle, 4>& out) {
  switch (split) {
    case 0:
      out[0] = c;
      return 1;
    case 1:
    case 2:
    case 4: {
      const int e = split == 1 ? 0 : (split == 2 ? 1 : 2);
      const int a = c[static_cast<std::size_t>(e)], b = c[static_cast<std::size_t>((e + 1) % 3)];
      const int d = c[static_cast<std::size_t>((e + 2) % 3)], x = m[static_cast<std::size_t>(e)];
      out[0] = {a, x, d};
      out[1] = {x, b, d};
      return 2;
    }
    case 7:
      out[0] = {c[0], m[0], m[2]};
      out[1] = {m[0], c[1], m[1]};
      out[2] = {m[2], m[1], c[2]};
      out[3] = {m[0], m[1], m[2]};
      return 4;
    default: {
      // Two split edges, k + 1 and k + 2 (meeting at corner k + 2); edge k whole.
      const int k = split == 6 ? 0 : (split == 5 ? 1 : 2);
      const int a = c[static_cast<std::size_t>(k)], b = c[static_cast<std::size_t>((k + 1) % 3)];
      const int d = c[static_cast<std::size_t>((k + 2) % 3)];
      const int m1 = m[static_cast<std::size_t>((k + 1) % 3)], m2 = m[static_cast<std::size_t>((k + 2) % 3)];
      out[0] = {m1, d, m2};
      out[1] = {a, b, m1};
      out[2] = {a, m1, m2};
      return 3;
    }
  }
}

}  // namespace

void EdgeMap::reset(std::size_t expected) {
  std::size_t capacity = 64;
  while (capacity < 2 * expected) capacity *= 2;
  keys_.assign(capacity, kEmpty);
  values_.resize(capacity);
  mask_ = capacity - 1;
  size_ = 0;
}

void EdgeMap::insert(std::uint64_t k, std::int32_t value) {
  if (2 * (size_ + 1) > keys_.size()) {
    std::vector<std::uint64_t> old_keys = std::move(keys_);
    std::vector<std::int32_t> old_values = std::move(values_);
    reset(size_ + 1);
    for (std::size_t i = 0; i < old_keys.size(); ++i)
      if (old_keys[i] != kEmpty) insert(old_keys[i], old_values[i]);
  }
  std::size_t i = static_cast<std::size_t>((k * 0x9E3779B97F4A7C15ull) >> 20) & mask_;
  while (keys_[i] != kEmpty && keys_[i] != k) i = (i + 1) & mask_;
  if (keys_[i] == kEmpty) ++size_;
  keys_[i] = k;
  values_[i] = value;
}

std::int32_t EdgeMap::find(std::uint64_t k) const {
  if (size_ == 0) return -1;
  std::size_t i = static_cast<std::size_t>((k * 0x9E3779B97F4A7C15ull) >> 20) & mask_;
  while (keys_[i] != kEmpty) {
    if (keys_[i] == k) return values_[i];
    i = (i + 1) & mask_;
  }
  return -1;
}

void build_star_mesh(const Setup& s, const SphereGrid& sphere, const Directions& dirs, const std::vector<double>& far,
                     const std::vector<Surface>& surface, const std::vector<std::uint32_t>& triangle,
                     const TraceContext& tracer_in, StarMeshScratch& sc, VisibilityVolume& vv, bool with_mesh,
                     VolumeCost* cost, bool check_predicted) {
  PhaseTimer refine_timer(cost ? &cost->refine_s : nullptr);
  PhaseTimer candidates_timer(cost ? &cost->candidates_s : nullptr);
  RayCounts refine_counts;
  refine_counts.timed = cost != nullptr;
  TraceContext tracer = tracer_in;
  tracer.counts = &refine_counts;
  const int nv = sphere.num_vertices();
  const int ne = sphere.ne;
  const int na = sphere.na;
  const int nt = sphere.num_triangle_slots();
  const double alive_gap = 1e-6 * std::max(1.0, s.d_max);

  // Samples: the corners, then the points where edges were split.
  sc.extra_direction.clear();
  sc.extra_far.clear();
  sc.extra_surface.clear();
  sc.extra_triangle.clear();
  sc.extra_parent.clear();
  auto sample_far = [&](int v) { return v < nv ? far[v] : sc.extra_far[static_cast<std::size_t>(v - nv)]; };
  auto sample_surface = [&](int v) { return v < nv ? surface[v] : sc.extra_surface[static_cast<std::size_t>(v - nv)]; };
  auto sample_direction = [&](int v) { return v < nv ? dirs.corner(v) : sc.extra_direction[static_cast<std::size_t>(v - nv)]; };
  auto sample_triangle = [&](int v) { return v < nv ? triangle[v] : sc.extra_triangle[static_cast<std::size_t>(v - nv)]; };
  // Two samples' distances differ enough for a jump between them (every jump's edge passed this).
  auto samples_differ = [&](int a, int b) { return differ(sample_far(a), sample_surface(a), sample_far(b), sample_surface(b)); };
  auto slot_corners = [&](int t) { return sphere.corners(t); };

  // Live corners (something visible) and live slots (all three corners live).
  auto& alive = sc.alive;
  alive.resize(static_cast<std::size_t>(nv));
  int dead = 0;
  {
    // Locals: a byte store could otherwise alias the vectors' own pointers and nv (which lambdas
    // capture by reference), reloaded per corner.
    const double* r = far.data();
    std::uint8_t* live_corner = alive.data();
    const int corners = nv;
    for (int v = 0; v < corners; ++v) {
      const std::uint8_t a = r[v] > alive_gap ? 1 : 0;
      live_corner[v] = a;
      dead += 1 - a;
    }
  }
  const bool all_alive = dead == 0;
  auto& flags = sc.slot_flags;
  auto& candidate = sc.candidate;
  flags.resize(static_cast<std::size_t>(nt));
  candidate.assign(static_cast<std::size_t>(nv), 0);
  if (all_alive) {
    std::fill(flags.begin(), flags.end(), kLive);
    for (int j = 0; j < na; ++j) {
      flags[static_cast<std::size_t>(2 * j)] = 0;                         // no Ta at the south pole
      flags[static_cast<std::size_t>(2 * ((ne - 1) * na + j) + 1)] = 0;  // no Tb at the north pole
    }
  } else {
    // The live corners of dead slots: only those can be pinched, and only slots with two of them
    // can border the dead region.
    auto update_slots = [&]() {
      std::fill(candidate.begin(), candidate.end(), 0);
      sphere.for_each_quad([&](int i, int t, int v00, int v01, int v10, int v11) {
        flags[t] = i >= 1 && alive[v00] && alive[v01] && alive[v11] ? kLive : 0;
        flags[t + 1] = i <= ne - 2 && alive[v00] && alive[v11] && alive[v10] ? kLive : 0;
        if (i >= 1 && !flags[t]) candidate[v00] |= alive[v00], candidate[v01] |= alive[v01], candidate[v11] |= alive[v11];
        if (i <= ne - 2 && !flags[t + 1])
          candidate[v00] |= alive[v00], candidate[v11] |= alive[v11], candidate[v10] |= alive[v10];
      });
    };
    update_slots();
    // A corner where the visible region touches itself (two separate fans of live slots) would
    // be a non-manifold vertex: drop it, until there is none.
    for (int round = 0; round < 64; ++round) {
      bool changed = false;
      for (int v = 0; v < nv; ++v) {
        if (!candidate[v]) continue;
        std::array<int, 6> local{};
        const int n = sphere.ring(v, local, sc.pole_ring);
        const int* ring = n < 0 ? sc.pole_ring.data() : local.data();
        const int size = n < 0 ? static_cast<int>(sc.pole_ring.size()) : n;
        int runs = 0;
        for (int k = 0; k < size; ++k)
          if (flags[ring[k]] && !flags[ring[(k + size - 1) % size]]) ++runs;
        if (runs >= 2) {
          alive[v] = 0;
          changed = true;
        }
      }
      if (!changed) break;
      update_slots();
    }
  }
  auto live = [&](int t) { return (flags[static_cast<std::size_t>(t)] & kLive) != 0; };

  // Jump candidates on the grid's edges between live slots. Each edge is examined once per quad
  // that owns it (its bottom, left and diagonal edge) and recorded from the slot that runs along
  // it from the lower to the higher corner.
  auto& jumps = sc.jumps;
  auto& edges = sc.edges;
  jumps.clear();
  // The rows in fixed chunks (in parallel when the VV is spread over the threads), each with its
  // own list, joined in row order: the same jumps in the same order either way.
  constexpr int kRowChunk = 16;
  const int chunks = (ne + kRowChunk - 1) / kRowChunk;
  sc.chunk_jumps.resize(static_cast<std::size_t>(chunks));
  sc.chunk_gap.resize(static_cast<std::size_t>(chunks));
  for_each_index(tracer.parallel, chunks, [&](int chunk) {
    std::vector<Jump>& found = sc.chunk_jumps[static_cast<std::size_t>(chunk)];
    found.clear();
    auto consider = [&](int t, int e, int p, int q) {
      if (p > q || !live(t)) return;
      if (!all_alive && !live(sphere.neighbour(t, e))) return;
      Jump jump;
      jump.u = p;
      jump.w = q;
      jump.slot = t;
      jump.edge = e;
      jump.lo_far = far[p];
      jump.lo_surface = surface[p];
      jump.hi_far = far[q];
      jump.hi_surface = surface[q];
      jump.lo_triangle = triangle[p];
      jump.hi_triangle = triangle[q];
      found.push_back(jump);
    };
    // A cheap test on r first (raw pointers: the compiler cannot keep vector data in registers
    // across the byte-sized flag writes); the surfaces only when it passes.
    const double* r = far.data();
    const Surface* sf = surface.data();
    auto gap = [&](int p, int q) { return gap_between(r[p], r[q]); };
    auto plane_pair = [&](int p, int q) { return sf[p] == sf[q] && is_plane(sf[p]); };
    // Rows between the poles first test every quad without branches (mark_gaps), then look at the
    // few that have a gap.
    std::vector<double>& any_gap = sc.chunk_gap[static_cast<std::size_t>(chunk)];
    any_gap.resize(static_cast<std::size_t>(na));
    for (int i = chunk * kRowChunk; i < std::min(ne, (chunk + 1) * kRowChunk); ++i) {
      const SphereGrid::QuadRow row = sphere.quad_row(i);
      const bool inner = !row.south && !row.north;
      if (inner) {
        mark_gaps(r + row.lo, r + row.hi, na - 1, any_gap.data());
        any_gap[static_cast<std::size_t>(na - 1)] = 1.0;  // the wrapping quad: tested below
      }
      for (int j = 0; j < na; ++j) {
        if (inner && any_gap[static_cast<std::size_t>(j)] == 0.0) continue;
        const auto [v00, v01, v10, v11] = row.quad(j);
        const bool diagonal = gap(v00, v11), bottom = !row.south && gap(v00, v01), left = gap(v00, v10);
        if (!(diagonal || bottom || left)) continue;
        const int t = 2 * (i * na + j);
        if (diagonal && !plane_pair(v00, v11)) consider(t, 2, v11, v00), consider(t + 1, 0, v00, v11);
        if (bottom && !plane_pair(v00, v01)) consider(t, 0, v00, v01), consider(sphere.tb(i - 1, j), 1, v01, v00);
        if (left && !plane_pair(v00, v10)) consider(t + 1, 2, v10, v00), consider(sphere.ta(i, j - 1), 1, v00, v10);
      }
    }
  });
  for (const std::vector<Jump>& found : sc.chunk_jumps) jumps.insert(jumps.end(), found.begin(), found.end());
  // Sized once for these and the split edges' jumps to come (8 % as many on Charlotte, under a
  // fifth), so that the map is not rebuilt as it grows.
  edges.reset(jumps.size() + jumps.size() / 4 + 64);
  for (std::size_t k = 0; k < jumps.size(); ++k) {
    jumps[k].other = sphere.neighbour(jumps[k].slot, jumps[k].edge);
    edges.insert(EdgeMap::key(jumps[k].u, jumps[k].w), static_cast<std::int32_t>(k));
  }

  // Locating the jumps from `first` on: rounds of one ray per bracket (aimed, see probe_of, else
  // at its middle), each keeping the part of the bracket with the larger gap (a jump keeps its
  // gap, a smooth but steep r(w) loses half of it per bisecting round), until the bracket is
  // kBracketWidth wide. A bracket whose gap falls to the confirmation level is smooth: it leaves the
  // rounds early, and so does a settled one (little volume at stake). Both ends on one plane is no
  // jump: the ground seen at grazing angles changes fast but stays flat. With allow_split, an edge
  // whose middle ray differs from both ends is split there instead.
  auto open = [&](const Jump& jump) {
    return jump.split < 0 && jump.lo_far > alive_gap && jump.hi_far > alive_gap &&
           jump.gap() > kJumpConfirmed * std::max(jump.lo_far, jump.hi_far) &&
           !(jump.lo_surface == jump.hi_surface && is_plane(jump.lo_surface));
  };
  // A bracket is settled when it can misplace no more volume than the largest jump's after
  // kBisections rounds. Only between two radial surfaces, and only when the wall's vertices stay
  // within reach at its ray: a wide bracket with a plane (ground, band cap) on one side would put
  // the other side's vertex beyond that plane, through the plane's exact faces.
  auto settled = [&](const Jump& jump) {
    if (jump.lo_surface != Surface::radial || jump.hi_surface != Surface::radial) return false;
    const double a = jump.lo_far / s.d_max, b = jump.hi_far / s.d_max;
    if (std::abs(a * a * a - b * b * b) * (jump.lambda_hi - jump.lambda_lo) > kSettledStake) return false;
    const double lambda = 0.5 * (jump.lambda_lo + jump.lambda_hi);
    const Vec3 d = ((1.0 - lambda) * sample_direction(jump.u) + lambda * sample_direction(jump.w)).normalized();
    return std::max(jump.lo_far, jump.hi_far) <= visible_far_bound(s, d.z());
  };
  // Where to probe a bracket: aimed at the silhouette when the nearer side's ray ended on an
  // obstacle triangle whose cone the rays leave inside the bracket (the occluder's edge, seen from
  // g: a ray just past it, then one just before it), else the bracket's middle. An aimed ray that
  // still meets the occluder (its next triangle) narrows the bracket all the same and aims again
  // from there, at most kMaxAimed times.
  const Vec3 g_local = s.g - tracer.embree.origin;
  auto probe_of = [&](Jump& jump, std::uint32_t& predicted) {
    predicted = kNoTriangle;
    const double middle = 0.5 * (jump.lambda_lo + jump.lambda_hi);
    if (jump.aimed >= kMaxAimed) return middle;
    const bool lo_near = jump.lo_far <= jump.hi_far;
    const std::uint32_t occluder = lo_near ? jump.lo_triangle : jump.hi_triangle;
    if (occluder == kNoTriangle || (lo_near ? jump.lo_surface : jump.hi_surface) != Surface::radial) return middle;
    const double exit = cone_exit(tracer.embree.triangles.data() + 9 * static_cast<std::size_t>(occluder), g_local,
                                  sample_direction(jump.u), sample_direction(jump.w),
                                  lo_near ? jump.lambda_lo : jump.lambda_hi, lo_near ? jump.lambda_hi : jump.lambda_lo);
    if (!std::isfinite(exit)) return middle;
    const double step = lo_near ? kAimStep : -kAimStep;  // towards the far side
    auto inside = [&](double lambda) {
      return lambda > jump.lambda_lo + 0.5 * kAimStep && lambda < jump.lambda_hi - 0.5 * kAimStep;
    };
    const double probe = inside(exit + step) ? exit + step : (inside(exit - step) ? exit - step : middle);
    if (probe != middle) ++jump.aimed;
    // The ray just before the exit lies inside the occluder's cone (the rays from `from` to the exit
    // do: the inside of a cone is an interval of lambda): it meets the occluder, at its plane.
    if (probe == exit - step) predicted = occluder;
    return probe;
  };
  // The foot of a building seen from above the ground: an edge from a ray on the ground to one on
  // an obstacle triangle crosses, between them, the line where that triangle's plane meets the
  // ground, and r = min(ground, obstacle) has a concave kink there that the edge's linear
  // interpolation cuts. Where along the edge (lambda in (0, 1), from u), in closed form (the
  // ground point g + h v / v_z, v = (1 - lambda) d_u + lambda d_w, lies on the plane: linear in
  // lambda); NaN when it does not lie on the edge.
  const double height = s.ground - s.g.z();  // < 0: g above the ground
  auto kink_of = [&](const Jump& jump) {
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    const bool lo_ground = jump.lo_surface == Surface::ground, hi_ground = jump.hi_surface == Surface::ground;
    if (lo_ground == hi_ground || !(height < 0.0)) return kNaN;
    const std::uint32_t t = lo_ground ? jump.hi_triangle : jump.lo_triangle;
    if (t == kNoTriangle || (lo_ground ? jump.hi_surface : jump.lo_surface) != Surface::radial) return kNaN;
    const TrianglePlane plane = plane_of(tracer.embree.triangles.data() + 9 * static_cast<std::size_t>(t), g_local);
    const Vec3& n = plane.normal;
    const Vec3 a = sample_direction(jump.u), b = sample_direction(jump.w);
    const double c = -plane.offset;  // n . (g - p0)
    const double f0 = c * a.z() + height * n.dot(a), f1 = c * b.z() + height * n.dot(b);
    if (!(std::abs(f0 - f1) > 0.0)) return kNaN;
    const double lambda = f0 / (f0 - f1);
    if (!(lambda > kAimStep && lambda < 1.0 - kAimStep)) return kNaN;
    if (!((1.0 - lambda) * a.z() + lambda * b.z() < 0.0)) return kNaN;
    return lambda;
  };
  // The jumps are located in fixed blocks of kJumpBlock, each running all its rounds on its own
  // (in parallel when the VV is spread over the threads): a round's rays are traced in chunks of
  // one block's jumps, so the result does not depend on the number of threads. A first pass's
  // splits are numbered afterwards, in jump order.
  auto bisect = [&](std::size_t first, bool allow_split) {
    const std::size_t end = jumps.size();
    sc.middle.resize(end - first);
    auto run_block = [&](std::size_t begin, std::size_t stop, JumpBlock& block) {
      FlushDenormals flush;
      auto& [active, direction, probe, mid_far, mid_surface, mid_triangle, kink_ray, traced, predicted_ray, predictions,
             prediction_misses, prediction_error] = block;
      active.clear();
      for (std::size_t k = begin; k < stop; ++k) active.push_back(static_cast<std::int32_t>(k));
      for (int round = 0; round < kBisections + kMaxAimed && !active.empty(); ++round) {
        // The first round of a first pass probes the middles (or a building's foot): a middle ray unlike
        // both ends splits the edge.
        const bool middles = allow_split && round == 0;
        const std::size_t n = active.size();
        direction.resize(n);
        probe.resize(n);
        kink_ray.resize(n);
        mid_far.resize(n);
        mid_surface.resize(n);
        mid_triangle.resize(n);
        predicted_ray.assign(n, 0);
        traced.clear();
        for (std::size_t m = 0; m < n; ++m) {
          Jump& jump = jumps[static_cast<std::size_t>(active[m])];
          const double kink = middles ? kink_of(jump) : std::numeric_limits<double>::quiet_NaN();
          kink_ray[m] = std::isfinite(kink) ? 1 : 0;
          std::uint32_t predicted = kNoTriangle;
          const double lambda =
              kink_ray[m] ? kink : (middles ? 0.5 * (jump.lambda_lo + jump.lambda_hi) : probe_of(jump, predicted));
          probe[m] = lambda;
          direction[m] = ((1.0 - lambda) * sample_direction(jump.u) + lambda * sample_direction(jump.w)).normalized();
          if (predicted == kNoTriangle || check_predicted) traced.push_back(static_cast<std::int32_t>(m));
          if (predicted == kNoTriangle) continue;
          predicted_ray[m] = 1;
          ++predictions;
          // As a traced ray would store it: hits count up to the visible part's end.
          const TrianglePlane plane =
              plane_of(tracer.embree.triangles.data() + 9 * static_cast<std::size_t>(predicted), g_local);
          const double hit = plane.offset / plane.normal.dot(direction[m]);
          const bool within = hit <= visible_far_bound(s, direction[m].z()) * (1.0 + 1e-6);
          mid_far[m] = star_far(s, direction[m].z(), within ? hit : kInfinity, mid_surface[m]);
          mid_triangle[m] = within ? predicted : kNoTriangle;
        }
        trace_range(
            tracer, 0, traced.size(),
            [&](std::size_t start, std::size_t count, Vec3* d, int* column) {
              for (std::size_t k = 0; k < count; ++k) {
                const auto m = static_cast<std::size_t>(traced[start + k]);
                d[k] = direction[m];
                column[k] = (jumps[static_cast<std::size_t>(active[m])].slot / 2) % na;
              }
            },
            [&](std::size_t k, const Vec3& d, double hit, std::uint32_t hit_triangle) {
              const auto m = static_cast<std::size_t>(traced[k]);
              Surface traced_surface;
              const double traced_far = star_far(s, d.z(), hit, traced_surface);
              if (predicted_ray[m]) {  // checked only: the prediction stays
                const double error = std::abs(mid_far[m] / traced_far - 1.0);
                prediction_misses += error > 1e-3 ? 1 : 0;
                prediction_error = std::max(prediction_error, error);
                return;
              }
              mid_far[m] = traced_far;
              mid_surface[m] = traced_surface;
              mid_triangle[m] = hit_triangle;
            });
        std::size_t kept = 0;
        for (std::size_t m = 0; m < n; ++m) {
          Jump& jump = jumps[static_cast<std::size_t>(active[m])];
          const double mid = mid_far[m];
          if (kink_ray[m]) {
            // The ray meets the foot where the plane says (nothing in front of it): a vertex there.
            const double expected = height / direction[m].z();
            if (expected <= s.d_max && std::abs(mid - expected) <= 1e-3 * expected + 1e-3) {
              jump.split = kPendingSplit;
              sc.middle[static_cast<std::size_t>(active[m]) - first] = {direction[m], expected, Surface::ground, kNoTriangle};
              continue;
            }
          }
          if (middles && mid > alive_gap && differ(jump.lo_far, jump.lo_surface, mid, mid_surface[m]) &&
              differ(mid, mid_surface[m], jump.hi_far, jump.hi_surface)) {
            jump.split = kPendingSplit;
            sc.middle[static_cast<std::size_t>(active[m]) - first] = {direction[m], mid, mid_surface[m], mid_triangle[m]};
            continue;
          }
          if (std::abs(mid - jump.lo_far) >= std::abs(jump.hi_far - mid)) {
            jump.lambda_hi = probe[m];
            jump.hi_far = mid;
            jump.hi_surface = mid_surface[m];
            jump.hi_triangle = mid_triangle[m];
          } else {
            jump.lambda_lo = probe[m];
            jump.lo_far = mid;
            jump.lo_surface = mid_surface[m];
            jump.lo_triangle = mid_triangle[m];
          }
          if (jump.lambda_hi - jump.lambda_lo > kBracketWidth * (1.0 + 1e-9) && open(jump) && !settled(jump))
            active[kept++] = active[m];
        }
        active.resize(kept);
      }
    };
    const std::size_t blocks = (end - first + kJumpBlock - 1) / kJumpBlock;
    if (sc.blocks.size() < blocks) sc.blocks.resize(blocks);
    for (std::size_t b = 0; b < blocks; ++b) {
      sc.blocks[b].predictions = sc.blocks[b].prediction_misses = 0;
      sc.blocks[b].prediction_error = 0.0;
    }
    for_each_index(tracer.parallel && blocks > 1, static_cast<int>(blocks), [&](int b) {
      const std::size_t begin = first + static_cast<std::size_t>(b) * kJumpBlock;
      run_block(begin, std::min(end, begin + kJumpBlock), sc.blocks[static_cast<std::size_t>(b)]);
    });
    if (cost != nullptr)
      for (std::size_t b = 0; b < blocks; ++b) {
        cost->refine_predicted += sc.blocks[b].predictions;
        cost->predicted_misses += sc.blocks[b].prediction_misses;
        cost->predicted_error = std::max(cost->predicted_error, sc.blocks[b].prediction_error);
      }
    for (std::size_t k = first; k < end; ++k) {
      Jump& jump = jumps[k];
      if (jump.split != kPendingSplit) continue;
      const Middle& middle = sc.middle[k - first];
      jump.split = nv + static_cast<int>(sc.extra_far.size());
      sc.extra_direction.push_back(middle.direction);
      sc.extra_far.push_back(middle.far);
      sc.extra_surface.push_back(middle.surface);
      sc.extra_triangle.push_back(middle.triangle);
      sc.extra_parent.push_back(static_cast<std::int32_t>(k));
    }
  };
  candidates_timer.stop();
  PhaseTimer first_pass_timer(cost ? &cost->first_pass_s : nullptr);
  bisect(0, true);
  first_pass_timer.stop();
  PhaseTimer second_pass_timer(cost ? &cost->second_pass_s : nullptr);

  // Split edges: mark the slots on both sides, then look for jumps on the new edges (the halves
  // of the split edges and the edges inside the split slots).
  const std::size_t level0_jumps = jumps.size();
  auto& complex_slots = sc.complex_slots;
  complex_slots.clear();
  for (std::size_t k = 0; k < level0_jumps; ++k) {
    const Jump& jump = jumps[k];
    if (jump.split < 0) continue;
    const int t = jump.slot, other = jump.other;
    flags[static_cast<std::size_t>(t)] |= static_cast<std::uint8_t>(1 << (kSplitShift + jump.edge));
    const auto c = slot_corners(other);
    for (int e = 0; e < 3; ++e)
      if (c[static_cast<std::size_t>(e)] == jump.w && c[static_cast<std::size_t>((e + 1) % 3)] == jump.u)
        flags[static_cast<std::size_t>(other)] |= static_cast<std::uint8_t>(1 << (kSplitShift + e));
    complex_slots.push_back(t);
    complex_slots.push_back(other);
  }
  std::sort(complex_slots.begin(), complex_slots.end());
  complex_slots.erase(std::unique(complex_slots.begin(), complex_slots.end()), complex_slots.end());
  // The split points of slot t's split edges.
  auto midpoints = [&](int t, const Triangle& c) {
    Triangle m{-1, -1, -1};
    const int split = flags[static_cast<std::size_t>(t)] >> kSplitShift;
    for (int e = 0; e < 3; ++e)
      if (split & (1 << e)) {
        const std::int32_t k = edges.find(EdgeMap::key(c[static_cast<std::size_t>(e)], c[static_cast<std::size_t>((e + 1) % 3)]));
        m[static_cast<std::size_t>(e)] = jumps[static_cast<std::size_t>(k)].split;
      }
    return m;
  };
  for (int t : complex_slots) {
    const Triangle c = slot_corners(t);
    std::array<Triangle, 4> piece;
    const int n = pieces(c, flags[static_cast<std::size_t>(t)] >> kSplitShift, midpoints(t, c), piece);
    for (int p = 0; p < n; ++p)
      for (int e = 0; e < 3; ++e) {
        const int a = piece[static_cast<std::size_t>(p)][static_cast<std::size_t>(e)];
        const int b = piece[static_cast<std::size_t>(p)][static_cast<std::size_t>((e + 1) % 3)];
        if (a < nv && b < nv) continue;  // a whole edge of the grid: examined above
        const std::uint64_t key = EdgeMap::key(a, b);
        if (!samples_differ(a, b) || edges.find(key) >= 0) continue;
        // A half of a split grid edge lies on the slot across it too.
        Jump jump;
        jump.u = std::min(a, b);
        jump.w = std::max(a, b);
        jump.slot = t;
        if (a < nv || b < nv) {
          const Jump& parent = jumps[static_cast<std::size_t>(sc.extra_parent[static_cast<std::size_t>(std::max(a, b) - nv)])];
          jump.other = parent.slot == t ? parent.other : parent.slot;
        }
        jump.lo_far = sample_far(jump.u);
        jump.lo_surface = sample_surface(jump.u);
        jump.lo_triangle = sample_triangle(jump.u);
        jump.hi_far = sample_far(jump.w);
        jump.hi_surface = sample_surface(jump.w);
        jump.hi_triangle = sample_triangle(jump.w);
        edges.insert(key, static_cast<std::int32_t>(jumps.size()));
        jumps.push_back(jump);
      }
  }
  bisect(level0_jumps, false);
  second_pass_timer.stop();
  PhaseTimer untwist_timer(cost ? &cost->untwist_s : nullptr);

  // Confirmed jumps, and the slots they touch (on both sides of a grid edge): marked in the flags,
  // then listed in ascending order by one pass over them, eight flags at a time (nothing set
  // kComplex before; sorting the slots took longer).
  for (int t : complex_slots) flags[static_cast<std::size_t>(t)] |= kComplex;
  for (std::size_t k = 0; k < jumps.size(); ++k) {
    Jump& jump = jumps[k];
    jump.confirmed = open(jump);
    if (!jump.confirmed) continue;
    flags[static_cast<std::size_t>(jump.slot)] |= kComplex;
    if (jump.other >= 0) flags[static_cast<std::size_t>(jump.other)] |= kComplex;
  }
  complex_slots.clear();
  {
    const std::uint8_t* f = flags.data();
    constexpr std::uint64_t kAnyComplex = 0x0101010101010101ull * kComplex;
    int t = 0;
    for (; t + 8 <= nt; t += 8) {
      std::uint64_t word;
      std::memcpy(&word, f + t, sizeof word);
      if ((word & kAnyComplex) == 0) continue;
      for (int k = t; k < t + 8; ++k)
        if (f[k] & kComplex) complex_slots.push_back(k);
    }
    for (; t < nt; ++t)
      if (f[t] & kComplex) complex_slots.push_back(t);
  }

  // Each complex slot's pieces with the jumps on their edges, found once (the twist check, the
  // count and the fill pass read them; each looked them up in the edge map before). Only an edge
  // whose ends differ can hold a jump (every jump was made on such an edge): the others are not
  // looked up. A complex slot's pieces are piece_of[t] >> 3 on, piece_of[t] & 7 of them (only
  // complex slots are set).
  auto& slot_pieces = sc.slot_pieces;
  auto& piece_of = sc.piece_of;
  slot_pieces.clear();
  piece_of.resize(static_cast<std::size_t>(nt));
  for (int t : complex_slots) {
    const Triangle c = slot_corners(t);
    std::array<Triangle, 4> piece;
    const int n = pieces(c, flags[static_cast<std::size_t>(t)] >> kSplitShift, midpoints(t, c), piece);
    piece_of[static_cast<std::size_t>(t)] = static_cast<std::int32_t>(slot_pieces.size() << 3) | n;
    for (int p = 0; p < n; ++p) {
      SlotPiece q{piece[static_cast<std::size_t>(p)], {-1, -1, -1}};
      for (std::size_t e = 0; e < 3; ++e) {
        const int a = q.corners[e], b = q.corners[(e + 1) % 3];
        if (samples_differ(a, b)) q.jump[e] = edges.find(EdgeMap::key(a, b));
      }
      slot_pieces.push_back(q);
    }
  }
  // The confirmed jumps on the edges of a piece.
  auto jumps_of = [&](const SlotPiece& q) {
    std::array<Jump*, 3> edge{};
    for (std::size_t e = 0; e < 3; ++e) {
      const std::int32_t k = q.jump[e];
      if (k >= 0 && jumps[static_cast<std::size_t>(k)].confirmed) edge[e] = &jumps[static_cast<std::size_t>(k)];
    }
    return edge;
  };
  auto for_each_piece = [&](int t, auto visit) {
    const std::int32_t entry = piece_of[static_cast<std::size_t>(t)];
    const SlotPiece* first = slot_pieces.data() + (entry >> 3);
    for (int p = 0; p < (entry & 7); ++p) visit(first[p]);
  };
  // r just beside the jump on sample p's side.
  auto side_far = [](const Jump& jump, int p) { return p == jump.u ? jump.lo_far : jump.hi_far; };

  // A triangle takes at most two jump edges, joined by one wall that must not twist (the nearer
  // side at one end nearer at the other too): drop the weakest jump of any other triangle until
  // none is left. Dropping only lowers counts, so this ends. A triangle can only come to need a
  // drop when one of its jumps is dropped: after the first pass over every complex slot, each
  // pass visits (in the same ascending order) only the slots on both sides of the last pass's
  // drops, which drops exactly what passes over every slot would.
  auto& visit = sc.twist_visit;
  auto& dropped_at = sc.twist_next;
  visit.assign(complex_slots.begin(), complex_slots.end());
  while (!visit.empty()) {
    dropped_at.clear();
    for (int t : visit) {
      if (!live(t)) continue;
      for_each_piece(t, [&](const SlotPiece& piece) {
        const Triangle& c = piece.corners;
        const std::array<Jump*, 3> edge = jumps_of(piece);
        const int count = (edge[0] != nullptr) + (edge[1] != nullptr) + (edge[2] != nullptr);
        if (count < 2) return;
        if (count == 2) {
          const int r = edge[1] == nullptr ? 0 : (edge[2] == nullptr ? 1 : 2);  // lone corner c[r]
          const Jump& p = *edge[static_cast<std::size_t>(r)];
          const Jump& q = *edge[static_cast<std::size_t>((r + 2) % 3)];
          const int a = c[static_cast<std::size_t>(r)];
          const int b = c[static_cast<std::size_t>((r + 1) % 3)];
          const int d = c[static_cast<std::size_t>((r + 2) % 3)];
          if ((side_far(p, a) - side_far(p, b)) * (side_far(q, a) - side_far(q, d)) > 0.0) return;
        }
        Jump* weakest = nullptr;
        for (Jump* j : edge)
          if (j != nullptr && (weakest == nullptr || j->gap() < weakest->gap())) weakest = j;
        weakest->confirmed = false;
        dropped_at.push_back(weakest->slot);
        if (weakest->other >= 0) dropped_at.push_back(weakest->other);
      });
    }
    std::sort(dropped_at.begin(), dropped_at.end());
    dropped_at.erase(std::unique(dropped_at.begin(), dropped_at.end()), dropped_at.end());
    visit.swap(dropped_at);
  }
  untwist_timer.stop();
  refine_timer.stop();
  if (cost != nullptr) {
    cost->refine_rays += refine_counts.traced;
    cost->embree_s += 1e-9 * static_cast<double>(refine_counts.embree_ns.load());
  }
  // Faces of a piece (a, b, c) in outward order with its confirmed jumps: face(a, b, c) writes,
  // counts or adds up one face, centroid(x, y, z) makes (or counts) the centroid of three outer
  // vertices; vertex(v) is sample v's vertex and jump_end(jump, p) the jump's end on sample p's
  // side (mesh vertex ids, or the points themselves for the volume alone).
  auto emit = [&](const SlotPiece& piece, auto&& face, auto&& centroid, auto&& vertex, auto&& jump_end) {
    const Triangle& corners = piece.corners;
    const std::array<Jump*, 3> edge = jumps_of(piece);
    const int count = (edge[0] != nullptr) + (edge[1] != nullptr) + (edge[2] != nullptr);
    if (count == 0) {
      face(vertex(corners[0]), vertex(corners[1]), vertex(corners[2]));
      return;
    }
    const int r = count == 1 ? (edge[0] != nullptr ? 0 : (edge[1] != nullptr ? 1 : 2))
                             : (edge[1] == nullptr ? 0 : (edge[2] == nullptr ? 1 : 2));
    const int x = corners[static_cast<std::size_t>(r)];
    const int y = corners[static_cast<std::size_t>((r + 1) % 3)];
    const int z = corners[static_cast<std::size_t>((r + 2) % 3)];
    if (count == 1) {
      // The jump on edge x-y ends inside the triangle: a wall from it to the centroid.
      const Jump& jump = *edge[static_cast<std::size_t>(r)];
      const auto px = jump_end(jump, x), py = jump_end(jump, y);
      const auto centre = centroid(vertex(x), vertex(y), vertex(z));
      face(vertex(x), px, centre);
      face(py, vertex(y), centre);
      face(vertex(y), vertex(z), centre);
      face(vertex(z), vertex(x), centre);
      face(px, py, centre);
    } else {
      // Jumps on the two edges at the lone corner x: its corner piece, the far piece, and the
      // wall between them.
      const Jump& p = *edge[static_cast<std::size_t>(r)];            // on x-y
      const Jump& q = *edge[static_cast<std::size_t>((r + 2) % 3)];  // on z-x
      const auto px = jump_end(p, x), py = jump_end(p, y);
      const auto qx = jump_end(q, x), qz = jump_end(q, z);
      face(vertex(x), px, qx);
      face(py, vertex(y), vertex(z));
      face(py, vertex(z), qz);
      face(qx, px, py);
      face(qx, py, qz);
    }
  };
  // Where a confirmed jump's wall meets the surface on its near (lo) or far (hi) side.
  auto jump_point = [&](const Jump& jump, bool far_side) {
    const double lambda = 0.5 * (jump.lambda_lo + jump.lambda_hi);
    const Vec3 d = ((1.0 - lambda) * sample_direction(jump.u) + lambda * sample_direction(jump.w)).normalized();
    return far_side ? point_on(s, d, distance_on(s, jump.hi_far, jump.hi_surface, d), jump.hi_surface)
                    : point_on(s, d, distance_on(s, jump.lo_far, jump.lo_surface, d), jump.lo_surface);
  };
  // A corner's exact z on a plane (point_on's, without a call per corner).
  const std::array<double, 4> plane_z = {0.0, s.low, s.high, s.ground};
  static_assert(static_cast<int>(Surface::band_low) == 1 && static_cast<int>(Surface::band_high) == 2 &&
                static_cast<int>(Surface::ground) == 3);
  // Split point k (sample nv + k).
  auto extra_point = [&](std::size_t k) {
    return point_on(s, sc.extra_direction[k], sc.extra_far[k], sc.extra_surface[k]);
  };
  // The determinants of the directions at the corners of row i's two kinds of slot: a plain
  // slot's face is g + far d at its three corners, so its six-fold volume is r_a r_b r_c
  // det(d_a, d_b, d_c), and the determinant is the same along a row.
  auto row_determinants = [&](int i) {
    std::array<double, 2> det{};
    for (int h = 0; h < 2; ++h) {
      const Triangle c = slot_corners(2 * i * na + h);
      det[static_cast<std::size_t>(h)] = dirs.corner(c[0]).dot(dirs.corner(c[1]).cross(dirs.corner(c[2])));
    }
    return det;
  };
  auto& row_volume = sc.row_volume;
  auto total_volume = [&] {
    double six_volume = 0.0;
    for (double r : row_volume) six_volume += r;
    return six_volume / 6.0;
  };
  if (!with_mesh) {
    // The volume alone (no mesh asked for; beyond the paper, issue 35): the fill pass's sums below,
    // in its order, over the points its faces would join, computed here instead of stored, so that
    // the volume is the mesh's to the last bit. The border fans all end at g: they add nothing.
    PhaseTimer volume_timer(cost ? &cost->volume_s : nullptr);
    // As the vertex pass below writes it (its hot loop keeps g and the row's angles in locals, which
    // a shared function would make it reload per corner; the equality of the two volumes, tested,
    // holds them together).
    auto corner_point = [&](int v) {
      if (v >= nv) return extra_point(static_cast<std::size_t>(v - nv));
      const int i = v == 0 ? 0 : (v == nv - 1 ? ne : 1 + (v - 1) / na);
      const auto j = static_cast<std::size_t>(v - sphere.row_first(i));
      const double sin_el = dirs.sin_el_corner[static_cast<std::size_t>(i)];
      const double cos_el = dirs.cos_el_corner[static_cast<std::size_t>(i)];
      const auto k = static_cast<std::size_t>(v);
      return Vec3(s.g.x() + far[k] * (cos_el * dirs.cos_az_corner[j]), s.g.y() + far[k] * (cos_el * dirs.sin_az_corner[j]),
                  surface[k] == Surface::radial ? s.g.z() + far[k] * sin_el : plane_z[static_cast<std::size_t>(surface[k])]);
    };
    auto end_point = [&](const Jump& jump, int p) { return jump_point(jump, p != jump.u); };
    auto centroid_point = [](const Vec3& x, const Vec3& y, const Vec3& z) { return Vec3((x + y + z) / 3.0); };
    row_volume.assign(static_cast<std::size_t>(ne), 0.0);
    for_each_index(tracer.parallel, ne, [&](int i) {
      const std::array<double, 2> det = row_determinants(i);
      double plain = 0.0, other = 0.0;
      auto face = [&](const Vec3& a, const Vec3& b, const Vec3& c) { other += six_volume_of(s.g, a, b, c); };
      const std::uint8_t* f = flags.data() + 2 * i * na;
      const double* r = far.data();
      const SphereGrid::QuadRow row = sphere.quad_row(i);
      for (int j = 0; j < na; ++j) {
        const auto [v00, v01, v10, v11] = row.quad(j);
        for (int h = 0; h < 2; ++h) {
          const std::uint8_t flag = f[2 * j + h];
          if (flag == kLive)
            plain += h == 0 ? r[v00] * r[v01] * r[v11] * det[0] : r[v00] * r[v11] * r[v10] * det[1];
          else if (flag & kLive)
            for_each_piece(2 * (i * na + j) + h,
                           [&](const SlotPiece& piece) { emit(piece, face, centroid_point, corner_point, end_point); });
        }
      }
      row_volume[static_cast<std::size_t>(i)] = plain + other;
    });
    vv.volume = total_volume();
    return;
  }

  PhaseTimer mesh_timer(cost ? &cost->mesh_s : nullptr);
  PhaseTimer count_timer(cost ? &cost->count_s : nullptr);

  // Vertices: the used corners, the split points of edges, two per confirmed jump, a centroid
  // per triangle with one jump edge (counted per row), and g when the mesh borders the dead region
  // (fans to g).
  auto& corner_vertex = sc.corner_vertex;
  int num_vertices = 0;
  if (all_alive) {
    // The identity: kept from the previous VV when it was one too, of the same size.
    if (!sc.corner_identity || corner_vertex.size() != static_cast<std::size_t>(nv)) {
      corner_vertex.resize(static_cast<std::size_t>(nv));
      for (int v = 0; v < nv; ++v) corner_vertex[v] = v;
      sc.corner_identity = true;
    }
    num_vertices = nv;
  } else {
    sc.corner_identity = false;
    corner_vertex.assign(static_cast<std::size_t>(nv), -1);
    sphere.for_each_quad([&](int, int t, int v00, int v01, int v10, int v11) {
      if (live(t)) corner_vertex[v00] = corner_vertex[v01] = corner_vertex[v11] = 0;
      if (live(t + 1)) corner_vertex[v00] = corner_vertex[v11] = corner_vertex[v10] = 0;
    });
    for (int v = 0; v < nv; ++v)
      if (corner_vertex[v] == 0) corner_vertex[v] = num_vertices++;
  }
  auto& extra_vertex = sc.extra_vertex;
  extra_vertex.resize(sc.extra_far.size());
  for (auto& id : extra_vertex) id = num_vertices++;
  auto outer = [&](int v) { return v < nv ? corner_vertex[v] : extra_vertex[static_cast<std::size_t>(v - nv)]; };
  auto jump_vertex = [](const Jump& jump, int p) { return p == jump.u ? jump.vertex : jump.vertex + 1; };
  for (Jump& jump : jumps)
    if (jump.confirmed) {
      jump.vertex = num_vertices;
      num_vertices += 2;
    }

  // Border fans to g on the slot's edges next to the dead region (the border only appears where
  // far = 0, i.e. the ground or a band face through g: the fan is exact).
  auto border = [&](int t, const Triangle& c, auto&& face, int apex) {
    if (candidate[c[0]] + candidate[c[1]] + candidate[c[2]] < 2) return;
    for (int e = 0; e < 3; ++e)
      if (!live(sphere.neighbour(t, e))) face(outer(c[static_cast<std::size_t>((e + 1) % 3)]), outer(c[static_cast<std::size_t>(e)]), apex);
  };

  // Count pass: faces per slot (mesh_triangle_faces) and centroids per row. When the VV is spread
  // over the threads, the rows are counted in parallel from zero and then shifted by the faces of
  // the rows before them (the same offsets either way).
  const bool parallel = tracer.parallel;
  auto& triangle_faces = vv.mesh_triangle_faces;
  triangle_faces.resize(static_cast<std::size_t>(nt) + 1);
  triangle_faces[0] = 0;
  auto& row_centroid = sc.row_centroid;
  row_centroid.assign(static_cast<std::size_t>(ne) + 1, 0);
  auto& plain_row = sc.plain_row;
  plain_row.assign(static_cast<std::size_t>(ne), 0);
  auto& row_border = sc.row_border;
  row_border.assign(static_cast<std::size_t>(ne), 0);
  const std::uint8_t* slot_flag = flags.data();
  std::int32_t* offsets = triangle_faces.data();
  // Row i's offsets counted on from `faces`; returns the count after the row.
  auto count_row = [&](int i, std::int32_t faces) {
    int centroids = 0;
    // A row of plain slots only (no dead corner anywhere): one face each, no branch per slot.
    if (all_alive) {
      int plain = 0;
      for (int t = 2 * i * na; t < 2 * (i + 1) * na; ++t) plain += slot_flag[t] == kLive;
      if (plain == 2 * na) {
        plain_row[static_cast<std::size_t>(i)] = 1;
        const int first = 2 * i * na, slots = 2 * na;  // locals: the stores could alias na otherwise
        for (int k = 0; k < slots; ++k) offsets[first + k + 1] = faces + k + 1;
        return faces + slots;
      }
    }
    for (int t = 2 * i * na; t < 2 * (i + 1) * na; ++t) {
      if (slot_flag[t] == kLive) {
        ++faces;
      } else if (slot_flag[t] & kLive) {
        auto count_face = [&](int, int, int) { ++faces; };
        auto count_centroid = [&](int, int, int) {
          ++centroids;
          return 0;
        };
        for_each_piece(t, [&](const SlotPiece& piece) { emit(piece, count_face, count_centroid, outer, jump_vertex); });
      }
      if (!all_alive && (slot_flag[t] & kLive)) {
        const int before = faces;
        border(t, slot_corners(t), [&](int, int, int) { ++faces; }, 0);
        if (faces > before) row_border[static_cast<std::size_t>(i)] = 1;
      }
      offsets[t + 1] = faces;
    }
    row_centroid[static_cast<std::size_t>(i) + 1] = centroids;
    return faces;
  };
  if (!parallel) {
    std::int32_t faces = 0;
    for (int i = 0; i < ne; ++i) faces = count_row(i, faces);
  } else {
    auto& row_faces = sc.row_faces;
    row_faces.assign(static_cast<std::size_t>(ne) + 1, 0);
    for_each_index(true, ne, [&](int i) { row_faces[static_cast<std::size_t>(i) + 1] = count_row(i, 0); });
    for (std::size_t i = 1; i < row_faces.size(); ++i) row_faces[i] += row_faces[i - 1];
    for_each_index(true, ne, [&](int i) {
      const std::int32_t base = row_faces[static_cast<std::size_t>(i)];
      if (base == 0) return;
      for (int t = 2 * i * na; t < 2 * (i + 1) * na; ++t) offsets[t + 1] += base;
    });
  }
  const bool any_border = std::find(row_border.begin(), row_border.end(), std::uint8_t{1}) != row_border.end();
  row_centroid[0] = num_vertices;
  for (std::size_t i = 1; i < row_centroid.size(); ++i) row_centroid[i] += row_centroid[i - 1];
  num_vertices = row_centroid.back();
  const int apex = any_border ? num_vertices++ : -1;

  count_timer.stop();
  PhaseTimer vertices_timer(cost ? &cost->vertices_s : nullptr);
  TriangleMesh& mesh = vv.mesh;
  mesh.vertices.resize(num_vertices, 3);
  mesh.faces.resize(triangle_faces.back(), 3);
  auto set_vertex = [&](int id, const Vec3& p) {
    double* out = mesh.vertices.data() + 3 * static_cast<std::size_t>(id);
    out[0] = p.x();
    out[1] = p.y();
    out[2] = p.z();
  };
  // Vertices first (the centroids are made from them): corners by rows of the sphere, a corner on
  // a plane at its plane_z.
  for_each_index(parallel, ne + 1, [&](int i) {
    const int first = sphere.row_first(i), last = sphere.row_end(i);
    // Locals: the stores of doubles could otherwise alias g, the row's angles and the arrays'
    // pointers, reloaded per corner.
    const double sin_el = dirs.sin_el_corner[static_cast<std::size_t>(i)], cos_el = dirs.cos_el_corner[static_cast<std::size_t>(i)];
    const double gx = s.g.x(), gy = s.g.y(), gz = s.g.z();
    const double* r = far.data();
    const Surface* on = surface.data();
    const double* cos_az = dirs.cos_az_corner.data();
    const double* sin_az = dirs.sin_az_corner.data();
    const std::int32_t* id = corner_vertex.data();
    double* vertices = mesh.vertices.data();
    for (int v = first; v < last; ++v) {
      if (id[v] < 0) continue;
      const auto j = static_cast<std::size_t>(v - first);
      double* out = vertices + 3 * static_cast<std::size_t>(id[v]);
      out[0] = gx + r[v] * (cos_el * cos_az[j]);
      out[1] = gy + r[v] * (cos_el * sin_az[j]);
      out[2] = on[v] == Surface::radial ? gz + r[v] * sin_el : plane_z[static_cast<std::size_t>(on[v])];
    }
  });
  for (std::size_t k = 0; k < extra_vertex.size(); ++k)
    set_vertex(extra_vertex[k], extra_point(k));
  for (const Jump& jump : jumps) {
    if (!jump.confirmed) continue;
    set_vertex(jump.vertex, jump_point(jump, false));
    set_vertex(jump.vertex + 1, jump_point(jump, true));
  }
  if (apex >= 0) set_vertex(apex, s.g);

  vertices_timer.stop();
  PhaseTimer fill_timer(cost ? &cost->fill_s : nullptr);
  // Fill pass, with the volume (signed tetrahedra against g, divergence theorem) per row; a plain
  // slot's by row_determinants.
  row_volume.assign(static_cast<std::size_t>(ne), 0.0);
  auto position = [&](int id) {
    const double* p = mesh.vertices.data() + 3 * static_cast<std::size_t>(id);
    return Vec3(p[0], p[1], p[2]);
  };
  for_each_index(parallel, ne, [&](int i) {
    const std::array<double, 2> det = row_determinants(i);
    std::int32_t* out = mesh.faces.data() + 3 * static_cast<std::size_t>(triangle_faces[static_cast<std::size_t>(2 * i * na)]);
    int centroid = row_centroid[static_cast<std::size_t>(i)];
    double plain = 0.0, other = 0.0;
    auto face = [&](int a, int b, int c) {
      out[0] = a;
      out[1] = b;
      out[2] = c;
      out += 3;
      if (a != apex && b != apex && c != apex) other += six_volume_of(s.g, position(a), position(b), position(c));
    };
    auto make_centroid = [&](int x, int y, int z) {
      const int id = centroid++;
      set_vertex(id, (position(x) + position(y) + position(z)) / 3.0);
      return id;
    };
    const std::uint8_t* f = flags.data() + 2 * i * na;
    const double* r = far.data();
    const std::int32_t* id = corner_vertex.data();
    const SphereGrid::QuadRow row = sphere.quad_row(i);
    if (sc.plain_row[static_cast<std::size_t>(i)]) {
      // Every corner is its own mesh vertex (all alive) and every slot one face: no branch per
      // slot; the same sums in the same order as below.
      for (int j = 0; j < na; ++j) {
        const auto [v00, v01, v10, v11] = row.quad(j);
        out[0] = v00;
        out[1] = v01;
        out[2] = v11;
        out[3] = v00;
        out[4] = v11;
        out[5] = v10;
        out += 6;
        plain += r[v00] * r[v01] * r[v11] * det[0];
        plain += r[v00] * r[v11] * r[v10] * det[1];
      }
      row_volume[static_cast<std::size_t>(i)] = plain;
      return;
    }
    for (int j = 0; j < na; ++j) {
      const auto [v00, v01, v10, v11] = row.quad(j);
      if (f[2 * j] == kLive) {
        out[0] = id[v00];
        out[1] = id[v01];
        out[2] = id[v11];
        out += 3;
        plain += r[v00] * r[v01] * r[v11] * det[0];
      } else if (f[2 * j] & kLive) {
        for_each_piece(2 * (i * na + j), [&](const SlotPiece& piece) { emit(piece, face, make_centroid, outer, jump_vertex); });
      }
      if (!all_alive && (f[2 * j] & kLive)) border(2 * (i * na + j), Triangle{v00, v01, v11}, face, apex);
      if (f[2 * j + 1] == kLive) {
        out[0] = id[v00];
        out[1] = id[v11];
        out[2] = id[v10];
        out += 3;
        plain += r[v00] * r[v11] * r[v10] * det[1];
      } else if (f[2 * j + 1] & kLive) {
        for_each_piece(2 * (i * na + j) + 1, [&](const SlotPiece& piece) { emit(piece, face, make_centroid, outer, jump_vertex); });
      }
      if (!all_alive && (f[2 * j + 1] & kLive)) border(2 * (i * na + j) + 1, Triangle{v00, v11, v10}, face, apex);
    }
    row_volume[static_cast<std::size_t>(i)] = plain + other;
  });
  fill_timer.stop();
  mesh_timer.stop();
  PhaseTimer volume_timer(cost ? &cost->volume_s : nullptr);
  vv.volume = total_volume();
}

}  // namespace vistrack::detail
