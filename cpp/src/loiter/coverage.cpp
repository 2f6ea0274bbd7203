// Camera footprint and coverage (sections 2.2 and 4.1).
//
// Camera model: a circular field of view of full angle fov (74 deg), i.e. a cone of half-angle
// beta = 37 deg, on a roll gimbal (+-25 deg). Levelled (the paper: the gimbal angle is "measured
// from the vertical"), its axis is tilted by the gimbal angle; on the body, which banks by
// atan(v psi_dot / g) in a coordinated turn (pitch and sideslip neglected), by gimbal - bank, to the
// left of vertical, in the plane across the track (camera_tilt); the ground footprint
// is the cone's plane section, an ellipse (see camera_footprint). At 61 m and nadir it is a disk of
// radius 61 tan 37 deg = 45.97 m, area 6,637.9 m^2: the paper's 6,638 m^2.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <vector>

#include "loiter/tangents.hpp"
#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"
#include "vistrack/loiter.hpp"

namespace vistrack {

namespace {

constexpr double kDegree = kPi / 180.0;

// The fraction of one AOI the camera sees at each gimbal angle, at one pose.
class AoiView {
 public:
  // body_tilt: the axis' tilt at gimbal angle 0 (minus the bank on the body, 0 levelled).
  AoiView(const LoiterCamera& camera, const Configuration& pose, double body_tilt, const Vec2& center, double radius)
      : camera_(camera), pose_(pose), body_tilt_(body_tilt), center_(center), radius_(radius) {}

  double fraction(double gimbal) const {
    return footprint_disk_area(camera_footprint(camera_, pose_, body_tilt_ + gimbal), center_, radius_) /
           (kPi * radius_ * radius_);
  }

  // Whether the AOI's centre lies in the footprint for some gimbal angle in [-limit, limit]: the
  // smallest angle between the ray to it and the camera axis is at most beta. When it never does,
  // a line through the centre separates it from the (convex) footprint: at most half the disk can
  // be in view.
  bool centre_can_be_seen(double limit) const {
    const Vec2 offset = center_ - Vec2(pose_.x, pose_.y);
    const Vec2 forward = detail::unit_at(pose_.psi);
    const double along = offset.dot(forward), across = offset.dot(detail::left_of(forward));
    const double h = camera_.altitude;
    const double tilt = std::clamp(std::atan2(across, h), body_tilt_ - limit, body_tilt_ + limit);
    const double cosine = (across * std::sin(tilt) + h * std::cos(tilt)) / std::sqrt(along * along + across * across + h * h);
    return cosine >= std::cos(0.5 * camera_.fov_deg * kDegree) * (1.0 - 1e-12);
  }

  // The gimbal angle in [-limit, limit] that holds most of the AOI in view, and that fraction:
  // a scan (including the angle that aims the axis at the centre), then Brent's method around the
  // best scanned angle.
  std::pair<double, double> best(double limit) const {
    const Vec2 offset = center_ - Vec2(pose_.x, pose_.y);
    const double across = offset.dot(detail::left_of(detail::unit_at(pose_.psi)));
    const double aim = std::clamp(std::atan2(across, camera_.altitude) - body_tilt_, -limit, limit);
    constexpr int kScan = 4;
    double best_gimbal = aim, best_fraction = fraction(aim);
    for (int k = 0; k <= kScan && limit > 0.0 && best_fraction < 1.0; ++k) {
      const double g = -limit + 2.0 * limit * k / kScan;
      const double f = fraction(g);
      if (f > best_fraction) {
        best_fraction = f;
        best_gimbal = g;
      }
    }
    if (best_fraction <= 0.0 || best_fraction >= 1.0 || limit == 0.0) return {best_gimbal, best_fraction};
    const double step = 2.0 * limit / kScan;
    std::uintmax_t iterations = 60;
    const auto found = boost::math::tools::brent_find_minima(
        [this](double g) { return -fraction(g); }, std::max(-limit, best_gimbal - step),
        std::min(limit, best_gimbal + step), 16, iterations);
    if (-found.second > best_fraction) return {found.first, -found.second};
    return {best_gimbal, best_fraction};
  }

 private:
  const LoiterCamera& camera_;
  Configuration pose_;
  double body_tilt_;
  Vec2 center_;
  double radius_;
};

// The pointing at one step. Every candidate's best angle and fraction are known; the AOIs that
// can reach the threshold each do so on one interval of gimbal angles (their fraction is unimodal
// in the angle). The gimbal takes the angle covered by the most such intervals and, there, the one
// with the most of those AOIs' area in view. With none able to reach it, the angle that holds the
// best-held AOI best (nothing counts as covered either way).
struct Candidate {
  std::size_t aoi;
  double gimbal;    // its best angle
  double fraction;  // its best fraction
};

double choose_gimbal(const std::vector<AoiView>& views, const std::vector<Candidate>& candidates, double threshold,
                     double limit) {
  std::vector<std::size_t> able;
  std::size_t best = 0;
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    if (candidates[c].fraction > candidates[best].fraction) best = c;
    if (candidates[c].fraction >= threshold) able.push_back(c);
  }
  if (able.size() <= 1) return candidates[best].gimbal;
  // Interval of each able AOI: bisection from its best angle to the threshold on both sides.
  struct Interval {
    double lo, hi;
    std::size_t candidate;
  };
  std::vector<Interval> intervals;
  for (const std::size_t c : able) {
    const AoiView& view = views[c];
    const auto edge = [&](double inside, double outside) {
      if (view.fraction(outside) >= threshold) return outside;
      for (int k = 0; k < 40 && std::abs(outside - inside) > 1e-7; ++k) {
        const double middle = 0.5 * (inside + outside);
        (view.fraction(middle) >= threshold ? inside : outside) = middle;
      }
      return inside;
    };
    intervals.push_back({edge(candidates[c].gimbal, -limit), edge(candidates[c].gimbal, limit), c});
  }
  // Where the intervals overlap: each overlap region starts where an interval starts. Within a
  // region, the angle with most of its members' area in view; regions compared by (count, area).
  std::size_t most = 0;
  double best_g = candidates[best].gimbal, best_seen = -1.0;
  for (const Interval& start : intervals) {
    std::vector<std::size_t> members;
    double lo = start.lo, hi = start.hi;
    for (const Interval& other : intervals)
      if (other.lo <= start.lo && other.hi >= start.lo) {
        members.push_back(other.candidate);
        hi = std::min(hi, other.hi);
      }
    if (members.size() < most) continue;
    const auto seen = [&](double g) {
      double total = 0.0;
      for (const std::size_t c : members) total += views[c].fraction(g);
      return total;
    };
    double g_here = lo, seen_here = seen(lo);
    constexpr int kScan = 4;
    for (int k = 1; k <= kScan; ++k) {
      const double g = lo + (hi - lo) * k / kScan;
      const double value = seen(g);
      if (value > seen_here) {
        seen_here = value;
        g_here = g;
      }
    }
    if (hi - lo > 1e-7) {
      const double step = (hi - lo) / kScan;
      std::uintmax_t iterations = 60;
      const auto found = boost::math::tools::brent_find_minima(
          [&](double g) { return -seen(g); }, std::max(lo, g_here - step), std::min(hi, g_here + step), 16, iterations);
      if (-found.second > seen_here) {
        seen_here = -found.second;
        g_here = found.first;
      }
    }
    if (members.size() > most || seen_here > best_seen) {
      most = members.size();
      best_seen = seen_here;
      best_g = g_here;
    }
  }
  return best_g;
}

}  // namespace

double Footprint::area() const { return kPi * semi_along * semi_across; }

double bank_angle(double speed, double turn_rate, double gravity) { return std::atan(speed * turn_rate / gravity); }

double camera_tilt(const LoiterCamera& camera, double bank, double gimbal) {
  return camera.levelled ? gimbal : gimbal - bank;
}

// The cone of half-angle beta about the axis (0, sin tilt, -cos tilt) (across-track s to the left,
// along-track a, the camera at height h) meets the ground where
//   (s sin tilt + h cos tilt)^2 >= cos^2 beta (a^2 + s^2 + h^2)
// <=> cos^2 beta a^2 + k (s - s0)^2 <= h^2 sin^2 beta cos^2 beta / k,
// k = cos^2 beta - sin^2 tilt, s0 = h sin tilt cos tilt / k: an ellipse when k > 0.
Footprint camera_footprint(const LoiterCamera& camera, const Configuration& pose, double tilt) {
  const double beta = 0.5 * camera.fov_deg * kDegree;
  const double cb = std::cos(beta), sb = std::sin(beta), st = std::sin(tilt), ct = std::cos(tilt);
  const double k = cb * cb - st * st;
  if (!(k > 0.0) || !std::isfinite(tilt))
    detail::fail_field("tilt", tilt, "plus half the field of view reaches 90 degrees: the footprint is not bounded");
  const double h = camera.altitude;
  Footprint f;
  f.along = detail::unit_at(pose.psi);
  f.center = Vec2(pose.x, pose.y) + (h * st * ct / k) * detail::left_of(f.along);
  f.semi_along = h * sb / std::sqrt(k);
  f.semi_across = h * sb * cb / k;
  return f;
}

double footprint_disk_area(const Footprint& footprint, const Vec2& center, double rho) {
  const Vec2 d = center - footprint.center;
  return ellipse_disk_intersection_area(footprint.semi_along, footprint.semi_across, d.dot(footprint.along),
                                        d.dot(detail::left_of(footprint.along)), rho);
}

LoiterCoverage loiter_coverage(const Points3& poses, const std::vector<double>& turn_rates,
                               const std::vector<Vec2>& aois, double aoi_radius, double speed,
                               const LoiterCamera& camera, const LoiterCoverageOptions& options) {
  camera.validate();
  options.validate();
  require_positive(aoi_radius, "aoi_radius");
  require_positive(speed, "speed");
  if (aois.empty()) throw Error("aois: at least one area of interest (AOI centre) is needed");
  for (std::size_t i = 0; i < aois.size(); ++i) {
    require_finite(aois[i].x(), "aois[" + std::to_string(i) + "][0]");
    require_finite(aois[i].y(), "aois[" + std::to_string(i) + "][1]");
  }
  const auto n = static_cast<std::size_t>(poses.rows());
  if (turn_rates.size() != n)
    detail::fail_field("turn_rates", std::to_string(turn_rates.size()) + " values",
                       "need one per pose (" + std::to_string(n) + ")");
  {
    // Dense: a fraction per step and AOI (8 bytes) beside four numbers per step.
    const double steps = static_cast<double>(n), count = static_cast<double>(aois.size());
    const double bytes = steps * (8.0 * count + 32.0);
    const double fits = options.dt * bytes / limits::kMaxWorkBytes;
    require_work_bytes(bytes, "dt", detail::to_text(options.dt),
                       "scoring " + detail::to_text(steps) + " steps x " + detail::to_text(count) +
                           " AOIs (a dense coverage matrix, 8 bytes per step and AOI)",
                       "raise dt (" + detail::to_text(std::ceil(fits)) + " s fits) or score fewer AOIs");
  }
  const double limit = camera.max_gimbal_deg * kDegree;
  const double beta = 0.5 * camera.fov_deg * kDegree;
  for (std::size_t k = 0; k < n; ++k) {
    const auto row = static_cast<Eigen::Index>(k);
    for (int c = 0; c < 3; ++c)
      require_finite(poses(row, c), "poses[" + std::to_string(k) + "][" + std::to_string(c) + "]");
    require_finite(turn_rates[k], "turn_rates[" + std::to_string(k) + "]");
    const double bank = bank_angle(speed, turn_rates[k], options.gravity);
    if (std::abs(camera_tilt(camera, bank, 0.0)) + limit + beta >= 0.5 * kPi * (1.0 - 1e-9))
      detail::fail_field("turn_rates[" + std::to_string(k) + "]", turn_rates[k],
                         "banks the aircraft by " + detail::computed_text(bank / kDegree) +
                             " deg: with the gimbal and half the field of view the camera would see the horizon");
  }

  const std::size_t m = aois.size();
  LoiterCoverage out;
  out.steps = n;
  out.aoi_count = m;
  out.fraction.assign(n * m, 0.0);
  out.pointed.assign(n, -1);
  out.gimbal.assign(n, 0.0);
  out.bank.assign(n, 0.0);
  out.tilt.assign(n, 0.0);
  const double h = camera.altitude;

  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 16), [&](const tbb::blocked_range<std::size_t>& range) {
    for (std::size_t k = range.begin(); k != range.end(); ++k) {
      const auto row = static_cast<Eigen::Index>(k);
      const Configuration pose{poses(row, 0), poses(row, 1), poses(row, 2)};
      const double bank = bank_angle(speed, turn_rates[k], options.gravity);
      out.bank[k] = bank;
      const double body_tilt = camera_tilt(camera, bank, 0.0);
      // With no AOI in reach the gimbal levels the camera as far as it can.
      out.gimbal[k] = std::clamp(-body_tilt, -limit, limit);
      // The footprint never reaches farther from the nadir point than the far edge of the cone.
      const double reach = h * std::tan(std::abs(body_tilt) + limit + beta);
      // Candidates: AOIs that could reach the threshold. Above 1/2 that needs the centre in view.
      const auto in_reach = [&](std::size_t i) {
        return (aois[i] - Vec2(pose.x, pose.y)).norm() - aoi_radius < reach;
      };
      std::vector<AoiView> views;
      std::vector<Candidate> candidates;
      for (std::size_t i = 0; i < m; ++i) {
        if (!in_reach(i)) continue;
        AoiView view(camera, pose, body_tilt, aois[i], aoi_radius);
        if (options.threshold > 0.5 && !view.centre_can_be_seen(limit)) continue;
        const auto [gimbal, fraction] = view.best(limit);
        if (!(fraction > 0.0)) continue;
        views.push_back(view);
        candidates.push_back({i, gimbal, fraction});
      }
      if (!candidates.empty()) out.gimbal[k] = choose_gimbal(views, candidates, options.threshold, limit);
      out.tilt[k] = body_tilt + out.gimbal[k];
      // Every AOI in reach, seen with that pointing (levelled when no AOI is a candidate); the
      // pointed AOI is the one most in view.
      double most = 0.0;
      for (std::size_t i = 0; i < m; ++i) {
        if (!in_reach(i)) continue;
        const double f = AoiView(camera, pose, body_tilt, aois[i], aoi_radius).fraction(out.gimbal[k]);
        out.fraction[k * m + i] = f;
        if (!candidates.empty() && f > most) {
          most = f;
          out.pointed[k] = static_cast<int>(i);
        }
      }
    }
  });

  out.time_per_aoi.assign(m, 0.0);
  out.area_per_aoi.assign(m, 0.0);
  const double disk = kPi * aoi_radius * aoi_radius;
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t i = 0; i < m; ++i) {
      const double f = out.fraction[k * m + i];
      if (f >= options.threshold) {
        out.time_per_aoi[i] += options.dt;
        out.area_per_aoi[i] += f * disk * options.dt;
      }
    }
  for (std::size_t i = 0; i < m; ++i) {
    out.time += out.time_per_aoi[i];
    out.area += out.area_per_aoi[i];
  }
  return out;
}

LoiterCoverage loiter_coverage(const LoiterPlan& plan, const LoiterCamera& camera, const LoiterCoverageOptions& options) {
  options.validate();
  const LoiterSamples samples = plan.sample_states(options.dt, false);
  return loiter_coverage(samples.poses, samples.turn_rate, plan.problem.aois, plan.problem.parameters.aoi_radius,
                         plan.problem.parameters.speed, camera, options);
}

}  // namespace vistrack
