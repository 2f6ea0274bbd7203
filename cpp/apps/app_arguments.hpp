// Command-line helpers shared by the standalone executables.
#pragma once

#include <exception>
#include <string>

#include "vistrack/error.hpp"

namespace vistrack::apps {

// The value of a numeric flag; vistrack::Error naming the flag when the text is not a number.
inline double number(const std::string& flag, const std::string& text) {
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used == text.size()) return value;
  } catch (const std::exception&) {
  }
  detail::fail_field(flag, text, "expected a number");
}

}  // namespace vistrack::apps
