#include "vistrack/parameters.hpp"

#include "vistrack/error.hpp"

namespace vistrack {

void Uav::validate() const {
  require_positive(speed, "uav.speed");
  require_positive(min_turn_radius, "uav.min_turn_radius");
  require_finite(altitude, "uav.altitude");
}

void Sensor::validate() const {
  require_positive(d_max, "sensor.d_max");
  if (altitude_band) {
    require_finite(altitude_band->first, "sensor.altitude_band[0]");
    require_finite(altitude_band->second, "sensor.altitude_band[1]");
    if (!(altitude_band->first < altitude_band->second))
      detail::fail_field("sensor.altitude_band", detail::to_text(altitude_band->first) + ", " +
                                                     detail::to_text(altitude_band->second),
                         "the lower altitude must be below the upper one");
  }
}

void Planning::validate() const {
  require_positive(spacing, "planning.spacing");
  require_positive(cutoff, "planning.cutoff");
  if (!(resolution_deg >= 0.1 && resolution_deg <= 30.0))
    detail::fail_field("planning.resolution_deg", resolution_deg, "must be in [0.1, 30] degrees (the VV grid's range)");
  require_positive(min_spacing, "planning.min_spacing");
  if (max_depth < 0 || max_depth > 30)
    detail::fail_field("planning.max_depth", max_depth, "must be in [0, 30]");
  if (!(rate_margin >= 0.0 && rate_margin < 1.0))
    detail::fail_field("planning.rate_margin", rate_margin, "must be in [0, 1) (a fraction of v - v_g)");
  if (locus != Locus::smooth && locus != Locus::paper)
    detail::fail_field("planning.locus", static_cast<int>(locus), "must be \"smooth\" or \"paper\"");
  require_non_negative(tracking_margin, "planning.tracking_margin");
  require_positive(check_spacing, "planning.check_spacing");
  require_positive(check_min_spacing, "planning.check_min_spacing");
  if (!(check_min_spacing <= check_spacing))
    detail::fail_field("planning.check_min_spacing", check_min_spacing,
                       "must not exceed planning.check_spacing = " + detail::to_text(check_spacing));
  if (!(turn_share > 0.0 && turn_share < 1.0))
    detail::fail_field("planning.turn_share", turn_share, "must be in (0, 1) (a share of the free turn rate)");
}

std::string to_string(Locus locus) { return locus == Locus::paper ? "paper" : "smooth"; }

Locus locus_from_string(const std::string& text, const std::string& field) {
  if (text == "smooth") return Locus::smooth;
  if (text == "paper") return Locus::paper;
  detail::fail_field(field, "\"" + text + "\"", "must be \"smooth\" or \"paper\"");
}

void Control::validate() const {
  require_positive(beta, "control.beta");
  require_positive(k_psi, "control.k_psi");
}

void SimulationOptions::validate() const {
  require_positive(rtol, "simulation.rtol");
  require_positive(atol, "simulation.atol");
  require_positive(max_step, "simulation.max_step");
  require_positive(output_step, "simulation.output_step");
}

}  // namespace vistrack
