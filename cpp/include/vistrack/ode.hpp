// Dormand-Prince 5(4) [Dormand & Prince 1980, the paper's ref. 30]: adaptive steps with the
// embedded 4th-order error estimate and local extrapolation, the 4th-order continuous extension
// (dense output), events located on the dense output by Brent's method, and a fixed-step mode.
//
// The step-size control, error norm and starting step follow Hairer, Norsett & Wanner (and
// scipy.integrate.RK45, which uses the same rules), so a trajectory can be checked step for step
// against scipy. Header-only on purpose: the right-hand side is a template parameter so that it
// is inlined into the stepper (the closed loop spends its time there).
//
//   auto result = vistrack::solve_ode<2>([](double t, const Vec& y, Vec& dy) {...},
//                                        t0, t1, y0, options, t_eval, events);
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"

namespace vistrack {

struct OdeOptions {
  double rtol = 1e-6;
  double atol = 1e-8;
  double max_step = std::numeric_limits<double>::infinity();
  double first_step = 0.0;   // 0: chosen automatically (Hairer-Wanner starting step)
  double fixed_step = 0.0;   // > 0: steps of exactly this size (last one shortened), no error control
  std::size_t max_steps = 10'000'000;
  // The tolerances' ranges are limits.hpp's.
  void validate() const {
    require_tolerances(rtol, atol, "ode.");
    if (!(max_step > 0.0)) detail::fail_field("ode.max_step", max_step, "must be greater than 0");
    require_non_negative(first_step, "ode.first_step");
    require_non_negative(fixed_step, "ode.fixed_step");
    if (max_steps == 0) detail::fail_field("ode.max_steps", max_steps, "must be at least 1");
  }
};

struct OdeStatistics {
  std::size_t rhs_evaluations = 0;
  std::size_t accepted_steps = 0;
  std::size_t rejected_steps = 0;
  OdeStatistics& operator+=(const OdeStatistics& other) {
    rhs_evaluations += other.rhs_evaluations;
    accepted_steps += other.accepted_steps;
    rejected_steps += other.rejected_steps;
    return *this;
  }
};

template <int N>
using OdeVector = Eigen::Matrix<double, N, 1>;

// A zero crossing of event function value(t, y) to locate during the integration.
template <int N>
struct OdeEvent {
  std::function<double(double, const OdeVector<N>&)> value;
  int direction = 0;  // +1: only rising crossings (- to +), -1: only falling, 0: both
  int terminal = 0;   // k > 0: stop the integration at the k-th crossing
};

template <int N>
struct OdeEventHit {
  std::size_t event = 0;  // index into the events given
  double t = 0.0;
  OdeVector<N> y;
};

template <int N>
struct OdeResult {
  std::vector<double> t;           // the t_eval inside the integrated span, or every step
  std::vector<OdeVector<N>> y;
  std::vector<OdeEventHit<N>> events;  // in time order
  bool terminated = false;         // stopped by a terminal event
  OdeStatistics statistics;
};

namespace detail {

// Butcher tableau of DP5 (the FSAL 7-stage pair), error weights E = b5 - b4 and the dense output
// polynomial P (Hairer's continuous extension, in scipy's layout: y(t_old + x h) =
// y_old + h * sum_j Q[:, j] x^(j+1), Q = K^T P).
struct DormandPrinceTableau {
  static constexpr double c[7] = {0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0};
  static constexpr double a[7][6] = {
      {0, 0, 0, 0, 0, 0},
      {1.0 / 5.0, 0, 0, 0, 0, 0},
      {3.0 / 40.0, 9.0 / 40.0, 0, 0, 0, 0},
      {44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0, 0, 0},
      {19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0, 0, 0},
      {9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0, -5103.0 / 18656.0, 0},
      {35.0 / 384.0, 0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0}};
  static constexpr double b[6] = {35.0 / 384.0, 0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0,
                                  11.0 / 84.0};
  static constexpr double e[7] = {-71.0 / 57600.0, 0, 71.0 / 16695.0, -71.0 / 1920.0,
                                  17253.0 / 339200.0, -22.0 / 525.0, 1.0 / 40.0};
  static constexpr double p[7][4] = {
      {1.0, -8048581381.0 / 2820520608.0, 8663915743.0 / 2820520608.0, -12715105075.0 / 11282082432.0},
      {0, 0, 0, 0},
      {0, 131558114200.0 / 32700410799.0, -68118460800.0 / 10900136933.0, 87487479700.0 / 32700410799.0},
      {0, -1754552775.0 / 470086768.0, 14199869525.0 / 1410260304.0, -10690763975.0 / 1880347072.0},
      {0, 127303824393.0 / 49829197408.0, -318862633887.0 / 49829197408.0, 701980252875.0 / 199316789632.0},
      {0, -282668133.0 / 205662961.0, 2019193451.0 / 616988883.0, -1453857185.0 / 822651844.0},
      {0, 40617522.0 / 29380423.0, -110615467.0 / 29380423.0, 69997945.0 / 29380423.0}};
};

// RMS norm, the norm of Hairer-Wanner's error control.
template <class V>
double rms_norm(const V& x) {
  return x.size() == 0 ? 0.0 : x.norm() / std::sqrt(static_cast<double>(x.size()));
}

// Brent's method for a root of f on [a, b] with f(a) f(b) <= 0.
template <class F>
double brent_root(F&& f, double a, double b, double fa, double fb, double xtol) {
  if (fa == 0.0) return a;
  if (fb == 0.0) return b;
  double c = a, fc = fa, d = b - a, e = d;
  for (int iteration = 0; iteration < 200; ++iteration) {
    if ((fb > 0.0) == (fc > 0.0)) {
      c = a;
      fc = fa;
      d = e = b - a;
    }
    if (std::abs(fc) < std::abs(fb)) {
      a = b; b = c; c = a;
      fa = fb; fb = fc; fc = fa;
    }
    const double tol = 2.0 * std::numeric_limits<double>::epsilon() * std::abs(b) + 0.5 * xtol;
    const double m = 0.5 * (c - b);
    if (std::abs(m) <= tol || fb == 0.0) return b;
    if (std::abs(e) >= tol && std::abs(fa) > std::abs(fb)) {
      double p, q;
      const double s = fb / fa;
      if (a == c) {  // secant
        p = 2.0 * m * s;
        q = 1.0 - s;
      } else {  // inverse quadratic interpolation
        const double qa = fa / fc, r = fb / fc;
        p = s * (2.0 * m * qa * (qa - r) - (b - a) * (r - 1.0));
        q = (qa - 1.0) * (r - 1.0) * (s - 1.0);
      }
      if (p > 0.0) q = -q; else p = -p;
      if (2.0 * p < std::min(3.0 * m * q - std::abs(tol * q), std::abs(e * q))) {
        e = d;
        d = p / q;
      } else {
        d = m;
        e = m;
      }
    } else {
      d = m;
      e = m;
    }
    a = b;
    fa = fb;
    b += std::abs(d) > tol ? d : (m > 0.0 ? tol : -tol);
    fb = f(b);
  }
  return b;
}

}  // namespace detail

// One accepted step and its continuous extension (4th order, exact at both ends).
template <int N>
struct DenseStep {
  double t_old = 0.0;
  double t_new = 0.0;
  OdeVector<N> y_old;
  OdeVector<N> y_new;
  Eigen::Matrix<double, N, 4> q;  // K^T P

  OdeVector<N> operator()(double t) const {
    if (t == t_new) return y_new;
    const double h = t_new - t_old;
    const double x = (t - t_old) / h;
    return y_old + h * x * (q.col(0) + x * (q.col(1) + x * (q.col(2) + x * q.col(3))));
  }
};

// The Dormand-Prince 5(4) stepper. Rhs: callable (double t, const OdeVector<N>& y,
// OdeVector<N>& dydt). Integrates forward from t0 to t_bound (> t0).
template <int N, class Rhs>
class DormandPrince {
 public:
  using Vector = OdeVector<N>;
  using Tableau = detail::DormandPrinceTableau;

  DormandPrince(Rhs rhs, double t0, const Vector& y0, double t_bound, const OdeOptions& options)
      : rhs_(std::move(rhs)), options_(options), t_(t0), t_bound_(t_bound), y_(y0) {
    options_.validate();
    require_finite(t0, "t0");
    require_finite(t_bound, "t_bound");
    if (!(t_bound > t0)) detail::fail_field("t_bound", t_bound, "must be greater than t0 = " + detail::to_text(t0));
    // Known before the first step: a fixed step that cannot reach t_bound within max_steps.
    if (options_.fixed_step > 0.0 && (t_bound - t0) / options_.fixed_step > static_cast<double>(options_.max_steps))
      detail::fail_field("ode.fixed_step", options_.fixed_step,
                         "needs more than ode.max_steps = " + std::to_string(options_.max_steps) + " steps to reach " +
                             detail::to_text(t_bound));
    for (Eigen::Index i = 0; i < y0.size(); ++i)
      require_finite(y0[i], "y0[" + std::to_string(i) + "]");
    const Eigen::Index n = y0.size();
    for (auto& k : k_) k.resize(n);
    f_.resize(n);
    evaluate(t_, y_, f_);
    if (options_.fixed_step > 0.0) {
      h_abs_ = options_.fixed_step;
    } else if (options_.first_step > 0.0) {
      h_abs_ = std::min(options_.first_step, options_.max_step);
    } else {
      h_abs_ = initial_step();
    }
  }

  double t() const { return t_; }
  const Vector& y() const { return y_; }
  bool finished() const { return t_ >= t_bound_; }
  const DenseStep<N>& last_step() const { return dense_; }
  const OdeStatistics& statistics() const { return stats_; }

  // One accepted step (rejected trials included). Returns false once t_bound is reached.
  bool step() {
    if (finished()) return false;
    if (stats_.accepted_steps >= options_.max_steps)
      detail::fail_field("ode.max_steps", options_.max_steps,
                         "step limit reached at t = " + detail::to_text(t_) + " before " +
                             detail::to_text(t_bound_));
    const double min_step =
        10.0 * std::abs(std::nextafter(t_, std::numeric_limits<double>::infinity()) - t_);
    if (options_.fixed_step > 0.0) {
      double t_new = t_ + options_.fixed_step;
      // Do not leave a sliver of a step to the end because of rounding.
      if (t_new > t_bound_ || t_bound_ - t_new < 1e-9 * options_.fixed_step) t_new = t_bound_;
      trial(t_new - t_);
      accept(t_new);
      return true;
    }
    double h_abs = std::clamp(h_abs_, min_step, options_.max_step);
    bool rejected = false;
    while (true) {
      if (h_abs < min_step)
        detail::fail_field("ode.step", h_abs, "step size became too small at t = " + detail::to_text(t_));
      double t_new = t_ + h_abs;
      if (t_new > t_bound_) t_new = t_bound_;
      const double h = t_new - t_;
      h_abs = std::abs(h);
      trial(h);
      const double error = error_norm(h);
      if (!std::isfinite(error)) {
        if (y_new_.allFinite() && k_[6].allFinite())
          detail::fail_field("ode.atol", options_.atol,
                             "the scaled error estimate overflows near t = " + detail::to_text(t_) +
                                 ": atol/rtol are too small for the state's scale");
        detail::fail_field("ode.rhs", error, "the right-hand side is not finite near t = " + detail::to_text(t_));
      }
      if (error < 1.0) {
        double factor = error == 0.0 ? kMaxFactor : std::min(kMaxFactor, kSafety * std::pow(error, -0.2));
        if (rejected) factor = std::min(1.0, factor);
        h_abs_ = h_abs * factor;
        accept(t_new);
        return true;
      }
      h_abs *= std::max(kMinFactor, kSafety * std::pow(error, -0.2));
      rejected = true;
      ++stats_.rejected_steps;
    }
  }

 private:
  static constexpr double kSafety = 0.9;
  static constexpr double kMinFactor = 0.2;
  static constexpr double kMaxFactor = 10.0;

  void evaluate(double t, const Vector& y, Vector& dydt) {
    rhs_(t, y, dydt);
    ++stats_.rhs_evaluations;
  }

  // Hairer-Wanner starting step (Solving ODEs I, II.4), as scipy's select_initial_step.
  double initial_step() {
    const double interval = t_bound_ - t_;
    const Vector scale = (options_.atol + options_.rtol * y_.array().abs()).matrix();
    const double d0 = detail::rms_norm((y_.array() / scale.array()).matrix());
    const double d1 = detail::rms_norm((f_.array() / scale.array()).matrix());
    double h0 = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;
    h0 = std::min(h0, interval);
    const Vector y1 = y_ + h0 * f_;
    Vector f1(y_.size());
    evaluate(t_ + h0, y1, f1);
    const double d2 = detail::rms_norm(((f1 - f_).array() / scale.array()).matrix()) / h0;
    const double h1 = (d1 <= 1e-15 && d2 <= 1e-15) ? std::max(1e-6, h0 * 1e-3)
                                                   : std::pow(0.01 / std::max(d1, d2), 1.0 / 5.0);
    return std::min({100.0 * h0, h1, interval, options_.max_step});
  }

  // Stages of one step of size h from (t_, y_): y_new_, f_new_ and k_[0..6].
  void trial(double h) {
    k_[0] = f_;
    for (int s = 1; s < 6; ++s) {
      stage_ = y_;
      for (int j = 0; j < s; ++j)
        if (Tableau::a[s][j] != 0.0) stage_ += (h * Tableau::a[s][j]) * k_[static_cast<std::size_t>(j)];
      evaluate(t_ + Tableau::c[s] * h, stage_, k_[static_cast<std::size_t>(s)]);
    }
    y_new_ = y_;
    for (int j = 0; j < 6; ++j)
      if (Tableau::b[j] != 0.0) y_new_ += (h * Tableau::b[j]) * k_[static_cast<std::size_t>(j)];
    evaluate(t_ + h, y_new_, k_[6]);
  }

  double error_norm(double h) {
    stage_.setZero();
    for (int j = 0; j < 7; ++j)
      if (Tableau::e[j] != 0.0) stage_ += (h * Tableau::e[j]) * k_[static_cast<std::size_t>(j)];
    const auto scale = options_.atol + options_.rtol * y_.array().abs().max(y_new_.array().abs());
    return detail::rms_norm((stage_.array() / scale).matrix());
  }

  void accept(double t_new) {
    dense_.t_old = t_;
    dense_.t_new = t_new;
    dense_.y_old = y_;
    dense_.y_new = y_new_;
    dense_.q.resize(y_.size(), 4);
    dense_.q.setZero();
    for (int j = 0; j < 7; ++j)
      for (int m = 0; m < 4; ++m)
        if (Tableau::p[j][m] != 0.0) dense_.q.col(m) += Tableau::p[j][m] * k_[static_cast<std::size_t>(j)];
    t_ = t_new;
    y_ = y_new_;
    f_ = k_[6];  // first same as last
    ++stats_.accepted_steps;
  }

  Rhs rhs_;
  OdeOptions options_;
  double t_;
  double t_bound_;
  double h_abs_ = 0.0;
  Vector y_, f_, y_new_, stage_;
  std::array<Vector, 7> k_;
  DenseStep<N> dense_;
  OdeStatistics stats_;
};

// Integrates dy/dt = rhs(t, y) from t0 to t1. Output at the sorted times t_eval (those inside
// [t0, t1]; interpolated on the dense output), or at every step when t_eval is empty. Events are
// located on the dense output of each step to about machine precision.
template <int N, class Rhs>
OdeResult<N> solve_ode(Rhs rhs, double t0, double t1, const OdeVector<N>& y0, const OdeOptions& options,
                       const std::vector<double>& t_eval = {}, const std::vector<OdeEvent<N>>& events = {}) {
  for (std::size_t i = 0; i < t_eval.size(); ++i) {
    require_finite(t_eval[i], "t_eval[" + std::to_string(i) + "]");
    if (i > 0 && !(t_eval[i] >= t_eval[i - 1]))
      detail::fail_field("t_eval[" + std::to_string(i) + "]", t_eval[i], "t_eval must be sorted");
  }
  for (std::size_t i = 0; i < events.size(); ++i) {
    if (!events[i].value) detail::fail_field("events[" + std::to_string(i) + "]", "empty", "needs a function");
    if (events[i].direction < -1 || events[i].direction > 1)
      detail::fail_field("events[" + std::to_string(i) + "].direction", events[i].direction, "must be -1, 0 or +1");
  }
  DormandPrince<N, Rhs> stepper(std::move(rhs), t0, y0, t1, options);
  OdeResult<N> result;
  std::size_t next = static_cast<std::size_t>(std::lower_bound(t_eval.begin(), t_eval.end(), t0) - t_eval.begin());
  if (t_eval.empty()) {
    result.t.push_back(t0);
    result.y.push_back(y0);
  } else if (next < t_eval.size() && t_eval[next] == t0) {
    result.t.push_back(t0);
    result.y.push_back(y0);
    ++next;
  }
  std::vector<double> g_old(events.size());
  std::vector<int> counts(events.size(), 0);
  for (std::size_t i = 0; i < events.size(); ++i) g_old[i] = events[i].value(t0, y0);

  while (stepper.step()) {
    const DenseStep<N>& step = stepper.last_step();
    double t_end = step.t_new;
    // Events: a crossing is a change from a non-zero sign to the other sign or to zero, so a
    // root found at the end of one step is not found again at the start of the next.
    struct Crossing { double t; std::size_t event; };
    std::vector<Crossing> crossings;
    for (std::size_t i = 0; i < events.size(); ++i) {
      const double g_new = events[i].value(step.t_new, step.y_new);
      const bool rising = g_old[i] < 0.0 && g_new >= 0.0;
      const bool falling = g_old[i] > 0.0 && g_new <= 0.0;
      const int dir = events[i].direction;
      if ((rising && dir >= 0) || (falling && dir <= 0)) {
        auto g = [&](double t) { return events[i].value(t, step(t)); };
        const double xtol = 4.0 * std::numeric_limits<double>::epsilon() * std::abs(step.t_new);
        crossings.push_back({detail::brent_root(g, step.t_old, step.t_new, g_old[i], g_new, xtol), i});
      }
      g_old[i] = g_new;
    }
    std::sort(crossings.begin(), crossings.end(),
              [](const Crossing& a, const Crossing& b) { return a.t < b.t; });
    for (const Crossing& c : crossings) {
      result.events.push_back({c.event, c.t, step(c.t)});
      const int terminal = events[c.event].terminal;
      if (terminal > 0 && ++counts[c.event] >= terminal) {
        result.terminated = true;
        t_end = c.t;
        break;
      }
    }
    if (t_eval.empty()) {
      result.t.push_back(t_end);
      result.y.push_back(result.terminated ? step(t_end) : step.y_new);
    } else {
      while (next < t_eval.size() && t_eval[next] <= t_end) {
        result.t.push_back(t_eval[next]);
        result.y.push_back(step(t_eval[next]));
        ++next;
      }
    }
    if (result.terminated) break;
  }
  result.statistics = stepper.statistics();
  return result;
}

}  // namespace vistrack
