// alpha(g) of eq. (4) (section III.D) on a direction grid: Embree rays give the visible interval
// per direction, and the grid corners' intervals give a closed radial mesh.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "visibility/embree_scene.hpp"
#include "visibility/radial_mesh.hpp"
#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"
#include "vistrack/visibility.hpp"

namespace vistrack {

namespace {

using detail::Interval;
using detail::Setup;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kBandTolerance = 1e-3;  // m: a POI this close to a band face counts as inside the band

void validate(const VisibilityScene& scene, const Vec3& g, double d_max,
              const std::optional<std::pair<double, double>>& band, const std::string& g_field) {
  for (int k = 0; k < 3; ++k) require_coordinate(g[k], g_field + "[" + std::to_string(k) + "]");
  require_length(d_max, "d_max");
  if (band) {
    require_coordinate(band->first, "altitude_band[0]");
    require_coordinate(band->second, "altitude_band[1]");
    if (!(band->first < band->second))
      detail::fail_field("altitude_band", "(" + detail::to_text(band->first) + ", " + detail::to_text(band->second) + ")",
                         "h_lo must be below h_hi");
  }
  if (g.z() < scene.ground_level() - 1e-9)
    detail::fail_field(g_field + "[2]", g.z(), "below the ground level " + detail::to_text(scene.ground_level()));
  if (scene.inside_obstacle(g))
    detail::fail_field(g_field, "(" + detail::to_text(g.x()) + ", " + detail::to_text(g.y()) + ", " + detail::to_text(g.z()) + ")",
                       "the POI lies inside an obstacle");
}

// Sines of the elevations of the mesh's vertex rows: the grid's cell boundaries (exactly 0 on the
// horizon), plus the creases of the open-field VV, which are latitude circles about g: where the
// sphere r = d_max meets the band planes and the ground (sin el = (z - g.z) / d_max). A vertex
// row on each crease keeps the caps' rims exact instead of cutting the corner across a cell;
// grid rows closer than a quarter step to a crease are dropped (no slivers), except the horizon.
std::vector<double> vertex_row_sines(const DirectionGrid& grid, const Setup& s) {
  const int ne = grid.num_elevation;
  const double step = kPi / ne;
  std::vector<double> creases;
  std::vector<double> planes = {s.ground};
  if (s.has_band) {
    planes.push_back(s.low);
    planes.push_back(s.high);
  }
  for (double z : planes) {
    const double c = (z - s.g.z()) / s.d_max;
    if (std::abs(c) < 1.0 - 1e-9 && c != 0.0) creases.push_back(std::asin(c));
  }
  std::vector<double> elevations;
  for (int i = 0; i <= ne; ++i) {
    const double el = (2 * i - ne) * kPi / (2.0 * ne);  // exactly 0 on the horizon row
    bool near_crease = false;
    for (double e : creases) near_crease = near_crease || std::abs(e - el) < 0.25 * step;
    if (i == 0 || i == ne || 2 * i == ne || !near_crease) elevations.push_back(el);
  }
  // The horizon row always stays, so a crease just below it (the ground seen from a POI a little
  // above it: asin(-h / d_max)) gets its own thin row rather than none: the linear surface from
  // the sphere at the horizon to the ground a row below would lose 0.2 % of a Charlotte VV.
  for (double e : creases)
    if (std::abs(e) > 1e-9 && std::abs(std::abs(e) - kPi / 2.0) > 0.25 * step) elevations.push_back(e);
  std::sort(elevations.begin(), elevations.end());
  elevations.erase(std::unique(elevations.begin(), elevations.end(), [](double a, double b) { return std::abs(a - b) < 1e-12; }),
                   elevations.end());
  std::vector<double> sines;
  for (std::size_t k = 0; k < elevations.size(); ++k) {
    const double el = elevations[k];
    if (k == 0) sines.push_back(-1.0);
    else if (k + 1 == elevations.size()) sines.push_back(1.0);
    else if (el == 0.0) sines.push_back(0.0);
    else sines.push_back(std::sin(el));
  }
  // A crease row's sine is set exactly: its corner rays meet sphere and plane at the same point.
  for (double z : planes) {
    const double c = (z - s.g.z()) / s.d_max;
    for (std::size_t k = 1; k + 1 < sines.size(); ++k)
      if (std::abs(sines[k] - c) < 1e-12) sines[k] = c;
  }
  return sines;
}

// The visible interval of each ray k < n from g along direction_of(k) (unit), handed to
// store(k, interval). Traced in parallel chunks of neighbouring directions, 64 per
// rtcIntersect1M call; rays end where the band, the ground or d_max end the interval anyway, and
// rays with nothing to see there are not traced at all.
template <class DirectionOf, class Store>
void trace_intervals(const detail::EmbreeScene& embree, const Setup& s, std::size_t n, DirectionOf direction_of,
                     Store store) {
  const auto t_far = static_cast<float>(s.d_max);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 2048), [&](const tbb::blocked_range<std::size_t>& r) {
    detail::FlushDenormals flush;
    constexpr std::size_t kChunk = 64;
    std::array<float, 3 * kChunk> rays{};
    std::array<float, kChunk> t{}, t_max{};
    std::array<bool, kChunk> ground{};
    std::array<std::size_t, kChunk> slot{};
    std::array<Vec3, kChunk> d;
    std::array<double, kChunk> hit{};
    for (std::size_t start = r.begin(); start < r.end(); start += kChunk) {
      const std::size_t count = std::min(kChunk, r.end() - start);
      std::size_t traced = 0;
      for (std::size_t k = 0; k < count; ++k) {
        d[k] = direction_of(start + k);
        hit[k] = kInf;
        const Interval bound = detail::visible_interval(s, d[k].z(), kInf);
        if (!(bound.far > bound.near)) continue;
        for (int c = 0; c < 3; ++c) rays[3 * traced + c] = static_cast<float>(d[k][c]);
        t_max[traced] = static_cast<float>(bound.far) * (1.0f + 1e-6f);
        slot[traced++] = k;
      }
      embree.trace(s.g, rays.data(), traced, 0.0f, t_far, t.data(), ground.data(), t_max.data());
      // Ground hits are dropped: the ground is applied exactly, and a ray grazing the ground
      // plane from a POI on it must not stop.
      for (std::size_t m = 0; m < traced; ++m)
        if (!ground[m]) hit[slot[m]] = static_cast<double>(t[m]);
      for (std::size_t k = 0; k < count; ++k) store(start + k, detail::visible_interval(s, d[k].z(), hit[k]));
    }
  });
}

VisibilityVolume compute(const VisibilityScene& scene, const Vec3& g, double d_max,
                         const std::optional<std::pair<double, double>>& band, double resolution_deg) {
  VisibilityVolume vv;
  vv.poi = g;
  vv.d_max = d_max;
  vv.altitude_band = band;
  vv.grid = DirectionGrid::from_resolution(resolution_deg);
  const int na = vv.grid.num_azimuth;

  Setup s;
  s.g = g;
  s.d_max = d_max;
  s.ground = scene.ground_level();
  if (band) {
    s.has_band = true;
    s.low = band->first;
    s.high = band->second;
    s.poi_in_band = g.z() >= s.low - kBandTolerance && g.z() <= s.high + kBandTolerance;
  }

  // Rays: every cell's sample ray (the grid's intervals), then every corner of the sphere grid (the
  // mesh); the star mesh traces more rays where it locates jumps.
  const std::vector<double> row_sines = vertex_row_sines(vv.grid, s);
  const detail::SphereGrid sphere{static_cast<int>(row_sines.size()) - 1, na};
  const detail::Directions dirs(vv.grid, sphere, row_sines);
  const std::size_t n_cells = vv.grid.size();
  const auto n_corners = static_cast<std::size_t>(sphere.num_vertices());
  vv.near.assign(n_cells, 0.0);
  vv.far.assign(n_cells, 0.0);
  std::vector<Interval> corner(n_corners);
  const detail::EmbreeScene& embree = detail::EmbreeScene::of(scene);
  trace_intervals(embree, s, n_cells + n_corners, [&](std::size_t k) { return dirs.ray(k); },
                  [&](std::size_t k, const Interval& iv) {
                    if (k >= n_cells) {
                      corner[k - n_cells] = iv;
                    } else if (iv.far > iv.near) {
                      vv.near[k] = iv.near;
                      vv.far[k] = iv.far;
                    }
                  });
  if (s.poi_in_band) {
    const detail::IntervalTracer tracer = [&](const std::vector<Vec3>& directions) {
      std::vector<Interval> out(directions.size());
      trace_intervals(embree, s, directions.size(), [&](std::size_t k) { return directions[k]; },
                      [&](std::size_t k, const Interval& iv) { out[k] = iv; });
      return out;
    };
    vv.mesh = detail::build_star_mesh(s, sphere, dirs, corner, tracer, vv.volume, vv.mesh_triangle_faces);
    vv.mesh_row_sines = row_sines;
  } else {
    vv.mesh = detail::build_shell_mesh(s, sphere, dirs, corner, vv.volume);
  }
  return vv;
}

}  // namespace

VisibilityVolume visibility_volume(const VisibilityScene& scene, const Vec3& g, double d_max,
                                   std::optional<std::pair<double, double>> altitude_band, double resolution_deg) {
  validate(scene, g, d_max, altitude_band, "g");
  (void)DirectionGrid::from_resolution(resolution_deg);
  return compute(scene, g, d_max, altitude_band, resolution_deg);
}

VisibilityVolume visibility_volume(const Environment& env, const Vec3& g, double d_max,
                                   std::optional<std::pair<double, double>> altitude_band, double resolution_deg) {
  return visibility_volume(VisibilityScene(env), g, d_max, altitude_band, resolution_deg);
}

std::vector<VisibilityVolume> visibility_volumes(const VisibilityScene& scene, const Points3& pois, double d_max,
                                                 std::optional<std::pair<double, double>> altitude_band,
                                                 double resolution_deg) {
  (void)DirectionGrid::from_resolution(resolution_deg);
  // Validate every point first, on the calling thread, so the error names the row.
  for (Eigen::Index k = 0; k < pois.rows(); ++k)
    validate(scene, pois.row(k).transpose(), d_max, altitude_band, "pois[" + std::to_string(k) + "]");
  std::vector<VisibilityVolume> result(static_cast<std::size_t>(pois.rows()));
  tbb::parallel_for(Eigen::Index{0}, pois.rows(), [&](Eigen::Index k) {
    result[static_cast<std::size_t>(k)] = compute(scene, pois.row(k).transpose(), d_max, altitude_band, resolution_deg);
  });
  return result;
}

}  // namespace vistrack
