// The receding-horizon city follower's programme (follow.hpp, The horizon city follower) and the
// guidance that flies it (TurnRateHold): a second's flight against the flight layer's own discrete flight, the
// one-second value against camera_sees and an analytic tower shadow, an open field where every
// second is seen, a lost vehicle steered for, and bad input named.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "error_message.hpp"
#include "flight_setup.hpp"
#include "vistrack/environment.hpp"
#include "vistrack/error.hpp"
#include "vistrack/flight.hpp"
#include "vistrack/follow.hpp"

using namespace vistrack;
using vistrack::testing::error_message;

namespace {

// The call throws an Error whose message starts with the field's name.
template <class Call>
void expect_error_naming(Call&& call, const std::string& field) {
  const std::string message = error_message(std::forward<Call>(call));
  EXPECT_EQ(message.rfind(field + " = ", 0), 0u) << message;
}

constexpr double kDeg = 3.14159265358979323846 / 180.0;

Ring rectangle(double x0, double y0, double x1, double y1) {
  return {Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)};
}

// A tower 100-140 m east of the origin, 40 m wide, 200 m tall; and one far away (an open field).
Environment tower() { return Environment::from_buildings({{{rectangle(100, -20, 140, 20), {}}, 200.0, 1}}); }
Environment open_field() { return Environment::from_buildings({{{rectangle(9000, 9000, 9010, 9010), {}}, 5.0, 1}}); }

Uav roll_uav() {
  Uav uav = flight_setup::vehicle(20.0, 50.0, DynamicsModel::Roll);
  uav.altitude = 300.0;
  return uav;
}

std::vector<Vec2> parked(int horizon, const Vec2& at = Vec2::Zero()) {
  return std::vector<Vec2>(static_cast<std::size_t>(horizon) + 1, at);
}

HorizonOptions small(int horizon) {
  HorizonOptions o;
  o.horizon = horizon;
  o.spacing = 40.0;
  o.half_width = 400.0;
  o.heading_step_deg = 30.0;
  return o;
}

}  // namespace

TEST(TurnRateHold, FliesTheCoordinatedCircleOfItsRate) {
  // Dubins: radius v / rate at once; roll model: the bank settles at atan(v rate / g).
  const double rate = 0.2;
  TurnRateHold hold(rate);
  const auto dubins = fly(flight_setup::vehicle(20.0, 50.0), Wind{}, hold, {0, 0, 0},
                          flight_setup::options(FlightIntegration::Discrete, 0.01, 20.0));
  // Discrete flight turns before each step: the samples are the vertices of a regular polygon of
  // side v dt turning by rate dt, on the circle of radius v dt / (2 sin(rate dt / 2)) through the start.
  const double half_turn = 0.5 * rate * 0.01, radius = 20.0 * 0.01 / (2.0 * std::sin(half_turn));
  const Vec2 centre(-radius * std::sin(half_turn), radius * std::cos(half_turn));
  for (std::size_t i = 0; i < dubins.size(); i += 100)
    EXPECT_NEAR((Vec2(dubins.x[i], dubins.y[i]) - centre).norm(), radius, 1e-6) << i;
  EXPECT_NEAR(radius, 100.0, 1e-4);
  TurnRateHold roll(rate);
  const auto banked = fly(roll_uav(), Wind{}, roll, {0, 0, 0}, flight_setup::options(FlightIntegration::Discrete, 0.02, 20.0));
  EXPECT_NEAR(banked.bank.back(), std::atan(20.0 * rate / kStandardGravity), 1e-9);
  roll.set_turn_rate(-0.1);
  EXPECT_EQ(roll.turn_rate(), -0.1);
  EXPECT_EQ(roll.command({1, 2, 3}, 0.0).turn_rate, -0.1);
  expect_error_naming([] { TurnRateHold bad(std::nan("")); }, "turn_rate");
}

TEST(HorizonPlanner, ASecondIsTheFlightLayersSecond) {
  // Two implementations: fly_second against fly() with the command held, in wind, from a bank.
  const VisibilityScene scene(open_field());
  const Uav uav = roll_uav();
  const HorizonPlanner planner(scene, uav, DownwardCamera{}, 300.0, small(2));
  const Vec2 wind(3.0, -2.0);
  for (double command : planner.banks()) {
    TurnRateHold hold(RollModel(uav).turn_rate(command));
    // fly() starts level; the planner from level too, heading 0.7 rad at (10, 20).
    const auto flown = fly(uav, Wind{wind.x(), wind.y(), std::nullopt}, hold, {10, 20, 0.7},
                           flight_setup::options(FlightIntegration::Discrete, 0.02, 1.0));
    const HorizonSecond s = planner.fly_second(Vec2(10, 20), 0.7, 0.0, command, wind);
    EXPECT_NEAR(s.position.x(), flown.x.back(), 1e-9);
    EXPECT_NEAR(s.position.y(), flown.y.back(), 1e-9);
    EXPECT_NEAR(s.heading, flown.psi.back(), 1e-12);
    EXPECT_NEAR(s.bank, flown.bank.back(), 1e-12);
  }
}

TEST(HorizonPlanner, OneSecondValueIsTheCameraAndTheTowersShadow) {
  // Horizon 1: V_1 is the reward itself, camera_sees at each grid point times the line of sight.
  const VisibilityScene scene(tower());
  const Uav uav = roll_uav();
  const DownwardCamera camera{74.0 * kDeg, 25.0 * kDeg, CameraMount::PanTilt};
  const HorizonPlanner planner(scene, uav, camera, 300.0, small(1));
  const std::vector<float> values = planner.first_values(parked(1), Vec2::Zero());
  const std::size_t n = planner.grid_side(), cells = n * n, headings = planner.heading_count();
  ASSERT_EQ(values.size(), planner.banks().size() * headings * cells);
  const auto cell = [&](double x, double y) {
    return static_cast<std::size_t>(std::lround((x + 400.0) / 40.0)) * n +
           static_cast<std::size_t>(std::lround((y + 400.0) / 40.0));
  };
  const std::size_t level = 2;  // level flight
  const std::size_t heading = 3;  // 90 degrees: north
  // The camera: seen at nadir and 160 m off (within 300 tan(62 deg) = 564 m); not 400 m off diagonally.
  EXPECT_EQ(values[(level * headings + heading) * cells + cell(0, 0)], 1.0f);
  EXPECT_EQ(values[(level * headings + heading) * cells + cell(-160, 0)], 1.0f);
  EXPECT_EQ(values[(level * headings + heading) * cells + cell(-400, -400)], 0.0f);  // 566 m: outside
  // The tower's shadow: from (400, 0, 300) the ray to the vehicle crosses x = 140 at z = 105 < 200;
  // from (-400, 0, 300) nothing is in the way; from (400, 200, 300) the ray passes y = 70 at x = 140.
  for (std::size_t b = 0; b < planner.banks().size(); ++b)
    for (std::size_t h = 0; h < headings; ++h) EXPECT_EQ(values[(b * headings + h) * cells + cell(400, 0)], 0.0f);
  EXPECT_EQ(values[(level * headings + heading) * cells + cell(-320, 0)], 1.0f);
  EXPECT_EQ(values[(level * headings + heading) * cells + cell(320, 200)], 1.0f);
  // Every entry agrees with camera_sees (and the line of sight is clear away from the tower's side).
  for (std::size_t b = 0; b < planner.banks().size(); ++b)
    for (std::size_t h = 0; h < headings; ++h)
      for (std::size_t m = 0; m < cells; ++m) {
        const double x = -400.0 + 40.0 * static_cast<double>(m / n), y = -400.0 + 40.0 * static_cast<double>(m % n);
        if (x < 100.0) {
          const bool sees = camera_sees(camera, Vec3(x, y, 300.0), static_cast<double>(h) * 30.0 * kDeg,
                                        planner.banks()[b], Vec3::Zero());
          ASSERT_EQ(values[(b * headings + h) * cells + m], sees ? 1.0f : 0.0f) << b << " " << h << " " << m;
        }
      }
}

TEST(HorizonPlanner, InAnOpenFieldWithAWideCameraEverySecondIsSeen) {
  // A pan-tilt camera reaching 89 degrees off the down axis sees the vehicle from the whole grid, so
  // every state whose seconds stay on the grid expects the whole horizon, and the choice does.
  const VisibilityScene scene(open_field());
  const DownwardCamera wide{90.0 * kDeg, 44.0 * kDeg, CameraMount::PanTilt};
  const int horizon = 6;
  const HorizonPlanner planner(scene, roll_uav(), wide, 300.0, small(horizon));
  std::vector<Vec2> driving;
  for (int k = 0; k <= horizon; ++k) driving.emplace_back(5.0 * k, 0.0);
  const std::vector<float> values = planner.first_values(driving, Vec2::Zero());
  const std::size_t n = planner.grid_side(), centre = (n / 2) * n + n / 2;
  for (std::size_t b = 0; b < planner.banks().size(); ++b)
    for (std::size_t h = 0; h < planner.heading_count(); ++h)
      EXPECT_NEAR(values[(b * planner.heading_count() + h) * n * n + centre], horizon, 1e-5);
  const HorizonChoice choice = planner.choose(driving, Vec2::Zero(), Vec2(-50, 0), 0.0, 0.0);
  EXPECT_NEAR(choice.value, horizon, 1e-5);
  EXPECT_FALSE(choice.heading_for_vehicle);
}

TEST(HorizonPlanner, ALostVehicleIsSteeredFor) {
  // The vehicle 3 km east, the UAV heading north: nothing in reach, so the command turns right
  // (negative bank) at full bank; west of it, left.
  const VisibilityScene scene(open_field());
  const HorizonPlanner planner(scene, roll_uav(), DownwardCamera{}, 300.0, small(3));
  const HorizonChoice east = planner.choose(parked(3, Vec2(3000, 0)), Vec2::Zero(), Vec2::Zero(), kPi / 2, 0.0);
  EXPECT_TRUE(east.heading_for_vehicle);
  EXPECT_EQ(east.bank_command, planner.banks().front());
  EXPECT_EQ(east.value, 0.0);
  const HorizonChoice west = planner.choose(parked(3, Vec2(-3000, 0)), Vec2::Zero(), Vec2::Zero(), kPi / 2, 0.0);
  EXPECT_EQ(west.bank_command, planner.banks().back());
  EXPECT_NEAR(west.turn_rate, 20.0 / 50.0, 1e-12);  // the full bank turns at v / r_min
}

TEST(HorizonPlanner, BadInputIsNamed) {
  const VisibilityScene scene(open_field());
  const HorizonPlanner planner(scene, roll_uav(), DownwardCamera{}, 300.0, small(3));
  expect_error_naming([&] { planner.choose(parked(2), Vec2::Zero(), Vec2::Zero(), 0.0, 0.0); }, "vehicle");
  expect_error_naming([&] { planner.choose(parked(3), Vec2::Zero(), Vec2::Zero(), std::nan(""), 0.0); }, "heading");
  auto lost = parked(3);
  lost[2].x() = std::nan("");
  expect_error_naming([&] { planner.choose(lost, Vec2::Zero(), Vec2::Zero(), 0.0, 0.0); }, "vehicle[2].x");
  expect_error_naming([&] { planner.choose(parked(3), Vec2(INFINITY, 0), Vec2::Zero(), 0.0, 0.0); }, "wind.east");
  HorizonOptions bad = small(3);
  bad.heading_step_deg = 7.0;
  expect_error_naming([&] { HorizonPlanner(scene, roll_uav(), DownwardCamera{}, 300.0, bad); }, "heading_step_deg");
  bad = small(0);
  expect_error_naming([&] { HorizonPlanner(scene, roll_uav(), DownwardCamera{}, 300.0, bad); }, "horizon");
  bad = small(3);
  bad.dt = 0.3;
  expect_error_naming([&] { HorizonPlanner(scene, roll_uav(), DownwardCamera{}, 300.0, bad); }, "dt");
  bad = small(3);
  bad.spacing = 1.0;
  expect_error_naming([&] { HorizonPlanner(scene, roll_uav(), DownwardCamera{}, 300.0, bad); }, "half_width");
}
