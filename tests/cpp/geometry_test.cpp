#include "vistrack/geometry.hpp"

#include <gtest/gtest.h>

#include <random>

namespace vistrack {
namespace {

TEST(Geometry, WrapToPiRange) {
  EXPECT_DOUBLE_EQ(wrap_to_pi(kPi), kPi);
  EXPECT_DOUBLE_EQ(wrap_to_pi(-kPi), kPi);
  EXPECT_NEAR(wrap_to_pi(3 * kPi + 0.5), -kPi + 0.5, 1e-12);
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> angle(-100.0, 100.0);
  for (int i = 0; i < 10000; ++i) {
    const double a = angle(rng);
    const double w = wrap_to_pi(a);
    EXPECT_GT(w, -kPi);
    EXPECT_LE(w, kPi);
    EXPECT_NEAR(std::sin(w), std::sin(a), 1e-12);
    EXPECT_NEAR(std::cos(w), std::cos(a), 1e-12);
    const double w2 = wrap_to_two_pi(a);
    EXPECT_GE(w2, 0.0);
    EXPECT_LT(w2, kTwoPi);
    EXPECT_NEAR(std::cos(w2), std::cos(a), 1e-12);
  }
}

TEST(Geometry, AreaOrientationAndContainment) {
  Polygon square{{Vec2(0, 0), Vec2(0, 10), Vec2(10, 10), Vec2(10, 0)}, {}};  // clockwise
  EXPECT_DOUBLE_EQ(signed_area(square.outer), -100.0);
  square.holes.push_back({Vec2(4, 4), Vec2(6, 4), Vec2(6, 6), Vec2(4, 6)});  // ccw hole
  normalize_orientation(square);
  EXPECT_DOUBLE_EQ(signed_area(square.outer), 100.0);
  EXPECT_DOUBLE_EQ(signed_area(square.holes[0]), -4.0);
  EXPECT_DOUBLE_EQ(area(square), 96.0);
  EXPECT_TRUE(contains(square, Vec2(1, 1)));
  EXPECT_FALSE(contains(square, Vec2(5, 5)));  // in the hole
  EXPECT_TRUE(contains(square, Vec2(0, 5)));   // on the boundary
  EXPECT_FALSE(contains(square, Vec2(11, 5)));
  EXPECT_DOUBLE_EQ(distance_to_boundary(square, Vec2(2, 5)), 2.0);
  EXPECT_DOUBLE_EQ(distance_to_boundary(square, Vec2(3, 5)), 1.0);  // hole edge at x = 4
}

TEST(Geometry, SimplePolygons) {
  EXPECT_TRUE(is_simple({Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)}));
  EXPECT_FALSE(is_simple({Vec2(0, 0), Vec2(1, 1), Vec2(1, 0), Vec2(0, 1)}));  // bow tie
  EXPECT_FALSE(is_simple({Vec2(0, 0), Vec2(1, 0)}));
  EXPECT_FALSE(is_simple({Vec2(0, 0), Vec2(1, 0), Vec2(2, 0)}));  // degenerate
}

}  // namespace
}  // namespace vistrack

TEST(Geometry, PastFinishLineIsTheSignedDistanceAlongTheLeg) {
  using vistrack::Vec2;
  EXPECT_DOUBLE_EQ(vistrack::past_finish_line(Vec2(12, 3), Vec2(0, 0), Vec2(10, 0)), 2.0);
  EXPECT_DOUBLE_EQ(vistrack::past_finish_line(Vec2(5, -7), Vec2(0, 0), Vec2(10, 0)), -5.0);
  // Any direction: the leg (1, 1) -> (4, 5) has length 5; (4, 5) + 2 * (3, 4) / 5 + a sideways step.
  EXPECT_NEAR(vistrack::past_finish_line(Vec2(4 + 1.2 - 4, 5 + 1.6 + 3), Vec2(1, 1), Vec2(4, 5)), 2.0, 1e-12);
  EXPECT_EQ(vistrack::past_finish_line(Vec2(3, 3), Vec2(1, 1), Vec2(1, 1)), 0.0);  // no leg
}
