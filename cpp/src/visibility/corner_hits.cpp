// Corner rays as a z-buffer on the sphere (see corner_hits.hpp).
//
// Why: the corner rays the clearance bounds cannot decide are the ones that meet buildings, and
// Embree spent about 50 ns on each (about 0.8 ms of a 1-degree Charlotte VV on one thread, plus
// packing the rays and reading the hits). Their directions form a regular grid, so each triangle
// can instead be tested against the grid directions inside its footprint (the same per-triangle
// spans the clearance bounds are made of): a direction d from g lies in the triangle's cone when
// it is on the inner side of the three planes through g and the triangle's edges, and meets its
// plane at t = (n . q0) / (n . d). Per row of the grid the three edge tests and the plane are
// affine in (cos az, sin az): two multiply-adds each per direction. In double precision on
// Embree's own float vertices: two triangles sharing an edge compute the same edge plane with
// opposite signs, so no direction slips between them.
#include "visibility/corner_hits.hpp"

#include <Eigen/Geometry>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "simd/cpu.hpp"
#include "visibility/corner_scan.hpp"
#include "visibility/embree_scene.hpp"

namespace vistrack::detail {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// One triangle's tests, relative to g: inside(d) = all edge[e] . d >= 0; the distance
// along d to its plane is offset / plane . d.
struct Cone {
  std::array<Vec3, 3> edge;
  Vec3 plane;
  double offset = 0.0;
  bool valid = false;
};

Cone cone_of(const float* t, const Vec3& g_local) {
  const std::array<Vec3, 3> q = {Vec3(t[0], t[1], t[2]) - g_local, Vec3(t[3], t[4], t[5]) - g_local,
                                 Vec3(t[6], t[7], t[8]) - g_local};
  Cone cone;
  for (std::size_t e = 0; e < 3; ++e) cone.edge[e] = q[e].cross(q[(e + 1) % 3]);
  const double triple = cone.edge[0].dot(q[2]);  // q0 . (q1 x q2): g off the triangle's plane
  if (!(triple != 0.0)) return cone;
  if (triple < 0.0)
    for (Vec3& n : cone.edge) n = -n;
  cone.plane = (q[1] - q[0]).cross(q[2] - q[0]);
  cone.offset = cone.plane.dot(q[0]);
  cone.valid = cone.offset != 0.0;
  return cone;
}

}  // namespace

std::size_t corner_hits(const Clearance& clearance, const std::vector<float>& triangles, const Vec3& g_local,
                        const Setup& s, const SphereGrid& sphere, const Directions& dirs, bool parallel,
                        CornerHits& out) {
  const int ne = sphere.ne, na = sphere.na;
  const auto n = static_cast<std::size_t>(sphere.num_vertices());
  const std::vector<double>& sines = dirs.sin_el_corner;
  const double d_az = kTwoPi / na;
  const bool avx2 = avx2_kernel_available();  // the same hits either way (corner_scan.hpp)
  const double* cos_az = dirs.cos_az_corner.data();
  const double* sin_az = dirs.sin_az_corner.data();
  // Hits count up to where the ray's visible part ends anyway (as the traced rays' t_max): as an
  // inverse distance, from w_min on (+inf: the row sees nothing).
  std::vector<double> row_w_min(static_cast<std::size_t>(ne) + 1);
  for (std::size_t i = 0; i < row_w_min.size(); ++i) {
    const double t_max = visible_far_bound(s, sines[i]) * (1.0 + 1e-6);
    row_w_min[i] = t_max > 0.0 ? 1.0 / t_max : kInf;
  }
  // A footprint's rows are those with sin_lo <= sine <= sin_hi: std::lower_bound and upper_bound
  // on the row sines, started from a table of buckets of sine instead of a binary search over all
  // rows (whose branches are unpredictable). first_row[k]: the first row at or above bucket k's
  // start; a search starts one bucket lower (the start's rounding) and walks up a few rows.
  const int buckets = 4 * ne;
  const double per_unit = 0.5 * buckets;
  std::vector<int>& first_row = out.first_row;
  first_row.resize(static_cast<std::size_t>(buckets) + 1);
  for (int k = 0, i = 0; k <= buckets; ++k) {
    const double start = -1.0 + k / per_unit;
    while (i <= ne && sines[static_cast<std::size_t>(i)] < start) ++i;
    first_row[static_cast<std::size_t>(k)] = i;
  }
  auto walk_from = [&](double x) {
    const double bucket = std::floor((x + 1.0) * per_unit) - 1.0;
    return first_row[static_cast<std::size_t>(std::clamp(bucket, 0.0, static_cast<double>(buckets)))];
  };
  auto lower_row = [&](double x) {  // std::lower_bound(sines, x) - begin
    int i = walk_from(x);
    while (i <= ne && sines[static_cast<std::size_t>(i)] < x) ++i;
    return i;
  };
  auto upper_row = [&](double x) {  // std::upper_bound(sines, x) - begin
    int i = walk_from(x);
    while (i <= ne && sines[static_cast<std::size_t>(i)] <= x) ++i;
    return i;
  };
  // Footprints k = part, part + parts, ... into the first thread's arrays (part 0: the result's,
  // the owner in place of the triangle until `finish`) or the second's.
  auto scan = [&](std::size_t part, std::size_t parts) {
    // On the thread that fills it. The owner is read only where a hit was kept (w > 0), which
    // sets it: no fill (stale values from the previous VV, never read).
    std::vector<double>& inverse = part == 0 ? out.inverse : out.second_inverse;
    std::vector<std::uint32_t>& owners = part == 0 ? out.triangle : out.second_owner;
    inverse.assign(n, 0.0);
    owners.resize(n);
    double* hit = inverse.data();
    std::uint32_t* owner = owners.data();
    std::size_t tested = 0;
    for (std::size_t k = part; k < clearance.footprints.size(); k += parts) {
      const Footprint& f = clearance.footprints[k];
      const auto ordinal = static_cast<std::uint32_t>(k);
      const int i0 = lower_row(f.sin_lo), i1 = upper_row(f.sin_hi) - 1;
      if (i0 > i1) continue;
      const Cone cone = cone_of(triangles.data() + 9 * static_cast<std::size_t>(f.face), g_local);
      if (!cone.valid) continue;
      const double inv_offset = 1.0 / cone.offset;
      // Columns: one or two runs (the span wraps past azimuth 0).
      int runs = 1;
      std::array<int, 2> first{0, 0}, last{na - 1, na - 1};
      if (!f.every) {
        const int j0 = static_cast<int>(std::ceil(f.az_lo / d_az)), j1 = static_cast<int>(std::floor(f.az_hi / d_az));
        if (j1 - j0 + 1 >= na) {
          // every column
        } else if (j0 < 0) {
          first = {0, j0 + na};
          last = {j1, na - 1};
          runs = j1 >= 0 ? 2 : 1;
          if (j1 < 0) first[0] = j0 + na, last[0] = j1 + na;
        } else if (j1 >= na) {
          first = {j0, 0};
          last = {na - 1, j1 - na};
          runs = j0 < na ? 2 : 1;
          if (j0 >= na) first[0] = j0 - na, last[0] = j1 - na;
        } else {
          first[0] = j0;
          last[0] = j1;
        }
      }
      for (int i = i0; i <= i1; ++i) {
        const double sin_el = sines[static_cast<std::size_t>(i)];
        const double w_min = row_w_min[static_cast<std::size_t>(i)];
        if (w_min == kInf) continue;
        const double cos_el = dirs.cos_el_corner[static_cast<std::size_t>(i)];
        // edge e . d = a_e cos az + b_e sin az + c_e along the row.
        std::array<double, 4> a{}, b{}, c{};
        for (std::size_t e = 0; e < 4; ++e) {
          const Vec3& m = e < 3 ? cone.edge[e] : cone.plane;
          a[e] = cos_el * m.x();
          b[e] = cos_el * m.y();
          c[e] = sin_el * m.z();
        }
        double* row_hit = hit + sphere.row_first(i);
        std::uint32_t* row_owner = owner + sphere.row_first(i);
        // A pole is one direction, column 0's: cos el = 0 makes the row's formula (0, 0, sin el).
        const bool pole = i == 0 || i == ne;
        for (int r = 0; r < (pole ? 1 : runs); ++r) {
          const int j0 = pole ? 0 : first[static_cast<std::size_t>(r)], j1 = pole ? 0 : last[static_cast<std::size_t>(r)];
          tested += static_cast<std::size_t>(j1 - j0 + 1);
          if (avx2)
            scan_run_avx2(cos_az, sin_az, j0, j1, a.data(), b.data(), c.data(), inv_offset, w_min, ordinal, row_hit,
                          row_owner);
          else
            scan_run(cos_az, sin_az, j0, j1, a.data(), b.data(), c.data(), inv_offset, w_min, ordinal, row_hit, row_owner);
        }
      }
    }
    return tested;
  };
  std::size_t tested = 0;
  if (parallel) {
    // Alternate footprints on two threads (neighbours in the list share a bucket row, so both
    // threads get near and far triangles), each into its own buffer, merged as one pass in list
    // order would have decided: the larger inverse distance, on a tie the earlier footprint.
    std::size_t even = 0, odd = 0;
    tbb::parallel_invoke([&] { even = scan(0, 2); }, [&] { odd = scan(1, 2); });
    tested = even + odd;
  } else {
    tested = scan(0, 1);
  }
  auto finish = [&](std::size_t begin, std::size_t end) {
    // Locals: the stores could otherwise alias the vectors' pointers, reloaded per corner.
    double* w0 = out.inverse.data();
    std::uint32_t* owner0 = out.triangle.data();  // becomes the triangle
    const double* w1 = out.second_inverse.data();
    const std::uint32_t* owner1 = out.second_owner.data();
    const Footprint* footprints = clearance.footprints.data();
    for (std::size_t v = begin; v < end; ++v) {
      double w = w0[v];
      std::uint32_t owner = owner0[v];
      if (parallel && (w1[v] > w || (w1[v] == w && w > 0.0 && owner1[v] < owner))) {
        w = w1[v], owner = owner1[v];
        w0[v] = w;
      }
      owner0[v] = w > 0.0 ? footprints[owner].face : EmbreeScene::kNoTriangle;
    }
  };
  if (parallel) tbb::parallel_invoke([&] { finish(0, n / 2); }, [&] { finish(n / 2, n); });
  else finish(0, n);
  return tested;
}

}  // namespace vistrack::detail
