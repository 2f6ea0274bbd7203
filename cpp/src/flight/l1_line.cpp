// L1 line tracking (flight.hpp): ArduPlane's leg guidance on the airspeed vector.
#include <algorithm>
#include <cmath>

#include "vistrack/error.hpp"
#include "vistrack/flight.hpp"

namespace vistrack {

namespace {

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// The signed angle from a to b, positive counter-clockwise.
double angle_to(const Vec2& a, const Vec2& b) { return std::atan2(cross(a, b), a.dot(b)); }

}  // namespace

L1Line::L1Line(double speed, const L1Gains& gains) : speed_(speed), gains_(gains) {
  require_positive(speed, "speed");
  gains.validate();
  distance_ = gains.damping * gains.period * speed / kPi;
}

double L1Line::turn_rate(const Configuration& q, const Vec2& line_start, const Vec2& target) const {
  const Vec2 p(q.x, q.y);
  const Vec2 velocity = speed_ * Vec2(std::cos(q.psi), std::sin(q.psi));
  const Vec2 line = target - line_start;
  const double length = line.norm();
  const double scale = std::max({1.0, line_start.cwiseAbs().maxCoeff(), target.cwiseAbs().maxCoeff()});
  double eta = 0.0;
  if (!(length > 1e-12 * scale)) {
    eta = angle_to(velocity, target - p);  // no line: fly to the target
  } else {
    const Vec2 along = line / length;
    const Vec2 from_start = p - line_start;
    const double along_track = from_start.dot(along);
    const double from_start_distance = from_start.norm();
    if (from_start_distance > distance_ && along_track < -0.7071 * from_start_distance) {
      eta = angle_to(velocity, line_start - p);  // far behind the start: go there first
    } else if (along_track > length + 3.0 * speed_) {
      eta = angle_to(velocity, target - p);  // well past the target: come back to it
    } else {
      const double cross_track = cross(along, from_start);  // positive left of the line
      const double sine_capture = std::clamp(-cross_track / distance_, -0.7071, 0.7071);
      eta = std::asin(sine_capture) + angle_to(velocity, along);
    }
  }
  eta = std::clamp(eta, -0.5 * kPi, 0.5 * kPi);
  const double lateral_acceleration = 4.0 * gains_.damping * gains_.damping * speed_ * speed_ / distance_ * std::sin(eta);
  return lateral_acceleration / speed_;
}

}  // namespace vistrack
