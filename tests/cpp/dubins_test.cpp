// Dubins solvers: hand-derived vectors, seeded randomized properties, robustness cases,
// path to a circle and intercept against brute-force oracles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "dubins/path_integration.hpp"
#include "error_message.hpp"
#include "vistrack/dubins.hpp"
#include "vistrack/error.hpp"

using vistrack::testing::error_message;

using namespace vistrack;

namespace {

constexpr double kPiTest = 3.14159265358979323846;

double scale_of(const Configuration& a, const Configuration& b, double rho) {
  return std::max({1.0, rho, std::fabs(a.x), std::fabs(a.y), std::fabs(b.x), std::fabs(b.y)});
}

double position_error(const Configuration& a, const Configuration& b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}

double heading_error(const Configuration& a, const Configuration& b) {
  return std::fabs(wrap_to_pi(a.psi - b.psi));
}

Configuration random_configuration(std::mt19937_64& rng, double extent) {
  std::uniform_real_distribution<double> pos(-extent, extent), ang(-kPiTest, kPiTest);
  return {pos(rng), pos(rng), ang(rng)};
}

}  // namespace

// ---- hand-derived vectors ------------------------------------------------------------------

TEST(DubinsHand, StraightLine) {
  // Goal 10 m ahead, same heading: LSL with t = q = 0 and p = 10 (RSR ties; LSL comes first).
  const DubinsPath p = dubins_shortest_path({0, 0, 0}, {10, 0, 0}, 1.0);
  EXPECT_EQ(p.word, DubinsWord::LSL);
  EXPECT_NEAR(p.segment_lengths[0], 0.0, 1e-15);
  EXPECT_NEAR(p.segment_lengths[1], 10.0, 1e-14);
  EXPECT_NEAR(p.segment_lengths[2], 0.0, 1e-15);
  EXPECT_NEAR(p.length, 10.0, 1e-14);
}

TEST(DubinsHand, QuarterTurnLeftIsOneArc) {
  // Left circle of (0,0,0) with rho = 1 is centred at (0,1); the point at angle 0 about it is
  // (1,1) with heading pi/2. One arc of pi/2 rad: length rho * pi/2 = 1.5707963...
  const DubinsPath p = dubins_shortest_path({0, 0, 0}, {1, 1, kPiTest / 2}, 1.0);
  EXPECT_EQ(p.word, DubinsWord::LSL);
  EXPECT_NEAR(p.length, kPiTest / 2, 1e-12);
  EXPECT_NEAR(p.segment_lengths[0] + p.segment_lengths[1], 0.0, 1e-12);
}

TEST(DubinsHand, QuarterTurnRightRadiusTwo) {
  // rho = 2: right circle centred at (0,-2); (2,-2) heading -pi/2 is a quarter clockwise:
  // length 2 * pi/2 = pi.
  const DubinsPath p = dubins_shortest_path({0, 0, 0}, {2, -2, -kPiTest / 2}, 2.0);
  // LSR (0, 0, pi/2) with tangent circles (centres (0,2), (0,-2)) ties with RSR; either way
  // one right arc.
  EXPECT_NEAR(p.length, kPiTest, 1e-12);
  const auto types = p.segment_types();
  for (int k = 0; k < 3; ++k)
    if (p.segment_lengths[static_cast<std::size_t>(k)] > 1e-12) {
      EXPECT_EQ(types[static_cast<std::size_t>(k)], DubinsSegment::Right);
    }
}

TEST(DubinsHand, QuarterTurnThenStraight) {
  // Quarter left to (1,1) heading north, then 5 m north to (1,6): LSL (pi/2, 5, 0).
  const DubinsPath p = dubins_shortest_path({0, 0, 0}, {1, 6, kPiTest / 2}, 1.0);
  EXPECT_EQ(p.word, DubinsWord::LSL);
  EXPECT_NEAR(p.segment_lengths[0], kPiTest / 2, 1e-12);
  EXPECT_NEAR(p.segment_lengths[1], 5.0, 1e-12);
  EXPECT_NEAR(p.segment_lengths[2], 0.0, 1e-12);
}

TEST(DubinsHand, LrlAndMirroredRlr) {
  // Built by hand with rho = 1: left pi/6 from (0,0,0) reaches (1/2, 1 - sqrt3/2) heading pi/6;
  // the right circle there is centred at (1, 1 - sqrt3); clockwise 4 pi/3 reaches
  // (1/2, 1 - 3 sqrt3/2) heading 5 pi/6; the left circle there is centred at (0, 1 - 2 sqrt3);
  // left pi/6 ends at (0, 2 - 2 sqrt3) heading pi. Length pi/6 + 4 pi/3 + pi/6 = 5 pi/3.
  // Competitors: LSR/RSL impossible (circle centres 2 sqrt3 - 2 = 1.46 < 2 apart); LSL and RSR
  // need two 3 pi/2 arcs (> 9.4); RLR's middle arc alone is pi + 2 acos(0.134) = 6.01.
  const double s3 = std::sqrt(3.0);
  const Configuration goal{0.0, 2.0 - 2.0 * s3, kPiTest};
  const DubinsPath p = dubins_shortest_path({0, 0, 0}, goal, 1.0);
  EXPECT_EQ(p.word, DubinsWord::LRL);
  EXPECT_NEAR(p.segment_lengths[0], kPiTest / 6, 1e-12);
  EXPECT_NEAR(p.segment_lengths[1], 4 * kPiTest / 3, 1e-12);
  EXPECT_NEAR(p.segment_lengths[2], kPiTest / 6, 1e-12);
  EXPECT_NEAR(p.length, 5 * kPiTest / 3, 1e-12);
  const DubinsPath m = dubins_shortest_path({0, 0, 0}, {0.0, -(2.0 - 2.0 * s3), -kPiTest}, 1.0);
  EXPECT_EQ(m.word, DubinsWord::RLR);
  EXPECT_NEAR(m.length, 5 * kPiTest / 3, 1e-12);
}

TEST(DubinsHand, HalfTurnsAndTangentInnerCircles) {
  // (0, 2) heading pi is the top of the start's left circle (centre (0, 1)): half a left turn,
  // length pi.
  const DubinsPath p = dubins_shortest_path({0, 0, 0}, {0, 2, kPiTest}, 1.0);
  EXPECT_EQ(p.word, DubinsWord::LSL);
  EXPECT_NEAR(p.length, kPiTest, 1e-12);
  // The half turn then 3 m west to (-3, 2): LSL (pi, 3, 0), length pi + 3.
  const DubinsPath q = dubins_shortest_path({0, 0, 0}, {-3, 2, kPiTest}, 1.0);
  EXPECT_NEAR(q.segment_lengths[0], kPiTest, 1e-12);
  EXPECT_NEAR(q.segment_lengths[1], 3.0, 1e-12);
  EXPECT_NEAR(q.length, kPiTest + 3.0, 1e-12);
  // Goal (2, 2, 0): start left centre (0, 1), goal right centre (2, 2) + (sin 0, -cos 0) = (2, 1),
  // 2 apart: tangent circles, so LSR = quarter left to (1, 1) heading pi/2, then quarter right:
  // (pi/2, 0, pi/2), length pi. It is also the shortest (the straight-line distance is 2.83 and
  // any path must turn by +pi/2 then -pi/2).
  const DubinsPath r = dubins_path({0, 0, 0}, {2, 2, 0}, 1.0, DubinsWord::LSR);
  EXPECT_NEAR(r.segment_lengths[0], kPiTest / 2, 1e-9);
  EXPECT_NEAR(r.segment_lengths[1], 0.0, 1e-9);
  EXPECT_NEAR(r.segment_lengths[2], kPiTest / 2, 1e-9);
  EXPECT_NEAR(dubins_shortest_path({0, 0, 0}, {2, 2, 0}, 1.0).length, kPiTest, 1e-9);
  // RSL mirror: (2, -2, 0).
  const DubinsPath m = dubins_path({0, 0, 0}, {2, -2, 0}, 1.0, DubinsWord::RSL);
  EXPECT_NEAR(m.length, kPiTest, 1e-9);
}

// ---- robustness ---------------------------------------------------------------------------

TEST(DubinsRobust, IdenticalStartAndGoalIsZero) {
  for (double psi : {0.0, 0.3, -2.0, 3.1, kPiTest, -kPiTest}) {
    const Configuration q{1.5, -2.0, psi};
    const DubinsPath p = dubins_shortest_path(q, q, 3.0);
    EXPECT_EQ(p.length, 0.0) << psi;
    EXPECT_EQ(dubins_shortest_length(q, q, 3.0), 0.0);
  }
}

TEST(DubinsRobust, HeadingsDifferingByMultiplesOfTwoPi) {
  for (int k = -50; k <= 50; ++k) {
    const Configuration a{1.0, 2.0, 0.3};
    const Configuration b{1.0, 2.0, 0.3 + 2.0 * kPiTest * k};
    EXPECT_EQ(dubins_shortest_path(a, b, 1.0).length, 0.0) << k;
    // Same goal 5 m ahead: 5 m whatever the winding.
    const Configuration c{1.0 + 5.0 * std::cos(0.3), 2.0 + 5.0 * std::sin(0.3), b.psi};
    EXPECT_NEAR(dubins_shortest_path(a, c, 1.0).length, 5.0, 1e-9) << k;
  }
}

TEST(DubinsRobust, GoalOnTurningCircleIsSingleArc) {
  // Any point of the start's left circle with the tangent heading: one arc of rho * angle.
  const double rho = 7.0;
  for (int k = 1; k < 360; ++k) {
    const double a = 2.0 * kPiTest * k / 360.0;
    const Configuration goal{rho * std::sin(a), rho * (1.0 - std::cos(a)), a};
    const DubinsPath p = dubins_shortest_path({0, 0, 0}, goal, rho);
    // Beyond a half turn the right-hand detour can be shorter; the single arc is LSL's answer.
    const auto lengths = dubins_word_lengths({0, 0, 0}, goal, rho);
    EXPECT_NEAR(lengths[0], rho * a, 1e-9 * rho) << k;
    if (a < kPiTest) {
      EXPECT_NEAR(p.length, rho * a, 1e-9 * rho) << k;
      EXPECT_NEAR(p.segment_lengths[1], 0.0, 1e-9 * rho);
    }
    const Configuration right{rho * std::sin(a), -rho * (1.0 - std::cos(a)), -a};
    EXPECT_NEAR(dubins_word_lengths({0, 0, 0}, right, rho)[3], rho * a, 1e-9 * rho) << k;
  }
}

TEST(DubinsRobust, TinyDistancesAheadAndBehind) {
  for (double d : {1e-9, 1e-7, 1e-6, 1e-3}) {
    // Ahead: the straight of length d.
    EXPECT_NEAR(dubins_shortest_path({0, 0, 0}, {d, 0, 0}, 1.0).length, d, 1e-15) << d;
    // Behind by more than the length snap: a full loop plus d (LSL: t = pi, p = d, q = pi).
    const DubinsPath back = dubins_shortest_path({0, 0, 0}, {-d, 0, 0}, 1.0);
    EXPECT_NEAR(back.length, 2.0 * kPiTest + d, 1e-9) << d;
    EXPECT_LT(position_error(detail::integrate(back, back.length), back.goal), 1e-9);
  }
  // Below the documented snap (1e-11 rho here), a goal behind is the start itself.
  EXPECT_LT(dubins_shortest_path({0, 0, 0}, {-1e-13, 0, 0}, 1.0).length, 1e-12);
}

TEST(DubinsRobust, NeverNaNOnDegenerateGrid) {
  // Positions on a grid of multiples of rho with headings multiples of pi/4: tangencies, coincident
  // circles and CCC limits everywhere.
  for (int ix = -4; ix <= 4; ++ix)
    for (int iy = -4; iy <= 4; ++iy)
      for (int ia = -4; ia <= 4; ++ia)
        for (int ib = -4; ib <= 4; ++ib) {
          const Configuration a{0, 0, ia * kPiTest / 4};
          const Configuration b{ix * 1.0, iy * 1.0, ib * kPiTest / 4};
          const DubinsPath p = dubins_shortest_path(a, b, 1.0);
          ASSERT_TRUE(std::isfinite(p.length));
          EXPECT_LT(position_error(detail::integrate(p, p.length), b), 1e-9);
          EXPECT_LT(heading_error(detail::integrate(p, p.length), b), 1e-9);
        }
}

TEST(DubinsRobust, ReplanningFromSampledPointsGivesRemainingLength) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int checked = 0;
  for (int n = 0; n < 20000; ++n) {
    const double rho = 0.5 + 4.0 * unit(rng);
    const Configuration a = random_configuration(rng, n % 2 ? 3.0 * rho : 20.0);
    const Configuration b = random_configuration(rng, n % 2 ? 3.0 * rho : 20.0);
    const DubinsPath p = dubins_shortest_path(a, b, rho);
    const double scale = scale_of(a, b, rho);
    // Random arc lengths plus every segment junction and the end.
    std::vector<double> s{p.segment_lengths[0], p.segment_lengths[0] + p.segment_lengths[1], p.length};
    for (int k = 0; k < 5; ++k) s.push_back(unit(rng) * p.length);
    for (double arc : s) {
      const Configuration q = p.at(std::min(arc, p.length));
      const double remaining = dubins_shortest_length(q, b, rho);
      ASSERT_NEAR(remaining, p.length - arc, 1e-7 * scale)
          << "n=" << n << " word=" << to_string(p.word) << " s=" << arc << " of " << p.length;
      ++checked;
    }
  }
  EXPECT_GT(checked, 150000);
}

// ---- seeded randomized properties (>= 100,000 cases) -----------------------------------

TEST(DubinsProperty, RandomizedInvariants) {
  std::mt19937_64 rng(20260522);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  constexpr int kCases = 120000;
  for (int n = 0; n < kCases; ++n) {
    const double rho = 0.05 + 5.0 * unit(rng);
    // A third of the cases within a few turn radii (CCC and tangent regime).
    const double extent = n % 3 == 0 ? 2.5 * rho : 50.0 * unit(rng) + rho;
    const Configuration a = random_configuration(rng, extent);
    const Configuration b = random_configuration(rng, extent);
    const double scale = scale_of(a, b, rho);
    const DubinsPath p = dubins_shortest_path(a, b, rho);
    ASSERT_TRUE(std::isfinite(p.length));
    // Endpoint reached by integrating the segments.
    const Configuration end = detail::integrate(p, p.length);
    ASSERT_LT(position_error(end, b), 1e-9 * scale) << n;
    ASSERT_LT(heading_error(end, b), 1e-9) << n;
    // Length equals the sum of segments; all segments non-negative.
    ASSERT_NEAR(p.length, p.segment_lengths[0] + p.segment_lengths[1] + p.segment_lengths[2], 1e-12 * scale);
    for (double seg : p.segment_lengths) ASSERT_GE(seg, 0.0);
    // No word is shorter, and every existing word also ends at the goal.
    const auto lengths = dubins_word_lengths(a, b, rho);
    for (int k = 0; k < kDubinsWordCount; ++k) {
      if (!std::isfinite(lengths[static_cast<std::size_t>(k)])) continue;
      ASSERT_GE(lengths[static_cast<std::size_t>(k)], p.length - 1e-12 * scale);
      if (n % 10 == 0) {
        const DubinsPath w = dubins_path(a, b, rho, static_cast<DubinsWord>(k));
        ASSERT_LT(position_error(detail::integrate(w, w.length), b), 1e-9 * scale) << to_string(w.word);
        ASSERT_LT(heading_error(detail::integrate(w, w.length), b), 1e-9) << to_string(w.word);
      }
    }
    // Batch kernel agrees.
    DubinsWord word;
    ASSERT_NEAR(dubins_shortest_length(a, b, rho, &word), p.length, 1e-12 * scale);
    // Scaling positions and rho by k scales the length by k.
    const double k = 0.1 + 10.0 * unit(rng);
    ASSERT_NEAR(dubins_shortest_length({k * a.x, k * a.y, a.psi}, {k * b.x, k * b.y, b.psi}, k * rho),
                k * p.length, 1e-9 * k * scale);
    // Rigid motion: rotate by r about the origin and translate by (tx, ty).
    const double r = 2.0 * kPiTest * unit(rng), tx = 100.0 * (unit(rng) - 0.5), ty = 100.0 * (unit(rng) - 0.5);
    const auto move = [&](const Configuration& q) {
      return Configuration{std::cos(r) * q.x - std::sin(r) * q.y + tx, std::sin(r) * q.x + std::cos(r) * q.y + ty,
                           q.psi + r};
    };
    ASSERT_NEAR(dubins_shortest_length(move(a), move(b), rho), p.length, 1e-9 * (scale + 100.0)) << n;
    // Mirror (y, psi) -> (-y, -psi).
    ASSERT_NEAR(dubins_shortest_length({a.x, -a.y, -a.psi}, {b.x, -b.y, -b.psi}, rho), p.length, 1e-9 * scale);
    // Reversal: from the goal to the start with headings + pi.
    ASSERT_NEAR(dubins_shortest_length({b.x, b.y, b.psi + kPiTest}, {a.x, a.y, a.psi + kPiTest}, rho), p.length,
                1e-9 * scale)
        << n;
  }
}

TEST(DubinsProperty, SamplingEndsExactlyAtGoal) {
  std::mt19937_64 rng(11);
  for (int n = 0; n < 2000; ++n) {
    const Configuration a = random_configuration(rng, 10.0), b = random_configuration(rng, 10.0);
    const DubinsPath p = dubins_shortest_path(a, b, 1.3);
    const Points3 rows = p.sample(0.37);
    ASSERT_GE(rows.rows(), 2);
    EXPECT_EQ(rows(rows.rows() - 1, 0), b.x);
    EXPECT_EQ(rows(rows.rows() - 1, 1), b.y);
    EXPECT_EQ(rows(rows.rows() - 1, 2), b.psi);
    EXPECT_EQ(rows(0, 0), a.x);
    // Consecutive samples are at most `step` apart (chord <= arc).
    for (Eigen::Index k = 1; k < rows.rows(); ++k)
      ASSERT_LE(std::hypot(rows(k, 0) - rows(k - 1, 0), rows(k, 1) - rows(k - 1, 1)), 0.37 + 1e-9);
    const Points3 at = p.sample_at({0.0, 0.5 * p.length, p.length});
    EXPECT_EQ(at(2, 0), b.x);
  }
}

TEST(DubinsBatch, MatchesScalarAndRejectsNaN) {
  std::mt19937_64 rng(3);
  const int n = 50000;
  Points3 a(n, 3), b(n, 3);
  for (int i = 0; i < n; ++i) {
    const Configuration qa = random_configuration(rng, 8.0), qb = random_configuration(rng, 8.0);
    a.row(i) << qa.x, qa.y, qa.psi;
    b.row(i) << qb.x, qb.y, qb.psi;
  }
  const DubinsBatch out = dubins_shortest_lengths(a, b, 1.7);
  for (int i = 0; i < n; ++i) {
    const DubinsPath p = dubins_shortest_path({a(i, 0), a(i, 1), a(i, 2)}, {b(i, 0), b(i, 1), b(i, 2)}, 1.7);
    ASSERT_NEAR(out.lengths[static_cast<std::size_t>(i)], p.length, 1e-12 * (1.0 + p.length));
    ASSERT_EQ(out.words[static_cast<std::size_t>(i)], static_cast<std::uint8_t>(p.word));
  }
  b(17, 2) = std::numeric_limits<double>::quiet_NaN();
  try {
    dubins_shortest_lengths(a, b, 1.7);
    FAIL() << "NaN accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("q1s[17].psi"), std::string::npos) << e.what();
  }
}

TEST(DubinsBatch, BitIdenticalToScalarKernel) {
  // The batch runs the CSC words four pairs per AVX2 instruction where the CPU has it; every
  // lane must round exactly like the scalar kernel that dubins_shortest_path uses. Mixed data:
  // random far and near pairs, degenerate grid pairs, a count that is not a multiple of 4, and
  // one block with a huge heading (scalar fallback).
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<double> a, b;
  const auto push = [&](const Configuration& p, const Configuration& q) {
    a.insert(a.end(), {p.x, p.y, p.psi});
    b.insert(b.end(), {q.x, q.y, q.psi});
  };
  for (int n = 0; n < 60001; ++n) {
    const double extent = n % 3 == 0 ? 2.0 : 30.0;
    push({extent * unit(rng), extent * unit(rng), 4.0 * unit(rng)}, {extent * unit(rng), extent * unit(rng), 40.0 * unit(rng)});
  }
  for (int ix = -3; ix <= 3; ++ix)
    for (int ia = -4; ia <= 4; ++ia)
      for (int ib = -8; ib <= 8; ++ib) push({0, 0, ia * kPiTest / 4}, {ix * 0.5, 0.5, ib * kPiTest / 4});
  push({0, 0, 1e9}, {1, 2, 3});
  const std::size_t n = a.size() / 3;
  std::vector<double> lengths(n);
  std::vector<std::uint8_t> words(n);
  dubins_shortest_lengths(a.data(), b.data(), n, 1.3, lengths.data(), words.data());
  for (std::size_t i = 0; i < n; ++i) {
    DubinsWord w;
    const double l = dubins_shortest_length({a[3 * i], a[3 * i + 1], a[3 * i + 2]}, {b[3 * i], b[3 * i + 1], b[3 * i + 2]},
                                            1.3, &w);
    ASSERT_EQ(lengths[i], l) << i;
    ASSERT_EQ(words[i], static_cast<std::uint8_t>(w)) << i;
  }
}

// ---- bad input -----------------------------------------------------------------------------

TEST(DubinsErrors, NamesTheField) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(error_message([&] { dubins_shortest_path({0, 0, 0}, {1, 1, 0}, 0.0); }).find("rho"), std::string::npos);
  EXPECT_NE(error_message([&] { dubins_shortest_path({0, 0, 0}, {1, 1, 0}, -1.0); }).find("rho = -1"), std::string::npos);
  EXPECT_NE(error_message([&] { dubins_shortest_path({0, nan, 0}, {1, 1, 0}, 1.0); }).find("q0.y"), std::string::npos);
  EXPECT_NE(error_message([&] { dubins_shortest_path({0, 0, 0}, {1, 1, nan}, 1.0); }).find("q1.psi"), std::string::npos);
  EXPECT_NE(error_message([&] { from_name<DubinsWord>("LLL"); }).find("word"), std::string::npos);
  EXPECT_NE(error_message([&] { from_name<Circulation>("up"); }).find("direction"), std::string::npos);
  EXPECT_NE(error_message([&] { dubins_path({0, 0, 0}, {100, 0, 0}, 1.0, DubinsWord::LRL); }).find("word"),
            std::string::npos);
  const DubinsPath p = dubins_shortest_path({0, 0, 0}, {3, 0, 0}, 1.0);
  EXPECT_NE(error_message([&] { p.at(4.0); }).find("s = 4"), std::string::npos);
  EXPECT_NE(error_message([&] { p.sample(0.0); }).find("step"), std::string::npos);
  InterceptProblem bad;
  bad.pursuer_speed = -1.0;
  EXPECT_NE(error_message([&] { intercept_circle(bad); }).find("pursuer_speed"), std::string::npos);
  bad = InterceptProblem{};
  bad.target_speed = nan;
  EXPECT_NE(error_message([&] { intercept_circle(bad); }).find("target_speed"), std::string::npos);
  bad = InterceptProblem{};
  bad.circle.radius = -2.0;
  EXPECT_NE(error_message([&] { intercept_circle(bad); }).find("radius = -2"), std::string::npos);
  bad = InterceptProblem{};
  bad.circle.center = Vec2(100.0, 0.0);
  bad.target_speed = 1e12;
  EXPECT_NE(error_message([&] { intercept_circle(bad); }).find("target_speed = 1e+12"), std::string::npos);
  TargetCircle circle;
  EXPECT_NE(error_message([&] { dubins_path_to_circle({0, 0, 0}, 1.0, circle, nan); }).find("angle"), std::string::npos);
}

// ---- polynomial sin/cos/atan2 used by the length kernel --------------------------------------

#include "dubins/fast_math.hpp"

TEST(DubinsFastMath, MatchesLibm) {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> wide(-1e5, 1e5), unit(-1.0, 1.0);
  for (int n = 0; n < 200000; ++n) {
    const double x = n % 2 ? wide(rng) : 8.0 * unit(rng);
    const auto sc = detail::fast_sincos(x);
    ASSERT_NEAR(sc.s, std::sin(x), 2e-16 * (1.0 + std::fabs(x) * 1e-5)) << x;
    ASSERT_NEAR(sc.c, std::cos(x), 2e-16 * (1.0 + std::fabs(x) * 1e-5)) << x;
    const double y = unit(rng) * std::pow(10.0, 6.0 * unit(rng)), z = unit(rng) * std::pow(10.0, 6.0 * unit(rng));
    ASSERT_NEAR(detail::fast_atan2(y, z), std::atan2(y, z), 4.5e-16 * std::fabs(std::atan2(y, z)) + 1e-300) << y << " " << z;
  }
  // Axes and quadrant boundaries.
  for (double y : {0.0, 1.0, -1.0})
    for (double z : {1.0, -1.0, 0.0})
      if (y != 0.0 || z != 0.0) {
        EXPECT_NEAR(detail::fast_atan2(y, z), std::atan2(y, z), 1e-16);
      }
  EXPECT_NEAR(detail::fast_sincos(1e7).s, std::sin(1e7), 1e-15);  // libm fallback beyond 1e6
  EXPECT_NEAR(detail::mod_two_pi_poly(2.0 * kPiTest * 1000.0 + 0.5), 0.5, 1e-12);
}

// ---- path to a circle (Section III) ----------------------------------------------------------

TEST(DubinsCircle, GoalIsTangentAndLengthIsContinuousUnderFourRho) {
  std::mt19937_64 rng(123);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int cases = 0;
  while (cases < 40) {
    const double rho = 0.3 + unit(rng);
    TargetCircle circle;
    circle.center = Vec2(40.0 * (unit(rng) - 0.5), 40.0 * (unit(rng) - 0.5));
    circle.radius = 0.2 + 4.0 * unit(rng);
    circle.direction = cases % 2 ? CircleDirection::Clockwise : CircleDirection::CounterClockwise;
    const Configuration q0{0.0, 0.0, 2.0 * kPiTest * unit(rng)};
    if (!four_rho_condition(Vec2(q0.x, q0.y), rho, circle)) continue;
    ++cases;
    // Dense sampling: neighbouring angles differ by at most (r + 2 rho + |C| + r) h: no 2 pi rho jump.
    const int n = 20000;
    const double h = kTwoPi / n;
    const double bound = (2.0 * circle.radius + 2.0 * rho + circle.center.norm()) * h;
    double previous = dubins_length_to_circle(q0, rho, circle, 0.0);
    for (int k = 1; k <= n; ++k) {
      const double angle = k * h;
      const double d = dubins_length_to_circle(q0, rho, circle, angle);
      ASSERT_LE(std::fabs(d - previous), bound) << "case " << cases << " angle " << angle;
      // Under the 4 rho condition the shortest word is CSC: D == D_CSC (Section II).
      if (k % 50 == 0) {
        ASSERT_NEAR(d, dubins_csc_length_to_circle(q0, rho, circle, angle), 1e-12 * (1.0 + d));
        const DubinsPath p = dubins_path_to_circle(q0, rho, circle, angle);
        const Configuration goal = circle.configuration(angle);
        ASSERT_LT(position_error(detail::integrate(p, p.length), goal), 1e-9 * (1.0 + circle.center.norm()));
        ASSERT_LT(heading_error(detail::integrate(p, p.length), goal), 1e-9);
        // Tangent heading in the travel direction.
        const double tangent = circle.direction == CircleDirection::Clockwise ? angle - kPiTest / 2 : angle + kPiTest / 2;
        ASSERT_NEAR(wrap_to_pi(goal.psi - tangent), 0.0, 1e-12);
      }
      previous = d;
    }
    // Period exactly 2 pi.
    EXPECT_NEAR(dubins_length_to_circle(q0, rho, circle, 0.7), dubins_length_to_circle(q0, rho, circle, 0.7 + 6 * kTwoPi),
                1e-9);
  }
}

TEST(DubinsCircle, PaperEquationsForRhoEqualToRadius) {
  // Section III with r_t = rho, clockwise travel, pursuer at the origin heading 0:
  // LSL: L_S = |(c_x + 2 rho cos a, c_y + 2 rho sin a - rho)| (2), phi_1 = angle of that vector
  // mod 2 pi (3), phi_2 = mod(a - phi_1 - pi/2, 2 pi) (4).
  // LSR: the goal's right circle is centred at C, so L_S = sqrt(c_x^2 + (c_y - rho)^2 - 4 rho^2)
  // (5) does not depend on a; phi_1 = mod(psi_1 + psi_2) (6) with psi_1 = atan(2 rho / L_S) and
  // psi_2 the angle of (c_x, c_y - rho) -- a two-argument arctangent: with the one-argument
  // atan of the paper the quadrant is lost for c_x < 0 (the case below); phi_2 = mod(phi_1 - a
  // + pi/2) (7).
  const double rho = 1.0, cx = -4.0, cy = 3.0;
  TargetCircle circle;
  circle.center = Vec2(cx, cy);
  circle.radius = rho;
  circle.direction = CircleDirection::Clockwise;
  const auto mod = [](double x) { return x - kTwoPi * std::floor(x / kTwoPi); };
  for (int k = 0; k < 64; ++k) {
    const double a = kTwoPi * k / 64.0 + 0.01;
    const Configuration goal = circle.configuration(a);
    const double ex = cx + 2 * rho * std::cos(a), ey = cy + 2 * rho * std::sin(a) - rho;
    const double ls_lsl = std::hypot(ex, ey);
    const double phi1 = mod(std::atan2(ey, ex));
    const double phi2 = mod(a - phi1 - kPiTest / 2);
    const DubinsPath lsl = dubins_path({0, 0, 0}, goal, rho, DubinsWord::LSL);
    EXPECT_NEAR(lsl.segment_lengths[1], ls_lsl, 1e-12);
    EXPECT_NEAR(lsl.length, rho * (phi1 + phi2) + ls_lsl, 1e-9) << a;
    const double ls_lsr = std::sqrt(cx * cx + (cy - rho) * (cy - rho) - 4 * rho * rho);
    const double psi1 = std::atan(2 * rho / ls_lsr), psi2 = std::atan2(cy - rho, cx);
    const double phi1_lsr = mod(psi1 + psi2), phi2_lsr = mod(phi1_lsr - a + kPiTest / 2);
    const DubinsPath lsr = dubins_path({0, 0, 0}, goal, rho, DubinsWord::LSR);
    EXPECT_NEAR(lsr.segment_lengths[1], ls_lsr, 1e-12);
    EXPECT_NEAR(lsr.length, rho * (phi1_lsr + phi2_lsr) + ls_lsr, 1e-9) << a;
    // The one-argument atan of (6) would give a different first arc here (c_x < 0).
    EXPECT_GT(std::fabs(mod(psi1 + std::atan((cy - rho) / cx)) - phi1_lsr), 1.0);
  }
}

// ---- intercept (Section IV) against a brute-force oracle -------------------------------------

namespace {

// Earliest T on a grid of step dt with D(alpha(T)) <= v_p T.
double brute_force_intercept_time(const InterceptProblem& p, double dt) {
  const double sign = p.circle.direction == CircleDirection::Clockwise ? -1.0 : 1.0;
  for (double t = 0.0; t < 1e4; t += dt) {
    const double angle = p.target_angle0 + sign * p.target_speed * t / p.circle.radius;
    if (dubins_length_to_circle(p.pursuer, p.rho, p.circle, angle) <= p.pursuer_speed * t) return t;
  }
  return std::numeric_limits<double>::infinity();
}

}  // namespace

TEST(DubinsIntercept, MatchesBruteForceScan) {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int with_condition = 0, without = 0;
  for (int n = 0; n < 60; ++n) {
    InterceptProblem p;
    p.rho = 0.3 + 1.5 * unit(rng);
    p.pursuer = {10.0 * (unit(rng) - 0.5), 10.0 * (unit(rng) - 0.5), kTwoPi * unit(rng)};
    p.circle.center = Vec2(30.0 * (unit(rng) - 0.5), 30.0 * (unit(rng) - 0.5));
    p.circle.radius = 0.5 + 5.0 * unit(rng);
    p.circle.direction = n % 2 ? CircleDirection::Clockwise : CircleDirection::CounterClockwise;
    p.target_angle0 = kTwoPi * (unit(rng) - 0.5);
    p.pursuer_speed = 0.5 + 2.0 * unit(rng);
    p.target_speed = 0.2 + 3.0 * unit(rng);  // faster than the pursuer in many cases
    const InterceptResult r = intercept_circle(p);
    (r.four_rho_condition ? with_condition : without)++;
    const double dt = 1e-3;
    const double t_brute = brute_force_intercept_time(p, dt);
    ASSERT_TRUE(std::isfinite(t_brute));
    // The grid finds the first grid time at or after the first crossing.
    EXPECT_LE(r.time, t_brute + 1e-9) << n;
    EXPECT_GE(r.time, t_brute - dt - 1e-9) << n;
    // Equal travel times at the answer (the paper's loop condition "dt > eps" would stop at the
    // first negative dt; we bisect on the bracket): residual tiny and <= 0.
    EXPECT_LE(r.residual, 0.0);
    EXPECT_GT(r.residual, -1e-9);
    // The target is at the path's goal at that time, with the path's final heading.
    const double sign = p.circle.direction == CircleDirection::Clockwise ? -1.0 : 1.0;
    const Configuration target = p.circle.configuration(p.target_angle0 + sign * p.target_speed * r.time / p.circle.radius);
    EXPECT_LT(position_error(detail::integrate(r.path, r.path.length), target), 1e-8);
    EXPECT_LT(heading_error(detail::integrate(r.path, r.path.length), target), 1e-8);
    EXPECT_DOUBLE_EQ(r.period, kTwoPi);
    // alpha_min is the minimum of D over a dense scan.
    double dense_min = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 4000; ++k) dense_min = std::min(dense_min, dubins_length_to_circle(p.pursuer, p.rho, p.circle, kTwoPi * k / 4000));
    EXPECT_LE(dubins_length_to_circle(p.pursuer, p.rho, p.circle, r.alpha_min), dense_min + 1e-9);
  }
  EXPECT_GT(with_condition, 5);
  EXPECT_GT(without, 5);
}

TEST(DubinsIntercept, PaperScenarioAndTrivialStart) {
  // Fig. 7 scenario: pursuer (0, 0, 0), C = (-4, 3), alpha_i = pi, v_p = 1, v_t = 1.2, rho = r = 1.
  InterceptProblem p;
  p.circle.center = Vec2(-4.0, 3.0);
  p.circle.radius = 1.0;
  p.target_angle0 = kPiTest;
  p.pursuer_speed = 1.0;
  p.target_speed = 1.2;
  const InterceptResult r = intercept_circle(p);
  // |p - C| - r = 4 = 4 rho: the strict condition fails (answer feasible, optimality not proven).
  EXPECT_FALSE(r.four_rho_condition);
  EXPECT_NEAR(r.time, brute_force_intercept_time(p, 1e-4), 1e-4);
  // Pursuer already on the target with its heading: time 0.
  InterceptProblem q = p;
  q.pursuer = q.circle.configuration(q.target_angle0);
  const InterceptResult z = intercept_circle(q);
  EXPECT_EQ(z.time, 0.0);
  EXPECT_EQ(z.path.length, 0.0);
}
