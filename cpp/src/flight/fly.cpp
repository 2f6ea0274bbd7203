// fly(): the vehicle (Dubins or roll model) in wind under a FlightGuidance, discrete (the paper's
// update) or continuous (Dormand-Prince 5(4) with switching located on the dense output).
#include <algorithm>
#include <cmath>
#include <limits>

#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"
#include "vistrack/flight.hpp"
#include "vistrack/ode.hpp"

namespace vistrack {

namespace {

// Continuous state: (x, y, psi) for the Dubins model, (x, y, psi, phi) for the roll model.
template <int N>
Configuration as_configuration(const OdeVector<N>& y) {
  return {y[0], y[1], y[2]};
}

// Everything one flight shares between its two integrators.
class Flight {
 public:
  Flight(const Uav& vehicle, const WindField& wind, FlightGuidance& guidance, const FlightOptions& options,
         double t0, const FlightCallback& on_step, const FlightProgress& progress)
      : v_(vehicle.speed),
        rate_limit_(vehicle.speed / vehicle.min_turn_radius),
        roll_(vehicle.dynamics == DynamicsModel::Roll),
        roll_model_(vehicle),
        wind_(wind),
        guidance_(guidance),
        options_(options),
        t0_(t0),
        t_end_(t0 + options.max_time),
        on_step_(on_step),
        progress_(progress) {}

  double clamp_rate(double rate) const {
    if (!std::isfinite(rate))
      detail::fail_field("guidance.turn_rate", rate, "the guidance returned a non-finite turn rate");
    return std::clamp(rate, -rate_limit_, rate_limit_);
  }

  // A sample of the continuous flight: the turn rate there is the command's (Dubins) or the
  // bank's (roll).
  template <int N>
  void record(double t, const OdeVector<N>& y) {
    const Configuration q = as_configuration(y);
    const GuidanceCommand c = guidance_.command(q, t);
    const double bank_command = roll_model_.bank_command(clamp_rate(c.turn_rate));
    if constexpr (N == 4) push(t, q, roll_model_.turn_rate(y[3]), y[3], bank_command, c);
    else push(t, q, clamp_rate(c.turn_rate), bank_command, bank_command, c);
  }

  // After an accepted step: the guidance's stateful logic, then the caller's hook (which may
  // feed the guidance; then the guidance looks again). True when the guidance changed.
  bool after_step(double t, const Configuration& q) {
    const std::uint64_t before = guidance_.revision();
    guidance_.advance(q, t);
    if (on_step_) {
      const std::uint64_t fed = guidance_.revision();
      on_step_(t, q);
      if (guidance_.revision() != fed) guidance_.advance(q, t);
    }
    report(t);
    if (guidance_.revision() == before) return false;
    out_.switch_times.push_back(t);
    return true;
  }

  void report(double t) {
    if (!progress_) return;
    const auto permille = static_cast<std::size_t>(std::min(1000.0, 1000.0 * (t - t0_) / options_.max_time));
    if (permille != last_permille_) {
      last_permille_ = permille;
      progress_(permille, 1000);
    }
  }

  FlightTrajectory discrete(const Configuration& start) {
    const double dt = options_.dt;
    const auto steps = static_cast<std::size_t>(std::floor(options_.max_time / dt + 1e-9));
    reserve(std::min<std::size_t>(steps + 1, 1'000'000));
    Configuration q = start;
    double t = t0_;
    double bank = 0.0;  // roll model: level at the start
    for (std::size_t k = 0; k < steps && !guidance_.done(); ++k) {
      const GuidanceCommand c = guidance_.command(q, t);
      double rate = clamp_rate(c.turn_rate);
      const double bank_command = roll_model_.bank_command(rate);
      if (roll_) {
        const double bank_now = bank;
        bank = roll_model_.step(bank, bank_command, dt);
        rate = roll_model_.turn_rate(bank);
        push(t, q, rate, bank_now, bank_command, c);
      } else {
        push(t, q, rate, bank_command, bank_command, c);  // the Dubins vehicle banks at once
      }
      q.psi += rate * dt;
      const Vec2 w = wind_.at(t + 0.5 * dt);
      q.x += dt * (v_ * std::cos(q.psi) + w.x());
      q.y += dt * (v_ * std::sin(q.psi) + w.y());
      t = t0_ + static_cast<double>(k + 1) * dt;  // no drift from summing dt
      after_step(t, q);
    }
    if (roll_) record(t, OdeVector<4>(q.x, q.y, q.psi, bank));
    else record(t, OdeVector<3>(q.x, q.y, q.psi));
    return finish(t);
  }

  FlightTrajectory continuous(const Configuration& start) {
    try {
      if (roll_) return integrate<4>(OdeVector<4>(start.x, start.y, start.psi, 0.0));
      return integrate<3>(OdeVector<3>(start.x, start.y, start.psi));
    } catch (const Error& e) {
      throw Error(std::string(e.what()) +
                  " (integration = continuous: a guidance whose command jumps back and forth, such as "
                  "LineFeedback without smooth_sign, makes a sliding mode; smooth it or fly discrete)");
    }
  }

  template <int N>
  FlightTrajectory integrate(const OdeVector<N>& start) {
    using State = OdeVector<N>;
    const double dt = options_.dt;
    OdeOptions ode;
    ode.rtol = options_.rtol;
    ode.atol = options_.atol;
    ode.max_step = dt;
    // Far more steps than a smooth flight needs (about one per dt): a chattering command fails
    // fast instead of crawling.
    ode.max_steps = 100 * static_cast<std::size_t>(std::ceil(options_.max_time / dt)) + 1000;
    reserve(std::min<std::size_t>(static_cast<std::size_t>(options_.max_time / dt) + 2, 1'000'000));
    State y = start;
    double t = t0_;
    record(t, y);
    std::size_t next_output = 1;  // outputs at t0 + k dt
    auto rhs = [this](double time, const State& s, State& ds) {
      const double rate = clamp_rate(guidance_.command(as_configuration(s), time).turn_rate);
      const Vec2 w = wind_.at(time);
      ds[0] = v_ * std::cos(s[2]) + w.x();
      ds[1] = v_ * std::sin(s[2]) + w.y();
      if constexpr (N == 4) {
        ds[2] = roll_model_.turn_rate(s[3]);
        ds[3] = roll_model_.bank_rate(s[3], roll_model_.bank_command(rate));
      } else {
        ds[2] = rate;
      }
    };
    while (!guidance_.done() && t < t_end_) {
      // End the step sequence where the guidance changes by itself or the wind has a kink.
      double bound = t_end_;
      for (double change : {guidance_.next_change_time(t), wind_.next_sample_time(t)})
        if (change > t && change < bound) bound = change;
      DormandPrince<N, decltype(rhs)> stepper(rhs, t, y, bound, ode);
      double g_old = guidance_.switching_function(as_configuration(y), t);
      bool restart = false;
      while (!restart && stepper.step()) {
        const DenseStep<N>& step = stepper.last_step();
        double t_stop = step.t_new;
        const double g_new = guidance_.switching_function(as_configuration(step.y_new), step.t_new);
        bool event = g_old > 0.0 && g_new <= 0.0;
        if (event) t_stop = first_nonpositive(step);
        const State y_stop = event ? step(t_stop) : step.y_new;
        // Output samples inside the step; one at its end comes after advance(), like the event
        // itself: a sample holds the target its command steers to from there on.
        while (true) {
          const double t_out = t0_ + static_cast<double>(next_output) * dt;
          if (t_out >= t_stop || t_out > t_end_) break;
          record<N>(t_out, step(t_out));
          ++next_output;
        }
        t = t_stop;
        y = y_stop;
        restart = after_step(t, as_configuration(y)) || event;
        const bool on_grid = t0_ + static_cast<double>(next_output) * dt == t;
        if (on_grid) ++next_output;
        if ((event || on_grid) && out_.t.back() != t) record(t, y);
        if (guidance_.done()) break;
        g_old = guidance_.switching_function(as_configuration(y), t);
      }
      out_.statistics += stepper.statistics();
      if (!restart && stepper.finished() && bound == t_end_) break;
    }
    if (out_.t.back() != t) record(t, y);
    return finish(t);
  }

 private:
  // The earliest time in the step where the switching function is <= 0, to the last bit, by
  // bisection on the dense output (the right end of the bracket, so advance() sees the switch).
  template <int N>
  double first_nonpositive(const DenseStep<N>& step) const {
    double lo = step.t_old, hi = step.t_new;
    for (int k = 0; k < 200 && hi - lo > 4.0 * std::numeric_limits<double>::epsilon() * std::abs(hi); ++k) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      if (guidance_.switching_function(as_configuration(step(mid)), mid) <= 0.0) hi = mid;
      else lo = mid;
    }
    return hi;
  }

  void reserve(std::size_t n) {
    for (auto* v : {&out_.t, &out_.x, &out_.y, &out_.psi, &out_.command, &out_.bank, &out_.bank_command,
                    &out_.target_x, &out_.target_y, &out_.wind_east, &out_.wind_north})
      v->reserve(n);
    out_.target_index.reserve(n);
  }

  // One sample; bank_command is the coordinated bank of the guidance's clamped command (with the
  // Dubins model also the bank).
  void push(double t, const Configuration& q, double rate, double bank, double bank_command,
            const GuidanceCommand& c) {
    const Vec2 w = wind_.at(t);
    out_.t.push_back(t);
    out_.x.push_back(q.x);
    out_.y.push_back(q.y);
    out_.psi.push_back(q.psi);
    out_.command.push_back(rate);
    out_.bank.push_back(bank);
    out_.bank_command.push_back(bank_command);
    out_.target_x.push_back(c.target.x());
    out_.target_y.push_back(c.target.y());
    out_.target_index.push_back(c.target_index);
    out_.wind_east.push_back(w.x());
    out_.wind_north.push_back(w.y());
  }

  FlightTrajectory finish(double t) {
    out_.finished = guidance_.done();
    out_.end_time = t;
    if (progress_) progress_(1000, 1000);
    return std::move(out_);
  }

  double v_, rate_limit_;
  bool roll_;
  RollModel roll_model_;
  const WindField& wind_;
  FlightGuidance& guidance_;
  FlightOptions options_;
  double t0_, t_end_;
  const FlightCallback& on_step_;
  const FlightProgress& progress_;
  std::size_t last_permille_ = std::numeric_limits<std::size_t>::max();
  FlightTrajectory out_;
};

void validate(const Uav& vehicle, const FlightOptions& options, const Configuration& start, double t0) {
  vehicle.validate();
  options.validate();
  require_coordinate(start.x, "start.x");
  require_coordinate(start.y, "start.y");
  require_angle(start.psi, "start.psi");
  require_finite(t0, "t0");
  const double psi_max = vehicle.speed * options.dt / vehicle.min_turn_radius;
  if (options.integration == FlightIntegration::Discrete && psi_max > kPi / 2.0)
    detail::fail_field("dt", options.dt, "psi_max = v dt / R = " + detail::computed_text(psi_max) + " rad exceeds pi/2");
}

FlightTrajectory fly_valid(const Uav& vehicle, const WindField& wind, FlightGuidance& guidance,
                           const Configuration& start, const FlightOptions& options, double t0,
                           const FlightCallback& on_step, const FlightProgress& progress) {
  guidance.start(start, t0);
  Flight flight(vehicle, wind, guidance, options, t0, on_step, progress);
  return options.integration == FlightIntegration::Discrete ? flight.discrete(start) : flight.continuous(start);
}

}  // namespace

// A field built beforehand was checked against the airspeed it was made for, which may not be this
// vehicle's: its largest speed (O(1), kept by the field) is checked here once more.
FlightTrajectory fly(const Uav& vehicle, const WindField& wind, FlightGuidance& guidance, const Configuration& start,
                     const FlightOptions& options, double t0, const FlightCallback& on_step,
                     const FlightProgress& progress) {
  validate(vehicle, options, start, t0);
  if (!(wind.max_speed() < vehicle.speed))
    detail::fail_field("wind", wind.max_speed(),
                       "its largest speed must be below the airspeed " + detail::to_text(vehicle.speed) + " m/s");
  return fly_valid(vehicle, wind, guidance, start, options, t0, on_step, progress);
}

FlightTrajectory fly(const Uav& vehicle, const Wind& wind, FlightGuidance& guidance, const Configuration& start,
                     const FlightOptions& options, double t0, const FlightCallback& on_step,
                     const FlightProgress& progress) {
  validate(vehicle, options, start, t0);
  const WindField field(wind, vehicle.speed, t0, options.max_time + options.dt);
  return fly_valid(vehicle, field, guidance, start, options, t0, on_step, progress);
}

}  // namespace vistrack
