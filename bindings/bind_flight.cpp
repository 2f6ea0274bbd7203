// vistrack._core.flight: the vehicle (Dubins or roll model) in wind flown by a guidance law (flight.hpp).
#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "vistrack/error.hpp"
#include "vistrack/flight.hpp"

namespace py = pybind11;

namespace vistrack::bindings {

namespace {

py::array_t<double> columns(const std::vector<const std::vector<double>*>& cols) {
  const std::size_t n = cols.front()->size();
  py::array_t<double> out({static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(cols.size())});
  auto view = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < cols.size(); ++j)
      view(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(j)) = (*cols[j])[i];
  return out;
}

}  // namespace

void bind_flight(py::module_& parent) {
  py::module_ m = parent.def_submodule(
      "flight",
      "The flight layer: a Dubins vehicle (airspeed v, turn rate <= v/R) in wind (constant plus seeded "
      "Dryden gusts, MIL-F-8785C) flown by a guidance law, with the paper's discrete update or Dormand-Prince "
      "5(4). Every planner flies here.");

  const Gusts gust_defaults;
  py::class_<Gusts>(m, "Gusts",
                    "Dryden turbulence (MIL-F-8785C, horizontal): RMS intensity sigma_u = sigma_v (speed units), "
                    "length scale L_u = L_v (length units), seed. Reproducible from the seed.")
      .def(py::init([](const AnyInteger& seed, double intensity, double length_scale, double sample_step) {
             Gusts g{integer<std::uint64_t>(seed, "seed"), intensity, length_scale, sample_step};
             g.validate();
             return g;
           }),
           py::kw_only(), py::arg("seed") = gust_defaults.seed, py::arg("intensity") = gust_defaults.intensity,
           py::arg("length_scale") = gust_defaults.length_scale, py::arg("sample_step") = gust_defaults.sample_step,
           "seed; intensity sigma (speed units); length_scale L (length units); sample_step (s) of the "
           "precomputed series, 0: L / (20 V).")
      .def_property(
          "seed", [](const Gusts& g) { return g.seed; },
          [](Gusts& g, const AnyInteger& seed) { g.seed = integer<std::uint64_t>(seed, "seed"); }, "random seed")
      .def_readwrite("intensity", &Gusts::intensity, "sigma_u = sigma_v, speed units")
      .def_readwrite("length_scale", &Gusts::length_scale, "L_u = L_v, length units")
      .def_readwrite("sample_step", &Gusts::sample_step, "s between precomputed samples; 0: L / (20 V)")
      .def_static(
          "mil_f_8785c",
          [](double altitude, double wind_speed_20ft, const AnyInteger& seed, double length_unit, double speed_unit) {
            return mil_f_8785c_gusts(altitude, wind_speed_20ft, integer<std::uint64_t>(seed, "seed"), length_unit,
                                     speed_unit);
          },
          py::arg("altitude"), py::arg("wind_speed_20ft"),
                  py::arg("seed") = 0, py::arg("length_unit") = 1.0, py::arg("speed_unit") = 1.0,
                  "Gusts of the MIL-F-8785C low-altitude model at `altitude` (m, 3.05-304.8) for the wind speed "
                  "at 20 ft W20 (m/s; light 7.7, moderate 15.4, severe 23.2), in flight units: speeds divided by "
                  "speed_unit (m/s per unit), lengths by length_unit (m per unit).")
      .def("__repr__", [](const Gusts& g) {
        return Repr("Gusts")
            .add("seed", g.seed)
            .add("intensity", g.intensity)
            .add("length_scale", g.length_scale)
            .add("sample_step", g.sample_step)
            .str();
      });

  py::class_<Wind>(m, "Wind", "Wind the vehicle does not know: constant (east, north) plus optional Gusts.")
      .def(py::init([](double east, double north, std::optional<Gusts> gusts) {
             Wind w{east, north, gusts};
             w.validate();
             return w;
           }),
           py::arg("east") = 0.0, py::arg("north") = 0.0, py::arg("gusts") = py::none(),
           "Constant wind (east, north) in speed units; gusts: Gusts or None.")
      .def_readwrite("east", &Wind::east, "east component, speed units")
      .def_readwrite("north", &Wind::north, "north component, speed units")
      .def_readwrite("gusts", &Wind::gusts, "Gusts or None")
      .def("__repr__", [](const Wind& w) {
        Repr text("Wind");
        text.add("east", w.east).add("north", w.north);
        if (w.gusts) text.item("gusts=" + Repr("Gusts").add("seed", w.gusts->seed).item("...").str());
        return text.str();
      });

  py::class_<DrydenLowAltitude>(m, "DrydenLowAltitude", "MIL-F-8785C low-altitude turbulence at one altitude.")
      .def_readonly("sigma_u", &DrydenLowAltitude::sigma_u, "longitudinal RMS intensity, m/s")
      .def_readonly("sigma_v", &DrydenLowAltitude::sigma_u, "lateral RMS intensity (= sigma_u), m/s")
      .def_readonly("sigma_w", &DrydenLowAltitude::sigma_w, "vertical RMS intensity, m/s")
      .def_readonly("length_u", &DrydenLowAltitude::length_u, "longitudinal length scale, m")
      .def_readonly("length_v", &DrydenLowAltitude::length_u, "lateral length scale (= length_u), m")
      .def_readonly("length_w", &DrydenLowAltitude::length_w, "vertical length scale (= altitude), m");
  m.def("dryden_low_altitude", &dryden_low_altitude, py::arg("altitude"), py::arg("wind_speed_20ft"),
      "MIL-F-8785C low-altitude intensities (m/s) and length scales (m) at altitude (m) for W20 (m/s).");

  py::class_<WindField>(m, "WindField", "w(t) for one flight: the constant wind plus the precomputed gust series.")
      .def(py::init<const Wind&, double, double, double>(), py::arg("wind"), py::arg("airspeed"), py::arg("t0"),
           py::arg("duration"),
           "Precomputes the gusts on [t0, t0 + duration] for a vehicle of that airspeed (Taylor's frozen field). "
           "VistrackError when the wind speed reaches the airspeed.")
      .def(
          "at",
          [](const WindField& w, const std::vector<double>& times) {
            py::array_t<double> out({static_cast<py::ssize_t>(times.size()), py::ssize_t{2}});
            auto view = out.mutable_unchecked<2>();
            for (std::size_t i = 0; i < times.size(); ++i) {
              const Vec2 v = w.at(times[i]);
              view(static_cast<py::ssize_t>(i), 0) = v.x();
              view(static_cast<py::ssize_t>(i), 1) = v.y();
            }
            return out;
          },
          py::arg("times"), "Wind (east, north) at each time: array (n, 2).")
      .def_property_readonly("sample_step", &WindField::sample_step, "s between gust samples (0 without gusts)")
      .def_property_readonly("max_speed", &WindField::max_speed, "largest wind speed over the span")
      .def_property_readonly("has_gusts", &WindField::has_gusts, "whether gusts were generated");

  py::class_<LineFeedbackTerms>(m, "LineFeedbackTerms", "Every term of the law (5) at one state.")
      .def_readonly("target_angle", &LineFeedbackTerms::target_angle, "phi_T, rad")
      .def_readonly("cross_track", &LineFeedbackTerms::cross_track, "s")
      .def_readonly("cross_track_step", &LineFeedbackTerms::cross_track_step, "s_dot dt")
      .def_readonly("reference_angle", &LineFeedbackTerms::reference_angle, "phi_R, rad")
      .def_readonly("unsaturated", &LineFeedbackTerms::unsaturated, "phi_T + phi_R, rad")
      .def_readonly("turn", &LineFeedbackTerms::turn, "psi_turn, clamped to +-psi_max, rad")
      .def_readonly("saturated", &LineFeedbackTerms::saturated, "whether the clamp acted");

  m.def(
      "paper_gains",
      [](double turn_radius) {
        const LineFeedbackGains gains = LineFeedbackGains::for_turn_radius(turn_radius);
        return std::make_pair(gains.g, gains.h);
      },
      py::arg("turn_radius"),
      "The law (5)'s gains (g, h) for turn radius R: the paper's (0.1, 5.25), given for its R = 0.7, scaled by "
      "0.7 / R (both multiply lengths).");

  py::class_<LineFeedback>(m, "LineFeedback",
                           "The paper's feedback law (5): psi_turn = clamp(phi_T + |g s + h s_dot dt| sign(phi_T), "
                           "+-v dt / R) towards the line whose end is the target; turn rate psi_turn / dt.")
      .def(py::init([](double speed, double turn_radius, double dt, std::pair<double, double> gains, bool smooth) {
             return LineFeedback(speed, turn_radius, dt, LineFeedbackGains{gains.first, gains.second}, smooth);
           }),
           py::arg("speed"), py::arg("turn_radius"), py::arg("dt"),
           py::arg("gains") = std::make_pair(LineFeedbackGains{}.g, LineFeedbackGains{}.h),
           py::arg("smooth_sign") = false,
           "speed v, turn_radius R, law step dt (psi_max = v dt / R <= pi/2), gains (g, h); smooth_sign: "
           "sign(phi_T) -> clamp(phi_T / psi_max, -1, 1) for continuous flight.")
      .def(
          "terms",
          [](const LineFeedback& law, const Pose& q, const Vec2& line_start, const Vec2& target) {
            return law.terms(configuration(q), line_start, target);
          },
          py::arg("state"), py::arg("line_start"), py::arg("target"),
          "Every term of (5) at state (x, y, psi) for the line line_start -> target (LineFeedbackTerms).")
      .def(
          "turn_rate",
          [](const LineFeedback& law, const Pose& q, const Vec2& line_start,
             const Vec2& target) { return law.turn_rate(configuration(q), line_start, target); },
          py::arg("state"), py::arg("line_start"), py::arg("target"), "psi_turn / dt, rad/s.")
      .def_property_readonly("max_turn", &LineFeedback::max_turn, "psi_max = v dt / R, rad per step")
      .def_property_readonly("speed", &LineFeedback::speed, "v")
      .def_property_readonly("turn_radius", &LineFeedback::turn_radius, "R")
      .def_property_readonly("dt", &LineFeedback::dt, "law step, s")
      .def_property_readonly("gains", [](const LineFeedback& l) { return std::make_pair(l.gains().g, l.gains().h); },
                             "(g, h)")
      .def_property_readonly("smooth_sign", &LineFeedback::smooth_sign, "whether sign(phi_T) is smoothed")
      .def("set_wind", &LineFeedback::set_wind, py::arg("mean_wind"),
           "Wind-aware (beyond the paper): phi_T and s_dot from the course over the ground with this known mean "
           "wind (east, north), as navigate(wind_aware=True) flies.")
      .def_property_readonly("wind_aware", &LineFeedback::wind_aware, "whether set_wind was called");

  py::class_<L1Line>(m, "L1Line",
                     "L1 line tracking as ArduPlane flies a leg (Park, Deyst & How 2004; AP_L1_Control): lateral "
                     "acceleration 4 damping^2 v^2 / L1 sin(eta) towards the point L1 = damping period v / pi ahead "
                     "on the line; continuous in the state (no chatter).")
      .def(py::init([](double speed, double period, double damping) { return L1Line(speed, L1Gains{period, damping}); }),
           py::arg("speed"), py::arg("period") = L1Gains{}.period, py::arg("damping") = L1Gains{}.damping,
           "speed v; period (s, ArduPlane NAVL1_PERIOD 17) and damping (NAVL1_DAMPING 0.75).")
      .def(
          "turn_rate",
          [](const L1Line& law, const Pose& q, const Vec2& line_start, const Vec2& target) {
            return law.turn_rate(configuration(q), line_start, target);
          },
          py::arg("state"), py::arg("line_start"), py::arg("target"), "Turn rate a / v, rad/s.")
      .def_property_readonly("distance", &L1Line::distance, "L1, length units")
      .def("set_wind", &L1Line::set_wind, py::arg("mean_wind"),
           "Wind-aware (beyond the paper, as ArduPlane flies L1): steer the ground velocity with this known mean "
           "wind (east, north), as navigate(wind_aware=True) flies.")
      .def_property_readonly("wind_aware", &L1Line::wind_aware, "whether set_wind was called");

  py::class_<FlightGuidance>(m, "FlightGuidance",
                             "A guidance law for fly(): turn-rate command and target from (x, y, psi) and t; its "
                             "stateful logic runs only after accepted steps.")
      .def("command",
           [](const FlightGuidance& g, const Pose& q, double t) {
             const GuidanceCommand c = g.command(configuration(q), t);
             return py::make_tuple(c.turn_rate, py::make_tuple(c.target.x(), c.target.y()), c.target_index);
           },
           py::arg("state"), py::arg("t") = 0.0, "(turn_rate, (target_x, target_y), target_index) at a state.")
      .def(
          "start", [](FlightGuidance& g, const Pose& q, double t) { g.start(configuration(q), t); },
          py::arg("state"), py::arg("t") = 0.0,
          "Reset the discrete state for a flight from (x, y, psi) at t (an outside vehicle model: vistrack.fdm).")
      .def(
          "advance", [](FlightGuidance& g, const Pose& q, double t) { g.advance(configuration(q), t); },
          py::arg("state"), py::arg("t"),
          "The stateful logic (switch targets, finish) at an accepted state (an outside vehicle model: vistrack.fdm).")
      .def_property_readonly("done", &FlightGuidance::done, "True once there is nothing more to fly")
      .def_property_readonly("revision", &FlightGuidance::revision, "counts changes of the active target");

  py::class_<CurveL1, FlightGuidance>(
      m, "CurveL1",
      "L1 guidance on a curve (Park, Deyst & How 2004): the reference point is where the circle of radius "
      "L1 = damping period v / pi about the vehicle leaves the path ahead of its closest point; turn rate "
      "4 damping^2 v / L1 sin(eta). The path (a polyline) may be replaced during flight (set_path from on_step).")
      .def(py::init([](double speed, const InputArray& path, double period, double damping) {
             return CurveL1(speed, to_points(path, "path"), L1Gains{period, damping});
           }),
           py::arg("speed"), py::arg("path"), py::arg("period") = L1Gains{}.period,
           py::arg("damping") = L1Gains{}.damping, "speed v; path: array (n, 2); period (s) and damping of L1.")
      .def("set_path", [](CurveL1& g, const InputArray& path) { g.set_path(to_points(path, "path")); },
           py::arg("path"), "Replace the path (array (n, 2), n >= 1; one point: fly to it).")
      .def("reference_point", &CurveL1::reference_point, py::arg("position"), "The L1 reference point, (2,).")
      .def_property_readonly("distance", &CurveL1::distance, "L1, length units")
      .def_property_readonly("path", [](const CurveL1& g) { return to_array(g.path()); }, "array (n, 2)");

  py::class_<TurnRateHold, FlightGuidance>(
      m, "TurnRateHold",
      "Holds a commanded turn rate, set during flight (set_turn_rate from on_step): the roll model banks towards "
      "atan(v rate / g), the Dubins vehicle turns at once. Never done by itself.")
      .def(py::init<double>(), py::arg("turn_rate") = 0.0, "turn_rate: rad/s, finite (the vehicle clamps it).")
      .def("set_turn_rate", &TurnRateHold::set_turn_rate, py::arg("turn_rate"), "From the next step on (rad/s).")
      .def_property_readonly("turn_rate", &TurnRateHold::turn_rate, "rad/s");

  py::class_<WaypointFollower, FlightGuidance>(
      m, "WaypointFollower",
      "Classical waypoint navigation on the law (5): the line from the previous waypoint (the start for the "
      "first) to the active one; next waypoint when within waypoint_radius. finish_at_last=False holds at the "
      "last waypoint until add_waypoint() gives more (feed it from fly()'s on_step).")
      .def(py::init([](const LineFeedback& law, const InputArray& waypoints, double radius, bool finish_at_last) {
             return WaypointFollower(law, to_points(waypoints, "waypoints"), radius, finish_at_last);
           }),
           py::arg("law"), py::arg("waypoints"), py::arg("waypoint_radius"), py::arg("finish_at_last") = true,
           "law: LineFeedback; waypoints: array (n, 2); waypoint_radius R_WP >= 0.")
      .def(py::init([](const L1Line& law, const InputArray& waypoints, double radius, bool finish_at_last) {
             return WaypointFollower(law, to_points(waypoints, "waypoints"), radius, finish_at_last);
           }),
           py::arg("law"), py::arg("waypoints"), py::arg("waypoint_radius"), py::arg("finish_at_last") = true,
           "The same with each leg flown by L1 line tracking (law: L1Line).")
      .def("add_waypoint", &WaypointFollower::add_waypoint, py::arg("point"),
           py::arg("available_from") = -std::numeric_limits<double>::infinity(),
           "Append a waypoint usable from time available_from on (non-decreasing); allowed during flight.")
      .def_property_readonly(
          "waypoints",
          [](const WaypointFollower& w) { return to_array(w.waypoints()); },
          "array (n, 2)")
      .def_property("passed_line", &WaypointFollower::passed_line, &WaypointFollower::set_passed_line,
                    "ArduPlane's switching: a waypoint is also done once past the line through it perpendicular "
                    "to its leg, and the turn is anticipated (waypoint_nav's 'wn_passed_line')")
      .def_property("finish_line", &WaypointFollower::finish_line, &WaypointFollower::set_finish_line,
                    "the flight ends past the last waypoint's perpendicular line, not inside R_WP of it")
      .def_property_readonly("active", &WaypointFollower::active, "index of the active waypoint")
      .def_property_readonly("accepted_at", [](const WaypointFollower& w) { return to_numpy(w.accepted_at()); },
                             "time each waypoint was accepted (NaN: not yet)")
      .def_property_readonly("waypoint_radius", &WaypointFollower::acceptance_radius, "R_WP");

  py::class_<FlightSmoothness>(m, "FlightSmoothness", "How smoothly a flight banks (flight_smoothness).")
      .def_readonly("bank_rms_deg", &FlightSmoothness::bank_rms_deg,
                    "RMS of the bank about its moving mean over the window, degrees")
      .def_readonly("roll_reversals_per_s", &FlightSmoothness::roll_reversals_per_s,
                    "reversals of the bank (deadband: successive extrema that far apart) per second")
      .def_readonly("roll_reversals", &FlightSmoothness::roll_reversals, "their count")
      .def_readonly("max_roll_rate_deg_s", &FlightSmoothness::max_roll_rate_deg_s,
                    "largest |bank change / time| between successive samples, deg/s")
      .def("as_dict", [](const FlightSmoothness& s) {
             py::dict d;
             d["bank_rms_deg"] = s.bank_rms_deg;
             d["roll_reversals_per_s"] = s.roll_reversals_per_s;
             d["roll_reversals"] = s.roll_reversals;
             d["max_roll_rate_deg_s"] = s.max_roll_rate_deg_s;
             return d;
           }, "The measures as a dict (metrics.json).")
      .def("__repr__", [](const FlightSmoothness& s) {
        return Repr("FlightSmoothness")
            .add("bank_rms_deg", s.bank_rms_deg)
            .add("roll_reversals_per_s", s.roll_reversals_per_s)
            .add("max_roll_rate_deg_s", s.max_roll_rate_deg_s)
            .str();
      });
  py::class_<FlightTrajectory>(m, "FlightTrajectory",
                               "One sample per output time: state, the turn rate applied from there, the bank, the "
                               "active target and the wind.")
      .def_property_readonly("t", [](const FlightTrajectory& f) { return to_numpy(f.t); }, "times (n,), s")
      .def_property_readonly("x", [](const FlightTrajectory& f) { return to_numpy(f.x); }, "x (n,)")
      .def_property_readonly("y", [](const FlightTrajectory& f) { return to_numpy(f.y); }, "y (n,)")
      .def_property_readonly("psi", [](const FlightTrajectory& f) { return to_numpy(f.psi); },
                             "heading (n,), rad, as integrated (not wrapped)")
      .def_property_readonly("command", [](const FlightTrajectory& f) { return to_numpy(f.command); },
                             "turn rate applied from each sample (clamped to +-v/R), rad/s")
      .def_property_readonly("bank", [](const FlightTrajectory& f) { return to_numpy(f.bank); },
                             "bank (n,), rad, positive left wing down: the roll model's state, or the Dubins "
                             "model's coordinated bank of the turn rate applied from each sample")
      .def_property_readonly("bank_command", [](const FlightTrajectory& f) { return to_numpy(f.bank_command); },
                             "the coordinated bank of the guidance's clamped turn-rate command (n,), rad")
      .def("smoothness", [](const FlightTrajectory& f, double window, double deadband_deg) {
             return flight_smoothness(f.t, f.bank, window, deadband_deg);
           },
           py::arg("window") = 5.0, py::arg("deadband_deg") = 1.0,
           "How smoothly this flight banks (FlightSmoothness of its bank history).")
      .def_property_readonly("target", [](const FlightTrajectory& f) { return columns({&f.target_x, &f.target_y}); },
                             "active target (n, 2)")
      .def_property_readonly(
          "target_index",
          [](const FlightTrajectory& f) {
            return py::array_t<int>(static_cast<py::ssize_t>(f.target_index.size()), f.target_index.data());
          },
          "active target's index (n,), -1: none")
      .def_property_readonly("wind", [](const FlightTrajectory& f) { return columns({&f.wind_east, &f.wind_north}); },
                             "wind (east, north) at each sample (n, 2)")
      .def_property_readonly("array", [](const FlightTrajectory& f) { return columns({&f.t, &f.x, &f.y, &f.psi}); },
                             "(n, 4): t, x, y, psi")
      .def_readonly("finished", &FlightTrajectory::finished, "the guidance said done (else max_time was reached)")
      .def_readonly("end_time", &FlightTrajectory::end_time, "time of the last sample, s")
      .def_property_readonly("switch_times", [](const FlightTrajectory& f) { return to_numpy(f.switch_times); },
                             "times where the guidance changed its target")
      .def_readonly("statistics", &FlightTrajectory::statistics, "integrator work, vistrack.OdeStatistics (continuous flights)")
      .def("__len__", &FlightTrajectory::size);

  m.def("flight_smoothness",
        [](const Eigen::VectorXd& t, const Eigen::VectorXd& bank, double window, double deadband_deg) {
          return flight_smoothness(std::vector<double>(t.data(), t.data() + t.size()),
                                   std::vector<double>(bank.data(), bank.data() + bank.size()), window, deadband_deg);
        },
        py::arg("t"), py::arg("bank"), py::arg("window") = 5.0,
        py::arg("deadband_deg") = 1.0,
        "How smoothly a bank history (t in s, increasing; bank in rad) banks: bank_rms_deg about its moving mean "
        "over a centred window (s), roll_reversals_per_s with a deadband (successive extrema at least deadband_deg "
        "apart), max_roll_rate_deg_s between samples.");

  m.def("coordinated_bank", &coordinated_bank, py::arg("speed"), py::arg("turn_rate"),
        py::arg("gravity") = kStandardGravity,
        "Bank of a coordinated turn, atan(v psi_dot / g), rad (positive left).");

  py::class_<RollModel>(m, "RollModel",
                        "The roll model of a Uav: bank command atan(v r / g) within +-phi_max, "
                        "phi_dot = clamp((phi_c - phi) / tau, +-p_max), psi_dot = g tan(phi) / v.")
      .def(py::init<const Uav&, double>(), py::arg("uav"), py::arg("gravity") = kStandardGravity,
           "The model of uav (its speed, min_turn_radius, roll_time_constant, max_roll_rate_deg_s).")
      .def_property_readonly("max_bank", &RollModel::max_bank, "phi_max = atan(v^2 / (g R)), rad")
      .def_property_readonly("time_constant", &RollModel::time_constant, "tau, s")
      .def_property_readonly("max_roll_rate", &RollModel::max_roll_rate, "p_max, rad/s")
      .def("bank_command", &RollModel::bank_command, py::arg("turn_rate"), "atan(v r / g) within +-phi_max, rad")
      .def("bank_rate", &RollModel::bank_rate, py::arg("bank"), py::arg("bank_command"),
           "clamp((phi_c - phi) / tau, +-p_max), rad/s")
      .def("turn_rate", &RollModel::turn_rate, py::arg("bank"), "g tan(phi) / v, rad/s")
      .def("step", &RollModel::step, py::arg("bank"), py::arg("bank_command"), py::arg("dt"),
           "The bank after dt with the command held (closed form), rad.");

  const FlightOptions defaults;
  m.def(
      "fly",
      [](FlightGuidance& guidance, const Pose& start, double speed, double turn_radius,
         std::optional<Wind> wind, double dt, double max_time, FlightIntegration integration, double t0,
         std::optional<std::function<void(double, Pose)>> on_step,
         std::optional<std::function<void(std::size_t, std::size_t)>> progress, double rtol, double atol,
         std::optional<Uav> uav) {
        require_positive(speed, "speed");
        require_positive(turn_radius, "turn_radius");
        Uav vehicle = uav.value_or(Uav{});
        vehicle.speed = speed;
        vehicle.min_turn_radius = turn_radius;
        FlightOptions options;
        options.integration = integration;
        options.dt = dt;
        options.max_time = max_time;
        options.rtol = rtol;
        options.atol = atol;
        FlightCallback step_hook;
        if (on_step)
          step_hook = [&on_step](double t, const Configuration& q) {
            py::gil_scoped_acquire acquire;
            (*on_step)(t, std::make_tuple(q.x, q.y, q.psi));
          };
        FlightProgress bar;
        if (progress)
          bar = [&progress](std::size_t done, std::size_t total) {
            py::gil_scoped_acquire acquire;
            (*progress)(done, total);
          };
        const Wind w = wind.value_or(Wind{});
        py::gil_scoped_release release;
        return fly(vehicle, w, guidance, configuration(start), options, t0, step_hook, bar);
      },
      py::arg("guidance"), py::arg("start"), py::arg("speed"), py::arg("turn_radius"), py::arg("wind") = py::none(),
      py::arg("dt") = defaults.dt, py::arg("max_time") = defaults.max_time,
      py::arg("integration") = defaults.integration, py::arg("t0") = 0.0, py::arg("on_step") = py::none(),
      py::arg("progress") = py::none(), py::arg("rtol") = defaults.rtol, py::arg("atol") = defaults.atol,
      py::arg("uav") = py::none(),
      "Fly the vehicle (speed v, turn_radius R; uav: a Uav whose dynamics and roll parameters to use, its speed and "
      "radius replaced by these, None: the Dubins model) from start (x, y, psi) at t0 under the guidance until it is done or "
      "t0 + max_time. integration 'discrete' (the paper's update, step dt) or 'continuous' (Dormand-Prince, output "
      "every dt). on_step(t, state) runs after each accepted step (it may feed the guidance); progress(done, total) "
      "in per mille of max_time. Releases the GIL (callbacks take it).");
}

}  // namespace vistrack::bindings
