// The exact XOR volume (eq. 56) of two star VV meshes built over one triangulated sphere, per
// direction: the fast path that computes what CGAL's corefinement computes on the same meshes.
//
// About its POI a star VV mesh is the graph r(w) of flat faces over the triangle slots of the
// sphere of grid corners (radial walls and fans to g hold no volume about g). Over one slot both
// meshes' faces tile the same cone of directions, so the XOR there is the sum, over the pieces
// where a face of A and a face of B overlap, of the integral of |r_a^3 - r_b^3| / 3. Over one
// piece both are planes, r = d / (n . w); they cross on the plane m . w = 0 with
// m = d_a n_b - d_b n_a through the origin, which splits the piece into two cones where one
// plane is the farther, and the volume of a cone capped by a plane is a fan of tetrahedra.
// Everything is linear in the (unnormalised) direction vectors, so clipping is exact.
#include <Eigen/Geometry>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "vistrack/error.hpp"
#include "vistrack/volume.hpp"

namespace vistrack {
namespace {

// A face seen from the origin (its POI): corners p in outward order and its plane n . x = d.
struct Face {
  std::array<Vec3, 3> p;
  Vec3 n;
  double d = 0.0;
};

// A convex cone of directions given by the corner vectors of its cross-section, in outward order.
// A triangle clipped by four planes has at most seven corners; rounding on nearly parallel planes
// can add crossings, so there is room for more, and clip() never writes past the end.
struct Cone {
  std::array<Vec3, 16> v;
  int size = 0;
  void push(const Vec3& w) {
    if (size < static_cast<int>(v.size())) v[static_cast<std::size_t>(size++)] = w;
  }
};

Cone cone_of(const Face& f) {
  Cone c;
  for (const Vec3& p : f.p) c.push(p);
  return c;
}

// The part of cone q with m . w >= 0 (Sutherland-Hodgman on the corner vectors: they lie in one
// open hemisphere, so the chord between two of them stays in the plane of their arc).
Cone clip(const Cone& q, const Vec3& m) {
  Cone out;
  for (int k = 0; k < q.size; ++k) {
    const Vec3& a = q.v[static_cast<std::size_t>(k)];
    const Vec3& b = q.v[static_cast<std::size_t>((k + 1) % q.size)];
    const double sa = m.dot(a), sb = m.dot(b);
    if (sa >= 0.0) out.push(a);
    if ((sa >= 0.0) != (sb >= 0.0)) out.push(a + (sa / (sa - sb)) * (b - a));
  }
  return out;
}

// Volume between the origin and the plane n . x = d over the directions of cone q.
double capped_volume(const Cone& q, const Vec3& n, double d) {
  if (q.size < 3) return 0.0;
  auto on_plane = [&](const Vec3& w) { return Vec3(w * (d / n.dot(w))); };
  const Vec3 first = on_plane(q.v[0]);
  Vec3 previous = on_plane(q.v[1]);
  double six_volume = 0.0;
  for (int k = 2; k < q.size; ++k) {
    const Vec3 current = on_plane(q.v[static_cast<std::size_t>(k)]);
    six_volume += first.dot(previous.cross(current));
    previous = current;
  }
  return six_volume / 6.0;
}

// Integral of |r_a^3 - r_b^3| / 3 over cone q, with r the distance to the planes of a and b.
double cone_xor(const Cone& q, const Face& a, const Face& b) {
  const Vec3 m = a.d * b.n - b.d * a.n;  // m . w > 0 where a is the farther plane
  const Cone a_farther = clip(q, m);
  const Cone b_farther = clip(q, -m);
  return capped_volume(a_farther, a.n, a.d) - capped_volume(a_farther, b.n, b.d) +
         capped_volume(b_farther, b.n, b.d) - capped_volume(b_farther, a.n, a.d);
}

// The faces of `vv` over triangle slot t that hold volume about the POI (the radial surface; not
// the walls and fans, whose planes pass through it), in the POI frame.
int graph_faces(const VisibilityVolume& vv, std::size_t t, std::array<Face, 8>& out) {
  int count = 0;
  for (std::int32_t f = vv.mesh_triangle_faces[t]; f < vv.mesh_triangle_faces[t + 1]; ++f) {
    Face face;
    for (Eigen::Index c = 0; c < 3; ++c)
      face.p[static_cast<std::size_t>(c)] = vv.mesh.vertices.row(vv.mesh.faces(f, c)).transpose() - vv.poi;
    face.n = (face.p[1] - face.p[0]).cross(face.p[2] - face.p[0]);
    face.d = face.n.dot(face.p[0]);
    if (!(face.d > 1e-9 * face.n.norm() * face.p[0].norm())) continue;  // radial
    if (count == static_cast<int>(out.size()))
      detail::fail_field("mesh_triangle_faces", std::to_string(t), "more faces over one triangle than a VV mesh builds");
    out[static_cast<std::size_t>(count++)] = face;
  }
  return count;
}

// XOR over slot t: pairwise overlaps of the faces of a and b (one face each when neither has a
// wall there: the same cone), or the whole volume of one side where the other sees nothing.
double slot_xor(const VisibilityVolume& a, const VisibilityVolume& b, std::size_t t) {
  std::array<Face, 8> fa, fb;
  const int na = graph_faces(a, t, fa);
  const int nb = graph_faces(b, t, fb);
  double total = 0.0;
  if (na == 0 || nb == 0) {
    for (int k = 0; k < na; ++k) total += fa[static_cast<std::size_t>(k)].d / 6.0;
    for (int k = 0; k < nb; ++k) total += fb[static_cast<std::size_t>(k)].d / 6.0;
    return total;
  }
  if (na == 1 && nb == 1) return cone_xor(cone_of(fa[0]), fa[0], fb[0]);
  for (int i = 0; i < na; ++i) {
    for (int j = 0; j < nb; ++j) {
      const Face& f = fb[static_cast<std::size_t>(j)];
      Cone q = cone_of(fa[static_cast<std::size_t>(i)]);
      for (int e = 0; e < 3 && q.size >= 3; ++e)
        q = clip(q, f.p[static_cast<std::size_t>(e)].cross(f.p[static_cast<std::size_t>((e + 1) % 3)]));
      if (q.size >= 3) total += cone_xor(q, fa[static_cast<std::size_t>(i)], f);
    }
  }
  return total;
}

}  // namespace

bool shares_radial_mesh(const VisibilityVolume& a, const VisibilityVolume& b) {
  auto described = [](const VisibilityVolume& v) {
    return !v.mesh_triangle_faces.empty() && v.mesh_row_sines.size() >= 2 &&
           v.mesh_triangle_faces.size() ==
               2 * (v.mesh_row_sines.size() - 1) * static_cast<std::size_t>(v.grid.num_azimuth) + 1 &&
           v.mesh_triangle_faces.back() == v.mesh.faces.rows();
  };
  if (!described(a) || !described(b) || a.grid.num_azimuth != b.grid.num_azimuth ||
      a.mesh_row_sines.size() != b.mesh_row_sines.size())
    return false;
  for (std::size_t k = 0; k < a.mesh_row_sines.size(); ++k)
    if (std::abs(a.mesh_row_sines[k] - b.mesh_row_sines[k]) > 1e-12) return false;
  return true;
}

double radial_xor_volume(const VisibilityVolume& a, const VisibilityVolume& b) {
  if (!shares_radial_mesh(a, b))
    detail::fail_field("b.mesh_row_sines", std::to_string(b.mesh_row_sines.size()) + " rows",
                       "the meshes are not built over one triangulated sphere (radial XOR needs two star VVs on "
                       "the same grid with the same vertex rows)");
  // One partial sum per sphere row, added in order: the same result on any number of threads.
  const std::size_t slots_per_row = 2 * static_cast<std::size_t>(a.grid.num_azimuth);
  const std::size_t rows = (a.mesh_triangle_faces.size() - 1) / slots_per_row;
  std::vector<double> row_sums(rows, 0.0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows, 4), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t row = r.begin(); row < r.end(); ++row)
      for (std::size_t t = row * slots_per_row; t < (row + 1) * slots_per_row; ++t) row_sums[row] += slot_xor(a, b, t);
  });
  double total = 0.0;
  for (double s : row_sums) total += s;
  return std::max(total, 0.0);
}

}  // namespace vistrack
