// The flight layer's vehicle models: the roll model's step response against its closed form and
// against a fine independent integration, a coordinated turn's radius, bank and roll-rate bounds
// under the chattering law (5), the Dubins model untouched by the roll parameters, and the
// smoothness measures on bank histories whose answers are known.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "vistrack/error.hpp"
#include "vistrack/flight.hpp"
#include "flight_setup.hpp"

using namespace vistrack;

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

// L1 line tracking on one fixed line from a to b.
class OnLine : public FlightGuidance {
 public:
  OnLine(const L1Line& law, const Vec2& a, const Vec2& b) : law_(law), a_(a), b_(b) {}
  void start(const Configuration&, double) override {}
  GuidanceCommand command(const Configuration& q, double) const override { return {law_.turn_rate(q, a_, b_), b_, 0}; }
  void advance(const Configuration&, double) override {}
  bool done() const override { return false; }

 private:
  L1Line law_;
  Vec2 a_, b_;
};

// The moving mean and RMS by brute force: the oracle of bank_rms_deg.
double brute_force_rms_deg(const std::vector<double>& t, const std::vector<double>& bank, double window) {
  double squares = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    double sum = 0.0;
    int count = 0;
    for (std::size_t j = 0; j < t.size(); ++j)
      if (t[j] >= t[i] - 0.5 * window && t[j] <= t[i] + 0.5 * window) sum += bank[j], ++count;
    squares += (bank[i] - sum / count) * (bank[i] - sum / count);
  }
  return std::sqrt(squares / static_cast<double>(t.size())) / kDeg;
}

using flight_setup::options;

Uav roll_uav(double speed = 20.0, double radius = 50.0, double tau = 0.5, double rate_deg = 70.0) {
  Uav uav = flight_setup::vehicle(speed, radius, DynamicsModel::Roll);
  uav.roll_time_constant = tau;
  uav.max_roll_rate_deg_s = rate_deg;
  return uav;
}

// phi_dot = bank_rate(phi, c) by explicit midpoint steps of 1e-5 s: an oracle independent of step().
double integrate_bank(const RollModel& model, double bank, double command, double duration) {
  const int n = static_cast<int>(std::ceil(duration / 1e-5));
  const double h = duration / n;
  for (int k = 0; k < n; ++k) {
    const double mid = bank + 0.5 * h * model.bank_rate(bank, command);
    bank += h * model.bank_rate(mid, command);
  }
  return bank;
}

}  // namespace

TEST(RollModel, SmallStepIsTheFirstOrderResponse) {
  const RollModel model(roll_uav());
  const double command = 10.0 * kDeg;  // below p_max tau = 35 deg: no rate limit
  for (double t : {0.1, 0.5, 1.0, 2.5})
    EXPECT_NEAR(model.step(0.0, command, t), command * (1.0 - std::exp(-t / 0.5)), 1e-15) << t;
  // At t = tau the response has covered 1 - 1/e of the step.
  EXPECT_NEAR(model.step(0.0, command, 0.5) / command, 1.0 - std::exp(-1.0), 1e-14);
}

TEST(RollModel, LargeStepRampsAtTheRateLimitThenApproaches) {
  const RollModel model(roll_uav());
  const double command = model.max_bank();  // 39.2 deg at 20 m/s, 50 m: past p_max tau = 35 deg
  ASSERT_GT(command, 0.5 * 70.0 * kDeg);
  const double ramp = (command - 0.5 * 70.0 * kDeg) / (70.0 * kDeg);
  EXPECT_NEAR(model.step(0.0, command, 0.5 * ramp), 0.5 * ramp * 70.0 * kDeg, 1e-15);
  for (double t : {0.5 * ramp, ramp, ramp + 0.1, 0.7, 1.5, 3.0}) {
    const double closed = model.step(0.0, command, t);
    EXPECT_NEAR(closed, integrate_bank(model, 0.0, command, t), 1e-9) << t;
    // Composition: two half steps are one step (the closed form is exact).
    EXPECT_NEAR(model.step(model.step(0.0, command, 0.5 * t), command, 0.5 * t), closed, 1e-14) << t;
  }
  // Both directions alike.
  EXPECT_NEAR(model.step(0.0, -command, 0.7), -model.step(0.0, command, 0.7), 1e-15);
}

TEST(RollModel, CommandIsTheCoordinatedBankWithinTheVehiclesLimit) {
  const Uav uav = roll_uav(20.0, 50.0);
  const RollModel model(uav);
  EXPECT_NEAR(model.max_bank(), std::atan(400.0 / (kStandardGravity * 50.0)), 1e-15);
  EXPECT_NEAR(model.bank_command(0.1), std::atan(20.0 * 0.1 / kStandardGravity), 1e-15);
  EXPECT_DOUBLE_EQ(model.bank_command(10.0), model.max_bank());
  // The bank of the largest turn rate v / R turns at exactly v / R.
  EXPECT_NEAR(model.turn_rate(model.bank_command(20.0 / 50.0)), 20.0 / 50.0, 1e-15);
  EXPECT_NEAR(coordinated_bank(20.0, 0.1), std::atan(2.0 / kStandardGravity), 1e-15);
}

TEST(RollModel, CoordinatedTurnHasRadiusVSquaredOverGTanPhi) {
  // Ask for the turn rate of a 30-degree bank; after the transient the circle's radius is
  // v^2 / (g tan 30 deg) = 70.65 m, in both integrators.
  const double v = 20.0, phi = 30.0 * kDeg;
  const double radius = v * v / (kStandardGravity * std::tan(phi));
  for (auto integration : {FlightIntegration::Discrete, FlightIntegration::Continuous}) {
    TurnRateHold guidance(kStandardGravity * std::tan(phi) / v);
    const auto traj = fly(roll_uav(v, 50.0), Wind{}, guidance, {0, 0, 0}, options(integration, 0.01, 60.0));
    // The circle's centre from three far-apart samples after the transient; every later sample on it.
    const std::size_t n = traj.size();
    const Vec2 a(traj.x[n / 2], traj.y[n / 2]), b(traj.x[2 * n / 3], traj.y[2 * n / 3]), c(traj.x[n - 1], traj.y[n - 1]);
    const double d = 2.0 * (a.x() * (b.y() - c.y()) + b.x() * (c.y() - a.y()) + c.x() * (a.y() - b.y()));
    const Vec2 centre((a.squaredNorm() * (b.y() - c.y()) + b.squaredNorm() * (c.y() - a.y()) +
                       c.squaredNorm() * (a.y() - b.y())) / d,
                      (a.squaredNorm() * (c.x() - b.x()) + b.squaredNorm() * (a.x() - c.x()) +
                       c.squaredNorm() * (b.x() - a.x())) / d);
    const double tolerance = integration == FlightIntegration::Discrete ? 2e-3 : 1e-6;
    for (std::size_t i = n / 2; i < n; i += 50)
      EXPECT_NEAR((Vec2(traj.x[i], traj.y[i]) - centre).norm(), radius, tolerance * radius) << to_string(integration);
    EXPECT_NEAR(traj.bank[n - 1], phi, 1e-9);
  }
}

TEST(RollModel, BankAndRollRateStayWithinTheLimitsUnderTheChatteringLaw5) {
  // The law (5) saturates and flips its command every few steps; the roll model filters it.
  const std::vector<Vec2> route{{400, 0}, {400, 400}, {0, 400}, {0, 0}};
  const Uav uav = roll_uav(20.0, 50.0);
  const RollModel model(uav);
  const LineFeedback law(20.0, 50.0, 0.02);
  WaypointFollower wn(law, route, 50.0);
  const auto traj = fly(uav, Wind{3.0, -2.0, std::nullopt}, wn, {0, 0, 0}, options(FlightIntegration::Discrete, 0.02, 400.0));
  ASSERT_TRUE(traj.finished);
  for (std::size_t i = 0; i < traj.size(); ++i) {
    ASSERT_LE(std::abs(traj.bank[i]), model.max_bank() * (1.0 + 1e-12)) << i;
    if (i > 0) {
      ASSERT_LE(std::abs(traj.bank[i] - traj.bank[i - 1]), 70.0 * kDeg * 0.02 * (1.0 + 1e-9)) << i;
    }
  }
  const FlightSmoothness roll = flight_smoothness(traj.t, traj.bank);
  EXPECT_LE(roll.max_roll_rate_deg_s, 70.0 * (1.0 + 1e-9));
  // The same route on the Dubins vehicle: the bank jumps (that is what the roll model removes).
  Uav dubins = uav;
  dubins.dynamics = DynamicsModel::Dubins;
  WaypointFollower wn_dubins(law, route, 50.0);
  const auto instant = fly(dubins, Wind{3.0, -2.0, std::nullopt}, wn_dubins, {0, 0, 0},
                           options(FlightIntegration::Discrete, 0.02, 400.0));
  const FlightSmoothness jumpy = flight_smoothness(instant.t, instant.bank);
  EXPECT_GT(jumpy.max_roll_rate_deg_s, 10.0 * roll.max_roll_rate_deg_s);
  EXPECT_GT(jumpy.roll_reversals_per_s, roll.roll_reversals_per_s);
}

TEST(RollModel, ContinuousAndDiscreteAgreeOnASmoothGuidance) {
  const std::vector<Vec2> route{{400, 0}, {400, 400}};
  const Uav uav = roll_uav(20.0, 50.0);
  std::vector<FlightTrajectory> flights;
  for (auto integration : {FlightIntegration::Discrete, FlightIntegration::Continuous}) {
    const LineFeedback law(20.0, 50.0, 0.02, {}, /*smooth_sign=*/true);
    WaypointFollower wn(law, route, 50.0);
    flights.push_back(fly(uav, Wind{}, wn, {0, 0, 0}, options(integration, 0.002, 60.0)));
  }
  // Same sample times up to the end; positions within a few metres after 40 s of flight.
  const std::size_t n = std::min(flights[0].size(), flights[1].size());
  for (std::size_t i = 0; i < n; i += 1000) {
    EXPECT_NEAR(flights[0].x[i], flights[1].x[i], 1.0) << flights[0].t[i];
    EXPECT_NEAR(flights[0].y[i], flights[1].y[i], 1.0) << flights[0].t[i];
    EXPECT_NEAR(flights[0].bank[i], flights[1].bank[i], 1.0 * kDeg) << flights[0].t[i];
  }
}

TEST(RollModel, DubinsFlightIgnoresTheRollParametersAndBanksAtOnce) {
  Uav a;
  Uav b;
  b.roll_time_constant = 3.0;
  b.max_roll_rate_deg_s = 5.0;
  TurnRateHold ga(0.3), gb(0.3);
  const auto ta = fly(a, Wind{}, ga, {0, 0, 0}, options(FlightIntegration::Discrete, 0.02, 10.0));
  const auto tb = fly(b, Wind{}, gb, {0, 0, 0}, options(FlightIntegration::Discrete, 0.02, 10.0));
  EXPECT_EQ(ta.x, tb.x);
  EXPECT_EQ(ta.psi, tb.psi);
  EXPECT_DOUBLE_EQ(ta.bank.front(), coordinated_bank(a.speed, 0.3));
}

TEST(RollModel, BadParametersNameTheField) {
  for (auto [field, tau, rate] : {std::tuple{"uav.roll_time_constant", 0.0, 70.0},
                                  std::tuple{"uav.roll_time_constant", std::nan(""), 70.0},
                                  std::tuple{"uav.max_roll_rate_deg_s", 0.5, -1.0},
                                  std::tuple{"uav.max_roll_rate_deg_s", 0.5, 1e300}}) {
    try {
      (void)RollModel(roll_uav(20.0, 50.0, tau, rate));
      ADD_FAILURE() << field;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  }
}

TEST(FlightSmoothnessMeasures, SineBankHasTwoReversalsPerPeriodAndItsRms) {
  std::vector<double> t, bank;
  const double amplitude = 10.0 * kDeg, frequency = 0.5;  // 2 s period
  for (int k = 0; k <= 6000; ++k) {
    t.push_back(k * 0.01);
    bank.push_back(amplitude * std::sin(2.0 * 3.14159265358979323846 * frequency * t.back()));
  }
  const FlightSmoothness s = flight_smoothness(t, bank);
  // Rising from 0, then turning at every extremum: 0.5, 1.5, ..., 59.5 s.
  EXPECT_EQ(s.roll_reversals, 60u);
  EXPECT_NEAR(s.roll_reversals_per_s, 1.0, 1e-12);
  EXPECT_NEAR(s.bank_rms_deg, brute_force_rms_deg(t, bank, 5.0), 1e-9);
  // Far from the ends the 5 s mean of a 2 s period holds half a period: the RMS lies below A / sqrt(2).
  EXPECT_LT(s.bank_rms_deg, 10.0 / std::sqrt(2.0));
  EXPECT_GT(s.bank_rms_deg, 5.0);
  EXPECT_NEAR(s.max_roll_rate_deg_s, 10.0 * 2.0 * 3.14159265358979323846 * frequency, 0.01);
}

TEST(FlightSmoothnessMeasures, DeadbandIgnoresNoiseAndASteadyTurnIsSmooth) {
  std::vector<double> t, bank;
  for (int k = 0; k <= 1000; ++k) {
    t.push_back(k * 0.02);
    bank.push_back(20.0 * kDeg + ((k % 2) ? 0.4 : -0.4) * kDeg);  // 0.8 deg of chatter: below 1 deg
  }
  FlightSmoothness s = flight_smoothness(t, bank);
  EXPECT_EQ(s.roll_reversals, 0u);
  EXPECT_NEAR(s.bank_rms_deg, brute_force_rms_deg(t, bank, 5.0), 1e-9);
  EXPECT_NEAR(s.bank_rms_deg, 0.4, 2e-3);
  EXPECT_NEAR(s.max_roll_rate_deg_s, 0.8 / 0.02, 1e-9);
  // With a deadband below the chatter every flip counts.
  s = flight_smoothness(t, bank, 5.0, 0.5);
  EXPECT_EQ(s.roll_reversals, 999u);
  // A constant bank: nothing at all.
  std::vector<double> steady(t.size(), 20.0 * kDeg);
  s = flight_smoothness(t, steady);
  EXPECT_EQ(s.roll_reversals, 0u);
  EXPECT_NEAR(s.bank_rms_deg, 0.0, 1e-9);
  EXPECT_EQ(s.max_roll_rate_deg_s, 0.0);
}

TEST(FlightSmoothnessMeasures, BadInputNamesTheField) {
  const auto names = [](const std::function<void()>& call, const std::string& field) {
    try {
      call();
      ADD_FAILURE() << field;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  names([] { (void)flight_smoothness({0, 1}, {0}); }, "bank");
  names([] { (void)flight_smoothness({0}, {0}); }, "t");
  names([] { (void)flight_smoothness({0, 1, 0.5}, {0, 0, 0}); }, "t[2]");
  names([] { (void)flight_smoothness({0, 1}, {0, std::nan("")}); }, "bank[1]");
  names([] { (void)flight_smoothness({0, 1}, {0, 0}, 0.0); }, "window");
  names([] { (void)flight_smoothness({0, 1}, {0, 0}, 5.0, -1.0); }, "deadband_deg");
}

TEST(L1LineTracking, ByHandOnAnEastwardLine) {
  const L1Line l1(20.0);  // ArduPlane's 17 s, 0.75: L1 = 0.75 * 17 * 20 / pi = 81.17 m
  EXPECT_NEAR(l1.distance(), 0.75 * 17.0 * 20.0 / 3.14159265358979323846, 1e-12);
  const Vec2 a(0, 0), b(1000, 0);
  // On the line, along it: no turn.
  EXPECT_EQ(l1.turn_rate({100, 0, 0}, a, b), 0.0);
  // 20 m right of it (south), heading east: Nu1 = asin(20 / L1), turn left at 4 z^2 v / L1 sin(Nu1).
  const double nu1 = std::asin(20.0 / l1.distance());
  EXPECT_NEAR(l1.turn_rate({100, -20, 0}, a, b), 4.0 * 0.5625 * 20.0 / l1.distance() * std::sin(nu1), 1e-14);
  // Left of it: the mirror image.
  EXPECT_NEAR(l1.turn_rate({100, 20, 0}, a, b), -l1.turn_rate({100, -20, 0}, a, b), 1e-15);
  // Far off: the capture angle is capped at 45 degrees; heading along the line, eta = 45 deg.
  EXPECT_NEAR(l1.turn_rate({100, -500, 0}, a, b), 4.0 * 0.5625 * 20.0 / l1.distance() * std::sqrt(0.5), 1e-4);
  // Far behind the start: fly to the start (here straight ahead: no turn).
  EXPECT_NEAR(l1.turn_rate({-500, 0, 0}, a, b), 0.0, 1e-15);
  // Heading away from the line's direction: |eta| capped at pi/2, the largest turn.
  EXPECT_NEAR(std::abs(l1.turn_rate({100, 0, kPi}, a, b)), 4.0 * 0.5625 * 20.0 / l1.distance(), 1e-12);
}

TEST(L1LineTracking, CapturesALineWithoutChatterOnTheRollModel) {
  const Uav uav = roll_uav(20.0, 50.0);
  OnLine follower(L1Line(20.0), {0, 0}, {5000, 0});
  const auto traj = fly(uav, Wind{}, follower, {0, -150, 0}, options(FlightIntegration::Discrete, 0.02, 90.0));
  // Settled on the line after a minute, smoothly.
  std::size_t late = 0;
  for (std::size_t i = 0; i < traj.size(); ++i)
    if (traj.t[i] > 60.0) {
      EXPECT_LT(std::abs(traj.y[i]), 1.0) << traj.t[i];
      ++late;
    }
  EXPECT_GT(late, 100u);
  const FlightSmoothness s = flight_smoothness(traj.t, traj.bank);
  EXPECT_LE(s.roll_reversals_per_s, 0.1);
  EXPECT_LE(s.max_roll_rate_deg_s, 70.0 * (1.0 + 1e-9));
  // The same in continuous flight: the law is continuous, no sliding mode.
  OnLine again(L1Line(20.0), {0, 0}, {5000, 0});
  const auto smooth = fly(uav, Wind{}, again, {0, -150, 0}, options(FlightIntegration::Continuous, 0.02, 90.0));
  EXPECT_NEAR(smooth.y.back(), traj.y.back(), 0.5);
}

TEST(CurveL1Guidance, ReferencePointByHand) {
  CurveL1 l1(20.0, {{0, 0}, {100, 0}, {100, 100}}, L1Gains{8.0, 0.75});  // L1 = 0.75 * 8 * 20 / pi
  const double L = l1.distance();
  EXPECT_NEAR(L, 120.0 / kPi, 1e-12);
  // On the first leg, 10 m south of it at x = 50: the circle leaves the path on the first leg at
  // x = 50 + sqrt(L^2 - 100).
  const Vec2 ref = l1.reference_point({50, -10});
  EXPECT_NEAR(ref.y(), 0.0, 1e-12);
  EXPECT_NEAR(ref.x(), 50.0 + std::sqrt(L * L - 100.0), 1e-9);
  // Near the corner the reference point lies on the second leg, L1 from the vehicle.
  const Vec2 corner = l1.reference_point({90, 0});
  EXPECT_NEAR(corner.x(), 100.0, 1e-12);
  EXPECT_NEAR((corner - Vec2(90, 0)).norm(), L, 1e-9);
  // Past the end: along the last direction.
  const Vec2 beyond = l1.reference_point({100, 95});
  EXPECT_NEAR(beyond.x(), 100.0, 1e-12);
  EXPECT_NEAR(beyond.y(), 95.0 + L, 1e-9);
  // Farther than L1 from the path: its closest point.
  const Vec2 far = l1.reference_point({50, -500});
  EXPECT_NEAR(far.x(), 50.0, 1e-12);
  EXPECT_NEAR(far.y(), 0.0, 1e-12);
  // One point: fly to it.
  l1.set_path({{7, 8}, {7, 8}});
  EXPECT_EQ(l1.reference_point({0, 0}), Vec2(7, 8));
  EXPECT_THROW(l1.set_path({}), Error);
}

TEST(CurveL1Guidance, FliesACircleOnTheRollModelSmoothly) {
  // A 150 m circle as a polyline of 1-degree chords; the roll model at 20 m/s (steady bank 15 deg).
  std::vector<Vec2> circle;
  for (int k = 0; k <= 720; ++k) circle.emplace_back(150.0 * std::cos(k * kDeg), 150.0 * std::sin(k * kDeg));
  CurveL1 l1(20.0, circle, L1Gains{8.0, 0.75});
  const auto traj = fly(roll_uav(20.0, 50.0), Wind{}, l1, {150, 0, kPi / 2}, options(FlightIntegration::Discrete, 0.02, 90.0));
  double worst = 0.0;
  for (std::size_t i = 0; i < traj.size(); ++i)
    if (traj.t[i] > 20.0) worst = std::max(worst, std::abs(std::hypot(traj.x[i], traj.y[i]) - 150.0));
  // L1 guidance holds a circle with a small steady offset (Park et al.: inside by about L1^2 / (2 R)).
  EXPECT_LT(worst, 0.1 * 150.0);
  // The roll-in from level settles within a few swings; then the bank holds.
  const FlightSmoothness s = flight_smoothness(traj.t, traj.bank);
  EXPECT_LT(s.roll_reversals_per_s, 0.1);
  EXPECT_LE(s.max_roll_rate_deg_s, 70.0 * (1.0 + 1e-9));
}
