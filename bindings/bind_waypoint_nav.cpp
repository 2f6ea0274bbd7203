// vistrack._core.waypoint_nav: DWN turning points, reachability, DWN/WN flights and metrics.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "bindings.hpp"
#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"
#include "vistrack/waypoint_nav.hpp"

namespace py = pybind11;

namespace vistrack::bindings {

namespace {

using Weights = std::pair<double, double>;

FuelWeights fuel_weights(const Weights& w) { return {w.first, w.second}; }

// navigate()'s and Options' keyword arguments as the struct (not validated: the callee does).
WaypointNavOptions navigation_options(NavigationMethod method, double turn_radius, double speed, double dt,
                                      std::pair<double, double> gains, std::optional<double> waypoint_radius,
                                      const Weights& weights, FlightIntegration integration,
                                      std::optional<double> max_time, DynamicsModel dynamics,
                                      double roll_time_constant, double max_roll_rate_deg_s, LegGuidance guidance,
                                      double l1_period, bool wind_aware, double replan_interval,
                                      DwnTracking dwn_tracking, std::optional<double> path_anticipation) {
  WaypointNavOptions o;
  o.method = method;
  o.turn_radius = turn_radius;
  o.speed = speed;
  o.dt = dt;
  o.gains = {gains.first, gains.second};
  o.waypoint_radius = waypoint_radius;
  o.weights = fuel_weights(weights);
  o.integration = integration;
  o.max_time = max_time;
  o.dynamics = dynamics;
  o.roll_time_constant = roll_time_constant;
  o.max_roll_rate_deg_s = max_roll_rate_deg_s;
  o.guidance = guidance;
  o.l1.period = l1_period;
  o.wind_aware = wind_aware;
  o.replan_interval = replan_interval;
  o.dwn_tracking = dwn_tracking;
  o.path_anticipation = path_anticipation;
  return o;
}

// turning_points' batch result: one entry per horizon.
struct TurningPointBatch {
  py::array_t<double> theta, length;
  py::array_t<std::int32_t> turn_case;
  Points2 point;
};

}  // namespace

void bind_waypoint_nav(py::module_& parent) {
  py::module_ m = parent.def_submodule(
      "waypoint_nav",
      "Dubins waypoint navigation (Silverberg & Xu 2019) against classical waypoint navigation: the turning "
      "point of the 3-waypoint horizon (exact minimisation over theta, four turn cases), the reachability zone, "
      "DWN/WN flights on the flight layer and their metrics.");

  py::class_<HorizonPath>(m, "HorizonPath",
                          "The horizon path C -> arc -> straight -> T_n -> arc through W_n -> straight -> W_{n+1}.")
      .def_readonly("feasible", &HorizonPath::feasible, "False when a tangent does not exist at this theta")
      .def_property_readonly("case", [](const HorizonPath& p) { return to_string(p.turn_case); },
                             "'ccw-ccw', 'ccw-cw', 'cw-ccw' or 'cw-cw' (first arc, arc about W_n)")
      .def_readonly("theta", &HorizonPath::theta, "circle about W_n centred at W_n + R (cos theta, sin theta), [0, 2 pi)")
      .def_readonly("point", &HorizonPath::point, "T_n: the turning point, end of the first straight")
      .def_readonly("line_start", &HorizonPath::line_start, "start of the first straight (end of the first arc)")
      .def_readonly("exit_point", &HorizonPath::exit_point, "where the path leaves the circle about W_n")
      .def_readonly("circle_center", &HorizonPath::circle_center, "centre of the circle about W_n")
      .def_readonly("heading_at_waypoint", &HorizonPath::heading_at_waypoint, "heading at W_n, rad")
      .def_readonly("first_arc", &HorizonPath::first_arc, "arc length on the vehicle's turning circle")
      .def_readonly("first_straight", &HorizonPath::first_straight, "length of the straight to T_n")
      .def_readonly("arc_to_waypoint", &HorizonPath::arc_to_waypoint, "arc T_n -> W_n")
      .def_readonly("arc_from_waypoint", &HorizonPath::arc_from_waypoint, "arc W_n -> exit")
      .def_readonly("last_straight", &HorizonPath::last_straight, "straight exit -> W_{n+1}")
      .def_readonly("length", &HorizonPath::length, "weighted length w_a arcs + w_s straights (inf if infeasible)")
      .def("__repr__", [](const HorizonPath& p) {
        return Repr("HorizonPath").add("case", p.turn_case).add("theta", p.theta).add("point", p.point).add("length", p.length).str();
      });

  py::class_<TurningPoint, HorizonPath>(m, "TurningPoint", "The optimal horizon path over theta and the four cases.")
      .def_property_readonly(
          "case_lengths",
          [](const TurningPoint& t) {
            std::map<std::string, double> lengths;
            for (int c = 0; c < kTurnCaseCount; ++c)
              lengths[to_string(static_cast<TurnCase>(c))] = t.case_lengths[static_cast<std::size_t>(c)];
            return lengths;
          },
          "best length found per case (exact for the winner; the others are refined only where they could win)")
      .def_readonly("evaluations", &TurningPoint::evaluations, "F(h) evaluations spent");

  m.def(
      "turning_point",
      [](const Pose& pose, const Vec2& w_next, const Vec2& w_after, double turn_radius, const Weights& weights) {
        return turning_point(configuration(pose), w_next, w_after, turn_radius, fuel_weights(weights));
      },
      py::arg("pose"), py::arg("w_next"), py::arg("w_after"), py::arg("turn_radius"),
      py::arg("weights") = Weights{FuelWeights{}.arc, FuelWeights{}.straight},
      "Turning point T_n over the horizon (pose C, W_n, W_{n+1}): minimises F = w_a L_a + w_s L_s over theta for "
      "the four cases; theta to 1e-12 rad.");
  m.def(
      "air_mass_turning_point",
      [](const Pose& pose, const Vec2& w_next, const Vec2& w_after, double turn_radius, double speed,
         const Vec2& wind, const Weights& weights) {
        return air_mass_turning_point(configuration(pose), w_next, w_after, turn_radius, speed, wind,
                                      fuel_weights(weights));
      },
      py::arg("pose"), py::arg("w_next"), py::arg("w_after"), py::arg("turn_radius"), py::arg("speed"),
      py::arg("wind"), py::arg("weights") = Weights{FuelWeights{}.arc, FuelWeights{}.straight},
      "Turning point planned in the air mass of the mean wind (east, north) at airspeed speed: the horizon "
      "solved for the waypoints as the air sees them (W - wind tau, tau from the path's arc lengths), mapped back "
      "to the ground (each point moved by wind x the time the vehicle reaches it). Wind (0, 0): turning_point.");
  py::class_<TurningPointBatch>(m, "TurningPoints", "Turning points of many horizons, one row each.")
      .def_readonly("theta", &TurningPointBatch::theta, "(n,) theta of each optimum, rad")
      .def_readonly("length", &TurningPointBatch::length, "(n,) its weighted length")
      .def_readonly("case", &TurningPointBatch::turn_case, "(n,) its turn case, indexing CASES")
      .def_readonly("point", &TurningPointBatch::point, "(n, 2) the turning points T_n");
  m.def(
      "turning_points",
      [](const Points3& poses, const Points2& w_next, const Points2& w_after, double turn_radius,
         const Weights& weights) {
        if (w_next.rows() != poses.rows() || w_after.rows() != poses.rows())
          detail::fail_field("w_next.shape[0]", w_next.rows(), "poses, w_next and w_after need the same row count");
        const auto n = static_cast<std::size_t>(poses.rows());
        std::vector<double> theta(n), length(n);
        std::vector<std::int32_t> cases(n);
        Points2 point(poses.rows(), 2);
        const FuelWeights w = fuel_weights(weights);
        {
          py::gil_scoped_release release;
          for (Eigen::Index i = 0; i < poses.rows(); ++i) {
            const TurningPoint tp = turning_point({poses(i, 0), poses(i, 1), poses(i, 2)}, w_next.row(i).transpose(),
                                                  w_after.row(i).transpose(), turn_radius, w);
            theta[static_cast<std::size_t>(i)] = tp.theta;
            length[static_cast<std::size_t>(i)] = tp.length;
            cases[static_cast<std::size_t>(i)] = static_cast<std::int32_t>(tp.turn_case);
            point.row(i) = tp.point.transpose();
          }
        }
        return TurningPointBatch{to_numpy(theta), to_numpy(length), to_numpy(cases), std::move(point)};
      },
      py::arg("poses"), py::arg("w_next"), py::arg("w_after"), py::arg("turn_radius"),
      py::arg("weights") = Weights{FuelWeights{}.arc, FuelWeights{}.straight},
      "Batch of turning points, one thread, GIL released: poses (n, 3), w_next and w_after (n, 2) -> "
      "TurningPoints.");
  m.attr("CASES") = enum_names<TurnCase>();
  m.def(
      "horizon_path",
      [](const Pose& pose, const Vec2& w_next, const Vec2& w_after, double turn_radius, TurnCase c,
         double theta, const Weights& weights) {
        return horizon_path(configuration(pose), w_next, w_after, turn_radius, c, theta,
                            fuel_weights(weights));
      },
      py::arg("pose"), py::arg("w_next"), py::arg("w_after"), py::arg("turn_radius"), py::arg("case"),
      py::arg("theta"), py::arg("weights") = Weights{FuelWeights{}.arc, FuelWeights{}.straight},
      "The horizon path of one case at one theta.");
  m.def(
      "horizon_lengths",
      [](const Pose& pose, const Vec2& w_next, const Vec2& w_after, double turn_radius, TurnCase tc,
         const std::vector<double>& thetas, const Weights& weights) {
        std::vector<double> out(thetas.size());
        for (std::size_t i = 0; i < thetas.size(); ++i)
          out[i] = horizon_path(configuration(pose), w_next, w_after, turn_radius, tc, thetas[i], fuel_weights(weights))
                       .length;
        return to_numpy(out);
      },
      py::arg("pose"), py::arg("w_next"), py::arg("w_after"), py::arg("turn_radius"), py::arg("case"),
      py::arg("thetas"), py::arg("weights") = Weights{FuelWeights{}.arc, FuelWeights{}.straight},
      "F(theta) of one case at each theta (inf where the path does not exist).");
  m.def(
      "reachability",
      [](const Pose& pose, const Points2& pts, double turn_radius) {
        require_length(turn_radius, "turn_radius");
        require_coordinate(std::get<0>(pose), "pose[0]");
        require_coordinate(std::get<1>(pose), "pose[1]");
        require_angle(std::get<2>(pose), "pose[2]");
        for (Eigen::Index i = 0; i < pts.rows(); ++i)
          for (int k = 0; k < 2; ++k)
            require_coordinate(pts(i, k), "points[" + std::to_string(i) + "][" + std::to_string(k) + "]");
        std::vector<double> out(static_cast<std::size_t>(pts.rows()));
        for (Eigen::Index i = 0; i < pts.rows(); ++i)
          out[static_cast<std::size_t>(i)] = reachability(configuration(pose), pts.row(i).transpose(), turn_radius);
        return to_numpy(out);
      },
      py::arg("pose"), py::arg("points"), py::arg("turn_radius"),
      "For each point (n, 2): <= 0 inside the reachability zone (unreachable), > 0 outside.");

  py::class_<DubinsWaypointGuidance, FlightGuidance>(
      m, "DubinsWaypointGuidance",
      "DWN as a flight guidance for vistrack.flight.fly: the law (5) to each turning point, the next one when it "
      "becomes unreachable; the last waypoint flown to directly.")
      .def(py::init([](const LineFeedback& law, const InputArray& waypoints, double turn_radius, const Weights& w) {
             return DubinsWaypointGuidance(law, to_points(waypoints, "waypoints"), turn_radius, fuel_weights(w));
           }),
           py::arg("law"), py::arg("waypoints"), py::arg("turn_radius"),
           py::arg("weights") = Weights{FuelWeights{}.arc, FuelWeights{}.straight})
      .def(py::init([](const L1Line& law, const InputArray& waypoints, double turn_radius, const Weights& w) {
             return DubinsWaypointGuidance(law, to_points(waypoints, "waypoints"), turn_radius, fuel_weights(w));
           }),
           py::arg("law"), py::arg("waypoints"), py::arg("turn_radius"),
           py::arg("weights") = Weights{FuelWeights{}.arc, FuelWeights{}.straight},
           "The same with each leg to a turning point flown by L1 line tracking (law: L1Line).")
      .def_property_readonly("active", &DubinsWaypointGuidance::active, "index of the waypoint being approached")
      .def("set_wind", &DubinsWaypointGuidance::set_wind, py::arg("mean_wind"), py::arg("speed"),
           "Plan every turning point in the air mass of the mean wind (east, north) at airspeed speed, the law "
           "flying the air frame's line (give it a law without wind); (0, 0): the paper's planning.")
      .def_property("replan_interval", &DubinsWaypointGuidance::replan_interval,
                    &DubinsWaypointGuidance::set_replan_interval,
                    "re-plan the active turning point every so many s (section 2.1); 0: at the reachability switch")
      .def(
          "set_path_following",
          [](DubinsWaypointGuidance& g, double speed, double anticipation, double lookahead_radii,
             double heading_gain) {
            g.set_path_following(PathFollowingGains{lookahead_radii, heading_gain, anticipation}, speed);
          },
          py::arg("speed"), py::arg("anticipation"), py::arg("lookahead_radii") = PathFollowingGains{}.lookahead_radii,
          py::arg("heading_gain") = PathFollowingGains{}.heading_gain,
          "Beyond the paper: fly each planned horizon path (first arc, straight to T_n, arc through W_n, straight "
          "to W_{n+1}) with PathFollower at airspeed speed, its curvature feed-forward anticipation s ahead (a "
          "banking vehicle's roll lag), instead of the leg law to T_n; the last waypoint along the last plan's "
          "tail.")
      .def_property_readonly("path_following", &DubinsWaypointGuidance::path_following,
                             "True once set_path_following was called")
      .def_property_readonly(
          "turning_points",
          [](const DubinsWaypointGuidance& g) {
            std::vector<Vec2> points;
            for (const TurningPointRecord& record : g.turning_points()) points.push_back(record.path.point);
            return to_array(points);
          },
          "(k, 2) every turning point planned so far");

  py::class_<TurningPointRecord>(m, "TurningPointRecord", "One turning point planned during a DWN flight.")
      .def_readonly("t", &TurningPointRecord::t, "when it was planned, s")
      .def_readonly("waypoint", &TurningPointRecord::waypoint, "index of its waypoint in the flown list")
      .def_property_readonly("pose", [](const TurningPointRecord& r) { return Pose{r.pose.x, r.pose.y, r.pose.psi}; },
                             "(x, y, psi) of the vehicle when planned")
      .def_readonly("path", &TurningPointRecord::path, "the horizon path")
      .def_readonly("direct", &TurningPointRecord::direct, "the last waypoint, flown to directly")
      .def_property_readonly("wind", [](const TurningPointRecord& r) { return r.wind; },
                             "(east, north) mean wind it was planned in the air mass of; (0, 0): in still air")
      .def_property_readonly("air_point", [](const TurningPointRecord& r) { return r.air_point; },
                             "(x, y) the turning point as a point of the air mass when planned (drifts with wind)");

  py::class_<NavigationResult>(m, "NavigationResult", "One WN or DWN flight and its metrics.")
      .def_readonly("trajectory", &NavigationResult::trajectory, "vistrack.flight.FlightTrajectory")
      .def_readonly("turning_points", &NavigationResult::turning_points, "TurningPointRecord list (DWN)")
      .def_readonly("method", &NavigationResult::method, "'dwn' or 'wn'")
      .def_readonly("waypoint_radius", &NavigationResult::waypoint_radius, "R_WP (WN)")
      .def_readonly("max_time", &NavigationResult::max_time, "time limit used, s")
      .def_property_readonly("miss_distances", [](const NavigationResult& r) { return to_numpy(r.metrics.miss_distances); },
                             "closest approach to each waypoint")
      .def_property_readonly(
          "reached",
          [](const NavigationResult& r) {
            py::array_t<bool> out(static_cast<py::ssize_t>(r.metrics.reached.size()));
            for (std::size_t i = 0; i < r.metrics.reached.size(); ++i) out.mutable_data()[i] = r.metrics.reached[i] != 0;
            return out;
          },
          "whether the guidance got past each waypoint in time")
      .def_property_readonly("all_reached", [](const NavigationResult& r) { return r.metrics.all_reached; })
      .def_property_readonly("closest_times", [](const NavigationResult& r) { return to_numpy(r.metrics.closest_times); },
                             "time of each waypoint's closest approach, s")
      .def_property_readonly("overshoots", [](const NavigationResult& r) { return to_numpy(r.metrics.overshoots); },
                             "per waypoint: the largest distance outside the turn there")
      .def_property_readonly("overshoot", [](const NavigationResult& r) { return r.metrics.overshoot; },
                             "largest distance from the legs outside their turns")
      .def_property_readonly("undershoot", [](const NavigationResult& r) { return r.metrics.undershoot; },
                             "largest distance from the legs inside their turns")
      .def_property_readonly("swirls", [](const NavigationResult& r) { return r.metrics.swirls; },
                             "loops around the active waypoint: full turns of the bearing to it, either way, "
                             "while it is the target")
      .def_property_readonly("path_length", [](const NavigationResult& r) { return r.metrics.path_length; })
      .def_property_readonly("duration", [](const NavigationResult& r) { return r.metrics.duration; })
      .def_property_readonly("fuel", [](const NavigationResult& r) { return r.metrics.fuel; },
                             "sum of v dt (w_s + (w_a - w_s) |r| / (v/R))");

  const WaypointNavOptions defaults;
  py::class_<WaypointNavOptions>(m, "Options",
                                 "One navigation flight's settings; the defaults (the paper's section 3) are those of "
                                 "navigate() and fly().")
      .def(py::init([](NavigationMethod method, double turn_radius, double speed, double dt,
                       std::pair<double, double> gains, std::optional<double> waypoint_radius, const Weights& weights,
                       FlightIntegration integration, std::optional<double> max_time, DynamicsModel dynamics,
                       double roll_time_constant, double max_roll_rate_deg_s, LegGuidance guidance,
                       double l1_period, bool wind_aware, double replan_interval, DwnTracking dwn_tracking,
                       std::optional<double> path_anticipation) {
             return make_validated(navigation_options(method, turn_radius, speed, dt, gains, waypoint_radius, weights,
                                                      integration, max_time, dynamics, roll_time_constant,
                                                      max_roll_rate_deg_s, guidance, l1_period, wind_aware,
                                                      replan_interval, dwn_tracking, path_anticipation));
           }),
           py::kw_only(), py::arg("method") = defaults.method, py::arg("turn_radius") = defaults.turn_radius,
           py::arg("speed") = defaults.speed, py::arg("dt") = defaults.dt,
           py::arg("gains") = std::make_pair(defaults.gains.g, defaults.gains.h), py::arg("waypoint_radius") = py::none(),
           py::arg("weights") = Weights{defaults.weights.arc, defaults.weights.straight},
           py::arg("integration") = defaults.integration, py::arg("max_time") = py::none(),
           py::arg("dynamics") = defaults.dynamics, py::arg("roll_time_constant") = defaults.roll_time_constant,
           py::arg("max_roll_rate_deg_s") = defaults.max_roll_rate_deg_s, py::arg("guidance") = defaults.guidance,
           py::arg("l1_period") = defaults.l1.period, py::arg("wind_aware") = defaults.wind_aware,
           py::arg("replan_interval") = defaults.replan_interval, py::arg("dwn_tracking") = defaults.dwn_tracking,
           py::arg("path_anticipation") = py::none(),
           "method 'dwn', 'wn' or 'wn_passed_line'; turn_radius R; speed v; law step dt; gains (g, h); waypoint_radius: WN's R_WP "
           "(None: R); weights (w_a, w_s); integration 'discrete' or 'continuous'; max_time (None: 3 (route length + "
           "2 pi R per waypoint) / v); dynamics 'dubins' or 'roll' (metres and seconds) with the roll model's "
           "roll_time_constant (s) and max_roll_rate_deg_s; guidance 'law5' (the paper's law (5) with gains) or "
           "'l1' (L1 line tracking, period l1_period s, damping 0.75) on every leg; wind_aware: the leg law steers the "
           "course over the ground with the known mean wind (and DWN plans its turning points in the air mass); "
           "replan_interval: DWN re-plans the active turning point every so many seconds (0: only at the "
           "reachability switch, the paper's flights); dwn_tracking (beyond the paper) 'paper' (the leg law to each "
           "turning point), 'path' (the planned horizon path followed in closed loop, the roll anticipated "
           "path_anticipation s ahead, None: the roll model's lag) or 'auto' ('paper' on dubins, 'path' on roll).")
      .def_readwrite("method", &WaypointNavOptions::method, "'dwn' or 'wn'")
      .def_readwrite("turn_radius", &WaypointNavOptions::turn_radius, "R: minimum turn radius and DWN's turning circles")
      .def_readwrite("speed", &WaypointNavOptions::speed, "v")
      .def_readwrite("dt", &WaypointNavOptions::dt, "the law's step (and the discrete flight's)")
      .def_property(
          "gains", [](const WaypointNavOptions& o) { return std::make_pair(o.gains.g, o.gains.h); },
          [](WaypointNavOptions& o, std::pair<double, double> gains) { o.gains = {gains.first, gains.second}; },
          "(g, h) of the feedback law (5)")
      .def_readwrite("waypoint_radius", &WaypointNavOptions::waypoint_radius, "WN's R_WP; None: R (DWN has none)")
      .def_property(
          "weights", [](const WaypointNavOptions& o) { return Weights{o.weights.arc, o.weights.straight}; },
          [](WaypointNavOptions& o, const Weights& weights) { o.weights = fuel_weights(weights); },
          "(w_a, w_s): fuel per unit length on arcs and straights")
      .def_readwrite("integration", &WaypointNavOptions::integration, "'discrete' (the paper's) or 'continuous'")
      .def_readwrite("max_time", &WaypointNavOptions::max_time, "time limit, s; None: from the route")
      .def_readwrite("dynamics", &WaypointNavOptions::dynamics,
                     "'dubins' (the paper's) or 'roll' (the roll model: route in metres, speed in m/s)")
      .def_readwrite("roll_time_constant", &WaypointNavOptions::roll_time_constant, "roll model: tau, s")
      .def_readwrite("guidance", &WaypointNavOptions::guidance,
                     "'law5' (the paper's law (5)) or 'l1' (L1 line tracking) on every leg")
      .def_property(
          "l1_period", [](const WaypointNavOptions& o) { return o.l1.period; },
          [](WaypointNavOptions& o, double period) { o.l1.period = period; }, "guidance l1: the L1 period, s")
      .def_readwrite("wind_aware", &WaypointNavOptions::wind_aware,
                     "the leg law knows the mean wind and steers the course over the ground (beyond the paper)")
      .def_readwrite("max_roll_rate_deg_s", &WaypointNavOptions::max_roll_rate_deg_s, "roll model: p_max, deg/s")
      .def_readwrite("replan_interval", &WaypointNavOptions::replan_interval,
                     "DWN: re-plan the active turning point every so many seconds; 0: at the reachability switch only")
      .def_readwrite("dwn_tracking", &WaypointNavOptions::dwn_tracking,
                     "DWN: 'paper' (the leg law to each turning point), 'path' (the planned path followed, beyond the "
                     "paper) or 'auto' ('paper' on dubins, 'path' on roll)")
      .def_readwrite("path_anticipation", &WaypointNavOptions::path_anticipation,
                     "DWN 'path': the feed-forward's lead, s; None: roll_lag()")
      .def("resolved_tracking", &WaypointNavOptions::resolved_tracking, "What 'auto' means for this vehicle.")
      .def("roll_lag", &WaypointNavOptions::roll_lag,
           "The roll model's lag, s: the heading lost to the bank's response to a step 0 -> phi_max, integral of "
           "(1 - phi / phi_max) dt (tau without the rate limit; 0 on dubins).")
      .def("validate", &WaypointNavOptions::validate, "Raise VistrackError naming the first invalid field.")
      .def("__repr__", [](const WaypointNavOptions& o) {
        Repr text("waypoint_nav.Options");
        text.add("method", o.method).add("turn_radius", o.turn_radius).add("speed", o.speed).add("dt", o.dt);
        text.add("gains", Vec2(o.gains.g, o.gains.h));
        if (o.waypoint_radius) text.add("waypoint_radius", *o.waypoint_radius);
        text.add("weights", Vec2(o.weights.arc, o.weights.straight));
        text.add("integration", o.integration);
        if (o.max_time) text.add("max_time", *o.max_time);
        text.add("dynamics", o.dynamics).add("guidance", o.guidance);
        if (o.guidance == LegGuidance::L1) text.add("l1_period", o.l1.period);
        if (o.wind_aware) text.add("wind_aware", o.wind_aware);
        if (o.replan_interval > 0.0) text.add("replan_interval", o.replan_interval);
        if (o.dwn_tracking != DwnTracking::Auto) text.add("dwn_tracking", o.dwn_tracking);
        if (o.path_anticipation) text.add("path_anticipation", *o.path_anticipation);
        if (o.dynamics == DynamicsModel::Roll)
          text.add("roll_time_constant", o.roll_time_constant).add("max_roll_rate_deg_s", o.max_roll_rate_deg_s);
        return text.str();
      });

  m.def(
      "navigate",
      [](const InputArray& waypoints, const Pose& start, NavigationMethod method, double turn_radius, double speed,
         double dt, std::pair<double, double> gains, std::optional<double> waypoint_radius, const Weights& weights,
         std::optional<Wind> wind, FlightIntegration integration, std::optional<double> max_time,
         DynamicsModel dynamics, double roll_time_constant, double max_roll_rate_deg_s, LegGuidance guidance,
         double l1_period, bool wind_aware, double replan_interval, DwnTracking dwn_tracking,
         std::optional<double> path_anticipation) {
        const WaypointNavOptions o = navigation_options(method, turn_radius, speed, dt, gains, waypoint_radius, weights,
                                                        integration, max_time, dynamics, roll_time_constant,
                                                        max_roll_rate_deg_s, guidance, l1_period, wind_aware,
                                                        replan_interval, dwn_tracking, path_anticipation);
        const std::vector<Vec2> route = to_points(waypoints, "waypoints");
        const Wind w = wind.value_or(Wind{});
        py::gil_scoped_release release;
        return navigate(route, configuration(start), o, w);
      },
      py::arg("waypoints"), py::arg("start"), py::kw_only(), py::arg("method") = defaults.method,
      py::arg("turn_radius") = defaults.turn_radius, py::arg("speed") = defaults.speed, py::arg("dt") = defaults.dt,
      py::arg("gains") = std::make_pair(defaults.gains.g, defaults.gains.h), py::arg("waypoint_radius") = py::none(),
      py::arg("weights") = Weights{defaults.weights.arc, defaults.weights.straight}, py::arg("wind") = py::none(),
      py::arg("integration") = defaults.integration, py::arg("max_time") = py::none(),
      py::arg("dynamics") = defaults.dynamics, py::arg("roll_time_constant") = defaults.roll_time_constant,
      py::arg("max_roll_rate_deg_s") = defaults.max_roll_rate_deg_s, py::arg("guidance") = defaults.guidance,
      py::arg("l1_period") = defaults.l1.period, py::arg("wind_aware") = defaults.wind_aware,
      py::arg("replan_interval") = defaults.replan_interval, py::arg("dwn_tracking") = defaults.dwn_tracking,
      py::arg("path_anticipation") = py::none(),
      "Fly every waypoint (n, 2) in order from start (x, y, psi) with 'dwn' or 'wn' on the 'dubins' or 'roll' "
      "vehicle, each leg by 'law5' or 'l1' (DWN: or its planned path followed, dwn_tracking 'path'; 'auto': on the "
      "roll model); returns NavigationResult. Releases the GIL.");

  m.def(
      "navigation_guidance",
      [](const InputArray& waypoints, const Pose& start, const WaypointNavOptions& options, std::optional<Wind> wind) {
        return navigation_guidance(to_points(waypoints, "waypoints"), configuration(start), options,
                                   wind.value_or(Wind{}));
      },
      py::arg("waypoints"), py::arg("start"), py::arg("options"), py::arg("wind") = py::none(),
      "The guidance navigate() flies for these waypoints (n, 2) from start (x, y, psi) with these Options: a "
      "DubinsWaypointGuidance or a WaypointFollower, for any vehicle that flies a FlightGuidance (vistrack.fdm's "
      "aircraft too); wind: its constant part is known to the guidance when options.wind_aware.");
  m.def(
      "navigation_time_limit",
      [](const InputArray& waypoints, const Pose& start, const WaypointNavOptions& options) {
        return navigation_time_limit(to_points(waypoints, "waypoints"), configuration(start), options);
      },
      py::arg("waypoints"), py::arg("start"), py::arg("options"),
      "navigate()'s time limit (s): options.max_time, else 3 (route length from start + 2 pi R per waypoint) / v.");

  m.def(
      "navigation_metrics",
      [](const std::vector<double>& t, const std::vector<double>& x, const std::vector<double>& y,
         const std::vector<double>& command, const std::vector<int>& target_index, bool finished, const Vec2& start,
         const InputArray& waypoints, double speed, double turn_radius, const Weights& weights) {
        const std::size_t n = t.size();
        if (x.size() != n || y.size() != n || command.size() != n || target_index.size() != n)
          detail::fail_field("trajectory", static_cast<double>(n),
                             "t, x, y, command and target_index must have the same length");
        FlightTrajectory traj;
        traj.t = t;
        traj.x = x;
        traj.y = y;
        traj.command = command;
        traj.target_index = target_index;
        traj.finished = finished;
        traj.psi.assign(n, 0.0);
        const NavigationMetrics r =
            navigation_metrics(traj, start, to_points(waypoints, "waypoints"), speed, turn_radius, fuel_weights(weights));
        py::dict out;
        out["miss_distances"] = to_numpy(r.miss_distances);
        out["closest_times"] = to_numpy(r.closest_times);
        out["reached"] = std::vector<bool>(r.reached.begin(), r.reached.end());
        out["all_reached"] = r.all_reached;
        out["overshoot"] = r.overshoot;
        out["undershoot"] = r.undershoot;
        out["swirls"] = r.swirls;
        out["path_length"] = r.path_length;
        out["duration"] = r.duration;
        out["fuel"] = r.fuel;
        return out;
      },
      py::arg("t"), py::arg("x"), py::arg("y"), py::arg("command"), py::arg("target_index"), py::arg("finished"),
      py::arg("start"), py::arg("waypoints"), py::arg("speed"), py::arg("turn_radius"),
      py::arg("weights") = Weights{FuelWeights{}.arc, FuelWeights{}.straight},
      "The metrics of navigate() (miss distances, reached, over- and undershoot, swirls, path length, duration, "
      "fuel) of a flight flown elsewhere (vistrack.fdm): samples t, x, y, the turn-rate command and the guidance's "
      "target index, as a dict.");
}

}  // namespace vistrack::bindings
