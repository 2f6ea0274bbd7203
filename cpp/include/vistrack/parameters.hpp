// Parameter structs shared by planning, guidance and simulation. Every default lives here, and
// nowhere else (the Python side reads them from the bindings). Each validate() throws Error
// naming the field and the allowed range (vistrack/limits.hpp: coordinates |v| <= 1e7 m, lengths
// [1e-6, 1e7] m, speeds [1e-6, 1e4] m/s); input is validated once, where it enters the API.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
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

// Which reference R(t) the orbit planner builds.
enum class Locus : std::uint8_t {
  // Beyond the paper: R(t) checked against MaxRadius along the whole POI path (not only at the
  // samples), kept tracking_margin inside it, and C1 with a bounded d2R/dt2 that the guidance
  // feeds forward (the default).
  smooth = 0,
  // The paper's: Algorithm 1's radii at the samples, piecewise linear between them, no check.
  paper = 1,
};
std::string to_string(Locus locus);                                        // "smooth" / "paper"
Locus locus_from_string(const std::string& text, const std::string& field = "planning.locus");

// Adaptive placement of visibility volumes (section IV.B) and the locus built on them (IV.C).
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
  Locus locus = Locus::smooth;
  // Smooth locus only. R(t) stays this far inside MaxRadius, so that the flown path, which
  // leaves the reference by the tracking error, stays in the visibility polygon too (m; the
  // closed loop's largest radial error after capture on the examples: 0.12 m campus and
  // paper_small, 0.9 m demo, 1.06 m paper_slow; bench/locus_table.py).
  double tracking_margin = 1.0;
  // The locus check computes MaxRadius every check_spacing m of POI travel (plus at the samples),
  // then halves the intervals where R(t) touches the bound down to check_min_spacing (m).
  double check_spacing = 10.0;
  double check_min_spacing = 1.0;
  // Share of the turn rate that Lemma 6 leaves free on the orbit, v / r_min - v (1 + v_g/v)^2 / R,
  // that the feed-forward of d2R/dt2 may use; the rest stays for the feedback terms of (86).
  double turn_share = 0.5;
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

// ---- flight (issue 13): wind, the flight integrator, the paper's feedback law (5) -------------

// Dryden turbulence on top of the constant wind (MIL-F-8785C, horizontal components; see
// flight.hpp for the spectra). Units are those of the flight (SI, or the paper's nondimensional
// units): intensity in speed units, length_scale in length units. mil_f_8785c_gusts() in
// flight.hpp derives them from altitude and the wind speed at 20 ft.
struct Gusts {
  std::uint64_t seed = 0;      // the same seed gives the same gust history
  double intensity = 1.0;      // sigma_u = sigma_v, RMS of each horizontal component (speed units)
  double length_scale = 200.0; // L_u = L_v (length units)
  double sample_step = 0.0;    // s between precomputed samples; 0: L / (20 V), V the airspeed
  void validate() const;
};

// Wind the vehicle does not know: constant (east, north) plus optional Dryden gusts.
struct Wind {
  double east = 0.0;   // speed units
  double north = 0.0;
  std::optional<Gusts> gusts;
  void validate() const;  // finite components; airspeed checks happen where the vehicle is known
};

// How fly() advances the vehicle: the paper's discrete update, or Dormand-Prince 5(4).
enum class FlightIntegration : std::uint8_t { Discrete = 0, Continuous = 1 };

struct FlightOptions {
  FlightIntegration integration = FlightIntegration::Discrete;
  double dt = 0.02;          // s. Discrete: the step (psi_max = v dt / R). Continuous: output
                             // spacing and largest step.
  double max_time = 3600.0;  // s after the start; the flight stops there unless the guidance is done
  double rtol = 1e-9;        // continuous only
  double atol = 1e-12;       // continuous only
  void validate() const;
};

// Gains of the illustrative feedback law (5) of the Dubins waypoint navigation paper (section 3.1).
struct LineFeedbackGains {
  double g = 0.1;    // on the cross-track distance s
  double h = 5.25;   // on its change over one law step, s_dot dt
  void validate() const;
};

// ---- waypoint_nav (issue 13): Dubins waypoint navigation against classical WN ------------------

// Fuel per unit length (1): w_a on arcs, w_s on straights; w_a = w_s = 1 is the shortest path (2).
struct FuelWeights {
  double arc = 1.0;       // w_a
  double straight = 1.0;  // w_s
  void validate() const;
};

enum class NavigationMethod : std::uint8_t { Dubins = 0, Classical = 1 };  // "dwn", "wn"

// One navigation flight; the defaults are the paper's section 3 (R 0.7, v 0.8, dt 0.02, and the
// gains g 0.1, h 5.25 of LineFeedbackGains).
struct WaypointNavOptions {
  NavigationMethod method = NavigationMethod::Dubins;
  double turn_radius = 0.7;   // R: the vehicle's minimum turn radius and DWN's turning circles
  double speed = 0.8;         // v
  double dt = 0.02;           // the law's step (and the discrete flight's)
  LineFeedbackGains gains;
  std::optional<double> waypoint_radius;  // WN's R_WP; unset: R. DWN has none (set: an Error)
  FuelWeights weights;
  FlightIntegration integration = FlightIntegration::Discrete;
  std::optional<double> max_time;  // unset: 3 (route length + 2 pi R per waypoint) / v
  void validate() const;
};

// ---- path following (issue 14): a guidance that flies a path of lines and arcs -------------

// Gains of PathFollower (flight.hpp, Path following), scaled by the vehicle so one set fits every size:
// the cross-track correction steers at atan(e / (lookahead_radii R)) back to the path, the heading
// loop closes at heading_gain v / R per radian. With these the linearised cross-track error is a
// second-order system with damping 0.5 sqrt(heading_gain * lookahead_radii) = 0.87.
struct PathFollowingGains {
  double lookahead_radii = 1.0;
  double heading_gain = 3.0;
  void validate() const;
};

// ---- loiter (issue 14): loiter planners over areas of interest, camera coverage -------------
// Wilhelm, Clem, Eberhart, "Direct Entry Minimal Path UAV Loitering Path Planning" (2017),
// section 4.1: Raven RQ-11B, turn radius 46 m at 12 m/s, AOI radius = turn radius, one loiter.

struct LoiterParameters {
  double turn_radius = 46.0;  // r, m: turns outside the loiter (minimum turn radius)
  double speed = 12.0;        // v, m/s (constant airspeed)
  double aoi_radius = 46.0;   // R, m: the loiter circle around each AOI centre (POI); R >= r
  int turns = 1;              // full loiters flown around each AOI (at least 1)
  void validate() const;      // throws Error naming the field
};

// The camera of section 2.2: a circular (conic) field of view, full angle fov_deg, on a one-axis
// (roll) gimbal of +-max_gimbal_deg. altitude: height above the AOIs' ground plane. 61 m is the
// height at which the paper's nadir footprint is 6,638 m^2 (pi (61 tan 37 deg)^2 = 6,637.9 m^2).
// levelled: the gimbal angle is measured from the vertical, as the paper states (a gimbal that
// also takes out the bank); false: a roll gimbal under the banked body, whose belly faces out of
// every turn, so the axis tilts by gimbal - bank (see camera_tilt in loiter.hpp).
struct LoiterCamera {
  double fov_deg = 74.0;
  double max_gimbal_deg = 25.0;
  double altitude = 61.0;
  bool levelled = true;
  void validate() const;
};

// Section 4.1's coverage rule: an AOI counts as covered at a time step when at least `threshold`
// of its disk lies in the footprint; time steps dt apart (the paper samples at 1 s).
struct LoiterCoverageOptions {
  double threshold = 0.75;
  double dt = 1.0;          // s
  double gravity = 9.80665; // m/s^2, for the bank angle of a coordinated turn
  void validate() const;
};

// ---- follow (issue 15): following a ground vehicle (sinusoidal and loiter modes) ---------------

enum class LoiterPattern : std::uint8_t { Circle = 0, Rose = 1 };  // "circle" | "rose"
enum class OffsetReference : std::uint8_t { North = 0, Heading = 1 };  // "north" | "heading"

// The follow planner's settings. Angles in radians; speeds are taken from the Uav (airspeed v,
// minimum turn radius r_min, altitude of the camera).
struct FollowParameters {
  // Sinusoidal mode (section II). T, the time the vehicle takes to travel one period D = v_g T.
  double period = 30.0;               // s
  // The tightest planned turn is turn_margin * r_min: the period is raised where the sinusoid's
  // peak curvature A' 2 pi / D would exceed 1 / (turn_margin r_min), and the loiter circle's
  // radius follows Lemma 6 of the tracking paper with this radius.
  double turn_margin = 1.25;
  // Loiter above the threshold h_sigma of the speed ratio sigma = v_p / v_g, with a hysteresis
  // band of this full width centred on it: loiter from sigma > h + band / 2, back to the
  // sinusoid below h - band / 2.
  double threshold = 3.0;             // h_sigma (the paper's ~3)
  double hysteresis = 0.5;            // full band width, < threshold
  LoiterPattern loiter_pattern = LoiterPattern::Circle;  // Fig. 3
  // Circle: its radius. Rose: the largest distance from the centre. 0: the smallest flyable
  // (circle: turn_margin r_min (1 + 1 / (h - band / 2))^2; rose: 3 times that turn radius).
  double loiter_radius = 0.0;         // m
  Circulation loiter_direction = Circulation::CounterClockwise;
  // Offset vector (Fig. 3): distance L and angle theta. reference "north": theta is fixed to the
  // map (radians counter-clockwise from east); "heading": counter-clockwise from the vehicle's
  // heading (0 ahead, pi/2 to its left).
  double offset_distance = 0.0;       // m
  double offset_angle = 0.0;          // rad
  OffsetReference offset_reference = OffsetReference::Heading;
  // Wind compensation (section III): plan in the air mass with the wind estimate (see follow.hpp).
  bool wind_compensation = true;
  // Waypoints are generated every update_period (section V: 1 Hz), each one the desired position
  // update_period later.
  double update_period = 1.0;         // s
  void validate() const;
};

// How a follow run is flown by the flight layer at step dt, steered by the
// waypoint paper's feedback law (5) with its gains (LineFeedbackGains, given for the paper's
// turn radius 0.7) rescaled to the UAV's r_min, since g and h multiply lengths.
struct FollowFlight {
  // The paper's discrete update, or Dormand-Prince (then updates happen at the first accepted
  // step ending at or after each update time, at most dt late).
  FlightIntegration integration = FlightIntegration::Discrete;
  double dt = 0.02;        // s, flight step and law step
  double max_time = 0.0;   // s after the start; 0: until the vehicle's track ends
  void validate() const;
};

}  // namespace vistrack
