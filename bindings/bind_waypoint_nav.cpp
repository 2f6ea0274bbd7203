// vistrack._core.waypoint_nav: DWN turning points, reachability, DWN/WN flights and metrics.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstdint>
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

using Pose = std::tuple<double, double, double>;
using Weights = std::pair<double, double>;

Configuration configuration(const Pose& q) { return {std::get<0>(q), std::get<1>(q), std::get<2>(q)}; }
FuelWeights fuel_weights(const Weights& w) { return {w.first, w.second}; }

py::array_t<double> to_numpy(const std::vector<double>& values) {
  return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
}

std::vector<Vec2> points(const Points2& array, const std::string& field) {
  std::vector<Vec2> out;
  for (Eigen::Index i = 0; i < array.rows(); ++i) {
    const Vec2 p = array.row(i).transpose();
    require_finite(p.x(), field + "[" + std::to_string(i) + "].x");
    require_finite(p.y(), field + "[" + std::to_string(i) + "].y");
    out.push_back(p);
  }
  return out;
}

NavigationMethod method_from_string(const std::string& text) {
  if (text == "dwn") return NavigationMethod::Dubins;
  if (text == "wn") return NavigationMethod::Classical;
  detail::fail_field("method", text, "must be 'dwn' or 'wn'");
}

std::string method_name(NavigationMethod m) { return m == NavigationMethod::Dubins ? "dwn" : "wn"; }

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
        return "HorizonPath(case='" + to_string(p.turn_case) + "', theta=" + detail::to_text(p.theta) +
               ", point=(" + detail::to_text(p.point.x()) + ", " + detail::to_text(p.point.y()) +
               "), length=" + detail::to_text(p.length) + ")";
      });

  py::class_<TurningPoint, HorizonPath>(m, "TurningPoint", "The optimal horizon path over theta and the four cases.")
      .def_property_readonly(
          "case_lengths",
          [](const TurningPoint& t) {
            py::dict d;
            for (int c = 0; c < kTurnCaseCount; ++c)
              d[py::str(to_string(static_cast<TurnCase>(c)))] = t.case_lengths[static_cast<std::size_t>(c)];
            return d;
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
        py::dict out;
        out["theta"] = to_numpy(theta);
        out["length"] = to_numpy(length);
        out["case"] = py::array_t<std::int32_t>(static_cast<py::ssize_t>(n), cases.data());
        out["point"] = point;
        return out;
      },
      py::arg("poses"), py::arg("w_next"), py::arg("w_after"), py::arg("turn_radius"),
      py::arg("weights") = Weights{FuelWeights{}.arc, FuelWeights{}.straight},
      "Batch of turning points, one thread, GIL released: poses (n, 3), w_next and w_after (n, 2) -> dict of "
      "theta (n,), length (n,), case (n,) indexing CASES, point (n, 2).");
  py::list case_names;
  for (int c = 0; c < kTurnCaseCount; ++c) case_names.append(to_string(static_cast<TurnCase>(c)));
  m.attr("CASES") = py::tuple(case_names);
  m.def(
      "horizon_path",
      [](const Pose& pose, const Vec2& w_next, const Vec2& w_after, double turn_radius, const std::string& c,
         double theta, const Weights& weights) {
        return horizon_path(configuration(pose), w_next, w_after, turn_radius, turn_case_from_string(c), theta,
                            fuel_weights(weights));
      },
      py::arg("pose"), py::arg("w_next"), py::arg("w_after"), py::arg("turn_radius"), py::arg("case"),
      py::arg("theta"), py::arg("weights") = Weights{FuelWeights{}.arc, FuelWeights{}.straight},
      "The horizon path of one case at one theta.");
  m.def(
      "horizon_lengths",
      [](const Pose& pose, const Vec2& w_next, const Vec2& w_after, double turn_radius, const std::string& c,
         const std::vector<double>& thetas, const Weights& weights) {
        const TurnCase tc = turn_case_from_string(c);
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
      .def(py::init([](const LineFeedback& law, const Points2& waypoints, double turn_radius, const Weights& w) {
             return DubinsWaypointGuidance(law, points(waypoints, "waypoints"), turn_radius, fuel_weights(w));
           }),
           py::arg("law"), py::arg("waypoints"), py::arg("turn_radius"),
           py::arg("weights") = Weights{FuelWeights{}.arc, FuelWeights{}.straight})
      .def_property_readonly("active", &DubinsWaypointGuidance::active, "index of the waypoint being approached")
      .def_property_readonly(
          "turning_points",
          [](const DubinsWaypointGuidance& g) {
            Points2 out(static_cast<Eigen::Index>(g.turning_points().size()), 2);
            for (std::size_t i = 0; i < g.turning_points().size(); ++i)
              out.row(static_cast<Eigen::Index>(i)) = g.turning_points()[i].path.point.transpose();
            return out;
          },
          "(k, 2) every turning point planned so far");

  py::class_<TurningPointRecord>(m, "TurningPointRecord", "One turning point planned during a DWN flight.")
      .def_readonly("t", &TurningPointRecord::t, "when it was planned, s")
      .def_readonly("waypoint", &TurningPointRecord::waypoint, "index of its waypoint in the flown list")
      .def_property_readonly("pose", [](const TurningPointRecord& r) { return Pose{r.pose.x, r.pose.y, r.pose.psi}; },
                             "(x, y, psi) of the vehicle when planned")
      .def_readonly("path", &TurningPointRecord::path, "the horizon path")
      .def_readonly("direct", &TurningPointRecord::direct, "the last waypoint, flown to directly");

  py::class_<NavigationResult>(m, "NavigationResult", "One WN or DWN flight and its metrics.")
      .def_readonly("trajectory", &NavigationResult::trajectory, "vistrack.flight.FlightTrajectory")
      .def_readonly("turning_points", &NavigationResult::turning_points, "TurningPointRecord list (DWN)")
      .def_property_readonly("method", [](const NavigationResult& r) { return method_name(r.method); }, "'dwn' or 'wn'")
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
      .def_property_readonly("overshoot", [](const NavigationResult& r) { return r.metrics.overshoot; },
                             "largest distance from the legs outside their turns")
      .def_property_readonly("undershoot", [](const NavigationResult& r) { return r.metrics.undershoot; },
                             "largest distance from the legs inside their turns")
      .def_property_readonly("swirls", [](const NavigationResult& r) { return r.metrics.swirls; },
                             "full 2 pi heading excursions while one waypoint is active")
      .def_property_readonly("path_length", [](const NavigationResult& r) { return r.metrics.path_length; })
      .def_property_readonly("duration", [](const NavigationResult& r) { return r.metrics.duration; })
      .def_property_readonly("fuel", [](const NavigationResult& r) { return r.metrics.fuel; },
                             "sum of v dt (w_s + (w_a - w_s) |r| / (v/R))");

  const WaypointNavOptions defaults;
  py::dict d;
  d["turn_radius"] = defaults.turn_radius;
  d["speed"] = defaults.speed;
  d["dt"] = defaults.dt;
  d["gains"] = py::make_tuple(defaults.gains.g, defaults.gains.h);
  d["weights"] = py::make_tuple(defaults.weights.arc, defaults.weights.straight);
  d["integration"] = to_string(defaults.integration);
  d["method"] = method_name(defaults.method);
  m.attr("DEFAULTS") = d;

  m.def(
      "navigate",
      [](const Points2& waypoints, const Pose& start, const std::string& method, double turn_radius, double speed,
         double dt, std::pair<double, double> gains, std::optional<double> waypoint_radius, const Weights& weights,
         std::optional<Wind> wind, const std::string& integration, std::optional<double> max_time) {
        WaypointNavOptions o;
        o.method = method_from_string(method);
        o.turn_radius = turn_radius;
        o.speed = speed;
        o.dt = dt;
        o.gains = {gains.first, gains.second};
        o.waypoint_radius = waypoint_radius;
        o.weights = fuel_weights(weights);
        o.integration = flight_integration_from_string(integration);
        o.max_time = max_time;
        const std::vector<Vec2> route = points(waypoints, "waypoints");
        const Wind w = wind.value_or(Wind{});
        py::gil_scoped_release release;
        return navigate(route, configuration(start), o, w);
      },
      py::arg("waypoints"), py::arg("start"), py::kw_only(), py::arg("method") = method_name(defaults.method),
      py::arg("turn_radius") = defaults.turn_radius, py::arg("speed") = defaults.speed, py::arg("dt") = defaults.dt,
      py::arg("gains") = std::make_pair(defaults.gains.g, defaults.gains.h), py::arg("waypoint_radius") = py::none(),
      py::arg("weights") = Weights{defaults.weights.arc, defaults.weights.straight}, py::arg("wind") = py::none(),
      py::arg("integration") = to_string(defaults.integration), py::arg("max_time") = py::none(),
      "Fly every waypoint (n, 2) in order from start (x, y, psi) with 'dwn' or 'wn'; returns NavigationResult. "
      "Releases the GIL.");
}

}  // namespace vistrack::bindings
