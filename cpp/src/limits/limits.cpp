// The checks of vistrack/limits.hpp.
#include "vistrack/limits.hpp"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <sstream>

namespace vistrack {

std::string limits::range_text(double low, double high, const std::string& unit) {
  std::ostringstream out;
  out << "[" << low << ", " << high << "]" << (unit.empty() ? "" : " " + unit);
  return out.str();
}

std::string limits::bytes_text(double bytes) {
  std::ostringstream out;
  out.precision(4);
  if (bytes >= 1e9) out << bytes / 1e9 << " GB";
  else if (bytes >= 1e6) out << bytes / 1e6 << " MB";
  else out << bytes / 1e3 << " kB";
  return out.str();
}

void require_work_bytes(double bytes, const std::string& field, const std::string& value, const std::string& work,
                        const std::string& remedy) {
  if (bytes <= limits::kMaxWorkBytes) return;  // NaN never comes: every estimate is a product of counts
  throw Error(field + " = " + value + ": " + work + " would hold about " + limits::bytes_text(bytes) +
              ", above the " + limits::bytes_text(limits::kMaxWorkBytes) +
              " one planned piece of work may take (MAX_WORK_BYTES): " + remedy);
}

void require_in_range(double value, double low, double high, const std::string& unit, const std::string& field) {
  if (!(value >= low && value <= high))  // NaN fails both
    detail::fail_field(field, value, "must be a finite number in " + limits::range_text(low, high, unit));
}

void require_time_step(double value, const std::string& field) {
  if (!(value > 0.0 && value <= limits::kMaxTimeStep))  // NaN fails both
    detail::fail_field(field, value, "must be a finite number in (0, " + detail::to_text(limits::kMaxTimeStep) + "] s");
}

void require_coordinate(double value, const std::string& field) {
  require_in_range(value, -limits::kMaxCoordinate, limits::kMaxCoordinate, "m (coordinates)", field);
}

void require_length(double value, const std::string& field) {
  require_in_range(value, limits::kMinLength, limits::kMaxLength, "m", field);
}

void require_speed(double value, const std::string& field) {
  require_in_range(value, limits::kMinSpeed, limits::kMaxSpeed, "m/s", field);
}

void require_angle(double value, const std::string& field) {
  require_in_range(value, -limits::kMaxAngle, limits::kMaxAngle, "rad", field);
}

void require_threads(int value, const std::string& field) {
  if (value < 0 || value > limits::kMaxThreads)
    detail::fail_field(field, value, "must be 0 (all cores) or a thread count in [1, " +
                                         std::to_string(limits::kMaxThreads) + "]");
}

void require_beta(double value, const std::string& field) {
  require_in_range(value, limits::kMinGain, limits::kMaxBeta, "1/m", field);
}

void require_heading_gain(double value, const std::string& field) {
  require_in_range(value, limits::kMinGain, limits::kMaxHeadingGain, "1/s", field);
}

void require_tolerances(double rtol, double atol, const std::string& prefix) {
  require_in_range(rtol, limits::kMinRelativeTolerance, limits::kMaxRelativeTolerance, "", prefix + "rtol");
  require_in_range(atol, limits::kMinAbsoluteTolerance, limits::kMaxAbsoluteTolerance, "", prefix + "atol");
}

void require_regular_file(const std::string& path, const std::string& field, const std::string& kind) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (path.empty()) detail::fail_field(field, "''", "no " + kind + " file given");
  if (error == std::errc::too_many_symbolic_link_levels)
    detail::fail_field(field, path, "cannot read the " + kind + " file (a symlink loop)");
  if (!fs::exists(status)) detail::fail_field(field, path, "no such " + kind + " file");
  if (fs::is_directory(status)) detail::fail_field(field, path, "is a folder, not a " + kind + " file");
  if (!fs::is_regular_file(status)) detail::fail_field(field, path, "is not a regular " + kind + " file");
  const std::uintmax_t size = fs::file_size(path, error);
  if (!error && size > static_cast<std::uintmax_t>(limits::kMaxInputFileBytes))
    detail::fail_field(field, path, "the " + kind + " file has " + std::to_string(size) +
                                        " bytes, above the limit of " + std::to_string(limits::kMaxInputFileBytes) +
                                        " bytes for an input file");
}

std::string detail::printable(const std::string& text, bool quote, std::size_t kLongest) {
  std::string out = quote ? "'" : "";
  for (std::size_t i = 0; i < text.size() && i < kLongest; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  if (text.size() > kLongest) out += "...";
  return quote ? out + "'" : out;
}

}  // namespace vistrack
