// The road network G = (N, E): validation against the building footprints and shortest routes.
#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "environment/detail.hpp"
#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"

namespace vistrack {

namespace {

std::string point_text(const Vec2& p) { return "(" + detail::to_text(p.x()) + ", " + detail::to_text(p.y()) + ")"; }

// Parameters t in [0, 1] where the segment a + t (b - a) meets the ring: every corner within
// `tolerance` of the segment (this also covers the ends of walls the road runs along, which
// are rarely exactly collinear in floating point), and every proper crossing of an edge.
void boundary_contacts(const Ring& ring, const Vec2& a, const Vec2& b, double tolerance, std::vector<double>& ts) {
  const Vec2 d = b - a;
  const double length_squared = d.squaredNorm();
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2& c = ring[i];
    const double t = std::clamp((c - a).dot(d) / length_squared, 0.0, 1.0);
    if ((a + t * d - c).norm() <= tolerance) ts.push_back(t);
    const Vec2 f = ring[(i + 1) % ring.size()] - c;
    const double denominator = d.x() * f.y() - d.y() * f.x();
    if (std::abs(denominator) <= 1e-12 * std::sqrt(length_squared * f.squaredNorm())) continue;  // parallel
    const Vec2 ac = c - a;
    const double t_cross = (ac.x() * f.y() - ac.y() * f.x()) / denominator;
    const double s_cross = (ac.x() * d.y() - ac.y() * d.x()) / denominator;
    if (t_cross >= 0.0 && t_cross <= 1.0 && s_cross >= 0.0 && s_cross <= 1.0) ts.push_back(t_cross);
  }
}

// True when some part of the segment lies strictly inside the footprint. Between two
// consecutive boundary contacts the segment is either inside or outside, so the midpoint of
// each piece decides; a piece running along a wall is on the boundary, which is allowed.
bool crosses_interior(const Polygon& footprint, const Vec2& a, const Vec2& b) {
  const double scale = std::max({1.0, a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff()});
  const double tolerance = 1e-9 * scale;
  std::vector<double> ts{0.0, 1.0};
  boundary_contacts(footprint.outer, a, b, tolerance, ts);
  for (const Ring& hole : footprint.holes) boundary_contacts(hole, a, b, tolerance, ts);
  std::sort(ts.begin(), ts.end());
  for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
    if (ts[k + 1] - ts[k] <= 1e-12) continue;
    const Vec2 middle = a + 0.5 * (ts[k] + ts[k + 1]) * (b - a);
    if (contains(footprint, middle) && distance_to_boundary(footprint, middle) > tolerance) return true;
  }
  return false;
}

}  // namespace

void validate_road_network(const RoadNetwork& roads, const std::string& field_prefix) {
  const std::string prefix = field_prefix.empty() ? "" : field_prefix + ".";
  const auto node_count = static_cast<int>(roads.nodes.size());
  if (!roads.oneway.empty() && roads.oneway.size() != roads.edges.size())
    detail::fail_field(prefix + "oneway", std::to_string(roads.oneway.size()) + " flags",
                       "needs one flag per edge (" + std::to_string(roads.edges.size()) + ") or none");
  for (std::size_t i = 0; i < roads.nodes.size(); ++i)
    for (int k = 0; k < 2; ++k)
      require_coordinate(roads.nodes[i][k], prefix + "nodes[" + std::to_string(i) + "][" + std::to_string(k) + "]");
  for (std::size_t e = 0; e < roads.edges.size(); ++e) {
    const auto [from, to] = roads.edges[e];
    const std::string field = prefix + "edges[" + std::to_string(e) + "]";
    const std::string value = "(" + std::to_string(from) + ", " + std::to_string(to) + ")";
    if (from < 0 || from >= node_count || to < 0 || to >= node_count)
      detail::fail_field(field, value, "node index out of range [0, " + std::to_string(node_count) + ")");
    if (from == to) detail::fail_field(field, value, "an edge must join two different nodes");
    const Vec2& a = roads.nodes[static_cast<std::size_t>(from)];
    if (a == roads.nodes[static_cast<std::size_t>(to)])
      detail::fail_field(field, value, "the edge has zero length (both nodes at " + point_text(a) + ")");
  }
}

void Environment::set_roads(RoadNetwork roads) {
  validate_road_network(roads);
  std::vector<Bounds2> boxes;
  for (const Building& building : buildings_) boxes.push_back(vistrack::bounds(building.footprint.outer));
  for (std::size_t e = 0; e < roads.edges.size(); ++e) {
    const auto [from, to] = roads.edges[e];
    const std::string field = "roads.edges[" + std::to_string(e) + "]";
    const std::string value = "(" + std::to_string(from) + ", " + std::to_string(to) + ")";
    const Vec2& a = roads.nodes[static_cast<std::size_t>(from)];
    const Vec2& b = roads.nodes[static_cast<std::size_t>(to)];
    const Vec2 low = a.cwiseMin(b), high = a.cwiseMax(b);
    for (std::size_t i = 0; i < buildings_.size(); ++i) {
      const Bounds2& box = boxes[i];
      if (high.x() < box.min.x() || low.x() > box.max.x() || high.y() < box.min.y() || low.y() > box.max.y())
        continue;
      if (crosses_interior(buildings_[i].footprint, a, b))
        detail::fail_field(field, value,
                           "the road from " + point_text(a) + " to " + point_text(b) +
                               " crosses the footprint of building id " + std::to_string(buildings_[i].id) +
                               " (buildings[" + std::to_string(i) + "])");
    }
  }
  roads_ = std::move(roads);
}

namespace {

// Dijkstra's predecessors from `from` (stopping at `to`), one-way edges driven their way only
// unless `ignore_oneway`; distance[to] stays infinite when `to` is unreachable.
std::vector<int> route_tree(const RoadNetwork& roads, int from, int to, bool ignore_oneway, std::vector<double>& distance) {
  const auto n = static_cast<int>(roads.nodes.size());
  std::vector<std::vector<std::pair<int, double>>> adjacent(static_cast<std::size_t>(n));
  for (std::size_t e = 0; e < roads.edges.size(); ++e) {
    const auto [a, b] = roads.edges[e];
    if (a < 0 || a >= n || b < 0 || b >= n)
      detail::fail_field("roads.edges[" + std::to_string(e) + "]", "(" + std::to_string(a) + ", " + std::to_string(b) + ")",
                         "node index out of range");
    const double length = (roads.nodes[static_cast<std::size_t>(a)] - roads.nodes[static_cast<std::size_t>(b)]).norm();
    adjacent[static_cast<std::size_t>(a)].emplace_back(b, length);
    if (ignore_oneway || !roads.is_oneway(e)) adjacent[static_cast<std::size_t>(b)].emplace_back(a, length);
  }
  distance.assign(static_cast<std::size_t>(n), std::numeric_limits<double>::infinity());
  std::vector<int> previous(static_cast<std::size_t>(n), -1);
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  distance[static_cast<std::size_t>(from)] = 0.0;
  queue.emplace(0.0, from);
  while (!queue.empty()) {
    const auto [d, node] = queue.top();
    queue.pop();
    if (d > distance[static_cast<std::size_t>(node)]) continue;
    if (node == to) break;
    for (const auto& [next, length] : adjacent[static_cast<std::size_t>(node)]) {
      const double candidate = d + length;
      // Ties go to the lower node index, so the route does not depend on edge order.
      auto& best = distance[static_cast<std::size_t>(next)];
      if (candidate < best || (candidate == best && node < previous[static_cast<std::size_t>(next)])) {
        best = candidate;
        previous[static_cast<std::size_t>(next)] = node;
        queue.emplace(candidate, next);
      }
    }
  }
  return previous;
}

}  // namespace

std::vector<int> shortest_route(const RoadNetwork& roads, int from, int to) {
  const auto n = static_cast<int>(roads.nodes.size());
  if (from < 0 || from >= n) detail::fail_field("from", from, "no such road node");
  if (to < 0 || to >= n) detail::fail_field("to", to, "no such road node");
  std::vector<double> distance;
  const std::vector<int> previous = route_tree(roads, from, to, false, distance);
  if (!std::isfinite(distance[static_cast<std::size_t>(to)])) {
    std::vector<double> undirected;
    route_tree(roads, from, to, true, undirected);
    if (std::isfinite(undirected[static_cast<std::size_t>(to)]))
      detail::fail_field("to", to, "no road route from node " + std::to_string(from) +
                                       " that respects one-way streets (there is one driving against them)");
    detail::fail_field("to", to, "no road route from node " + std::to_string(from));
  }
  std::vector<int> route{to};
  while (route.back() != from) route.push_back(previous[static_cast<std::size_t>(route.back())]);
  std::reverse(route.begin(), route.end());
  return route;
}

}  // namespace vistrack
