// MaxRadius by line of sight, for the locus check: the disk at h_UAV centred above the POI is
// probed directly with occlusion rays instead of through a visibility volume's mesh (about 20 times
// fewer rays than a 1-degree VV; it agrees with MaxRadius of the VV's polygon to the mesh's error).
#include <algorithm>
#include <cmath>
#include <limits>

#include "locus.hpp"
#include "vistrack/error.hpp"
#include "vistrack/orbit.hpp"

namespace vistrack {

double visible_disk_radius(const VisibilityScene& scene, const Vec3& poi, double altitude, const Sensor& sensor,
                           int azimuths, int rings) {
  sensor.validate();
  require_finite(altitude, "altitude");
  if (azimuths < 8) detail::fail_field("azimuths", azimuths, "must be at least 8");
  if (rings < 1) detail::fail_field("rings", rings, "must be at least 1");
  return detail::visible_disk_radius_of_valid(scene, poi, altitude, sensor, azimuths, rings);
}

double detail::visible_disk_radius_of_valid(const VisibilityScene& scene, const Vec3& poi, double altitude,
                                            const Sensor& sensor, int azimuths, int rings) {
  const Vec3 g = scene.poi_on_surface(poi);
  if (sensor.altitude_band && !(altitude > sensor.altitude_band->first && altitude < sensor.altitude_band->second))
    return 0.0;  // the flight plane lies outside the feasible airspace: nothing visible there
  const double dh = altitude - g.z();
  if (!(std::abs(dh) < sensor.d_max)) return 0.0;
  const double reach = std::sqrt(sensor.d_max * sensor.d_max - dh * dh);  // d_max on the plane
  const auto n = static_cast<std::size_t>(azimuths);
  std::vector<Vec2> direction(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double a = 2.0 * kPi * (static_cast<double>(k) + 0.5) / static_cast<double>(n);
    direction[k] = Vec2(std::cos(a), std::sin(a));
  }
  // Line of sight from g to the plane point at radius rho[i] along azimuth which[i].
  auto visible = [&](const std::vector<std::size_t>& which, const std::vector<double>& rho) {
    Points3 from(static_cast<Eigen::Index>(which.size()), 3), to(static_cast<Eigen::Index>(which.size()), 3);
    for (std::size_t i = 0; i < which.size(); ++i) {
      const auto row = static_cast<Eigen::Index>(i);
      from.row(row) = g.transpose();
      const Vec2 p = g.head<2>() + rho[i] * direction[which[i]];
      to.row(row) << p.x(), p.y(), altitude;
    }
    return scene.line_of_sight(from, to);
  };

  // Rings: every azimuth at reach * i / rings. Along an azimuth the visible points normally form
  // one interval from the centre out (2.5D obstacles); the rings catch blocked bands (holes of the
  // polygon) wider than reach / rings. lo: largest radius seen so far with every ring inside it
  // visible; hi: the first blocked ring (infinity when none).
  std::vector<double> lo(n, 0.0), hi(n, std::numeric_limits<double>::infinity());
  {
    std::vector<std::size_t> which;
    std::vector<double> rho;
    for (std::size_t k = 0; k < n; ++k)
      for (int i = 1; i <= rings; ++i) {
        which.push_back(k);
        rho.push_back(reach * static_cast<double>(i) / static_cast<double>(rings));
      }
    const std::vector<bool> seen = visible(which, rho);
    for (std::size_t k = 0; k < n; ++k)
      for (int i = 1; i <= rings; ++i) {
        const std::size_t at = k * static_cast<std::size_t>(rings) + static_cast<std::size_t>(i - 1);
        if (!seen[at]) {
          hi[k] = rho[at];
          break;
        }
        lo[k] = rho[at];
      }
  }
  // Bisection between lo and hi, only on the azimuths that can still set the minimum.
  const double tolerance = std::max(1e-3, 1e-5 * reach);
  for (int step = 0; step < 64; ++step) {
    double bound = reach;  // the smallest radius known to be blocked (or the reach)
    for (std::size_t k = 0; k < n; ++k) bound = std::min(bound, hi[k]);
    std::vector<std::size_t> which;
    std::vector<double> rho;
    for (std::size_t k = 0; k < n; ++k)
      if (std::isfinite(hi[k]) && lo[k] < bound && hi[k] - lo[k] > tolerance) {
        which.push_back(k);
        rho.push_back(0.5 * (lo[k] + hi[k]));
      }
    if (which.empty()) break;
    const std::vector<bool> seen = visible(which, rho);
    for (std::size_t i = 0; i < which.size(); ++i) (seen[i] ? lo : hi)[which[i]] = rho[i];
  }
  // Every azimuth sees up to lo (at the rings and the bisection points): the disk of the smallest lo.
  return *std::min_element(lo.begin(), lo.end());
}

}  // namespace vistrack
