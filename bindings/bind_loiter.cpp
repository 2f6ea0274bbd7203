// vistrack._core.loiter: Fly-Through, TLPP and LDLPP loiter planners, camera footprint, coverage.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "vistrack/error.hpp"
#include "vistrack/loiter.hpp"

namespace py = pybind11;

namespace vistrack::bindings {
namespace {

py::tuple pair(const Vec2& p) { return py::make_tuple(p.x(), p.y()); }

LoiterProblem make_problem(const InputArray& aois, const Vec2& start, const Vec2& end, double turn_radius, double speed,
                           double aoi_radius, const AnyInteger& turns) {
  LoiterProblem problem;
  problem.aois = to_points(aois, "aois");
  problem.start = start;
  problem.end = end;
  problem.parameters = {turn_radius, speed, aoi_radius, integer<int>(turns, "turns")};
  problem.validate();
  return problem;
}

LoiterCoverageOptions make_options(double threshold, double dt) {
  LoiterCoverageOptions options;
  options.threshold = threshold;
  options.dt = dt;
  options.validate();
  return options;
}

const char* const kParameterArgs =
    "turn_radius r (m), speed v (m/s), aoi_radius R >= r (m), turns: full loiters per AOI (>= 1).";
const std::string kProblemArgs = std::string("aois: (n, 2) AOI centres (POIs), m; start, end: (x, y), m; ") + kParameterArgs;

}  // namespace

void bind_loiter(py::module_& parent) {
  py::module_ m = parent.def_submodule(
      "loiter",
      "Loiter planning over areas of interest (Wilhelm, Clem, Eberhart 2017): Fly-Through, TLPP and LDLPP as "
      "exact paths of lines and arcs, the visiting order search, a conic camera's footprint on a roll gimbal and "
      "the 75 % coverage rule. Units m, s, rad; headings counter-clockwise from +x.");

  const LoiterParameters defaults;
  const LoiterCamera camera_defaults;
  const LoiterCoverageOptions coverage_defaults;
  // The printed planners; beyond the paper, the ones that choose their loiter directions.
  m.attr("METHODS") = py::make_tuple(to_string(LoiterMethod::FlyThrough), to_string(LoiterMethod::Tlpp),
                                     to_string(LoiterMethod::Ldlpp));
  m.attr("BEYOND_PAPER_METHODS") = py::make_tuple(to_string(LoiterMethod::TlppBest), to_string(LoiterMethod::LdlppBest));
  m.attr("ORDERS") = enum_names<LoiterOrder>();
  m.attr("EXACT_ORDER_LIMIT") = kExactOrderLimit;
  m.attr("STANDARD_GRAVITY") = kStandardGravity;

  py::class_<LoiterParameters>(m, "Parameters",
                               "The vehicle and the loiters of a plan; the defaults (section 4.1's Raven RQ-11B, R = r, "
                               "one loiter) are those of plan() and of a loiter scenario.")
      .def(py::init([](double turn_radius, double speed, double aoi_radius, const AnyInteger& turns) {
             return make_validated(LoiterParameters{turn_radius, speed, aoi_radius, integer<int>(turns, "turns")});
           }),
           py::kw_only(), py::arg("turn_radius") = defaults.turn_radius, py::arg("speed") = defaults.speed,
           py::arg("aoi_radius") = defaults.aoi_radius, py::arg("turns") = defaults.turns, kParameterArgs)
      .def_readwrite("turn_radius", &LoiterParameters::turn_radius, "r: the aircraft's minimum turn radius, m.")
      .def_readwrite("speed", &LoiterParameters::speed, "v: constant airspeed, m/s.")
      .def_readwrite("aoi_radius", &LoiterParameters::aoi_radius, "R >= r: the loiter circle about each AOI, m.")
      .def_property(
          "turns", [](const LoiterParameters& p) { return p.turns; },
          [](LoiterParameters& p, const AnyInteger& turns) { p.turns = integer<int>(turns, "turns"); },
          "Full loiters flown around each AOI (at least 1).")
      .def("validate", &LoiterParameters::validate, "Raise VistrackError naming the first invalid field.")
      .def("__repr__", [](const LoiterParameters& p) {
        return Repr("loiter.Parameters")
            .add("turn_radius", p.turn_radius)
            .add("speed", p.speed)
            .add("aoi_radius", p.aoi_radius)
            .add("turns", p.turns)
            .str();
      });

  py::class_<LoiterCoverageOptions>(m, "CoverageOptions",
                                    "Section 4.1's coverage rule: an AOI is covered at a time step when at least "
                                    "`threshold` of its disk lies in the footprint; steps dt apart (the paper: 1 s).")
      .def(py::init([](double threshold, double dt, double gravity) {
             return make_validated(LoiterCoverageOptions{threshold, dt, gravity});
           }),
           py::kw_only(), py::arg("threshold") = coverage_defaults.threshold, py::arg("dt") = coverage_defaults.dt,
           py::arg("gravity") = coverage_defaults.gravity,
           "threshold: a fraction in (0, 1]; dt (s); gravity (m/s^2) for the bank of a coordinated turn.")
      .def_readwrite("threshold", &LoiterCoverageOptions::threshold, "Share of an AOI's disk in view to count, (0, 1].")
      .def_readwrite("dt", &LoiterCoverageOptions::dt, "Time step, s.")
      .def_readwrite("gravity", &LoiterCoverageOptions::gravity, "m/s^2, for the bank angle of a coordinated turn.")
      .def("validate", &LoiterCoverageOptions::validate, "Raise VistrackError naming the first invalid field.")
      .def("__repr__", [](const LoiterCoverageOptions& o) {
        return Repr("loiter.CoverageOptions").add("threshold", o.threshold).add("dt", o.dt).add("gravity", o.gravity).str();
      });

  py::class_<LoiterSegment>(m, "Segment",
                            "One piece of a plan: a line or an arc (radius r for turns, R around an AOI).")
      .def_property_readonly("kind", [](const LoiterSegment& s) { return to_string(s.kind); }, "'line' or 'arc'.")
      .def_property_readonly("role", [](const LoiterSegment& s) { return to_string(s.role); },
                             "'transit' (lines between AOIs), 'entry' (turns and lines onto a loiter circle), "
                             "'loiter' (arcs on an AOI's loiter circle), 'exit' (turns leaving it).")
      .def_property_readonly("start", [](const LoiterSegment& s) { return pair(s.start); }, "(x, y) at the start, m.")
      .def_property_readonly("end", [](const LoiterSegment& s) { return pair(s.end); }, "(x, y) at the end, m.")
      .def_readonly("start_heading", &LoiterSegment::start_heading, "Heading at the start, rad (continuous along the plan).")
      .def_readonly("end_heading", &LoiterSegment::end_heading, "Heading at the end, rad.")
      .def_property_readonly(
          "center",
          [](const LoiterSegment& s) -> std::optional<py::tuple> {
            if (s.kind == SegmentKind::Line) return std::nullopt;
            return pair(s.center);
          },
          "Arc centre (x, y), m; None for lines.")
      .def_property_readonly(
          "radius",
          [](const LoiterSegment& s) -> std::optional<double> {
            if (s.kind == SegmentKind::Line) return std::nullopt;
            return s.radius;
          },
          "Arc radius, m; None for lines.")
      .def_property_readonly(
          "direction",
          [](const LoiterSegment& s) -> std::optional<std::string> {
            if (s.kind == SegmentKind::Line) return std::nullopt;
            return to_string(s.direction);
          },
          "'ccw' or 'cw' for arcs; None for lines.")
      .def_readonly("sweep", &LoiterSegment::sweep, "Angle turned on an arc, rad (0 for lines).")
      .def_readonly("length", &LoiterSegment::length, "Length, m.")
      .def_property_readonly(
          "aoi", [](const LoiterSegment& s) -> std::optional<int> { return s.aoi < 0 ? std::nullopt : std::optional<int>(s.aoi); },
          "Index of the AOI this piece enters, circles or leaves; None for transit.")
      .def("at", [](const LoiterSegment& s, double d) {
             const Configuration q = s.at(d);
             return py::make_tuple(q.x, q.y, q.psi);
           }, py::arg("s"), "(x, y, psi) after arc length s along the segment.")
      .def("__repr__", [](const LoiterSegment& s) {
        Repr text("Segment");
        text.add("kind", s.kind).add("role", s.role).add("length", s.length);
        if (s.kind == SegmentKind::Arc) text.add("radius", s.radius).add("direction", s.direction).add("sweep", s.sweep);
        if (s.aoi >= 0) text.add("aoi", s.aoi);
        return text.str();
      });

  py::class_<LoiterSamples>(m, "Samples", "A plan sampled in time.")
      .def_property_readonly("t", [](const LoiterSamples& s) { return to_numpy(s.t); }, "Times, s.")
      .def_readonly("poses", &LoiterSamples::poses, "(n, 3): x, y, psi (continuous).")
      .def_property_readonly("turn_rate", [](const LoiterSamples& s) { return to_numpy(s.turn_rate); },
                             "Turn rate of the segment each sample lies on, rad/s.")
      .def_property_readonly("segment", [](const LoiterSamples& s) { return to_numpy(s.segment); },
                             "Index of that segment.");

  py::class_<LoiterPlan>(m, "Plan", "A loiter plan: the path as segments, its length and times.")
      .def_property_readonly("method", [](const LoiterPlan& p) { return to_string(p.method); },
                             "'fly_through', 'tlpp' or 'ldlpp'.")
      .def_readonly("order", &LoiterPlan::order, "Visiting order: indices into aois.")
      .def_property_readonly(
          "directions",
          [](const LoiterPlan& p) {
            std::vector<std::string> out;
            for (const Circulation d : p.directions) out.push_back(to_string(d));
            return out;
          },
          "Loiter direction of each AOI ('ccw' or 'cw'), indexed like aois.")
      .def_readonly("segments", &LoiterPlan::segments, "The path: list of Segment.")
      .def_property_readonly("segment_offsets", [](const LoiterPlan& p) { return to_numpy(p.segment_offsets); },
                             "Arc length at the start of each segment, m.")
      .def_readonly("length", &LoiterPlan::length, "Path length, m.")
      .def_readonly("flight_time", &LoiterPlan::flight_time, "length / speed, s.")
      .def_readonly("loiter_time", &LoiterPlan::loiter_time, "Time on the AOIs' loiter circles, s.")
      .def_readonly("transit_time", &LoiterPlan::transit_time, "Time off them, s (flight_time - loiter_time).")
      .def_property_readonly("loiter_sweep", [](const LoiterPlan& p) { return to_numpy(p.loiter_sweep); },
                             "Angle flown on each AOI's loiter circle, rad (indexed like aois).")
      .def_property_readonly("aois", [](const LoiterPlan& p) { return to_array(p.problem.aois); },
                             "(n, 2) AOI centres, m.")
      .def_property_readonly("start", [](const LoiterPlan& p) { return pair(p.problem.start); }, "(x, y), m.")
      .def_property_readonly("end", [](const LoiterPlan& p) { return pair(p.problem.end); }, "(x, y), m.")
      .def_property_readonly("turn_radius", [](const LoiterPlan& p) { return p.problem.parameters.turn_radius; }, "r, m.")
      .def_property_readonly("speed", [](const LoiterPlan& p) { return p.problem.parameters.speed; }, "v, m/s.")
      .def_property_readonly("aoi_radius", [](const LoiterPlan& p) { return p.problem.parameters.aoi_radius; }, "R, m.")
      .def_property_readonly("turns", [](const LoiterPlan& p) { return p.problem.parameters.turns; },
                             "Full loiters per AOI.")
      .def("at_time", [](const LoiterPlan& p, double t) {
             const Configuration q = p.at_time(t);
             return py::make_tuple(q.x, q.y, q.psi);
           }, py::arg("t"), "(x, y, psi) at time t in [0, flight_time].")
      .def("sample", &LoiterPlan::sample, py::arg("dt") = 1.0,
           "(n, 3) array of x, y, psi (continuous) at t = 0, dt, 2 dt, ... and the end point last.")
      .def("sample_states", &LoiterPlan::sample_states, py::arg("dt") = 1.0, py::arg("include_end") = true,
           "Samples (t, poses, turn_rate, segment) at t = 0, dt, ...; include_end appends the end point.")
      .def("__repr__", [](const LoiterPlan& p) {
        return Repr("loiter.Plan")
            .add("method", p.method)
            .add("aois", p.problem.aois.size())
            .add("length", p.length)
            .add("flight_time", p.flight_time)
            .add("transit_time", p.transit_time)
            .str();
      });

  py::class_<Footprint>(m, "Footprint", "A camera's ground footprint: an ellipse with axes along and across the heading.")
      .def_property_readonly("center", [](const Footprint& f) { return pair(f.center); }, "(x, y), m.")
      .def_property_readonly("along", [](const Footprint& f) { return pair(f.along); }, "Unit vector of the heading.")
      .def_readonly("semi_along", &Footprint::semi_along, "Semi-axis along the heading, m.")
      .def_readonly("semi_across", &Footprint::semi_across, "Semi-axis across it, m.")
      .def_property_readonly("area", &Footprint::area, "pi * semi_along * semi_across, m^2.")
      .def("disk_area", &footprint_disk_area, py::arg("center"), py::arg("radius"),
           "Exact area of the disk (center, radius) inside the footprint, m^2.");

  py::class_<LoiterCamera>(m, "Camera",
                           "Section 2.2's camera: circular field of view fov_deg, roll gimbal +-max_gimbal_deg, "
                           "altitude above the AOIs (61 m gives the paper's 6,638 m^2 nadir footprint).")
      .def(py::init([](double fov_deg, double max_gimbal_deg, double altitude, bool levelled) {
             LoiterCamera c{fov_deg, max_gimbal_deg, altitude, levelled};
             c.validate();
             return c;
           }),
           py::arg("fov_deg") = camera_defaults.fov_deg, py::arg("max_gimbal_deg") = camera_defaults.max_gimbal_deg,
           py::arg("altitude") = camera_defaults.altitude, py::arg("levelled") = camera_defaults.levelled,
           "fov_deg (full angle), max_gimbal_deg, altitude (m); levelled: the gimbal angle is measured from the "
           "vertical (the paper), else the gimbal sits under the banked body (its belly faces out of turns).")
      .def_readwrite("fov_deg", &LoiterCamera::fov_deg, "Full angle of the circular field of view, degrees.")
      .def_readwrite("max_gimbal_deg", &LoiterCamera::max_gimbal_deg, "Largest gimbal roll either side, degrees.")
      .def_readwrite("altitude", &LoiterCamera::altitude, "Height above the AOIs' ground, m.")
      .def_readwrite("levelled", &LoiterCamera::levelled,
                     "True: the gimbal angle is measured from the vertical (the paper's camera); False: the gimbal "
                     "rolls with the banked body, so the axis tilts by gimbal - bank.")
      .def("tilt", &camera_tilt, py::arg("bank"), py::arg("gimbal"),
           "The axis' tilt to the left of vertical, rad, for a bank and a gimbal angle (rad, positive left).")
      .def("validate", &LoiterCamera::validate, "Raise VistrackError naming the first invalid field.")
      .def("footprint", [](const LoiterCamera& c, const std::array<double, 3>& pose, double tilt) {
             c.validate();
             return camera_footprint(c, {pose[0], pose[1], pose[2]}, tilt);
           }, py::arg("pose"), py::arg("tilt") = 0.0,
           "Ground footprint (an ellipse) at pose (x, y, psi) with the axis tilted `tilt` rad to the left.")
      .def("__repr__", [](const LoiterCamera& c) {
        Repr text("loiter.Camera");
        text.add("fov_deg", c.fov_deg).add("max_gimbal_deg", c.max_gimbal_deg).add("altitude", c.altitude);
        if (!c.levelled) text.add("levelled", false);
        return text.str();
      });

  py::class_<LoiterCoverage>(m, "Coverage", "Camera coverage of the AOIs along a path (section 4.1).")
      .def_readonly("time", &LoiterCoverage::time, "Covered time summed over the AOIs, s.")
      .def_property_readonly("time_per_aoi", [](const LoiterCoverage& c) { return to_numpy(c.time_per_aoi); },
                             "Covered time of each AOI, s.")
      .def_readonly("area", &LoiterCoverage::area,
                    "The paper's 'AOI coverage (m^2)': the area of each covered AOI inside the footprint, summed "
                    "over time steps and AOIs, times dt (m^2 s; m^2 at the paper's 1 s).")
      .def_property_readonly("area_per_aoi", [](const LoiterCoverage& c) { return to_numpy(c.area_per_aoi); },
                             "That sum for each AOI.")
      .def_property_readonly(
          "fraction",
          [](const LoiterCoverage& c) {
            py::array_t<double> out({static_cast<py::ssize_t>(c.steps), static_cast<py::ssize_t>(c.aoi_count)});
            std::copy(c.fraction.begin(), c.fraction.end(), out.mutable_data());
            return out;
          },
          "(steps, AOIs): fraction of each AOI's disk in the footprint at each step.")
      .def_property_readonly("pointed", [](const LoiterCoverage& c) { return to_numpy(c.pointed); },
                             "Per step: the AOI the gimbal serves, -1 when none is in reach.")
      .def_property_readonly("gimbal", [](const LoiterCoverage& c) { return to_numpy(c.gimbal); },
                             "Per step: gimbal roll, rad, positive to the left.")
      .def_property_readonly("tilt", [](const LoiterCoverage& c) { return to_numpy(c.tilt); },
                             "Per step: the camera axis' tilt to the left of vertical, rad (Camera.tilt of bank and gimbal).")
      .def_property_readonly("bank", [](const LoiterCoverage& c) { return to_numpy(c.bank); },
                             "Per step: bank angle of the coordinated turn, rad, positive to the left.")
      .def_readonly("steps", &LoiterCoverage::steps, "Number of time steps.");

  m.def(
      "plan",
      [](const InputArray& aois, LoiterMethod method, const Vec2& start, const Vec2& end, double turn_radius,
         double speed, double aoi_radius, const AnyInteger& turns, LoiterOrder order) {
        const LoiterProblem problem = make_problem(aois, start, end, turn_radius, speed, aoi_radius, turns);
        py::gil_scoped_release release;
        return plan_loiter(problem, method, order);
      },
      py::arg("aois"), py::arg("method") = LoiterMethod::Ldlpp, py::arg("start") = Vec2(0.0, 0.0), py::arg("end") = Vec2(0.0, 0.0),
      py::arg("turn_radius") = defaults.turn_radius, py::arg("speed") = defaults.speed,
      py::arg("aoi_radius") = defaults.aoi_radius, py::arg("turns") = defaults.turns, py::arg("order") = LoiterOrder::Given,
      (std::string("Plan a loiter mission. ") + kProblemArgs +
       " method: 'fly_through', 'tlpp' or 'ldlpp'; order: 'given' or 'best' (shortest plan: exact up to 9 AOIs, "
       "2-opt/or-opt above).")
          .c_str());
  m.def(
      "plan_in_order",
      [](const InputArray& aois, const std::vector<int>& order, LoiterMethod method, const Vec2& start,
         const Vec2& end, double turn_radius, double speed, double aoi_radius, const AnyInteger& turns) {
        const LoiterProblem problem = make_problem(aois, start, end, turn_radius, speed, aoi_radius, turns);
        return plan_loiter_in_order(problem, method, order);
      },
      py::arg("aois"), py::arg("order"), py::arg("method") = LoiterMethod::Ldlpp, py::arg("start") = Vec2(0.0, 0.0),
      py::arg("end") = Vec2(0.0, 0.0), py::arg("turn_radius") = defaults.turn_radius,
      py::arg("speed") = defaults.speed, py::arg("aoi_radius") = defaults.aoi_radius,
      py::arg("turns") = defaults.turns, "Plan visiting the AOIs in this order (a permutation of 0..n-1).");
  m.def(
      "order_length",
      [](const InputArray& aois, const std::vector<int>& order, LoiterMethod method, const Vec2& start,
         const Vec2& end, double turn_radius, double speed, double aoi_radius, const AnyInteger& turns) {
        const LoiterProblem problem = make_problem(aois, start, end, turn_radius, speed, aoi_radius, turns);
        return loiter_order_length(problem, method, order);
      },
      py::arg("aois"), py::arg("order"), py::arg("method") = LoiterMethod::Ldlpp, py::arg("start") = Vec2(0.0, 0.0),
      py::arg("end") = Vec2(0.0, 0.0), py::arg("turn_radius") = defaults.turn_radius,
      py::arg("speed") = defaults.speed, py::arg("aoi_radius") = defaults.aoi_radius,
      py::arg("turns") = defaults.turns,
      "Path length of a visiting order (no validation of the order's geometry): inf when the method cannot fly it.");
  m.def(
      "best_order",
      [](const InputArray& aois, LoiterMethod method, bool exact, const Vec2& start, const Vec2& end,
         double turn_radius, double speed, double aoi_radius, const AnyInteger& turns) {
        const LoiterProblem problem = make_problem(aois, start, end, turn_radius, speed, aoi_radius, turns);
        py::gil_scoped_release release;
        return best_loiter_order(problem, method, exact);
      },
      py::arg("aois"), py::arg("method") = LoiterMethod::Ldlpp, py::arg("exact") = true, py::arg("start") = Vec2(0.0, 0.0),
      py::arg("end") = Vec2(0.0, 0.0), py::arg("turn_radius") = defaults.turn_radius,
      py::arg("speed") = defaults.speed, py::arg("aoi_radius") = defaults.aoi_radius,
      py::arg("turns") = defaults.turns,
      "The visiting order with the shortest plan: exact branch and bound (at most 12 AOIs) or the 2-opt heuristic.");

  m.def(
      "plan_coverage",
      [](const LoiterPlan& plan, const LoiterCamera& camera, double threshold, double dt) {
        const LoiterCoverageOptions options = make_options(threshold, dt);
        camera.validate();
        py::gil_scoped_release release;
        return loiter_coverage(plan, camera, options);
      },
      py::arg("plan"), py::arg("camera") = camera_defaults, py::arg("threshold") = coverage_defaults.threshold,
      py::arg("dt") = coverage_defaults.dt,
      "Coverage of a plan sampled every dt (t = 0, dt, ... up to the flight time), exact turn rates.");
  m.def(
      "sample_coverage",
      [](const Points3& poses, const std::vector<double>& turn_rates, const InputArray& aois, double aoi_radius,
         double speed, const LoiterCamera& camera, double threshold, double dt) {
        const std::vector<Vec2> centers = to_points(aois, "aois");
        const LoiterCoverageOptions options = make_options(threshold, dt);
        py::gil_scoped_release release;
        return loiter_coverage(poses, turn_rates, centers, aoi_radius, speed, camera, options);
      },
      py::arg("poses"), py::arg("turn_rates"), py::arg("aois"), py::arg("aoi_radius") = defaults.aoi_radius,
      py::arg("speed") = defaults.speed, py::arg("camera") = camera_defaults,
      py::arg("threshold") = coverage_defaults.threshold, py::arg("dt") = coverage_defaults.dt,
      "Coverage of poses (n, 3) sampled every dt with their turn rates (rad/s, for the bank angle).");
  m.def("bank_angle", &bank_angle, py::arg("speed"), py::arg("turn_rate"), py::arg("gravity") = kStandardGravity,
        "Bank of a coordinated turn, atan(v psi_dot / g), rad, positive to the left.");
  m.def("ellipse_disk_area", &ellipse_disk_intersection_area, py::arg("a"), py::arg("b"), py::arg("cx"),
        py::arg("cy"), py::arg("rho"),
        "Exact area of the ellipse x^2/a^2 + y^2/b^2 <= 1 intersected with the disk of radius rho at (cx, cy).");
  m.def("entry_angle", &ldlpp_entry_angle, py::arg("aoi_radius"), py::arg("turn_radius"),
        "LDLPP's alpha_ED = asin(r / (R + r)) (14), rad.");
  m.def("entry_distance", &ldlpp_entry_distance, py::arg("aoi_radius"), py::arg("turn_radius"),
        "LDLPP's D_Entry = (R + r) cos(alpha_ED) (15), m.");
  m.def("turn_angle", &ldlpp_turn_angle, py::arg("aoi_radius"), py::arg("turn_radius"),
        "Heading change of LDLPP's entry and exit turns, pi/2 - alpha_ED, rad.");
}

}  // namespace vistrack::bindings
