// Tracing the rays of a VV from its POI (private to the library): rays in coherent chunks of 64
// neighbouring directions per rtcIntersect1M call, skipping the rays the Clearance bounds say meet
// no obstacle, and the rays that would see nothing anyway (outside the band).
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "visibility/clearance.hpp"
#include "visibility/embree_scene.hpp"
#include "visibility/radial_mesh.hpp"

namespace vistrack::detail {

// What tracing one VV's rays cost: rays handed to Embree and rays decided without it, and, when
// `timed`, the nanoseconds spent in Embree (summed over threads: the floor the rays set).
struct RayCounts {
  std::atomic<std::size_t> traced{0};
  std::atomic<std::size_t> skipped{0};
  std::atomic<std::int64_t> embree_ns{0};
  bool timed = false;
};

// Adds the seconds from its construction to stop() to *slot (nothing when slot is null).
class PhaseTimer {
 public:
  explicit PhaseTimer(double* slot) : slot_(slot), start_(slot ? std::chrono::steady_clock::now() : std::chrono::steady_clock::time_point{}) {}
  void stop() {
    if (slot_ != nullptr) *slot_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    slot_ = nullptr;
  }
  ~PhaseTimer() { stop(); }
  PhaseTimer(const PhaseTimer&) = delete;
  PhaseTimer& operator=(const PhaseTimer&) = delete;

 private:
  double* slot_;
  std::chrono::steady_clock::time_point start_;
};

struct TraceContext {
  const EmbreeScene& embree;
  const Setup& setup;
  const Clearance& clearance;
  bool parallel = false;         // spread the rays over TBB's threads
  RayCounts* counts = nullptr;   // optional
};

// Rays k in [begin, end): fill(start, count, d, column) sets the unit directions d[m] of rays
// start + m (m < count <= 64) and their azimuth columns (any column whose closed span holds the
// azimuth); store(k, d, hit) receives the first obstacle hit (+inf when none, and for rays not
// traced). Ground hits count as none: the ground is applied exactly by visible_interval, and a
// ray grazing the ground from a POI on it must not stop. A store taking a fourth argument also
// gets the obstacle triangle hit (EmbreeScene::kNoTriangle when none).
template <class Fill, class Store>
void trace_range(const TraceContext& c, std::size_t begin, std::size_t end, Fill fill, Store store) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  constexpr std::size_t kChunk = 64;
  const Setup& s = c.setup;
  const auto t_far = static_cast<float>(s.d_max);
  std::array<float, 3 * kChunk> rays{};
  std::array<float, kChunk> t{}, t_max{};
  std::array<bool, kChunk> ground{};
  std::array<std::uint8_t, kChunk> slot{};
  std::array<Vec3, kChunk> d;
  std::array<int, kChunk> column{};
  std::array<double, kChunk> hit{};
  constexpr bool wants_triangle = std::is_invocable_v<Store&, std::size_t, const Vec3&, double, std::uint32_t>;
  std::array<std::uint32_t, kChunk> triangle{}, hit_triangle{};
  std::size_t traced_total = 0;
  std::chrono::steady_clock::duration in_embree{};
  const bool timed = c.counts != nullptr && c.counts->timed;
  for (std::size_t start = begin; start < end; start += kChunk) {
    const std::size_t count = std::min(kChunk, end - start);
    fill(start, count, d.data(), column.data());
    std::size_t traced = 0;
    for (std::size_t k = 0; k < count; ++k) {
      hit[k] = kInf;
      if constexpr (wants_triangle) hit_triangle[k] = EmbreeScene::kNoTriangle;
      const double sin_el = d[k].z();
      if (c.clearance.clear(sin_el, column[k])) continue;
      const double bound = visible_far_bound(s, sin_el);
      if (!(bound > 0.0)) continue;
      for (int a = 0; a < 3; ++a) rays[3 * traced + a] = static_cast<float>(d[k][a]);
      t_max[traced] = static_cast<float>(bound) * (1.0f + 1e-6f);
      slot[traced++] = static_cast<std::uint8_t>(k);
    }
    if (traced > 0) {
      const auto before = timed ? std::chrono::steady_clock::now() : std::chrono::steady_clock::time_point{};
      c.embree.trace(s.g, rays.data(), traced, 0.0f, t_far, t.data(), ground.data(), t_max.data(),
                     wants_triangle ? triangle.data() : nullptr);
      if (timed) in_embree += std::chrono::steady_clock::now() - before;
    }
    for (std::size_t m = 0; m < traced; ++m)
      if (!ground[m]) {
        hit[slot[m]] = static_cast<double>(t[m]);
        if constexpr (wants_triangle) hit_triangle[slot[m]] = triangle[m];
      }
    for (std::size_t k = 0; k < count; ++k) {
      if constexpr (wants_triangle) store(start + k, d[k], hit[k], hit_triangle[k]);
      else store(start + k, d[k], hit[k]);
    }
    traced_total += traced;
  }
  if (c.counts != nullptr) {
    c.counts->traced += traced_total;
    c.counts->skipped += (end - begin) - traced_total;
    c.counts->embree_ns += std::chrono::duration_cast<std::chrono::nanoseconds>(in_embree).count();
  }
}

// trace_range over [0, n), in parallel when c.parallel. The chunks of 64 rays start at multiples
// of 64 either way: Embree's result for a ray may depend in its last bits on the rays traced with
// it, and the VV must not depend on the number of threads.
template <class Fill, class Store>
void trace_all(const TraceContext& c, std::size_t n, Fill fill, Store store) {
  // Tasks of 8 chunks (512 rays): a VV alone spreads its bisection rounds (1-4k rays each) over
  // the threads too, not only its corner rays.
  constexpr std::size_t kChunksPerTask = 8;
  if (!c.parallel || n < 2 * 64 * kChunksPerTask) {
    FlushDenormals flush;
    trace_range(c, 0, n, fill, store);
    return;
  }
  const std::size_t tasks = (n + 64 * kChunksPerTask - 1) / (64 * kChunksPerTask);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tasks, 1), [&](const tbb::blocked_range<std::size_t>& r) {
    FlushDenormals flush;
    trace_range(c, r.begin() * 64 * kChunksPerTask, std::min(n, r.end() * 64 * kChunksPerTask), fill, store);
  });
}

}  // namespace vistrack::detail
