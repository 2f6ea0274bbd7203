// The mesh of a VV whose POI lies in the altitude band (near = 0 on every ray): the radial
// surface r = far over the sphere of grid corners, with radial walls where r jumps.
//
// Why walls: at a silhouette (an occluder in front of what lies behind it) r(w) jumps from r1 to
// r2. A mesh edge that crosses the jump and interpolates r linearly holds
// (r1 + r2)(r1 - r2)^2 / 4 less of r^3 than the step does, so a plain corner mesh of a Charlotte
// VV holds 0.2-2.4 % less volume than the per-direction intervals. Each such edge is bisected with
// more rays until the jump is pinned to 1/2^kBisections of the edge, and the triangles on both
// sides share a radial wall there.
#include <algorithm>
#include <cmath>
#include <vector>

#include "visibility/radial_mesh.hpp"

namespace vistrack::detail {

namespace {

constexpr double kJumpCandidate = 0.1;  // relative gap |r_u - r_w| / max(r_u, r_w) worth bisecting
constexpr double kJumpConfirmed = 0.05;  // relative gap still left after bisection: a jump
constexpr int kBisections = 6;

// A mesh edge u-w (u < w) across which r jumps, bracketed by bisection: the ray at lambda_lo of
// the way from u to w is on u's side of the jump, the ray at lambda_hi on w's side.
struct Jump {
  int u = 0;
  int w = 0;
  double lambda_lo = 0.0;
  double lambda_hi = 1.0;
  Interval lo;
  Interval hi;
  bool confirmed = false;
  int triangle = 0;  // the live triangle the edge was found in (as its edge `edge`)
  int edge = 0;
  int vertex_u = -1;  // the two mesh vertices on the jump's ray: r on u's side and on w's side
  int vertex_w = -1;
  double gap() const { return std::abs(hi.far - lo.far); }
};

bool is_plane(Surface s) { return s != Surface::radial; }

Vec3 edge_direction(const Directions& dirs, const Jump& jump, double lambda) {
  return ((1.0 - lambda) * dirs.corner(jump.u) + lambda * dirs.corner(jump.w)).normalized();
}

// Distance along unit d to the surface that ended interval `iv` (measured on a nearby ray): the
// exact plane distance for the ground and the band caps, the measured distance otherwise.
double distance_on(const Setup& s, const Interval& iv, const Vec3& d) {
  double z = 0.0;
  if (iv.far_surface == Surface::ground) z = s.ground;
  else if (iv.far_surface == Surface::band_low) z = s.low;
  else if (iv.far_surface == Surface::band_high) z = s.high;
  else return iv.far;
  const double t = (z - s.g.z()) / d.z();
  return std::isfinite(t) && t > 0.0 ? std::min(t, s.d_max) : iv.far;
}

// Finds the jump edges between live triangles: candidates by their corners' gap, then
// kBisections rounds of rays, each keeping the half of the bracket with the larger gap (a jump
// keeps its gap, a smooth but steep r(w) loses half of it per round).
std::vector<Jump> find_jumps(const Setup& s, const SphereGrid& sphere, const Directions& dirs,
                             const std::vector<Interval>& corner, const std::vector<char>& tri_alive,
                             const IntervalTracer& trace) {
  std::vector<Jump> jumps;
  auto consider = [&](int t, int e, int p, int q) {
    if (p > q) return;  // each inner edge once (its other triangle has it as q-p)
    const Interval& a = corner[p];
    const Interval& b = corner[q];
    if (std::abs(a.far - b.far) <= kJumpCandidate * std::max(a.far, b.far)) return;
    // Two hits on one plane are joined exactly by the flat triangle between them.
    if (a.far_surface == b.far_surface && is_plane(a.far_surface)) return;
    if (!tri_alive[sphere.neighbour(t, e)]) return;
    Jump jump;
    jump.u = p;
    jump.w = q;
    jump.lo = a;
    jump.hi = b;
    jump.triangle = t;
    jump.edge = e;
    jumps.push_back(jump);
  };
  sphere.for_each_quad([&](int, int t, int v00, int v01, int v10, int v11) {
    if (tri_alive[t]) consider(t, 0, v00, v01), consider(t, 1, v01, v11), consider(t, 2, v11, v00);
    if (tri_alive[t + 1]) consider(t + 1, 0, v00, v11), consider(t + 1, 1, v11, v10), consider(t + 1, 2, v10, v00);
  });
  // A bracket whose gap falls to the confirmation level is smooth: it leaves the rounds early.
  const double alive_gap = 1e-6 * std::max(1.0, s.d_max);
  // Both ends on one plane is no jump: the ground seen at grazing angles changes fast but stays
  // flat, and flat triangles hold it exactly.
  auto open = [&](const Jump& jump) {
    return jump.lo.far - jump.lo.near > alive_gap && jump.hi.far - jump.hi.near > alive_gap &&
           jump.gap() > kJumpConfirmed * std::max(jump.lo.far, jump.hi.far) &&
           !(jump.lo.far_surface == jump.hi.far_surface && is_plane(jump.lo.far_surface));
  };
  std::vector<std::size_t> active(jumps.size());
  for (std::size_t k = 0; k < jumps.size(); ++k) active[k] = k;
  std::vector<Vec3> directions;
  for (int round = 0; round < kBisections && !active.empty(); ++round) {
    directions.clear();
    for (std::size_t k : active)
      directions.push_back(edge_direction(dirs, jumps[k], 0.5 * (jumps[k].lambda_lo + jumps[k].lambda_hi)));
    const std::vector<Interval> mid = trace(directions);
    std::size_t kept = 0;
    for (std::size_t m = 0; m < active.size(); ++m) {
      Jump& jump = jumps[active[m]];
      const double lambda = 0.5 * (jump.lambda_lo + jump.lambda_hi);
      if (std::abs(mid[m].far - jump.lo.far) >= std::abs(jump.hi.far - mid[m].far)) {
        jump.lambda_hi = lambda;
        jump.hi = mid[m];
      } else {
        jump.lambda_lo = lambda;
        jump.lo = mid[m];
      }
      if (open(jump)) active[kept++] = active[m];
    }
    active.resize(kept);
  }
  for (Jump& jump : jumps) jump.confirmed = open(jump);
  return jumps;
}

}  // namespace

TriangleMesh build_star_mesh(const Setup& s, const SphereGrid& sphere, const Directions& dirs,
                             const std::vector<Interval>& corner, const IntervalTracer& trace, double& volume,
                             std::vector<std::int32_t>& triangle_faces) {
  const int nv = sphere.num_vertices();
  const int ne = sphere.ne;
  const double alive_gap = 1e-6 * std::max(1.0, s.d_max);
  std::vector<char> alive(static_cast<std::size_t>(nv));
  for (int v = 0; v < nv; ++v) alive[v] = corner[v].far - corner[v].near > alive_gap ? 1 : 0;

  // Live triangles (all three corners see something), and the live corners of dead triangles:
  // only those can be pinched, and only triangles with two of them can border the dead region.
  const int nt = sphere.num_triangle_slots();
  std::vector<char> tri_alive(static_cast<std::size_t>(nt));
  std::vector<char> candidate(static_cast<std::size_t>(nv));
  auto update_triangles = [&]() {
    std::fill(candidate.begin(), candidate.end(), 0);
    sphere.for_each_quad([&](int i, int t, int v00, int v01, int v10, int v11) {
      tri_alive[t] = i >= 1 && alive[v00] && alive[v01] && alive[v11];
      tri_alive[t + 1] = i <= ne - 2 && alive[v00] && alive[v11] && alive[v10];
      if (i >= 1 && !tri_alive[t]) candidate[v00] |= alive[v00], candidate[v01] |= alive[v01], candidate[v11] |= alive[v11];
      if (i <= ne - 2 && !tri_alive[t + 1])
        candidate[v00] |= alive[v00], candidate[v11] |= alive[v11], candidate[v10] |= alive[v10];
    });
  };
  update_triangles();
  // A corner where the visible region touches itself (two separate fans of live triangles) would
  // be a non-manifold vertex: drop it, until there is none.
  std::vector<int> pole_ring;
  for (int round = 0; round < 64; ++round) {
    bool changed = false;
    for (int v = 0; v < nv; ++v) {
      if (!candidate[v]) continue;
      std::array<int, 6> local{};
      const int n = sphere.ring(v, local, pole_ring);
      const int* ring = n < 0 ? pole_ring.data() : local.data();
      const int size = n < 0 ? static_cast<int>(pole_ring.size()) : n;
      int runs = 0;
      for (int k = 0; k < size; ++k)
        if (tri_alive[ring[k]] && !tri_alive[ring[(k + size - 1) % size]]) ++runs;
      if (runs >= 2) {
        alive[v] = 0;
        changed = true;
      }
    }
    if (!changed) break;
    update_triangles();
  }

  std::vector<Jump> jumps = find_jumps(s, sphere, dirs, corner, tri_alive, trace);
  // edge_jump[3 t + e]: the jump on edge e of triangle t, or -1; jump_triangles: the triangles
  // with one.
  std::vector<int> edge_jump(3 * static_cast<std::size_t>(nt), -1);
  std::vector<int> jump_triangles;
  for (std::size_t k = 0; k < jumps.size(); ++k) {
    const Jump& jump = jumps[k];
    if (!jump.confirmed) continue;
    const int other = sphere.neighbour(jump.triangle, jump.edge);
    const auto c = sphere.corners(other);
    for (int e = 0; e < 3; ++e)
      if (c[static_cast<std::size_t>(e)] == jump.w && c[static_cast<std::size_t>((e + 1) % 3)] == jump.u)
        edge_jump[3 * static_cast<std::size_t>(other) + e] = static_cast<int>(k);
    edge_jump[3 * static_cast<std::size_t>(jump.triangle) + jump.edge] = static_cast<int>(k);
    jump_triangles.push_back(jump.triangle);
    jump_triangles.push_back(other);
  }
  std::sort(jump_triangles.begin(), jump_triangles.end());
  jump_triangles.erase(std::unique(jump_triangles.begin(), jump_triangles.end()), jump_triangles.end());
  // The confirmed jumps on the edges of triangle t, in the order of its corners' edges.
  auto jumps_of = [&](int t) {
    std::array<Jump*, 3> edge{};
    for (int e = 0; e < 3; ++e) {
      const int k = edge_jump[3 * static_cast<std::size_t>(t) + e];
      edge[static_cast<std::size_t>(e)] = k >= 0 && jumps[static_cast<std::size_t>(k)].confirmed ? &jumps[static_cast<std::size_t>(k)] : nullptr;
    }
    return edge;
  };
  // r just beside the jump on corner p's side.
  auto side_far = [](const Jump& jump, int p) { return p == jump.u ? jump.lo.far : jump.hi.far; };

  // A triangle takes at most two jump edges, joined by one wall that must not twist (the nearer
  // side at one end nearer at the other too): drop the weakest jump of any other triangle until
  // none is left. Dropping only lowers counts, so this ends.
  for (bool changed = true; changed;) {
    changed = false;
    for (int t : jump_triangles) {
      const auto c = sphere.corners(t);
      const std::array<Jump*, 3> edge = jumps_of(t);
      const int count = (edge[0] != nullptr) + (edge[1] != nullptr) + (edge[2] != nullptr);
      if (count < 2) continue;
      if (count == 2) {
        const int r = edge[1] == nullptr ? 0 : (edge[2] == nullptr ? 1 : 2);  // lone corner c[r]
        const Jump& p = *edge[static_cast<std::size_t>(r)];
        const Jump& q = *edge[static_cast<std::size_t>((r + 2) % 3)];
        const int a = c[static_cast<std::size_t>(r)];
        const int b = c[static_cast<std::size_t>((r + 1) % 3)];
        const int d = c[static_cast<std::size_t>((r + 2) % 3)];
        if ((side_far(p, a) - side_far(p, b)) * (side_far(q, a) - side_far(q, d)) > 0.0) continue;
      }
      Jump* weakest = nullptr;
      for (Jump* j : edge)
        if (j != nullptr && (weakest == nullptr || j->gap() < weakest->gap())) weakest = j;
      weakest->confirmed = false;
      changed = true;
    }
  }

  triangle_faces.assign(static_cast<std::size_t>(nt) + 1, 0);
  // Corners, apex, two vertices per jump and a centre per triangle with a jump ending in it.
  const auto expected_points = static_cast<Eigen::Index>(nv + 1 + 2 * jumps.size() + jump_triangles.size());
  MeshBuilder out(s.g, expected_points, 5 * static_cast<Eigen::Index>(nv) + 8);
  std::vector<int> outer(static_cast<std::size_t>(nv), -1);
  int apex = -1;
  auto outer_of = [&](int v) {
    if (outer[v] < 0) outer[v] = out.add(point_on(s, dirs.corner(v), corner[v].far, corner[v].far_surface));
    return outer[v];
  };
  // The vertex beside the jump on edge p-q on p's side (both created on first use, on the ray at
  // the middle of the final bracket, so the wall is radial and shared by both triangles).
  auto jump_vertex = [&](Jump& jump, int p) {
    if (jump.vertex_u < 0) {
      const Vec3 d = edge_direction(dirs, jump, 0.5 * (jump.lambda_lo + jump.lambda_hi));
      jump.vertex_u = out.add(point_on(s, d, distance_on(s, jump.lo, d), jump.lo.far_surface));
      jump.vertex_w = out.add(point_on(s, d, distance_on(s, jump.hi, d), jump.hi.far_surface));
    }
    return p == jump.u ? jump.vertex_u : jump.vertex_w;
  };
  // Triangle t with corners (a, b, c) in outward order; border fans to g on edges next to the
  // dead region (the border only appears where far = 0, i.e. the ground or a band face through
  // g: the fan is then exact).
  auto emit = [&](int t, int a, int b, int c) {
    const std::array<int, 3> corners{a, b, c};
    const std::array<Jump*, 3> edge = jumps_of(t);
    const int count = (edge[0] != nullptr) + (edge[1] != nullptr) + (edge[2] != nullptr);
    if (count == 0) {
      out.face(outer_of(a), outer_of(b), outer_of(c));
    } else if (count == 1) {
      // The jump on edge x-y ends inside the triangle: a wall from it to the centroid.
      const int r = edge[0] != nullptr ? 0 : (edge[1] != nullptr ? 1 : 2);
      const int x = corners[static_cast<std::size_t>(r)];
      const int y = corners[static_cast<std::size_t>((r + 1) % 3)];
      const int z = corners[static_cast<std::size_t>((r + 2) % 3)];
      Jump& jump = *edge[static_cast<std::size_t>(r)];
      const int px = jump_vertex(jump, x), py = jump_vertex(jump, y);
      const int centre = out.add((out.point(outer_of(x)) + out.point(outer_of(y)) + out.point(outer_of(z))) / 3.0);
      out.face(outer_of(x), px, centre);
      out.face(py, outer_of(y), centre);
      out.face(outer_of(y), outer_of(z), centre);
      out.face(outer_of(z), outer_of(x), centre);
      out.face(px, py, centre);
    } else {
      // Jumps on the two edges at the lone corner x: its corner piece, the far piece, and the
      // wall between them.
      const int r = edge[1] == nullptr ? 0 : (edge[2] == nullptr ? 1 : 2);
      const int x = corners[static_cast<std::size_t>(r)];
      const int y = corners[static_cast<std::size_t>((r + 1) % 3)];
      const int z = corners[static_cast<std::size_t>((r + 2) % 3)];
      Jump& p = *edge[static_cast<std::size_t>(r)];            // on x-y
      Jump& q = *edge[static_cast<std::size_t>((r + 2) % 3)];  // on z-x
      const int px = jump_vertex(p, x), py = jump_vertex(p, y);
      const int qx = jump_vertex(q, x), qz = jump_vertex(q, z);
      out.face(outer_of(x), px, qx);
      out.face(py, outer_of(y), outer_of(z));
      out.face(py, outer_of(z), qz);
      out.face(qx, px, py);
      out.face(qx, py, qz);
    }
    if (candidate[a] + candidate[b] + candidate[c] < 2) return;  // no edge on the border
    for (int e = 0; e < 3; ++e) {
      if (tri_alive[sphere.neighbour(t, e)]) continue;
      const int p = corners[static_cast<std::size_t>(e)];
      const int q = corners[static_cast<std::size_t>((e + 1) % 3)];
      if (apex < 0) apex = out.add(s.g);
      out.face(outer_of(q), outer_of(p), apex);
    }
  };
  sphere.for_each_quad([&](int, int t, int v00, int v01, int v10, int v11) {
    triangle_faces[static_cast<std::size_t>(t)] = out.num_faces();
    if (tri_alive[t]) emit(t, v00, v01, v11);
    triangle_faces[static_cast<std::size_t>(t) + 1] = out.num_faces();
    if (tri_alive[t + 1]) emit(t + 1, v00, v11, v10);
  });
  triangle_faces[static_cast<std::size_t>(nt)] = out.num_faces();
  return out.finish(volume);
}

}  // namespace vistrack::detail
