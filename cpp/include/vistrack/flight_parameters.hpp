// The flight layer's parameters (wind, integration, the feedback laws' gains), with their
// defaults.
// Each validate() throws Error naming the field and its allowed range (vistrack/limits.hpp).
#pragma once

#include <cstdint>
#include <optional>

#include "vistrack/error.hpp"

namespace vistrack {

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
  void validate() const;  // finite components; WindField checks the speed against the airspeed
};

// How fly() advances the vehicle: the paper's discrete update, or Dormand-Prince 5(4).
enum class FlightIntegration : std::uint8_t { Discrete = 0, Continuous = 1 };

template <>
struct EnumNames<FlightIntegration> {
  static constexpr const char* field = "integration";
  static constexpr EnumName<FlightIntegration> names[] = {{"discrete", FlightIntegration::Discrete},
      {"continuous", FlightIntegration::Continuous}};
};

struct FlightOptions {
  FlightIntegration integration = FlightIntegration::Discrete;
  double dt = 0.02;          // s. Discrete: the step (psi_max = v dt / R). Continuous: output
                             // spacing and largest step.
  double max_time = 3600.0;  // s after the start; the flight stops there unless the guidance is done
  double rtol = 1e-9;        // continuous only
  double atol = 1e-12;       // continuous only
  void validate() const;
};

// The lateral law that flies a leg or a path: the waypoint paper's feedback law (5), or L1
// guidance (beyond the papers: Park's law as autopilots fly it, continuous in the state, so the
// bank does not chatter as behind the saturated law (5)).
enum class LegGuidance : std::uint8_t { LineFeedback = 0, L1 = 1 };

template <>
struct EnumNames<LegGuidance> {
  static constexpr const char* field = "guidance";
  static constexpr EnumName<LegGuidance> names[] = {{"law5", LegGuidance::LineFeedback}, {"l1", LegGuidance::L1}};
};

// Gains of the illustrative feedback law (5) of the Dubins waypoint navigation paper (section 3.1).
struct LineFeedbackGains {
  double g = 0.1;    // on the cross-track distance s
  double h = 5.25;   // on its change over one law step, s_dot dt
  void validate() const;
  // The paper's gains (given for its turn radius 0.7) for turn radius R: g and h multiply lengths,
  // so both scale by 0.7 / R (a flight in metres flies the paper's law at its proportions).
  static LineFeedbackGains for_turn_radius(double turn_radius);
};

// Gains of the L1 line tracker (L1Line, flight.hpp): ArduPlane's defaults NAVL1_PERIOD = 17 s and
// NAVL1_DAMPING = 0.75 (libraries/AP_L1_Control); L1 = damping * period * v / pi.
struct L1Gains {
  double period = 17.0;   // s
  double damping = 0.75;
  void validate() const;
};

// Gains of PathFollower (flight.hpp, Path following), scaled by the vehicle so one set fits every size:
// the cross-track correction steers at atan(e / (lookahead_radii R)) back to the path, the heading
// loop closes at heading_gain v / R per radian. With these the linearised cross-track error is a
// second-order system with damping 0.5 sqrt(heading_gain * lookahead_radii) = 0.87.
struct PathFollowingGains {
  double lookahead_radii = 1.0;
  double heading_gain = 3.0;
  // s: the curvature feed-forward reads the path this long ahead (v times it in length), so a
  // banking vehicle starts its roll before an arc rather than its roll time constant late; 0: none.
  double anticipation = 0.0;
  void validate() const;
};

}  // namespace vistrack
