// The single error type of vistrack, and the checks that build its messages.
#pragma once

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>

namespace vistrack {

// Invalid input or an operation that cannot be carried out. The message names the offending
// field and value. Bound to Python as vistrack.VistrackError (a ValueError).
class Error : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

namespace detail {

template <class T>
std::string to_text(const T& value) {
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

// The shortest text that reads back as the same double (1e+300, not 1.0000000000000001e+300).
inline std::string to_text(double value) {
  for (int digits = 6; digits <= 17; ++digits) {
    std::ostringstream out;
    out.precision(digits);
    out << value;
    if (digits == 17 || !std::isfinite(value) || std::strtod(out.str().c_str(), nullptr) == value) return out.str();
  }
  return {};
}

// "field = value: reason", the shape of every message about a bad input value.
template <class T>
[[noreturn]] void fail_field(const std::string& field, const T& value, const std::string& reason) {
  throw Error(field + " = " + to_text(value) + ": " + reason);
}

}  // namespace detail

inline void require_finite(double value, const std::string& field) {
  if (!std::isfinite(value)) detail::fail_field(field, value, "must be a finite number");
}

inline void require_positive(double value, const std::string& field) {
  if (!(value > 0.0) || !std::isfinite(value))
    detail::fail_field(field, value, "must be a finite number greater than 0");
}

inline void require_non_negative(double value, const std::string& field) {
  if (!(value >= 0.0) || !std::isfinite(value))
    detail::fail_field(field, value, "must be a finite number greater than or equal to 0");
}

}  // namespace vistrack
