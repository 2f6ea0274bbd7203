// Dormand-Prince 5(4): problems with known solutions, the observed order of convergence of the
// fixed-step method and of the dense output, event timing, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "vistrack/error.hpp"
#include "vistrack/ode.hpp"

namespace vistrack {
namespace {

using V1 = OdeVector<1>;
using V2 = OdeVector<2>;

// y' = y cos t, y(0) = 1: y = exp(sin t). Time-dependent and non-polynomial.
auto exp_sin = [](double t, const V1& y, V1& dy) { dy[0] = y[0] * std::cos(t); };

// Harmonic oscillator: y = (cos t, -sin t).
auto oscillator = [](double, const V2& y, V2& dy) { dy << y[1], -y[0]; };

TEST(DormandPrince, AdaptiveMeetsTheTolerance) {
  for (double rtol : {1e-4, 1e-7, 1e-10}) {
    OdeOptions options;
    options.rtol = rtol;
    options.atol = rtol * 1e-3;
    const auto sol = solve_ode<1>(exp_sin, 0.0, 10.0, V1(1.0), options);
    double worst = 0.0;
    for (std::size_t k = 0; k < sol.t.size(); ++k)
      worst = std::max(worst, std::abs(sol.y[k][0] - std::exp(std::sin(sol.t[k]))) / std::exp(1.0));
    EXPECT_LT(worst, 50 * rtol) << rtol;
    EXPECT_EQ(sol.t.back(), 10.0);
    // Six stages per trial step (FSAL), plus f(t0) and the starting-step probe.
    const auto& s = sol.statistics;
    EXPECT_EQ(s.rhs_evaluations, 6 * (s.accepted_steps + s.rejected_steps) + 2);
    EXPECT_EQ(sol.t.size(), s.accepted_steps + 1);
  }
}

TEST(DormandPrince, ExactForLowDegreePolynomials) {
  // y' = 4 t^3 - 3 t^2 + 1 has a quartic solution: DP5 integrates it exactly and the dense
  // output (4th order) reproduces it between the steps too.
  auto rhs = [](double t, const V1&, V1& dy) { dy[0] = 4 * t * t * t - 3 * t * t + 1; };
  OdeOptions options;
  options.fixed_step = 0.37;
  std::vector<double> t_eval;
  for (int k = 0; k <= 100; ++k) t_eval.push_back(3.0 * k / 100.0);
  const auto sol = solve_ode<1>(rhs, 0.0, 3.0, V1(2.0), options, t_eval);
  ASSERT_EQ(sol.t.size(), t_eval.size());
  for (std::size_t k = 0; k < sol.t.size(); ++k) {
    const double t = sol.t[k];
    EXPECT_NEAR(sol.y[k][0], t * t * t * t - t * t * t + t + 2.0, 1e-12) << t;
  }
}

double fixed_step_error(double h, bool dense) {
  OdeOptions options;
  options.fixed_step = h;
  std::vector<double> t_eval;
  if (dense) {
    // Points strictly inside steps, where only the continuous extension answers.
    for (double t = 0.3 * h; t < 4.0; t += h) t_eval.push_back(t);
  } else {
    t_eval = {4.0};
  }
  const auto sol = solve_ode<1>(exp_sin, 0.0, 4.0, V1(1.0), options, t_eval);
  double worst = 0.0;
  for (std::size_t k = 0; k < sol.t.size(); ++k)
    worst = std::max(worst, std::abs(sol.y[k][0] - std::exp(std::sin(sol.t[k]))));
  return worst;
}

TEST(DormandPrince, ObservedOrderOfConvergence) {
  // Global error ~ C h^5 for the steps; the continuous extension is 4th order locally, so its
  // error at interior points is O(h^5) per step and does not accumulate: order >= 4 observed.
  const double e1 = fixed_step_error(0.1, false), e2 = fixed_step_error(0.05, false),
               e3 = fixed_step_error(0.025, false);
  const double p1 = std::log2(e1 / e2), p2 = std::log2(e2 / e3);
  EXPECT_NEAR(p1, 5.0, 0.3) << e1 << " " << e2;
  EXPECT_NEAR(p2, 5.0, 0.3) << e2 << " " << e3;
  const double d1 = fixed_step_error(0.2, true), d2 = fixed_step_error(0.1, true), d3 = fixed_step_error(0.05, true);
  EXPECT_GT(std::log2(d1 / d2), 3.8);
  EXPECT_GT(std::log2(d2 / d3), 3.8);
}

TEST(DormandPrince, DenseOutputBetweenAdaptiveSteps) {
  OdeOptions options;
  options.rtol = 1e-9;
  options.atol = 1e-12;
  std::vector<double> t_eval;
  for (int k = 0; k <= 1000; ++k) t_eval.push_back(20.0 * k / 1000.0);
  const auto sol = solve_ode<2>(oscillator, 0.0, 20.0, V2(1.0, 0.0), options, t_eval);
  ASSERT_EQ(sol.t.size(), t_eval.size());
  EXPECT_LT(sol.statistics.accepted_steps, 500u);  // far fewer steps than outputs
  for (std::size_t k = 0; k < sol.t.size(); ++k) {
    EXPECT_NEAR(sol.y[k][0], std::cos(sol.t[k]), 2e-8);
    EXPECT_NEAR(sol.y[k][1], -std::sin(sol.t[k]), 2e-8);
  }
}

TEST(DormandPrince, EventTimingDirectionAndTermination) {
  OdeOptions options;
  options.rtol = 1e-10;
  options.atol = 1e-12;
  OdeEvent<2> any{[](double, const V2& y) { return y[0]; }, 0, 0};     // cos t = 0
  OdeEvent<2> rising{[](double, const V2& y) { return y[0]; }, +1, 0};  // at 3pi/2 + 2k pi
  OdeEvent<2> at_time{[](double t, const V2&) { return t - 2.5; }, 0, 0};
  const auto sol = solve_ode<2>(oscillator, 0.0, 10.0, V2(1.0, 0.0), options, {}, {any, rising, at_time});
  std::vector<double> any_times, rising_times, time_times;
  for (const auto& hit : sol.events) {
    (hit.event == 0 ? any_times : hit.event == 1 ? rising_times : time_times).push_back(hit.t);
    EXPECT_NEAR(hit.y[0], std::cos(hit.t), 1e-8);
  }
  ASSERT_EQ(any_times.size(), 3u);  // pi/2, 3pi/2, 5pi/2 < 10
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(any_times[static_cast<std::size_t>(k)], M_PI / 2 + k * M_PI, 1e-9);
  ASSERT_EQ(rising_times.size(), 1u);
  EXPECT_NEAR(rising_times[0], 1.5 * M_PI, 1e-9);
  ASSERT_EQ(time_times.size(), 1u);
  EXPECT_NEAR(time_times[0], 2.5, 1e-13);
  for (std::size_t k = 1; k < sol.events.size(); ++k) EXPECT_LE(sol.events[k - 1].t, sol.events[k].t);
  EXPECT_FALSE(sol.terminated);

  OdeEvent<2> stop_second{[](double, const V2& y) { return y[0]; }, 0, 2};
  const auto stopped = solve_ode<2>(oscillator, 0.0, 10.0, V2(1.0, 0.0), options, {}, {stop_second});
  EXPECT_TRUE(stopped.terminated);
  EXPECT_NEAR(stopped.t.back(), 1.5 * M_PI, 1e-9);
  EXPECT_NEAR(stopped.y.back()[0], 0.0, 1e-9);
}

TEST(DormandPrince, RandomLinearSystemsAgainstTheExactSolution) {
  // y' = [[a, -w], [w, a]] y: y(t) = e^{a t} R(w t) y0. Seeded, many cases.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 100; ++trial) {
    const double a = -1.0 + 1.2 * unit(rng), w = 10.0 * unit(rng);
    const V2 y0(2 * unit(rng) - 1, 2 * unit(rng) - 1);
    auto rhs = [&](double, const V2& y, V2& dy) { dy << a * y[0] - w * y[1], w * y[0] + a * y[1]; };
    OdeOptions options;
    options.rtol = 1e-8;
    options.atol = 1e-10;
    options.max_step = 0.5;
    const double t1 = 1.0 + 4.0 * unit(rng);
    const auto sol = solve_ode<2>(rhs, 0.0, t1, y0, options);
    const double c = std::cos(w * t1), s = std::sin(w * t1), g = std::exp(a * t1);
    const V2 exact(g * (c * y0[0] - s * y0[1]), g * (s * y0[0] + c * y0[1]));
    EXPECT_LT((sol.y.back() - exact).norm(), 1e-6 * (1 + exact.norm())) << trial;
    for (std::size_t k = 1; k < sol.t.size(); ++k) EXPECT_LE(sol.t[k] - sol.t[k - 1], 0.5 + 1e-15);
  }
}

TEST(DormandPrince, DynamicSizeMatchesFixedSize) {
  using VX = OdeVector<Eigen::Dynamic>;
  auto rhs = [](double, const VX& y, VX& dy) { dy.resize(2); dy << y[1], -y[0]; };
  VX y0(2);
  y0 << 1.0, 0.0;
  const auto dynamic = solve_ode<Eigen::Dynamic>(rhs, 0.0, 7.0, y0, OdeOptions{});
  const auto fixed = solve_ode<2>(oscillator, 0.0, 7.0, V2(1.0, 0.0), OdeOptions{});
  ASSERT_EQ(dynamic.t.size(), fixed.t.size());
  EXPECT_EQ(dynamic.y.back()[0], fixed.y.back()[0]);
}

TEST(DormandPrince, BadInputIsAnError) {
  OdeOptions options;
  EXPECT_THROW(solve_ode<1>(exp_sin, 1.0, 1.0, V1(1.0), options), Error);
  EXPECT_THROW(solve_ode<1>(exp_sin, 0.0, 1.0, V1(std::nan("")), options), Error);
  options.rtol = -1.0;
  EXPECT_THROW(solve_ode<1>(exp_sin, 0.0, 1.0, V1(1.0), options), Error);
  auto blows_up = [](double t, const V1&, V1& dy) { dy[0] = t > 0.5 ? std::nan("") : 1.0; };
  try {
    solve_ode<1>(blows_up, 0.0, 1.0, V1(1.0), OdeOptions{});
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("ode.rhs"), std::string::npos);
  }
  EXPECT_THROW(solve_ode<1>(exp_sin, 0.0, 1.0, V1(1.0), OdeOptions{}, {0.5, 0.2}), Error);
  OdeOptions few;
  few.max_steps = 3;
  few.max_step = 0.01;
  EXPECT_THROW(solve_ode<1>(exp_sin, 0.0, 1.0, V1(1.0), few), Error);
}

}  // namespace
}  // namespace vistrack
