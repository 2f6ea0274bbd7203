// The inner loop of corner_hits (private to the library): one triangle tested against a run of
// directions of one row of the sphere grid, in plain C++ and four directions per AVX2 instruction.
#pragma once

#include <cstdint>

namespace vistrack::detail {

// One row's run of columns [first, last] against one triangle: coefficients a, b, c give edge
// e . d (e < 3) and plane . d (e = 3) as a[e] cos az + b[e] sin az + c[e]. Keeps per column the
// nearest hit as its inverse distance w = plane . d / offset (no division per direction; larger is
// nearer, 0 none) and its owner (the footprint's ordinal): where all three edge tests are >= 0,
// w >= w_min and w > row_w[j], row_w[j] = w and row_owner[j] = owner. GCC compiles the two stores
// under one branch and does not vectorize the loop for plain x86-64 (runs are about 5 columns).
inline void scan_run(const double* __restrict cos_az, const double* __restrict sin_az, int first, int last,
                     const double* a, const double* b, const double* c, double inv_offset, double w_min,
                     std::uint32_t owner, double* __restrict row_w, std::uint32_t* __restrict row_owner) {
  const double a0 = a[0], a1 = a[1], a2 = a[2], a3 = a[3], b0 = b[0], b1 = b[1], b2 = b[2], b3 = b[3];
  const double c0 = c[0], c1 = c[1], c2 = c[2], c3 = c[3];
  for (int j = first; j <= last; ++j) {
    const double ca = cos_az[j], sa = sin_az[j];
    const double e0 = a0 * ca + b0 * sa + c0;
    const double e1 = a1 * ca + b1 * sa + c1;
    const double e2 = a2 * ca + b2 * sa + c2;
    const double w = (a3 * ca + b3 * sa + c3) * inv_offset;
    const bool take = (e0 >= 0.0) & (e1 >= 0.0) & (e2 >= 0.0) & (w >= w_min) & (w > row_w[j]);
    row_w[j] = take ? w : row_w[j];
    row_owner[j] = take ? owner : row_owner[j];
  }
}

// scan_run, four columns per AVX2 instruction: the same operations in the same order (no FMA),
// so every column rounds and decides exactly as in scan_run (visibility_test checks bit
// equality). Call only where avx2_kernel_available() (simd/cpu.hpp).
void scan_run_avx2(const double* cos_az, const double* sin_az, int first, int last, const double* a,
                   const double* b, const double* c, double inv_offset, double w_min, std::uint32_t owner,
                   double* row_w, std::uint32_t* row_owner);

}  // namespace vistrack::detail
