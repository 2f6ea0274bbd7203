// Dubins shortest path over the six words, one given word, and evaluation along a path.
#include <algorithm>
#include <cmath>
#include <limits>

#include "dubins/kernel.hpp"
#include "dubins/path_integration.hpp"
#include "dubins/validate.hpp"
#include "vistrack/dubins.hpp"
#include "vistrack/error.hpp"

namespace vistrack {
namespace {

DubinsPath make_path(const Configuration& q0, const Configuration& q1, double rho, DubinsWord word,
                     const detail::WordSegments& w) {
  DubinsPath path;
  path.start = q0;
  path.goal = q1;
  path.rho = rho;
  path.word = word;
  path.segment_lengths = {w.t * rho, w.p * rho, w.q * rho};
  path.length = path.segment_lengths[0] + path.segment_lengths[1] + path.segment_lengths[2];
  return path;
}

// Advance configuration q along one segment by arc length `distance` (m). The chord forms
// 2 sin(a/2) cos(h + a/2) avoid cancellation for short arcs.
void advance(Configuration& q, DubinsSegment type, double distance, double rho) {
  if (type == DubinsSegment::Straight) {
    q.x += distance * std::cos(q.psi);
    q.y += distance * std::sin(q.psi);
    return;
  }
  const double turn = (type == DubinsSegment::Left ? 1.0 : -1.0) * distance / rho;
  const double chord = 2.0 * rho * std::sin(0.5 * distance / rho);  // always forward
  const double mid = q.psi + 0.5 * turn;
  q.x += chord * std::cos(mid);
  q.y += chord * std::sin(mid);
  q.psi += turn;
}

}  // namespace

void validate_dubins_problem(const Configuration& q0, const Configuration& q1, double rho) {
  detail::require_dubins_problem(q0, q1, rho);
}

std::array<DubinsSegment, 3> segment_types(DubinsWord word) {
  using S = DubinsSegment;
  switch (word) {
    case DubinsWord::LSL: return {S::Left, S::Straight, S::Left};
    case DubinsWord::LSR: return {S::Left, S::Straight, S::Right};
    case DubinsWord::RSL: return {S::Right, S::Straight, S::Left};
    case DubinsWord::RSR: return {S::Right, S::Straight, S::Right};
    case DubinsWord::RLR: return {S::Right, S::Left, S::Right};
    case DubinsWord::LRL: return {S::Left, S::Right, S::Left};
  }
  detail::fail_field("word", static_cast<int>(word), "unknown Dubins word");
}

Configuration detail::integrate(const DubinsPath& path, double s) {
  Configuration q = path.start;
  const auto types = path.segment_types();
  double remaining = s;
  for (int k = 0; k < 3 && remaining > 0.0; ++k) {
    const double d = std::min(remaining, path.segment_lengths[static_cast<std::size_t>(k)]);
    advance(q, types[static_cast<std::size_t>(k)], d, path.rho);
    remaining -= d;
  }
  return q;
}

Configuration DubinsPath::at(double s) const {
  if (!(s >= 0.0) || !(s <= length))
    detail::fail_field("s", s, "arc length must lie in [0, length = " + detail::computed_text(length) + "]");
  if (s == length) return goal;
  return detail::integrate(*this, s);
}

Points3 DubinsPath::sample(double step) const {
  require_length(step, "step");
  const double count_real = std::floor(length / step);
  if (count_real > 1e8) detail::fail_field("step", step, "gives more than 1e8 samples");
  if (length == 0.0) {  // start and goal coincide: one row, the goal
    Points3 row(1, 3);
    row << goal.x, goal.y, goal.psi;
    return row;
  }
  auto count = static_cast<Eigen::Index>(count_real);
  // The last regular sample may coincide with the goal; keep the goal once.
  if (count > 0 && static_cast<double>(count) * step >= length) --count;
  Points3 rows(count + 2, 3);
  for (Eigen::Index k = 0; k <= count; ++k) {
    const Configuration q = detail::integrate(*this, static_cast<double>(k) * step);
    rows.row(k) << q.x, q.y, q.psi;
  }
  rows.row(count + 1) << goal.x, goal.y, goal.psi;
  return rows;
}

Points3 DubinsPath::sample_at(const std::vector<double>& arc_lengths) const {
  Points3 rows(static_cast<Eigen::Index>(arc_lengths.size()), 3);
  for (std::size_t k = 0; k < arc_lengths.size(); ++k) {
    const double s = arc_lengths[k];
    if (!(s >= 0.0) || !(s <= length))
      detail::fail_field("arc_lengths[" + std::to_string(k) + "]", s,
                         "must lie in [0, length = " + detail::computed_text(length) + "]");
    const Configuration q = at(s);
    rows.row(static_cast<Eigen::Index>(k)) << q.x, q.y, q.psi;
  }
  return rows;
}

std::array<double, kDubinsWordCount> dubins_word_lengths(const Configuration& q0,
                                                         const Configuration& q1, double rho) {
  detail::require_dubins_problem(q0, q1, rho);
  const detail::DubinsFrame f = detail::make_frame(q0, q1, rho);
  std::array<double, kDubinsWordCount> lengths{};
  for (int k = 0; k < kDubinsWordCount; ++k) {
    const detail::WordSegments w = detail::word_segments(f, static_cast<DubinsWord>(k));
    lengths[static_cast<std::size_t>(k)] =
        w.ok ? (w.t * rho + w.p * rho + w.q * rho) : std::numeric_limits<double>::infinity();
  }
  return lengths;
}

DubinsPath dubins_path(const Configuration& q0, const Configuration& q1, double rho, DubinsWord word) {
  detail::require_dubins_problem(q0, q1, rho);
  if (static_cast<int>(word) >= kDubinsWordCount)
    detail::fail_field("word", static_cast<int>(word), "unknown Dubins word");
  const detail::DubinsFrame f = detail::make_frame(q0, q1, rho);
  const detail::WordSegments w = detail::word_segments(f, word);
  if (!w.ok)
    detail::fail_field("word", to_string(word),
                       "no path of this word between q0 and q1 (CCC needs circle centres within 4 rho, "
                       "LSR/RSL needs them at least 2 rho apart)");
  return make_path(q0, q1, rho, word, w);
}

DubinsPath dubins_shortest_path(const Configuration& q0, const Configuration& q1, double rho) {
  detail::require_dubins_problem(q0, q1, rho);
  // The length-only kernel chooses the word (so the batch and this function always agree);
  // the word formulas then give its segments.
  const detail::DubinsFrame f = detail::make_frame(q0, q1, rho);
  std::uint8_t code = 0;
  detail::shortest_length_normalised(f, code);
  const auto best_word = static_cast<DubinsWord>(code);
  const detail::WordSegments best = detail::word_segments(f, best_word);
  return make_path(q0, q1, rho, best_word, best);
}

}  // namespace vistrack
