// L1 guidance (flight.hpp): ArduPlane's leg tracking (L1Line) and Park's law on a curve (CurveL1),
// both on the airspeed vector.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "flight/known_wind.hpp"
#include "vistrack/error.hpp"
#include "vistrack/flight.hpp"
#include "vistrack/limits.hpp"

namespace vistrack {

namespace {

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// The signed angle from a to b, positive counter-clockwise.
double angle_to(const Vec2& a, const Vec2& b) { return std::atan2(cross(a, b), a.dot(b)); }

// L1 = damping * period * v / pi, after checking v and the gains.
double l1_distance(double speed, const L1Gains& gains) {
  require_positive(speed, "speed");
  gains.validate();
  return gains.damping * gains.period * speed / kPi;
}

// The turn rate a / v of the lateral acceleration a = 4 damping^2 v^2 / L1 sin(eta), |eta| <= pi/2.
double l1_turn_rate(double eta, double speed, double distance, const L1Gains& gains) {
  return 4.0 * gains.damping * gains.damping * speed / distance * std::sin(std::clamp(eta, -0.5 * kPi, 0.5 * kPi));
}

}  // namespace

L1Line::L1Line(double speed, const L1Gains& gains)
    : speed_(speed), distance_(l1_distance(speed, gains)), gains_(gains) {}

void L1Line::set_wind(const Vec2& mean_wind) {
  wind_ = detail::known_wind(mean_wind, speed_);
  wind_aware_ = true;
}

double L1Line::turn_rate(const Configuration& q, const Vec2& line_start, const Vec2& target) const {
  const Vec2 p(q.x, q.y);
  // The velocity the law steers: the airspeed vector, or with the wind known the ground velocity.
  const Vec2 velocity = speed_ * Vec2(std::cos(q.psi), std::sin(q.psi)) + (wind_aware_ ? wind_ : Vec2::Zero());
  const double ground_speed = wind_aware_ ? velocity.norm() : speed_;
  // L1 grows with the ground speed (checked gains: the constructor's l1_distance validated them).
  const double distance = wind_aware_ ? distance_ * ground_speed / speed_ : distance_;
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
    if (from_start_distance > distance && along_track < -0.7071 * from_start_distance) {
      eta = angle_to(velocity, line_start - p);  // far behind the start: go there first
    } else if (along_track > length + 3.0 * speed_) {
      eta = angle_to(velocity, target - p);  // well past the target: come back to it
    } else {
      const double cross_track = cross(along, from_start);  // positive left of the line
      const double sine_capture = std::clamp(-cross_track / distance, -0.7071, 0.7071);
      eta = std::asin(sine_capture) + angle_to(velocity, along);
    }
  }
  if (!wind_aware_) return l1_turn_rate(eta, speed_, distance_, gains_);
  // a / v with a = 4 damping^2 V_g^2 / L1 sin(eta): the ground-speed law's acceleration, turned by the airspeed.
  return l1_turn_rate(eta, ground_speed, distance, gains_) * ground_speed / speed_;
}

namespace {

// The largest u >= 0 with |a + u d - p| = r, given |a - p| <= r (the circle is left at u).
double leave_circle(const Vec2& a, const Vec2& d, const Vec2& p, double r) {
  const Vec2 f = a - p;
  const double qa = d.squaredNorm(), qb = 2.0 * f.dot(d), qc = f.squaredNorm() - r * r;
  const double disc = std::max(0.0, qb * qb - 4.0 * qa * qc);
  return (-qb + std::sqrt(disc)) / (2.0 * qa);
}

}  // namespace

CurveL1::CurveL1(double speed, const std::vector<Vec2>& path, const L1Gains& gains)
    : speed_(speed), distance_(l1_distance(speed, gains)), gains_(gains) {
  set_path(path);
}

void CurveL1::set_path(const std::vector<Vec2>& path) {
  std::vector<Vec2> points;
  for (std::size_t k = 0; k < path.size(); ++k) {
    require_coordinate(path[k].x(), "path[" + std::to_string(k) + "].x");
    require_coordinate(path[k].y(), "path[" + std::to_string(k) + "].y");
    if (points.empty() || (path[k] - points.back()).norm() > 1e-9 * (1.0 + path[k].norm())) points.push_back(path[k]);
  }
  if (points.empty()) detail::fail_field("path", path.size(), "needs at least one point");
  path_ = std::move(points);
  touch();
}

Vec2 CurveL1::reference_point(const Vec2& p) const {
  if (path_.size() == 1) return path_.front();  // a held point: fly to it
  // The closest point of the path.
  std::size_t best = 0;
  double best_u = 0.0, best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k + 1 < path_.size(); ++k) {
    const Vec2 d = path_[k + 1] - path_[k];
    const double u = std::clamp((p - path_[k]).dot(d) / d.squaredNorm(), 0.0, 1.0);
    const double distance = (path_[k] + u * d - p).norm();
    if (distance < best_distance) best = k, best_u = u, best_distance = distance;
  }
  const Vec2 closest = path_[best] + best_u * (path_[best + 1] - path_[best]);
  if (best_distance >= distance_) return closest;
  // Walk ahead to where the path leaves the circle of radius L1.
  Vec2 a = closest;
  for (std::size_t k = best; k + 1 < path_.size(); ++k) {
    const Vec2 b = path_[k + 1];
    if ((b - p).norm() >= distance_) return a + std::min(1.0, leave_circle(a, b - a, p, distance_)) * (b - a);
    a = b;
  }
  const Vec2 last = path_.back() - path_[path_.size() - 2];
  return a + leave_circle(a, last.normalized(), p, distance_) * last.normalized();
}

GuidanceCommand CurveL1::command(const Configuration& state, double) const {
  const Vec2 p(state.x, state.y);
  const Vec2 velocity = speed_ * Vec2(std::cos(state.psi), std::sin(state.psi));
  const Vec2 reference = reference_point(p);
  GuidanceCommand c;
  c.turn_rate = l1_turn_rate(angle_to(velocity, reference - p), speed_, distance_, gains_);
  c.target = reference;
  return c;
}

}  // namespace vistrack
