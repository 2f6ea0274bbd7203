// The single error type of vistrack, and the checks that build its messages.
#pragma once

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>

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

// A value computed from the input (a limit, a distance, a rate) quoted in a message: 4 significant
// digits ("LDLPP needs 159.3 m", not 159.3486742963367). The user's own values are echoed as given
// (to_text above, the shortest text that reads back as the same double).
inline std::string computed_text(double value) {
  std::ostringstream out;
  out.precision(4);
  out << value;
  return out.str();
}

// "field = value: reason", the shape of every message about a bad input value.
template <class T>
[[noreturn]] void fail_field(const std::string& field, const T& value, const std::string& reason) {
  throw Error(field + " = " + to_text(value) + ": " + reason);
}

}  // namespace detail

// ---- Enum values by name -------------------------------------------------------------------
// An enum that crosses the API by name (YAML, CLI, Python) specialises EnumNames beside its
// declaration: `field`, how messages name the input by default, and `names`, its {name, value}
// table. A value's first entry is its name; later entries for it are accepted spellings.
template <class E>
struct EnumName {
  const char* name;
  E value;
};
template <class E>
struct EnumNames;

template <class E, class = void>
struct has_enum_names : std::false_type {};
template <class E>
struct has_enum_names<E, std::void_t<decltype(EnumNames<E>::names)>> : std::true_type {};

template <class E, class = std::enable_if_t<has_enum_names<E>::value>>
std::string to_string(E value) {
  for (const EnumName<E>& entry : EnumNames<E>::names)
    if (entry.value == value) return entry.name;
  return "unknown";
}

// The value named `text` (any letter case); Error "field = 'text': must be one of 'a', 'b'" otherwise.
template <class E>
E from_name(const std::string& text, const std::string& field = EnumNames<E>::field) {
  const auto lower = [](std::string t) {
    for (char& ch : t) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    return t;
  };
  const std::string key = lower(text);
  std::string allowed;
  for (const EnumName<E>& entry : EnumNames<E>::names) {
    if (lower(entry.name) == key) return entry.value;
    if (to_string(entry.value) == entry.name) allowed += (allowed.empty() ? "'" : ", '") + std::string(entry.name) + "'";
  }
  detail::fail_field(field, "'" + text + "'", "must be one of " + allowed);
}

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
