// Shortest Dubins lengths for many pairs: an allocation-free kernel (branch-free CSC part with
// polynomial sin/cos/atan2, CCC words only for the pairs whose circles are within 4 rho), TBB
// across cores.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <array>
#include <cmath>
#include <limits>

#include "dubins/kernel.hpp"
#include "vistrack/dubins.hpp"
#include "vistrack/error.hpp"

namespace vistrack {
namespace {

constexpr std::array<const char*, 3> kComponent{"x", "y", "psi"};

void require_finite_rows(const double* rows, std::size_t n, const char* name) {
  for (std::size_t i = 0; i < 3 * n; ++i)
    if (!std::isfinite(rows[i]))
      detail::fail_field(std::string(name) + "[" + std::to_string(i / 3) + "]." + kComponent[i % 3],
                         rows[i], "must be a finite number");
}

void lengths_range(const double* q0s, const double* q1s, std::size_t begin, std::size_t end, double rho,
                   double* lengths, std::uint8_t* words) {
  for (std::size_t i = begin; i < end; ++i) {
    const Configuration a{q0s[3 * i], q0s[3 * i + 1], q0s[3 * i + 2]};
    const Configuration b{q1s[3 * i], q1s[3 * i + 1], q1s[3 * i + 2]};
    std::uint8_t word = 0;
    lengths[i] = detail::shortest_length_normalised(detail::make_frame(a, b, rho), word) * rho;
    words[i] = word;
  }
}

}  // namespace

double dubins_shortest_length(const Configuration& q0, const Configuration& q1, double rho,
                              DubinsWord* word) {
  std::uint8_t k = 0;
  const double length = detail::shortest_length_normalised(detail::make_frame(q0, q1, rho), k) * rho;
  if (word) *word = static_cast<DubinsWord>(k);
  return length;
}

void dubins_shortest_lengths(const double* q0s, const double* q1s, std::size_t n, double rho,
                             double* lengths, std::uint8_t* words, int threads) {
  require_positive(rho, "rho");
  if (threads < 0) detail::fail_field("threads", threads, "must be 0 (all cores) or positive");
  require_finite_rows(q0s, n, "q0s");
  require_finite_rows(q1s, n, "q1s");
  const auto run = [&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1024), [&](const tbb::blocked_range<std::size_t>& range) {
      lengths_range(q0s, q1s, range.begin(), range.end(), rho, lengths, words);
    });
  };
  if (threads == 0) {
    run();
  } else {
    tbb::task_arena arena(threads);
    arena.execute(run);
  }
}

DubinsBatch dubins_shortest_lengths(const Points3& q0s, const Points3& q1s, double rho, int threads) {
  if (q0s.rows() != q1s.rows())
    detail::fail_field("q1s.rows", q1s.rows(), "must equal q0s.rows = " + std::to_string(q0s.rows()));
  const auto n = static_cast<std::size_t>(q0s.rows());
  DubinsBatch out;
  out.lengths.resize(n);
  out.words.resize(n);
  dubins_shortest_lengths(q0s.data(), q1s.data(), n, rho, out.lengths.data(), out.words.data(), threads);
  return out;
}

}  // namespace vistrack
