// Wind for one flight: constant part plus Dryden gusts (MIL-F-8785C), see flight.hpp.
#include <unsupported/Eigen/MatrixFunctions>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "vistrack/error.hpp"
#include "vistrack/flight.hpp"

namespace vistrack {

namespace {

constexpr double kFeet = 0.3048;  // m per ft

// A 2x2 symmetric positive semi-definite matrix's square root R (R R^T = M).
Eigen::Matrix2d psd_root(const Eigen::Matrix2d& m) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(0.5 * (m + m.transpose()));
  const Eigen::Vector2d roots = eig.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  return eig.eigenvectors() * roots.asDiagonal();
}

}  // namespace

DrydenLowAltitude dryden_low_altitude(double altitude, double wind_speed_20ft) {
  require_finite(altitude, "altitude");
  if (!(altitude >= 10.0 * kFeet && altitude <= 1000.0 * kFeet))
    detail::fail_field("altitude", altitude, "the low-altitude model holds from 3.048 to 304.8 m (10-1000 ft)");
  require_non_negative(wind_speed_20ft, "wind_speed_20ft");
  const double h = altitude / kFeet;  // the model's formulas are in feet
  const double base = 0.177 + 0.000823 * h;
  DrydenLowAltitude out;
  out.sigma_w = 0.1 * wind_speed_20ft;
  out.sigma_u = out.sigma_w / std::pow(base, 0.4);
  out.length_w = altitude;
  out.length_u = h / std::pow(base, 1.2) * kFeet;
  return out;
}

Gusts mil_f_8785c_gusts(double altitude, double wind_speed_20ft, std::uint64_t seed, double length_unit,
                        double speed_unit) {
  require_positive(length_unit, "length_unit");
  require_positive(speed_unit, "speed_unit");
  const DrydenLowAltitude model = dryden_low_altitude(altitude, wind_speed_20ft);
  Gusts gusts;
  gusts.seed = seed;
  gusts.intensity = model.sigma_u / speed_unit;
  gusts.length_scale = model.length_u / length_unit;
  return gusts;
}

namespace detail {

double NormalStream::next() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  // 53-bit uniforms in (0, 1] and [0, 1).
  const double u1 = (static_cast<double>(engine_() >> 11) + 1.0) * 0x1.0p-53;
  const double u2 = static_cast<double>(engine_() >> 11) * 0x1.0p-53;
  const double radius = std::sqrt(-2.0 * std::log(u1));
  spare_ = radius * std::sin(kTwoPi * u2);
  has_spare_ = true;
  return radius * std::cos(kTwoPi * u2);
}

DrydenFilter dryden_filter(double sigma, double time_scale, double step, bool lateral) {
  // Continuous state space x' = A x + B eta (eta unit white noise), y = C x, realising H_u or H_v
  // of flight.hpp. H_u is first order: its second state is a decoupled, noise-free dummy.
  const double a = 1.0 / time_scale;
  Eigen::Matrix2d A;
  Eigen::Vector2d B;
  DrydenFilter f;
  if (lateral) {
    // sigma sqrt(T) (1 + sqrt(3) T s) / (T^2 (s + a)^2), controllable canonical form.
    A << 0.0, 1.0, -a * a, -2.0 * a;
    B << 0.0, 1.0;
    const double k = sigma * std::sqrt(time_scale) / (time_scale * time_scale);
    f.output << k, k * std::sqrt(3.0) * time_scale;
  } else {
    // sigma sqrt(2 T) a / (s + a).
    A << -a, 0.0, 0.0, -1.0;
    B << 1.0, 0.0;
    f.output << sigma * std::sqrt(2.0 * time_scale) * a, 0.0;
  }
  // Van Loan: exp([[-A, B B^T], [0, A^T]] h) = [[., Phi^-1 Q], [0, Phi^T]].
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m.topLeftCorner<2, 2>() = -A;
  m.topRightCorner<2, 2>() = B * B.transpose();
  m.bottomRightCorner<2, 2>() = A.transpose();
  const Eigen::Matrix4d e = (m * step).exp();
  f.transition = e.bottomRightCorner<2, 2>().transpose();
  const Eigen::Matrix2d q = f.transition * e.topRightCorner<2, 2>();
  f.noise_root = psd_root(q);
  // Stationary covariance: (I (x) A + A (x) I) vec(P) = -vec(B B^T).
  Eigen::Matrix4d k = Eigen::Matrix4d::Zero();
  for (int i = 0; i < 2; ++i) {
    k.block<2, 2>(2 * i, 2 * i) += A;  // I (x) A
    for (int j = 0; j < 2; ++j) k.block<2, 2>(2 * i, 2 * j) += A(i, j) * Eigen::Matrix2d::Identity();  // A (x) I
  }
  const Eigen::Matrix2d bb = B * B.transpose();
  const Eigen::Vector4d vec_p = k.partialPivLu().solve(-Eigen::Map<const Eigen::Vector4d>(bb.data()));
  f.stationary = Eigen::Map<const Eigen::Matrix2d>(vec_p.data());
  f.stationary_root = psd_root(f.stationary);
  return f;
}

std::vector<double> dryden_series(const DrydenFilter& filter, std::size_t n, NormalStream& noise) {
  std::vector<double> out(n);
  Eigen::Vector2d x = filter.stationary_root * Eigen::Vector2d(noise.next(), noise.next());
  for (std::size_t k = 0; k < n; ++k) {
    out[k] = filter.output * x;
    x = filter.transition * x + filter.noise_root * Eigen::Vector2d(noise.next(), noise.next());
  }
  return out;
}

}  // namespace detail

WindField::WindField(const Wind& wind, double airspeed, double t0, double duration) : wind_(wind), t0_(t0) {
  wind.validate();
  require_positive(airspeed, "speed");
  require_finite(t0, "t0");
  require_positive(duration, "duration");
  const Vec2 mean(wind.east, wind.north);
  max_speed_ = mean.norm();
  if (!(max_speed_ < airspeed))
    detail::fail_field("wind", "(" + detail::to_text(wind.east) + ", " + detail::to_text(wind.north) + ")",
                       "its speed " + detail::computed_text(max_speed_) + " must be below the airspeed " +
                           detail::to_text(airspeed));
  if (!wind.gusts || wind.gusts->intensity == 0.0) return;
  const Gusts& gusts = *wind.gusts;
  const double time_scale = gusts.length_scale / airspeed;  // Taylor: T = L / V
  step_ = gusts.sample_step > 0.0 ? gusts.sample_step : time_scale / 20.0;
  const double count = std::ceil(duration / step_) + 2.0;
  if (count > 1e8)
    detail::fail_field("wind.gusts.sample_step", step_, "more than 1e8 gust samples for a flight of " +
                                                            detail::to_text(duration) + " s");
  const auto n = static_cast<std::size_t>(count);
  detail::NormalStream noise(gusts.seed);
  const auto u = detail::dryden_series(detail::dryden_filter(gusts.intensity, time_scale, step_, false), n, noise);
  const auto v = detail::dryden_series(detail::dryden_filter(gusts.intensity, time_scale, step_, true), n, noise);
  const Vec2 along = max_speed_ > 0.0 ? Vec2(mean / max_speed_) : Vec2(1.0, 0.0);
  const Vec2 left(-along.y(), along.x());
  gust_east_.resize(n);
  gust_north_.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 g = u[k] * along + v[k] * left;
    gust_east_[k] = g.x();
    gust_north_[k] = g.y();
    const double speed = (mean + g).norm();
    if (!(speed < airspeed))
      detail::fail_field("wind.gusts.intensity", gusts.intensity,
                         "the gusts take the wind speed to " + detail::computed_text(speed) + " at t = " +
                             detail::computed_text(t0 + static_cast<double>(k) * step_) + ", at or above the airspeed " +
                             detail::to_text(airspeed));
    max_speed_ = std::max(max_speed_, speed);
  }
}

double WindField::next_sample_time(double t) const {
  if (gust_east_.empty()) return std::numeric_limits<double>::infinity();
  const double k = std::floor((t - t0_) / step_) + 1.0;
  double next = t0_ + k * step_;
  if (next <= t) next = t0_ + (k + 1.0) * step_;
  return next > t0_ + static_cast<double>(gust_east_.size() - 1) * step_ ? std::numeric_limits<double>::infinity()
                                                                         : next;
}

Vec2 WindField::at(double t) const {
  Vec2 w(wind_.east, wind_.north);
  if (gust_east_.empty()) return w;
  const double position = (t - t0_) / step_;
  const double last = static_cast<double>(gust_east_.size() - 1);
  if (!(position > 0.0)) return w + Vec2(gust_east_.front(), gust_north_.front());
  if (position >= last) return w + Vec2(gust_east_.back(), gust_north_.back());
  const auto k = static_cast<std::size_t>(position);
  const double f = position - static_cast<double>(k);
  return w + Vec2(gust_east_[k] + f * (gust_east_[k + 1] - gust_east_[k]),
                  gust_north_[k] + f * (gust_north_[k + 1] - gust_north_[k]));
}

}  // namespace vistrack
