// The sinusoid of section II: speed ratio and amplitude (eqs. 9-10), along-track rate (eq. 5),
// arc length and its inverse. Elliptic integrals from Boost.Math: libstdc++ 12's
// std::comp_ellint_2 is 4x slower and loses accuracy towards k = 1 (4.3e-13 relative at
// k = 0.99 against a 50-digit AGM; Boost is within 2e-16 there), where large speed ratios live.
#include <algorithm>
#include <cmath>
#include <limits>

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_2.hpp>

#include "vistrack/error.hpp"
#include "vistrack/follow.hpp"
#include "vistrack/limits.hpp"

namespace vistrack {

namespace {

// Boost.Math's default policy evaluates doubles in long double: 5x slower for the incomplete
// integral, and no more accurate here (within 2e-16 of a 50-digit AGM on the complete one).
using InDouble = boost::math::policies::policy<boost::math::policies::promote_double<false>>;

// 1 + a^2 cos^2 u = (1 + a^2)(1 - k^2 sin^2 u) with k = a / sqrt(1 + a^2): the negative parameter
// -a^2 of eq. (10) becomes the modulus k in [0, 1) (derived from cos^2 = 1 - sin^2).
struct Modulus {
  double scale;  // sqrt(1 + a^2)
  double k;      // a / sqrt(1 + a^2)
};

Modulus modulus(double a) {
  const double scale = std::hypot(1.0, a);
  return {scale, a / scale};
}

// sigma(a) = (1/2pi) int_0^2pi sqrt(1 + a^2 cos^2 u) du = (2/pi) sqrt(1 + a^2) E(k).
double ratio_of_slope(double a) {
  if (a == 0.0) return 1.0;
  const Modulus m = modulus(a);
  if (m.k >= 1.0) return 2.0 / kPi * a;  // a beyond 1e8: E(1) = 1 and sqrt(1 + a^2) = a in doubles
  return 2.0 / kPi * m.scale * boost::math::ellint_2(m.k, InDouble());
}

// sigma(a) and d sigma / da = (2/pi) (1/a) [sqrt(1 + a^2) E(k) - K(k) / sqrt(1 + a^2)], from
// a cos^2 / sqrt(1 + a^2 cos^2) = ((1 + a^2 cos^2) - 1) / (a sqrt(1 + a^2 cos^2)); E once.
struct RatioAndSlope {
  double ratio;
  double derivative;
};

RatioAndSlope ratio_and_derivative(double a) {
  if (a < 1e-4) {  // series: sigma = 1 + a^2/4 - 3a^4/64 + O(a^6)
    const double a2 = a * a;
    return {1.0 + a2 / 4.0 - 3.0 * a2 * a2 / 64.0, 0.5 * a * (1.0 - 0.375 * a2)};
  }
  const Modulus m = modulus(a);
  if (m.k >= 1.0) return {2.0 / kPi * a, 2.0 / kPi};
  const double e = boost::math::ellint_2(m.k, InDouble());
  return {2.0 / kPi * m.scale * e, 2.0 / kPi / a * (m.scale * e - boost::math::ellint_1(m.k, InDouble()) / m.scale)};
}

// int_0^phi sqrt(1 + a^2 cos^2 u) du for any real phi: E(phi, k) reduced to [-pi/2, pi/2] by
// E(n pi + r, k) = 2 n E(k) + E(r, k).
double integral_to_phase(double phi, double a) {
  if (a == 0.0) return phi;
  const Modulus m = modulus(a);
  const double n = std::round(phi / kPi);
  const double r = phi - n * kPi;
  if (m.k >= 1.0) return a * (2.0 * n + std::sin(r));  // the a -> infinity limit, int |cos|
  return m.scale * (2.0 * n * boost::math::ellint_2(m.k, InDouble()) + boost::math::ellint_2(m.k, r, InDouble()));
}

double slope_of(double amplitude, double period_distance) {
  require_non_negative(amplitude, "amplitude");
  require_positive(period_distance, "period_distance");
  return kTwoPi * amplitude / period_distance;
}

}  // namespace

double sinusoid_speed_ratio(double amplitude, double period_distance) {
  return ratio_of_slope(slope_of(amplitude, period_distance));
}

double sinusoid_slope(double speed_ratio) {
  if (!std::isfinite(speed_ratio) || !(speed_ratio >= 1.0))
    detail::fail_field("speed_ratio", speed_ratio,
                       "must be a finite number >= 1 (below 1 the vehicle outruns the UAV: no sinusoid is slow enough)");
  // v_p / v_g of two speeds in the speed range [1e-6, 1e4] m/s; far beyond, Boost's elliptic
  // integrals overflow (a Boost ValueError naming no field).
  constexpr double kMaxRatio = limits::kMaxSpeed / limits::kMinSpeed;
  if (speed_ratio > kMaxRatio)
    detail::fail_field("speed_ratio", speed_ratio,
                       "must be at most " + detail::to_text(kMaxRatio) + " (the ratio of the largest to the smallest "
                       "speed)");
  if (speed_ratio == 1.0) return 0.0;
  const double sigma = speed_ratio;
  // Bracket: Jensen gives sigma <= sqrt(1 + a^2/2); sqrt(1 + x^2) >= max(x, (1 + x)/sqrt 2) gives
  // sigma >= max(2a/pi, (1 + 2a/pi)/sqrt 2).
  double lo = std::sqrt(2.0 * (sigma - 1.0) * (sigma + 1.0));
  double hi = std::max(lo, 0.5 * kPi * std::min(sigma, std::sqrt(2.0) * sigma - 1.0));
  // Start from the asymptotes: a = 2 sqrt(sigma - 1)(1 + 3 (sigma - 1)/8) from the series, and
  // sigma = (2/pi)(a + (ln 4a - 1/2)/(2a)) for large a (E(k) near k = 1). sigma(a) is increasing
  // and convex, so Newton converges (about four evaluations); the bracket guards it.
  double a;
  if (sigma < 2.0) {
    a = 2.0 * std::sqrt(sigma - 1.0) * (1.0 + 0.375 * (sigma - 1.0));
  } else {
    const double a0 = 0.5 * kPi * sigma;
    a = a0 - (std::log(4.0 * a0) - 0.5) / (2.0 * a0);
  }
  a = std::clamp(a, lo, hi);
  for (int iteration = 0; iteration < 60; ++iteration) {
    const RatioAndSlope v = ratio_and_derivative(a);
    const double f = v.ratio - sigma;
    if (f == 0.0) break;
    if (f > 0.0) hi = a; else lo = a;
    double next = a - f / v.derivative;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    const double step = std::abs(next - a);
    a = next;
    // Converged, or down to the rounding of sigma(a) itself.
    if (step <= 2e-16 * a || (std::abs(f) <= 2.0 * std::numeric_limits<double>::epsilon() * sigma && step <= 1e-14 * a))
      break;
  }
  return a;
}

double sinusoid_amplitude(double speed_ratio, double period_distance) {
  require_positive(period_distance, "period_distance");
  return sinusoid_slope(speed_ratio) * period_distance / kTwoPi;
}

SinusoidShape sinusoid_shape(double speed_ratio, double uav_speed, double period, double turn_radius) {
  require_positive(uav_speed, "uav_speed");
  require_positive(period, "period");
  require_positive(turn_radius, "turn_radius");
  SinusoidShape shape;
  shape.slope = sinusoid_slope(speed_ratio);
  // Peak curvature of y = A sin(2 pi x / D) is a 2 pi / D: keep it within 1 / rho.
  const double by_period = uav_speed * period / speed_ratio;  // v_g T, v_g = v_p / sigma
  const double floor = kTwoPi * shape.slope * turn_radius;
  shape.curvature_limited = floor > by_period;
  shape.period_distance = std::max(by_period, floor);
  shape.amplitude = shape.slope * shape.period_distance / kTwoPi;
  return shape;
}

double sinusoid_along_track_rate(double x, double amplitude, double period_distance, double uav_speed) {
  require_finite(x, "x");
  require_positive(uav_speed, "uav_speed");
  const double a = slope_of(amplitude, period_distance);
  const double c = std::cos(kTwoPi * x / period_distance);
  return uav_speed / std::sqrt(1.0 + a * a * c * c);
}

double sinusoid_arc_length(double x, double amplitude, double period_distance) {
  require_finite(x, "x");
  const double a = slope_of(amplitude, period_distance);
  return period_distance / kTwoPi * integral_to_phase(kTwoPi * x / period_distance, a);
}

double sinusoid_phase_at_arc(double arc, double amplitude, double period_distance) {
  require_finite(arc, "arc");
  const double a = slope_of(amplitude, period_distance);
  const double unit = period_distance / kTwoPi;
  const double target = arc / unit;  // int_0^phi sqrt(1 + a^2 cos^2) du to reach
  if (a == 0.0) return target;
  // Whole half periods first (each integrates to 2 sqrt(1 + a^2) E(k)), then Newton on [0, pi].
  const double half = integral_to_phase(kPi, a);
  const double n = std::floor(target / half);
  const double rest = target - n * half;
  double lo = 0.0, hi = kPi;
  double phi = kPi * rest / half;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double f = integral_to_phase(phi, a) - rest;
    if (f == 0.0) break;
    if (f > 0.0) hi = phi; else lo = phi;
    const double c = std::cos(phi);
    double next = phi - f / std::sqrt(1.0 + a * a * c * c);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // safeguard
    const double step = std::abs(next - phi);
    phi = next;
    if (step <= 1e-14 || hi - lo <= 1e-14) break;  // quadratic convergence: the last step was below 1e-14
  }
  return n * kPi + phi;
}

}  // namespace vistrack
