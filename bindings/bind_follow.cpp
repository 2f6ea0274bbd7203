// vistrack._core.follow: following a ground vehicle (sinusoid and loiter modes, hysteresis,
// offset vector, wind compensation) and the runs flown by the flight layer.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <tuple>

#include "bindings.hpp"
#include "vistrack/error.hpp"
#include "vistrack/follow.hpp"

namespace py = pybind11;

namespace vistrack::bindings {

namespace {

// follow.threshold from Python: "auto" (kAutoThreshold) or a speed ratio > 1 (0 is not a spelling of "auto").
double threshold_of(const py::object& value) {
  if (py::isinstance<py::str>(value)) {
    const auto text = value.cast<std::string>();
    if (text != "auto") detail::fail_field("follow.threshold", "\"" + text + "\"", "must be \"auto\" or a number > 1");
    return kAutoThreshold;
  }
  const auto number = value.cast<double>();
  if (!(number > 1.0) || !std::isfinite(number))
    detail::fail_field("follow.threshold", number, "must be \"auto\" or a finite number > 1 (a speed ratio v_p / v_g)");
  return number;
}

py::object threshold_name(double threshold) {
  if (threshold == kAutoThreshold) return py::str("auto");
  return py::float_(threshold);
}

}  // namespace

void bind_follow(py::module_& parent) {
  py::module_ m = parent.def_submodule(
      "follow",
      "Following a ground vehicle (ground_vehicle_following paper): the sinusoid's amplitude from the speed "
      "ratio (eqs. 5, 9-10), loiter (circle or rose) above a threshold with hysteresis, an offset vector, "
      "wind compensation in the air mass, waypoints at 1 Hz, and the camera footprint metric.");

  m.def("sinusoid_amplitude", py::vectorize(&sinusoid_amplitude), py::arg("speed_ratio"), py::arg("period_distance"),
        "Amplitude A (m) of y = A sin(2 pi x / D) whose arc length over one period D is speed_ratio * D "
        "(eqs. 9-10: sigma = (2/pi) E(-A'^2), A' = 2 pi A / D), to 1e-12 relative. speed_ratio >= 1 "
        "(1 gives 0). Scalars or numpy arrays.");
  m.def("speed_ratio", py::vectorize(&sinusoid_speed_ratio), py::arg("amplitude"), py::arg("period_distance"),
        "sigma = v_p / v_g of eqs. (9)-(10) for amplitude A and period distance D. Scalars or arrays.");
  m.def("sinusoid_slope", py::vectorize(&sinusoid_slope), py::arg("speed_ratio"),
        "A' = 2 pi A / D for a speed ratio (independent of D).");
  m.def("along_track_rate", py::vectorize(&sinusoid_along_track_rate), py::arg("x"), py::arg("amplitude"),
        py::arg("period_distance"), py::arg("uav_speed"),
        "eq. (5): x_dot = v_p / sqrt(1 + A'^2 cos^2(2 pi x / D)), m/s.");
  m.def("arc_length", py::vectorize(&sinusoid_arc_length), py::arg("x"), py::arg("amplitude"), py::arg("period_distance"),
        "Arc length of the sinusoid from 0 to x (incomplete elliptic integral of the second kind).");
  m.def("phase_at_arc", py::vectorize(&sinusoid_phase_at_arc), py::arg("arc"), py::arg("amplitude"),
        py::arg("period_distance"), "The phase 2 pi x / D at which the arc length from 0 is `arc`.");

  py::class_<VehicleLeg>(m, "VehicleLeg",
                         "One leg of a route: heading (rad from east), speed at its start and end (m/s, linear "
                         "in between; 0 and 0 is a stop), duration (s).")
      .def(py::init([](double heading, double speed, double duration, std::optional<double> end_speed) {
             return VehicleLeg{heading, speed, duration, end_speed.value_or(std::numeric_limits<double>::quiet_NaN())};
           }),
           py::arg("heading"), py::arg("speed"), py::arg("duration"), py::arg("end_speed") = py::none(),
           "end_speed None: constant speed.")
      .def_readwrite("heading", &VehicleLeg::heading, "rad, counter-clockwise from east")
      .def_readwrite("speed", &VehicleLeg::speed, "m/s at the start")
      .def_readwrite("duration", &VehicleLeg::duration, "s")
      // The C++ struct keeps NaN for "constant speed"; Python sees the effective end speed, never NaN.
      .def_property(
          "end_speed", [](const VehicleLeg& leg) { return std::isnan(leg.end_speed) ? leg.speed : leg.end_speed; },
          [](VehicleLeg& leg, std::optional<double> end_speed) {
            leg.end_speed = end_speed.value_or(std::numeric_limits<double>::quiet_NaN());
          },
          "m/s at the end (the start speed on a constant-speed leg; set None for constant speed)");

  py::class_<GroundVehicle>(m, "GroundVehicle",
                            "A ground vehicle as a piecewise-linear track (t, x, y): position interpolated, "
                            "velocity per segment, heading of the last moving segment.")
      .def(py::init([](const InputArray& t, const InputArray& xy) {
             return GroundVehicle(to_values(t, "track.t"), to_array(to_points(xy, "track.xy")));
           }),
           py::arg("t"), py::arg("xy"), "Times (n,) strictly increasing and positions (n, 2).")
      .def_static("from_legs", &GroundVehicle::from_legs, py::arg("legs"), py::arg("start") = Vec2(0.0, 0.0),
                  py::arg("t0") = 0.0, py::arg("step") = 0.1,
                  "Drive the legs from `start` at t0 (speed ramps sampled every `step` s).")
      .def_static(
          "along_path",
          [](const InputArray& path, const std::vector<VehicleLeg>& legs, double t0, double step) {
            return GroundVehicle::along_path(to_array(to_points(path, "path")), legs, t0, step);
          },
          py::arg("path"), py::arg("legs"), py::arg("t0") = 0.0, py::arg("step") = 0.1,
          "Along a road polyline (n, 2) with the legs' speed profile (their headings ignored).")
      .def("position", &GroundVehicle::position, py::arg("t"), "Position (2,) at t (clamped to the track).")
      .def("velocity", &GroundVehicle::velocity, py::arg("t"), "Velocity (2,) of the segment at t (0 outside).")
      .def("heading", &GroundVehicle::heading, py::arg("t"), "Heading (rad) at t; a standing vehicle keeps its last.")
      .def(
          "sample",
          [](const GroundVehicle& v, const InputArray& times) {
            const std::vector<double> t = to_values(times, "times");
            Points2 p(static_cast<Eigen::Index>(t.size()), 2);
            for (std::size_t i = 0; i < t.size(); ++i) p.row(static_cast<Eigen::Index>(i)) = v.position(t[i]).transpose();
            return p;
          },
          py::arg("times"), "Positions (n, 2) at the given times.")
      .def_property_readonly("times", &GroundVehicle::times, "Sample times (s).")
      .def_property_readonly("positions", &GroundVehicle::positions, "Sample positions (n, 2).")
      .def_property_readonly("headings", &GroundVehicle::headings, "Heading per segment (rad).")
      .def_property_readonly("start_time", &GroundVehicle::start_time, "s")
      .def_property_readonly("end_time", &GroundVehicle::end_time, "s")
      .def_property_readonly("max_speed", &GroundVehicle::max_speed, "Largest segment speed (m/s).");

  const auto follow_uav = py::repr(py::cast(kFollowUav)).cast<std::string>();  // Uav is bound by now
  m.def("default_uav", [] { return kFollowUav; },
        ("The follower's vehicle where a scenario gives none, as a new " + follow_uav +
         " (the paper's UAV flies at 20-23 m/s).")
            .c_str());

  const FollowParameters defaults;
  py::class_<FollowParameters>(m, "FollowParameters",
                               "The follow planner's settings (defaults from the C++ struct). Angles in radians.")
      .def(py::init([](double period, double turn_margin, const py::object& threshold_value, double hysteresis,
                       const std::string& loiter_pattern, double loiter_radius, Circulation loiter_direction,
                       double offset_distance, double offset_angle, const std::string& offset_reference,
                       bool wind_compensation, double update_period, const std::string& strategy,
                       double strategy_margin, double standoff_radius) {
             const double threshold = threshold_of(threshold_value);
             FollowParameters p{period, turn_margin, threshold, hysteresis,
                                from_name<LoiterPattern>(loiter_pattern, "follow.loiter_pattern"), loiter_radius,
                                loiter_direction, offset_distance, offset_angle,
                                from_name<OffsetReference>(offset_reference, "follow.offset_reference"),
                                wind_compensation, update_period,
                                from_name<FollowStrategy>(strategy, "follow.strategy"), strategy_margin,
                                standoff_radius};
             p.validate();
             return p;
           }),
           py::kw_only(), py::arg("period") = defaults.period, py::arg("turn_margin") = defaults.turn_margin,
           py::arg("threshold") = threshold_name(defaults.threshold), py::arg("hysteresis") = defaults.hysteresis,
           py::arg("loiter_pattern") = to_string(defaults.loiter_pattern), py::arg("loiter_radius") = defaults.loiter_radius,
           py::arg("loiter_direction") = defaults.loiter_direction, py::arg("offset_distance") = defaults.offset_distance,
           py::arg("offset_angle") = defaults.offset_angle, py::arg("offset_reference") = to_string(defaults.offset_reference),
           py::arg("wind_compensation") = defaults.wind_compensation, py::arg("update_period") = defaults.update_period,
           py::arg("strategy") = to_string(defaults.strategy), py::arg("strategy_margin") = defaults.strategy_margin,
           py::arg("standoff_radius") = defaults.standoff_radius, "Validated parameters.")
      .def_readwrite("period", &FollowParameters::period, "T: time for the vehicle to cover one period, s")
      .def_readwrite("turn_margin", &FollowParameters::turn_margin, "tightest planned turn / r_min")
      .def_property(
          "threshold", [](const FollowParameters& p) { return threshold_name(p.threshold); },
          [](FollowParameters& p, const py::object& v) { p.threshold = threshold_of(v); },
          "h_sigma: loiter above this speed ratio; 'auto': picked from the camera (camera_threshold)")
      .def_readwrite("hysteresis", &FollowParameters::hysteresis, "full width of the band about the threshold")
      .def_property(
          "loiter_pattern", [](const FollowParameters& p) { return to_string(p.loiter_pattern); },
          [](FollowParameters& p, const std::string& v) { p.loiter_pattern = from_name<LoiterPattern>(v, "follow.loiter_pattern"); },
          "'circle' or 'rose'")
      .def_readwrite("loiter_radius", &FollowParameters::loiter_radius, "m; 0: the smallest flyable")
      .def_readwrite("loiter_direction", &FollowParameters::loiter_direction, "'ccw' or 'cw'")
      .def_readwrite("offset_distance", &FollowParameters::offset_distance, "L, m")
      .def_readwrite("offset_angle", &FollowParameters::offset_angle, "theta, rad")
      .def_property(
          "offset_reference", [](const FollowParameters& p) { return to_string(p.offset_reference); },
          [](FollowParameters& p, const std::string& v) {
            p.offset_reference = from_name<OffsetReference>(v, "follow.offset_reference");
          },
          "'north' (theta from east on the map) or 'heading' (theta from the vehicle's heading)")
      .def_readwrite("wind_compensation", &FollowParameters::wind_compensation, "plan in the air mass")
      .def_readwrite("update_period", &FollowParameters::update_period, "s between waypoints (1 Hz)")
      .def_property(
          "strategy", [](const FollowParameters& p) { return to_string(p.strategy); },
          [](FollowParameters& p, const std::string& v) { p.strategy = from_name<FollowStrategy>(v, "follow.strategy"); },
          "'paper' (sinusoid and loiter), 'standoff' (vector field (74) about the offset point) or 'auto' (per update, "
          "the pattern predicted to see the vehicle most)")
      .def_readwrite("strategy_margin", &FollowParameters::strategy_margin,
                     "strategy auto: switch only for this much more predicted camera fraction")
      .def_readwrite("standoff_radius", &FollowParameters::standoff_radius,
                     "m; the standoff orbit's constant radius (the baseline's); 0: the smallest flyable per update")
      .def("validate", &FollowParameters::validate, "Raise VistrackError naming the first invalid field.")
      .def("__copy__", [](const FollowParameters& p) { return p; }, "A copy (copy.copy): every field.")
      .def("__deepcopy__", [](const FollowParameters& p, const py::dict&) { return p; }, py::arg("memo"),
           "A copy (copy.deepcopy): the fields are values.");

  const FollowFlight flight_defaults;
  py::class_<FollowFlight>(m, "FollowFlight",
                           "How a follow run is flown: integration ('discrete' | 'continuous'), step dt (s), "
                           "max_time (s, 0: until the track ends), guidance of each 1 s leg ('law5': the paper's "
                           "law (5); 'l1': L1 line tracking, beyond the paper) and the L1 gains (period s, damping).")
      .def(py::init([](const std::string& integration, double dt, double max_time, LegGuidance guidance,
                       double l1_period, double l1_damping) {
             FollowFlight f{from_name<FlightIntegration>(integration, "flight.integration"), dt, max_time, guidance,
                            L1Gains{l1_period, l1_damping}};
             f.validate();
             return f;
           }),
           py::kw_only(), py::arg("integration") = to_string(flight_defaults.integration),
           py::arg("dt") = flight_defaults.dt, py::arg("max_time") = flight_defaults.max_time,
           py::arg("guidance") = flight_defaults.guidance, py::arg("l1_period") = flight_defaults.l1.period,
           py::arg("l1_damping") = flight_defaults.l1.damping)
      .def_property_readonly("integration", [](const FollowFlight& f) { return to_string(f.integration); })
      .def_readwrite("dt", &FollowFlight::dt, "s")
      .def_readwrite("max_time", &FollowFlight::max_time, "s; 0: until the track ends")
      .def_readwrite("guidance", &FollowFlight::guidance, "'law5' or 'l1'")
      .def_property_readonly("l1_period", [](const FollowFlight& f) { return f.l1.period; }, "L1 period, s")
      .def_property_readonly("l1_damping", [](const FollowFlight& f) { return f.l1.damping; }, "L1 damping");

  const DownwardCamera camera_defaults;
  py::class_<DownwardCamera>(m, "DownwardCamera",
                             "Downward conic camera (fov the full cone angle) on its mount: 'roll' (a roll gimbal that "
                             "points it at the target as far as max_gimbal allows), 'pan_tilt' (pointed at the target, "
                             "at most max_gimbal from the body's down axis) or 'fixed' (the paper's body-fixed camera).")
      .def(py::init([](double fov, double max_gimbal, const std::string& mount) {
             DownwardCamera c{fov, max_gimbal, from_name<CameraMount>(mount, "camera.mount")};
             c.validate();
             return c;
           }),
           py::kw_only(), py::arg("fov") = camera_defaults.fov, py::arg("max_gimbal") = camera_defaults.max_gimbal,
           py::arg("mount") = to_string(camera_defaults.mount),
           "fov: full angle (rad, default 74 degrees); max_gimbal: the gimbal's range (rad, default 25 degrees); "
           "mount: 'roll', 'pan_tilt' or 'fixed'.")
      .def_readwrite("fov", &DownwardCamera::fov, "rad")
      .def_readwrite("max_gimbal", &DownwardCamera::max_gimbal, "rad")
      .def_property(
          "mount", [](const DownwardCamera& c) { return to_string(c.mount); },
          [](DownwardCamera& c, const std::string& v) { c.mount = from_name<CameraMount>(v, "camera.mount"); },
          "'roll', 'pan_tilt' or 'fixed'");
  m.def("camera_sees", &camera_sees, py::arg("camera"), py::arg("uav"), py::arg("psi"), py::arg("bank"),
        py::arg("target"), "Whether the ground point target (3,) is in the footprint of the camera at uav (3,).");

  py::class_<SinusoidShape>(m, "SinusoidShape", "The sinusoid the planner flies at a speed ratio.")
      .def_readonly("slope", &SinusoidShape::slope, "a = A' = 2 pi A / D")
      .def_readonly("period_distance", &SinusoidShape::period_distance, "D, m")
      .def_readonly("amplitude", &SinusoidShape::amplitude, "A, m")
      .def_readonly("curvature_limited", &SinusoidShape::curvature_limited, "D is the curvature floor 2 pi a rho");
  m.def("sinusoid_shape", &sinusoid_shape, py::arg("speed_ratio"), py::arg("uav_speed"), py::arg("period"),
        py::arg("turn_radius"),
        "D = max(v_p T / sigma, 2 pi a rho) and A = a D / (2 pi): the sinusoid the planner flies (rho = turn_margin "
        "r_min).");
  m.def("camera_reach", &camera_reach, py::arg("camera"), py::arg("altitude"),
        "w = altitude tan(fov / 2 + max_gimbal): how far to the side a level UAV's camera sees, m.");
  py::class_<ThresholdChoice>(m, "ThresholdChoice", "The threshold the planner uses and the numbers behind it.")
      .def_readonly("threshold", &ThresholdChoice::threshold, "h used")
      .def_readonly("automatic", &ThresholdChoice::automatic, "picked from the camera")
      .def_readonly("upper_ratio", &ThresholdChoice::upper_ratio, "sigma_u = h + band / 2")
      .def_readonly("amplitude", &ThresholdChoice::amplitude, "A at sigma_u, m")
      .def_readonly("reach", &ThresholdChoice::reach, "w, the camera's lateral reach, m")
      .def_readonly("beyond_reach", &ThresholdChoice::beyond_reach, "A > w");
  m.def("camera_threshold", &camera_threshold, py::arg("parameters"), py::arg("uav"),
        py::arg("camera") = DownwardCamera{},
        "The threshold h the planner uses: with threshold 'auto' the largest whose sinusoid's amplitude at h + band/2 "
        "stays within camera_reach; else the user's, with its amplitude and reach.");

  py::class_<LoiterShape>(m, "LoiterShape", "The loiter pattern about its centre by arc length (circle or rose).")
      .def_property_readonly("pattern", [](const LoiterShape& s) { return to_string(s.pattern); })
      .def_readonly("radius", &LoiterShape::radius, "circle radius or the rose's extent, m")
      .def_readonly("turn_radius", &LoiterShape::turn_radius, "the rose's turn radius rho, m")
      .def_readonly("direction", &LoiterShape::direction, "+1 counter-clockwise turns")
      .def_property_readonly("delta", &LoiterShape::delta, "rose: rotation of the line per pass beyond pi")
      .def_property_readonly("piece_length", &LoiterShape::piece_length, "circle: circumference; rose: one pass")
      .def(
          "sample",
          [](const LoiterShape& s, const InputArray& arcs) {
            const std::vector<double> a = to_values(arcs, "arcs");
            Points2 p(static_cast<Eigen::Index>(a.size()), 2);
            for (std::size_t i = 0; i < a.size(); ++i) p.row(static_cast<Eigen::Index>(i)) = s.position(a[i]).transpose();
            return p;
          },
          py::arg("arcs"), "Positions (n, 2) relative to the centre at the given arc lengths.");

  const VehicleReportOptions report_defaults;
  py::class_<VehicleReportOptions>(m, "VehicleReportOptions",
                                   "The vehicle's 1 Hz reports as a radio link delivers them (beyond the paper).")
      .def(py::init([](double position_noise, double velocity_noise, double latency, double dropout, double timeout,
                       std::uint64_t seed) {
             VehicleReportOptions o{position_noise, velocity_noise, latency, dropout, timeout, seed};
             o.validate();
             return o;
           }),
           py::kw_only(), py::arg("position_noise") = report_defaults.position_noise,
           py::arg("velocity_noise") = report_defaults.velocity_noise, py::arg("latency") = report_defaults.latency,
           py::arg("dropout") = report_defaults.dropout, py::arg("timeout") = report_defaults.timeout,
           py::arg("seed") = report_defaults.seed,
           "position_noise m and velocity_noise m/s (standard deviations per axis), latency s, dropout (probability "
           "a report is lost), timeout s (no fresh report for this long: the vehicle is lost), seed.")
      .def_readonly("position_noise", &VehicleReportOptions::position_noise, "m")
      .def_readonly("velocity_noise", &VehicleReportOptions::velocity_noise, "m/s")
      .def_readonly("latency", &VehicleReportOptions::latency, "s")
      .def_readonly("dropout", &VehicleReportOptions::dropout, "probability")
      .def_readonly("timeout", &VehicleReportOptions::timeout, "s")
      .def_readonly("seed", &VehicleReportOptions::seed);

  py::class_<FollowObservation>(m, "FollowObservation", "What the planner sees at an update.")
      .def(py::init([](const Vec2& vehicle_position, const Vec2& vehicle_velocity, double vehicle_heading,
                       const Vec2& uav_position, double uav_heading, const Vec2& offset_rate) {
             return FollowObservation{vehicle_position, vehicle_velocity, vehicle_heading, uav_position, uav_heading,
                                      offset_rate};
           }),
           py::kw_only(), py::arg("vehicle_position"), py::arg("vehicle_velocity"), py::arg("vehicle_heading") = 0.0,
           py::arg("uav_position") = Vec2(0.0, 0.0), py::arg("uav_heading") = 0.0,
           py::arg("offset_rate") = Vec2(0.0, 0.0))
      .def_readwrite("vehicle_position", &FollowObservation::vehicle_position)
      .def_readwrite("vehicle_velocity", &FollowObservation::vehicle_velocity)
      .def_readwrite("vehicle_heading", &FollowObservation::vehicle_heading)
      .def_readwrite("uav_position", &FollowObservation::uav_position)
      .def_readwrite("uav_heading", &FollowObservation::uav_heading)
      .def_readwrite("offset_rate", &FollowObservation::offset_rate)
      .def_readwrite("lost", &FollowObservation::lost, "no fresh report: orbit the vehicle's estimate");

  py::class_<FollowTick>(m, "FollowTick", "One update of the planner: mode, pattern parameters, state, waypoint.")
      .def_readonly("t", &FollowTick::t, "s")
      .def_property_readonly("mode", [](const FollowTick& k) { return to_string(k.mode); }, "'sinusoid' | 'loiter' | 'straight'")
      .def_readonly("speed_ratio", &FollowTick::speed_ratio, "sigma (inf when the offset point stands in the frame)")
      .def_readonly("uav_speed", &FollowTick::uav_speed, "v_p planned with, m/s")
      .def_readonly("frame_velocity", &FollowTick::frame_velocity, "offset point's velocity in the planning frame")
      .def_readonly("track_angle", &FollowTick::track_angle, "direction of the sinusoid's axis, rad")
      .def_readonly("amplitude", &FollowTick::amplitude, "A, m")
      .def_readonly("period_distance", &FollowTick::period_distance, "D, m")
      .def_readonly("period", &FollowTick::period, "s")
      .def_readonly("phase", &FollowTick::phase, "sinusoid phase, rad")
      .def_readonly("arc", &FollowTick::arc, "loiter arc length, m")
      .def_readonly("capturing", &FollowTick::capturing, "holding the entry point until the UAV is close")
      .def_readonly("lost", &FollowTick::lost, "orbiting the vehicle's estimate")
      .def_readonly("radius", &FollowTick::radius, "standoff orbit radius, m")
      .def_readonly("predicted_camera", &FollowTick::predicted_camera,
                    "strategy auto: the chosen pattern's predicted camera fraction (-1: none)")
      .def_readonly("offset_vector", &FollowTick::offset_vector, "O - vehicle, m")
      .def_readonly("offset_point", &FollowTick::offset_point, "O, m")
      .def_readonly("offset_velocity", &FollowTick::offset_velocity, "O's velocity, m/s")
      .def_readonly("waypoint", &FollowTick::waypoint, "the waypoint issued at t, m")
      .def_readonly("vehicle_predicted", &FollowTick::vehicle_predicted,
                    "the vehicle update_period later, predicted (the waypoint's region of interest), m");

  py::class_<FollowPlanner>(m, "FollowPlanner", "The 1 Hz follow planner of sections II-V.")
      .def(py::init<const FollowParameters&, const Uav&, const Vec2&, const DownwardCamera&>(), py::arg("parameters"),
           py::arg("uav"), py::arg("wind_estimate") = Vec2(0.0, 0.0), py::arg("camera") = DownwardCamera{},
           "wind_estimate (east, north) m/s is used with compensation; camera: what an 'auto' threshold is picked for.")
      .def_property_readonly("threshold_choice", &FollowPlanner::threshold_choice, "The threshold in use.")
      .def("orbit_radius", &FollowPlanner::orbit_radius, py::arg("frame_speed"),
           "Radius of the planner's orbits about an offset point moving at frame_speed (Lemma 6), m.")
      .def("predicted_camera", &FollowPlanner::predicted_camera, py::arg("tick"),
           "The camera fraction predicted over one steady cycle of the tick's pattern (strategy auto).")
      .def("update", &FollowPlanner::update, py::arg("t"), py::arg("observation"),
           "The update at time t: mode with hysteresis, pattern advanced, next waypoint.")
      .def("offset_vector", &FollowPlanner::offset_vector, py::arg("vehicle_heading"), "O - vehicle for that heading.")
      .def("set_offset", &FollowPlanner::set_offset, py::arg("distance"), py::arg("angle"),
           "Change the offset's distance (m) and angle (rad) from the next update on.")
      .def(
          "planned_path",
          [](const FollowPlanner& p, const FollowTick& tick, double horizon, double step) {
            return to_array(p.planned_path(tick, horizon, step));
          },
          py::arg("tick"), py::arg("horizon"), py::arg("step"),
          "The planned ground path from the tick on, (n, 2): O + O_dot tau + relative_position(tick, tau) at "
          "tau = 0, step, ..., horizon (what flight.guidance l1 flies).")
      .def("relative_position", &FollowPlanner::relative_position, py::arg("tick"), py::arg("tau"),
           "Desired position relative to the offset point tau s after the tick.")
      .def(
          "next_mode",
          [](const FollowPlanner& p, FollowMode current, double sigma) {
            return p.next_mode(current, sigma);
          },
          py::arg("current"), py::arg("speed_ratio"), "The mode after `current` for sigma, with the hysteresis band.")
      .def_property_readonly("loiter_shape", &FollowPlanner::loiter_shape, "The loiter pattern in use.");

  py::class_<FollowMetrics>(m, "FollowMetrics", "Scores of one follow run (lengths in m, times in s).")
      .def_readonly("duration", &FollowMetrics::duration)
      .def_readonly("mean_tracking_error", &FollowMetrics::mean_tracking_error, "mean distance from the planned path")
      .def_readonly("max_tracking_error", &FollowMetrics::max_tracking_error)
      .def_readonly("mean_along_track_lag", &FollowMetrics::mean_along_track_lag, "mean lag behind the desired position")
      .def_readonly("max_along_track_lag", &FollowMetrics::max_along_track_lag)
      .def_readonly("final_along_track_lag", &FollowMetrics::final_along_track_lag)
      .def_readonly("time_sinusoid", &FollowMetrics::time_sinusoid)
      .def_readonly("time_loiter", &FollowMetrics::time_loiter)
      .def_readonly("time_straight", &FollowMetrics::time_straight)
      .def_readonly("time_standoff", &FollowMetrics::time_standoff)
      .def_readonly("time_capturing", &FollowMetrics::time_capturing, "s holding an entry point until reached")
      .def_readonly("mode_switches", &FollowMetrics::mode_switches)
      .def_readonly("camera_fraction", &FollowMetrics::camera_fraction, "time fraction with the vehicle in view")
      .def_readonly("mean_vehicle_distance", &FollowMetrics::mean_vehicle_distance)
      .def_readonly("mean_offset_distance", &FollowMetrics::mean_offset_distance)
      .def_readonly("mean_offset_error", &FollowMetrics::mean_offset_error, "mean of UAV - offset point (2,)")
      .def_readonly("lost_time", &FollowMetrics::lost_time, "s without a report younger than the timeout")
      .def_readonly("lost_episodes", &FollowMetrics::lost_episodes)
      .def_readonly("mean_reacquire_time", &FollowMetrics::mean_reacquire_time, "s from a fresh report to the camera")
      .def_readonly("max_reacquire_time", &FollowMetrics::max_reacquire_time, "s");

  py::class_<FollowRun>(m, "FollowRun", "One follow run: per-sample arrays, the 1 Hz updates and the metrics.")
      .def_readonly("t", &FollowRun::t, "sample times (s)")
      .def_readonly("state", &FollowRun::state, "(n, 3) x, y, psi")
      .def_readonly("turn_rate", &FollowRun::turn_rate, "applied turn rate (rad/s)")
      .def_readonly("bank", &FollowRun::bank, "coordinated-turn bank (rad)")
      .def_readonly("vehicle", &FollowRun::vehicle, "(n, 2) vehicle position")
      .def_readonly("offset_point", &FollowRun::offset_point, "(n, 2)")
      .def_readonly("desired", &FollowRun::desired, "(n, 2) desired position")
      .def_readonly("target", &FollowRun::target, "(n, 2) the waypoint flown to")
      .def_property_readonly("mode", [](const FollowRun& r) {
             std::vector<std::string> names;
             names.reserve(r.mode.size());
             for (std::uint8_t k : r.mode) names.push_back(to_string(static_cast<FollowMode>(k)));
             return names;
           }, "mode of the current update at each sample")
      .def_readonly("capturing", &FollowRun::capturing, "the update holds its entry point (0/1)")
      .def_readonly("in_view", &FollowRun::in_view, "vehicle in the camera footprint (0/1)")
      .def_readonly("lost", &FollowRun::lost, "the vehicle is lost (0/1; empty: never)")
      .def_readonly("tracking_error", &FollowRun::tracking_error, "distance from the planned path (m)")
      .def_readonly("along_track_lag", &FollowRun::along_track_lag, "m, > 0 behind")
      .def_readonly("wind", &FollowRun::wind, "(n, 2) true wind")
      .def_readonly("ticks", &FollowRun::ticks, "the 1 Hz updates")
      .def_readonly("threshold", &FollowRun::threshold, "the threshold the planner used")
      .def_readonly("metrics", &FollowRun::metrics)
      .def_property_readonly("waypoints", &FollowRun::waypoints, "(k, 2) the generated waypoints")
      .def_property_readonly("waypoint_times", &FollowRun::waypoint_times, "when each waypoint was issued (s)");

  const auto run_options = [](const FollowFlight& flight, const DownwardCamera& camera, std::optional<Vec3> start,
                               double path_window, const std::vector<std::tuple<double, double, double>>& offsets,
                               const VehicleReportOptions& reports) {
    FollowRunOptions options;
    options.reports = reports;
    options.flight = flight;
    options.camera = camera;
    options.start = start;
    options.path_window = path_window;
    for (const auto& [t, d, a] : offsets) options.offset_schedule.push_back({t, d, a});
    return options;
  };
  const FollowRunOptions option_defaults;
  m.def(
      "follow",
      [run_options](const GroundVehicle& vehicle, const Uav& uav, const FollowParameters& parameters, const Wind& wind,
                    std::optional<Vec2> wind_estimate, const FollowFlight& flight, const DownwardCamera& camera,
                    std::optional<Vec3> start, double path_window,
                    const std::vector<std::tuple<double, double, double>>& offsets, const VehicleReportOptions& reports) {
        const FollowRunOptions options = run_options(flight, camera, start, path_window, offsets, reports);
        const Vec2 estimate = wind_estimate.value_or(Vec2(wind.east, wind.north));
        py::gil_scoped_release release;
        return follow(vehicle, uav, parameters, wind, estimate, options);
      },
      py::arg("vehicle"), py::arg("uav"), py::arg("parameters"), py::arg("wind") = Wind{}, py::kw_only(),
      py::arg("wind_estimate") = py::none(), py::arg("flight") = FollowFlight{}, py::arg("camera") = DownwardCamera{},
      py::arg("start") = py::none(), py::arg("path_window") = option_defaults.path_window,
      py::arg("offset_schedule") = std::vector<std::tuple<double, double, double>>{},
      py::arg("reports") = VehicleReportOptions{},
      "Fly the follow planner's 1 Hz waypoints with the flight layer (the waypoint paper's law (5), a "
      "WaypointFollower fed during the flight). wind: the true wind (vistrack.flight.Wind); wind_estimate "
      "(east, north): what the planner compensates (None: the true constant wind). start: (x, y, psi) or None "
      "(on the planned path). offset_schedule: (t, distance, angle) keys, linear in between. reports: what the "
      "UAV knows of the vehicle (VehicleReportOptions; default: the truth at each update).");
  m.def(
      "orbit_follow",
      [run_options](const GroundVehicle& vehicle, const Uav& uav, const Control& control, double radius,
                    const FollowParameters& parameters, const Wind& wind, const FollowFlight& flight,
                    const DownwardCamera& camera, std::optional<Vec3> start, double path_window,
                    const std::vector<std::tuple<double, double, double>>& offsets, const VehicleReportOptions& reports) {
        const FollowRunOptions options = run_options(flight, camera, start, path_window, offsets, reports);
        py::gil_scoped_release release;
        return orbit_follow(vehicle, uav, control, radius, parameters, wind, options);
      },
      py::arg("vehicle"), py::arg("uav"), py::arg("control"), py::arg("radius"), py::arg("parameters"),
      py::arg("wind") = Wind{}, py::kw_only(), py::arg("flight") = FollowFlight{}, py::arg("camera") = DownwardCamera{},
      py::arg("start") = py::none(), py::arg("path_window") = option_defaults.path_window,
      py::arg("offset_schedule") = std::vector<std::tuple<double, double, double>>{},
      py::arg("reports") = VehicleReportOptions{},
      "The baseline follower: the tracking paper's vector field (74) and steering law (86) orbiting the offset "
      "point (from parameters and offset_schedule) at a constant radius, flown by the flight layer in the true "
      "wind, knowing the vehicle from the same reports as the planner (at each update, carried along its "
      "velocity in between). The result's desired position is the orbit's nearest point.");
}

}  // namespace vistrack::bindings
