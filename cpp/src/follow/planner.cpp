// The follow planner (sections II, III, V): mode with hysteresis, the pattern's state from one
// 1 Hz update to the next, and the waypoint.
#include <algorithm>
#include <cmath>
#include <limits>

#include "vistrack/error.hpp"
#include "vistrack/follow.hpp"
#include "vistrack/vehicle.hpp"

namespace vistrack {

namespace {

// A turn of the planning frame by more than this between two updates (a corner of the road)
// re-enters the sinusoid at the phase nearest to the UAV instead of rotating the pattern about
// the offset point, which would throw the desired position across it.
constexpr double kReentryTurn = 20.0 * kPi / 180.0;
// Substeps of the loiter pattern's speed equation (RK4), s.
constexpr double kLoiterStep = 0.05;
// Strategy auto considers the sinusoid up to this speed ratio (its amplitude is then kilometres).
constexpr double kMaxSinusoidRatio = 50.0;

Vec2 rotate(const Vec2& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

double wrap_phase(double phi) { return phi - kTwoPi * std::floor(phi / kTwoPi); }

// Arc length of the tick's sinusoid from phase 0 to phi.
double arc_at_phase(const FollowTick& tick, double phi) {
  return sinusoid_arc_length(tick.period_distance * phi / kTwoPi, tick.amplitude, tick.period_distance);
}

// The sinusoid relative to the offset point, in the frame of its x axis: lead and lateral.
Vec2 sinusoid_point(const FollowTick& tick, double phi, double arc) {
  const double lead = tick.period_distance * phi / kTwoPi - arc / tick.speed_ratio;
  return {lead, tick.amplitude * std::sin(phi)};
}

}  // namespace

FollowPlanner::FollowPlanner(const FollowParameters& parameters, const Uav& uav, const Vec2& wind_estimate,
                             const DownwardCamera& camera)
    : parameters_(parameters), uav_(uav), wind_(wind_estimate), camera_(camera) {
  parameters_.validate();
  uav_.validate();
  camera_.validate();
  gains_ = GuidanceGains::from(uav_, Control{});
  gains_.direction = parameters_.loiter_direction;
  threshold_ = camera_threshold(parameters_, uav_, camera);
  parameters_.threshold = threshold_.threshold;
  require_finite(wind_.x(), "wind_estimate.east");
  require_finite(wind_.y(), "wind_estimate.north");
  if (!(wind_.norm() < uav_.speed))
    detail::fail_field("wind_estimate", detail::to_text(wind_.x()) + ", " + detail::to_text(wind_.y()),
                       "the wind must be slower than the UAV's airspeed " + detail::to_text(uav_.speed));
  const double turn = orbit_radius(uav_.speed / (parameters_.threshold - 0.5 * parameters_.hysteresis));
  loiter_.pattern = parameters_.loiter_pattern;
  loiter_.direction = sign(parameters_.loiter_direction);
  loiter_.turn_radius = turn;
  const double automatic = loiter_.pattern == LoiterPattern::Circle ? turn : 3.0 * turn;
  loiter_.radius = parameters_.loiter_radius > 0.0 ? parameters_.loiter_radius : automatic;
  if (loiter_.pattern == LoiterPattern::Rose && !(loiter_.radius >= 2.0 * turn))
    detail::fail_field("follow.loiter_radius", loiter_.radius,
                       "a rose needs at least twice its turn radius " + detail::to_text(turn) + " m");
  loiter_.validate();
}

LoiterShape FollowPlanner::loiter_for(const FollowTick& tick) const {
  LoiterShape shape = loiter_;
  // The smallest flyable circle for the offset point's current speed, unless the user gave one.
  if (shape.pattern == LoiterPattern::Circle && parameters_.loiter_radius == 0.0 && tick.radius > 0.0)
    shape.radius = tick.radius;
  return shape;
}

double FollowPlanner::orbit_radius(double frame_speed) const {
  const double ratio = std::min(1.0, std::max(0.0, frame_speed) / uav_.speed);
  return parameters_.turn_margin * uav_.min_turn_radius * std::pow(1.0 + ratio, 2);
}

double FollowPlanner::standoff_radius(const FollowTick& tick) const {
  return parameters_.standoff_radius > 0.0 ? parameters_.standoff_radius : tick.radius;
}

Vec2 FollowPlanner::offset_vector(double vehicle_heading) const {
  const double angle = parameters_.offset_angle + (parameters_.offset_reference == OffsetReference::Heading ? vehicle_heading : 0.0);
  return parameters_.offset_distance * Vec2(std::cos(angle), std::sin(angle));
}

void FollowPlanner::set_offset(double distance, double angle) {
  require_non_negative(distance, "offset.distance");
  require_finite(angle, "offset.angle");
  parameters_.offset_distance = distance;
  parameters_.offset_angle = angle;
}

FollowMode FollowPlanner::next_mode(FollowMode current, double speed_ratio) const {
  const double half = 0.5 * parameters_.hysteresis;
  if (current == FollowMode::Loiter) {
    if (speed_ratio > parameters_.threshold - half) return FollowMode::Loiter;
  } else if (speed_ratio > parameters_.threshold + half) {
    return FollowMode::Loiter;
  }
  return speed_ratio >= 1.0 ? FollowMode::Sinusoid : FollowMode::Straight;
}

void FollowPlanner::set_sinusoid_shape(FollowTick& tick) const {
  const double frame_speed = tick.frame_velocity.norm();
  const SinusoidShape shape = sinusoid_shape(tick.speed_ratio, tick.uav_speed, parameters_.period,
                                             parameters_.turn_margin * uav_.min_turn_radius);
  tick.period_distance = shape.period_distance;
  tick.amplitude = shape.amplitude;
  tick.period = tick.period_distance / frame_speed;
}

// Entering a pattern: the point of it the UAV reaches soonest, scored as its distance plus the
// arc the UAV would turn through to fly along it there (rho |heading change|, rho the planned
// turn radius). The heading term also breaks the tie where the sinusoid crosses its axis twice.
double FollowPlanner::entry_cost(const Vec2& point, const Vec2& direction, const Vec2& uav_relative,
                                 double uav_heading) const {
  const double turn = std::abs(wrap_to_pi(std::atan2(direction.y(), direction.x()) - uav_heading));
  return (point - uav_relative).norm() + parameters_.turn_margin * uav_.min_turn_radius * turn;
}

void FollowPlanner::enter_sinusoid(FollowTick& tick, const Vec2& uav_relative, double uav_heading) const {
  const double a = kTwoPi * tick.amplitude / tick.period_distance;
  double best = std::numeric_limits<double>::infinity();
  constexpr int kSamples = 720;
  for (int i = 0; i < kSamples; ++i) {
    const double phi = kTwoPi * i / kSamples;
    const Vec2 point = rotate(sinusoid_point(tick, phi, arc_at_phase(tick, phi)), tick.track_angle);
    // In the planning frame the UAV moves along (1, A' cos phi) of the sinusoid's axes.
    const Vec2 direction = rotate(Vec2(1.0, a * std::cos(phi)), tick.track_angle);
    const double cost = entry_cost(point, direction, uav_relative, uav_heading);
    if (cost < best) {
      best = cost;
      tick.phase = phi;
    }
  }
}

void FollowPlanner::enter_loiter(FollowTick& tick, const Vec2& uav_relative, double uav_heading) const {
  // Over enough of the pattern to see every point of the circle, or every orientation of the
  // rose's line.
  const LoiterShape shape = loiter_for(tick);  // once: the loop below samples it up to 400 x 64 times
  const double piece = shape.piece_length();
  const int pieces =
      shape.pattern == LoiterPattern::Circle ? 1 : std::min(400, static_cast<int>(std::ceil(kTwoPi / shape.delta())) + 2);
  const double step = std::min(shape.turn_radius / 8.0, piece / 64.0);
  const int samples = static_cast<int>(std::ceil(pieces * piece / step));
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < samples; ++i) {
    const double s = i * step;
    const Vec2 direction = tick.frame_velocity + pattern_speed(tick, shape, s) * shape.tangent(s);
    const double cost = entry_cost(shape.position(s), direction, uav_relative, uav_heading);
    if (cost < best) {
      best = cost;
      tick.arc = s;
    }
  }
}

// ds/dt along the loiter pattern so that the UAV's speed in the planning frame is v_p:
// |v_f + s_dot t(s)| = v_p, the positive root (as the tracking paper's eq. (13) for an orbit).
double FollowPlanner::pattern_speed(const FollowTick& tick, const LoiterShape& shape, double s) const {
  const Vec2 t = shape.tangent(s);
  const double b = tick.frame_velocity.dot(t);
  const double disc = b * b - tick.frame_velocity.squaredNorm() + tick.uav_speed * tick.uav_speed;
  return std::max(0.0, -b + std::sqrt(std::max(0.0, disc)));
}

double FollowPlanner::loiter_step(const FollowTick& tick, const LoiterShape& shape, double s, double h) const {
  const double k1 = pattern_speed(tick, shape, s);
  const double k2 = pattern_speed(tick, shape, s + 0.5 * h * k1);
  const double k3 = pattern_speed(tick, shape, s + 0.5 * h * k2);
  const double k4 = pattern_speed(tick, shape, s + h * k3);
  return s + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

double FollowPlanner::advance_arc(const FollowTick& tick, double tau) const {
  if (!(tau > 0.0)) return tick.arc;
  // Fixed steps from the update, then one partial step: nearby tau share their steps, so the
  // desired position is smooth in tau.
  const LoiterShape shape = loiter_for(tick);
  const int whole = static_cast<int>(std::floor(tau / kLoiterStep));
  double s = tick.arc;
  for (int i = 0; i < whole; ++i) s = loiter_step(tick, shape, s, kLoiterStep);
  const double rest = tau - whole * kLoiterStep;
  return rest > 0.0 ? loiter_step(tick, shape, s, rest) : s;
}

std::vector<Vec2> FollowPlanner::relative_positions(const FollowTick& tick, const std::vector<double>& taus) const {
  std::vector<Vec2> out;
  out.reserve(taus.size());
  if (tick.mode != FollowMode::Loiter || tick.capturing) {
    for (double tau : taus) out.push_back(relative_position(tick, tau));
    return out;
  }
  // advance_arc in one pass: the whole steps shared by increasing taus are taken once.
  const LoiterShape shape = loiter_for(tick);
  double s = tick.arc;
  int done = 0;
  double last = -std::numeric_limits<double>::infinity();
  for (double tau : taus) {
    if (!(tau >= last)) detail::fail_field("taus", tau, "must increase");
    last = tau;
    if (!(tau > 0.0)) {
      out.push_back(shape.position(tick.arc));
      continue;
    }
    const int whole = static_cast<int>(std::floor(tau / kLoiterStep));
    for (; done < whole; ++done) s = loiter_step(tick, shape, s, kLoiterStep);
    const double rest = tau - whole * kLoiterStep;
    out.push_back(shape.position(rest > 0.0 ? loiter_step(tick, shape, s, rest) : s));
  }
  return out;
}

Vec2 FollowPlanner::relative_position(const FollowTick& tick, double tau) const {
  if (tick.capturing) tau = 0.0;  // the held point
  switch (tick.mode) {
    case FollowMode::Sinusoid: {
      const double arc = arc_at_phase(tick, tick.phase) + tick.uav_speed * std::max(0.0, tau);
      const double phi = sinusoid_phase_at_arc(arc, tick.amplitude, tick.period_distance);
      return rotate(sinusoid_point(tick, phi, arc), tick.track_angle);
    }
    case FollowMode::Loiter:
      return loiter_for(tick).position(advance_arc(tick, tau));
    case FollowMode::Standoff:
      return standoff_relative(tick, tau);
    case FollowMode::Straight:
      break;
  }
  return Vec2::Zero();
}

// The standoff orbit: the UAV's path along the vector field (74) about the offset point, from
// where it was at the update, in the planning frame (where the offset point moves at the frame
// velocity and the UAV at v_p), relative to the offset point. RK4 on a fixed 0.5 s grid from the
// update, then one partial step (nearby tau share their steps).
Vec2 FollowPlanner::standoff_relative(const FollowTick& tick, double tau) const {
  constexpr double kStep = 0.5;
  GuidanceGains gains = gains_;
  gains.speed = tick.uav_speed;
  OrbitState orbit{Vec2::Zero(), tick.frame_velocity, tick.radius, 0.0};
  const auto rate = [&](const Vec2& p, double s) {
    orbit.center = tick.frame_velocity * s;
    return vector_field(p, orbit, gains, tick.track_angle).u;
  };
  const auto rk4 = [&](const Vec2& p, double s, double h) -> Vec2 {
    const Vec2 k1 = rate(p, s);
    const Vec2 k2 = rate(p + 0.5 * h * k1, s + 0.5 * h);
    const Vec2 k3 = rate(p + 0.5 * h * k2, s + 0.5 * h);
    const Vec2 k4 = rate(p + h * k3, s + h);
    return p + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  };
  tau = std::max(0.0, tau);
  const int whole = static_cast<int>(std::floor(tau / kStep));
  Vec2 p = tick.uav_relative;
  for (int i = 0; i < whole; ++i) p = rk4(p, i * kStep, kStep);
  const double rest = tau - whole * kStep;
  if (rest > 0.0) p = rk4(p, whole * kStep, rest);
  return p - tick.frame_velocity * tau;
}

// Camera fraction over one steady cycle of the tick's pattern: air-path samples (tau_i, relative
// position), headings and turn rates by differences, the coordinated bank, camera_sees from the
// UAV at rel + offset vector above the vehicle.
double FollowPlanner::predicted_camera(const FollowTick& tick) const {
  constexpr int kSamples = 36;
  std::vector<double> tau;
  std::vector<Vec2> rel;
  tau.reserve(kSamples + 1);
  rel.reserve(kSamples + 1);
  const double v = tick.uav_speed;
  switch (tick.mode) {
    case FollowMode::Sinusoid: {
      for (int j = 0; j <= kSamples; ++j) {
        const double phi = kTwoPi * j / kSamples;
        const double arc = arc_at_phase(tick, phi);
        tau.push_back(arc / v);
        rel.push_back(rotate(sinusoid_point(tick, phi, arc), tick.track_angle));
      }
      break;
    }
    case FollowMode::Loiter: {
      const LoiterShape shape = loiter_for(tick);
      const double piece = shape.piece_length();
      double t = 0.0;
      for (int j = 0; j <= kSamples; ++j) {
        const double s = piece * j / kSamples;
        if (j > 0) {
          const double speed = pattern_speed(tick, shape, s - 0.5 * piece / kSamples);
          if (!(speed > 0.0)) return 0.0;
          t += piece / kSamples / speed;
        }
        tau.push_back(t);
        rel.push_back(shape.position(s));
      }
      break;
    }
    case FollowMode::Standoff: {
      FollowTick steady = tick;
      const double across = std::atan2(tick.frame_velocity.y(), tick.frame_velocity.x()) + 0.5 * kPi;
      steady.uav_relative = tick.radius * Vec2(std::cos(across), std::sin(across));
      const double horizon = kTwoPi * tick.radius / v * (1.0 + tick.frame_velocity.norm() / v);
      for (int j = 0; j <= kSamples; ++j) {
        tau.push_back(horizon * j / kSamples);
        rel.push_back(standoff_relative(steady, tau.back()));
      }
      break;
    }
    case FollowMode::Straight:
      return 0.0;
  }
  // The air path p = v_f tau + rel: its heading and turn rate give the bank.
  const std::size_t n = tau.size();
  std::vector<double> heading(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t a = i == 0 ? 0 : i - 1, b = i + 1 < n ? i + 1 : n - 1;
    const Vec2 d = tick.frame_velocity * (tau[b] - tau[a]) + rel[b] - rel[a];
    heading[i] = std::atan2(d.y(), d.x());
  }
  double seen = 0.0, total = 0.0;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double dt = tau[i + 1] - tau[i];
    if (!(dt > 0.0)) continue;
    const double turn_rate = wrap_to_pi(heading[i + 1] - heading[i]) / dt;
    const double bank = coordinated_bank(v, turn_rate);
    const Vec2 p = 0.5 * (rel[i] + rel[i + 1]) + tick.offset_vector;
    const double psi = heading[i] + 0.5 * wrap_to_pi(heading[i + 1] - heading[i]);
    if (camera_sees(camera_, Vec3(p.x(), p.y(), uav_.altitude), psi, bank, Vec3::Zero())) seen += dt;
    total += dt;
  }
  return total > 0.0 ? seen / total : 0.0;
}

// The strategy's mode at this update (the paper's: `paper_mode`, the threshold with its band).
FollowMode FollowPlanner::choose_mode(const FollowTick& tick, FollowMode paper_mode, double& predicted) const {
  predicted = -1.0;
  const bool orbits = tick.speed_ratio > 1.0;
  switch (parameters_.strategy) {
    case FollowStrategy::Paper:
      return paper_mode;
    case FollowStrategy::Standoff:
      return orbits ? FollowMode::Standoff : FollowMode::Straight;
    case FollowStrategy::Auto:
      break;
  }
  if (tick.speed_ratio < 1.0) return FollowMode::Straight;
  // Hold a pattern being captured; otherwise the best predicted, leaving the standoff orbit or the
  // current pattern only for a margin more.
  if (has_previous_ && !previous_.lost && previous_.capturing && previous_.mode != FollowMode::Straight)
    return previous_.mode;
  FollowMode best = FollowMode::Sinusoid;
  double best_fraction = -1.0, current_fraction = -1.0, standoff_fraction = -1.0;
  for (FollowMode mode : {FollowMode::Sinusoid, FollowMode::Loiter, FollowMode::Standoff}) {
    if (mode != FollowMode::Sinusoid && !orbits) continue;
    // A nearly standing offset point: the sinusoid's amplitude grows without bound (eq. 10).
    if (mode == FollowMode::Sinusoid && !(tick.speed_ratio <= kMaxSinusoidRatio)) continue;
    FollowTick candidate = tick;
    candidate.mode = mode;
    if (mode == FollowMode::Standoff) candidate.radius = standoff_radius(tick);
    if (mode == FollowMode::Sinusoid) set_sinusoid_shape(candidate);
    const double fraction = predicted_camera(candidate);
    if (mode == FollowMode::Standoff) standoff_fraction = fraction;
    if (fraction > best_fraction) {
      best_fraction = fraction;
      best = mode;
    }
    if (has_previous_ && !previous_.lost && previous_.mode == mode) current_fraction = fraction;
  }
  // The standoff orbit (the baseline's own pattern, flown by its law) is the default: another
  // pattern must be predicted to see the vehicle a margin more often, as the steady cycle knows
  // neither the roll lag nor the capture.
  if (orbits && best != FollowMode::Standoff && best_fraction <= standoff_fraction + parameters_.strategy_margin) {
    predicted = standoff_fraction;
    return FollowMode::Standoff;
  }
  if (current_fraction >= 0.0 && best_fraction <= current_fraction + parameters_.strategy_margin) {
    predicted = current_fraction;
    return previous_.mode;
  }
  predicted = best_fraction;
  return best;
}

std::vector<Vec2> FollowPlanner::planned_path(const FollowTick& tick, double horizon, double step) const {
  require_positive(horizon, "horizon");
  require_positive(step, "step");
  const auto n = static_cast<std::size_t>(std::ceil(horizon / step));
  std::vector<double> taus(n + 1);
  for (std::size_t k = 0; k <= n; ++k) taus[k] = std::min(horizon, static_cast<double>(k) * step);
  std::vector<Vec2> path = relative_positions(tick, taus);
  for (std::size_t k = 0; k <= n; ++k) path[k] += tick.offset_point + tick.offset_velocity * taus[k];
  return path;
}

FollowTick FollowPlanner::update(double t, const FollowObservation& o) {
  require_finite(t, "t");
  if (has_previous_ && !(t > previous_.t))
    detail::fail_field("t", t, "updates must move forward in time (the last was " + detail::to_text(previous_.t) + ")");
  FollowTick tick;
  tick.t = t;
  tick.lost = o.lost;
  // Lost: orbit the vehicle's estimate itself (the last known position carried along its velocity).
  tick.offset_vector = o.lost ? Vec2::Zero() : offset_vector(o.vehicle_heading);
  tick.offset_point = o.vehicle_position + tick.offset_vector;
  const Vec2 offset_velocity = o.vehicle_velocity + (o.lost ? Vec2::Zero() : o.offset_rate);
  if (parameters_.wind_compensation) {
    tick.uav_speed = uav_.speed;
    tick.frame_velocity = offset_velocity - wind_;
  } else {
    tick.uav_speed = uav_.speed;
    tick.frame_velocity = offset_velocity;
  }
  const double frame_speed = tick.frame_velocity.norm();
  const bool frame_moves = frame_speed > 1e-9 * tick.uav_speed;
  tick.speed_ratio = frame_moves ? tick.uav_speed / frame_speed : std::numeric_limits<double>::infinity();
  tick.track_angle = frame_moves ? std::atan2(tick.frame_velocity.y(), tick.frame_velocity.x())
                                 : (has_previous_ ? previous_.track_angle : o.vehicle_heading);
  if (o.lost) {
    tick.mode = tick.speed_ratio > 1.0 ? FollowMode::Loiter : FollowMode::Straight;
  } else if (has_previous_ && !previous_.lost) {
    tick.mode = next_mode(previous_.mode, tick.speed_ratio);
  } else {
    tick.mode = tick.speed_ratio > parameters_.threshold ? FollowMode::Loiter
                : tick.speed_ratio >= 1.0                  ? FollowMode::Sinusoid
                                                           : FollowMode::Straight;
  }
  tick.radius = orbit_radius(frame_speed);
  if (!o.lost) {
    tick.mode = choose_mode(tick, tick.mode, tick.predicted_camera);
  }
  if (tick.mode == FollowMode::Standoff) tick.radius = standoff_radius(tick);
  const Vec2 uav_relative = o.uav_position - tick.offset_point;
  // Losing or regaining the vehicle moves the centre: the pattern is entered afresh.
  const bool same_mode = has_previous_ && previous_.mode == tick.mode && previous_.lost == tick.lost;
  bool entered = false;
  if (tick.mode == FollowMode::Sinusoid) {
    set_sinusoid_shape(tick);
    if (same_mode && std::abs(wrap_to_pi(tick.track_angle - previous_.track_angle)) <= kReentryTurn) {
      // The phase reached under the previous update's shape, kept as the new shape's phase.
      const double arc = arc_at_phase(previous_, previous_.phase) +
                         (previous_.capturing ? 0.0 : previous_.uav_speed * (t - previous_.t));
      tick.phase = wrap_phase(sinusoid_phase_at_arc(arc, previous_.amplitude, previous_.period_distance));
    } else {
      enter_sinusoid(tick, uav_relative, o.uav_heading);
      entered = true;
    }
  } else if (tick.mode == FollowMode::Standoff) {
    // The field (74) converges from anywhere: no phase to keep, no entry point to capture.
    tick.uav_relative = uav_relative;
  } else if (tick.mode == FollowMode::Loiter) {
    if (same_mode) {
      tick.arc = previous_.capturing ? previous_.arc : advance_arc(previous_, t - previous_.t);
      if (loiter_.pattern == LoiterPattern::Circle) {
        const LoiterShape circle = loiter_for(tick);
        // A circle about a set point (section II), flown as a path: once captured, each update
        // restarts it at the UAV's bearing from the centre instead of at a timed point the UAV
        // would have to catch (in wind it plans without, it could not: Fig. 6).
        if (!previous_.capturing) {
          const double angle = std::atan2(uav_relative.y(), uav_relative.x()) - circle.rotation;
          tick.arc = circle.radius * wrap_phase(circle.direction * angle);
        }
        tick.arc = std::fmod(tick.arc, circle.piece_length());
      }
    } else {
      enter_loiter(tick, uav_relative, o.uav_heading);
      entered = true;
    }
  }
  // Capture: a pattern just entered holds its point (moving with the offset point) until the UAV
  // is within one update's flight of it; only then does it run at v_p, which the UAV could not
  // catch up with.
  if (tick.mode != FollowMode::Straight && tick.mode != FollowMode::Standoff &&
      (entered || (same_mode && previous_.capturing))) {
    tick.capturing = true;
    tick.capturing = (relative_position(tick, 0.0) - uav_relative).norm() > uav_.speed * parameters_.update_period;
  }
  // The waypoint: the desired position one update later, with the vehicle predicted at its
  // current velocity and heading.
  const double dt = parameters_.update_period;
  tick.offset_velocity = offset_velocity;
  tick.waypoint = tick.offset_point + offset_velocity * dt + relative_position(tick, dt);
  tick.vehicle_predicted = o.vehicle_position + o.vehicle_velocity * dt;
  previous_ = tick;
  has_previous_ = true;
  return tick;
}

}  // namespace vistrack
