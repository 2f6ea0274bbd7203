// A smooth reference R(t) under a ceiling (beyond the paper): of the C1 quadratic splines that the
// vehicle can fly (Lemma 5's rate bound, a d2R/dt2 bound from the turn-rate limit) and that stay
// under the ceiling, the one with the largest integral of R (less a d2R/dt2 penalty, so that it
// does not zig-zag where the ceiling leaves it free). A banded linear program on the
// spline's control points, solved by a log-barrier interior point method with banded Newton steps;
// with a penalty on d2R/dt2 (Planning::radius_smoothing) a banded quadratic program, the same way.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "vistrack/error.hpp"
#include "vistrack/orbit.hpp"

namespace vistrack {

void SmoothRadiusLimits::validate() const {
  require_positive(uav_speed, "limits.uav_speed");
  require_non_negative(poi_speed, "limits.poi_speed");
  require_positive(min_turn_radius, "limits.min_turn_radius");
  if (!(uav_speed > poi_speed))
    detail::fail_field("limits.uav_speed", uav_speed, "must exceed the POI speed " + detail::to_text(poi_speed));
  require_positive(max_rate, "limits.max_rate");
  if (!(max_rate <= (uav_speed - poi_speed) * (1.0 + 1e-12)))
    detail::fail_field("limits.max_rate", max_rate,
                       "must not exceed v - v_g = " + detail::computed_text(uav_speed - poi_speed) + " (Lemma 5)");
  if (!(turn_share > 0.0 && turn_share < 1.0))
    detail::fail_field("limits.turn_share", turn_share, "must be in (0, 1)");
}

double SmoothRadiusLimits::max_acceleration(double r_lo, double rate) const {
  const double v = uav_speed;
  const double ratio = 1.0 + poi_speed / v;
  if (!(r_lo > 0.0)) return 0.0;
  // The turn rate Lemma 6 leaves free on an orbit of radius >= r_lo ...
  const double free_turn = v / min_turn_radius - v * ratio * ratio / r_lo;
  if (!(free_turn > 0.0)) return 0.0;
  // ... over |u_theta| >= sqrt(v^2 - (v_g + |R_dot|)^2), the d2R/dt2 term of (85) on the orbit.
  const double radial = poi_speed + std::abs(rate);
  return turn_share * free_turn * std::sqrt(std::max(0.0, v * v - radial * radial));
}

void Ceiling::validate() const {
  if (breaks.size() < 2) detail::fail_field("ceiling.breaks", breaks.size(), "need at least two break times");
  if (starts.size() + 1 != breaks.size() || ends.size() != starts.size())
    detail::fail_field("ceiling.starts", starts.size(),
                       "need one start and one end value per interval between breaks (" +
                           std::to_string(breaks.size() - 1) + ")");
  for (std::size_t j = 0; j < breaks.size(); ++j) {
    require_finite(breaks[j], "ceiling.breaks[" + std::to_string(j) + "]");
    if (j > 0 && !(breaks[j] > breaks[j - 1]))
      detail::fail_field("ceiling.breaks[" + std::to_string(j) + "]", breaks[j], "break times must increase");
  }
  for (std::size_t j = 0; j < starts.size(); ++j) {
    require_finite(starts[j], "ceiling.starts[" + std::to_string(j) + "]");
    require_finite(ends[j], "ceiling.ends[" + std::to_string(j) + "]");
  }
}

double Ceiling::at(double t) const {
  require_finite(t, "t");
  t = std::clamp(t, breaks.front(), breaks.back());
  const auto it = std::upper_bound(breaks.begin(), breaks.end(), t);
  std::size_t j = it == breaks.begin() ? 0 : static_cast<std::size_t>(it - breaks.begin()) - 1;
  j = std::min(j, starts.size() - 1);
  auto value = [&](std::size_t i) {
    const double u = (t - breaks[i]) / (breaks[i + 1] - breaks[i]);
    return starts[i] + std::clamp(u, 0.0, 1.0) * (ends[i] - starts[i]);
  };
  double out = value(j);
  if (j > 0 && t <= breaks[j]) out = std::min(out, value(j - 1));  // on a break: the smaller side
  return out;
}

namespace {

// One linear constraint a . c[first .. first + 2] <= b (the spline's rows touch three neighbours).
struct Row {
  std::size_t first;
  std::array<double, 3> a;
  double b;
};

// Symmetric positive definite matrix of bandwidth 2: diagonal, first and second off-diagonal.
struct Band {
  std::vector<double> d, e, f;
  explicit Band(std::size_t n) : d(n, 0.0), e(n, 0.0), f(n, 0.0) {}
  void add(const Row& row, double weight) {
    const std::size_t n = d.size();
    for (std::size_t p = 0; p < 3; ++p) {
      const std::size_t i = row.first + p;
      if (i >= n || row.a[p] == 0.0) continue;
      d[i] += weight * row.a[p] * row.a[p];
      if (p + 1 < 3 && i + 1 < n) e[i] += weight * row.a[p] * row.a[p + 1];
      if (p + 2 < 3 && i + 2 < n) f[i] += weight * row.a[p] * row.a[p + 2];
    }
  }
  // Solves this x = rhs in place by a banded LDL^T factorisation (O(n)); false when not positive.
  bool solve(std::vector<double>& rhs) const {
    const std::size_t n = d.size();
    std::vector<double> D(n), l1(n, 0.0), l2(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      double di = d[i];
      if (i >= 1) di -= l1[i - 1] * l1[i - 1] * D[i - 1];
      if (i >= 2) di -= l2[i - 2] * l2[i - 2] * D[i - 2];
      if (!(di > 0.0)) return false;
      D[i] = di;
      double ei = e[i];
      if (i >= 1) ei -= l2[i - 1] * l1[i - 1] * D[i - 1];
      l1[i] = ei / di;
      l2[i] = f[i] / di;
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (i >= 1) rhs[i] -= l1[i - 1] * rhs[i - 1];
      if (i >= 2) rhs[i] -= l2[i - 2] * rhs[i - 2];
    }
    for (std::size_t i = 0; i < n; ++i) rhs[i] /= D[i];
    for (std::size_t i = n; i-- > 0;) {
      if (i + 1 < n) rhs[i] -= l1[i] * rhs[i + 1];
      if (i + 2 < n) rhs[i] -= l2[i] * rhs[i + 2];
    }
    return true;
  }
};

double slack(const Row& row, const std::vector<double>& c) {
  double s = row.b;
  for (std::size_t p = 0; p < 3; ++p)
    if (row.a[p] != 0.0) s -= row.a[p] * c[row.first + p];
  return s;
}

// Maximises w . c - (penalty_weight / 2) sum over penalties of (a . c)^2 subject to rows, from a
// strictly feasible c, by the log-barrier method: each centring minimises
// t (-w.c + penalty) - sum log(slack) by Newton steps with a backtracking (Armijo) line
// search that keeps every slack positive, and t grows until the duality gap rows / t is below
// gap. c is updated in place and stays strictly feasible.
void barrier_lp(const std::vector<Row>& rows, const std::vector<double>& w, const std::vector<Row>& penalties,
                double penalty_weight, std::vector<double>& c, double t, double gap) {
  const std::size_t n = c.size();
  const double m = static_cast<double>(rows.size());
  std::vector<double> grad(n), step(n), trial(n), slacks(rows.size()), moves(rows.size());
  for (;;) {
    for (int newton = 0; newton < 100; ++newton) {
      Band hessian(n);
      for (std::size_t i = 0; i < n; ++i) grad[i] = -t * w[i];
      // The quadratic term t (weight / 2) sum (a . c)^2 over the penalty rows.
      for (const Row& row : penalties) {
        const double value = -slack(row, c);  // b = 0: a . c
        for (std::size_t p = 0; p < 3; ++p)
          if (row.a[p] != 0.0) grad[row.first + p] += t * penalty_weight * value * row.a[p];
        hessian.add(row, t * penalty_weight);
      }
      for (std::size_t k = 0; k < rows.size(); ++k) {
        const Row& row = rows[k];
        const double s = slacks[k] = slack(row, c);
        for (std::size_t p = 0; p < 3; ++p)
          if (row.a[p] != 0.0) grad[row.first + p] += row.a[p] / s;
        hessian.add(row, 1.0 / (s * s));
      }
      double largest = 0.0;
      for (double x : hessian.d) largest = std::max(largest, x);
      for (double& x : hessian.d) x += 1e-14 * largest;  // the boundary control points are barely constrained
      for (std::size_t i = 0; i < n; ++i) step[i] = -grad[i];
      if (!hessian.solve(step)) break;
      double decrement = 0.0;  // lambda^2
      double linear = 0.0;     // -t w . step
      for (std::size_t i = 0; i < n; ++i) {
        decrement -= grad[i] * step[i];
        linear -= t * w[i] * step[i];
      }
      if (!(decrement > 1e-10)) break;
      // Along the step each slack changes by -alpha a.step: the longest step that keeps them all
      // positive, then backtracking on the barrier function (slack ratios only, no new products).
      double alpha_max = std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k < rows.size(); ++k) {
        double move = 0.0;
        for (std::size_t p = 0; p < 3; ++p)
          if (rows[k].a[p] != 0.0) move += rows[k].a[p] * step[rows[k].first + p];
        moves[k] = move / slacks[k];
        if (moves[k] > 0.0) alpha_max = std::min(alpha_max, 1.0 / moves[k]);
      }
      // Along the step each penalty row's value a . c changes by a . step.
      double quadratic_first = 0.0, quadratic_second = 0.0;
      for (const Row& row : penalties) {
        double value = 0.0, move = 0.0;
        for (std::size_t p = 0; p < 3; ++p) {
          value += row.a[p] * c[row.first + p];
          move += row.a[p] * step[row.first + p];
        }
        quadratic_first += value * move;
        quadratic_second += move * move;
      }
      quadratic_first *= t * penalty_weight;
      quadratic_second *= 0.5 * t * penalty_weight;
      double alpha = std::min(1.0, 0.99 * alpha_max);
      bool accepted = false;
      for (int k = 0; k < 60 && !accepted; ++k, alpha *= 0.5) {
        double change = alpha * (linear + quadratic_first) + alpha * alpha * quadratic_second;
        for (double r : moves) change -= std::log1p(-alpha * r);
        accepted = change <= -0.25 * alpha * decrement;
        if (accepted)
          for (std::size_t i = 0; i < n; ++i) c[i] += alpha * step[i];
      }
      if (!accepted) break;
    }
    if (m / t <= gap) return;
    t *= 20.0;
  }
}

// Chords of g(x) = sqrt(v^2 - (v_g + x)^2) on [0, max_rate], denser near the end where g falls
// fastest: g >= alpha + beta x on each piece (g is concave, so the chords lie below it).
struct Chord {
  double alpha, beta;
};
std::vector<Chord> rate_chords(const SmoothRadiusLimits& limits) {
  const double v = limits.uav_speed;
  auto g = [&](double x) {
    const double radial = limits.poi_speed + x;
    return std::sqrt(std::max(0.0, v * v - radial * radial));
  };
  const std::array<double, 3> nodes{0.0, 0.75, 1.0};
  std::vector<Chord> chords;
  for (std::size_t k = 0; k + 1 < nodes.size(); ++k) {
    const double x0 = nodes[k] * limits.max_rate, x1 = nodes[k + 1] * limits.max_rate;
    const double beta = (g(x1) - g(x0)) / (x1 - x0);
    chords.push_back({g(x0) - beta * x0, beta});
  }
  return chords;
}

}  // namespace

RadiusProfile smooth_radius(const Ceiling& ceiling, const SmoothRadiusLimits& limits, double knot_spacing, int passes,
                            double smoothing) {
  if (passes < 1) detail::fail_field("passes", passes, "must be at least 1");
  limits.validate();
  ceiling.validate();
  require_finite(knot_spacing, "knot_spacing");
  const std::vector<double>& breaks = ceiling.breaks;
  const double t0 = breaks.front(), t1 = breaks.back();
  double c_min = std::numeric_limits<double>::infinity(), c_max = -c_min;
  for (std::size_t j = 0; j < ceiling.starts.size(); ++j) {
    c_min = std::min({c_min, ceiling.starts[j], ceiling.ends[j]});
    c_max = std::max({c_max, ceiling.starts[j], ceiling.ends[j]});
  }
  const double scale = std::max({1.0, std::abs(c_min), std::abs(c_max)});
  const double lemma6_radius = limits.min_turn_radius * (1.0 + limits.poi_speed / limits.uav_speed) *
                              (1.0 + limits.poi_speed / limits.uav_speed);
  const double a_top = limits.max_acceleration(std::max(c_max, 1.05 * lemma6_radius), 0.0);
  // Knots: fine enough that switching d2R/dt2 only at knots costs about 5 cm (A h^2 / 8).
  double h = knot_spacing > 0.0 ? knot_spacing : (a_top > 0.0 ? std::sqrt(8.0 * 0.05 / a_top) : t1 - t0);
  const auto n = static_cast<std::size_t>(std::clamp(std::ceil((t1 - t0) / h), 1.0, 4000.0));
  h = (t1 - t0) / static_cast<double>(n);
  const std::size_t controls = n + 2;  // c_0 .. c_n+1; knot i = t0 + i h, i = 0 .. n
  // Between two neighbouring constraint points (knots and breaks) R is one parabola and the
  // ceiling one line: R rises at most A h^2 / 8 above its chord, which the ceiling rows leave free.
  const double bulge = a_top * h * h / 8.0;

  // R(t) on [knot i, knot i+1] with u = (t - knot_i) / h: 1/2 (1-u)^2 c_i + (1/2 + u - u^2) c_i+1 + 1/2 u^2 c_i+2.
  auto point_row = [&](double t, double bound) {
    const double x = std::clamp((t - t0) / h, 0.0, static_cast<double>(n));
    const auto i = std::min(static_cast<std::size_t>(x), n - 1);
    const double u = x - static_cast<double>(i);
    return Row{i, {0.5 * (1 - u) * (1 - u), 0.5 + u - u * u, 0.5 * u * u}, bound};
  };

  std::vector<Row> fixed;  // ceiling and rate rows
  for (std::size_t i = 0; i <= n; ++i) {
    const double t = t0 + static_cast<double>(i) * h;
    fixed.push_back(point_row(t, ceiling.at(t) - bulge));
  }
  for (double t : breaks) fixed.push_back(point_row(t, ceiling.at(t) - bulge));
  for (std::size_t i = 0; i <= n; ++i) {  // Lemma 5 at every knot (dR/dt is linear in between)
    fixed.push_back(Row{i, {-1.0 / h, 1.0 / h, 0.0}, limits.max_rate});
    fixed.push_back(Row{i, {1.0 / h, -1.0 / h, 0.0}, limits.max_rate});
  }
  const std::vector<Chord> chords = rate_chords(limits);

  // The integral of R: each interval gives h/6, 2h/3, h/6 to its three control points.
  std::vector<double> w(controls, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    w[i] += h / 6.0;
    w[i + 1] += 2.0 * h / 3.0;
    w[i + 2] += h / 6.0;
  }

  // The d2R/dt2 penalty: one row per interval, d2R/dt2 sqrt(h) (its square is the integral of
  // (d2R/dt2)^2 there), weighted so that d2R/dt2 = a_top held for a unit time costs smoothing / 2 of
  // the top radius (scale) in the integral of R; the weight scales as length / acceleration^2, so
  // the same smoothing means the same on any city and vehicle.
  if (!(smoothing >= 0.0 && smoothing <= 1e3)) detail::fail_field("smoothing", smoothing, "must be in [0, 1e3]");
  const double weight = a_top > 0.0 ? smoothing * scale / (a_top * a_top) : 0.0;
  std::vector<Row> penalties;
  if (weight > 0.0)
    for (std::size_t i = 0; i < n; ++i) {
      const double row_scale = std::sqrt(h) / (h * h);
      penalties.push_back(Row{i, {row_scale, -2.0 * row_scale, row_scale}, 0.0});
    }
  // Start strictly inside: constant R below every ceiling, dR/dt = d2R/dt2 = 0.
  const double delta = 1e-3 * scale;
  std::vector<double> c(controls, c_min - bulge - delta);
  std::vector<double> floor(n, c_min - bulge - 2.0 * delta);  // R at both ends of interval i stays above
  double t_barrier = static_cast<double>(fixed.size()) / ((t1 - t0) * scale);
  for (int pass = 0; pass < passes; ++pass) {
    std::vector<Row> rows = fixed;
    for (std::size_t i = 0; i < n; ++i) {
      // d2R/dt2 on interval i and dR/dt at both its knots, on c_i, c_i+1, c_i+2.
      const std::array<double, 3> accel{1.0 / (h * h), -2.0 / (h * h), 1.0 / (h * h)};
      const std::array<std::array<double, 3>, 2> rate{{{-1.0 / h, 1.0 / h, 0.0}, {0.0, -1.0 / h, 1.0 / h}}};
      // |d2R/dt2| <= scale_i g(|R_dot|) >= scale_i (alpha + beta |R_dot|) for R >= the floor less the bulge.
      // alpha_0 = g(0). Near and under Lemma 6's radius the budget vanishes, and so would the
      // problem's conditioning: it is taken at 5 % above that radius at least, and the caller
      // checks the result against the exact bound (smooth_radius_violation) where R is lower.
      const double r_lo = std::max(floor[i] - bulge, 1.05 * lemma6_radius);
      const double share = limits.max_acceleration(r_lo, 0.0) / chords.front().alpha;
      for (const Chord& chord : chords)
        for (const auto& r : rate)
          for (double s : {1.0, -1.0})
            for (double s_rate : {1.0, -1.0}) {
              Row row{i, {0.0, 0.0, 0.0}, share * chord.alpha};
              for (std::size_t p = 0; p < 3; ++p) row.a[p] = s * accel[p] - share * chord.beta * s_rate * r[p];
              rows.push_back(row);
            }
      rows.push_back(Row{i, {-0.5, -0.5, 0.0}, -floor[i]});  // R(knot i) >= floor
      rows.push_back(Row{i, {0.0, -0.5, -0.5}, -floor[i]});  // R(knot i+1) >= floor
    }
    // Duality gap: the mean of R within 1 cm of the optimum.
    barrier_lp(rows, w, penalties, weight, c, t_barrier, 1e-2 * (t1 - t0));
    t_barrier = static_cast<double>(rows.size()) / (1.0 * (t1 - t0));  // warm start near the optimum
    // Raise each interval's floor to what R reached, so the next pass may use the larger budget.
    for (std::size_t i = 0; i < n; ++i)
      floor[i] = std::max(floor[i], std::min(0.5 * (c[i] + c[i + 1]), 0.5 * (c[i + 1] + c[i + 2])) - delta);
  }

  RadiusProfile profile;
  for (std::size_t i = 0; i <= n; ++i) {
    profile.times.push_back(i == n ? t1 : t0 + static_cast<double>(i) * h);
    profile.radii.push_back(0.5 * (c[i] + c[i + 1]));
    profile.rates.push_back((c[i + 1] - c[i]) / h);
  }
  return profile;
}

std::string smooth_radius_violation(const RadiusProfile& profile, const SmoothRadiusLimits& limits) {
  limits.validate();
  profile.validate();
  const double tolerance = 1e-9;
  const std::vector<double>& t = profile.times;
  if (!profile.smooth()) return "the profile is piecewise linear: dR/dt jumps at its knots";
  for (std::size_t k = 0; k < t.size(); ++k)
    if (std::abs(profile.rates[k]) > limits.max_rate * (1.0 + tolerance) + tolerance)
      return "|dR/dt| = " + detail::computed_text(std::abs(profile.rates[k])) + " m/s at t = " + detail::computed_text(t[k]) +
             " s exceeds " + detail::computed_text(limits.max_rate) + " m/s (Lemma 5)";
  for (std::size_t k = 0; k + 1 < t.size(); ++k) {
    const double span = t[k + 1] - t[k];
    const double accel = (profile.rates[k + 1] - profile.rates[k]) / span;
    double lowest = std::min(profile.radii[k], profile.radii[k + 1]);
    if (profile.rates[k] < 0.0 && profile.rates[k + 1] > 0.0)
      lowest = std::min(lowest, profile.radii[k] - 0.5 * profile.rates[k] * profile.rates[k] / accel);
    // d2R/dt2 is constant on the segment and dR/dt linear: the bound is concave in dR/dt, so its
    // smallest value on the segment is at an end.
    const double bound = std::min(limits.max_acceleration(lowest, profile.rates[k]),
                                  limits.max_acceleration(lowest, profile.rates[k + 1]));
    if (std::abs(accel) > bound * (1.0 + 1e-6) + tolerance)
      return "|d2R/dt2| = " + detail::computed_text(std::abs(accel)) + " m/s^2 at t = " + detail::computed_text(t[k]) +
             " s exceeds the " + detail::computed_text(bound) + " m/s^2 that the turn rate leaves at R = " +
             detail::computed_text(lowest) + " m";
  }
  return "";
}

}  // namespace vistrack
