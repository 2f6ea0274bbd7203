// The angular grid of a VV and the volumes it represents.
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>

#include "visibility/radial_mesh.hpp"
#include "vistrack/error.hpp"
#include "vistrack/visibility.hpp"

namespace vistrack {

double DirectionGrid::elevation(int row) const { return -kPi / 2.0 + (row + 0.5) * kPi / num_elevation; }

double DirectionGrid::azimuth(int column) const { return (column + 0.5) * kTwoPi / num_azimuth; }

double DirectionGrid::solid_angle(int row) const {
  // Cell area on the unit sphere: d_az * (sin(el_top) - sin(el_bottom)).
  const double d_el = kPi / num_elevation;
  const double bottom = -kPi / 2.0 + row * d_el;
  return (kTwoPi / num_azimuth) * (std::sin(bottom + d_el) - std::sin(bottom));
}

double detail::corner_sine(int row, int num_elevation) {
  if (row <= 0) return -1.0;
  if (row >= num_elevation) return 1.0;
  if (2 * row == num_elevation) return 0.0;
  return std::sin((2 * row - num_elevation) * kPi / (2.0 * num_elevation));
}

Vec3 DirectionGrid::corner(int row, int column) const {
  const double sin_el = detail::corner_sine(row, num_elevation);
  const double cos_el = std::sqrt(std::max(0.0, 1.0 - sin_el * sin_el));
  const double az = column * kTwoPi / num_azimuth;
  return {cos_el * std::cos(az), cos_el * std::sin(az), sin_el};
}

double DirectionGrid::corner_weight(int row) const {
  return 0.5 * ((row > 0 ? solid_angle(row - 1) : 0.0) + (row < num_elevation ? solid_angle(row) : 0.0));
}

DirectionGrid DirectionGrid::from_resolution(double resolution_deg) {
  if (!(resolution_deg >= 0.1 && resolution_deg <= 30.0))
    detail::fail_field("resolution_deg", resolution_deg, "must lie in [0.1, 30] degrees");
  DirectionGrid grid;
  // An even number of rows puts a row boundary on the horizon: the ground plane through a POI on
  // the ground is then meshed exactly.
  grid.num_elevation = 2 * static_cast<int>(std::lround(90.0 / resolution_deg));
  grid.num_azimuth = static_cast<int>(std::lround(360.0 / resolution_deg));
  return grid;
}

double VisibilityVolume::grid_volume() const {
  double total = 0.0;
  for (int i = 0; i <= grid.num_elevation; ++i) {
    double row = 0.0;
    for (int j = 0; j < grid.num_azimuth; ++j) {
      const std::size_t k = static_cast<std::size_t>(i) * grid.num_azimuth + j;
      if (far[k] > near[k]) row += far[k] * far[k] * far[k] - near[k] * near[k] * near[k];
    }
    total += grid.corner_weight(i) * row / 3.0;
  }
  return total;
}

double mesh_volume(const TriangleMesh& mesh) {
  if (mesh.faces.rows() == 0) return 0.0;
  // Signed tetrahedra against the first vertex (a nearby reference keeps the sum well conditioned).
  const Vec3 reference = mesh.vertices.row(0).transpose();
  double six_volume = 0.0;
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f) {
    const Vec3 a = mesh.vertices.row(mesh.faces(f, 0)).transpose() - reference;
    const Vec3 b = mesh.vertices.row(mesh.faces(f, 1)).transpose() - reference;
    const Vec3 c = mesh.vertices.row(mesh.faces(f, 2)).transpose() - reference;
    six_volume += a.dot(b.cross(c));
  }
  return six_volume / 6.0;
}

}  // namespace vistrack
