// Branch-free sin/cos and atan2 for the Dubins length kernel: straight-line code (selects, no
// table lookups, no slow paths) so the compiler can keep the batch loop branch-light.
// Accuracy: a few ulp on the ranges used (checked against std:: in dubins_test.cpp).
// sin/cos: Cody-Waite reduction by pi/2 in three parts (exact for |x| < 2^20 * pi/2) and the
// fdlibm kernel polynomials; larger |x| falls back to std::sin/std::cos.
// atan2: reduction to [0, 1] by swapping |x|, |y|, then to [-0.1716, 0.4142] around pi/4 and the
// Cephes rational approximation of atan.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

// Forced inlining: the kernel is small straight-line code; keep it in the callers' loops.
#if defined(__GNUC__)
#define VISTRACK_DUBINS_INLINE inline __attribute__((always_inline))
#else
#define VISTRACK_DUBINS_INLINE inline
#endif

namespace vistrack::detail {

struct SinCos {
  double s, c;
};

// |x| below this uses the polynomial path (the three-part reduction is exact there).
constexpr double kFastTrigLimit = 1.0e6;

// Nearest integer of x (|x| < 2^51) as a double, by the 1.5 * 2^52 shift; no libm call.
VISTRACK_DUBINS_INLINE double round_shift(double x) {
  constexpr double kShift = 6755399441055744.0;
  return (x + kShift) - kShift;
}

// sin and cos for |x| < kFastTrigLimit: straight-line code, vectorizable.
VISTRACK_DUBINS_INLINE SinCos sincos_poly(double x) {
  const double shifted = x * 0.63661977236758134308 + 6755399441055744.0;
  const double kd = shifted - 6755399441055744.0;
  std::int64_t bits;
  std::memcpy(&bits, &shifted, sizeof bits);  // low bits of the mantissa hold kd mod 4
  const std::int64_t quadrant = bits & 3;
  const double r = ((x - kd * 1.57079632673412561417e+00) - kd * 6.07710050630396597660e-11) -
                   kd * 2.02226624871116645580e-21;
  const double z = r * r;
  const double sin_r =
      r + r * z *
              (-1.66666666666666324348e-01 +
               z * (8.33333333332248946124e-03 +
                    z * (-1.98412698298579493134e-04 +
                         z * (2.75573137070700676789e-06 + z * (-2.50507602534068634195e-08 + z * 1.58969099521155010221e-10)))));
  const double hz = 0.5 * z;
  const double w = 1.0 - hz;
  const double cos_r =
      w + (((1.0 - w) - hz) +
           z * z *
               (4.16666666666666019037e-02 +
                z * (-1.38888888888741095749e-03 +
                     z * (2.48015872894767294178e-05 +
                          z * (-2.75573143513906633035e-07 + z * (2.08757232129817482790e-09 + z * -1.13596475577881948265e-11))))));
  const bool odd = (quadrant & 1) != 0;  // selects below, no branches
  const double s = odd ? cos_r : sin_r;
  const double c = odd ? sin_r : cos_r;
  return {(quadrant & 2) != 0 ? -s : s, ((quadrant + 1) & 2) != 0 ? -c : c};
}

inline SinCos fast_sincos(double x) {
  if (!(std::fabs(x) < kFastTrigLimit)) return {std::sin(x), std::cos(x)};
  return sincos_poly(x);
}

// x mod 2 pi in [0, 2 pi] for |x| < kFastTrigLimit (three-part 2 pi, exact products).
VISTRACK_DUBINS_INLINE double mod_two_pi_poly(double x) {
  const double k = round_shift(x * 0.15915494309189533577);
  double r = ((x - k * 6.28318530693650245667e+00) - k * 2.43084020252158639064e-10) - k * 8.08906499484466582320e-21;
  r = r < 0.0 ? r + 6.28318530717958647692 : r;
  return r;
}

VISTRACK_DUBINS_INLINE double fast_atan2(double y, double x) {
  constexpr double kPiD = 3.14159265358979323846;
  const double ax = std::fabs(x), ay = std::fabs(y);
  const bool swap = ay > ax;
  const double num = swap ? ax : ay, den = swap ? ay : ax;
  double t = num / std::max(den, 1e-300);  // in [0, 1]; 0 / tiny = 0 when x = y = 0
  // atan(t) = pi/4 + atan((t - 1) / (t + 1)) for t > 0.66 (Cephes' split).
  const bool upper = t > 0.66;
  t = upper ? (t - 1.0) / (t + 1.0) : t;
  const double z = t * t;
  const double p = (((-8.750608600031904122785e-1 * z - 1.615753718733365076637e1) * z - 7.500855792314704667340e1) * z -
                    1.228866684490136173410e2) *
                       z -
                   6.485021904942025371773e1;
  const double q = ((((z + 2.485846490142306297962e1) * z + 1.650270098316988542046e2) * z + 4.328810604912902668951e2) * z +
                    4.853903996359136964868e2) *
                       z +
                   1.945506571482613964425e2;
  double a = t + t * (z * p / q);
  a = upper ? a + (0.25 * kPiD + 0.5 * 6.123233995736765886130e-17) : a;
  a = swap ? (0.5 * kPiD - a) : a;
  a = x < 0.0 ? (kPiD - a) : a;
  return std::copysign(a, y);
}

}  // namespace vistrack::detail
