// Shortest Dubins lengths for many pairs: one allocation-free kernel, TBB across cores.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

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

// Minimum over the six words without building paths.
inline double shortest_normalised(const detail::DubinsFrame& f, std::uint8_t& word) {
  double best = detail::word_lsl(f).total();
  std::uint8_t best_word = 0;
  const auto consider = [&](const detail::WordSegments& w, std::uint8_t k) {
    if (w.ok && w.total() < best) {
      best = w.total();
      best_word = k;
    }
  };
  consider(detail::word_lsr(f), 1);
  consider(detail::word_rsl(f), 2);
  consider(detail::word_rsr(f), 3);
  consider(detail::word_rlr(f), 4);
  consider(detail::word_lrl(f), 5);
  word = best_word;
  return best;
}

}  // namespace

double dubins_shortest_length(const Configuration& q0, const Configuration& q1, double rho,
                              DubinsWord* word) {
  std::uint8_t k = 0;
  const double length = shortest_normalised(detail::make_frame(q0, q1, rho), k) * rho;
  if (word) *word = static_cast<DubinsWord>(k);
  return length;
}

void dubins_shortest_lengths(const double* q0s, const double* q1s, std::size_t n, double rho,
                             double* lengths, std::uint8_t* words) {
  require_positive(rho, "rho");
  require_finite_rows(q0s, n, "q0s");
  require_finite_rows(q1s, n, "q1s");
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 2048),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i) {
                        const Configuration a{q0s[3 * i], q0s[3 * i + 1], q0s[3 * i + 2]};
                        const Configuration b{q1s[3 * i], q1s[3 * i + 1], q1s[3 * i + 2]};
                        std::uint8_t k = 0;
                        lengths[i] = shortest_normalised(detail::make_frame(a, b, rho), k) * rho;
                        words[i] = k;
                      }
                    });
}

DubinsBatch dubins_shortest_lengths(const Points3& q0s, const Points3& q1s, double rho) {
  if (q0s.rows() != q1s.rows())
    detail::fail_field("q1s.rows", q1s.rows(), "must equal q0s.rows = " + std::to_string(q0s.rows()));
  const auto n = static_cast<std::size_t>(q0s.rows());
  DubinsBatch out;
  out.lengths.resize(n);
  out.words.resize(n);
  dubins_shortest_lengths(q0s.data(), q1s.data(), n, rho, out.lengths.data(), out.words.data());
  return out;
}

}  // namespace vistrack
