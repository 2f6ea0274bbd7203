// The visiting order: the plan's own length (every leg a Dubins-type path of the method) is the
// cost. Exact: depth-first branch and bound over the orders, the walkers committing the path as
// each AOI is chosen, with an admissible bound (the length so far, each AOI still to fly its
// minimum loiter, and a gap between circles to reach it). Heuristic: 2-opt and or-opt moves from
// the given and the nearest-neighbour orders.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "loiter/walkers.hpp"
#include "vistrack/error.hpp"
#include "vistrack/loiter.hpp"

namespace vistrack {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

template <class Walker>
double order_length(const LoiterProblem& problem, const std::vector<int>& order) {
  Walker walker(problem, detail::PathSink());
  for (const int aoi : order)
    if (!walker.visit(aoi)) return kInfinity;
  return walker.finish() ? walker.length() : kInfinity;
}

template <class Walker>
class BranchAndBound {
 public:
  BranchAndBound(const LoiterProblem& problem, double incumbent, std::vector<int> incumbent_order)
      : problem_(problem),
        n_(problem.aois.size()),
        per_aoi_(Walker::per_aoi_minimum(problem)),
        best_(incumbent),
        best_order_(std::move(incumbent_order)) {
    const double R = problem.parameters.aoi_radius;
    reach_.assign(n_, kInfinity);
    to_end_.assign(n_, 0.0);
    for (std::size_t j = 0; j < n_; ++j) {
      const Vec2& p = problem.aois[j];
      // To reach circle j the aircraft comes from the start or from another circle.
      reach_[j] = std::max(0.0, (p - problem.start).norm() - R);
      for (std::size_t k = 0; k < n_; ++k)
        if (k != j) reach_[j] = std::min(reach_[j], std::max(0.0, (p - problem.aois[k]).norm() - 2.0 * R));
      to_end_[j] = std::max(0.0, (problem.end - p).norm() - R);
    }
    current_.resize(n_);
  }

  std::vector<int> run() {
    search(Walker(problem_, detail::PathSink()), 0, 0, -1);
    return best_order_;
  }
  double best() const { return best_; }

 private:
  void search(const Walker& walker, std::uint32_t visited, std::size_t depth, int last) {
    if (depth == n_) {
      Walker done = walker;
      if (done.finish() && done.length() < best_) {
        best_ = done.length();
        best_order_ = current_;
      }
      return;
    }
    // Admissible: what is committed, the pending AOI's and every unvisited AOI's least loiter,
    // the gap to reach each unvisited circle, and the way from some circle to the end.
    double bound = walker.length() + (last >= 0 ? per_aoi_ : 0.0);
    double end_gap = last >= 0 ? to_end_[static_cast<std::size_t>(last)] : kInfinity;
    for (std::size_t j = 0; j < n_; ++j)
      if (!(visited & (1u << j))) {
        bound += per_aoi_ + reach_[j];
        end_gap = std::min(end_gap, to_end_[j]);
      }
    if (bound + end_gap >= best_ * (1.0 - 1e-12)) return;
    for (std::size_t j = 0; j < n_; ++j) {
      if (visited & (1u << j)) continue;
      Walker next = walker;
      if (!next.visit(static_cast<int>(j))) continue;
      current_[depth] = static_cast<int>(j);
      search(next, visited | (1u << j), depth + 1, static_cast<int>(j));
    }
  }

  const LoiterProblem& problem_;
  std::size_t n_;
  double per_aoi_;
  double best_;
  std::vector<int> best_order_;
  std::vector<double> reach_, to_end_;
  std::vector<int> current_;
};

template <class Walker>
std::pair<std::vector<int>, double> improve(const LoiterProblem& problem, std::vector<int> order) {
  double length = order_length<Walker>(problem, order);
  const std::size_t n = order.size();
  bool improved = true;
  while (improved) {
    improved = false;
    for (std::size_t i = 0; i + 1 < n; ++i)  // 2-opt: reverse order[i..j]
      for (std::size_t j = i + 1; j < n; ++j) {
        std::vector<int> candidate = order;
        std::reverse(candidate.begin() + static_cast<std::ptrdiff_t>(i),
                     candidate.begin() + static_cast<std::ptrdiff_t>(j) + 1);
        const double l = order_length<Walker>(problem, candidate);
        if (l < length * (1.0 - 1e-12)) {
          order = std::move(candidate);
          length = l;
          improved = true;
        }
      }
    for (std::size_t i = 0; i < n; ++i)  // or-opt: move one AOI elsewhere
      for (std::size_t j = 0; j < n; ++j) {
        if (i == j) continue;
        std::vector<int> candidate = order;
        const int moved = candidate[i];
        candidate.erase(candidate.begin() + static_cast<std::ptrdiff_t>(i));
        candidate.insert(candidate.begin() + static_cast<std::ptrdiff_t>(j), moved);
        const double l = order_length<Walker>(problem, candidate);
        if (l < length * (1.0 - 1e-12)) {
          order = std::move(candidate);
          length = l;
          improved = true;
        }
      }
  }
  return {order, length};
}

std::vector<int> nearest_neighbour(const LoiterProblem& problem) {
  std::vector<int> order;
  std::vector<bool> used(problem.aois.size(), false);
  Vec2 at = problem.start;
  for (std::size_t k = 0; k < problem.aois.size(); ++k) {
    int best = -1;
    double best_distance = kInfinity;
    for (std::size_t j = 0; j < problem.aois.size(); ++j) {
      const double d = (problem.aois[j] - at).norm();
      if (!used[j] && d < best_distance) {
        best = static_cast<int>(j);
        best_distance = d;
      }
    }
    used[static_cast<std::size_t>(best)] = true;
    order.push_back(best);
    at = problem.aois[static_cast<std::size_t>(best)];
  }
  return order;
}

template <class Walker>
std::vector<int> best_order(const LoiterProblem& problem, bool exact) {
  std::vector<int> given(problem.aois.size());
  std::iota(given.begin(), given.end(), 0);
  auto [order, length] = improve<Walker>(problem, given);
  auto [other, other_length] = improve<Walker>(problem, nearest_neighbour(problem));
  if (other_length < length) {
    order = other;
    length = other_length;
  }
  if (exact) {
    // The heuristic's order is the first incumbent; infinite when it found none feasible.
    BranchAndBound<Walker> search(problem, std::isfinite(length) ? length * (1.0 + 1e-12) : kInfinity, order);
    order = search.run();
    length = search.best();
  }
  if (!std::isfinite(length)) {
    // No feasible order was found: report why the given order fails.
    Walker walker(problem, detail::PathSink());
    for (const int aoi : given)
      if (!walker.visit(aoi)) walker.failure().raise(problem);
    if (!walker.finish()) walker.failure().raise(problem);
  }
  return order;
}

}  // namespace

double loiter_order_length(const LoiterProblem& problem, LoiterMethod method, const std::vector<int>& order) {
  switch (method) {
    case LoiterMethod::FlyThrough: return order_length<detail::FlyThroughWalker>(problem, order);
    case LoiterMethod::Tlpp: return order_length<detail::TlppWalker>(problem, order);
    case LoiterMethod::Ldlpp: return order_length<detail::LdlppWalker>(problem, order);
    case LoiterMethod::TlppBest: return order_length<detail::TlppBothWalker>(problem, order);
    case LoiterMethod::LdlppBest: return order_length<detail::LdlppBestWalker>(problem, order);
  }
  return kInfinity;
}

std::vector<int> best_loiter_order(const LoiterProblem& problem, LoiterMethod method, bool exact) {
  problem.validate();
  if (exact && problem.aois.size() > 12)
    detail::fail_field("aois", std::to_string(problem.aois.size()) + " AOIs",
                       "the exact order search takes at most 12 (use the heuristic)");
  switch (method) {
    case LoiterMethod::FlyThrough: return best_order<detail::FlyThroughWalker>(problem, exact);
    case LoiterMethod::Tlpp: return best_order<detail::TlppWalker>(problem, exact);
    case LoiterMethod::Ldlpp: return best_order<detail::LdlppWalker>(problem, exact);
    case LoiterMethod::TlppBest: return best_order<detail::TlppBothWalker>(problem, exact);
    case LoiterMethod::LdlppBest: return best_order<detail::LdlppBestWalker>(problem, exact);
  }
  return {};
}

}  // namespace vistrack
