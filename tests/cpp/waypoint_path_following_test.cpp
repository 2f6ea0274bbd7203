// DWN's path following (beyond the paper): the horizon path as PathFollower pieces passes through
// the turning point, W_n and W_{n+1}; the roll model flown along it passes its waypoints closely.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "vistrack/error.hpp"
#include "vistrack/waypoint_nav.hpp"

using namespace vistrack;

namespace {

// Closest distance from `point` to the pieces (sampled every 1e-3 of R).
double distance_to(const std::vector<PathPiece>& pieces, const Vec2& point, double R) {
  double best = 1e300;
  for (const PathPiece& piece : pieces)
    for (double s = 0.0; s <= piece.length; s += 1e-3 * R) {
      const Configuration q = piece.at(s);
      best = std::min(best, (Vec2(q.x, q.y) - point).norm());
    }
  return best;
}

}  // namespace

TEST(WaypointPathFollowing, PiecesPassThroughTheTurningPointAndBothWaypoints) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double R = 50.0;
  for (int k = 0; k < 200; ++k) {
    const Configuration pose{0.0, 0.0, 3.0 * u(rng)};
    const Vec2 w_next(R * (5.0 + 3.0 * u(rng)), R * 3.0 * u(rng));
    const Vec2 w_after = w_next + R * (6.0 + 2.0 * u(rng)) * Vec2(std::cos(1.5 * u(rng)), std::sin(1.5 * u(rng)));
    const TurningPoint tp = turning_point(pose, w_next, w_after, R);
    const std::vector<PathPiece> pieces = horizon_pieces(pose, tp, R, 2.0 * R);
    ASSERT_FALSE(pieces.empty());
    EXPECT_LT(distance_to(pieces, tp.point, R), 2e-3 * R);
    EXPECT_LT(distance_to(pieces, w_next, R), 2e-3 * R);
    EXPECT_LT(distance_to(pieces, w_after, R), 2e-3 * R);
    // continuous, and the path follower accepts it (it checks the gaps and curvatures)
    EXPECT_NO_THROW(PathFollower(pieces, 20.0, R));
    const Configuration end = pieces.back().at(pieces.back().length);
    EXPECT_NEAR((Vec2(end.x, end.y) - w_after).norm(), 2.0 * R, 1e-6 * R);
  }
}

TEST(WaypointPathFollowing, AutoIsThePapersDwnOnDubinsAndThePathOnRoll) {
  WaypointNavOptions o;
  EXPECT_EQ(o.resolved_tracking(), DwnTracking::Paper);
  o.dynamics = DynamicsModel::Roll;
  EXPECT_EQ(o.resolved_tracking(), DwnTracking::Path);
  o.method = NavigationMethod::Classical;
  EXPECT_EQ(o.resolved_tracking(), DwnTracking::Paper);
  o.dwn_tracking = DwnTracking::Path;
  EXPECT_THROW(o.validate(), Error);
}

TEST(WaypointPathFollowing, TheRollModelPassesTheWaypointsOnThePath) {
  const std::vector<Vec2> route = {{400.0, 0.0}, {700.0, 300.0}, {1000.0, 0.0}, {1400.0, 100.0}};
  WaypointNavOptions o;
  o.turn_radius = 50.0;
  o.speed = 20.0;
  o.dynamics = DynamicsModel::Roll;
  o.guidance = LegGuidance::L1;
  const NavigationResult path = navigate(route, Configuration{0.0, 0.0, 0.0}, o);
  o.dwn_tracking = DwnTracking::Paper;
  const NavigationResult paper = navigate(route, Configuration{0.0, 0.0, 0.0}, o);
  double worst_path = 0.0, worst_paper = 0.0;
  for (double m : path.metrics.miss_distances) worst_path = std::max(worst_path, m / o.turn_radius);
  for (double m : paper.metrics.miss_distances) worst_paper = std::max(worst_paper, m / o.turn_radius);
  EXPECT_TRUE(path.metrics.all_reached);
  EXPECT_EQ(path.metrics.swirls, 0);
  EXPECT_LT(worst_path, 0.05);
  EXPECT_GT(worst_paper, worst_path);
}
