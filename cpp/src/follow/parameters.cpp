// Validation of the follow planner's parameters (follow_parameters.hpp) and of its camera.
#include <cmath>

#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"
#include "vistrack/follow.hpp"
#include "vistrack/follow_parameters.hpp"

namespace vistrack {

void FollowParameters::validate() const {
  require_time_step(period, "follow.period");
  if (!(turn_margin >= 1.0) || !std::isfinite(turn_margin))
    detail::fail_field("follow.turn_margin", turn_margin, "must be a finite number >= 1 (a multiple of r_min)");
  if (threshold != kAutoThreshold && (!(threshold > 1.0) || !std::isfinite(threshold)))
    detail::fail_field("follow.threshold", threshold,
                       "must be \"auto\" or a finite number > 1 (a speed ratio v_p / v_g)");
  require_non_negative(hysteresis, "follow.hysteresis");
  // "auto": camera_threshold picks h above 1 + band / 2, so any finite band fits.
  if (threshold != kAutoThreshold && hysteresis > threshold)
    detail::fail_field("follow.hysteresis", hysteresis,
                       "the band must not be wider than the threshold " + detail::to_text(threshold));
  if (threshold != kAutoThreshold && !(threshold - 0.5 * hysteresis > 1.0))
    detail::fail_field("follow.hysteresis", hysteresis,
                       "the band's lower edge threshold - hysteresis / 2 must stay above 1 (a loiter needs v_p > v_g)");
  require_in_range(loiter_radius, 0.0, limits::kMaxLength, "m", "follow.loiter_radius");
  require_in_range(offset_distance, 0.0, limits::kMaxLength, "m", "follow.offset_distance");
  require_finite(offset_angle, "follow.offset_angle");
  require_positive(update_period, "follow.update_period");
  if (!(strategy_margin >= 0.0 && strategy_margin <= 1.0))
    detail::fail_field("follow.strategy_margin", strategy_margin, "must be a fraction in [0, 1]");
  require_in_range(standoff_radius, 0.0, limits::kMaxLength, "m", "follow.standoff_radius");
}

void FollowFlight::validate() const {
  require_positive(dt, "flight.dt");
  require_non_negative(max_time, "flight.max_time");
  l1.validate();
}

void DownwardCamera::validate() const {
  if (!(fov > 0.0 && fov < kPi)) detail::fail_field("camera.fov", fov, "must be in (0, pi) radians");
  if (!(max_gimbal >= 0.0 && max_gimbal < 0.5 * kPi))
    detail::fail_field("camera.max_gimbal", max_gimbal, "must be in [0, pi/2) radians");
  if (mount != CameraMount::Roll && mount != CameraMount::PanTilt && mount != CameraMount::Fixed)
    detail::fail_field("camera.mount", static_cast<int>(mount), "must be roll, pan_tilt or fixed");
}

}  // namespace vistrack
