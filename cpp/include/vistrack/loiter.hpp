// Loiter planning over areas of interest (AOIs): Wilhelm, Clem, Eberhart, "Direct Entry Minimal
// Path UAV Loitering Path Planning" (Aerospace 2017, seeds/loitering_path_planning.txt).
//
// Three planners, each an exact path of straight lines and circular arcs (radius r for turns,
// radius R around an AOI centre, the POI), starting and ending at given points:
//  * Fly-Through (3.1): straight to the POI, three quarters of a turn at r and a straight r to
//    the offset point (the Dubins RSR/LSL word to the loiter circle: exactly 3/4 turn + r when
//    R = r), the loiter, then a turn at r until the next POI is straight ahead. CW/CCW from the
//    position of the next AOI.
//  * TLPP (3.2): tangent entry to the first AOI (eqs. 1-7), loiter, departure and entry on the
//    inner tangents between consecutive loiter circles (eqs. 8-12), the direction alternating.
//  * LDLPP (3.3): transit on the line between POIs, a CW entry turn from D_Entry (15), a CCW
//    loiter of at least `turns` full circles until the exit point, a CW exit turn onto the line to
//    the next POI.
// Beyond the paper: LdlppBest mirrors LDLPP at every AOI where that loiters less (a CCW entry
// turn, a CW loiter, a CCW exit; the transit is the same either way, so each AOI chooses alone);
// TlppBest plans TLPP with each first direction and keeps the shorter.
// Every AOI is circled at least `turns` times. The printed equations' slips are fixed where they
// are implemented (src/loiter/tangents.cpp, ldlpp.cpp) and tested against the printed forms.
//
// Coverage (sections 2.2, 4.1): a conic camera on a roll gimbal; its ground footprint is an
// ellipse, computed exactly from altitude and attitude (bank of the coordinated turn plus the
// gimbal); an AOI is covered at a step when >= 75 % of its disk lies in it (exact ellipse-disk
// intersection area).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "vistrack/dubins.hpp"
#include "vistrack/geometry.hpp"
#include "vistrack/loiter_parameters.hpp"

namespace vistrack {

// The printed planners, and beyond the paper: LDLPP with each AOI's loiter direction chosen
// (the printed one always loiters counter-clockwise), TLPP with both first directions tried (the
// printed rule picks the longer plan in most random layouts).
enum class LoiterMethod : std::uint8_t { FlyThrough = 0, Tlpp = 1, Ldlpp = 2, TlppBest = 3, LdlppBest = 4 };
template <>
struct EnumNames<LoiterMethod> {
  static constexpr const char* field = "method";
  static constexpr EnumName<LoiterMethod> names[] = {{"fly_through", LoiterMethod::FlyThrough},
      {"tlpp", LoiterMethod::Tlpp}, {"ldlpp", LoiterMethod::Ldlpp}, {"tlpp_best", LoiterMethod::TlppBest},
      {"ldlpp_best", LoiterMethod::LdlppBest}, {"fly-through", LoiterMethod::FlyThrough},
      {"flythrough", LoiterMethod::FlyThrough}};
};

// The visiting order: as given, or the one with the shortest plan (exact branch and bound up to
// kExactOrderLimit AOIs, 2-opt and or-opt moves above).
enum class LoiterOrder : std::uint8_t { Given = 0, Best = 1 };
constexpr int kExactOrderLimit = 9;
template <>
struct EnumNames<LoiterOrder> {
  static constexpr const char* field = "order";
  static constexpr EnumName<LoiterOrder> names[] = {{"given", LoiterOrder::Given}, {"best", LoiterOrder::Best}};
};

enum class SegmentKind : std::uint8_t { Line = 0, Arc = 1 };
// What a piece of the path is for. Transit: straight legs between AOIs (and from the start, to
// the end). Entry: turns and lines at r that bring the aircraft onto a loiter circle (Fly-Through's
// three-quarter turn and line to the offset point, LDLPP's entry turn). Loiter: arcs on an AOI's
// loiter circle (radius R). Exit: turns at r that leave it (Fly-Through's turn towards the next
// POI, LDLPP's exit turn). Transit time is the time off the loiter circles.
enum class SegmentRole : std::uint8_t { Transit = 0, Entry = 1, Loiter = 2, Exit = 3 };
template <>
struct EnumNames<SegmentKind> {
  static constexpr const char* field = "kind";
  static constexpr EnumName<SegmentKind> names[] = {{"line", SegmentKind::Line}, {"arc", SegmentKind::Arc}};
};
template <>
struct EnumNames<SegmentRole> {
  static constexpr const char* field = "role";
  static constexpr EnumName<SegmentRole> names[] = {{"transit", SegmentRole::Transit}, {"entry", SegmentRole::Entry},
      {"loiter", SegmentRole::Loiter}, {"exit", SegmentRole::Exit}};
};

// One piece of a plan. Headings are continuous along the plan (not wrapped).
struct LoiterSegment {
  SegmentKind kind = SegmentKind::Line;
  SegmentRole role = SegmentRole::Transit;
  Vec2 start = Vec2::Zero();
  Vec2 end = Vec2::Zero();
  double start_heading = 0.0;  // rad
  double end_heading = 0.0;    // rad
  // Arcs only (lines: centre 0, radius 0, sweep 0).
  Vec2 center = Vec2::Zero();
  double radius = 0.0;
  Circulation direction = Circulation::CounterClockwise;
  double sweep = 0.0;          // angle turned, rad (>= 0)
  double length = 0.0;         // m
  int aoi = -1;                // the AOI this piece enters, circles or leaves (index into aois), -1 transit

  // Configuration after arc length s in [0, length] (not clamped).
  Configuration at(double s) const;
  // Signed curvature: +1/radius counter-clockwise, -1/radius clockwise, 0 on lines.
  double curvature() const;
};

// The input common to every method.
struct LoiterProblem {
  std::vector<Vec2> aois;   // AOI centres (POIs), m
  Vec2 start = Vec2::Zero();
  Vec2 end = Vec2::Zero();
  LoiterParameters parameters;
  // Error naming the field: no AOI, a non-finite coordinate, aoi_radius < turn_radius, loiter
  // circles that overlap (centres closer than 2 R), start or end inside a loiter circle, and the
  // parameters' own checks.
  void validate() const;
};

// Samples of a plan at t = 0, dt, 2 dt, ... (and the end).
struct LoiterSamples {
  std::vector<double> t;          // s
  Points3 poses;                  // (n, 3): x, y, psi (continuous)
  std::vector<double> turn_rate;  // rad/s on the segment the sample lies on (the one starting there)
  std::vector<int> segment;       // index of that segment
};

struct LoiterPlan {
  LoiterMethod method = LoiterMethod::Ldlpp;
  LoiterProblem problem;
  std::vector<int> order;                 // visiting order: indices into problem.aois
  std::vector<Circulation> directions;    // loiter direction of each AOI (indexed like aois)
  std::vector<LoiterSegment> segments;
  std::vector<double> segment_offsets;    // arc length at the start of each segment, m
  double length = 0.0;                    // m
  double flight_time = 0.0;               // s, length / speed
  double loiter_time = 0.0;               // s on the loiter circles (role Loiter)
  double transit_time = 0.0;              // s off them: flight_time - loiter_time
  std::vector<double> loiter_sweep;       // angle flown on each AOI's loiter circle, rad (by aoi)

  // Configuration at time t in [0, flight_time] (the end exactly at flight_time).
  Configuration at_time(double t) const;
  // Index of the segment flown at time t (the later one at a boundary; the last at the end).
  std::size_t segment_at_time(double t) const;
  // Rows at t = k dt, k = 0, 1, ... while k dt <= flight_time; with include_end the end point is
  // appended when the flight time is not a multiple of dt.
  LoiterSamples sample_states(double dt, bool include_end = true) const;
  Points3 sample(double dt) const { return sample_states(dt, true).poses; }
};

// Plans with the given method. order Best searches the visiting order (see LoiterOrder).
// Throws Error naming the field on bad input, or when the geometry does not allow the method:
// LDLPP needs its lines long enough for the entry and exit turns (start and end at least D_Entry
// from their POI, consecutive POIs at least 2 D_Entry apart).
LoiterPlan plan_loiter(const LoiterProblem& problem, LoiterMethod method, LoiterOrder order = LoiterOrder::Given);
// Plans in this visiting order (a permutation of 0..n-1).
LoiterPlan plan_loiter_in_order(const LoiterProblem& problem, LoiterMethod method, const std::vector<int>& order);
// The path length of a visiting order, +infinity when the method cannot fly it (no Error).
double loiter_order_length(const LoiterProblem& problem, LoiterMethod method, const std::vector<int>& order);
// The visiting order with the shortest plan; exact (branch and bound) when exact is true, else
// the 2-opt / or-opt heuristic. Error when no order is feasible.
std::vector<int> best_loiter_order(const LoiterProblem& problem, LoiterMethod method, bool exact);

// LDLPP's entry/departure angle (14): alpha_ED = asin(r / (R + r)), the angle at the POI between
// the transit line and the centre of the entry turn (tangent externally to the loiter circle).
double ldlpp_entry_angle(double aoi_radius, double turn_radius);
// LDLPP's entry distance (15): D_Entry = (R + r) cos(alpha_ED) = sqrt(R^2 + 2 R r).
double ldlpp_entry_distance(double aoi_radius, double turn_radius);
// The heading change of LDLPP's entry (and exit) turn: pi/2 - alpha_ED. The paper's (16) stops the
// turn at alpha_ED, which leaves the aircraft off the loiter circle (see ldlpp.cpp).
double ldlpp_turn_angle(double aoi_radius, double turn_radius);

// ---- Camera footprint and coverage ------------------------------------------------------------

// The footprint of a conic camera on flat ground: an ellipse. Its axes are along the heading
// (semi_along) and across it (semi_across), its centre offset to the left of the nadir point.
struct Footprint {
  Vec2 center = Vec2::Zero();
  Vec2 along = Vec2(1.0, 0.0);  // unit vector of the heading
  double semi_along = 0.0;      // m
  double semi_across = 0.0;     // m
  double area() const;          // pi * semi_along * semi_across
};

// Bank of a coordinated turn at this turn rate: atan(v psi_dot / g), positive to the left (left
// turns bank left).
double bank_angle(double speed, double turn_rate, double gravity = kStandardGravity);

// The camera axis' tilt to the left of vertical for a bank (positive left) and a gimbal angle
// (positive left): the gimbal angle itself when the camera is levelled; on the body, gimbal - bank,
// because banking left (left wing down) turns the belly, and a camera under it, to the right.
double camera_tilt(const LoiterCamera& camera, double bank, double gimbal);

// Footprint of the camera at the pose, tilted `tilt` rad to the left of vertical (bank plus
// gimbal), at camera.altitude. With half-angle beta = fov/2, k = cos^2 beta - sin^2 tilt > 0,
// h the altitude: centre offset h sin(tilt) cos(tilt) / k to the left, semi-axes
// h sin(beta) / sqrt(k) along and h sin(beta) cos(beta) / k across (the cone's plane section).
// Error when |tilt| + beta >= 90 degrees (the section is not bounded).
Footprint camera_footprint(const LoiterCamera& camera, const Configuration& pose, double tilt);

// Exact area of (ellipse with semi-axes a along x and b along y, centred at the origin) intersected
// with (the disk of radius rho centred at (cx, cy)): the boundary integral over the arcs of each
// curve inside the other; the crossings are isolated with Lipschitz bounds and refined by safeguarded Newton steps.
double ellipse_disk_intersection_area(double a, double b, double cx, double cy, double rho);
// Area of the disk (center, rho) inside the footprint.
double footprint_disk_area(const Footprint& footprint, const Vec2& center, double rho);

struct LoiterCoverage {
  double time = 0.0;                  // s: sum over AOIs of the covered time steps times dt
  std::vector<double> time_per_aoi;   // s, by AOI
  // The paper's "AOI coverage (m^2)": at each step, the area of every covered AOI that lies in
  // the footprint, summed over steps and AOIs, times dt in seconds (m^2 s; m^2 at the paper's 1 s).
  double area = 0.0;
  std::vector<double> area_per_aoi;
  // Per step (n) and AOI (m), row-major: the fraction of the AOI's disk in the footprint.
  std::vector<double> fraction;
  std::vector<int> pointed;           // per step: the AOI most in view (-1: none aimed at)
  std::vector<double> gimbal;         // per step: gimbal angle, rad, positive to the left
  std::vector<double> bank;           // per step: bank angle, rad, positive to the left
  std::vector<double> tilt;           // per step: camera axis tilt to the left of vertical, rad
  std::size_t steps = 0;
  std::size_t aoi_count = 0;
};

// Coverage of sampled poses, one every options.dt, with the turn rate at each (for the bank). At
// each step the gimbal (within +-max_gimbal) takes the angle at which the most AOIs have at least
// options.threshold of their disk in the footprint, and among those angles the one with the most
// of those AOIs' area in view (with a single AOI: the angle that holds most of it); when no AOI can
// reach the threshold, the angle that holds the best-held AOI best. AOIs with at least the
// threshold in that footprint count as covered. Above a threshold of 1/2 only AOIs whose centre
// some angle brings into view are aimed at (the others cannot count); with none in reach the
// gimbal levels the camera. Steps are evaluated in parallel (TBB).
LoiterCoverage loiter_coverage(const Points3& poses, const std::vector<double>& turn_rates,
                               const std::vector<Vec2>& aois, double aoi_radius, double speed,
                               const LoiterCamera& camera = {}, const LoiterCoverageOptions& options = {});
// Coverage of a plan sampled at options.dt (t = 0, dt, ... up to the flight time; the exact turn
// rate of each sample's segment).
LoiterCoverage loiter_coverage(const LoiterPlan& plan, const LoiterCamera& camera = {},
                               const LoiterCoverageOptions& options = {});

}  // namespace vistrack
