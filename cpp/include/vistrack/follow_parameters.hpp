// The follow planner's parameters, with their defaults.
// Each validate() throws Error naming the field and its allowed range (vistrack/limits.hpp).
#pragma once

#include <cstdint>

#include "vistrack/dubins_parameters.hpp"
#include "vistrack/flight_parameters.hpp"
#include "vistrack/geometry.hpp"

namespace vistrack {

enum class LoiterPattern : std::uint8_t { Circle = 0, Rose = 1 };
template <>
struct EnumNames<LoiterPattern> {
  static constexpr const char* field = "loiter_pattern";
  static constexpr EnumName<LoiterPattern> names[] = {{"circle", LoiterPattern::Circle}, {"rose", LoiterPattern::Rose}};
};

// How the planner chooses its pattern at each update. "paper": the sinusoid below the threshold,
// the loiter above it (sections II-III). "standoff": the vector field (74) of the tracking paper
// about the offset point whenever the UAV is faster than it (a practitioner's standoff orbit).
// "auto": at each update the one of sinusoid, loiter and standoff whose steady pattern the camera
// model predicts to see the vehicle most (FollowPlanner::predicted_camera). Beyond the paper but
// "paper".
enum class FollowStrategy : std::uint8_t { Paper = 0, Standoff = 1, Auto = 2 };
template <>
struct EnumNames<FollowStrategy> {
  static constexpr const char* field = "follow.strategy";
  static constexpr EnumName<FollowStrategy> names[] = {{"paper", FollowStrategy::Paper},
      {"standoff", FollowStrategy::Standoff}, {"auto", FollowStrategy::Auto}};
};

// "north": the offset is fixed to the map; "heading": it turns with the vehicle.
enum class OffsetReference : std::uint8_t { North = 0, Heading = 1 };
template <>
struct EnumNames<OffsetReference> {
  static constexpr const char* field = "offset_reference";
  static constexpr EnumName<OffsetReference> names[] = {{"north", OffsetReference::North},
      {"heading", OffsetReference::Heading}, {"cardinal", OffsetReference::North},
      {"relative", OffsetReference::Heading}};
};

// FollowParameters::threshold for "auto": the planner picks h from its camera (camera_threshold in
// follow.hpp) so that the sinusoid's amplitude stays within the camera's reach (beyond the paper).
inline constexpr double kAutoThreshold = 0.0;

// The follower's vehicle where a scenario gives none: the paper's UAV flies at 20-23 m/s; 200 m
// above open ground.
inline constexpr Uav kFollowUav{21.0, 50.0, 200.0};

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
  // sinusoid below h - band / 2. kAutoThreshold (the default, beyond the paper): the largest h
  // whose sinusoid stays within the camera's reach at the band's upper edge (camera_threshold);
  // the paper's h is about 3 ("set to avoid the large amplitude", section II).
  double threshold = kAutoThreshold;  // h_sigma
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
  FollowStrategy strategy = FollowStrategy::Paper;
  // strategy auto: switch only to a pattern predicted to see the vehicle this much more often.
  double strategy_margin = 0.05;
  // The standoff orbit's radius: 0, the smallest flyable for the offset point's current speed
  // (Lemma 6 of the tracking paper, as the loiter circle); > 0, this constant radius (the
  // baseline's: a scenario sets the baseline's radius here for strategies standoff and auto).
  double standoff_radius = 0.0;       // m
  void validate() const;
};

// How a follow run is flown by the flight layer at step dt, steered by the
// waypoint paper's feedback law (5) with its gains (LineFeedbackGains, given for the paper's
// turn radius 0.7) rescaled to the UAV's r_min, since g and h multiply lengths.
// How a follow run flies the plan (LegGuidance, flight_parameters.hpp): one waypoint a second,
// each 1 s leg by the law (5), as the paper does; or the planned path itself
// (FollowPlanner::planned_path, renewed at every update) by L1 guidance on the curve.
struct FollowFlight {
  // The paper's discrete update, or Dormand-Prince (then updates happen at the first accepted
  // step ending at or after each update time, at most dt late).
  FlightIntegration integration = FlightIntegration::Discrete;
  double dt = 0.02;        // s, flight step and law step
  double max_time = 0.0;   // s after the start; 0: until the vehicle's track ends
  LegGuidance guidance = LegGuidance::LineFeedback;
  // guidance l1 (CurveL1): a period of 8 s puts L1 = 0.75 * 8 * v / pi = 40 m at the follow
  // examples' 21 m/s, under r_min = 50 m; at ArduPlane's 17 s (L1 = 85 m, made for larger
  // airframes) Fig. 7's compensated wind run flies a mean 52 m off its path (13 m at 8 s; bench/vehicle_models.py).
  L1Gains l1{8.0, 0.75};
  void validate() const;
};

}  // namespace vistrack
