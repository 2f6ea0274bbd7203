#include "vistrack/environment.hpp"

#include <algorithm>
#include <cstring>
#include <limits>

#include "environment/detail.hpp"
#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"

namespace vistrack {

namespace {

Bounds3 bounds_of(const Points3& vertices) {
  Bounds3 box{Vec3::Zero(), Vec3::Zero()};
  if (vertices.rows() == 0) return box;
  box.min = vertices.colwise().minCoeff().transpose();
  box.max = vertices.colwise().maxCoeff().transpose();
  return box;
}

// FNV-1a over raw bytes: stable across runs and platforms with the same endianness.
void hash_bytes(std::uint64_t& hash, const void* data, std::size_t size) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= bytes[i];
    hash *= 1099511628211ULL;
  }
}

}  // namespace

void validate_triangle_mesh(const Points3& vertices, const Faces& faces, const std::string& field) {
  if (faces.rows() == 0) throw Error(field + ".faces: the mesh has no triangles");
  for (Eigen::Index i = 0; i < vertices.rows(); ++i)
    for (int k = 0; k < 3; ++k)
      require_coordinate(vertices(i, k), field + ".vertices[" + std::to_string(i) + "][" + std::to_string(k) + "]");
  for (Eigen::Index i = 0; i < faces.rows(); ++i)
    for (int k = 0; k < 3; ++k)
      if (faces(i, k) < 0 || faces(i, k) >= vertices.rows())
        detail::fail_field(field + ".faces[" + std::to_string(i) + "]", faces(i, k),
                           "vertex index out of range [0, " + std::to_string(vertices.rows()) + ")");
}

void validate_geodetic_point(const GeodeticPoint& point, const std::string& field) {
  if (!(point.latitude >= -90.0 && point.latitude <= 90.0))
    detail::fail_field(field + ".latitude", point.latitude, "must be in [-90, 90] degrees");
  if (!(point.longitude >= -180.0 && point.longitude <= 180.0))
    detail::fail_field(field + ".longitude", point.longitude, "must be in [-180, 180] degrees");
  require_in_range(point.altitude, -limits::kMaxAltitude, limits::kMaxAltitude, "m", field + ".altitude");
}

void Environment::set_origin(const std::optional<GeodeticPoint>& origin) {
  if (origin) validate_geodetic_point(*origin, "origin");
  origin_ = origin;
}

Environment Environment::from_triangles(Points3 vertices, Faces faces) {
  validate_triangle_mesh(vertices, faces, "triangles");
  Environment env;
  env.mesh_.vertices = std::move(vertices);
  env.mesh_.faces = std::move(faces);
  env.bounds_ = bounds_of(env.mesh_.vertices);
  env.ground_level_ = env.bounds_.min.z();
  return env;
}

Environment Environment::from_buildings(std::vector<Building> buildings, RoadNetwork roads) {
  if (buildings.empty()) detail::fail_field("buildings", "[]", "an environment needs at least one building");
  detail::validate_buildings(buildings, detail::sources_for_buildings(buildings));
  Environment env = from_validated_buildings(std::move(buildings));
  env.set_roads(std::move(roads));
  return env;
}

Environment Environment::from_validated_buildings(std::vector<Building> buildings) {
  Environment env;
  env.buildings_ = std::move(buildings);
  env.mesh_ = detail::extrude(env.buildings_);
  env.bounds_ = bounds_of(env.mesh_.vertices);
  env.ground_level_ = 0.0;  // the ground plane z = 0, the bases measured from it
  return env;
}

std::vector<double> Environment::heights() const {
  std::vector<double> result;
  result.reserve(buildings_.size());
  for (const Building& b : buildings_) result.push_back(b.height);
  return result;
}

std::vector<double> Environment::min_heights() const {
  std::vector<double> result;
  result.reserve(buildings_.size());
  for (const Building& b : buildings_) result.push_back(b.min_height);
  return result;
}

double Environment::max_height() const { return bounds_.max.z() - ground_level_; }

std::vector<Polygon> Environment::footprints() const {
  std::vector<Polygon> result;
  result.reserve(buildings_.size());
  for (const Building& b : buildings_) result.push_back(b.footprint);
  return result;
}

std::uint64_t Environment::fingerprint() const {
  std::uint64_t hash = 14695981039346656037ULL;
  hash_bytes(hash, mesh_.vertices.data(), sizeof(double) * mesh_.vertices.size());
  hash_bytes(hash, mesh_.faces.data(), sizeof(std::int32_t) * mesh_.faces.size());
  for (const Vec2& node : roads_.nodes) hash_bytes(hash, node.data(), 2 * sizeof(double));
  for (const auto& edge : roads_.edges) hash_bytes(hash, &edge, sizeof(edge));
  for (std::size_t e = 0; e < roads_.oneway.size(); ++e)
    if (roads_.oneway[e]) hash_bytes(hash, &e, sizeof(e));  // two-way networks hash as before
  return hash;
}

}  // namespace vistrack
