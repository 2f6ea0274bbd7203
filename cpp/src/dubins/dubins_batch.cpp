// Shortest Dubins lengths for many pairs: an allocation-free kernel (branch-free CSC part with
// polynomial sin/cos/atan2, four pairs per instruction with AVX2 where available; CCC words only
// for the pairs whose circles are within 4 rho), TBB across cores.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "dubins/batch_avx2.hpp"
#include "dubins/kernel.hpp"
#include "dubins/validate.hpp"
#include "simd/cpu.hpp"
#include "vistrack/dubins.hpp"
#include "vistrack/error.hpp"

namespace vistrack {
namespace {

// Rows (x, y, psi): a fast pass over the whole batch, the message only for the first bad row.
void require_configuration_rows(const double* rows, std::size_t n, const char* name) {
  for (std::size_t i = 0; i < n; ++i) {
    const double* q = rows + 3 * i;
    if (std::abs(q[0]) <= limits::kMaxCoordinate && std::abs(q[1]) <= limits::kMaxCoordinate &&
        std::abs(q[2]) <= limits::kMaxAngle)
      continue;
    detail::require_configuration({q[0], q[1], q[2]}, std::string(name) + "[" + std::to_string(i) + "]");
  }
}

constexpr std::size_t kBlock = 256;

// Blocks of pairs: the CSC pass four at a time with AVX2 where the CPU has it, then the few
// pairs close enough for a CCC word. Blocks with huge headings use the scalar path.
void lengths_range(const double* q0s, const double* q1s, std::size_t begin, std::size_t end, double rho,
                   double* lengths, std::uint8_t* words, bool avx2) {
  std::array<double, kBlock> best, code;
  std::array<unsigned char, kBlock> ccc;
  for (std::size_t start = begin; start < end; start += kBlock) {
    const std::size_t count = std::min(kBlock, end - start);
    const double* a = q0s + 3 * start;
    const double* b = q1s + 3 * start;
    bool in_range = true;
    for (std::size_t i = 0; i < count; ++i)
      in_range &= detail::frame_in_poly_range({0.0, 0.0, a[3 * i + 2]}, {0.0, 0.0, b[3 * i + 2]});
    if (!in_range) {
      for (std::size_t i = 0; i < count; ++i) {
        DubinsWord w;
        lengths[start + i] = dubins_shortest_length({a[3 * i], a[3 * i + 1], a[3 * i + 2]},
                                                    {b[3 * i], b[3 * i + 1], b[3 * i + 2]}, rho, &w);
        words[start + i] = static_cast<std::uint8_t>(w);
      }
      continue;
    }
    const std::size_t vectorized = avx2 ? count - count % 4 : 0;
    if (vectorized > 0) detail::csc_block_avx2(a, b, vectorized, rho, kDubinsSnap, best.data(), code.data(), ccc.data());
    for (std::size_t i = vectorized; i < count; ++i) {
      const detail::CscChoice choice = detail::shortest_csc(
          detail::make_frame_poly({a[3 * i], a[3 * i + 1], a[3 * i + 2]}, {b[3 * i], b[3 * i + 1], b[3 * i + 2]}, rho));
      best[i] = choice.length;
      code[i] = choice.code;
      ccc[i] = choice.needs_ccc ? 1 : 0;
    }
    for (std::size_t i = 0; i < count; ++i) {
      auto word = static_cast<std::uint8_t>(code[i]);
      double length = best[i];
      if (ccc[i]) {
        const detail::DubinsFrame f = detail::make_frame_poly({a[3 * i], a[3 * i + 1], a[3 * i + 2]},
                                                              {b[3 * i], b[3 * i + 1], b[3 * i + 2]}, rho);
        length = detail::finish_with_ccc(f, length, word);
      }
      lengths[start + i] = length * rho;
      words[start + i] = word;
    }
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
  require_length(rho, "rho");
  require_threads(threads, "threads");
  require_configuration_rows(q0s, n, "q0s");
  require_configuration_rows(q1s, n, "q1s");
  for (std::size_t i = 0; i < n; ++i) {
    const double* a = q0s + 3 * i;
    const double* b = q1s + 3 * i;
    const double scale = std::max({std::abs(a[0]), std::abs(a[1]), std::abs(b[0]), std::abs(b[1])});
    if (scale > limits::kMaxCoordinateOverRho * rho) detail::require_dubins_scale(scale, rho, "rho (row " + std::to_string(i) + ")");
  }
  const bool avx2 = detail::avx2_kernel_available();
  const auto run = [&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4 * kBlock), [&](const tbb::blocked_range<std::size_t>& range) {
      lengths_range(q0s, q1s, range.begin(), range.end(), rho, lengths, words, avx2);
    });
  };
  // No more threads than TBB would use anyway: an arena of 1e5 threads crashes TBB.
  const int cores = tbb::this_task_arena::max_concurrency();
  if (threads == 0 || threads >= cores) {
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
