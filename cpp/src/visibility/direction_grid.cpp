// The angular grid of a VV and the volumes it represents.
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>

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

Vec2 DirectionGrid::sample_offset(int row, int column) const {
  // Weyl sequences with the R2 sequence's constants (1/rho and 1/rho^2, rho the plastic number):
  // x steps by an irrational fraction from row to row and y from column to column, so x is
  // equidistributed down every column and y along every row. x depending on the row only keeps
  // the azimuths separable (trig tables per row and per column).
  constexpr double kA = 0.7548776662466927;
  constexpr double kB = 0.5698402909980532;
  const double x = 0.5 + kA * row;
  const double y = 0.5 + kB * column;
  return {x - std::floor(x), y - std::floor(y)};
}

Vec3 DirectionGrid::direction(int row, int column) const {
  const Vec2 offset = sample_offset(row, column);
  const double d_el = kPi / num_elevation;
  const double bottom = std::sin(-kPi / 2.0 + row * d_el);
  const double top = std::sin(-kPi / 2.0 + (row + 1) * d_el);
  const double sin_el = bottom + offset.y() * (top - bottom);
  const double cos_el = std::sqrt(std::max(0.0, 1.0 - sin_el * sin_el));
  const double az = (column + offset.x()) * kTwoPi / num_azimuth;
  return {cos_el * std::cos(az), cos_el * std::sin(az), sin_el};
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
  for (int i = 0; i < grid.num_elevation; ++i) {
    double row = 0.0;
    for (int j = 0; j < grid.num_azimuth; ++j) {
      const std::size_t k = static_cast<std::size_t>(i) * grid.num_azimuth + j;
      if (far[k] > near[k]) row += far[k] * far[k] * far[k] - near[k] * near[k] * near[k];
    }
    total += grid.solid_angle(i) * row / 3.0;
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
