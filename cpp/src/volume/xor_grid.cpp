// The per-direction XOR volume of two VVs on one direction grid's corners (the trapezoid rule; the
// fast path of eq. (56) for VVs without a radial mesh),
// the frame and method parsing, and the dispatch between the grid and the mesh paths.
#include <algorithm>
#include <cmath>

#include "vistrack/error.hpp"
#include "vistrack/volume.hpp"

namespace vistrack {
namespace {

// Measure of [near, far] under r^2 dr; an empty interval (near >= far) has measure 0.
double radial_measure(double near, double far) {
  return far > near ? (far * far * far - near * near * near) / 3.0 : 0.0;
}

void require_intervals(const VisibilityVolume& v, const std::string& name) {
  if (v.grid.num_elevation <= 0 || v.grid.num_azimuth <= 0)
    detail::fail_field(name + ".grid", std::to_string(v.grid.num_elevation) + "x" + std::to_string(v.grid.num_azimuth),
                       "the direction grid is empty");
  if (v.near.size() != v.grid.num_corners() || v.far.size() != v.grid.num_corners())
    detail::fail_field(name + ".near/far", std::to_string(v.near.size()) + "/" + std::to_string(v.far.size()),
                       "need one interval per grid corner (" + std::to_string(v.grid.num_corners()) + ")");
}

Points3 translated(const Points3& vertices, const Vec3& offset) {
  Points3 out = vertices;
  out.rowwise() -= offset.transpose();
  return out;
}

}  // namespace

bool shares_direction_grid(const VisibilityVolume& a, const VisibilityVolume& b) {
  return a.grid.num_elevation > 0 && a.grid.num_azimuth > 0 &&
         a.grid.num_elevation == b.grid.num_elevation && a.grid.num_azimuth == b.grid.num_azimuth &&
         a.near.size() == a.grid.num_corners() && a.far.size() == a.grid.num_corners() &&
         b.near.size() == b.grid.num_corners() && b.far.size() == b.grid.num_corners();
}

double grid_xor_volume(const VisibilityVolume& a, const VisibilityVolume& b) {
  require_intervals(a, "a");
  require_intervals(b, "b");
  if (!shares_direction_grid(a, b))
    detail::fail_field("b.grid", std::to_string(b.grid.num_elevation) + "x" + std::to_string(b.grid.num_azimuth),
                       "differs from a.grid " + std::to_string(a.grid.num_elevation) + "x" +
                           std::to_string(a.grid.num_azimuth) + ": the per-direction XOR needs one grid");
  const int columns = a.grid.num_azimuth;
  double total = 0.0;
  for (int row = 0; row <= a.grid.num_elevation; ++row) {
    double row_sum = 0.0;
    const std::size_t first = static_cast<std::size_t>(row) * static_cast<std::size_t>(columns);
    for (std::size_t k = first; k < first + static_cast<std::size_t>(columns); ++k) {
      const double na = a.near[k], fa = a.far[k], nb = b.near[k], fb = b.far[k];
      if (!std::isfinite(na) || !std::isfinite(fa) || !std::isfinite(nb) || !std::isfinite(fb))
        detail::fail_field("near/far[" + std::to_string(k) + "]", "non-finite", "interval bounds must be finite");
      // |A xor B| = |A| + |B| - 2 |A n B| along the ray, with A n B = [max near, min far].
      const double both = radial_measure(std::max(na, nb), std::min(fa, fb));
      row_sum += radial_measure(na, fa) + radial_measure(nb, fb) - 2.0 * both;
    }
    total += a.grid.corner_weight(row) * row_sum;  // the trapezoid weight of the row
  }
  return std::max(total, 0.0);
}

double xor_volume(const VisibilityVolume& a, const VisibilityVolume& b, XorFrame frame, XorMethod method,
                  const MeshXorOptions& options) {
  // Every method but the grid's reads the meshes: a VV without its mesh is refused, not quietly
  // given the grid's trapezoid rule in place of the exact radial XOR.
  if (method != XorMethod::grid) {
    detail::require_mesh(a, "a");
    detail::require_mesh(b, "b");
  }
  // Star-shaped about one common point: both in the POI frame, or the same POI in the world.
  const bool common_centre = frame == XorFrame::poi || (a.poi - b.poi).norm() == 0.0;
  if (method == XorMethod::automatic && common_centre)
    method = shares_radial_mesh(a, b) ? XorMethod::radial : (shares_direction_grid(a, b) ? XorMethod::grid : method);
  if (method == XorMethod::radial || method == XorMethod::grid) {
    if (!common_centre)
      detail::fail_field("method", method == XorMethod::radial ? "radial" : "grid",
                         "the per-direction XOR needs both VVs about one point: frame \"poi\" or equal POIs");
    return method == XorMethod::radial ? radial_xor_volume(a, b) : grid_xor_volume(a, b);
  }
  if (frame == XorFrame::world) return mesh_xor_volume(a.mesh, b.mesh, options);
  const TriangleMesh a_local{translated(a.mesh.vertices, a.poi), a.mesh.faces};
  const TriangleMesh b_local{translated(b.mesh.vertices, b.poi), b.mesh.faces};
  MeshXorOptions nudged = options;
  nudged.perturbation = options.perturbation.value_or(kPoiFramePerturbation);
  return mesh_xor_volume(a_local, b_local, nudged);
}

}  // namespace vistrack
