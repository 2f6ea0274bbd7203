// alpha(g) of eq. (4) (section III.D) on a direction grid: the first obstacle hit per direction
// (per-triangle tests at the grid corners, Embree rays elsewhere) gives the visible interval, and
// the grid corners' intervals give a closed radial mesh.
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <string>

#include "visibility/corner_hits.hpp"
#include "visibility/embree_scene.hpp"
#include "visibility/radial_mesh.hpp"
#include "visibility/star_mesh.hpp"
#include "visibility/trace.hpp"
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
  Sensor{d_max, band}.validate("");
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

// Buffers of one VV, kept between VVs (a batch allocates them once per thread).
struct Workspace {
  detail::Clearance clearance;
  detail::CornerHits hits;  // first obstacle hit per corner ray, and the triangle hit
  std::vector<double> corner_far;
  std::vector<detail::Surface> corner_surface;
  std::vector<Interval> corner;  // shell meshes
  std::vector<int> missing_rows;  // grid corner rows that are no vertex row of the mesh
  detail::StarMeshScratch star;
};

// Workspaces lent to the VVs being computed (a pool rather than thread_local: a thread waiting
// inside one VV's parallel loop may start another VV).
class WorkspacePool {
 public:
  std::unique_ptr<Workspace> acquire() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (free_.empty()) return std::make_unique<Workspace>();
    std::unique_ptr<Workspace> w = std::move(free_.back());
    free_.pop_back();
    return w;
  }
  void release(std::unique_ptr<Workspace> w) {
    std::lock_guard<std::mutex> lock(mutex_);
    free_.push_back(std::move(w));
  }

 private:
  std::mutex mutex_;
  std::vector<std::unique_ptr<Workspace>> free_;
};

WorkspacePool& workspaces() {
  static WorkspacePool pool;
  return pool;
}

class WorkspaceLease {
 public:
  WorkspaceLease() : w_(workspaces().acquire()) {}
  ~WorkspaceLease() { workspaces().release(std::move(w_)); }
  WorkspaceLease(const WorkspaceLease&) = delete;
  WorkspaceLease& operator=(const WorkspaceLease&) = delete;
  Workspace& operator*() { return *w_; }

 private:
  std::unique_ptr<Workspace> w_;
};

// The grid's intervals (near/far per grid corner) from the mesh's corner rays: the vertex rows
// are the grid's corner rows plus crease rows, less the grid rows next to a crease, whose corners
// (at most three rows) are traced here.
void grid_intervals(VisibilityVolume& vv, const Setup& s, const detail::SphereGrid& sphere,
                    const std::vector<double>& row_sines, const detail::Directions& dirs,
                    const detail::TraceContext& tracer, Workspace& w) {
  const int ne = vv.grid.num_elevation, na = vv.grid.num_azimuth;
  const auto n = static_cast<std::size_t>(na);
  vv.near.assign(vv.grid.num_corners(), 0.0);
  vv.far.assign(vv.grid.num_corners(), 0.0);
  auto set = [&](std::size_t k, double sin_el, double far_or_hit, const Interval* corner) {
    if (s.poi_in_band) {
      vv.far[k] = std::max(0.0, far_or_hit);
      return;
    }
    const Interval iv = corner != nullptr ? *corner : detail::visible_interval(s, sin_el, far_or_hit);
    if (iv.far > iv.near) {
      vv.near[k] = iv.near;
      vv.far[k] = iv.far;
    }
  };
  w.missing_rows.clear();
  std::size_t v = 0;  // vertex row
  for (int i = 0; i <= ne; ++i) {
    const double sine = detail::corner_sine(i, ne);
    while (v + 1 < row_sines.size() && row_sines[v] < sine - 1e-12) ++v;
    if (std::abs(row_sines[v] - sine) > 1e-12) {
      w.missing_rows.push_back(i);
      continue;
    }
    const int first = sphere.row_first(static_cast<int>(v));
    const bool pole = v == 0 || v + 1 == row_sines.size();
    if (s.poi_in_band && !pole) {
      // A star VV's row as set() writes it, in a loop the compiler vectorizes (near stays 0).
      const double* from = w.corner_far.data() + first;
      double* to = vv.far.data() + static_cast<std::size_t>(i) * n;
      for (std::size_t j = 0; j < n; ++j) to[j] = std::max(0.0, from[j]);
      continue;
    }
    for (std::size_t j = 0; j < n; ++j) {
      const auto c = static_cast<std::size_t>(pole ? first : first + static_cast<int>(j));
      const std::size_t k = static_cast<std::size_t>(i) * n + j;
      if (s.poi_in_band) set(k, sine, w.corner_far[c], nullptr);
      else set(k, sine, 0.0, &w.corner[c]);
    }
  }
  if (w.missing_rows.empty()) return;
  auto ray = [&](std::size_t start, std::size_t count, Vec3* d, int* column) {
    for (std::size_t m = 0; m < count; ++m) {
      const std::size_t r = (start + m) / n, j = (start + m) % n;
      const double sine = detail::corner_sine(w.missing_rows[r], ne);
      const double cosine = std::sqrt(std::max(0.0, 1.0 - sine * sine));
      d[m] = Vec3(cosine * dirs.cos_az_corner[j], cosine * dirs.sin_az_corner[j], sine);
      column[m] = static_cast<int>(j);
    }
  };
  detail::trace_all(tracer, w.missing_rows.size() * n, ray, [&](std::size_t k, const Vec3& d, double hit) {
    const std::size_t r = k / n, j = k % n;
    const std::size_t out = static_cast<std::size_t>(w.missing_rows[r]) * n + j;
    if (s.poi_in_band) {
      detail::Surface surface;
      set(out, d.z(), detail::star_far(s, d.z(), hit, surface), nullptr);
    } else {
      set(out, d.z(), hit, nullptr);
    }
  });
}

// The VV; `parallel` spreads its rays and rows over TBB's threads (the result is the same).
VisibilityVolume compute(const VisibilityScene& scene, const Vec3& g, double d_max,
                         const std::optional<std::pair<double, double>>& band, double resolution_deg, bool parallel,
                         bool with_mesh, VolumeCost* cost = nullptr, bool check_predicted = false) {
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

  // Rays: one per corner of the sphere grid (the mesh and the grid's intervals), answered by the
  // obstacle triangles' footprints (corner_hits); the star mesh traces more with Embree where it
  // locates jumps, except those the clearance bounds show to meet no obstacle.
  const std::vector<double> row_sines = vertex_row_sines(vv.grid, s);
  const detail::SphereGrid sphere{static_cast<int>(row_sines.size()) - 1, na};
  const detail::Directions dirs(sphere, row_sines);
  const auto n_corners = static_cast<std::size_t>(sphere.num_vertices());
  const detail::EmbreeScene& embree = detail::EmbreeScene::of(scene);
  WorkspaceLease lease;
  Workspace& w = *lease;
  detail::PhaseTimer bounds_timer(cost ? &cost->bounds_s : nullptr);
  w.clearance.compute(embree.obstacles, g - embree.origin, d_max, na, parallel);
  bounds_timer.stop();
  detail::RayCounts counts;
  counts.timed = cost != nullptr;
  const detail::TraceContext tracer{embree, s, w.clearance, parallel, &counts};
  detail::PhaseTimer trace_timer(cost ? &cost->trace_s : nullptr);

  // The corner rays' first hits from the triangles' footprints (corner_hits.hpp), not Embree.
  const std::size_t tests = detail::corner_hits(w.clearance, embree.triangles, g - embree.origin, s, sphere, dirs,
                                                parallel, w.hits);
  // Per corner from its hit, on locals (the stores could otherwise alias the row's bounds and the
  // arrays' pointers, reloaded per corner).
  auto each_corner = [&](auto&& store) {
    detail::for_each_index(parallel, sphere.ne + 1, [&](int i) {
      const double sin_el = dirs.sin_el_corner[static_cast<std::size_t>(i)];
      const auto first = static_cast<std::size_t>(sphere.row_first(i));
      const auto end = static_cast<std::size_t>(sphere.row_end(i));
      const double* inverse = w.hits.inverse.data();
      for (std::size_t v = first; v < end; ++v) store(v, sin_el, detail::CornerHits::distance_of(inverse[v]));
    });
  };
  if (s.poi_in_band) {
    w.corner_far.resize(n_corners);
    w.corner_surface.resize(n_corners);
    double* far = w.corner_far.data();
    detail::Surface* surface = w.corner_surface.data();
    each_corner([&](std::size_t k, double sin_el, double hit) { far[k] = detail::star_far(s, sin_el, hit, surface[k]); });
  } else {
    w.corner.resize(n_corners);
    Interval* corner = w.corner.data();
    each_corner([&](std::size_t k, double sin_el, double hit) { corner[k] = detail::visible_interval(s, sin_el, hit); });
  }
  if (cost != nullptr) {
    cost->rays_skipped += n_corners;  // every vertex row's corner ray: no Embree
    cost->corner_tests += tests;
  }
  grid_intervals(vv, s, sphere, row_sines, dirs, tracer, w);
  trace_timer.stop();
  if (s.poi_in_band) {
    detail::build_star_mesh(s, sphere, dirs, w.corner_far, w.corner_surface, w.hits.triangle, tracer, w.star, vv,
                            with_mesh, cost, check_predicted);
    if (with_mesh) vv.mesh_row_sines = row_sines;
  } else {
    // A shell's volume comes from its mesh (few of these: the POI outside the band).
    detail::PhaseTimer mesh_timer(cost ? &cost->mesh_s : nullptr);
    vv.mesh = detail::build_shell_mesh(s, sphere, dirs, w.corner, vv.volume);
    if (!with_mesh) vv.mesh = TriangleMesh{};
  }
  vv.has_mesh = with_mesh;
  if (cost != nullptr) {
    cost->rays_traced += counts.traced;  // the grid's corner rows that are no vertex rows (grid_intervals)
    cost->rays_skipped += counts.skipped;
    cost->embree_s += 1e-9 * static_cast<double>(counts.embree_ns.load());
  }
  return vv;
}

}  // namespace

VisibilityVolume visibility_volume(const VisibilityScene& scene, const Vec3& g, double d_max,
                                   std::optional<std::pair<double, double>> altitude_band, double resolution_deg,
                                   bool with_mesh) {
  validate(scene, g, d_max, altitude_band, "g");
  (void)DirectionGrid::from_resolution(resolution_deg);
  // One VV alone: its rays and rows over every thread, isolated so that a thread waiting in it
  // takes no unrelated task.
  VisibilityVolume vv;
  tbb::this_task_arena::isolate([&] { vv = compute(scene, g, d_max, altitude_band, resolution_deg, true, with_mesh); });
  return vv;
}

VisibilityVolume visibility_volume_with_cost(const VisibilityScene& scene, const Vec3& g, double d_max,
                                             std::optional<std::pair<double, double>> altitude_band,
                                             double resolution_deg, VolumeCost& cost, bool parallel,
                                             bool check_predicted, bool with_mesh) {
  validate(scene, g, d_max, altitude_band, "g");
  (void)DirectionGrid::from_resolution(resolution_deg);
  VisibilityVolume vv;
  tbb::this_task_arena::isolate(
      [&] { vv = compute(scene, g, d_max, altitude_band, resolution_deg, parallel, with_mesh, &cost, check_predicted); });
  return vv;
}

VisibilityVolume visibility_volume(const Environment& env, const Vec3& g, double d_max,
                                   std::optional<std::pair<double, double>> altitude_band, double resolution_deg,
                                   bool with_mesh) {
  return visibility_volume(VisibilityScene(env), g, d_max, altitude_band, resolution_deg, with_mesh);
}

void detail::require_mesh(const VisibilityVolume& vv, const std::string& field) {
  if (!vv.has_mesh)
    throw Error(field + ": a VV computed without its mesh (with_mesh = false; its intervals and volume only): "
                "compute it with its mesh to read its mesh, slice it, save it or XOR it (but on the grid)");
}

double volume_bytes(double resolution_deg, bool with_mesh) {
  const DirectionGrid grid = DirectionGrid::from_resolution(resolution_deg);
  // Near and far per corner (16 bytes); per cell about one mesh vertex (24), two faces (24) and
  // their slots (8); the walls' and splits' vertices and faces follow the silhouettes, whose length
  // in cells grows as sqrt(cells): a ground POI in uptown Charlotte takes 2.5k sqrt(cells) bytes
  // at 5 degrees, 1.0k at 1 and 0.8k at 0.25 (test_visibility checks the estimate from above).
  const double cells = static_cast<double>(grid.size());
  const double intervals = 16.0 * static_cast<double>(grid.num_corners());
  return with_mesh ? intervals + 56.0 * cells + 3000.0 * std::sqrt(cells) : intervals;
}

std::vector<VisibilityVolume> visibility_volumes(const VisibilityScene& scene, const Points3& pois, double d_max,
                                                 std::optional<std::pair<double, double>> altitude_band,
                                                 double resolution_deg, bool with_mesh) {
  const double each = volume_bytes(resolution_deg, with_mesh);
  const double count = static_cast<double>(pois.rows());
  require_work_bytes(count * each, "pois", detail::to_text(count) + " points",
                     "their VVs (" + limits::bytes_text(each) + " each at resolution_deg " +
                         detail::to_text(resolution_deg) + ")",
                     "fewer points per call (batches of " +
                         detail::to_text(std::floor(limits::kMaxWorkBytes / each)) + " fit) or a coarser resolution_deg");
  // Validate every point first, on the calling thread, so the error names the row.
  for (Eigen::Index k = 0; k < pois.rows(); ++k)
    validate(scene, pois.row(k).transpose(), d_max, altitude_band, "pois[" + std::to_string(k) + "]");
  std::vector<VisibilityVolume> result(static_cast<std::size_t>(pois.rows()));
  // One VV per thread; a batch smaller than the thread count also spreads each VV.
  const bool parallel_inside = pois.rows() < tbb::this_task_arena::max_concurrency();
  tbb::parallel_for(Eigen::Index{0}, pois.rows(), [&](Eigen::Index k) {
    result[static_cast<std::size_t>(k)] = compute(scene, pois.row(k).transpose(), d_max, altitude_band, resolution_deg,
                                                  parallel_inside, with_mesh);
  });
  return result;
}

}  // namespace vistrack
