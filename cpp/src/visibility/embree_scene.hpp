// The Embree side of VisibilityScene (private to the library: Embree stays out of public headers).
#pragma once

#include <embree3/rtcore.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "visibility/clearance.hpp"
#include "vistrack/visibility.hpp"

namespace vistrack::detail {

struct EmbreeScene {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  unsigned ground_geometry = RTC_INVALID_GEOMETRY_ID;
  unsigned obstacle_geometry = RTC_INVALID_GEOMETRY_ID;
  // Obstacle triangles lying in the ground plane (a map's ground sheet, building floors): a hit on
  // one is a ground hit.
  std::vector<std::uint8_t> on_ground;
  // The obstacle triangles' corners relative to `origin` (9 floats each, by Embree's primID): the
  // star mesh finds where a ray leaves the triangle it hit (the silhouette a jump sits on).
  std::vector<float> triangles;
  static constexpr std::uint32_t kNoTriangle = ~std::uint32_t{0};
  Vec3 origin = Vec3::Zero();  // Embree vertices are floats relative to this point
  double ground_level = 0.0;
  Bounds3 bounds{};
  std::size_t num_triangles = 0;
  std::uint64_t fingerprint = 0;
  std::vector<Building> buildings;  // exact inside test for 2.5D cities
  ObstacleIndex obstacles;          // the obstacle triangles relative to `origin`, for Clearance

  explicit EmbreeScene(const Environment& env);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // First hits of n rays from `origin` (world) along unit directions dirs[3k..3k+2] within
  // [t_near, t_far] metres: t_hit[k] (+inf when none) and the hit geometry (ground, including
  // obstacle triangles in the ground plane, or obstacle).
  // Traced in coherent batches of 64 with rtcIntersect1M on the calling thread.
  // With t_far_each, ray k ends at t_far_each[k] instead of t_far. With hit_triangle, the obstacle
  // triangle each ray hit (its index in `triangles`), kNoTriangle for the ground or nothing.
  void trace(const Vec3& origin, const float* dirs, std::size_t n, float t_near, float t_far,
             float* t_hit, bool* hit_ground, const float* t_far_each = nullptr,
             std::uint32_t* hit_triangle = nullptr) const;
  // Number of obstacle crossings (ground excluded) along a ray, for parity tests.
  int count_crossings(const Vec3& origin, const Vec3& direction) const;

  static const EmbreeScene& of(const VisibilityScene& scene) { return *scene.impl_; }
};

// Saves MXCSR, sets flush-to-zero and denormals-are-zero for Embree, restores on exit.
class FlushDenormals {
 public:
  FlushDenormals();
  ~FlushDenormals();
  FlushDenormals(const FlushDenormals&) = delete;
  FlushDenormals& operator=(const FlushDenormals&) = delete;

 private:
  unsigned int saved_;
};

}  // namespace vistrack::detail
