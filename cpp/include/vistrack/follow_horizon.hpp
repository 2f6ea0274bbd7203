// Following over a city by receding-horizon dynamic programming (beyond every anchor: none of the
// papers follows through buildings; docs/following.md, "The horizon follower").
//
// Each second the follower predicts the vehicle over the next H seconds (the caller's prediction:
// positions at 0, 1, ..., H s) and plans the UAV's bank commands over them by backward induction:
//  * the UAV: airspeed v and the flight layer's vehicle model (Uav::dynamics: the roll model's
//    first-order, rate-limited bank, or the Dubins vehicle's bank at once), commanding one of five
//    banks held for a second: 0, +-phi_max / 2, +-phi_max, phi_max = atan(v^2 / (g r_min));
//  * its state: the position relative to the vehicle on a square grid (spacing, +-half_width), the
//    heading on a grid of heading_step_deg, the bank at the five levels (the level nearest the bank
//    a second's command ends at);
//  * a second's reward R_j: 1 where a ray from the grid point at the flight altitude reaches the
//    vehicle's predicted position at j s (vehicle_height above the surface under it) and the camera
//    sees it at that heading and bank (camera_sees), else 0;
//  * V_H = R_H, V_j = R_j + max over commands of V_{j+1} at the command's next state, read by linear
//    interpolation in heading and position (0 off the grid), planned in the air mass: the next
//    position relative to the vehicle is the command's second (from heading 0, still air) rotated to
//    the heading, plus the known wind's way, minus the vehicle's predicted way over that second.
// The choice: the command whose one-second flight from the UAV's actual state (exact, off the grid)
// ends where V_1 (read linearly between the bank levels too) is greatest; when V_1 is 0 at every
// command's end (the vehicle out of the grid's reach, or in sight nowhere over the horizon), the
// command that ends heading most nearly for the vehicle's position a second ahead.
// A second's flight is integrated as the flight layer's discrete update does (step dt: the bank
// first, by RollModel::step, then the heading at its turn rate, then the position).
#pragma once

#include <cstddef>
#include <vector>

#include "vistrack/dubins_parameters.hpp"
#include "vistrack/follow.hpp"
#include "vistrack/geometry.hpp"
#include "vistrack/vehicle.hpp"
#include "vistrack/visibility.hpp"

namespace vistrack {

struct HorizonOptions {
  int horizon = 24;                 // s of prediction, whole seconds (one command per second)
  double spacing = 20.0;            // m, the relative-position grid's step
  double half_width = 400.0;        // m: the grid spans +-half_width about the vehicle, east and north
  double heading_step_deg = 10.0;   // the heading grid's step (must divide 360)
  double vehicle_height = 0.5;      // m above the surface under the vehicle: where the rays end
  double dt = 0.02;                 // s, the integration step within a second (the flight layer's)
  void validate() const;
};

// One second flown with a bank command held.
struct HorizonSecond {
  Vec2 position = Vec2::Zero();
  double heading = 0.0;
  double bank = 0.0;
};

struct HorizonChoice {
  double bank_command = 0.0;        // rad, positive left wing down (a left turn)
  double turn_rate = 0.0;           // rad/s, g tan(bank_command) / v: what the guidance commands
  double value = 0.0;               // the seconds in sight the programme expects over the horizon
  bool heading_for_vehicle = false; // nothing in sight from any command's end: steering for the vehicle
  HorizonSecond next;               // the UAV a second later as the planner predicts it (known wind)
};

class HorizonPlanner {
 public:
  // flight_altitude: world z of the flight (ground level + uav.altitude). Error naming the field for
  // a bad option, UAV or camera.
  HorizonPlanner(const VisibilityScene& scene, const Uav& uav, const DownwardCamera& camera, double flight_altitude,
                 const HorizonOptions& options = {});

  // The best command now. vehicle: its predicted positions at 0, 1, ..., horizon s (horizon + 1
  // points); wind: the wind the follower knows (m/s); the UAV's position, heading and bank now.
  HorizonChoice choose(const std::vector<Vec2>& vehicle, const Vec2& wind, const Vec2& position, double heading,
                       double bank) const;
  // V_1 of the programme (bank level, heading index, grid point i * n + j; i east, j north), flat.
  std::vector<float> first_values(const std::vector<Vec2>& vehicle, const Vec2& wind) const;
  // The UAV's second with `bank_command` held from the given state in `wind`.
  HorizonSecond fly_second(const Vec2& position, double heading, double bank, double bank_command,
                           const Vec2& wind) const;
  // V_1 (first_values) at a continuous state: bank and heading linear, position bilinear, 0 off the grid.
  double value_at(const std::vector<float>& values, const Vec2& relative, double heading, double bank) const;

  const std::vector<double>& banks() const { return banks_; }   // the five bank levels, rad
  std::size_t grid_side() const { return side_; }                // n: grid points per axis
  std::size_t heading_count() const { return headings_; }
  const HorizonOptions& options() const { return options_; }
  const Uav& uav() const { return uav_; }

 private:
  struct Move {  // a second from heading 0 in still air: displacement, turn, bank level after
    Vec2 shift = Vec2::Zero();
    double turn = 0.0;
    std::size_t level_after = 0;
  };
  std::vector<float> rewards(const Vec2& vehicle) const;
  void add_best_next(std::vector<float>& now, const std::vector<float>& later, const Vec2& drift) const;

  VisibilityScene scene_;
  Uav uav_;
  DownwardCamera camera_;
  double altitude_;
  HorizonOptions options_;
  RollModel roll_;
  std::vector<double> banks_;
  std::size_t side_ = 0, headings_ = 0;
  std::vector<unsigned char> camera_table_;  // (bank level, heading, grid point): the camera sees the vehicle
  std::vector<Move> moves_;                  // (level before, command level)
};

}  // namespace vistrack
