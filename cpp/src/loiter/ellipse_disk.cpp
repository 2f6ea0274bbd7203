// Exact area of an ellipse intersected with a disk.
//
// The ellipse (a cos t, b sin t) is inside the disk where h(t) = |ellipse(t) - c|^2 - rho^2 < 0,
//   h(t) = K0 + K1 cos t + K2 sin t + K3 cos 2t,
// a trigonometric polynomial of degree 2 (at most four crossings). The crossings are isolated on
// 64 intervals with bounds on h' and h'' (an interval holds at most one crossing when
// |h(t0)| + |h(t1)| > max|h'| dt, or when h' keeps its sign, |h'(t0)| > max|h''| dt; none when
// |h(t0)| > |h'(t0)| dt + max|h''| dt^2 / 2; otherwise it is halved, at most 512 times per call),
// then refined by safeguarded Newton steps. Green's theorem over the boundary of the intersection,
// both curves counter-clockwise: the arcs of the ellipse inside the disk contribute ab dt / 2, the
// arcs of the circle inside the ellipse (rho^2 dphi + rho cx d(sin phi) - rho cy d(cos phi)) / 2.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "vistrack/error.hpp"
#include "vistrack/loiter.hpp"

namespace vistrack {

namespace {

constexpr int kIntervals = 64;
constexpr int kMaxDepth = 40;
constexpr int kMaxHalvings = 512;

struct Table {
  std::array<double, kIntervals + 1> t, cos1, sin1, cos2, sin2;
  Table() {
    for (int k = 0; k <= kIntervals; ++k) {
      const auto i = static_cast<std::size_t>(k);
      t[i] = kTwoPi * k / kIntervals;
      cos1[i] = std::cos(t[i]);
      sin1[i] = std::sin(t[i]);
      cos2[i] = std::cos(2.0 * t[i]);
      sin2[i] = std::sin(2.0 * t[i]);
    }
    // Exact at the ends of the period.
    cos1[kIntervals] = cos2[kIntervals] = 1.0;
    sin1[kIntervals] = sin2[kIntervals] = 0.0;
  }
};

const Table& table() {
  static const Table instance;
  return instance;
}

struct Trig {
  double k0, k1, k2, k3;
  double value(double c1, double s1, double c2) const { return k0 + k1 * c1 + k2 * s1 + k3 * c2; }
  double slope(double c1, double s1, double s2) const { return -k1 * s1 + k2 * c1 - 2.0 * k3 * s2; }
  double at(double t) const { return value(std::cos(t), std::sin(t), std::cos(2.0 * t)); }
  double slope_at(double t) const { return slope(std::cos(t), std::sin(t), std::sin(2.0 * t)); }
};

class Crossings {
 public:
  explicit Crossings(const Trig& h) : h_(h) {
    lipschitz1_ = std::abs(h.k1) + std::abs(h.k2) + 2.0 * std::abs(h.k3);
    lipschitz2_ = std::abs(h.k1) + std::abs(h.k2) + 4.0 * std::abs(h.k3);
  }

  std::vector<double> find() {
    const Table& tab = table();
    for (std::size_t k = 0; k < kIntervals; ++k) {
      const double h0 = h_.value(tab.cos1[k], tab.sin1[k], tab.cos2[k]);
      const double h1 = h_.value(tab.cos1[k + 1], tab.sin1[k + 1], tab.cos2[k + 1]);
      const double d0 = h_.slope(tab.cos1[k], tab.sin1[k], tab.sin2[k]);
      isolate(tab.t[k], tab.t[k + 1], h0, h1, d0, 0);
    }
    return roots_;
  }

 private:
  void isolate(double t0, double t1, double h0, double h1, double d0, int depth) {
    const double dt = t1 - t0;
    const bool change = (h0 < 0.0) != (h1 < 0.0);
    // Taylor from t0: h keeps its sign when |h(t0)| > |h'(t0)| dt + max|h''| dt^2 / 2.
    const bool none = !change && std::abs(h0) > std::abs(d0) * dt + 0.5 * lipschitz2_ * dt * dt;
    const bool at_most_one = none || std::abs(h0) + std::abs(h1) > lipschitz1_ * dt || std::abs(d0) > lipschitz2_ * dt;
    // Near a tangency of nearly equal curvatures h and h' stay tiny over a long arc: past a budget
    // of halvings such intervals count by their end signs only (the sliver left out is that thin).
    if (at_most_one || depth >= kMaxDepth || ++halvings_ > kMaxHalvings) {
      if (change) roots_.push_back(refine(t0, t1, h0, h1));
      return;
    }
    const double tm = 0.5 * (t0 + t1);
    const double hm = h_.at(tm);
    isolate(t0, tm, h0, hm, d0, depth + 1);
    isolate(tm, t1, hm, h1, h_.slope_at(tm), depth + 1);
  }

  // Safeguarded Newton on the bracket [t0, t1] (one sign change): Newton steps that stay inside
  // the shrinking bracket, bisection otherwise.
  double refine(double t0, double t1, double h0, double h1) const {
    if (h0 == 0.0) return t0;
    if (h1 == 0.0) return t1;
    double lo = t0, hi = t1;
    const bool rising = h0 < 0.0;
    double t = t0 + (t1 - t0) * h0 / (h0 - h1);  // regula falsi start
    for (int iteration = 0; iteration < 60; ++iteration) {
      const double c = std::cos(t), s = std::sin(t);
      const double value = h_.value(c, s, c * c - s * s);
      if (value == 0.0) return t;
      if ((value < 0.0) == rising) lo = t;
      else hi = t;
      const double slope = h_.slope(c, s, 2.0 * s * c);
      double next = slope != 0.0 ? t - value / slope : 0.5 * (lo + hi);
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      if (std::abs(next - t) <= 1e-15 * (1.0 + std::abs(t)) || hi - lo <= 1e-15) return next;
      t = next;
    }
    return t;
  }

  Trig h_;
  double lipschitz1_ = 0.0, lipschitz2_ = 0.0;
  std::vector<double> roots_;
  int halvings_ = 0;
};

}  // namespace

double ellipse_disk_intersection_area(double a, double b, double cx, double cy, double rho) {
  if (!(a > 0.0) || !(b > 0.0) || !(rho > 0.0) || !std::isfinite(a) || !std::isfinite(b) || !std::isfinite(rho) ||
      !std::isfinite(cx) || !std::isfinite(cy))
    throw Error("ellipse_disk_intersection_area: semi-axes and radius must be finite and > 0, centre finite (a = " +
                detail::to_text(a) + ", b = " + detail::to_text(b) + ", rho = " + detail::to_text(rho) + ")");
  // Bounding boxes apart: nothing in common.
  if (std::abs(cx) >= a + rho || std::abs(cy) >= b + rho) return 0.0;
  const Trig h{0.5 * (a * a + b * b) + cx * cx + cy * cy - rho * rho, -2.0 * a * cx, -2.0 * b * cy,
               0.5 * (a * a - b * b)};
  std::vector<double> roots = Crossings(h).find();
  // A tangency can leave an odd count; drop the crossing where h is flattest.
  while (roots.size() % 2 == 1) {
    std::size_t flattest = 0;
    for (std::size_t k = 1; k < roots.size(); ++k)
      if (std::abs(h.slope_at(roots[k])) < std::abs(h.slope_at(roots[flattest]))) flattest = k;
    roots.erase(roots.begin() + static_cast<std::ptrdiff_t>(flattest));
  }
  const double ellipse_area = kPi * a * b, disk_area = kPi * rho * rho;
  const auto inside_ellipse = [&](double x, double y) { return (x / a) * (x / a) + (y / b) * (y / b) < 1.0; };
  if (roots.empty()) {
    if (h.at(0.0) < 0.0) return ellipse_area;        // the ellipse lies in the disk
    if (inside_ellipse(cx, cy)) return disk_area;    // the disk lies in the ellipse
    return 0.0;
  }
  double twice_area = 0.0;
  const std::size_t n = roots.size();
  std::vector<double> phis(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double t0 = roots[k];
    const double t1 = k + 1 < n ? roots[k + 1] : roots[0] + kTwoPi;
    if (h.at(0.5 * (t0 + t1)) < 0.0) twice_area += a * b * (t1 - t0);
    phis[k] = std::atan2(b * std::sin(t0) - cy, a * std::cos(t0) - cx);
  }
  std::sort(phis.begin(), phis.end());
  for (std::size_t k = 0; k < n; ++k) {
    const double p0 = phis[k];
    const double p1 = k + 1 < n ? phis[k + 1] : phis[0] + kTwoPi;
    const double pm = 0.5 * (p0 + p1);
    if (inside_ellipse(cx + rho * std::cos(pm), cy + rho * std::sin(pm)))
      twice_area += rho * rho * (p1 - p0) + rho * cx * (std::sin(p1) - std::sin(p0)) -
                    rho * cy * (std::cos(p1) - std::cos(p0));
  }
  return std::clamp(0.5 * twice_area, 0.0, std::min(ellipse_area, disk_area));
}

}  // namespace vistrack
