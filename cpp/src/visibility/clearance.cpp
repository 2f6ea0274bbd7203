// Rays that certainly meet no obstacle (see clearance.hpp).
#include "visibility/clearance.hpp"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace vistrack::detail {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Slack on every bound: the rays are traced in floats, and the azimuths below come from a
// polynomial (error 1e-8 rad); a ray this close to a bound is traced.
constexpr double kAngleSlack = 1e-6;
constexpr double kSineSlack = 1e-6;

// atan2(y, x) in [0, 2 pi) to about 1e-8 rad (Abramowitz and Stegun 4.4.49 on [0, 1], then the
// octant), three times faster than std::atan2.
double azimuth_of(double x, double y) {
  const double ax = std::abs(x), ay = std::abs(y);
  const double big = std::max(ax, ay);
  if (big == 0.0) return 0.0;
  const double t = std::min(ax, ay) / big;
  const double t2 = t * t;
  double a = t * (0.9999993329 +
                  t2 * (-0.3332985605 +
                        t2 * (0.1994653599 +
                              t2 * (-0.1390853351 + t2 * (0.0964200441 + t2 * (-0.0559098861 + t2 * (0.0218612288 - t2 * 0.0040540580)))))));
  if (ay > ax) a = 0.5 * kPi - a;
  if (x < 0.0) a = kPi - a;
  if (y < 0.0) a = kTwoPi - a;
  return a >= kTwoPi ? a - kTwoPi : a;
}

// Squared distance from the origin to segment p-q in the plane (coordinates within the
// environment's range: no overflow, so no std::hypot, which is several times slower than a square
// root and ran three times per triangle).
double segment_distance2(double px, double py, double qx, double qy) {
  const double dx = qx - px, dy = qy - py;
  const double length2 = dx * dx + dy * dy;
  double t = length2 > 0.0 ? -(px * dx + py * dy) / length2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const double x = px + t * dx, y = py + t * dy;
  return x * x + y * y;
}

double sine_of_tangent(double tau) {
  if (tau == kInf) return 1.0;
  if (tau == -kInf) return -1.0;
  return tau / std::sqrt(1.0 + tau * tau);
}

}  // namespace

ObstacleIndex::ObstacleIndex(const Points3& vertices, const Faces& all_faces, double ground) {
  std::vector<Eigen::Index> kept;
  for (Eigen::Index f = 0; f < all_faces.rows(); ++f)
    if (std::max({vertices(all_faces(f, 0), 2), vertices(all_faces(f, 1), 2), vertices(all_faces(f, 2), 2)}) > ground) kept.push_back(f);
  Faces faces(static_cast<Eigen::Index>(kept.size()), 3);
  for (std::size_t k = 0; k < kept.size(); ++k) faces.row(static_cast<Eigen::Index>(k)) = all_faces.row(kept[k]);
  const Eigen::Index n = faces.rows();
  if (n == 0) return;
  double lo_x = kInf, lo_y = kInf, hi_x = -kInf, hi_y = -kInf;
  for (Eigen::Index v = 0; v < vertices.rows(); ++v) {
    lo_x = std::min(lo_x, vertices(v, 0));
    hi_x = std::max(hi_x, vertices(v, 0));
    lo_y = std::min(lo_y, vertices(v, 1));
    hi_y = std::max(hi_y, vertices(v, 1));
  }
  // About two triangles per bucket, buckets of 2 to 200 m.
  const double area = std::max(1.0, (hi_x - lo_x) * (hi_y - lo_y));
  cell = std::clamp(std::sqrt(2.0 * area / static_cast<double>(n)), 2.0, 200.0);
  x0 = lo_x;
  y0 = lo_y;
  nx = static_cast<int>(std::floor((hi_x - lo_x) / cell)) + 1;
  ny = static_cast<int>(std::floor((hi_y - lo_y) / cell)) + 1;
  std::vector<std::int32_t> bucket_of(static_cast<std::size_t>(n));
  bucket_start.assign(static_cast<std::size_t>(nx) * ny + 1, 0);
  for (Eigen::Index f = 0; f < n; ++f) {
    double cxf = 0.0, cyf = 0.0;
    for (int c = 0; c < 3; ++c) {
      cxf += vertices(faces(f, c), 0) / 3.0;
      cyf += vertices(faces(f, c), 1) / 3.0;
    }
    for (int c = 0; c < 3; ++c)
      overhang = std::max(overhang, std::hypot(vertices(faces(f, c), 0) - cxf, vertices(faces(f, c), 1) - cyf));
    const int ix = std::clamp(static_cast<int>(std::floor((cxf - x0) / cell)), 0, nx - 1);
    const int iy = std::clamp(static_cast<int>(std::floor((cyf - y0) / cell)), 0, ny - 1);
    bucket_of[static_cast<std::size_t>(f)] = iy * nx + ix;
    ++bucket_start[static_cast<std::size_t>(iy * nx + ix) + 1];
  }
  for (std::size_t b = 1; b < bucket_start.size(); ++b) bucket_start[b] += bucket_start[b - 1];
  const auto size = static_cast<std::size_t>(n);
  for (auto* column : {&ax, &ay, &bx, &by, &cx, &cy, &z_min, &z_max}) column->resize(size);
  face.resize(size);
  bucket_z_min.assign(bucket_start.size() - 1, kInf);
  bucket_z_max.assign(bucket_start.size() - 1, -kInf);
  std::vector<std::int32_t> next(bucket_start.begin(), bucket_start.end() - 1);
  for (Eigen::Index f = 0; f < n; ++f) {
    const auto b = static_cast<std::size_t>(bucket_of[static_cast<std::size_t>(f)]);
    const auto k = static_cast<std::size_t>(next[b]++);
    face[k] = static_cast<std::uint32_t>(kept[static_cast<std::size_t>(f)]);
    ax[k] = vertices(faces(f, 0), 0);
    ay[k] = vertices(faces(f, 0), 1);
    bx[k] = vertices(faces(f, 1), 0);
    by[k] = vertices(faces(f, 1), 1);
    cx[k] = vertices(faces(f, 2), 0);
    cy[k] = vertices(faces(f, 2), 1);
    z_min[k] = std::min({vertices(faces(f, 0), 2), vertices(faces(f, 1), 2), vertices(faces(f, 2), 2)});
    z_max[k] = std::max({vertices(faces(f, 0), 2), vertices(faces(f, 1), 2), vertices(faces(f, 2), 2)});
    bucket_z_min[b] = std::min(bucket_z_min[b], z_min[k]);
    bucket_z_max[b] = std::max(bucket_z_max[b], z_max[k]);
  }
}

void Clearance::none(int na) {
  num_azimuth = na;
  sin_lo.assign(static_cast<std::size_t>(na), -2.0);
  sin_hi.assign(static_cast<std::size_t>(na), 2.0);
  footprints.clear();
}

void Clearance::compute(const ObstacleIndex& index, const Vec3& g, double reach, int na, bool parallel) {
  num_azimuth = na;
  // tau ranges, first as tangents (lo: +inf, hi: -inf while nothing reaches the column).
  sin_lo.assign(static_cast<std::size_t>(na), kInf);
  sin_hi.assign(static_cast<std::size_t>(na), -kInf);
  footprints.clear();
  double all_lo = kInf, all_hi = -kInf;  // triangles over g reach every column
  const double d_az = kTwoPi / na;
  const double gx = g.x(), gy = g.y(), gz = g.z();
  // The buckets' rows row_begin, row_begin + row_step, ... below row_end between columns ix0..ix1
  // into (lo, hi, every_lo, every_hi), and their footprints into `found` (with the count after each
  // row into row_ends, when given).
  auto scan = [&](int ix0, int ix1, int row_begin, int row_step, int row_end, std::vector<double>& col_lo,
                  std::vector<double>& col_hi, double& every_lo, double& every_hi, std::vector<Footprint>& found,
                  std::vector<std::uint32_t>* row_ends) {
    for (int iy = row_begin; iy < row_end; iy += row_step) {
      if (row_ends != nullptr && iy > row_begin) row_ends->push_back(static_cast<std::uint32_t>(found.size()));
      for (int ix = ix0; ix <= ix1; ++ix) {
        const auto b = static_cast<std::size_t>(iy * index.nx + ix);
        if (index.bucket_start[b] == index.bucket_start[b + 1]) continue;
        if (index.bucket_z_min[b] > gz + reach || index.bucket_z_max[b] < gz - reach) continue;
        // Horizontal distance from g to the bucket grown by the overhang.
        const double bx0 = index.x0 + ix * index.cell - index.overhang, bx1 = bx0 + index.cell + 2.0 * index.overhang;
        const double by0 = index.y0 + iy * index.cell - index.overhang, by1 = by0 + index.cell + 2.0 * index.overhang;
        const double ex = std::max({bx0 - gx, 0.0, gx - bx1}), ey = std::max({by0 - gy, 0.0, gy - by1});
        if (ex * ex + ey * ey > reach * reach) continue;
        for (auto k = static_cast<std::size_t>(index.bucket_start[b]); k < static_cast<std::size_t>(index.bucket_start[b + 1]); ++k) {
          const double z_lo = index.z_min[k] - gz, z_hi = index.z_max[k] - gz;
          if (z_lo > reach || z_hi < -reach) continue;
          const double pax = index.ax[k] - gx, pay = index.ay[k] - gy;
          const double pbx = index.bx[k] - gx, pby = index.by[k] - gy;
          const double pcx = index.cx[k] - gx, pcy = index.cy[k] - gy;
          // rho_min: 0 when g's vertical passes through the triangle's footprint, else the
          // distance to its nearest edge (a vertical wall's footprint is a segment).
          const double ab = pax * pby - pay * pbx, bc = pbx * pcy - pby * pcx, ca = pcx * pay - pcy * pax;
          const double twice_area = ab + bc + ca;
          double rho_min;
          if (std::abs(twice_area) > 1e-12 * (1.0 + std::abs(ab) + std::abs(bc) + std::abs(ca)) &&
              ((ab >= 0.0 && bc >= 0.0 && ca >= 0.0) || (ab <= 0.0 && bc <= 0.0 && ca <= 0.0))) {
            rho_min = 0.0;
          } else {
            rho_min = std::sqrt(std::min({segment_distance2(pax, pay, pbx, pby), segment_distance2(pbx, pby, pcx, pcy),
                                          segment_distance2(pcx, pcy, pax, pay)}));
          }
          if (rho_min > reach) continue;
          const double rho_max = std::sqrt(std::max({pax * pax + pay * pay, pbx * pbx + pby * pby, pcx * pcx + pcy * pcy}));
          const double hi = z_hi >= 0.0 ? (rho_min > 0.0 ? z_hi / rho_min : kInf) : z_hi / rho_max;
          const double lo = z_lo <= 0.0 ? (rho_min > 0.0 ? z_lo / rho_min : -kInf) : z_lo / rho_max;
          // Azimuth span (under pi when g's vertical misses the footprint).
          const double a0 = azimuth_of(pax, pay);
          auto relative = [&](double x, double y) {
            double d = azimuth_of(x, y) - a0;
            if (d > kPi) d -= kTwoPi;
            if (d <= -kPi) d += kTwoPi;
            return d;
          };
          const double d1 = relative(pbx, pby), d2 = relative(pcx, pcy);
          const double span_lo = a0 + std::min({0.0, d1, d2}), span_hi = a0 + std::max({0.0, d1, d2});
          if (rho_min <= 1e-9 || span_hi - span_lo > kPi - 1e-3) {
            every_lo = std::min(every_lo, lo);
            every_hi = std::max(every_hi, hi);
            found.push_back({index.face[k], true, sine_of_tangent(lo) - kSineSlack, sine_of_tangent(hi) + kSineSlack,
                             0.0, kTwoPi});
            continue;
          }
          found.push_back({index.face[k], false, sine_of_tangent(lo) - kSineSlack, sine_of_tangent(hi) + kSineSlack,
                           span_lo - kAngleSlack, span_hi + kAngleSlack});
          const int j0 = static_cast<int>(std::floor((span_lo - kAngleSlack) / d_az));
          const int j1 = static_cast<int>(std::floor((span_hi + kAngleSlack) / d_az));
          for (int j = j0; j <= j1; ++j) {
            const auto c = static_cast<std::size_t>(j < 0 ? j + na : (j >= na ? j - na : j));
            col_lo[c] = std::min(col_lo[c], lo);
            col_hi[c] = std::max(col_hi[c], hi);
          }
        }
      }
    }
  };
  if (index.size() > 0) {
    const double margin = reach + index.overhang;
    const int ix0 = std::max(0, static_cast<int>(std::floor((gx - margin - index.x0) / index.cell)));
    const int ix1 = std::min(index.nx - 1, static_cast<int>(std::floor((gx + margin - index.x0) / index.cell)));
    const int iy0 = std::max(0, static_cast<int>(std::floor((gy - margin - index.y0) / index.cell)));
    const int iy1 = std::min(index.ny - 1, static_cast<int>(std::floor((gy + margin - index.y0) / index.cell)));
    if (parallel && iy1 > iy0) {
      // Alternate rows on the two threads (halves of the rows were uneven: g's surroundings fill
      // some rows more than others), their footprints then joined in row order: the list a
      // serial pass makes, so that corner_hits breaks ties the same way.
      half_lo.assign(static_cast<std::size_t>(na), kInf);
      half_hi.assign(static_cast<std::size_t>(na), -kInf);
      double half_all_lo = kInf, half_all_hi = -kInf;
      for (std::size_t part = 0; part < 2; ++part) {
        split_footprints[part].clear();
        split_row_ends[part].clear();
      }
      tbb::parallel_invoke(
          [&] {
            scan(ix0, ix1, iy0, 2, iy1 + 1, sin_lo, sin_hi, all_lo, all_hi, split_footprints[0], &split_row_ends[0]);
          },
          [&] {
            scan(ix0, ix1, iy0 + 1, 2, iy1 + 1, half_lo, half_hi, half_all_lo, half_all_hi, split_footprints[1],
                 &split_row_ends[1]);
          });
      for (std::size_t part = 0; part < 2; ++part)
        split_row_ends[part].push_back(static_cast<std::uint32_t>(split_footprints[part].size()));
      std::array<std::uint32_t, 2> taken{0, 0};
      for (int iy = iy0; iy <= iy1; ++iy) {
        const auto part = static_cast<std::size_t>((iy - iy0) % 2);
        const std::uint32_t end = split_row_ends[part][static_cast<std::size_t>((iy - iy0) / 2)];
        footprints.insert(footprints.end(), split_footprints[part].begin() + taken[part],
                          split_footprints[part].begin() + end);
        taken[part] = end;
      }
      for (std::size_t c = 0; c < sin_lo.size(); ++c) {
        sin_lo[c] = std::min(sin_lo[c], half_lo[c]);
        sin_hi[c] = std::max(sin_hi[c], half_hi[c]);
      }
      all_lo = std::min(all_lo, half_all_lo);
      all_hi = std::max(all_hi, half_all_hi);
    } else {
      scan(ix0, ix1, iy0, 1, iy1 + 1, sin_lo, sin_hi, all_lo, all_hi, footprints, nullptr);
    }
  }
  for (std::size_t c = 0; c < sin_lo.size(); ++c) {
    const double lo = std::min(sin_lo[c], all_lo), hi = std::max(sin_hi[c], all_hi);
    sin_lo[c] = lo == kInf ? 2.0 : sine_of_tangent(lo) - kSineSlack;
    sin_hi[c] = hi == -kInf ? -2.0 : sine_of_tangent(hi) + kSineSlack;
  }
}

}  // namespace vistrack::detail
