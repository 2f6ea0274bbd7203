// Parameter structs shared by planning, guidance and simulation. Every default lives here, and
// nowhere else (the Python side reads them from the bindings). Each validate() throws Error
// naming the field and the allowed range (vistrack/limits.hpp: coordinates |v| <= 1e7 m, lengths
// [1e-6, 1e7] m, speeds [1e-6, 1e4] m/s); input is validated once, where it enters the API.
#pragma once

#include <cstddef>
#include <optional>
#include <utility>

#include "vistrack/geometry.hpp"

namespace vistrack {

// The Dubins vehicle (1): constant speed v, minimum turn radius r_min = v / u_psi_max, altitude.
struct Uav {
  double speed = 20.0;             // v, m/s
  double min_turn_radius = 50.0;   // r_min, m
  double altitude = 300.0;         // h_UAV: world z of the flight plane, m (height above a ground at z = 0)
  void validate() const;           // throws Error naming the field
};

// The point of interest (section III): its speed along its road path, and for points given
// without z (the CLI's --points) its height above the surface under it, as in the data's paths.
struct PoiMotion {
  double speed = 5.0;    // v_g, m/s
  double height = 0.5;   // m above the surface
};

// The line-of-sight sensor (section III.D).
struct Sensor {
  double d_max = 400.0;                                 // maximum viewing distance, m
  std::optional<std::pair<double, double>> altitude_band;  // feasible airspace (h_lo, h_hi), m
  void validate() const;
};

// Adaptive placement of visibility volumes (section IV.B).
struct Planning {
  double spacing = 20.0;         // initial spacing of VVs along the path, m
  double cutoff = 20e6;          // d_cutoff, m^3
  double resolution_deg = 1.0;   // angular step of the VV ray grid, degrees
  double min_spacing = 1.0;      // never insert VVs closer than this, m
  int max_depth = 8;             // maximum number of halvings of one initial interval
  // Algorithm 1 keeps |dR/dt| <= (1 - rate_margin)(v - v_g). 0 is Lemma 5's limit, as in the paper;
  // there the attraction gain (68) of the guidance vanishes and the radial error is not corrected.
  double rate_margin = 0.0;
  // The planner refuses, before computing any VV, a plan whose worst case (every interval halved
  // to min_spacing or max_depth) needs more VVs than this: about path length / min_spacing VVs,
  // ~4 MB each on a 1-degree grid (estimate_work in orbit.hpp). Raise it explicitly for long paths.
  std::size_t max_volumes = 20000;
  void validate() const;
};

// Guidance (section V): circulation beta, heading gain k_psi, direction of travel.
struct Control {
  double beta = 0.025;
  double k_psi = 20.0;
  Circulation direction = Circulation::CounterClockwise;
  void validate() const;
};

// Closed-loop integration (section VI).
struct SimulationOptions {
  double rtol = 1e-6;
  double atol = 1e-8;
  double max_step = 1.0;      // s
  double output_step = 0.1;   // s between output samples
  void validate() const;
};

}  // namespace vistrack
