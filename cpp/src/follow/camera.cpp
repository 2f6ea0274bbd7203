// The downward camera of the follow metric: a cone (the field of view) about the body's down
// axis, tilted by the bank of a coordinated turn, rolled towards the target by a limited gimbal.
#include <algorithm>
#include <cmath>
#include <limits>

#include "vistrack/error.hpp"
#include "vistrack/follow.hpp"

namespace vistrack {

double camera_reach(const DownwardCamera& camera, double altitude) {
  camera.validate();
  require_positive(altitude, "uav.altitude");
  const double angle = 0.5 * camera.fov + (camera.mount == CameraMount::Fixed ? 0.0 : camera.max_gimbal);
  // The cone's edge reaches the horizon: the camera sees as far as the metric's disk allows.
  return angle < 0.5 * kPi ? altitude * std::tan(angle) : std::numeric_limits<double>::infinity();
}

ThresholdChoice camera_threshold(const FollowParameters& parameters, const Uav& uav, const DownwardCamera& camera) {
  parameters.validate();
  uav.validate();
  ThresholdChoice choice;
  choice.reach = camera_reach(camera, uav.altitude);
  const double half = 0.5 * parameters.hysteresis;
  const double rho = parameters.turn_margin * uav.min_turn_radius;
  const auto amplitude = [&](double sigma) {
    return sinusoid_shape(sigma, uav.speed, parameters.period, rho).amplitude;
  };
  choice.automatic = parameters.threshold == kAutoThreshold;
  if (choice.automatic) {
    // The amplitude grows with sigma (a(sigma) and a / sigma both increase): bisect on sigma_u.
    const double lowest = 1.0 + parameters.hysteresis + 0.01;  // sigma_u with h - band / 2 = 1.01
    constexpr double kHighest = 1e3;
    double lo = lowest, hi = kHighest;
    if (amplitude(lo) >= choice.reach) {
      hi = lo;
    } else if (amplitude(hi) <= choice.reach) {
      lo = hi;
    } else {
      for (int i = 0; i < 100 && hi - lo > 1e-9 * hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        (amplitude(mid) <= choice.reach ? lo : hi) = mid;
      }
    }
    choice.threshold = lo - half;
  } else {
    choice.threshold = parameters.threshold;
  }
  choice.upper_ratio = choice.threshold + half;
  choice.amplitude = amplitude(choice.upper_ratio);
  choice.beyond_reach = choice.amplitude > choice.reach * (1.0 + 1e-9);
  return choice;
}

bool camera_sees(const DownwardCamera& camera, const Vec3& uav, double psi, double bank, const Vec3& target) {
  const Vec3 left(-std::sin(psi), std::cos(psi), 0.0);
  const Vec3 up(0.0, 0.0, 1.0);
  const Vec3 r = target - uav;
  const double distance = r.norm();
  if (!(distance > 0.0)) return true;
  // The body's down axis, banked by phi (left wing down positive: it looks right by phi).
  const Vec3 down = -(std::cos(bank) * up + std::sin(bank) * left);
  switch (camera.mount) {
    case CameraMount::Fixed:
      return r.dot(down) >= std::cos(0.5 * camera.fov) * distance;
    case CameraMount::PanTilt: {
      // Pointed at the target, the axis within max_gimbal of the down axis: the target is seen
      // while its angle from the down axis is at most max_gimbal + fov / 2.
      const double off = std::acos(std::clamp(r.dot(down) / distance, -1.0, 1.0));
      return off <= camera.max_gimbal + 0.5 * camera.fov;
    }
    case CameraMount::Roll:
      break;
  }
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
