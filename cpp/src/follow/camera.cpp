// The downward camera of the follow metric: a cone (the field of view) about the body's down
// axis, tilted by the bank of a coordinated turn, rolled towards the target by a limited gimbal.
#include <algorithm>
#include <cmath>

#include "vistrack/error.hpp"
#include "vistrack/follow.hpp"

namespace vistrack {

bool camera_sees(const DownwardCamera& camera, const Vec3& uav, double psi, double bank, const Vec3& target) {
  const Vec3 left(-std::sin(psi), std::cos(psi), 0.0);
  const Vec3 up(0.0, 0.0, 1.0);
  const Vec3 r = target - uav;
  const double distance = r.norm();
  if (!(distance > 0.0)) return true;
  // The gimbal rolls the camera back by gamma (positive: towards the left) to put the target's
  // lateral angle beta (from the level nadir, positive left) on the axis: gamma = bank + beta,
  // within its range. A body banked left by phi looks right by phi.
  const double beta = std::atan2(r.dot(left), -r.dot(up));
  const double gamma = std::clamp(bank + beta, -camera.max_gimbal, camera.max_gimbal);
  const double roll = bank - gamma;  // the camera's roll from level, left wing down positive
  const Vec3 axis = -(std::cos(roll) * up + std::sin(roll) * left);
  return r.dot(axis) >= std::cos(0.5 * camera.fov) * distance;
}

}  // namespace vistrack
