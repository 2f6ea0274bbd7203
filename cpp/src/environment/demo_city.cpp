// Environment::demo: an embedded synthetic downtown, generated in code and deterministic on
// every platform (own integer hash, no std distributions, no files).
#include <algorithm>
#include <array>
#include <cmath>

#include "environment/detail.hpp"

namespace vistrack {

namespace {

// Street centre lines, slightly irregular like a real grid; the city spans 800 m x 800 m.
constexpr std::array<double, 9> kStreetX{-400.0, -290.0, -185.0, -95.0, 0.0, 95.0, 185.0, 290.0, 400.0};
constexpr std::array<double, 9> kStreetY{-400.0, -300.0, -210.0, -105.0, 0.0, 100.0, 205.0, 300.0, 400.0};
constexpr double kSetback = 12.0;  // street centre line to building front: carriageway plus sidewalk
constexpr double kGap = 4.0;       // between neighbouring buildings of one block
constexpr double kMinHeight = 10.0;
constexpr double kMaxHeight = 150.0;

// SplitMix64 finaliser: a well-mixed 64-bit hash of the block, the lot and a purpose tag.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

// Uniform in [0, 1) from integer keys.
double unit(std::uint64_t a, std::uint64_t b, std::uint64_t c, std::uint64_t tag) {
  const std::uint64_t h = mix(mix(mix(mix(a) ^ b) ^ c) ^ tag);
  return static_cast<double>(h >> 11) * 0x1.0p-53;
}

Ring rectangle(double x0, double y0, double x1, double y1) {
  return {Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)};
}

// A tall core that falls off towards the edges, with per-lot variation, rounded to 1 m.
double lot_height(const Vec2& centre, double u) {
  const double r = centre.norm() / 400.0;
  const double core = kMinHeight + (kMaxHeight - kMinHeight) * std::exp(-(r / 0.5) * (r / 0.5));
  return std::clamp(std::round(core * (0.5 + 0.7 * u)), kMinHeight, kMaxHeight);
}

void add_block(std::vector<Building>& buildings, std::size_t i, std::size_t j) {
  const double x0 = kStreetX[i] + kSetback, x1 = kStreetX[i + 1] - kSetback;
  const double y0 = kStreetY[j] + kSetback, y1 = kStreetY[j + 1] - kSetback;
  const Vec2 centre(0.5 * (x0 + x1), 0.5 * (y0 + y1));
  const double kind = unit(i, j, 0, 1);
  auto add = [&](Polygon footprint, double height) {
    buildings.push_back({std::move(footprint), height, static_cast<int>(buildings.size())});
  };
  if (i == 3 && j == 3) {
    // The landmark tower of the core: the tallest building, alone on its block.
    add({rectangle(x0 + 8.0, y0 + 10.0, x1 - 8.0, y1 - 10.0), {}}, kMaxHeight);
    return;
  }
  if (centre.norm() > 150.0 && kind < 0.18) {
    // A perimeter block around a courtyard (a footprint with a hole).
    const double depth = 14.0 + 6.0 * unit(i, j, 0, 2);
    add({rectangle(x0, y0, x1, y1), {rectangle(x0 + depth, y1 - depth, x1 - depth, y0 + depth)}},
        std::min(lot_height(centre, unit(i, j, 0, 3)), 40.0));
    return;
  }
  // Otherwise four lots split at a jittered point; each lot holds a rectangle, or an L when
  // the hash says so, set back from the lot edges by a few metres.
  const double sx = x0 + (x1 - x0) * (0.4 + 0.2 * unit(i, j, 0, 4));
  const double sy = y0 + (y1 - y0) * (0.4 + 0.2 * unit(i, j, 0, 5));
  const std::array<std::array<double, 4>, 4> lots{{{x0, y0, sx - 0.5 * kGap, sy - 0.5 * kGap},
                                                   {sx + 0.5 * kGap, y0, x1, sy - 0.5 * kGap},
                                                   {x0, sy + 0.5 * kGap, sx - 0.5 * kGap, y1},
                                                   {sx + 0.5 * kGap, sy + 0.5 * kGap, x1, y1}}};
  for (std::uint64_t k = 0; k < lots.size(); ++k) {
    const auto& lot = lots[k];
    const double inset = 3.0 * unit(i, j, k, 6);
    const double a0 = lot[0] + inset, b0 = lot[1] + inset, a1 = lot[2] - inset, b1 = lot[3] - inset;
    const Vec2 lot_centre(0.5 * (a0 + a1), 0.5 * (b0 + b1));
    const double height = lot_height(lot_centre, unit(i, j, k, 7));
    if (unit(i, j, k, 8) < 0.2) {
      // L shape: the lot's rectangle without one quadrant (the hash picks which corner).
      const double cx = a0 + (a1 - a0) * 0.55, cy = b0 + (b1 - b0) * 0.55;
      Ring l_shape{Vec2(a0, b0), Vec2(a1, b0), Vec2(a1, cy), Vec2(cx, cy), Vec2(cx, b1), Vec2(a0, b1)};
      const auto corner = static_cast<int>(4.0 * unit(i, j, k, 9));  // mirror in x and/or y
      for (Vec2& p : l_shape) {
        if (corner & 1) p.x() = a0 + a1 - p.x();
        if (corner & 2) p.y() = b0 + b1 - p.y();
      }
      add({l_shape, {}}, height);
    } else {
      add({rectangle(a0, b0, a1, b1), {}}, height);
    }
  }
}

}  // namespace

Environment Environment::demo() {
  std::vector<Building> buildings;
  for (std::size_t i = 0; i + 1 < kStreetX.size(); ++i)
    for (std::size_t j = 0; j + 1 < kStreetY.size(); ++j) add_block(buildings, i, j);
  // Road nodes at every intersection, edges along the streets between neighbours.
  RoadNetwork roads;
  const auto nx = static_cast<int>(kStreetX.size()), ny = static_cast<int>(kStreetY.size());
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      roads.nodes.emplace_back(kStreetX[static_cast<std::size_t>(i)], kStreetY[static_cast<std::size_t>(j)]);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int node = j * nx + i;
      if (i + 1 < nx) roads.edges.emplace_back(node, node + 1);
      if (j + 1 < ny) roads.edges.emplace_back(node, node + nx);
    }
  return from_buildings(std::move(buildings), std::move(roads));
}

}  // namespace vistrack
