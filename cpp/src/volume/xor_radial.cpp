// The exact XOR volume (eq. 56) of two star VV meshes, per direction: the fast path that computes
// what CGAL's corefinement computes on the same meshes.
//
// About its POI a star VV mesh is the graph r(w) of flat faces over the triangle slots of the
// sphere of grid corners (radial walls and fans to g hold no volume about g). When both meshes
// have the same vertex rows, their faces over one slot tile the same cone of directions, so the
// XOR there is the sum, over the pieces where a face of A and a face of B overlap, of the
// integral of |r_a^3 - r_b^3| / 3; otherwise (column_xor) faces are overlapped across the rows of
// each column and the XOR is vol(A) + vol(B) - 2 vol(A n B). Over one
// piece both are planes, r = d / (n . w); they cross on the plane m . w = 0 with
// m = d_a n_b - d_b n_a through the origin, which splits the piece into two cones where one
// plane is the farther, and the volume of a cone capped by a plane is a fan of tetrahedra.
// Everything is linear in the (unnormalised) direction vectors, so clipping is exact.
#include <Eigen/Geometry>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "vistrack/error.hpp"
#include "vistrack/volume.hpp"

namespace vistrack {
namespace {

// Faces holding volume over one triangle slot of a VV mesh: up to four pieces of a split slot,
// each with up to four faces beside its wall (visibility/star_mesh.cpp).
constexpr std::size_t kMaxSlotFaces = 16;

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

// Integral of min(r_a, r_b)^3 / 3 over cone q: the part of it inside both solids.
double cone_common(const Cone& q, const Face& a, const Face& b) {
  const Vec3 m = a.d * b.n - b.d * a.n;
  if (m.norm() <= 1e-12 * (a.d * b.n.norm() + b.d * a.n.norm())) return capped_volume(q, a.n, a.d);  // one plane
  return capped_volume(clip(q, m), b.n, b.d) + capped_volume(clip(q, -m), a.n, a.d);
}

// The cone of face a cut to the cone of face b (both in outward order).
Cone overlap(const Face& a, const Face& b) {
  Cone q = cone_of(a);
  for (int e = 0; e < 3 && q.size >= 3; ++e)
    q = clip(q, b.p[static_cast<std::size_t>(e)].cross(b.p[static_cast<std::size_t>((e + 1) % 3)]));
  return q;
}

// The faces of `vv` over triangle slot t that hold volume about the POI (the radial surface; not
// the walls and fans, whose planes pass through it), in the POI frame.
int graph_faces(const VisibilityVolume& vv, std::size_t t, std::array<Face, kMaxSlotFaces>& out) {
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
  std::array<Face, kMaxSlotFaces> fa, fb;
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
      const Cone q = overlap(fa[static_cast<std::size_t>(i)], fb[static_cast<std::size_t>(j)]);
      if (q.size >= 3) total += cone_xor(q, fa[static_cast<std::size_t>(i)], fb[static_cast<std::size_t>(j)]);
    }
  }
  return total;
}

struct SlotFaces {
  std::array<Face, kMaxSlotFaces> face;
  int size = 0;
};

// XOR over the lune of column j when the two meshes have different vertex rows (the ground crease
// of POIs at different heights above the ground): vol(A) + vol(B) - 2 vol(A n B) there, with
// A n B summed over every pair of faces whose cones overlap. A face of one mesh meets the faces
// of the other's rows whose elevation bands overlap its own, widened by a row for the chords'
// bulge.
double column_xor(const VisibilityVolume& a, const VisibilityVolume& b, int column) {
  const auto na = static_cast<std::size_t>(a.grid.num_azimuth);
  auto load = [&](const VisibilityVolume& v, std::vector<SlotFaces>& slots, double& volume) {
    const std::size_t rows = v.mesh_row_sines.size() - 1;
    slots.clear();
    slots.resize(2 * rows);
    for (std::size_t i = 0; i < rows; ++i)
      for (std::size_t s = 0; s < 2; ++s) {
        SlotFaces& slot = slots[2 * i + s];
        slot.size = graph_faces(v, 2 * (i * na + static_cast<std::size_t>(column)) + s, slot.face);
        for (int k = 0; k < slot.size; ++k) volume += slot.face[static_cast<std::size_t>(k)].d / 6.0;
      }
  };
  std::vector<SlotFaces> slots_a, slots_b;
  double volume_a = 0.0, volume_b = 0.0, common = 0.0;
  load(a, slots_a, volume_a);
  load(b, slots_b, volume_b);
  const std::vector<double>& rows_b = b.mesh_row_sines;
  const auto last_b = static_cast<std::ptrdiff_t>(rows_b.size()) - 2;
  for (std::size_t i = 0; i + 1 < a.mesh_row_sines.size(); ++i) {
    const auto below = std::upper_bound(rows_b.begin(), rows_b.end(), a.mesh_row_sines[i]) - rows_b.begin() - 1;
    const auto above = std::lower_bound(rows_b.begin(), rows_b.end(), a.mesh_row_sines[i + 1]) - rows_b.begin() - 1;
    for (std::ptrdiff_t k = std::max<std::ptrdiff_t>(0, below - 1); k <= std::min(last_b, above + 1); ++k)
      for (std::size_t sa = 0; sa < 2; ++sa)
        for (std::size_t sb = 0; sb < 2; ++sb) {
          const SlotFaces& fa = slots_a[2 * i + sa];
          const SlotFaces& fb = slots_b[2 * static_cast<std::size_t>(k) + sb];
          for (int p = 0; p < fa.size; ++p)
            for (int q = 0; q < fb.size; ++q) {
              const Face& x = fa.face[static_cast<std::size_t>(p)];
              const Face& y = fb.face[static_cast<std::size_t>(q)];
              const Cone piece = overlap(x, y);
              if (piece.size >= 3) common += cone_common(piece, x, y);
            }
        }
  }
  return volume_a + volume_b - 2.0 * common;
}

}  // namespace

bool shares_radial_mesh(const VisibilityVolume& a, const VisibilityVolume& b) {
  auto described = [](const VisibilityVolume& v) {
    return !v.mesh_triangle_faces.empty() && v.mesh_row_sines.size() >= 2 &&
           std::is_sorted(v.mesh_row_sines.begin(), v.mesh_row_sines.end()) &&
           v.mesh_triangle_faces.size() ==
               2 * (v.mesh_row_sines.size() - 1) * static_cast<std::size_t>(v.grid.num_azimuth) + 1 &&
           v.mesh_triangle_faces.back() == v.mesh.faces.rows();
  };
  return described(a) && described(b) && a.grid.num_azimuth == b.grid.num_azimuth &&
         a.grid.num_elevation == b.grid.num_elevation;
}

double radial_xor_volume(const VisibilityVolume& a, const VisibilityVolume& b) {
  detail::require_mesh(a, "a");
  detail::require_mesh(b, "b");
  if (!shares_radial_mesh(a, b))
    detail::fail_field("b.mesh_row_sines", std::to_string(b.mesh_row_sines.size()) + " rows",
                       "the radial XOR needs two star VVs (POI inside the band) on the same direction grid, "
                       "with the record of how their meshes cover it (mesh_row_sines, mesh_triangle_faces)");
  bool same_rows = a.mesh_row_sines.size() == b.mesh_row_sines.size();
  for (std::size_t k = 0; same_rows && k < a.mesh_row_sines.size(); ++k)
    same_rows = std::abs(a.mesh_row_sines[k] - b.mesh_row_sines[k]) <= 1e-12;
  // One partial sum per sphere row (same rows: slot against slot) or per column (different rows),
  // added in order: the same result on any number of threads.
  const std::size_t slots_per_row = 2 * static_cast<std::size_t>(a.grid.num_azimuth);
  const std::size_t parts = same_rows ? (a.mesh_triangle_faces.size() - 1) / slots_per_row
                                      : static_cast<std::size_t>(a.grid.num_azimuth);
  std::vector<double> sums(parts, 0.0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, parts, 4), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t part = r.begin(); part < r.end(); ++part) {
      if (!same_rows) {
        sums[part] = column_xor(a, b, static_cast<int>(part));
        continue;
      }
      for (std::size_t t = part * slots_per_row; t < (part + 1) * slots_per_row; ++t) sums[part] += slot_xor(a, b, t);
    }
  });
  double total = 0.0;
  for (double s : sums) total += s;
  return std::max(total, 0.0);
}

}  // namespace vistrack
