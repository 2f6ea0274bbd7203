// Validation of the orbit planner's inputs (orbit_parameters.hpp).
#include "vistrack/orbit_parameters.hpp"

#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"

namespace vistrack {

void Planning::validate() const {
  require_length(spacing, "planning.spacing");
  if (!(cutoff > 0.0 && cutoff <= limits::kMaxVolume))
    detail::fail_field("planning.cutoff", cutoff, "must be a finite number in (0, 1e21] m^3");
  if (!(resolution_deg >= 0.1 && resolution_deg <= 30.0))
    detail::fail_field("planning.resolution_deg", resolution_deg, "must be in [0.1, 30] degrees (the VV grid's range)");
  require_length(min_spacing, "planning.min_spacing");
  if (max_depth < 0 || max_depth > 30)
    detail::fail_field("planning.max_depth", max_depth, "must be in [0, 30]");
  if (!(rate_margin >= 0.0 && rate_margin < 1.0))
    detail::fail_field("planning.rate_margin", rate_margin, "must be in [0, 1) (a fraction of v - v_g)");
  if (max_volumes < 1) detail::fail_field("planning.max_volumes", max_volumes, "must be at least 1");
  if (locus != Locus::smooth && locus != Locus::paper)
    detail::fail_field("planning.locus", static_cast<int>(locus), "must be \"smooth\" or \"paper\"");
  require_in_range(tracking_margin, 0.0, limits::kMaxLength, "m", "planning.tracking_margin");
  require_length(check_spacing, "planning.check_spacing");
  require_length(check_min_spacing, "planning.check_min_spacing");
  if (!(check_min_spacing <= check_spacing))
    detail::fail_field("planning.check_min_spacing", check_min_spacing,
                       "must not exceed planning.check_spacing = " + detail::to_text(check_spacing));
  if (!(turn_share > 0.0 && turn_share < 1.0))
    detail::fail_field("planning.turn_share", turn_share, "must be in (0, 1) (a share of the free turn rate)");
  require_in_range(radius_smoothing, 0.0, 1e3, "", "planning.radius_smoothing");
}

}  // namespace vistrack
