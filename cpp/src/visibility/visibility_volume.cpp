// alpha(g) of eq. (4) (section III.D) on a direction grid: Embree rays give the visible interval
// per direction, and the grid corners' intervals give a closed radial mesh.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

#include "visibility/embree_scene.hpp"
#include "vistrack/error.hpp"
#include "vistrack/visibility.hpp"

namespace vistrack {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kBandTolerance = 1e-3;  // m: a POI this close to a band face counts as inside the band

// Which surface ends a visible interval: the position of a mesh vertex on a band cap or on the
// ground gets that surface's exact z.
enum class Surface : unsigned char { radial, band_low, band_high, ground };

struct Setup {
  Vec3 g;
  double d_max = 0.0;
  bool has_band = false;
  double low = 0.0;
  double high = 0.0;
  double ground = 0.0;
  bool poi_in_band = true;  // near = 0 along every ray (the VV is star-shaped about g)
};

struct Interval {
  double near = 0.0;
  double far = 0.0;
  Surface near_surface = Surface::radial;
  Surface far_surface = Surface::radial;
  // 1/near and 1/far without clamping (<= 0: the band is never entered). For a plane z = c the
  // inverse distance along g + t d is d.z / (c - g.z), linear in d: the shell mesh interpolates
  // these to find where the visible interval closes between two directions.
  double inv_near = 0.0;
  double inv_far = 0.0;
};

constexpr double kHugeInverse = 1e30;  // 1/t for t = 0 (kept finite for the interpolation)

// The visible part of the ray g + t d (|d| = 1, d.z = sin_el) given the first obstacle hit.
Interval visible_interval(const Setup& s, double sin_el, double obstacle_hit) {
  Interval iv;
  iv.far = std::min(s.d_max, obstacle_hit);
  iv.inv_far = 1.0 / iv.far;
  if (sin_el < 0.0) {
    const double t_ground = std::max(0.0, (s.ground - s.g.z()) / sin_el);
    if (t_ground < iv.far) {
      iv.far = t_ground;
      iv.far_surface = Surface::ground;
      iv.inv_far = t_ground > 0.0 ? 1.0 / t_ground : kHugeInverse;
    }
  }
  if (s.has_band) {
    double enter = -kInf;
    double exit = kInf;
    Surface enter_surface = Surface::radial;
    Surface exit_surface = Surface::radial;
    double z_enter = s.low, z_exit = s.high;  // planes met first and last going up
    if (sin_el > 0.0) {
      enter = (s.low - s.g.z()) / sin_el;
      exit = (s.high - s.g.z()) / sin_el;
      enter_surface = Surface::band_low;
      exit_surface = Surface::band_high;
    } else if (sin_el < 0.0) {
      enter = (s.high - s.g.z()) / sin_el;
      exit = (s.low - s.g.z()) / sin_el;
      enter_surface = Surface::band_high;
      exit_surface = Surface::band_low;
    } else if (!s.poi_in_band) {
      exit = -kInf;  // a horizontal ray from outside the band never enters it
    }
    if (exit < iv.far) {
      iv.far = exit;
      iv.far_surface = exit_surface;
    }
    if (!s.poi_in_band && enter > iv.near) {
      iv.near = enter;
      iv.near_surface = enter_surface;
    }
    if (!s.poi_in_band) {
      // The POI is below (or above) the band: it is entered through the near plane and left
      // through the far one, for upward (downward) rays only.
      if (s.g.z() > s.high) std::swap(z_enter, z_exit);
      iv.inv_near = sin_el / (z_enter - s.g.z());
      iv.inv_far = std::max(iv.inv_far, sin_el / (z_exit - s.g.z()));
    }
  }
  return iv;
}

Vec3 point_on(const Setup& s, const Vec3& d, double t, Surface surface) {
  Vec3 p = s.g + t * d;
  if (surface == Surface::band_low) p.z() = s.low;
  if (surface == Surface::band_high) p.z() = s.high;
  if (surface == Surface::ground) p.z() = s.ground;
  return p;
}

void validate(const VisibilityScene& scene, const Vec3& g, double d_max,
              const std::optional<std::pair<double, double>>& band, const std::string& g_field) {
  for (int k = 0; k < 3; ++k) require_finite(g[k], g_field + "[" + std::to_string(k) + "]");
  require_positive(d_max, "d_max");
  if (band) {
    require_finite(band->first, "altitude_band[0]");
    require_finite(band->second, "altitude_band[1]");
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

// The triangulated sphere of grid corners. Vertex rows i = 0..ne at elevations
// -pi/2 + i pi/ne (rows 0 and ne are the poles), columns j at azimuths j d_az. Quad (i, j) splits
// into Ta = [(i,j), (i,j+1), (i+1,j+1)] (absent at the south pole row) and
// Tb = [(i,j), (i+1,j+1), (i+1,j)] (absent at the north pole row), both outward oriented.
struct SphereGrid {
  int ne = 0;
  int na = 0;
  int num_vertices() const { return 2 + (ne - 1) * na; }
  int vertex(int i, int j) const {
    if (i <= 0) return 0;
    if (i >= ne) return num_vertices() - 1;
    return 1 + (i - 1) * na + wrap(j);
  }
  // Column index modulo na for j in [-1, na] (no division in the hot loops).
  int wrap(int j) const { return j < 0 ? j + na : (j >= na ? j - na : j); }
  int ta(int i, int j) const { return 2 * (i * na + wrap(j)); }
  int tb(int i, int j) const { return 2 * (i * na + wrap(j)) + 1; }
  int num_triangle_slots() const { return 2 * ne * na; }
  bool exists(int t) const {
    const int i = (t / 2) / na;
    return (t % 2 == 0) ? i >= 1 : i <= ne - 2;
  }
  std::array<int, 3> corners(int t) const {
    const int q = t / 2;
    const int i = q / na;
    const int j = q % na;
    if (t % 2 == 0) return {vertex(i, j), vertex(i, j + 1), vertex(i + 1, j + 1)};
    return {vertex(i, j), vertex(i + 1, j + 1), vertex(i + 1, j)};
  }
  // The triangle across edge e (corner e to corner e+1) of triangle t.
  int neighbour(int t, int e) const {
    const int q = t / 2;
    const int i = q / na;
    const int j = q % na;
    if (t % 2 == 0) {
      if (e == 0) return tb(i - 1, j);
      if (e == 1) return i <= ne - 2 ? tb(i, j + 1) : ta(ne - 1, j + 1);
      return i <= ne - 2 ? tb(i, j) : ta(ne - 1, j - 1);
    }
    if (e == 0) return i >= 1 ? ta(i, j) : tb(0, j + 1);
    if (e == 1) return ta(i + 1, j);
    return i >= 1 ? ta(i, j - 1) : tb(0, j - 1);
  }
  // Existing triangles around vertex (i, j) in cyclic order.
  int ring(int v, std::array<int, 6>& out, std::vector<int>& pole_ring) const {
    if (v == 0 || v == num_vertices() - 1) {
      pole_ring.clear();
      for (int j = 0; j < na; ++j) pole_ring.push_back(v == 0 ? tb(0, j) : ta(ne - 1, j));
      return -1;
    }
    const int i = 1 + (v - 1) / na;
    const int j = (v - 1) % na;
    const std::array<int, 6> all{ta(i, j), tb(i, j), ta(i, j - 1), tb(i - 1, j - 1), ta(i - 1, j - 1), tb(i - 1, j)};
    int n = 0;
    for (int t : all)
      if (exists(t)) out[static_cast<std::size_t>(n++)] = t;
    return n;
  }
};

// Unit directions of the grid's cell centres and of the sphere grid's corners, from trig tables.
struct Directions {
  const DirectionGrid& grid;
  const SphereGrid& sphere;
  std::vector<double> cos_el_cell, sin_el_cell, cos_az_cell, sin_az_cell;
  std::vector<double> cos_el_corner, sin_el_corner, cos_az_corner, sin_az_corner;

  // sin_el_rows: sines of the mesh's vertex-row elevations, from -1 (south pole) to 1.
  Directions(const DirectionGrid& g, const SphereGrid& s, const std::vector<double>& sin_el_rows)
      : grid(g), sphere(s) {
    const int ne = g.num_elevation;
    const int na = g.num_azimuth;
    const double d_az = kTwoPi / na;
    for (int i = 0; i < ne; ++i) {
      cos_el_cell.push_back(std::cos(g.elevation(i)));
      sin_el_cell.push_back(std::sin(g.elevation(i)));
    }
    for (double se : sin_el_rows) {
      sin_el_corner.push_back(se);
      cos_el_corner.push_back(std::sqrt(std::max(0.0, 1.0 - se * se)));
    }
    for (int j = 0; j < na; ++j) {
      cos_az_cell.push_back(std::cos((j + 0.5) * d_az));
      sin_az_cell.push_back(std::sin((j + 0.5) * d_az));
      cos_az_corner.push_back(std::cos(j * d_az));
      sin_az_corner.push_back(std::sin(j * d_az));
    }
  }
  std::size_t num_cells() const { return grid.size(); }
  // Ray k: the cell centres first (k = i * na + j), then the corners (k - num_cells).
  Vec3 ray(std::size_t k) const {
    const auto na = static_cast<std::size_t>(grid.num_azimuth);
    if (k < num_cells()) {
      const std::size_t i = k / na, j = k % na;
      return {cos_el_cell[i] * cos_az_cell[j], cos_el_cell[i] * sin_az_cell[j], sin_el_cell[i]};
    }
    return corner(static_cast<int>(k - num_cells()));
  }
  Vec3 corner(int v) const {
    if (v == 0) return {0.0, 0.0, -1.0};
    if (v == sphere.num_vertices() - 1) return {0.0, 0.0, 1.0};
    const int i = 1 + (v - 1) / sphere.na;
    const int j = (v - 1) % sphere.na;
    return {cos_el_corner[i] * cos_az_corner[j], cos_el_corner[i] * sin_az_corner[j], sin_el_corner[i]};
  }
};

// Writes vertices and faces straight into the mesh's arrays (sized for the worst case, trimmed at
// the end) and sums the volume on the way: signed tetrahedra against g (divergence theorem).
class MeshBuilder {
 public:
  MeshBuilder(const Vec3& g, Eigen::Index max_points, Eigen::Index max_faces) : g_(g) {
    mesh_.vertices.resize(max_points, 3);
    mesh_.faces.resize(max_faces, 3);
  }
  int add(const Vec3& p) {
    mesh_.vertices.row(num_points_) = p.transpose();
    return static_cast<int>(num_points_++);
  }
  void face(int a, int b, int c) {
    mesh_.faces.row(num_faces_) << a, b, c;
    ++num_faces_;
    const Vec3 pa = mesh_.vertices.row(a).transpose() - g_;
    const Vec3 pb = mesh_.vertices.row(b).transpose() - g_;
    const Vec3 pc = mesh_.vertices.row(c).transpose() - g_;
    six_volume_ += pa.x() * (pb.y() * pc.z() - pb.z() * pc.y()) - pa.y() * (pb.x() * pc.z() - pb.z() * pc.x()) +
                   pa.z() * (pb.x() * pc.y() - pb.y() * pc.x());
  }
  TriangleMesh finish(double& volume) {
    mesh_.vertices.conservativeResize(num_points_, 3);
    mesh_.faces.conservativeResize(num_faces_, 3);
    volume = six_volume_ / 6.0;
    return std::move(mesh_);
  }

 private:
  Vec3 g_;
  TriangleMesh mesh_;
  Eigen::Index num_points_ = 0;
  Eigen::Index num_faces_ = 0;
  double six_volume_ = 0.0;
};

// Star-shaped VV (near = 0 on every ray): the radial surface r = far over the triangles whose
// three corners see something, closed by a fan to g along the border of that region (the border
// only appears where far = 0, i.e. the ground or a band face through g: the fan is then exact).
TriangleMesh build_star_mesh(const Setup& s, const SphereGrid& sphere, const Directions& dirs,
                             const std::vector<Interval>& corner, double& volume) {
  const int nv = sphere.num_vertices();
  const int ne = sphere.ne;
  const int na = sphere.na;
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
    for (int i = 0; i < ne; ++i) {
      for (int j = 0; j < na; ++j) {
        const int jn = j + 1 == na ? 0 : j + 1;
        const int v00 = sphere.vertex(i, j), v01 = sphere.vertex(i, jn);
        const int v10 = sphere.vertex(i + 1, j), v11 = sphere.vertex(i + 1, jn);
        const int t = 2 * (i * na + j);
        tri_alive[t] = i >= 1 && alive[v00] && alive[v01] && alive[v11];
        tri_alive[t + 1] = i <= ne - 2 && alive[v00] && alive[v11] && alive[v10];
        if (i >= 1 && !tri_alive[t]) candidate[v00] |= alive[v00], candidate[v01] |= alive[v01], candidate[v11] |= alive[v11];
        if (i <= ne - 2 && !tri_alive[t + 1])
          candidate[v00] |= alive[v00], candidate[v11] |= alive[v11], candidate[v10] |= alive[v10];
      }
    }
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

  MeshBuilder out(s.g, nv + 1, 5 * static_cast<Eigen::Index>(nv) + 8);
  std::vector<int> outer(static_cast<std::size_t>(nv), -1);
  int apex = -1;
  auto outer_of = [&](int v) {
    if (outer[v] < 0) outer[v] = out.add(point_on(s, dirs.corner(v), corner[v].far, corner[v].far_surface));
    return outer[v];
  };
  auto emit = [&](int t, int a, int b, int c) {
    out.face(outer_of(a), outer_of(b), outer_of(c));
    if (candidate[a] + candidate[b] + candidate[c] < 2) return;  // no edge on the border
    const std::array<int, 3> corners{a, b, c};
    for (int e = 0; e < 3; ++e) {
      if (tri_alive[sphere.neighbour(t, e)]) continue;
      const int p = corners[static_cast<std::size_t>(e)];
      const int q = corners[static_cast<std::size_t>((e + 1) % 3)];
      if (apex < 0) apex = out.add(s.g);
      out.face(outer_of(q), outer_of(p), apex);
    }
  };
  for (int i = 0; i < ne; ++i) {
    for (int j = 0; j < na; ++j) {
      const int jn = j + 1 == na ? 0 : j + 1;
      const int v00 = sphere.vertex(i, j), v01 = sphere.vertex(i, jn);
      const int v10 = sphere.vertex(i + 1, j), v11 = sphere.vertex(i + 1, jn);
      const int t = 2 * (i * na + j);
      if (tri_alive[t]) emit(t, v00, v01, v11);
      if (tri_alive[t + 1]) emit(t + 1, v00, v11, v10);
    }
  }
  return out.finish(volume);
}

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

// Sines of the elevations of the mesh's vertex rows: the grid's cell boundaries (exactly 0 on the
// horizon), plus the creases of the open-field VV, which are latitude circles about g: where the
// sphere r = d_max meets the band planes and the ground (sin el = (z - g.z) / d_max). A vertex
// row on each crease keeps the caps' rims exact instead of cutting the corner across a cell;
// grid rows closer than a quarter step to a crease are dropped (no slivers).
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
  for (double e : creases)
    if (std::abs(e) > 0.25 * step && std::abs(std::abs(e) - kPi / 2.0) > 0.25 * step) elevations.push_back(e);
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

  // Rays: every cell centre (the grid's intervals), then every corner of the sphere grid (the
  // mesh). Traced in parallel chunks of neighbouring directions, 64 per rtcIntersect1M call.
  const std::vector<double> row_sines = vertex_row_sines(vv.grid, s);
  const SphereGrid sphere{static_cast<int>(row_sines.size()) - 1, na};
  const Directions dirs(vv.grid, sphere, row_sines);
  const std::size_t n_cells = vv.grid.size();
  const auto n_corners = static_cast<std::size_t>(sphere.num_vertices());
  vv.near.assign(n_cells, 0.0);
  vv.far.assign(n_cells, 0.0);
  std::vector<Interval> corner(n_corners);
  const detail::EmbreeScene& embree = detail::EmbreeScene::of(scene);
  const auto t_far = static_cast<float>(d_max);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n_cells + n_corners, 4096),
                    [&](const tbb::blocked_range<std::size_t>& r) {
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
                        // Rays end where the band, the ground or d_max end the interval anyway;
                        // rays with nothing to see there are not traced at all.
                        std::size_t traced = 0;
                        for (std::size_t k = 0; k < count; ++k) {
                          d[k] = dirs.ray(start + k);
                          hit[k] = kInf;
                          const Interval bound = visible_interval(s, d[k].z(), kInf);
                          if (!(bound.far > bound.near)) continue;
                          for (int c = 0; c < 3; ++c) rays[3 * traced + c] = static_cast<float>(d[k][c]);
                          t_max[traced] = static_cast<float>(bound.far) * (1.0f + 1e-6f);
                          slot[traced++] = k;
                        }
                        embree.trace(g, rays.data(), traced, 0.0f, t_far, t.data(), ground.data(), t_max.data());
                        // Ground hits are dropped: the ground is applied exactly, and a ray
                        // grazing the ground plane from a POI on it must not stop.
                        for (std::size_t m = 0; m < traced; ++m)
                          if (!ground[m]) hit[slot[m]] = static_cast<double>(t[m]);
                        for (std::size_t k = 0; k < count; ++k) {
                          const Interval iv = visible_interval(s, d[k].z(), hit[k]);
                          const std::size_t index = start + k;
                          if (index < n_cells) {
                            if (iv.far > iv.near) {
                              vv.near[index] = iv.near;
                              vv.far[index] = iv.far;
                            }
                          } else {
                            corner[index - n_cells] = iv;
                          }
                        }
                      }
                    });
  vv.mesh = s.poi_in_band ? build_star_mesh(s, sphere, dirs, corner, vv.volume)
                          : build_shell_mesh(s, sphere, dirs, corner, vv.volume);
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
