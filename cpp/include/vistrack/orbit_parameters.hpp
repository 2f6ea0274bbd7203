// The orbit planner's inputs (the POI's motion, VV placement, the locus), with their defaults.
// Each validate() throws Error naming the field and its allowed range (vistrack/limits.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "vistrack/error.hpp"
#include "vistrack/visibility_parameters.hpp"

namespace vistrack {

// The point of interest (section III): its speed along its road path, and for points given
// without z (the CLI's --points) its height above the surface under it, as in the data's paths.
struct PoiMotion {
  double speed = 5.0;    // v_g, m/s
  double height = 0.5;   // m above the surface
};

// Which reference R(t) the orbit planner builds.
enum class Locus : std::uint8_t {
  // Beyond the paper: R(t) checked against MaxRadius along the whole POI path (not only at the
  // samples), kept tracking_margin inside it, and C1 with a bounded d2R/dt2 that the guidance
  // feeds forward (the default).
  smooth = 0,
  // The paper's: Algorithm 1's radii at the samples, piecewise linear between them, no check.
  paper = 1,
};
template <>
struct EnumNames<Locus> {
  static constexpr const char* field = "planning.locus";
  static constexpr EnumName<Locus> names[] = {{"smooth", Locus::smooth}, {"paper", Locus::paper}};
};

// Adaptive placement of visibility volumes (section IV.B) and the locus built on them (IV.C).
struct Planning {
  double spacing = 20.0;         // initial spacing of VVs along the path, m
  double cutoff = 20e6;          // d_cutoff, m^3
  double resolution_deg = kDefaultResolutionDeg;  // angular step of the VV ray grid, degrees
  double min_spacing = 1.0;      // never insert VVs closer than this, m
  int max_depth = 8;             // maximum number of halvings of one initial interval
  // Algorithm 1 keeps |dR/dt| <= (1 - rate_margin)(v - v_g). 0 is Lemma 5's limit, as in the paper;
  // there the attraction gain (68) of the guidance vanishes and the radial error is not corrected.
  double rate_margin = 0.0;
  // The planner refuses, before computing any VV, a plan whose worst case (every interval halved
  // to min_spacing or max_depth) needs more VVs than this: about path length / min_spacing VVs,
  // ~4 MB each on a 1-degree grid (estimate_work in orbit.hpp). Raise it explicitly for long paths.
  std::size_t max_volumes = 20000;
  Locus locus = Locus::smooth;
  // Smooth locus only. R(t) stays this far inside MaxRadius, so that the flown path, which
  // leaves the reference by the tracking error, stays in the visibility polygon too (m; the
  // closed loop's largest radial error after capture on the examples: 0.08 m campus, 0.17 m
  // paper_small, 0.8 m demo, 1.14 m paper_slow; bench/locus_table.py).
  double tracking_margin = 1.0;
  // The locus check computes MaxRadius every check_spacing m of POI travel (plus at the samples),
  // then halves the intervals where R(t) touches the bound down to check_min_spacing (m).
  double check_spacing = 10.0;
  double check_min_spacing = 1.0;
  // Share of the turn rate that Lemma 6 leaves free on the orbit, v / r_min - v (1 + v_g/v)^2 / R,
  // that the feed-forward of d2R/dt2 may use; the rest stays for the feedback terms of (86).
  double turn_share = 0.5;
  // Beyond the paper: the smooth locus maximises the mean R less a d2R/dt2 penalty, so that it does
  // not zig-zag where the ceiling leaves the largest-area R free (dR/dt flipping sign every knot,
  // d2R/dt2 swinging +-3 m/s^2 every 0.19 s on the demo: its feed-forward made a roll-limited
  // aircraft reverse its bank 1.15 times a second). Holding the largest d2R/dt2 the turn budget
  // allows costs radius_smoothing / 2 of the ceiling's top radius; 0 = the largest-area R (the
  // plain linear program). 0.3: bench/vehicle_models.py and docs/vehicle.md.
  double radius_smoothing = 0.3;
  void validate() const;
};

}  // namespace vistrack
