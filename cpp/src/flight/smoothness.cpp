// flight_smoothness(): how a flown bank history chatters (flight.hpp).
#include <algorithm>
#include <cmath>
#include <string>

#include "vistrack/error.hpp"
#include "vistrack/flight.hpp"

namespace vistrack {

namespace {

void validate(const std::vector<double>& t, const std::vector<double>& bank, double window, double deadband_deg) {
  if (t.size() != bank.size())
    detail::fail_field("bank", bank.size(), "must have as many samples as t (" + std::to_string(t.size()) + ")");
  if (t.size() < 2) detail::fail_field("t", t.size(), "needs at least 2 samples");
  for (std::size_t i = 0; i < t.size(); ++i) {
    require_finite(t[i], "t[" + std::to_string(i) + "]");
    require_finite(bank[i], "bank[" + std::to_string(i) + "]");
    if (i > 0 && t[i] < t[i - 1])
      detail::fail_field("t[" + std::to_string(i) + "]", t[i], "times must not decrease");
  }
  require_positive(window, "window");
  require_non_negative(deadband_deg, "deadband_deg");
}

// Reversals with a deadband: a turn of the bank counts once it has moved `deadband` back from the
// last extremum.
std::size_t count_reversals(const std::vector<double>& bank, double deadband) {
  int direction = 0;
  double high = bank.front(), low = bank.front(), extreme = bank.front();
  std::size_t reversals = 0;
  for (double b : bank) {
    if (direction == 0) {
      high = std::max(high, b);
      low = std::min(low, b);
      if (b - low >= deadband && b - low > 0.0) direction = 1, extreme = b;
      else if (high - b >= deadband && high - b > 0.0) direction = -1, extreme = b;
    } else if (direction * (b - extreme) > 0.0) {
      extreme = b;
    } else if (std::abs(extreme - b) >= deadband && b != extreme) {
      ++reversals;
      direction = -direction;
      extreme = b;
    }
  }
  return reversals;
}

}  // namespace

FlightSmoothness flight_smoothness(const std::vector<double>& t, const std::vector<double>& bank, double window,
                                   double deadband_deg) {
  validate(t, bank, window, deadband_deg);
  constexpr double kDegree = kPi / 180.0;
  const std::size_t n = t.size();
  FlightSmoothness out;

  // Moving mean over [t_i - window/2, t_i + window/2] by prefix sums and two pointers.
  std::vector<double> prefix(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) prefix[i + 1] = prefix[i] + bank[i];
  double squares = 0.0;
  std::size_t lo = 0, hi = 0;
  for (std::size_t i = 0; i < n; ++i) {
    while (t[lo] < t[i] - 0.5 * window) ++lo;
    while (hi < n && t[hi] <= t[i] + 0.5 * window) ++hi;
    const double mean = (prefix[hi] - prefix[lo]) / static_cast<double>(hi - lo);
    squares += (bank[i] - mean) * (bank[i] - mean);
  }
  out.bank_rms_deg = std::sqrt(squares / static_cast<double>(n)) / kDegree;

  out.roll_reversals = count_reversals(bank, deadband_deg * kDegree);
  const double duration = t.back() - t.front();
  out.roll_reversals_per_s = duration > 0.0 ? static_cast<double>(out.roll_reversals) / duration : 0.0;

  for (std::size_t i = 1; i < n; ++i)
    if (t[i] > t[i - 1])
      out.max_roll_rate_deg_s =
          std::max(out.max_roll_rate_deg_s, std::abs(bank[i] - bank[i - 1]) / (t[i] - t[i - 1]) / kDegree);
  return out;
}

}  // namespace vistrack
