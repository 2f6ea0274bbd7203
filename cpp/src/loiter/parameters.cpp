// Validation of the loiter parameters, camera, coverage options and problem.
#include <cmath>
#include <string>

#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"
#include "vistrack/loiter.hpp"
#include "vistrack/loiter_parameters.hpp"

namespace vistrack {

namespace {
// The most AOIs one problem takes: the overlap check and the order search grow as n^2 (10^4 AOIs
// of the smallest radius already cover a 10 km square edge to edge).
constexpr std::size_t kMaxLoiterAois = 10000;
std::string point_text(const Vec2& p) { return "(" + detail::to_text(p.x()) + ", " + detail::to_text(p.y()) + ")"; }
}  // namespace

void LoiterParameters::validate() const {
  require_length(turn_radius, "turn_radius");
  require_speed(speed, "speed");
  require_length(aoi_radius, "aoi_radius");
  if (aoi_radius < turn_radius)
    detail::fail_field("aoi_radius", aoi_radius,
                       "must be at least turn_radius = " + detail::to_text(turn_radius) +
                           " (a loiter tighter than the aircraft can turn)");
  if (turns < 1) detail::fail_field("turns", turns, "must be at least 1 (every AOI is circled at least once)");
  if (turns > 1000) detail::fail_field("turns", turns, "must be at most 1000");
}

void LoiterCamera::validate() const {
  if (!(fov_deg > 0.0 && fov_deg < 180.0)) detail::fail_field("camera.fov_deg", fov_deg, "must be in (0, 180) degrees");
  if (!(max_gimbal_deg >= 0.0 && max_gimbal_deg < 90.0))
    detail::fail_field("camera.max_gimbal_deg", max_gimbal_deg, "must be in [0, 90) degrees");
  if (!(0.5 * fov_deg + max_gimbal_deg < 90.0))
    detail::fail_field("camera.max_gimbal_deg", max_gimbal_deg,
                       "plus half the field of view must stay below 90 degrees (the footprint would not be bounded)");
  require_length(altitude, "camera.altitude");
}

void LoiterCoverageOptions::validate() const {
  if (!(threshold > 0.0 && threshold <= 1.0)) detail::fail_field("threshold", threshold, "must be in (0, 1]");
  require_time_step(dt, "dt");
  require_positive(gravity, "gravity");
}

void LoiterProblem::validate() const {
  parameters.validate();
  if (aois.empty()) throw Error("aois: at least one area of interest (AOI centre) is needed");
  if (aois.size() > kMaxLoiterAois)  // the overlap check and the order search grow as n^2
    detail::fail_field("aois", std::to_string(aois.size()) + " centres", "at most " + std::to_string(kMaxLoiterAois) + " AOIs");
  require_coordinate(start.x(), "start[0]");
  require_coordinate(start.y(), "start[1]");
  require_coordinate(end.x(), "end[0]");
  require_coordinate(end.y(), "end[1]");
  const double R = parameters.aoi_radius;
  for (std::size_t i = 0; i < aois.size(); ++i) {
    const std::string field = "aois[" + std::to_string(i) + "]";
    require_coordinate(aois[i].x(), field + "[0]");
    require_coordinate(aois[i].y(), field + "[1]");
    for (std::size_t j = 0; j < i; ++j) {
      const double d = (aois[i] - aois[j]).norm();
      if (d < 2.0 * R)
        detail::fail_field(field, point_text(aois[i]),
                           "its loiter circle (radius " + detail::to_text(R) + ") overlaps that of aois[" +
                               std::to_string(j) + "] = " + point_text(aois[j]) + ": the centres are " +
                               detail::computed_text(d) + " m apart, at least 2 R = " + detail::computed_text(2.0 * R) +
                               " are needed");
    }
    const auto outside = [&](const char* name, const Vec2& point) {
      const double d = (point - aois[i]).norm();
      if (d < R)
        detail::fail_field(name, point_text(point),
                           "lies inside the loiter circle of " + field + " = " + point_text(aois[i]) + " (" +
                               detail::computed_text(d) + " m from its centre, radius " + detail::to_text(R) + ")");
    };
    outside("start", start);
    outside("end", end);
  }
}

}  // namespace vistrack
