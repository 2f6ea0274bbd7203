// Loiter planners and camera coverage: tangency to 1e-9, the printed equations' failing cases,
// continuity and turn-rate bounds of every plan, loiters of at least 2 pi, the order search
// against brute force, the exact ellipse-disk area against closed forms and Monte Carlo.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <tuple>
#include <random>

#include "loiter/tangents.hpp"
#include "error_message.hpp"
#include "vistrack/error.hpp"
#include "vistrack/loiter.hpp"
#include "vistrack/flight.hpp"

using vistrack::testing::error_message;

using namespace vistrack;

namespace {

constexpr double kPiTest = 3.14159265358979323846;
const LoiterMethod kMethods[] = {LoiterMethod::FlyThrough, LoiterMethod::Tlpp, LoiterMethod::Ldlpp};

// Random AOIs in [0, 800]^2, centres at least `separation` apart and 100 m from the origin.
LoiterProblem random_problem(std::mt19937_64& rng, int n, double separation = 170.0) {
  std::uniform_real_distribution<double> coordinate(0.0, 800.0);
  LoiterProblem p;
  while (static_cast<int>(p.aois.size()) < n) {
    const Vec2 c(coordinate(rng), coordinate(rng));
    bool ok = c.norm() >= 100.0;
    for (const Vec2& other : p.aois) ok = ok && (c - other).norm() >= separation;
    if (ok) p.aois.push_back(c);
  }
  return p;
}

std::vector<int> identity(std::size_t n) {
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  return order;
}

// Distance from the circle's tangent condition: |(t - c).(t - p)| / (|t - c| |t - p|), and the
// radius error.
double tangency_error(const Vec2& t, const Vec2& c, double radius, const Vec2& p) {
  const Vec2 a = t - c, b = t - p;
  return std::abs(a.dot(b)) / (a.norm() * std::max(b.norm(), 1e-300)) + std::abs(a.norm() - radius) / radius;
}

// Every structural property of a plan: pieces join in position and heading, arcs lie on their
// circles, lines point along their heading, the ends are the problem's start and end.
void expect_well_formed(const LoiterPlan& plan) {
  const auto& p = plan.problem.parameters;
  ASSERT_FALSE(plan.segments.empty());
  EXPECT_LT((plan.segments.front().start - plan.problem.start).norm(), 1e-9);
  EXPECT_LT((plan.segments.back().end - plan.problem.end).norm(), 1e-9);
  double length = 0.0;
  for (std::size_t k = 0; k < plan.segments.size(); ++k) {
    const LoiterSegment& s = plan.segments[k];
    length += s.length;
    EXPECT_GT(s.length, 0.0);
    const Configuration end = s.at(s.length);
    EXPECT_LT((Vec2(end.x, end.y) - s.end).norm(), 1e-9) << "segment " << k;
    EXPECT_NEAR(end.psi, s.end_heading, 1e-9);
    if (s.kind == SegmentKind::Arc) {
      EXPECT_TRUE(s.radius == p.turn_radius || s.radius == p.aoi_radius);
      EXPECT_NEAR((s.start - s.center).norm(), s.radius, 1e-9);
      EXPECT_NEAR((s.end - s.center).norm(), s.radius, 1e-9);
      // Loiter arcs are exactly the arcs on an AOI's loiter circle.
      const bool on_loiter_circle = s.aoi >= 0 && std::abs(s.radius - p.aoi_radius) < 1e-12 &&
                                    (s.center - plan.problem.aois[static_cast<std::size_t>(s.aoi)]).norm() < 1e-9;
      EXPECT_EQ(s.role == SegmentRole::Loiter, on_loiter_circle) << "segment " << k;
      // Heading is the tangent of the circle in the direction of travel.
      const Vec2 tangent = detail::tangent_direction(s.center, s.start, s.direction);
      EXPECT_NEAR(std::abs(wrap_to_pi(detail::heading_of(tangent) - s.start_heading)), 0.0, 1e-9);
    } else {
      EXPECT_NEAR(std::abs(wrap_to_pi(detail::heading_of(s.end - s.start) - s.start_heading)), 0.0, 1e-12);
    }
    if (k > 0) {
      const LoiterSegment& before = plan.segments[k - 1];
      EXPECT_LT((before.end - s.start).norm(), 1e-9) << "gap before segment " << k;
      EXPECT_NEAR(before.end_heading, s.start_heading, 1e-9) << "heading jump before segment " << k;
    }
  }
  EXPECT_NEAR(length, plan.length, 1e-9 * plan.length);
  EXPECT_NEAR(plan.flight_time, plan.length / p.speed, 1e-9);
}

}  // namespace

// ---- Tangents (eqs. 1-12) ----------------------------------------------------------------------

TEST(LoiterTangents, EntryAndExitTangentPointsTouchTheCircle) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coordinate(-500.0, 500.0), radius(10.0, 120.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec2 c(coordinate(rng), coordinate(rng)), p(coordinate(rng), coordinate(rng));
    const double R = radius(rng);
    if ((p - c).norm() < R * 1.001) continue;
    for (const Circulation d : {Circulation::CounterClockwise, Circulation::Clockwise}) {
      const Vec2 t = detail::entry_tangent_point(p, c, R, d);
      EXPECT_LT(tangency_error(t, c, R, p), 1e-9);
      // Arriving from p, the travel direction continues around the circle in direction d.
      EXPECT_GT((t - p).normalized().dot(detail::tangent_direction(c, t, d)), 1.0 - 1e-9);
      const Vec2 q = detail::exit_tangent_point(c, R, d, p);
      EXPECT_LT(tangency_error(q, c, R, p), 1e-9);
      EXPECT_GT((p - q).normalized().dot(detail::tangent_direction(c, q, d)), 1.0 - 1e-9);
    }
  }
}

TEST(LoiterTangents, PrintedEquationSixNeedsTheAoiRadius) {
  // (6) prints sqrt(D - r^2) with the turn radius; tangency to the AOI circle needs R. Equal when
  // R = r (the paper's runs), wrong as soon as R > r.
  const Vec2 p(0.0, 0.0), c(300.0, 120.0);
  const double R = 80.0, r = 46.0;
  const Vec2 w = p - c;
  const double D = w.squaredNorm();  // (3): the squared distance
  const Vec2 q = c + (R * R / D) * w;
  const Vec2 jw(w.y(), -w.x());
  const Vec2 printed = q - (R / D) * std::sqrt(D - r * r) * jw;
  const Vec2 derived = q - (R / D) * std::sqrt(D - R * R) * jw;
  EXPECT_GT(tangency_error(printed, c, R, p), 1e-3);
  EXPECT_LT(tangency_error(derived, c, R, p), 1e-12);
  EXPECT_LT((derived - detail::tangent_points(p, c, R)[0]).norm(), 1e-9);
  // Reading (3)'s D as the distance it is called (not squared) puts the point far off the circle.
  const double d = std::sqrt(D);
  const Vec2 as_distance = c + (R * R / d) * w - (R / d) * std::sqrt(std::max(0.0, d - R * R)) * jw;
  EXPECT_GT(tangency_error(as_distance, c, R, p), 0.1);
}

TEST(LoiterTangents, InnerTangentsTouchBothCirclesAndCrossTheMiddle) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> coordinate(-800.0, 800.0);
  const double R = 46.0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec2 c1(coordinate(rng), coordinate(rng)), c2(coordinate(rng), coordinate(rng));
    if ((c2 - c1).norm() < 2.0 * R) continue;
    for (const Circulation d : {Circulation::CounterClockwise, Circulation::Clockwise}) {
      const auto t = detail::inner_tangent(c1, c2, R, d);
      EXPECT_LT(tangency_error(t.departure, c1, R, t.entry), 1e-9);
      EXPECT_LT(tangency_error(t.entry, c2, R, t.departure), 1e-9);
      EXPECT_LT((0.5 * (t.departure + t.entry) - 0.5 * (c1 + c2)).norm(), 1e-9);
      const Vec2 along = (t.entry - t.departure).normalized();
      EXPECT_GT(along.dot(detail::tangent_direction(c1, t.departure, d)), 1.0 - 1e-9);
      EXPECT_GT(along.dot(detail::tangent_direction(c2, t.entry, detail::opposite(d))), 1.0 - 1e-9);
    }
  }
}

TEST(LoiterTangents, PrintedInnerTangentLosesTheQuadrant) {
  // Eqs. (8)-(12) as printed: theta = atan(|dy| / |dx|), lambda = zeta +- theta, departure
  // (X1 + R cos lambda, Y1 - R sin lambda), entry (X2 - R cos lambda, Y2 + R sin lambda).
  const double R = 46.0;
  const auto printed_ok = [&](const Vec2& p1, const Vec2& p2) {
    const Vec2 p12 = p1 - p2;
    const double d = p12.norm();
    const double theta = std::atan(std::abs(p12.y()) / std::abs(p12.x()));
    const double zeta = std::acos(R / (0.5 * d));
    bool any = false;
    for (const double lambda : {zeta + theta, zeta - theta}) {
      const Vec2 departure(p1.x() + R * std::cos(lambda), p1.y() - R * std::sin(lambda));
      const Vec2 entry(p2.x() - R * std::cos(lambda), p2.y() + R * std::sin(lambda));
      any = any || (tangency_error(departure, p1, R, entry) < 1e-9 && tangency_error(entry, p2, R, departure) < 1e-9);
    }
    return any;
  };
  const Vec2 p1(0.0, 0.0);
  EXPECT_TRUE(printed_ok(p1, Vec2(400.0, 300.0)));     // P2 up and to the right: the printed case
  EXPECT_FALSE(printed_ok(p1, Vec2(-400.0, -300.0)));  // down and to the left: no tangent
  EXPECT_FALSE(printed_ok(p1, Vec2(-400.0, 300.0)));
  for (const Vec2& p2 : {Vec2(-400.0, -300.0), Vec2(-400.0, 300.0)}) {
    const auto t = detail::inner_tangent(p1, p2, R, Circulation::CounterClockwise);
    EXPECT_LT(tangency_error(t.departure, p1, R, t.entry), 1e-9);
  }
}

// ---- LDLPP geometry (eqs. 13-17) ----------------------------------------------------------------

TEST(LoiterLdlpp, EntryAngleAndDistanceMatchTheGeometry) {
  for (const auto& radii : {std::pair{46.0, 46.0}, std::pair{80.0, 46.0}, std::pair{200.0, 30.0}}) {
    const double R = radii.first, r = radii.second;
    const double alpha = ldlpp_entry_angle(R, r), D = ldlpp_entry_distance(R, r);
    EXPECT_NEAR(alpha, std::asin(r / (R + r)), 1e-15);
    EXPECT_NEAR(D, (R + r) * std::cos(alpha), 1e-12);
    EXPECT_NEAR(D, std::sqrt(R * R + 2.0 * R * r), 1e-9);
    // The clockwise turn started D before P on the line (u = +x) touches the loiter circle.
    const Vec2 P(0.0, 0.0), S(-D, 0.0), turn_center = S + r * Vec2(0.0, -1.0);
    EXPECT_NEAR((turn_center - P).norm(), R + r, 1e-9);
    EXPECT_NEAR(std::atan2(r, D), alpha, 1e-12);  // the angle at P
    // Turning pi/2 - alpha reaches the contact point with the loiter's counter-clockwise heading.
    const auto turn_end = [&](double turned) -> Vec2 {
      return turn_center + r * detail::unit_at(0.5 * kPiTest - turned);
    };
    const Vec2 contact = turn_end(ldlpp_turn_angle(R, r));
    EXPECT_NEAR((contact - P).norm(), R, 1e-9);
    EXPECT_NEAR(std::abs(wrap_to_pi(-ldlpp_turn_angle(R, r) -
                                    detail::heading_of(detail::tangent_direction(P, contact, Circulation::CounterClockwise)))),
                0.0, 1e-9);
    // (16) as printed stops the turn when the heading change is alpha_ED: off the circle.
    EXPECT_GT(std::abs((turn_end(alpha) - P).norm() - R), 1.0);
  }
}

TEST(LoiterLdlpp, ExitPointClosesTheAnglePrintedSeventeenDoesNot) {
  const LoiterProblem problem = [] {
    LoiterProblem p;
    p.aois = {Vec2(300.0, 100.0), Vec2(500.0, 500.0)};
    return p;
  }();
  const LoiterPlan plan = plan_loiter(problem, LoiterMethod::Ldlpp);
  const double alpha = ldlpp_entry_angle(46.0, 46.0);
  // The exit point is where the loiter around POI 1 ends before the clockwise exit turn.
  const auto exit_it = std::find_if(plan.segments.begin(), plan.segments.end(),
                                    [](const LoiterSegment& s) { return s.role == SegmentRole::Exit; });
  ASSERT_NE(exit_it, plan.segments.end());
  const Vec2 F = exit_it->start, P2 = problem.aois[0], P3 = problem.aois[1];
  // The closing angle at P2 between F and P3, with the quadrant: alpha_ED.
  const Vec2 a = P3 - P2, b = F - P2;
  EXPECT_NEAR(std::atan2(std::abs(detail::cross(a, b)), a.dot(b)), alpha, 1e-9);
  // On the right of the line P2 -> P3 (counter-clockwise loiter into a clockwise exit turn).
  EXPECT_LT(detail::cross(a, b), 0.0);
  // Printed (17), the vertex at P3 (det read as det[P2 - P3, F - P3]): not alpha_ED.
  const Vec2 a3 = P2 - P3, b3 = F - P3;
  EXPECT_GT(std::abs(std::atan(std::abs(detail::cross(a3, b3)) / a3.dot(b3)) - alpha), 0.1);
  // And atan without the quadrant reports a negative angle for an obtuse one.
  const Vec2 behind = P2 - 50.0 * a.normalized() + Vec2(1.0, 1.0);
  const Vec2 bb = behind - P2;
  EXPECT_LT(std::atan(std::abs(detail::cross(a, bb)) / a.dot(bb)), 0.0);
  EXPECT_GT(std::atan2(std::abs(detail::cross(a, bb)), a.dot(bb)), 0.5 * kPiTest);
}

// ---- Plans ---------------------------------------------------------------------------------------

TEST(LoiterPlan, EveryMethodIsContinuousAndCirclesEveryAoi) {
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 60; ++trial) {
    LoiterProblem problem = random_problem(rng, 2 + trial % 8, 200.0);
    problem.parameters.turns = 1 + trial % 2;
    if (trial % 3 == 1) problem.parameters.aoi_radius = 60.0;
    if (trial % 5 == 2) problem.end = Vec2(-150.0, 40.0);
    for (const LoiterMethod method : kMethods) {
      SCOPED_TRACE(to_string(method) + " trial " + std::to_string(trial));
      const LoiterPlan plan = plan_loiter(problem, method);
      expect_well_formed(plan);
      for (std::size_t i = 0; i < problem.aois.size(); ++i)
        EXPECT_GE(plan.loiter_sweep[i], kTwoPi * problem.parameters.turns - 1e-9);
      EXPECT_GT(plan.transit_time, 0.0);
      EXPECT_NEAR(plan.transit_time + plan.loiter_time, plan.flight_time, 1e-9);
    }
  }
}

TEST(LoiterPlan, SamplesTurnNoFasterThanTheAircraftCan) {
  std::mt19937_64 rng(5);
  const LoiterProblem problem = random_problem(rng, 6);
  const double v = problem.parameters.speed, r = problem.parameters.turn_radius;
  for (const LoiterMethod method : kMethods) {
    const LoiterPlan plan = plan_loiter(problem, method);
    for (const double dt : {1.0, 0.1}) {
      const LoiterSamples s = plan.sample_states(dt);
      const auto n = s.poses.rows();
      EXPECT_NEAR(s.t.back(), plan.flight_time, 1e-9);
      for (Eigen::Index k = 1; k < n; ++k) {
        const double step = s.t[static_cast<std::size_t>(k)] - s.t[static_cast<std::size_t>(k - 1)];
        // Headings are continuous (not wrapped): the change over a step is at most v dt / r.
        EXPECT_LE(std::abs(s.poses(k, 2) - s.poses(k - 1, 2)), v * step / r + 1e-9);
        // Travel between samples never exceeds the speed (chords of arcs are shorter).
        EXPECT_LE((s.poses.row(k).head<2>() - s.poses.row(k - 1).head<2>()).norm(), v * step + 1e-9);
      }
      for (const double rate : s.turn_rate) EXPECT_LE(std::abs(rate), v / r + 1e-12);
    }
  }
}

TEST(LoiterPlan, FlyThroughTurnsThreeQuartersAndFliesROnWhenRadiiAgree) {
  LoiterProblem problem;
  // Inbound towards +x; the next AOI lies to the left of that line, so the loiter is clockwise
  // (after it the aircraft heads +y, towards the next AOI), as in the paper's Figure 6.
  problem.aois = {Vec2(400.0, 0.0), Vec2(400.0, 500.0)};
  const LoiterPlan plan = plan_loiter(problem, LoiterMethod::FlyThrough);
  expect_well_formed(plan);
  EXPECT_EQ(plan.directions[0], Circulation::Clockwise);
  const double r = 46.0;
  std::vector<const LoiterSegment*> entry;
  for (const auto& s : plan.segments)
    if (s.role == SegmentRole::Entry && s.aoi == 0) entry.push_back(&s);
  ASSERT_EQ(entry.size(), 2u);
  EXPECT_EQ(entry[0]->kind, SegmentKind::Arc);
  EXPECT_NEAR(entry[0]->sweep, 1.5 * kPiTest, 1e-9);
  EXPECT_EQ(entry[0]->direction, Circulation::Clockwise);
  EXPECT_EQ(entry[1]->kind, SegmentKind::Line);
  EXPECT_NEAR(entry[1]->length, r, 1e-9);
  EXPECT_LT((entry[1]->end - Vec2(400.0 - 46.0, 0.0)).norm(), 1e-9);  // the offset point
  // 400 m to the POI, 3/4 turn + r, then the loiter from the offset point.
  EXPECT_NEAR(plan.segment_offsets[3], 400.0 + 1.5 * kPiTest * r + r, 1e-9);
  EXPECT_EQ(plan.segments[3].role, SegmentRole::Loiter);
  EXPECT_NEAR(plan.segments[3].sweep, kTwoPi, 1e-12);
  // The turn towards the next POI is clockwise too, so with R = r it goes on around the loiter
  // circle (counted as loiter) until the POI at (400, 500) is straight ahead.
  EXPECT_EQ(plan.segments[4].role, SegmentRole::Loiter);
  EXPECT_EQ(plan.segments[5].kind, SegmentKind::Line);
  const Vec2 ahead = plan.segments[5].start + 1000.0 * detail::unit_at(plan.segments[5].start_heading);
  EXPECT_LT(std::abs(detail::cross(ahead - plan.segments[5].start, problem.aois[1] - plan.segments[5].start)) / 1000.0,
            1e-9);
  EXPECT_NEAR(plan.loiter_sweep[0], kTwoPi + plan.segments[4].sweep, 1e-12);
}

TEST(LoiterPlan, TlppAlternatesAndLdlppLoitersCounterClockwise) {
  std::mt19937_64 rng(13);
  const LoiterProblem problem = random_problem(rng, 7);
  const LoiterPlan tlpp = plan_loiter(problem, LoiterMethod::Tlpp);
  for (std::size_t k = 1; k < tlpp.order.size(); ++k)
    EXPECT_NE(tlpp.directions[static_cast<std::size_t>(tlpp.order[k])],
              tlpp.directions[static_cast<std::size_t>(tlpp.order[k - 1])]);
  const LoiterPlan ldlpp = plan_loiter(problem, LoiterMethod::Ldlpp);
  for (const auto& s : ldlpp.segments) {
    if (s.role == SegmentRole::Loiter) {
      EXPECT_EQ(s.direction, Circulation::CounterClockwise);
    }
    if (s.role == SegmentRole::Entry || s.role == SegmentRole::Exit) {
      EXPECT_EQ(s.direction, Circulation::Clockwise);
      EXPECT_NEAR(s.sweep, ldlpp_turn_angle(46.0, 46.0), 1e-12);
    }
  }
  // LDLPP's transit lines lie on the lines between POIs.
  for (const auto& s : ldlpp.segments)
    if (s.role == SegmentRole::Transit && s.kind == SegmentKind::Line) {
      std::vector<Vec2> stops{problem.start};
      for (const int i : ldlpp.order) stops.push_back(problem.aois[static_cast<std::size_t>(i)]);
      stops.push_back(problem.end);
      bool on_a_line = false;
      for (std::size_t k = 1; k < stops.size(); ++k) {
        const Vec2 u = (stops[k] - stops[k - 1]).normalized();
        on_a_line = on_a_line || (std::abs(detail::cross(u, s.start - stops[k - 1])) < 1e-9 &&
                                  std::abs(detail::cross(u, s.end - stops[k - 1])) < 1e-9);
      }
      EXPECT_TRUE(on_a_line);
    }
}

TEST(LoiterPlan, SingleAoiAndTouchingCircles) {
  LoiterProblem problem;
  problem.aois = {Vec2(200.0, 200.0)};
  for (const LoiterMethod method : kMethods) expect_well_formed(plan_loiter(problem, method));
  // TLPP with loiter circles that touch: the inner tangent has length 0.
  problem.aois = {Vec2(200.0, 200.0), Vec2(292.0, 200.0)};
  const LoiterPlan tlpp = plan_loiter(problem, LoiterMethod::Tlpp);
  expect_well_formed(tlpp);
}

// ---- Order search ------------------------------------------------------------------------------

TEST(LoiterOrder, ExactSearchMatchesBruteForce) {
  std::mt19937_64 rng(17);
  for (int trial = 0; trial < 8; ++trial) {
    const LoiterProblem problem = random_problem(rng, 4 + trial % 3);
    for (const LoiterMethod method : kMethods) {
      std::vector<int> order = identity(problem.aois.size());
      double brute = std::numeric_limits<double>::infinity();
      do {
        brute = std::min(brute, loiter_order_length(problem, method, order));
      } while (std::next_permutation(order.begin(), order.end()));
      const std::vector<int> best = best_loiter_order(problem, method, true);
      EXPECT_NEAR(loiter_order_length(problem, method, best), brute, 1e-9 * brute) << to_string(method);
      const LoiterPlan plan = plan_loiter(problem, method, LoiterOrder::Best);
      EXPECT_NEAR(plan.length, brute, 1e-6 * brute);
      // The heuristic is never worse than the given order.
      const double heuristic = loiter_order_length(problem, method, best_loiter_order(problem, method, false));
      EXPECT_LE(heuristic, loiter_order_length(problem, method, identity(problem.aois.size())) + 1e-9);
    }
  }
}

TEST(LoiterOrder, LdlppSkipsOrdersItCannotFly) {
  LoiterProblem problem;
  // aois 0 and 1 are 120 m apart: LDLPP cannot fly them one after the other (needs 159.3 m).
  problem.aois = {Vec2(300.0, 0.0), Vec2(420.0, 0.0), Vec2(360.0, 400.0)};
  EXPECT_TRUE(std::isinf(loiter_order_length(problem, LoiterMethod::Ldlpp, {0, 1, 2})));
  try {
    plan_loiter(problem, LoiterMethod::Ldlpp);
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("aois[1]"), std::string::npos) << e.what();
  }
  const LoiterPlan plan = plan_loiter(problem, LoiterMethod::Ldlpp, LoiterOrder::Best);
  expect_well_formed(plan);
  // aois 0 and 1 are not flown one after the other.
  const auto position = [&](int aoi) { return std::find(plan.order.begin(), plan.order.end(), aoi) - plan.order.begin(); };
  EXPECT_NE(std::abs(position(0) - position(1)), 1);
}

TEST(LoiterOrder, HeuristicAboveTheExactLimit) {
  std::mt19937_64 rng(19);
  const LoiterProblem problem = random_problem(rng, 12, 160.0);
  for (const LoiterMethod method : kMethods) {
    const LoiterPlan given = plan_loiter(problem, method);
    const LoiterPlan best = plan_loiter(problem, method, LoiterOrder::Best);
    expect_well_formed(best);
    EXPECT_LE(best.length, given.length + 1e-9);
  }
}

// ---- Bad input -----------------------------------------------------------------------------------

TEST(LoiterValidation, ErrorsNameTheField) {
  LoiterProblem good;
  good.aois = {Vec2(300.0, 300.0), Vec2(600.0, 300.0)};
  const auto with = [&](const std::function<void(LoiterProblem&)>& change) {
    LoiterProblem p = good;
    change(p);
    return error_message([&] { plan_loiter(p, LoiterMethod::Tlpp); });
  };
  EXPECT_NE(with([](LoiterProblem& p) { p.aois.clear(); }).find("aois"), std::string::npos);
  EXPECT_NE(with([](LoiterProblem& p) { p.parameters.aoi_radius = 30.0; }).find("aoi_radius"), std::string::npos);
  EXPECT_NE(with([](LoiterProblem& p) { p.aois[1] = Vec2(350.0, 300.0); }).find("aois[1]"), std::string::npos);
  EXPECT_NE(with([](LoiterProblem& p) { p.parameters.turns = 0; }).find("turns"), std::string::npos);
  EXPECT_NE(with([](LoiterProblem& p) { p.parameters.speed = 0.0; }).find("speed"), std::string::npos);
  EXPECT_NE(with([](LoiterProblem& p) { p.parameters.turn_radius = -1.0; }).find("turn_radius"), std::string::npos);
  EXPECT_NE(with([](LoiterProblem& p) { p.aois[0].y() = std::nan(""); }).find("aois[0][1]"), std::string::npos);
  EXPECT_NE(with([](LoiterProblem& p) { p.start = Vec2(310.0, 300.0); }).find("start"), std::string::npos);
  EXPECT_NE(error_message([] { from_name<LoiterMethod>("spiral"); }).find("method"), std::string::npos);
  EXPECT_NE(error_message([&] { plan_loiter_in_order(good, LoiterMethod::Tlpp, {0, 0}); }).find("order[1]"),
            std::string::npos);
  LoiterProblem close_start = good;
  close_start.aois[0] = Vec2(60.0, 0.0);
  EXPECT_NE(error_message([&] { plan_loiter(close_start, LoiterMethod::Ldlpp); }).find("start"), std::string::npos);
  LoiterCamera camera;
  camera.max_gimbal_deg = 60.0;
  EXPECT_NE(error_message([&] { camera.validate(); }).find("camera.max_gimbal_deg"), std::string::npos);
}

// ---- Footprint and the exact area ----------------------------------------------------------------

TEST(LoiterCamera, NadirFootprintIsThePapersArea) {
  const LoiterCamera camera;  // 74 deg, 61 m
  const Footprint nadir = camera_footprint(camera, {0.0, 0.0, 0.3}, 0.0);
  EXPECT_NEAR(nadir.semi_along, 61.0 * std::tan(37.0 * kPiTest / 180.0), 1e-9);
  EXPECT_NEAR(nadir.semi_across, nadir.semi_along, 1e-9);
  EXPECT_NEAR(nadir.area(), 6638.0, 0.5);  // the paper: 6,638 m^2
  // At 25 deg the section is an ellipse of 10,866 m^2. The paper's 51,223 m^2 is the area of a
  // circle whose radius is the footprint's whole near-to-far extent, h (tan 62 + tan 12 deg).
  const Footprint tilted = camera_footprint(camera, {0.0, 0.0, 0.0}, 25.0 * kPiTest / 180.0);
  EXPECT_NEAR(tilted.area(), 10866.0, 1.0);
  const double extent = 61.0 * (std::tan(62.0 * kPiTest / 180.0) + std::tan(12.0 * kPiTest / 180.0));
  EXPECT_NEAR(2.0 * tilted.semi_across, extent, 1e-9);
  EXPECT_NEAR(kPiTest * extent * extent, 51223.0, 1.0);
  // The near and far edges lie at 12 deg to the right and 62 deg to the left of the nadir.
  const double near_edge = tilted.center.y() - tilted.semi_across, far_edge = tilted.center.y() + tilted.semi_across;
  EXPECT_NEAR(near_edge, -61.0 * std::tan(12.0 * kPiTest / 180.0), 1e-9);
  EXPECT_NEAR(far_edge, 61.0 * std::tan(62.0 * kPiTest / 180.0), 1e-9);
}

TEST(LoiterCamera, FootprintBoundaryIsOnTheCone) {
  const LoiterCamera camera;
  const double beta = 37.0 * kPiTest / 180.0;
  for (const double tilt : {-0.7, -0.2, 0.0, 0.4, 0.8}) {
    const Configuration pose{10.0, -20.0, 1.1};
    const Footprint f = camera_footprint(camera, pose, tilt);
    const Vec2 left = detail::left_of(f.along);
    const Eigen::Vector3d axis(0.0, std::sin(tilt), -std::cos(tilt));  // (along, left, up)
    for (int k = 0; k < 16; ++k) {
      const double t = kTwoPi * k / 16;
      const Vec2 p = f.center + f.semi_along * std::cos(t) * f.along + f.semi_across * std::sin(t) * left;
      const Vec2 d = p - Vec2(pose.x, pose.y);
      const Eigen::Vector3d ray(d.dot(f.along), d.dot(left), -camera.altitude);
      EXPECT_NEAR(std::acos(ray.normalized().dot(axis)), beta, 1e-9);
    }
  }
}

TEST(LoiterCamera, EllipseDiskAreaClosedForms) {
  const double a = 60.0, b = 40.0;
  EXPECT_NEAR(ellipse_disk_intersection_area(a, b, 0.0, 0.0, 10.0), kPiTest * 100.0, 1e-9);  // disk inside
  EXPECT_NEAR(ellipse_disk_intersection_area(a, b, 5.0, -3.0, 200.0), kPiTest * a * b, 1e-9);  // ellipse inside
  EXPECT_EQ(ellipse_disk_intersection_area(a, b, 200.0, 0.0, 10.0), 0.0);
  EXPECT_NEAR(ellipse_disk_intersection_area(a, b, 0.0, 0.0, 1e-3 + 0.0), kPiTest * 1e-6, 1e-15);
  // Two circles (a = b): the lens area.
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 500; ++trial) {
    const double r1 = 10.0 + 90.0 * u(rng), r2 = 10.0 + 90.0 * u(rng), d = (r1 + r2) * u(rng) * 1.1;
    const double angle = kTwoPi * u(rng);
    double lens;
    if (d >= r1 + r2) lens = 0.0;
    else if (d <= std::abs(r1 - r2)) lens = kPiTest * std::min(r1, r2) * std::min(r1, r2);
    else {
      const double a1 = std::acos((d * d + r1 * r1 - r2 * r2) / (2.0 * d * r1));
      const double a2 = std::acos((d * d + r2 * r2 - r1 * r1) / (2.0 * d * r2));
      lens = r1 * r1 * (a1 - std::sin(2.0 * a1) / 2.0) + r2 * r2 * (a2 - std::sin(2.0 * a2) / 2.0);
    }
    EXPECT_NEAR(ellipse_disk_intersection_area(r1, r1, d * std::cos(angle), d * std::sin(angle), r2), lens,
                1e-8 * (1.0 + lens));
  }
}

TEST(LoiterCamera, EllipseDiskAreaAgainstMonteCarlo) {
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 40; ++trial) {
    const double a = 20.0 + 100.0 * u(rng), b = 20.0 + 100.0 * u(rng), rho = 10.0 + 60.0 * u(rng);
    const double cx = (a + rho) * (2.0 * u(rng) - 1.0), cy = (b + rho) * (2.0 * u(rng) - 1.0);
    const double exact = ellipse_disk_intersection_area(a, b, cx, cy, rho);
    // Uniform points in the disk: the fraction inside the ellipse.
    constexpr int kSamples = 200000;
    int inside = 0;
    for (int k = 0; k < kSamples; ++k) {
      const double radius = rho * std::sqrt(u(rng)), angle = kTwoPi * u(rng);
      const double x = cx + radius * std::cos(angle), y = cy + radius * std::sin(angle);
      inside += (x / a) * (x / a) + (y / b) * (y / b) <= 1.0;
    }
    const double disk = kPiTest * rho * rho, p = static_cast<double>(inside) / kSamples;
    const double sigma = disk * std::sqrt(std::max(p * (1.0 - p), 1e-6) / kSamples);
    EXPECT_NEAR(exact, disk * p, 5.0 * sigma + 1e-9) << "a " << a << " b " << b << " c " << cx << "," << cy;
  }
}

TEST(LoiterCamera, EllipseDiskAreaNearTangency) {
  // The disk touching the ellipse's vertex from inside and outside: continuous in the offset.
  const double a = 60.0, b = 40.0, rho = 20.0;
  double previous = ellipse_disk_intersection_area(a, b, a - rho - 1e-6, 0.0, rho);
  EXPECT_NEAR(previous, kPiTest * rho * rho, 1e-6);
  for (int k = 1; k <= 400; ++k) {
    const double x = a - rho + 0.2 * k;  // from internally tangent to externally tangent
    const double area = ellipse_disk_intersection_area(a, b, x, 0.0, rho);
    EXPECT_LE(area, previous + 1e-9);
    EXPECT_GE(previous - area, -1e-9);
    EXPECT_LT(previous - area, 40.0);  // no jumps
    previous = area;
  }
  EXPECT_NEAR(ellipse_disk_intersection_area(a, b, a + rho, 0.0, rho), 0.0, 1e-9);
}

// ---- Coverage ------------------------------------------------------------------------------------

TEST(LoiterCoverage, LoiterAtTheAoiRadiusKeepsItInView) {
  LoiterProblem problem;
  problem.aois = {Vec2(300.0, 300.0)};
  const LoiterPlan plan = plan_loiter(problem, LoiterMethod::Tlpp);
  const LoiterCoverage coverage = loiter_coverage(plan);
  ASSERT_EQ(coverage.time_per_aoi.size(), 1u);
  // Every step on the loiter circle sees the whole AOI region at >= 75 %.
  const LoiterSamples s = plan.sample_states(1.0, false);
  int loiter_steps = 0, covered_on_loiter = 0;
  for (std::size_t k = 0; k < s.t.size(); ++k)
    if (plan.segments[static_cast<std::size_t>(s.segment[k])].role == SegmentRole::Loiter) {
      ++loiter_steps;
      covered_on_loiter += coverage.fraction[k] >= 0.75;
      EXPECT_EQ(coverage.pointed[k], 0);
      EXPECT_LE(std::abs(coverage.gimbal[k]), 25.0 * kPiTest / 180.0 + 1e-12);
    }
  EXPECT_EQ(covered_on_loiter, loiter_steps);
  EXPECT_GE(coverage.time, loiter_steps * 1.0);
  EXPECT_LE(coverage.time, plan.flight_time + 1.0);
  EXPECT_GT(coverage.area, 0.75 * kPiTest * 46.0 * 46.0 * loiter_steps);
}

TEST(LoiterCoverage, BodyCameraLooksOutOfTheTurnLevelledOneDoesNot) {
  // Banking left (left wing down) turns the belly to the right: a camera under it, gimbal at 0,
  // looks to the right of the track by the bank. The levelled camera stays at nadir. Single
  // left-turning pose heading east, no AOI in reach (the gimbal then levels what it can).
  Points3 poses(1, 3);
  poses << 0.0, 0.0, 0.0;
  const double rate = 12.0 / 46.0, bank = bank_angle(12.0, rate);
  ASSERT_GT(bank, 0.2);
  LoiterCamera body;
  body.levelled = false;
  body.max_gimbal_deg = 0.0;
  const Footprint seen = camera_footprint(body, {0.0, 0.0, 0.0}, camera_tilt(body, bank, 0.0));
  EXPECT_LT(seen.center.y(), -body.altitude * std::tan(bank) * 0.99);  // to the right, at least h tan(bank)
  EXPECT_NEAR(camera_tilt(LoiterCamera{}, bank, 0.1), 0.1, 1e-15);
  const std::vector<Vec2> far{Vec2(5000.0, 0.0)};
  const LoiterCoverage levelled = loiter_coverage(poses, {rate}, far, 46.0, 12.0);
  EXPECT_NEAR(levelled.tilt[0], 0.0, 1e-15);
  const LoiterCoverage fixed = loiter_coverage(poses, {rate}, far, 46.0, 12.0, body);
  EXPECT_NEAR(fixed.tilt[0], -bank, 1e-15);
  body.max_gimbal_deg = 25.0;
  const LoiterCoverage gimballed = loiter_coverage(poses, {rate}, far, 46.0, 12.0, body);
  EXPECT_NEAR(gimballed.tilt[0], 0.0, 1e-15);  // the gimbal (25 deg > bank) levels it
  EXPECT_NEAR(gimballed.gimbal[0], bank, 1e-15);
}

TEST(LoiterCoverage, GimbalChoiceBeatsEveryScannedAngle) {
  // No gimbal angle covers more AOIs than the chosen one; with equally many, none holds more of
  // them in view (one AOI: more of it). Scenarios with AOIs close together, where two can count.
  const double limit = 25.0 * kPiTest / 180.0, disk = kPiTest * 46.0 * 46.0;
  for (const bool levelled : {true, false})
  for (const auto& aois : {std::vector<Vec2>{Vec2(250.0, 150.0), Vec2(500.0, 450.0)},
                           std::vector<Vec2>{Vec2(300.0, 300.0), Vec2(400.0, 300.0), Vec2(350.0, 390.0)}}) {
    LoiterProblem problem;
    problem.aois = aois;
    const LoiterPlan plan = plan_loiter(problem, LoiterMethod::Tlpp);
    LoiterCamera camera;
    camera.levelled = levelled;
    camera.altitude = 120.0;  // a footprint wide enough for two AOIs 100 m apart
    const LoiterCoverage coverage = loiter_coverage(plan, camera);
    const LoiterSamples s = plan.sample_states(1.0, false);
    const std::size_t m = aois.size();
    int doubles = 0;
    for (std::size_t k = 0; k < s.t.size(); ++k) {
      const Configuration pose{s.poses(static_cast<Eigen::Index>(k), 0), s.poses(static_cast<Eigen::Index>(k), 1),
                               s.poses(static_cast<Eigen::Index>(k), 2)};
      const auto score = [&](double gimbal, const std::vector<double>* given) {
        int count = 0;
        double seen = 0.0, most = 0.0;
        for (std::size_t i = 0; i < m; ++i) {
          const double f = given ? (*given)[i]
                                 : footprint_disk_area(camera_footprint(camera, pose, camera_tilt(camera, coverage.bank[k], gimbal)),
                                                       aois[i], 46.0) / disk;
          most = std::max(most, f);
          if (f >= 0.75) {
            ++count;
            seen += f;
          }
        }
        return std::tuple<int, double, double>{count, seen, most};
      };
      const std::vector<double> chosen(coverage.fraction.begin() + static_cast<std::ptrdiff_t>(k * m),
                                       coverage.fraction.begin() + static_cast<std::ptrdiff_t>((k + 1) * m));
      const auto [count, seen, most] = score(coverage.gimbal[k], &chosen);
      doubles += count >= 2;
      for (int j = 0; j <= 100; ++j) {
        const double g = -limit + 2.0 * limit * j / 100.0;
        const auto [other_count, other_seen, other_most] = score(g, nullptr);
        EXPECT_LE(other_count, count) << "step " << k;
        if (other_count == count && count >= 2) {
          EXPECT_LE(other_seen, seen + 1e-6) << "step " << k;
        }
        if (count <= 1 && coverage.pointed[k] >= 0) {
          EXPECT_LE(other_most, most + 1e-6) << "step " << k;
        }
      }
    }
    if (m == 3) {
      EXPECT_GT(doubles, 0);  // the close AOIs do count together somewhere
    }
  }
}

TEST(LoiterCoverage, BadInputNamesTheField) {
  Points3 poses(2, 3);
  poses << 0, 0, 0, 1, 0, 0;
  const std::vector<Vec2> aois{Vec2(100.0, 0.0)};
  EXPECT_THROW(loiter_coverage(poses, {0.0}, aois, 46.0, 12.0), Error);
  LoiterCamera body;
  body.levelled = false;
  EXPECT_THROW(loiter_coverage(poses, {0.0, 5.0}, aois, 46.0, 12.0, body), Error);  // banks past the horizon
  LoiterCoverageOptions options;
  options.threshold = 1.5;
  EXPECT_THROW(loiter_coverage(poses, {0.0, 0.0}, aois, 46.0, 12.0, LoiterCamera{}, options), Error);
}

// ---- Flying the plans (flight layer, PathFollower) ------------------------------------------------

namespace {

std::vector<PathPiece> pieces_of(const LoiterPlan& plan) {
  std::vector<PathPiece> pieces;
  for (const LoiterSegment& s : plan.segments) pieces.push_back({s.start, s.start_heading, s.length, s.curvature()});
  return pieces;
}

// Exact distance from p to the plan's lines and arcs.
double distance_to_plan(const LoiterPlan& plan, const Vec2& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const LoiterSegment& s : plan.segments) {
    best = std::min({best, (p - s.start).norm(), (p - s.end).norm()});
    if (s.kind == SegmentKind::Line) {
      const Vec2 u = (s.end - s.start) / s.length;
      const double along = (p - s.start).dot(u);
      if (along > 0.0 && along < s.length) best = std::min(best, std::abs(detail::cross(u, p - s.start)));
    } else {
      const double swept = detail::sweep_between(s.center, s.start, p, s.direction);
      if (swept <= s.sweep || s.sweep >= kTwoPi) best = std::min(best, std::abs((p - s.center).norm() - s.radius));
    }
  }
  return best;
}

}  // namespace

TEST(LoiterFlight, FollowerIsFeedForwardOnThePath) {
  LoiterProblem problem;
  problem.aois = {Vec2(300.0, 200.0), Vec2(600.0, 500.0)};
  const LoiterPlan plan = plan_loiter(problem, LoiterMethod::Tlpp);
  PathFollower follower(pieces_of(plan), 12.0, 46.0);
  follower.start(plan.at_time(0.0), 0.0);
  // On the path with the path's heading, the command is v * curvature of the piece there.
  for (const double t : {0.5, 20.0, 60.0}) {
    const Configuration q = plan.at_time(t);
    while (follower.progress() < t * 12.0 - 1.0) follower.advance(plan.at_time(follower.progress() / 12.0 + 0.5), 0.0);
    const PathFollower::Tracking tr = follower.track(q);
    EXPECT_NEAR(tr.s, t * 12.0, 1e-6);
    EXPECT_NEAR(tr.cross_track, 0.0, 1e-9);
    const double curvature = plan.segments[plan.segment_at_time(t)].curvature();
    EXPECT_NEAR(follower.command(q, t).turn_rate, 12.0 * curvature, 1e-9);
  }
}

TEST(LoiterFlight, PlansFlownWithoutWindStayOnThePath) {
  std::mt19937_64 rng(31);
  const LoiterProblem problem = random_problem(rng, 5);
  Uav vehicle;
  vehicle.speed = 12.0;
  vehicle.min_turn_radius = 46.0;
  for (const LoiterMethod method : kMethods) {
    const LoiterPlan plan = plan_loiter(problem, method);
    for (const FlightIntegration integration : {FlightIntegration::Discrete, FlightIntegration::Continuous}) {
      SCOPED_TRACE(to_string(method) + " " + to_string(integration));
      PathFollower follower(pieces_of(plan), 12.0, 46.0);
      FlightOptions options;
      options.integration = integration;
      options.dt = integration == FlightIntegration::Discrete ? 0.05 : 0.5;
      options.max_time = 2.0 * plan.flight_time;
      options.rtol = 1e-8;
      options.atol = 1e-8;
      const FlightTrajectory flown = fly(vehicle, Wind{}, follower, plan.at_time(0.0), options);
      EXPECT_TRUE(flown.finished);
      EXPECT_NEAR(flown.end_time, plan.flight_time, 1.0);
      double worst = 0.0;
      for (std::size_t k = 0; k < flown.size(); ++k)
        worst = std::max(worst, distance_to_plan(plan, Vec2(flown.x[k], flown.y[k])));
      // Continuous flight tracks to about a millimetre; the discrete update lags by up to v dt.
      EXPECT_LT(worst, integration == FlightIntegration::Discrete ? 1.0 : 0.01);
    }
  }
}

TEST(LoiterFlight, FollowerRejectsBadPaths) {
  EXPECT_NE(error_message([] { PathFollower({}, 12.0, 46.0); }).find("pieces"), std::string::npos);
  const PathPiece line{Vec2(0.0, 0.0), 0.0, 100.0, 0.0};
  EXPECT_NE(error_message([&] { PathFollower({line, {Vec2(100.0, 5.0), 0.0, 10.0, 0.0}}, 12.0, 46.0); })
                .find("pieces[1].start"),
            std::string::npos);
  EXPECT_NE(error_message([&] { PathFollower({{Vec2(0.0, 0.0), 0.0, 10.0, 1.0 / 20.0}}, 12.0, 46.0); })
                .find("pieces[0].curvature"),
            std::string::npos);
  EXPECT_NE(error_message([&] { PathFollower({line}, 12.0, 46.0, {0.0, 3.0}); }).find("lookahead_radii"),
            std::string::npos);
}
