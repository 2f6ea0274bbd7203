// The shared pieces of the VV mesh builders: visible intervals, the sphere of grid corners, and
// the mesh writer.
#include "visibility/radial_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vistrack::detail {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kHugeInverse = 1e30;  // 1/t for t = 0 (kept finite for the interpolation)
}  // namespace

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

std::array<int, 3> SphereGrid::corners(int t) const {
  const int q = t / 2;
  const int i = q / na;
  const int j = q % na;
  if (t % 2 == 0) return {vertex(i, j), vertex(i, j + 1), vertex(i + 1, j + 1)};
  return {vertex(i, j), vertex(i + 1, j + 1), vertex(i + 1, j)};
}

int SphereGrid::neighbour(int t, int e) const {
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

int SphereGrid::ring(int v, std::array<int, 6>& out, std::vector<int>& pole_ring) const {
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

Directions::Directions(const SphereGrid& s, const std::vector<double>& sin_el_rows) : sphere(s) {
  const int na = s.na;
  const double d_az = kTwoPi / na;
  for (double se : sin_el_rows) {
    sin_el_corner.push_back(se);
    cos_el_corner.push_back(std::sqrt(std::max(0.0, 1.0 - se * se)));
  }
  for (int j = 0; j < na; ++j) {
    cos_az_corner.push_back(std::cos(j * d_az));
    sin_az_corner.push_back(std::sin(j * d_az));
  }
}

MeshBuilder::MeshBuilder(const Vec3& g, Eigen::Index expected_points, Eigen::Index expected_faces) : g_(g) {
  mesh_.vertices.resize(expected_points, 3);
  mesh_.faces.resize(expected_faces, 3);
}

void MeshBuilder::face(int a, int b, int c) {
  if (num_faces_ == mesh_.faces.rows()) mesh_.faces.conservativeResize(2 * num_faces_ + 16, 3);
  mesh_.faces.row(num_faces_) << a, b, c;
  ++num_faces_;
  const Vec3 pa = mesh_.vertices.row(a).transpose() - g_;
  const Vec3 pb = mesh_.vertices.row(b).transpose() - g_;
  const Vec3 pc = mesh_.vertices.row(c).transpose() - g_;
  six_volume_ += pa.x() * (pb.y() * pc.z() - pb.z() * pc.y()) - pa.y() * (pb.x() * pc.z() - pb.z() * pc.x()) +
                 pa.z() * (pb.x() * pc.y() - pb.y() * pc.x());
}

TriangleMesh MeshBuilder::finish(double& volume) {
  mesh_.vertices.conservativeResize(num_points_, 3);
  mesh_.faces.conservativeResize(num_faces_, 3);
  volume = six_volume_ / 6.0;
  return std::move(mesh_);
}


}  // namespace vistrack::detail
