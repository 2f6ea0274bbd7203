// VisibilityScene: one Embree BVH per environment (obstacles plus the ground plane).
#include <pmmintrin.h>
#include <xmmintrin.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "visibility/embree_scene.hpp"
#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"

namespace vistrack {
namespace detail {

namespace {

constexpr double kGroundHalfSize = 1.0e6;      // m: covers every query the float scene can carry
constexpr double kMaxLocalCoordinate = 1.0e6;  // m from the local origin, beyond it floats are too coarse
constexpr std::size_t kBatch = 64;             // rays per rtcIntersect1M call (notes: 35-43 Mrays/s)
constexpr double kOnGround = 1e-6;             // m: a triangle this close to the ground plane lies in it

void embree_error(void* /*user*/, RTCError code, const char* message) {
  // Reported through rtcGetDeviceError after each build step; nothing to do here.
  (void)code;
  (void)message;
}

void check_device(RTCDevice device, const std::string& step) {
  const RTCError code = rtcGetDeviceError(device);
  if (code != RTC_ERROR_NONE)
    throw Error("Embree failed while " + step + " (error code " + std::to_string(static_cast<int>(code)) + ")");
}

void init_ray(RTCRay& ray, const float o[3], const float d[3], float t_near, float t_far) {
  ray.org_x = o[0];
  ray.org_y = o[1];
  ray.org_z = o[2];
  ray.dir_x = d[0];
  ray.dir_y = d[1];
  ray.dir_z = d[2];
  ray.tnear = t_near;
  ray.tfar = t_far;
  ray.time = 0.0f;
  ray.mask = 0xFFFFFFFFu;  // the Debian Embree has ray masks on: mask 0 would hit nothing
  ray.id = 0;
  ray.flags = 0;
}

}  // namespace

FlushDenormals::FlushDenormals() : saved_(_mm_getcsr()) {
  _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
  _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
}

FlushDenormals::~FlushDenormals() { _mm_setcsr(saved_); }

EmbreeScene::EmbreeScene(const Environment& env)
    : ground_level(env.ground_level()),
      bounds(env.bounds()),
      num_triangles(env.num_triangles()),
      fingerprint(env.fingerprint()),
      buildings(env.buildings()) {
  const TriangleMesh& mesh = env.mesh();
  origin = 0.5 * (bounds.min + bounds.max);
  origin.z() = ground_level;
  require_finite(ground_level, "environment.ground_level");
  // Validate before building: Embree silently drops triangles with NaN or huge coordinates.
  for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i)
    for (int k = 0; k < 3; ++k) {
      const double x = mesh.vertices(i, k);
      if (!std::isfinite(x))
        fail_field("environment.vertices[" + std::to_string(i) + "][" + std::to_string(k) + "]", x,
                   "vertex coordinates must be finite");
      if (std::abs(x - origin[k]) > kMaxLocalCoordinate)
        fail_field("environment.vertices[" + std::to_string(i) + "][" + std::to_string(k) + "]", x,
                   "farther than 1e6 m from the scene centre (float precision)");
    }
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      if (mesh.faces(f, k) < 0 || mesh.faces(f, k) >= mesh.vertices.rows())
        fail_field("environment.faces[" + std::to_string(f) + "]", mesh.faces(f, k), "vertex index out of range");

  device = rtcNewDevice(nullptr);
  if (device == nullptr) throw Error("Embree: cannot create a device");
  rtcSetDeviceErrorFunction(device, embree_error, nullptr);
  scene = rtcNewScene(device);
  rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);

  // Obstacles: shared, indexed vertices (a soup lets rays slip through cracks, see notes).
  if (mesh.faces.rows() > 0) {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
        static_cast<std::size_t>(mesh.vertices.rows())));
    for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i)
      for (int k = 0; k < 3; ++k)
        vertices[3 * i + k] = static_cast<float>(mesh.vertices(i, k) - origin[k]);
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
        static_cast<std::size_t>(mesh.faces.rows())));
    for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
      for (int k = 0; k < 3; ++k) indices[3 * f + k] = static_cast<unsigned>(mesh.faces(f, k));
    rtcCommitGeometry(geometry);
    obstacle_geometry = rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry);
    check_device(device, "loading the obstacle triangles");
    triangles.resize(9 * static_cast<std::size_t>(mesh.faces.rows()));
    for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k)
          triangles[9 * static_cast<std::size_t>(f) + 3 * c + k] = vertices[3 * mesh.faces(f, c) + k];
    on_ground.resize(static_cast<std::size_t>(mesh.faces.rows()));
    for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f) {
      double top = -std::numeric_limits<double>::infinity();
      for (int k = 0; k < 3; ++k) top = std::max(top, mesh.vertices(mesh.faces(f, k), 2));
      on_ground[static_cast<std::size_t>(f)] = top <= ground_level + kOnGround ? 1 : 0;
    }
    // Embree's own float corners: the clearance footprints then bound exactly the triangles that
    // corner_hits tests and cone_exit aims at.
    Points3 local(mesh.vertices.rows(), 3);
    for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i)
      for (int k = 0; k < 3; ++k) local(i, k) = vertices[3 * i + k];
    obstacles = ObstacleIndex(local, mesh.faces, ground_level - origin.z() + kOnGround);
  }

  // Ground plane z = ground_level (the environment's mesh does not contain it).
  {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 4));
    const float h = static_cast<float>(kGroundHalfSize);
    const std::array<float, 12> corners{-h, -h, 0.0f, h, -h, 0.0f, h, h, 0.0f, -h, h, 0.0f};
    std::copy(corners.begin(), corners.end(), vertices);
    auto* indices = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), 2));
    const std::array<unsigned, 6> ground_triangles{0, 1, 2, 0, 2, 3};
    std::copy(ground_triangles.begin(), ground_triangles.end(), indices);
    rtcCommitGeometry(geometry);
    ground_geometry = rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(scene);
  check_device(device, "building the BVH");
}

EmbreeScene::~EmbreeScene() {
  if (scene != nullptr) rtcReleaseScene(scene);
  if (device != nullptr) rtcReleaseDevice(device);
}

void EmbreeScene::trace(const Vec3& world_origin, const float* dirs, std::size_t n, float t_near, float t_far,
                        float* t_hit, bool* hit_ground, const float* t_far_each, std::uint32_t* hit_triangle) const {
  const float o[3] = {static_cast<float>(world_origin.x() - origin.x()),
                      static_cast<float>(world_origin.y() - origin.y()),
                      static_cast<float>(world_origin.z() - origin.z())};
  std::array<RTCRayHit, kBatch> batch;
  for (std::size_t start = 0; start < n; start += kBatch) {
    const std::size_t count = std::min(kBatch, n - start);
    for (std::size_t k = 0; k < count; ++k) {
      init_ray(batch[k].ray, o, dirs + 3 * (start + k), t_near, t_far_each ? t_far_each[start + k] : t_far);
      batch[k].hit.geomID = RTC_INVALID_GEOMETRY_ID;
      batch[k].hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    }
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;  // neighbouring directions from one point
    rtcIntersect1M(scene, &context, batch.data(), static_cast<unsigned>(count), sizeof(RTCRayHit));
    for (std::size_t k = 0; k < count; ++k) {
      const bool hit = batch[k].hit.geomID != RTC_INVALID_GEOMETRY_ID;
      t_hit[start + k] = hit ? batch[k].ray.tfar : std::numeric_limits<float>::infinity();
      const bool on_plane = hit && (batch[k].hit.geomID == ground_geometry ||
                                    (batch[k].hit.geomID == obstacle_geometry && on_ground[batch[k].hit.primID]));
      if (hit_ground != nullptr) hit_ground[start + k] = on_plane;
      if (hit_triangle != nullptr) hit_triangle[start + k] = hit && !on_plane ? batch[k].hit.primID : kNoTriangle;
    }
  }
}

int EmbreeScene::count_crossings(const Vec3& world_origin, const Vec3& direction) const {
  const Vec3 d = direction.normalized();
  const float o[3] = {static_cast<float>(world_origin.x() - origin.x()),
                      static_cast<float>(world_origin.y() - origin.y()),
                      static_cast<float>(world_origin.z() - origin.z())};
  const float df[3] = {static_cast<float>(d.x()), static_cast<float>(d.y()), static_cast<float>(d.z())};
  int crossings = 0;
  float t_near = 0.0f;
  for (int guard = 0; guard < 100000; ++guard) {
    RTCRayHit rayhit;
    init_ray(rayhit.ray, o, df, t_near, std::numeric_limits<float>::infinity());
    rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcIntersect1(scene, &context, &rayhit);
    if (rayhit.hit.geomID == RTC_INVALID_GEOMETRY_ID) break;
    if (rayhit.hit.geomID != ground_geometry) ++crossings;
    // Step past this hit (relative step: floats along a long ray).
    t_near = std::max(std::nextafter(rayhit.ray.tfar, std::numeric_limits<float>::infinity()),
                      rayhit.ray.tfar * (1.0f + 1e-6f) + 1e-5f);
  }
  return crossings;
}

}  // namespace detail

VisibilityScene::VisibilityScene(const Environment& env) : impl_(std::make_shared<detail::EmbreeScene>(env)) {}

double VisibilityScene::ground_level() const { return impl_->ground_level; }
Bounds3 VisibilityScene::bounds() const { return impl_->bounds; }
std::size_t VisibilityScene::num_triangles() const { return impl_->num_triangles; }
std::uint64_t VisibilityScene::fingerprint() const { return impl_->fingerprint; }

std::vector<double> VisibilityScene::first_hits(const Vec3& origin, const Points3& directions, double t_max) const {
  for (int k = 0; k < 3; ++k) require_coordinate(origin[k], "origin[" + std::to_string(k) + "]");
  if (!(t_max > 0.0)) detail::fail_field("t_max", t_max, "must be greater than 0 (+inf: no limit)");
  const auto n = static_cast<std::size_t>(directions.rows());
  std::vector<float> dirs(3 * n);
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3 d = directions.row(static_cast<Eigen::Index>(k)).transpose();
    const double length = d.norm();
    if (!(length > 0.0) || !std::isfinite(length))
      detail::fail_field("directions[" + std::to_string(k) + "]", length, "direction length must be finite and > 0");
    for (int c = 0; c < 3; ++c) dirs[3 * k + c] = static_cast<float>(d[c] / length);
  }
  std::vector<float> hits(n);
  const auto t_far = static_cast<float>(std::min(t_max, 1e30));
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096), [&](const tbb::blocked_range<std::size_t>& r) {
    detail::FlushDenormals flush;
    impl_->trace(origin, dirs.data() + 3 * r.begin(), r.size(), 0.0f, t_far, hits.data() + r.begin(), nullptr);
  });
  return {hits.begin(), hits.end()};
}

std::vector<bool> VisibilityScene::line_of_sight(const Points3& a, const Points3& b) const {
  if (a.rows() != b.rows())
    detail::fail_field("b.rows", b.rows(), "must equal a.rows = " + std::to_string(a.rows()));
  const auto n = static_cast<std::size_t>(a.rows());
  for (std::size_t k = 0; k < n; ++k)
    for (int c = 0; c < 3; ++c) {
      const auto row = static_cast<Eigen::Index>(k);
      require_coordinate(a(row, c), "a[" + std::to_string(k) + "][" + std::to_string(c) + "]");
      require_coordinate(b(row, c), "b[" + std::to_string(k) + "][" + std::to_string(c) + "]");
    }
  constexpr double kEndGap = 1e-3;  // m: endpoints may sit on a wall or on the ground
  std::vector<char> visible(n, 0);
  const detail::EmbreeScene& s = *impl_;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256), [&](const tbb::blocked_range<std::size_t>& r) {
    detail::FlushDenormals flush;
    std::array<RTCRay, detail::kBatch> rays;
    std::array<std::size_t, detail::kBatch> which;
    std::size_t count = 0;
    auto flush_batch = [&]() {
      if (count == 0) return;
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      rtcOccluded1M(s.scene, &context, rays.data(), static_cast<unsigned>(count), sizeof(RTCRay));
      // rtcOccluded sets tfar to -inf on a hit.
      for (std::size_t k = 0; k < count; ++k) visible[which[k]] = rays[k].tfar >= 0.0f ? 1 : 0;
      count = 0;
    };
    for (std::size_t k = r.begin(); k < r.end(); ++k) {
      const auto row = static_cast<Eigen::Index>(k);
      const Vec3 p = a.row(row).transpose();
      const Vec3 q = b.row(row).transpose();
      const double tolerance = 1e-9;
      if (p.z() < s.ground_level - tolerance || q.z() < s.ground_level - tolerance) continue;  // below ground
      const double length = (q - p).norm();
      if (length <= 2.0 * kEndGap) {
        visible[k] = 1;
        continue;
      }
      const Vec3 d = (q - p) / length;
      const float o[3] = {static_cast<float>(p.x() - s.origin.x()), static_cast<float>(p.y() - s.origin.y()),
                          static_cast<float>(p.z() - s.origin.z())};
      const float df[3] = {static_cast<float>(d.x()), static_cast<float>(d.y()), static_cast<float>(d.z())};
      detail::init_ray(rays[count], o, df, static_cast<float>(kEndGap), static_cast<float>(length - kEndGap));
      which[count] = k;
      if (++count == detail::kBatch) flush_batch();
    }
    flush_batch();
  });
  return {visible.begin(), visible.end()};
}

double VisibilityScene::surface_height(const Vec2& xy) const {
  require_coordinate(xy.x(), "xy[0]");
  require_coordinate(xy.y(), "xy[1]");
  const detail::EmbreeScene& s = *impl_;
  const double top = std::max(s.bounds.max.z(), s.ground_level) + 1.0;
  const float down[3] = {0.0f, 0.0f, -1.0f};
  float t = 0.0f;
  bool ground = false;
  detail::FlushDenormals flush;
  s.trace(Vec3(xy.x(), xy.y(), top), down, 1, 0.0f, std::numeric_limits<float>::infinity(), &t, &ground);
  if (!std::isfinite(t)) return s.ground_level;
  return ground ? s.ground_level : top - static_cast<double>(t);
}

Vec3 VisibilityScene::poi_on_surface(const Vec3& g) const {
  for (int k = 0; k < 2; ++k) require_coordinate(g[k], "g[" + std::to_string(k) + "]");
  require_in_range(g.z(), 0.0, limits::kMaxLength, "m", "g[2] (height of the POI above the surface)");
  return Vec3(g.x(), g.y(), surface_height(g.head<2>()) + g.z());
}

bool VisibilityScene::inside_obstacle(const Vec3& p) const {
  for (int k = 0; k < 3; ++k) require_coordinate(p[k], "point[" + std::to_string(k) + "]");
  const detail::EmbreeScene& s = *impl_;
  if (!s.buildings.empty()) {
    for (const Building& building : s.buildings)
      if (p.z() < s.ground_level + building.height && p.z() > s.ground_level + building.min_height &&
          contains(building.footprint, p.head<2>()) &&
          distance_to_boundary(building.footprint, p.head<2>()) > 1e-9)
        return true;
    return false;
  }
  // Parity of crossings along three generic upward directions, majority vote (robust to a ray
  // grazing an edge of a mesh that is not perfectly watertight).
  const std::array<Vec3, 3> directions{Vec3(0.123, 0.211, 1.0), Vec3(-0.301, 0.087, 1.0), Vec3(0.176, -0.254, 1.0)};
  int odd = 0;
  for (const Vec3& d : directions) odd += s.count_crossings(p, d) % 2;
  return odd >= 2;
}

std::vector<bool> line_of_sight(const Environment& env, const Points3& a, const Points3& b) {
  return VisibilityScene(env).line_of_sight(a, b);
}

}  // namespace vistrack
