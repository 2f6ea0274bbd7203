// The first obstacle hit of every corner ray of a VV without tracing it (private to the library;
// beyond the paper, issue 35): each triangle within reach is tested against the corner
// directions inside its footprint (Clearance::footprints), like a z-buffer on the sphere.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "visibility/clearance.hpp"
#include "visibility/radial_mesh.hpp"

namespace vistrack::detail {

// The corner rays' first hits, with the scratch that finds them. Kept as inverse distances, read
// through distance_of(), so that the distances need no array and pass of their own.
struct CornerHits {
  std::vector<double> inverse;          // per corner: 1 / the first obstacle hit's distance, 0: none
  std::vector<std::uint32_t> triangle;  // its face (EmbreeScene::kNoTriangle: none)
  std::vector<double> second_inverse;   // the second thread's, while two threads scan
  std::vector<std::uint32_t> second_owner;
  std::vector<int> first_row;  // rows by buckets of sine (corner_hits)
  static double distance_of(double inverse) {
    return inverse > 0.0 ? 1.0 / inverse : std::numeric_limits<double>::infinity();
  }
};

// CornerHits::distance_of(out.inverse[v]) and out.triangle[v] per corner v of `sphere` (directions
// `dirs`): the nearest obstacle triangle whose cone from g holds the direction and lies within
// visible_far_bound along it, its distance and face (Embree's primID), else +inf and kNoTriangle:
// what tracing the ray in exact arithmetic would return. `triangles`: 9 floats per face relative
// to the scene's origin (EmbreeScene::triangles), g_local: g relative to it. Alternate footprints
// on two of TBB's threads when `parallel`, merged to the same result (of two triangles at exactly
// the same distance the first footprint wins either way). Returns the number of (direction,
// triangle) tests made.
std::size_t corner_hits(const Clearance& clearance, const std::vector<float>& triangles, const Vec3& g_local,
                        const Setup& s, const SphereGrid& sphere, const Directions& dirs, bool parallel,
                        CornerHits& out);

}  // namespace vistrack::detail
