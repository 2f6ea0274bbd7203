// The ground vehicle: a piecewise-linear track, from samples, from legs, or along a road path.
#include <algorithm>
#include <cmath>
#include <string>

#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"
#include "vistrack/follow.hpp"

namespace vistrack {

namespace {

std::string indexed(const std::string& field, std::size_t i) { return field + "[" + std::to_string(i) + "]"; }

// Per segment: the direction of motion, or for a segment that does not move the last moving
// direction before it (the first moving one when none came before; 0 when nothing moves).
std::vector<double> headings_from_motion(const Points2& p) {
  const Eigen::Index n = p.rows();
  std::vector<double> heading(static_cast<std::size_t>(n - 1), 0.0);
  std::vector<bool> moves(heading.size(), false);
  for (Eigen::Index i = 0; i + 1 < n; ++i) {
    const Vec2 d = (p.row(i + 1) - p.row(i)).transpose();
    if (d.norm() > 0.0) {
      heading[static_cast<std::size_t>(i)] = std::atan2(d.y(), d.x());
      moves[static_cast<std::size_t>(i)] = true;
    }
  }
  const auto first = std::find(moves.begin(), moves.end(), true);
  double last = first == moves.end() ? 0.0 : heading[static_cast<std::size_t>(first - moves.begin())];
  for (std::size_t i = 0; i < heading.size(); ++i) {
    if (moves[i]) last = heading[i];
    else heading[i] = last;
  }
  return heading;
}

struct Sample {
  double t;
  double distance;  // travelled along the legs
};

// Times and travelled distances of the legs' speed profile, sampled at the leg ends and every
// `step` inside legs whose speed changes (the distance is exact at every sample).
std::vector<Sample> speed_profile(const std::vector<VehicleLeg>& legs, double t0, double step,
                                  std::vector<std::size_t>& leg_of_segment) {
  if (legs.empty()) detail::fail_field("legs", 0, "a vehicle needs at least one leg");
  require_finite(t0, "t0");
  require_positive(step, "step");
  std::vector<Sample> samples{{t0, 0.0}};
  for (std::size_t i = 0; i < legs.size(); ++i) {
    const VehicleLeg& leg = legs[i];
    const std::string field = indexed("legs", i);
    require_finite(leg.heading, field + ".heading");
    require_in_range(leg.speed, 0.0, limits::kMaxSpeed, "m/s", field + ".speed");
    require_positive(leg.duration, field + ".duration");
    const double end_speed = std::isnan(leg.end_speed) ? leg.speed : leg.end_speed;
    require_in_range(end_speed, 0.0, limits::kMaxSpeed, "m/s", field + ".end_speed");
    // A ramp is sampled every step: bound its samples (and the int below); a constant leg is one piece.
    if (end_speed != leg.speed && !(leg.duration / step <= 1e7))
      detail::fail_field(field + ".duration", leg.duration,
                         "more than 1e7 samples of step = " + detail::to_text(step) + " s");
    const int pieces = end_speed == leg.speed ? 1 : std::max(1, static_cast<int>(std::ceil(leg.duration / step)));
    const Sample start = samples.back();
    for (int k = 1; k <= pieces; ++k) {
      const double tau = leg.duration * k / pieces;
      // Speed linear in time: distance = v0 tau + (v1 - v0) tau^2 / (2 duration).
      const double d = leg.speed * tau + (end_speed - leg.speed) * tau * tau / (2.0 * leg.duration);
      samples.push_back({start.t + tau, start.distance + d});
      leg_of_segment.push_back(i);
    }
  }
  return samples;
}

}  // namespace

GroundVehicle::GroundVehicle(std::vector<double> times, Points2 positions, std::vector<double> headings)
    : times_(std::move(times)), positions_(std::move(positions)), headings_(std::move(headings)) {
  const std::size_t n = times_.size();
  if (n < 2) detail::fail_field("track", n, "a track needs at least two samples (t, x, y)");
  if (static_cast<std::size_t>(positions_.rows()) != n)
    detail::fail_field("track.x", positions_.rows(), "needs one position per time (" + std::to_string(n) + ")");
  for (std::size_t i = 0; i < n; ++i) {
    require_finite(times_[i], indexed("track.t", i));
    require_coordinate(positions_(static_cast<Eigen::Index>(i), 0), indexed("track.x", i));
    require_coordinate(positions_(static_cast<Eigen::Index>(i), 1), indexed("track.y", i));
    if (i > 0 && !(times_[i] > times_[i - 1]))
      detail::fail_field(indexed("track.t", i), times_[i],
                         "times must increase strictly (the previous sample is at " + detail::to_text(times_[i - 1]) + ")");
  }
  if (headings_.empty()) {
    headings_ = headings_from_motion(positions_);
  } else if (headings_.size() != n - 1) {
    detail::fail_field("track.heading", headings_.size(), "needs one heading per segment (" + std::to_string(n - 1) + ")");
  }
  for (std::size_t i = 0; i < headings_.size(); ++i) require_finite(headings_[i], indexed("track.heading", i));
}

GroundVehicle GroundVehicle::from_legs(const std::vector<VehicleLeg>& legs, const Vec2& start, double t0, double step) {
  require_coordinate(start.x(), "start[0]");
  require_coordinate(start.y(), "start[1]");
  std::vector<std::size_t> leg_of_segment;
  const std::vector<Sample> samples = speed_profile(legs, t0, step, leg_of_segment);
  std::vector<double> t(samples.size());
  Points2 p(static_cast<Eigen::Index>(samples.size()), 2);
  std::vector<double> heading(samples.size() - 1);
  Vec2 at = start;
  p.row(0) = at.transpose();
  t[0] = samples[0].t;
  for (std::size_t i = 1; i < samples.size(); ++i) {
    const std::size_t leg = leg_of_segment[i - 1];
    const double h = legs[leg].heading;
    at += (samples[i].distance - samples[i - 1].distance) * Vec2(std::cos(h), std::sin(h));
    // The leg that drives the vehicle off the coordinate range is named, not the track it makes.
    if (!(std::abs(at.x()) <= limits::kMaxCoordinate && std::abs(at.y()) <= limits::kMaxCoordinate))
      detail::fail_field(indexed("legs", leg) + ".duration", legs[leg].duration,
                         "drives the vehicle to (" + detail::to_text(at.x()) + ", " + detail::to_text(at.y()) +
                             ") m, beyond the coordinate limit |x|, |y| <= " +
                             detail::to_text(limits::kMaxCoordinate) + " m");
    p.row(static_cast<Eigen::Index>(i)) = at.transpose();
    t[i] = samples[i].t;
    heading[i - 1] = h;
  }
  return GroundVehicle(std::move(t), std::move(p), std::move(heading));
}

GroundVehicle GroundVehicle::along_path(const Points2& road, const std::vector<VehicleLeg>& legs, double t0,
                                        double step) {
  if (road.rows() < 2) detail::fail_field("path", road.rows(), "a road path needs at least two points");
  for (Eigen::Index i = 0; i < road.rows(); ++i) {
    require_coordinate(road(i, 0), indexed("path.x", static_cast<std::size_t>(i)));
    require_coordinate(road(i, 1), indexed("path.y", static_cast<std::size_t>(i)));
  }
  double length = 0.0;
  for (Eigen::Index i = 1; i < road.rows(); ++i) length += (road.row(i) - road.row(i - 1)).norm();
  require_positive(length, "path length");
  // Legs longer than the road drive it back and forth (a U-turn at each end).
  double total = 0.0;
  for (const VehicleLeg& leg : legs)
    total += 0.5 * (leg.speed + (std::isnan(leg.end_speed) ? leg.speed : leg.end_speed)) * leg.duration;
  const auto passes = static_cast<Eigen::Index>(std::max(1.0, std::ceil(total / length - 1e-9)));
  if (passes > 10000) detail::fail_field("path length", length, "is too short for the legs (more than 10000 passes)");
  Points2 path(passes * (road.rows() - 1) + 1, 2);
  path.row(0) = road.row(0);
  Eigen::Index k = 1;
  for (Eigen::Index pass = 0; pass < passes; ++pass)
    for (Eigen::Index i = 1; i < road.rows(); ++i) path.row(k++) = pass % 2 == 0 ? road.row(i) : road.row(road.rows() - 1 - i);
  return driven_along(path, legs, t0, step);
}

GroundVehicle GroundVehicle::driven_along(const Points2& path, const std::vector<VehicleLeg>& legs, double t0,
                                          double step) {
  std::vector<double> cumulative(static_cast<std::size_t>(path.rows()), 0.0);
  for (Eigen::Index i = 0; i < path.rows(); ++i) {
    require_coordinate(path(i, 0), indexed("path.x", static_cast<std::size_t>(i)));
    require_coordinate(path(i, 1), indexed("path.y", static_cast<std::size_t>(i)));
    if (i > 0) cumulative[static_cast<std::size_t>(i)] = cumulative[static_cast<std::size_t>(i - 1)] + (path.row(i) - path.row(i - 1)).norm();
  }
  const double length = cumulative.back();
  require_positive(length, "path length");
  std::vector<std::size_t> leg_of_segment;
  std::vector<Sample> profile = speed_profile(legs, t0, step, leg_of_segment);
  // Samples: the profile's, plus the times the vehicle passes a path vertex (the corners), up to
  // the end of the path.
  std::vector<double> t;
  std::vector<double> s;
  std::size_t vertex = 1;
  for (std::size_t i = 0; i < profile.size(); ++i) {
    if (i > 0) {
      const Sample& a = profile[i - 1];
      const Sample& b = profile[i];
      while (vertex + 1 < cumulative.size() && cumulative[vertex] <= a.distance) ++vertex;  // passed at a sample
      while (vertex + 1 < cumulative.size() && cumulative[vertex] < b.distance) {
        // Inside a profile piece the distance is quadratic in time; a linear interpolation of the
        // time is within the piece's sampling (pieces are short where the speed changes).
        const double f = (cumulative[vertex] - a.distance) / (b.distance - a.distance);
        t.push_back(a.t + f * (b.t - a.t));
        s.push_back(cumulative[vertex]);
        ++vertex;
      }
    }
    if (i > 0 && profile[i].distance > length) {
      const Sample& a = profile[i - 1];
      const double f = (length - a.distance) / (profile[i].distance - a.distance);
      t.push_back(a.t + f * (profile[i].t - a.t));
      s.push_back(length);
      break;
    }
    t.push_back(profile[i].t);
    s.push_back(profile[i].distance);
  }
  Points2 p(static_cast<Eigen::Index>(t.size()), 2);
  std::size_t seg = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    while (seg + 2 < cumulative.size() && s[i] > cumulative[seg + 1]) ++seg;
    const double span = cumulative[seg + 1] - cumulative[seg];
    const double f = span > 0.0 ? std::clamp((s[i] - cumulative[seg]) / span, 0.0, 1.0) : 0.0;
    const auto a = static_cast<Eigen::Index>(seg);
    p.row(static_cast<Eigen::Index>(i)) = path.row(a) + f * (path.row(a + 1) - path.row(a));
  }
  return GroundVehicle(std::move(t), std::move(p));
}

std::size_t GroundVehicle::segment(double t) const {
  if (t <= times_.front()) return 0;
  if (t >= times_.back()) return times_.size() - 2;
  const auto it = std::upper_bound(times_.begin(), times_.end(), t);
  return static_cast<std::size_t>(it - times_.begin()) - 1;
}

Vec2 GroundVehicle::position(double t) const {
  require_finite(t, "t");
  if (t <= times_.front()) return positions_.row(0).transpose();
  if (t >= times_.back()) return positions_.row(positions_.rows() - 1).transpose();
  const std::size_t i = segment(t);
  const double f = (t - times_[i]) / (times_[i + 1] - times_[i]);
  const auto a = static_cast<Eigen::Index>(i);
  return (positions_.row(a) + f * (positions_.row(a + 1) - positions_.row(a))).transpose();
}

Vec2 GroundVehicle::velocity(double t) const {
  require_finite(t, "t");
  if (t < times_.front() || t >= times_.back()) return Vec2::Zero();
  const std::size_t i = segment(t);
  const auto a = static_cast<Eigen::Index>(i);
  return ((positions_.row(a + 1) - positions_.row(a)) / (times_[i + 1] - times_[i])).transpose();
}

double GroundVehicle::heading(double t) const {
  require_finite(t, "t");
  return headings_[segment(t)];
}

double GroundVehicle::max_speed() const {
  double best = 0.0;
  for (std::size_t i = 0; i + 1 < times_.size(); ++i) {
    const auto a = static_cast<Eigen::Index>(i);
    best = std::max(best, (positions_.row(a + 1) - positions_.row(a)).norm() / (times_[i + 1] - times_[i]));
  }
  return best;
}

}  // namespace vistrack
