// The receding-horizon city follower's dynamic programme (follow.hpp, The horizon city follower).
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "vistrack/error.hpp"
#include "vistrack/follow.hpp"

namespace vistrack {

namespace {

// Where a grid axis is read at an offset of `offset` grid steps: for each grid index, the lower
// neighbour's index and the fraction towards the upper one, or no reading (off the grid).
struct AxisReading {
  std::vector<std::ptrdiff_t> base;  // -1: off the grid
  double fraction = 0.0;
};

AxisReading axis_reading(double offset, std::size_t side) {
  const auto n = static_cast<std::ptrdiff_t>(side);
  const double whole = std::floor(offset);
  AxisReading out;
  out.fraction = offset - whole;
  out.base.assign(side, -1);
  const auto shift = static_cast<std::ptrdiff_t>(whole);
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const std::ptrdiff_t lower = i + shift;
    if (lower >= 0 && lower <= n - 2) out.base[static_cast<std::size_t>(i)] = lower;
    else if (lower == n - 1 && out.fraction == 0.0) out.base[static_cast<std::size_t>(i)] = -2;  // the last point
  }
  return out;
}

// v (a grid's values, n per row) read bilinearly at the cell whose lower corner is `corner`.
double bilinear(const float* v, std::size_t corner, std::size_t n, double fu, double fw) {
  return (1.0 - fu) * ((1.0 - fw) * v[corner] + fw * v[corner + 1]) +
         fu * ((1.0 - fw) * v[corner + n] + fw * v[corner + n + 1]);
}

}  // namespace

void HorizonOptions::validate() const {
  if (horizon < 1 || horizon > 600) detail::fail_field("horizon", horizon, "must be 1-600 s");
  require_positive(spacing, "spacing");
  require_positive(half_width, "half_width");
  if (half_width / spacing > 200.0)
    detail::fail_field("half_width", half_width, "must be at most 200 grid steps (spacing " +
                                                             detail::to_text(spacing) + " m)");
  require_positive(heading_step_deg, "heading_step_deg");
  const double count = 360.0 / heading_step_deg;
  if (heading_step_deg > 90.0 || std::abs(count - std::round(count)) > 1e-9)
    detail::fail_field("heading_step_deg", heading_step_deg, "must divide 360 and be at most 90");
  require_non_negative(vehicle_height, "vehicle_height");
  require_positive(dt, "dt");
  if (dt > 1.0 || std::abs(1.0 / dt - std::round(1.0 / dt)) > 1e-6)
    detail::fail_field("dt", dt, "must divide 1 s (a second's integration step)");
}

HorizonPlanner::HorizonPlanner(const VisibilityScene& scene, const Uav& uav, const DownwardCamera& camera,
                               double flight_altitude, const HorizonOptions& options)
    : scene_(scene), uav_(uav), camera_(camera), altitude_(flight_altitude), options_(options), roll_(uav) {
  options_.validate();
  uav_.validate();
  camera_.validate();
  require_finite(flight_altitude, "flight_altitude");
  const double full = roll_.max_bank();
  banks_ = {-full, -0.5 * full, 0.0, 0.5 * full, full};
  side_ = 2 * static_cast<std::size_t>(std::floor(options_.half_width / options_.spacing + 1e-9)) + 1;
  headings_ = static_cast<std::size_t>(std::lround(360.0 / options_.heading_step_deg));
  half_ = 0.5 * static_cast<double>(side_ - 1) * options_.spacing;
  heading_step_ = 2.0 * kPi / static_cast<double>(headings_);
  const std::size_t cells = side_ * side_;
  // The camera from each grid point, heading and bank (the vehicle at the grid's origin, on the ground).
  camera_table_.assign(banks_.size() * headings_ * cells, 0);
  for (std::size_t b = 0; b < banks_.size(); ++b)
    for (std::size_t h = 0; h < headings_; ++h)
      for (std::size_t m = 0; m < cells; ++m) {
        const Vec2 at = grid_offset(m);
        camera_table_[(b * headings_ + h) * cells + m] =
            camera_sees(camera_, Vec3(at.x(), at.y(), uav_.altitude), static_cast<double>(h) * heading_step_,
                        banks_[b], Vec3::Zero()) ? 1 : 0;
      }
  for (std::size_t b = 0; b < banks_.size(); ++b)
    for (double command : banks_) {
      const HorizonSecond s = fly_second(Vec2::Zero(), 0.0, banks_[b], command, Vec2::Zero());
      std::size_t level = 0;
      for (std::size_t k = 1; k < banks_.size(); ++k)
        if (std::abs(banks_[k] - s.bank) < std::abs(banks_[level] - s.bank)) level = k;
      moves_.push_back({s.position, s.heading, level});
    }
}

Vec2 HorizonPlanner::grid_offset(std::size_t m) const {
  return {-half_ + static_cast<double>(m / side_) * options_.spacing,
          -half_ + static_cast<double>(m % side_) * options_.spacing};
}

HorizonSecond HorizonPlanner::fly_second(const Vec2& position, double heading, double bank, double bank_command,
                                         const Vec2& wind) const {
  const double dt = options_.dt;
  const auto steps = static_cast<int>(std::lround(1.0 / dt));
  const bool roll = uav_.dynamics == DynamicsModel::Roll;
  HorizonSecond s{position, heading, bank};
  for (int k = 0; k < steps; ++k) {  // as fly()'s discrete update: bank, heading, position
    s.bank = roll ? roll_.step(s.bank, bank_command, dt) : bank_command;
    s.heading += roll_.turn_rate(s.bank) * dt;
    s.position += dt * (uav_.speed * Vec2(std::cos(s.heading), std::sin(s.heading)) + wind);
  }
  return s;
}

std::vector<float> HorizonPlanner::rewards(const Vec2& vehicle) const {
  const std::size_t cells = side_ * side_;
  const Vec3 target = scene_.poi_on_surface(Vec3(vehicle.x(), vehicle.y(), options_.vehicle_height));
  Points3 sky(static_cast<Eigen::Index>(cells), 3), ground(static_cast<Eigen::Index>(cells), 3);
  for (std::size_t m = 0; m < cells; ++m) {
    const auto row = static_cast<Eigen::Index>(m);
    const Vec2 at = vehicle + grid_offset(m);
    sky.row(row) << at.x(), at.y(), altitude_;
    ground.row(row) = target.transpose();
  }
  const std::vector<bool> sight = scene_.line_of_sight(sky, ground);
  std::vector<float> out(camera_table_.size());
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = (camera_table_[k] && sight[k % cells]) ? 1.0f : 0.0f;
  return out;
}

void HorizonPlanner::add_best_next(std::vector<float>& now, const std::vector<float>& later, const Vec2& drift) const {
  const std::size_t cells = side_ * side_, levels = banks_.size();
  // For each (level before, heading): the most value over the commands of the next state.
  tbb::parallel_for(std::size_t{0}, levels * headings_, [&](std::size_t task) {
    const std::size_t b0 = task / headings_, h = task % headings_;
    const double angle = static_cast<double>(h) * heading_step_;
    const double c = std::cos(angle), s = std::sin(angle);
    std::vector<float> best(cells, 0.0f);  // values are counts, >= 0
    for (std::size_t command = 0; command < levels; ++command) {
      const Move& move = moves_[b0 * levels + command];
      const Vec2 way(c * move.shift.x() - s * move.shift.y() + drift.x(),
                     s * move.shift.x() + c * move.shift.y() + drift.y());
      const AxisReading east = axis_reading(way.x() / options_.spacing, side_);
      const AxisReading north = axis_reading(way.y() / options_.spacing, side_);
      const double turned = static_cast<double>(h) + move.turn / heading_step_;
      const double lower = std::floor(turned);
      const double fh = turned - lower;
      const auto wrap = [&](double index) {
        const auto n = static_cast<long long>(headings_);
        return static_cast<std::size_t>(((static_cast<long long>(index) % n) + n) % n);
      };
      const float* rows[2] = {&later[(move.level_after * headings_ + wrap(lower)) * cells],
                              &later[(move.level_after * headings_ + wrap(lower + 1.0)) * cells]};
      for (std::size_t i = 0; i < side_; ++i) {
        std::ptrdiff_t bi = east.base[i];
        if (bi == -1) continue;
        double fu = east.fraction;
        if (bi == -2) bi = static_cast<std::ptrdiff_t>(side_) - 2, fu = 1.0;
        for (std::size_t j = 0; j < side_; ++j) {
          std::ptrdiff_t bj = north.base[j];
          if (bj == -1) continue;
          double fw = north.fraction;
          if (bj == -2) bj = static_cast<std::ptrdiff_t>(side_) - 2, fw = 1.0;
          const auto corner = static_cast<std::size_t>(bi) * side_ + static_cast<std::size_t>(bj);
          const double value = (1.0 - fh) * bilinear(rows[0], corner, side_, fu, fw) +
                               fh * bilinear(rows[1], corner, side_, fu, fw);
          float& b = best[i * side_ + j];
          b = std::max(b, static_cast<float>(value));
        }
      }
    }
    float* out = &now[(b0 * headings_ + h) * cells];
    for (std::size_t m = 0; m < cells; ++m) out[m] += best[m];
  });
}

std::vector<float> HorizonPlanner::first_values(const std::vector<Vec2>& vehicle, const Vec2& wind) const {
  const auto horizon = static_cast<std::size_t>(options_.horizon);
  if (vehicle.size() != horizon + 1)
    detail::fail_field("vehicle", vehicle.size(), "must hold the vehicle's positions at 0, 1, ..., horizon = " +
                                                      std::to_string(horizon) + " s");
  for (std::size_t k = 0; k < vehicle.size(); ++k) {
    require_finite(vehicle[k].x(), "vehicle[" + std::to_string(k) + "].x");
    require_finite(vehicle[k].y(), "vehicle[" + std::to_string(k) + "].y");
  }
  require_finite(wind.x(), "wind.east");
  require_finite(wind.y(), "wind.north");
  std::vector<float> later;
  for (std::size_t j = horizon; j >= 1; --j) {
    std::vector<float> now = rewards(vehicle[j]);
    if (!later.empty()) add_best_next(now, later, wind - (vehicle[j + 1] - vehicle[j]));
    later = std::move(now);
  }
  return later;
}

double HorizonPlanner::value_at(const std::vector<float>& values, const Vec2& relative, double heading,
                                double bank) const {
  const std::size_t cells = side_ * side_;
  if (values.size() != banks_.size() * headings_ * cells)
    detail::fail_field("values", values.size(), "must be first_values' array");
  const double u = (relative.x() + half_) / options_.spacing, w = (relative.y() + half_) / options_.spacing;
  const double last = static_cast<double>(side_ - 1);
  if (!(u >= 0.0 && u <= last && w >= 0.0 && w <= last)) return 0.0;
  const auto i = static_cast<std::size_t>(std::min(std::floor(u), last - 1.0));
  const auto j = static_cast<std::size_t>(std::min(std::floor(w), last - 1.0));
  const double fu = u - static_cast<double>(i), fw = w - static_cast<double>(j);
  const double turned = std::fmod(std::fmod(heading, 2.0 * kPi) + 2.0 * kPi, 2.0 * kPi) / heading_step_;
  const auto h0 = static_cast<std::size_t>(std::floor(turned)) % headings_;
  const double fh = turned - std::floor(turned);
  // The bank linearly between its two nearest levels (clamped to the outer ones).
  const double level = std::clamp((bank - banks_.front()) / (banks_[1] - banks_[0]), 0.0,
                                  static_cast<double>(banks_.size() - 1));
  const auto b0 = std::min(static_cast<std::size_t>(std::floor(level)), banks_.size() - 2);
  const double fb = level - static_cast<double>(b0);
  double out = 0.0;
  for (std::size_t db = 0; db < 2; ++db)
    for (std::size_t dh = 0; dh < 2; ++dh) {
      const float* v = &values[((b0 + db) * headings_ + (h0 + dh) % headings_) * cells];
      out += (db ? fb : 1.0 - fb) * (dh ? fh : 1.0 - fh) * bilinear(v, i * side_ + j, side_, fu, fw);
    }
  return out;
}

HorizonChoice HorizonPlanner::choose(const std::vector<Vec2>& vehicle, const Vec2& wind, const Vec2& position,
                                     double heading, double bank) const {
  require_finite(position.x(), "position.x");
  require_finite(position.y(), "position.y");
  require_finite(heading, "heading");
  require_finite(bank, "bank");
  const std::vector<float> values = first_values(vehicle, wind);
  HorizonChoice best;
  double best_score = -std::numeric_limits<double>::infinity();
  for (double command : banks_) {
    const HorizonSecond next = fly_second(position, heading, bank, command, wind);
    const Vec2 relative = next.position - vehicle[1];
    double score = value_at(values, relative, next.heading, next.bank);
    const bool lost = !(score > 0.0);
    if (lost) {  // nothing in sight from here over the horizon: steer for the vehicle
      const Vec2 away = -relative;
      score = -std::abs(std::remainder(std::atan2(away.y(), away.x()) - next.heading, 2.0 * kPi));
    }
    if (score > best_score) {
      best_score = score;
      best = {command, roll_.turn_rate(command), lost ? 0.0 : score, lost, next};
    }
  }
  return best;
}

}  // namespace vistrack
