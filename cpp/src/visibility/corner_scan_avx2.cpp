// scan_run four columns at a time with AVX2 (see corner_scan.hpp). Like dubins_batch_avx2.cpp,
// this file is compiled for AVX2 by the pragma below, which follows the only other include (the
// header, whose inline scan_run is thus built for plain x86-64), so no inline function built for
// AVX2 can leak into the rest of the library; corner_hits checks the CPU before calling it.
#include "visibility/corner_scan.hpp"

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define VISTRACK_HAVE_AVX2_SCAN 1
#pragma GCC target("avx2")
#include <immintrin.h>
#endif

namespace vistrack::detail {

#if VISTRACK_HAVE_AVX2_SCAN

void scan_run_avx2(const double* cos_az, const double* sin_az, int first, int last, const double* a,
                   const double* b, const double* c, double inv_offset, double w_min, std::uint32_t owner,
                   double* row_w, std::uint32_t* row_owner) {
  const __m256d a0 = _mm256_set1_pd(a[0]), a1 = _mm256_set1_pd(a[1]), a2 = _mm256_set1_pd(a[2]);
  const __m256d a3 = _mm256_set1_pd(a[3]);
  const __m256d b0 = _mm256_set1_pd(b[0]), b1 = _mm256_set1_pd(b[1]), b2 = _mm256_set1_pd(b[2]);
  const __m256d b3 = _mm256_set1_pd(b[3]);
  const __m256d c0 = _mm256_set1_pd(c[0]), c1 = _mm256_set1_pd(c[1]), c2 = _mm256_set1_pd(c[2]);
  const __m256d c3 = _mm256_set1_pd(c[3]);
  const __m256d inv = _mm256_set1_pd(inv_offset), floor = _mm256_set1_pd(w_min), zero = _mm256_setzero_pd();
  const __m128i owners = _mm_set1_epi32(static_cast<int>(owner));
  const __m256i lane = _mm256_set_epi64x(3, 2, 1, 0);
  // The low 32 bits of each 64-bit lane of a mask: the owners' mask.
  const __m256i low_halves = _mm256_set_epi32(7, 7, 7, 7, 6, 4, 2, 0);
  for (int j = first; j <= last; j += 4) {
    // Lanes past `last` load nothing, store nothing and take nothing.
    const __m256i in_run = _mm256_cmpgt_epi64(_mm256_set1_epi64x(last - j + 1), lane);
    const __m256d ca = _mm256_maskload_pd(cos_az + j, in_run), sa = _mm256_maskload_pd(sin_az + j, in_run);
    const __m256d old = _mm256_maskload_pd(row_w + j, in_run);
    // ((a ca) + (b sa)) + c, as scan_run's expressions associate.
    const __m256d e0 = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(a0, ca), _mm256_mul_pd(b0, sa)), c0);
    const __m256d e1 = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(a1, ca), _mm256_mul_pd(b1, sa)), c1);
    const __m256d e2 = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(a2, ca), _mm256_mul_pd(b2, sa)), c2);
    const __m256d w =
        _mm256_mul_pd(_mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(a3, ca), _mm256_mul_pd(b3, sa)), c3), inv);
    __m256d take = _mm256_and_pd(_mm256_cmp_pd(e0, zero, _CMP_GE_OQ), _mm256_cmp_pd(e1, zero, _CMP_GE_OQ));
    take = _mm256_and_pd(take, _mm256_cmp_pd(e2, zero, _CMP_GE_OQ));
    take = _mm256_and_pd(take, _mm256_cmp_pd(w, floor, _CMP_GE_OQ));
    take = _mm256_and_pd(take, _mm256_cmp_pd(w, old, _CMP_GT_OQ));
    const __m256i store = _mm256_and_si256(_mm256_castpd_si256(take), in_run);
    if (_mm256_testz_si256(store, store)) continue;
    _mm256_maskstore_pd(row_w + j, store, w);
    const __m128i store32 = _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(store, low_halves));
    _mm_maskstore_epi32(reinterpret_cast<int*>(row_owner + j), store32, owners);
  }
}

#else

void scan_run_avx2(const double*, const double*, int, int, const double*, const double*, const double*, double,
                   double, std::uint32_t, double*, std::uint32_t*) {}

#endif

}  // namespace vistrack::detail
