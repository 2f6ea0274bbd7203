// The mesh of a VV whose POI lies outside the altitude band (the visible interval starts where
// the ray enters the band).
#include <algorithm>
#include <cstdint>
#include <unordered_map>

#include "visibility/radial_mesh.hpp"

namespace vistrack::detail {

// VV of a POI outside the band (near > 0): the outer surface r = far and the inner surface
// r = near over the region where far > near, linearly clipped in each triangle of the sphere
// grid (marching triangles on the gap far - near). The two surfaces meet on the clipping
// contour, where the chords of far and near cross: along the directions u + lambda (w - u),
// 1/r of a chord is linear in lambda, so the crossing is exact and both surfaces stay in the
// triangle's cone with the outer one outside (1/far <= 1/near at every corner).
TriangleMesh build_shell_mesh(const Setup& s, const SphereGrid& sphere, const Directions& dirs,
                              const std::vector<Interval>& corner, double& volume) {
  const int nv = sphere.num_vertices();
  const double alive_gap = 1e-6 * std::max(1.0, s.d_max);
  std::vector<char> alive(static_cast<std::size_t>(nv));
  for (int v = 0; v < nv; ++v) alive[v] = corner[v].far - corner[v].near > alive_gap ? 1 : 0;

  // A live corner is live in both senses (a positive gap, and 1/far < 1/near for the contour).
  for (int v = 0; v < nv; ++v) alive[v] = alive[v] && corner[v].inv_far < corner[v].inv_near;
  MeshBuilder out(s.g, 5 * static_cast<Eigen::Index>(nv), 8 * static_cast<Eigen::Index>(nv));
  std::vector<int> outer(static_cast<std::size_t>(nv), -1), inner(static_cast<std::size_t>(nv), -1);
  auto outer_of = [&](int v) {
    if (outer[v] < 0) outer[v] = out.add(point_on(s, dirs.corner(v), corner[v].far, corner[v].far_surface));
    return outer[v];
  };
  auto inner_of = [&](int v) {
    if (inner[v] < 0) inner[v] = out.add(point_on(s, dirs.corner(v), corner[v].near, corner[v].near_surface));
    return inner[v];
  };
  // 1/far and 1/near of a corner, linear in the direction for the band and ground planes.
  auto inverse_radii = [&](int v, double& inv_far, double& inv_near) {
    inv_far = corner[v].inv_far;
    inv_near = corner[v].inv_near;
  };
  // Contour vertex on the edge from live corner u to dead corner w, shared by both triangles.
  std::unordered_map<std::uint64_t, int> contour;
  auto contour_of = [&](int u, int w) {
    const std::uint64_t key = (static_cast<std::uint64_t>(static_cast<std::uint32_t>(u)) << 32) | static_cast<std::uint32_t>(w);
    const auto found = contour.find(key);
    if (found != contour.end()) return found->second;
    double fu, nu, fw, nw;
    inverse_radii(u, fu, nu);
    inverse_radii(w, fw, nw);
    const double a = fu - nu;  // < 0: u sees something
    const double b = fw - nw;  // >= 0: w does not
    double lambda = (b - a) > 0.0 ? a / (a - b) : 0.5;
    lambda = std::clamp(lambda, 1e-3, 1.0 - 1e-3);  // keep contour vertices apart from the corners
    const Vec3 d = (1.0 - lambda) * dirs.corner(u) + lambda * dirs.corner(w);
    const double inv_r = (1.0 - lambda) * fu + lambda * fw;
    const int id = out.add(s.g + d / inv_r);
    contour.emplace(key, id);
    return id;
  };

  const int nt = sphere.num_triangle_slots();
  for (int t = 0; t < nt; ++t) {
    if (!sphere.exists(t)) continue;
    const auto c = sphere.corners(t);
    const int live = alive[c[0]] + alive[c[1]] + alive[c[2]];
    if (live == 0) continue;
    if (live == 3) {
      out.face(outer_of(c[0]), outer_of(c[1]), outer_of(c[2]));
      out.face(inner_of(c[0]), inner_of(c[2]), inner_of(c[1]));
      continue;
    }
    // Rotate so that the lone corner (live when live == 1, dead when live == 2) comes first.
    int r = 0;
    for (int k = 0; k < 3; ++k)
      if ((live == 1) == static_cast<bool>(alive[c[static_cast<std::size_t>(k)]])) r = k;
    const int a = c[static_cast<std::size_t>(r)];
    const int b = c[static_cast<std::size_t>((r + 1) % 3)];
    const int d = c[static_cast<std::size_t>((r + 2) % 3)];
    if (live == 1) {
      // Live corner a; contour points on a-b and a-d.
      const int pab = contour_of(a, b);
      const int pad = contour_of(a, d);
      out.face(outer_of(a), pab, pad);
      out.face(inner_of(a), pad, pab);
    } else {
      // Dead corner a; live b and d; contour points on b-a and d-a. Quad b, d, p_da, p_ba.
      const int pba = contour_of(b, a);
      const int pda = contour_of(d, a);
      out.face(outer_of(b), outer_of(d), pda);
      out.face(outer_of(b), pda, pba);
      out.face(inner_of(b), pda, inner_of(d));
      out.face(inner_of(b), pba, pda);
    }
  }
  return out.finish(volume);
}

}  // namespace vistrack::detail
