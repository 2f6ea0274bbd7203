// AVX2 version of the CSC length kernel: the same operations, in the same order, as
// make_frame_poly + shortest_csc in kernel.hpp / fast_math.hpp (no FMA, so every lane rounds
// exactly like the scalar code; dubins_test checks bit equality). This file is compiled for
// AVX2 by the pragma below and includes nothing but intrinsics, so no inline function built for
// AVX2 can leak into the rest of the library; the caller checks the CPU before using it.
#include "dubins/batch_avx2.hpp"

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define VISTRACK_HAVE_AVX2_KERNEL 1
#pragma GCC target("avx2")
#include <immintrin.h>
#endif

namespace vistrack::detail {

#if VISTRACK_HAVE_AVX2_KERNEL

namespace {

using V = __m256d;
using M = __m256d;  // comparison masks

constexpr double kPiD = 3.14159265358979323846;
constexpr double kTwoPiD = 2.0 * kPiD;

inline V set(double x) { return _mm256_set1_pd(x); }
inline V add(V a, V b) { return _mm256_add_pd(a, b); }
inline V sub(V a, V b) { return _mm256_sub_pd(a, b); }
inline V mul(V a, V b) { return _mm256_mul_pd(a, b); }
inline V div(V a, V b) { return _mm256_div_pd(a, b); }
inline V neg(V a) { return _mm256_xor_pd(a, set(-0.0)); }
inline V abs(V a) { return _mm256_andnot_pd(set(-0.0), a); }
inline M lt(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_LT_OQ); }
inline M le(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_LE_OQ); }
inline M gt(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_GT_OQ); }
inline M ge(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_GE_OQ); }
inline M mand(M a, M b) { return _mm256_and_pd(a, b); }
inline M mor(M a, M b) { return _mm256_or_pd(a, b); }
inline M mnot(M a) { return _mm256_xor_pd(a, _mm256_castsi256_pd(_mm256_set1_epi64x(-1))); }
// m ? a : b
inline V sel(M m, V a, V b) { return _mm256_blendv_pd(b, a, m); }
// std::max(a, b) == (a < b) ? b : a, signed zeros included.
inline V max_std(V a, V b) { return sel(lt(a, b), b, a); }
inline V copysign(V a, V s) { return _mm256_or_pd(abs(a), _mm256_and_pd(s, set(-0.0))); }

struct SinCos4 {
  V s, c;
};

inline SinCos4 sincos_poly(V x) {
  const V shifted = add(mul(x, set(0.63661977236758134308)), set(6755399441055744.0));
  const V kd = sub(shifted, set(6755399441055744.0));
  const __m256i quadrant = _mm256_and_si256(_mm256_castpd_si256(shifted), _mm256_set1_epi64x(3));
  const V r = sub(sub(sub(x, mul(kd, set(1.57079632673412561417e+00))), mul(kd, set(6.07710050630396597660e-11))),
                  mul(kd, set(2.02226624871116645580e-21)));
  const V z = mul(r, r);
  V ps = add(set(-2.50507602534068634195e-08), mul(z, set(1.58969099521155010221e-10)));
  ps = add(set(2.75573137070700676789e-06), mul(z, ps));
  ps = add(set(-1.98412698298579493134e-04), mul(z, ps));
  ps = add(set(8.33333333332248946124e-03), mul(z, ps));
  ps = add(set(-1.66666666666666324348e-01), mul(z, ps));
  const V sin_r = add(r, mul(mul(r, z), ps));
  const V hz = mul(set(0.5), z);
  const V w = sub(set(1.0), hz);
  V pc = add(set(2.08757232129817482790e-09), mul(z, set(-1.13596475577881948265e-11)));
  pc = add(set(-2.75573143513906633035e-07), mul(z, pc));
  pc = add(set(2.48015872894767294178e-05), mul(z, pc));
  pc = add(set(-1.38888888888741095749e-03), mul(z, pc));
  pc = add(set(4.16666666666666019037e-02), mul(z, pc));
  const V cos_r = add(w, add(sub(sub(set(1.0), w), hz), mul(mul(z, z), pc)));
  const __m256i one = _mm256_set1_epi64x(1), two = _mm256_set1_epi64x(2);
  const M odd = _mm256_castsi256_pd(_mm256_cmpeq_epi64(_mm256_and_si256(quadrant, one), one));
  const M neg_s = _mm256_castsi256_pd(_mm256_cmpeq_epi64(_mm256_and_si256(quadrant, two), two));
  const M neg_c =
      _mm256_castsi256_pd(_mm256_cmpeq_epi64(_mm256_and_si256(_mm256_add_epi64(quadrant, one), two), two));
  const V s = sel(odd, cos_r, sin_r);
  const V c = sel(odd, sin_r, cos_r);
  return {sel(neg_s, neg(s), s), sel(neg_c, neg(c), c)};
}

inline V atan2_poly(V y, V x) {
  const V ax = abs(x), ay = abs(y);
  const M swap = gt(ay, ax);
  const V num = sel(swap, ax, ay), den = sel(swap, ay, ax);
  V t = div(num, max_std(den, set(1e-300)));
  const M upper = gt(t, set(0.66));
  t = sel(upper, div(sub(t, set(1.0)), add(t, set(1.0))), t);
  const V z = mul(t, t);
  V p = sub(mul(set(-8.750608600031904122785e-1), z), set(1.615753718733365076637e1));
  p = sub(mul(p, z), set(7.500855792314704667340e1));
  p = sub(mul(p, z), set(1.228866684490136173410e2));
  p = sub(mul(p, z), set(6.485021904942025371773e1));
  V q = add(z, set(2.485846490142306297962e1));
  q = add(mul(q, z), set(1.650270098316988542046e2));
  q = add(mul(q, z), set(4.328810604912902668951e2));
  q = add(mul(q, z), set(4.853903996359136964868e2));
  q = add(mul(q, z), set(1.945506571482613964425e2));
  V a = add(t, mul(t, div(mul(z, p), q)));
  a = sel(upper, add(a, set(0.25 * kPiD + 0.5 * 6.123233995736765886130e-17)), a);
  a = sel(swap, sub(set(0.5 * kPiD), a), a);
  a = sel(lt(x, set(0.0)), sub(set(kPiD), a), a);
  return copysign(a, y);
}

inline V wrap_small(V x, V snap) {
  x = sel(lt(x, set(0.0)), add(x, set(kTwoPiD)), x);
  x = sel(lt(x, set(0.0)), add(x, set(kTwoPiD)), x);
  x = sel(ge(x, set(kTwoPiD)), sub(x, set(kTwoPiD)), x);
  return sel(ge(x, sub(set(kTwoPiD), snap)), set(0.0), x);
}

inline M in_wedge(V wx, V wy, V p, V phi, V c, V s, V snap) {
  const V tol = mul(snap, p);
  const V ntol = neg(tol);
  const M narrow = mand(mand(ge(wy, ntol), ge(sub(mul(wx, s), mul(wy, c)), ntol)),
                        ge(add(mul(wx, add(set(1.0), c)), mul(wy, s)), set(0.0)));
  const M outside_wide = mand(gt(sub(mul(c, wy), mul(s, wx)), tol), gt(neg(wy), tol));
  return sel(le(phi, set(kPiD)), narrow, mnot(outside_wide));
}

// kernel.hpp mod2pi_snap: x - 2 pi floor(x / 2 pi), within snap of 2 pi (or negative) -> 0.
inline V mod2pi_snap(V x, V snap) {
  const V r = sub(x, mul(set(kTwoPiD), _mm256_floor_pd(div(x, set(kTwoPiD)))));
  return sel(mor(ge(r, sub(set(kTwoPiD), snap)), lt(r, set(0.0))), set(0.0), r);
}

// kernel.hpp word_lrl / word_rlr totals; `mirror` selects RLR. w is the vector between the
// outer circles, d = |w|.
inline V ccc_total(V wx, V wy, V d, V phi, V snap, bool mirror, M& ok) {
  const V quarter = mul(set(0.25), d);
  ok = mnot(gt(quarter, set(1.0 + 1e-12)));
  const V x = sel(lt(set(1.0), quarter), set(1.0), quarter);  // std::min(quarter, 1.0)
  const V kappa = atan2_poly(_mm256_sqrt_pd(mul(sub(set(1.0), x), add(set(1.0), x))), x);
  const V theta = atan2_poly(wy, wx);
  const V half_pi = set(0.5 * kPiD);
  const V t = mirror ? mod2pi_snap(add(add(neg(theta), kappa), half_pi), snap)
                     : mod2pi_snap(add(add(theta, kappa), half_pi), snap);
  const V p = add(set(kPiD), mul(set(2.0), kappa));
  const V q = mirror ? mod2pi_snap(add(add(add(neg(phi), theta), kappa), half_pi), snap)
                     : mod2pi_snap(add(add(sub(phi, theta), kappa), half_pi), snap);
  return add(add(t, p), q);
}

inline V load3(const double* rows, int component) {
  return _mm256_set_pd(rows[9 + component], rows[6 + component], rows[3 + component], rows[component]);
}

}  // namespace

void csc_block_avx2(const double* q0s, const double* q1s, std::size_t count, double rho, double snap_constant,
                    double* best_out, double* code_out, unsigned char* ccc_out) {
  const double inv_scalar = 1.0 / rho;
  const V inv = set(inv_scalar);
  const V inf = set(__builtin_inf());
  constexpr double kCccLimit = 16.0 * (1.0 + 1e-12) * (1.0 + 1e-12);
  std::size_t i = 0;
  for (; i + 4 <= count; i += 4) {
    const double* a = q0s + 3 * i;
    const double* b = q1s + 3 * i;
    const V x0 = load3(a, 0), y0 = load3(a, 1), p0 = load3(a, 2);
    const V x1 = load3(b, 0), y1 = load3(b, 1), p1 = load3(b, 2);
    // make_frame_poly
    const V dx = mul(sub(x1, x0), inv), dy = mul(sub(y1, y0), inv);
    const SinCos4 h0 = sincos_poly(p0);
    const V u = add(mul(h0.c, dx), mul(h0.s, dy));
    const V v = add(mul(neg(h0.s), dx), mul(h0.c, dy));
    const V magnitude = max_std(max_std(abs(x0), abs(y0)), max_std(abs(x1), abs(y1)));
    const V snap = mul(set(snap_constant), add(set(1.0), mul(magnitude, inv)));
    const V difference = sub(p1, p0);
    const V k = sub(add(mul(difference, set(0.15915494309189533577)), set(6755399441055744.0)), set(6755399441055744.0));
    V r = sub(sub(sub(difference, mul(k, set(6.28318530693650245667e+00))), mul(k, set(2.43084020252158639064e-10))),
              mul(k, set(8.08906499484466582320e-21)));
    r = sel(lt(r, set(0.0)), add(r, set(6.28318530717958647692)), r);
    const V phi = sel(mor(ge(r, sub(set(kTwoPiD), snap)), lt(r, snap)), set(0.0), r);
    const SinCos4 hp = sincos_poly(phi);
    const V c = hp.c, s = hp.s;
    // shortest_csc: LSL
    const V lx = sub(u, s), ly = sub(add(v, c), set(1.0));
    const V l2 = add(mul(lx, lx), mul(ly, ly)), lp = _mm256_sqrt_pd(l2);
    const M l_single = mor(le(lp, snap), in_wedge(lx, ly, lp, phi, c, s, snap));
    const V lsl = add(add(lp, phi), sel(l_single, set(0.0), set(kTwoPiD)));
    // RSR
    const V rx = add(u, s), ry = add(sub(v, c), set(1.0));
    const V r2 = add(mul(rx, rx), mul(ry, ry)), rp = _mm256_sqrt_pd(r2);
    const V phi_m = wrap_small(neg(phi), snap);
    const M r_single = mor(le(rp, snap), in_wedge(rx, neg(ry), rp, phi_m, c, neg(s), snap));
    const V rsr = add(add(rp, phi_m), sel(r_single, set(0.0), set(kTwoPiD)));
    // LSR
    const V ax = add(u, s), ay = sub(sub(v, c), set(1.0));
    const V a_tmp = sub(add(mul(ax, ax), mul(ay, ay)), set(4.0));
    const V ap = _mm256_sqrt_pd(max_std(a_tmp, set(0.0)));
    const V a_theta = atan2_poly(add(mul(ay, ap), mul(set(2.0), ax)), sub(mul(ax, ap), mul(set(2.0), ay)));
    const V lsr = sel(lt(a_tmp, mul(set(-4.0), snap)), inf,
                      add(add(ap, wrap_small(a_theta, snap)), wrap_small(sub(a_theta, phi), snap)));
    // RSL
    const V bx = sub(u, s), by = add(add(v, c), set(1.0));
    const V b_tmp = sub(add(mul(bx, bx), mul(by, by)), set(4.0));
    const V bp = _mm256_sqrt_pd(max_std(b_tmp, set(0.0)));
    const V b_theta = atan2_poly(sub(mul(by, bp), mul(set(2.0), bx)), add(mul(bx, bp), mul(set(2.0), by)));
    const V rsl = sel(lt(b_tmp, mul(set(-4.0), snap)), inf,
                      add(add(bp, wrap_small(neg(b_theta), snap)), wrap_small(sub(phi, b_theta), snap)));
    V best = lsl, code = set(0.0);
    M better = lt(lsr, best);
    code = sel(better, set(1.0), code);
    best = sel(better, lsr, best);
    better = lt(rsl, best);
    code = sel(better, set(2.0), code);
    best = sel(better, rsl, best);
    better = lt(rsr, best);
    code = sel(better, set(3.0), code);
    best = sel(better, rsr, best);
    // kernel.hpp finish_with_ccc, only where shortest_csc flags it: RLR then LRL.
    const M need = mor(le(r2, set(kCccLimit)), le(l2, set(kCccLimit)));
    if (_mm256_movemask_pd(need) != 0) {
      M ok;
      const V rlr = ccc_total(rx, ry, rp, phi, snap, true, ok);
      better = mand(mand(need, ok), lt(rlr, best));
      code = sel(better, set(4.0), code);
      best = sel(better, rlr, best);
      const V lrl = ccc_total(lx, ly, lp, phi, snap, false, ok);
      better = mand(mand(need, ok), lt(lrl, best));
      code = sel(better, set(5.0), code);
      best = sel(better, lrl, best);
    }
    _mm256_storeu_pd(best_out + i, best);
    _mm256_storeu_pd(code_out + i, code);
    for (std::size_t lane = 0; lane < 4; ++lane) ccc_out[i + lane] = 0;  // CCC done here
  }
  // The caller handles the remainder (count % 4) with the scalar kernel.
  (void)i;
}

#else

void csc_block_avx2(const double*, const double*, std::size_t, double, double, double*, double*, unsigned char*) {}

#endif

}  // namespace vistrack::detail
