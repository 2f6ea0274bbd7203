// The illustrative feedback law (5) of the Dubins waypoint navigation paper, section 3.1.
#include <algorithm>
#include <cmath>

#include "flight/known_wind.hpp"
#include "vistrack/error.hpp"
#include "vistrack/flight.hpp"

namespace vistrack {

LineFeedback::LineFeedback(double speed, double turn_radius, double dt, const LineFeedbackGains& gains,
                           bool smooth_sign)
    : speed_(speed), turn_radius_(turn_radius), dt_(dt), gains_(gains), smooth_sign_(smooth_sign) {
  require_positive(speed, "speed");
  require_positive(turn_radius, "turn_radius");
  require_positive(dt, "dt");
  gains.validate();
  const double psi_max = speed * dt / turn_radius;
  if (psi_max > kPi / 2.0)
    detail::fail_field("dt", dt, "psi_max = v dt / R = " + detail::computed_text(psi_max) + " rad exceeds pi/2");
}

void LineFeedback::set_wind(const Vec2& mean_wind) {
  wind_ = detail::known_wind(mean_wind, speed_);
  wind_aware_ = true;
}

LineFeedbackTerms LineFeedback::terms(const Configuration& q, const Vec2& line_start, const Vec2& target) const {
  LineFeedbackTerms out;
  const Vec2 p(q.x, q.y);
  const Vec2 to_target = target - p;
  // The direction the law steers: the heading, or with the wind known the course over the ground.
  const double cos_psi = std::cos(q.psi), sin_psi = std::sin(q.psi);
  const Vec2 ground = speed_ * Vec2(cos_psi, sin_psi) + wind_;
  const double course = wind_aware_ ? std::atan2(ground.y(), ground.x()) : q.psi;
  out.target_angle = wrap_to_pi(std::atan2(to_target.y(), to_target.x()) - course);
  const Vec2 line = target - line_start;
  const double scale = std::max({1.0, line_start.cwiseAbs().maxCoeff(), target.cwiseAbs().maxCoeff()});
  if (line.norm() > 1e-12 * scale) {
    const Vec2 along = line.normalized();
    const Vec2 left(-along.y(), along.x());
    out.cross_track = (p - line_start).dot(left);
    // d s / dt from the heading alone (the law does not know the wind): v sin(psi - chi); with
    // the wind known, from the ground velocity.
    out.cross_track_step = wind_aware_ ? ground.dot(left) * dt_
                                       : speed_ * (cos_psi * left.x() + sin_psi * left.y()) * dt_;
  }
  const double psi_max = max_turn();
  const double magnitude = std::abs(gains_.g * out.cross_track + gains_.h * out.cross_track_step);
  double direction = out.target_angle > 0.0 ? 1.0 : (out.target_angle < 0.0 ? -1.0 : 0.0);
  if (smooth_sign_) direction = std::clamp(out.target_angle / psi_max, -1.0, 1.0);
  out.reference_angle = magnitude * direction;
  out.unsaturated = out.target_angle + out.reference_angle;
  out.turn = std::clamp(out.unsaturated, -psi_max, psi_max);
  out.saturated = out.turn != out.unsaturated;
  return out;
}

}  // namespace vistrack
