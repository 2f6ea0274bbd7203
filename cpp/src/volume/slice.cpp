// Visibility polygons: plane slices of a VV mesh with CGAL's Polygon_mesh_slicer (section IV,
// "the VVs are then sliced along a constant altitude plane z = h_UAV [24]").
// Boost.Graph's edge descriptors inside the slicer trip GCC 12's -Wmaybe-uninitialized (a false
// positive in third-party code instantiated here).
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_slicer.h>

#include <array>
#include <cstdint>

#include <algorithm>
#include <cmath>
#include <limits>
#include <list>
#include <vector>

#include "volume/cgal_mesh.hpp"
#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"
#include "vistrack/volume.hpp"

namespace vistrack {

namespace {

using Polyline = std::vector<detail::CgalKernel::Point_3>;

// An altitude at least `clearance` away from every vertex height (the slicer returns many open
// pieces when the plane passes through vertices).
double nudged_altitude(const TriangleMesh& mesh, double altitude, double clearance) {
  std::vector<double> heights(static_cast<std::size_t>(mesh.vertices.rows()));
  for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i) heights[static_cast<std::size_t>(i)] = mesh.vertices(i, 2);
  std::sort(heights.begin(), heights.end());
  auto clear = [&](double z) {
    const auto it = std::lower_bound(heights.begin(), heights.end(), z - clearance);
    return it == heights.end() || *it > z + clearance;
  };
  if (clear(altitude)) return altitude;
  for (int k = 1; k < 1000; ++k)
    for (double sign : {1.0, -1.0}) {
      const double z = altitude + sign * 2.5 * k * clearance;
      if (clear(z)) return z;
    }
  return altitude;
}

Ring to_ring(const Polyline& line, double tolerance) {
  Ring ring;
  for (const auto& p : line) {
    const Vec2 q(p.x(), p.y());
    if (ring.empty() || (q - ring.back()).norm() > tolerance) ring.push_back(q);
  }
  while (ring.size() > 1 && (ring.front() - ring.back()).norm() <= tolerance) ring.pop_back();
  return ring;
}

}  // namespace

std::vector<Ring> slice_rings(const TriangleMesh& mesh, double altitude) {
  require_coordinate(altitude, "altitude");
  std::vector<Ring> rings;
  if (mesh.faces.rows() == 0) return rings;
  const double scale = std::max(1.0, (mesh.vertices.colwise().maxCoeff() - mesh.vertices.colwise().minCoeff()).norm());
  const double z = nudged_altitude(mesh, altitude, 1e-9 * scale + 1e-7);
  // Only the faces that cross the plane matter: slicing that band of faces instead of the whole
  // mesh saves building the slicer's AABB tree over every face (a VV has ~10^5).
  std::vector<detail::CgalKernel::Point_3> points;
  std::vector<std::array<std::size_t, 3>> polygons;
  std::vector<std::size_t> remap(static_cast<std::size_t>(mesh.vertices.rows()), SIZE_MAX);
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f) {
    int below = 0;
    for (int c = 0; c < 3; ++c) below += mesh.vertices(mesh.faces(f, c), 2) < z ? 1 : 0;
    if (below == 0 || below == 3) continue;
    std::array<std::size_t, 3> face{};
    for (int c = 0; c < 3; ++c) {
      const auto v = static_cast<std::size_t>(mesh.faces(f, c));
      if (remap[v] == SIZE_MAX) {
        remap[v] = points.size();
        points.emplace_back(mesh.vertices(mesh.faces(f, c), 0), mesh.vertices(mesh.faces(f, c), 1),
                            mesh.vertices(mesh.faces(f, c), 2));
      }
      face[static_cast<std::size_t>(c)] = remap[v];
    }
    polygons.push_back(face);
  }
  if (polygons.empty()) return rings;
  // The band may touch itself at vertices away from the plane: split those (edges crossing the
  // plane, which carry the slice from face to face, are untouched).
  CGAL::Polygon_mesh_processing::orient_polygon_soup(points, polygons);
  detail::CgalMesh sm;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, sm);
  CGAL::Polygon_mesh_slicer<detail::CgalMesh, detail::CgalKernel> slicer(sm);
  std::list<Polyline> polylines;
  slicer(detail::CgalKernel::Plane_3(0, 0, 1, -z), std::back_inserter(polylines));

  const double tolerance = 1e-9 * scale;
  std::vector<Ring> open;
  for (const Polyline& line : polylines) {
    if (line.size() < 2) continue;
    const bool closed = line.size() > 2 && CGAL::squared_distance(line.front(), line.back()) <= tolerance * tolerance;
    Ring ring = to_ring(line, tolerance);
    if (closed) {
      if (ring.size() >= 3) rings.push_back(std::move(ring));
    } else {
      // Keep the end points of open pieces exactly as given, for chaining.
      Ring piece;
      for (const auto& p : line) {
        const Vec2 q(p.x(), p.y());
        if (piece.empty() || (q - piece.back()).norm() > tolerance) piece.push_back(q);
      }
      if (piece.size() >= 2) open.push_back(std::move(piece));
    }
  }
  // Chain open pieces end to end (either direction) until each closes.
  const double join = 1e-7 * scale;
  std::vector<char> used(open.size(), 0);
  for (std::size_t start = 0; start < open.size(); ++start) {
    if (used[start]) continue;
    used[start] = 1;
    Ring chain = open[start];
    bool extended = true;
    while (extended && (chain.front() - chain.back()).norm() > join) {
      extended = false;
      for (std::size_t k = 0; k < open.size(); ++k) {
        if (used[k]) continue;
        const Ring& piece = open[k];
        if ((piece.front() - chain.back()).norm() <= join) {
          chain.insert(chain.end(), piece.begin() + 1, piece.end());
        } else if ((piece.back() - chain.back()).norm() <= join) {
          chain.insert(chain.end(), piece.rbegin() + 1, piece.rend());
        } else {
          continue;
        }
        used[k] = 1;
        extended = true;
        break;
      }
    }
    if ((chain.front() - chain.back()).norm() > join) continue;  // never closed: a fragment, dropped
    Ring ring;
    for (const Vec2& q : chain)
      if (ring.empty() || (q - ring.back()).norm() > tolerance) ring.push_back(q);
    while (ring.size() > 1 && (ring.front() - ring.back()).norm() <= join) ring.pop_back();
    if (ring.size() >= 3) rings.push_back(std::move(ring));
  }
  rings.erase(std::remove_if(rings.begin(), rings.end(), [](const Ring& r) { return std::abs(signed_area(r)) <= 0.0; }),
              rings.end());
  return rings;
}

std::vector<Polygon> nest_rings(const std::vector<Ring>& rings) {
  const std::size_t n = rings.size();
  std::vector<double> areas(n);
  std::vector<Polygon> as_polygon(n);
  for (std::size_t k = 0; k < n; ++k) {
    areas[k] = std::abs(signed_area(rings[k]));
    as_polygon[k].outer = rings[k];
  }
  // depth = number of rings containing this one (rings from a slice do not cross).
  std::vector<int> depth(n, 0);
  std::vector<std::size_t> parent(n, n);
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b) {
      if (a == b || areas[b] <= areas[a]) continue;
      if (!contains(as_polygon[b], rings[a].front())) continue;
      ++depth[a];
      if (parent[a] == n || areas[b] < areas[parent[a]]) parent[a] = b;
    }
  std::vector<Polygon> polygons;
  std::vector<std::size_t> index_of(n, n);
  for (std::size_t k = 0; k < n; ++k)
    if (depth[k] % 2 == 0) {
      index_of[k] = polygons.size();
      polygons.push_back(Polygon{rings[k], {}});
    }
  for (std::size_t k = 0; k < n; ++k)
    if (depth[k] % 2 == 1 && parent[k] < n && index_of[parent[k]] < n)
      polygons[index_of[parent[k]]].holes.push_back(rings[k]);
  for (Polygon& p : polygons) normalize_orientation(p);
  return polygons;
}

std::optional<double> visibility_slice_height(const VisibilityVolume& vv, double altitude) {
  require_coordinate(altitude, "altitude");
  if (!vv.altitude_band) return altitude;
  const double gap = 1e-6 * std::max(1.0, vv.d_max);
  const auto [low, high] = *vv.altitude_band;
  if (altitude < low - gap || altitude > high + gap) return std::nullopt;
  return std::clamp(altitude, low + gap, high - gap);
}

std::vector<Polygon> visibility_polygon(const VisibilityVolume& vv, double altitude, bool all_parts) {
  detail::require_mesh(vv, "vv");
  const std::optional<double> z = visibility_slice_height(vv, altitude);
  if (!z) return {};
  std::vector<Polygon> polygons = nest_rings(slice_rings(vv.mesh, *z));
  if (all_parts) return polygons;
  const Vec2 center = vv.poi.head<2>();
  std::vector<Polygon> kept;
  for (Polygon& p : polygons)
    if (contains(p, center)) kept.push_back(std::move(p));
  return kept;
}

}  // namespace vistrack
