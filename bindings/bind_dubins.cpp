// vistrack._core.dubins: Dubins paths, batch lengths, path to a circle, target intercept.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <array>
#include <map>
#include <string>

#include "bindings.hpp"
#include "vistrack/dubins.hpp"
#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"

namespace py = pybind11;

// (x, y, psi) from any sequence of three numbers (tuple, list, numpy row), to a tuple: a
// direct conversion keeps the per-path call cheap.
namespace pybind11::detail {
template <>
struct type_caster<vistrack::Configuration> {
  PYBIND11_TYPE_CASTER(vistrack::Configuration, const_name("tuple[float, float, float]"));

  bool load(handle source, bool) {
    if (!source || PyUnicode_Check(source.ptr()) || PyBytes_Check(source.ptr())) return false;
    PyObject* sequence = PySequence_Fast(source.ptr(), "");
    if (!sequence) {
      PyErr_Clear();
      return false;
    }
    bool ok = PySequence_Fast_GET_SIZE(sequence) == 3;
    double values[3] = {0.0, 0.0, 0.0};
    PyObject** items = PySequence_Fast_ITEMS(sequence);
    for (int k = 0; ok && k < 3; ++k) {
      values[k] = PyFloat_AsDouble(items[k]);
      if (values[k] == -1.0 && PyErr_Occurred()) {
        PyErr_Clear();
        ok = false;
      }
    }
    Py_DECREF(sequence);
    if (ok) value = {values[0], values[1], values[2]};
    return ok;
  }

  static handle cast(const vistrack::Configuration& q, return_value_policy, handle) {
    return make_tuple(q.x, q.y, q.psi).release();
  }
};
}  // namespace pybind11::detail

namespace vistrack::bindings {
namespace {

using Triple = Configuration;

const Configuration& to_configuration(const Configuration& q) { return q; }
py::tuple to_tuple(const Configuration& q) { return py::make_tuple(q.x, q.y, q.psi); }

const char* segment_letter(DubinsSegment s) {
  return s == DubinsSegment::Left ? "L" : (s == DubinsSegment::Right ? "R" : "S");
}

// (n, 3) float64 array, C order; the message names `field`.
InputArray require_rows3(const InputArray& a, const char* field) {
  if (a.ndim() != 2 || a.shape(1) != 3)
    throw Error(std::string(field) + ": expected an array of shape (n, 3), got ndim = " + std::to_string(a.ndim()) +
                (a.ndim() >= 2 ? ", shape[1] = " + std::to_string(a.shape(1)) : std::string()));
  return a;
}

TargetCircle make_circle(const Vec2& center, double radius, Circulation direction) {
  TargetCircle circle;
  circle.center = center;
  circle.radius = radius;
  circle.direction = direction;
  circle.validate();
  return circle;
}

InterceptProblem make_problem(const Triple& pursuer, double rho, double pursuer_speed, const Vec2& center,
                              double radius, double target_angle0, double target_speed,
                              Circulation direction, double angle_tolerance, int scan_samples) {
  InterceptProblem p;
  p.pursuer = to_configuration(pursuer);
  p.rho = rho;
  p.pursuer_speed = pursuer_speed;
  p.circle = make_circle(center, radius, direction);
  p.target_angle0 = target_angle0;
  p.target_speed = target_speed;
  p.angle_tolerance = angle_tolerance;
  p.scan_samples = scan_samples;
  p.validate();
  return p;
}

}  // namespace

void bind_dubins(py::module_& parent) {
  py::module_ m = parent.def_submodule(
      "dubins",
      "Dubins paths (shortest of LSL, LSR, RSL, RSR, RLR, LRL), batch lengths, shortest path to a point "
      "on a circle and the optimal intercept of a target moving on a circle (Manyam et al., Algorithm 1). "
      "Configurations are (x, y, psi), psi in rad counter-clockwise from +x; rho is the minimum turn "
      "radius. Snapping tolerance: eps = 1e-11 * (1 + max|coordinate| / rho) (see dubins.hpp).");

  m.attr("WORDS") = enum_names<DubinsWord>();
  m.attr("SNAP") = kDubinsSnap;

  py::class_<DubinsPath>(m, "DubinsPath", "One Dubins path: start, goal, turn radius, word and segment lengths.")
      .def_property_readonly("start", [](const DubinsPath& p) { return to_tuple(p.start); }, "(x, y, psi) at s = 0.")
      .def_property_readonly("goal", [](const DubinsPath& p) { return to_tuple(p.goal); }, "(x, y, psi) at s = length.")
      .def_readonly("rho", &DubinsPath::rho, "Minimum turn radius (m).")
      .def_property_readonly("word", [](const DubinsPath& p) { return to_string(p.word); }, "'LSL', 'LSR', ...")
      .def_property_readonly(
          "segment_types",
          [](const DubinsPath& p) {
            const auto t = p.segment_types();
            return py::make_tuple(segment_letter(t[0]), segment_letter(t[1]), segment_letter(t[2]));
          },
          "('L'|'S'|'R',) * 3: left arc, straight, right arc.")
      .def_property_readonly(
          "segment_lengths",
          [](const DubinsPath& p) { return py::make_tuple(p.segment_lengths[0], p.segment_lengths[1], p.segment_lengths[2]); },
          "Arc lengths of the three segments (m).")
      .def_readonly("length", &DubinsPath::length, "Total length (m), the sum of segment_lengths.")
      .def("at", [](const DubinsPath& p, double s) { return to_tuple(p.at(s)); }, py::arg("s"),
           "(x, y, psi) after arc length s in [0, length]; the goal exactly at s = length. Headings continue "
           "from start.psi (not wrapped).")
      .def("sample", &DubinsPath::sample, py::arg("step"),
           "Array (n, 3) of (x, y, psi) at s = 0, step, 2 step, ... and the goal exactly as the last row.")
      .def("sample_at", &DubinsPath::sample_at, py::arg("arc_lengths"),
           "Array (n, 3) of (x, y, psi) at the given arc lengths (each in [0, length]).")
      .def("__repr__", [](const DubinsPath& p) {
        return Repr("DubinsPath")
            .add("word", p.word)
            .add("length", p.length)
            .add("segment_lengths", Vec3(p.segment_lengths[0], p.segment_lengths[1], p.segment_lengths[2]))
            .str();
      });

  m.def(
      "shortest_path",
      [](const Triple& q0, const Triple& q1, double rho) {
        return dubins_shortest_path(to_configuration(q0), to_configuration(q1), rho);
      },
      py::arg("q0"), py::arg("q1"), py::arg("rho"), "Shortest of the six Dubins words from q0 to q1.");
  m.def(
      "shortest_length",
      [](const Triple& q0, const Triple& q1, double rho) {
        const Configuration a = to_configuration(q0), b = to_configuration(q1);
        validate_dubins_problem(a, b, rho);
        return dubins_shortest_length(a, b, rho);
      },
      py::arg("q0"), py::arg("q1"), py::arg("rho"),
      "Length of the shortest Dubins path (no path object; the batch kernel for one pair).");
  m.def(
      "path",
      [](const Triple& q0, const Triple& q1, double rho, DubinsWord word) {
        return dubins_path(to_configuration(q0), to_configuration(q1), rho, word);
      },
      py::arg("q0"), py::arg("q1"), py::arg("rho"), py::arg("word"),
      "The path of one given word ('LSL', ...); VistrackError when that word has no path.");
  m.def(
      "word_lengths",
      [](const Triple& q0, const Triple& q1, double rho) {
        const auto l = dubins_word_lengths(to_configuration(q0), to_configuration(q1), rho);
        std::map<std::string, double> lengths;
        for (int k = 0; k < kDubinsWordCount; ++k) lengths[to_string(static_cast<DubinsWord>(k))] = l[static_cast<std::size_t>(k)];
        return lengths;
      },
      py::arg("q0"), py::arg("q1"), py::arg("rho"), "Length of every word (inf where it does not exist), keyed by word.");
  m.def(
      "shortest_lengths",
      [](const InputArray& q0s_in, const InputArray& q1s_in, double rho, int threads) {
        const InputArray q0s = require_rows3(q0s_in, "q0s");
        const InputArray q1s = require_rows3(q1s_in, "q1s");
        if (q0s.shape(0) != q1s.shape(0))
          detail::fail_field("q1s.shape[0]", q1s.shape(0), "must equal q0s.shape[0] = " + std::to_string(q0s.shape(0)));
        const auto n = static_cast<std::size_t>(q0s.shape(0));
        py::array_t<double> lengths(static_cast<py::ssize_t>(n));
        py::array_t<std::uint8_t> codes(static_cast<py::ssize_t>(n));
        const double* a = q0s.data();
        const double* b = q1s.data();
        double* out = lengths.mutable_data();
        std::uint8_t* w = codes.mutable_data();
        {
          py::gil_scoped_release release;
          dubins_shortest_lengths(a, b, n, rho, out, w, threads);
        }
        return py::make_tuple(lengths, codes);
      },
      py::arg("q0s"), py::arg("q1s"), py::arg("rho"), py::arg("threads") = 0,
      "Batch: arrays (n, 3) of start and goal configurations -> (lengths (n,), words (n,) uint8 indexing "
      "WORDS). Multi-threaded (TBB; threads=0 uses all cores, else at most `threads`), releases the GIL.");

  m.def(
      "path_to_circle",
      [](const Triple& q0, double rho, const Vec2& center, double radius, double angle, Circulation direction) {
        return dubins_path_to_circle(to_configuration(q0), rho, make_circle(center, radius, direction), angle);
      },
      py::arg("q0"), py::arg("rho"), py::arg("center"), py::arg("radius"), py::arg("angle"), py::arg("direction") = TargetCircle{}.direction,
      "Shortest Dubins path from q0 to the point at `angle` (rad, about the centre) on the circle, arriving "
      "tangent to it in the travel direction ('cw': heading angle - pi/2, 'ccw': angle + pi/2).");
  m.def(
      "length_to_circle",
      [](const Triple& q0, double rho, const Vec2& center, double radius, const std::vector<double>& angles,
         Circulation direction, bool csc_only) {
        const TargetCircle circle = make_circle(center, radius, direction);
        const Configuration start = to_configuration(q0);
        for (std::size_t k = 0; k < angles.size(); ++k) require_angle(angles[k], "angles[" + std::to_string(k) + "]");
        std::vector<double> out(angles.size());
        {
          py::gil_scoped_release release;
          for (std::size_t k = 0; k < angles.size(); ++k)
            out[k] = csc_only ? dubins_csc_length_to_circle(start, rho, circle, angles[k])
                              : dubins_length_to_circle(start, rho, circle, angles[k]);
        }
        return py::array_t<double>(static_cast<py::ssize_t>(out.size()), out.data());
      },
      py::arg("q0"), py::arg("rho"), py::arg("center"), py::arg("radius"), py::arg("angles"), py::arg("direction") = TargetCircle{}.direction,
      py::arg("csc_only") = false,
      "D(alpha) for each angle: the length of the shortest path to the circle point (all six words), or with "
      "csc_only=True the paper's D_CSC(alpha) (min of LSL, LSR, RSL, RSR). Both agree and are continuous "
      "when the 4 rho condition holds; period exactly 2 pi.");
  m.def(
      "four_rho_condition",
      [](const Vec2& p, double rho, const Vec2& center, double radius) {
        require_length(rho, "rho");
        require_coordinate(p.x(), "p[0]");
        require_coordinate(p.y(), "p[1]");
        return four_rho_condition(p, rho, make_circle(center, radius, Circulation::Clockwise));
      },
      py::arg("p"), py::arg("rho"), py::arg("center"), py::arg("radius"),
      "Whether every point of the circle is farther than 4 rho from p (the paper's assumption).");

  py::class_<InterceptResult>(m, "InterceptResult", "Optimal interception of a target moving on a circle.")
      .def_readonly("angle", &InterceptResult::angle, "alpha*: interception angular position (rad, unwrapped).")
      .def_readonly("swept_angle", &InterceptResult::swept_angle, "Angle the target travels before interception (rad).")
      .def_readonly("time", &InterceptResult::time, "Interception time (s), equal for pursuer and target.")
      .def_readonly("residual", &InterceptResult::residual, "T_p - T_t at the returned angle (s), <= 0 and tiny.")
      .def_readonly("path", &InterceptResult::path, "The pursuer's Dubins path to the interception point.")
      .def_readonly("four_rho_condition", &InterceptResult::four_rho_condition,
                    "True: optimal (Proposition 1). False: feasible, optimality not guaranteed.")
      .def_readonly("period", &InterceptResult::period, "Period of D(alpha) used to step the brackets (2 pi).")
      .def_readonly("alpha_min", &InterceptResult::alpha_min, "argmin of D(alpha) over [0, 2 pi).")
      .def_readonly("bracket_windows", &InterceptResult::bracket_windows, "Periods skipped by Algorithm 1's bracket.")
      .def_readonly("bisection_steps", &InterceptResult::bisection_steps, "Bisection iterations.")
      .def_property_readonly("optimal", [](const InterceptResult& r) { return r.four_rho_condition; },
                             "Alias of four_rho_condition: whether optimality is guaranteed.");

  m.def(
      "intercept_circle",
      [](const Triple& pursuer, double rho, double pursuer_speed, const Vec2& center, double radius,
         double target_angle0, double target_speed, Circulation direction, double angle_tolerance,
         int scan_samples) {
        const InterceptProblem p = make_problem(pursuer, rho, pursuer_speed, center, radius, target_angle0,
                                                target_speed, direction, angle_tolerance, scan_samples);
        py::gil_scoped_release release;
        return intercept_circle(p);
      },
      py::arg("pursuer"), py::arg("rho"), py::arg("pursuer_speed"), py::arg("center"), py::arg("radius"),
      py::arg("target_angle0"), py::arg("target_speed"), py::arg("direction") = TargetCircle{}.direction,
      py::arg("angle_tolerance") = 1e-12, py::arg("scan_samples") = 2048,
      "Earliest interception of a target starting at angle target_angle0 on the circle and moving at "
      "target_speed in `direction`, by a Dubins pursuer (Algorithm 1: brackets one period of D(alpha) "
      "apart, first sign change, bisection to angle_tolerance rad).");
  m.def(
      "intercept_travel_times",
      [](const Triple& pursuer, double rho, double pursuer_speed, const Vec2& center, double radius,
         double target_angle0, double target_speed, Circulation direction, const std::vector<double>& swept) {
        const InterceptProblem p =
            make_problem(pursuer, rho, pursuer_speed, center, radius, target_angle0, target_speed, direction, 1e-12, 2048);
        InterceptTimes t;
        {
          py::gil_scoped_release release;
          t = intercept_travel_times(p, swept);
        }
        const auto arr = [](const std::vector<double>& v) {
          return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
        };
        return py::make_tuple(arr(t.angles), arr(t.pursuer), arr(t.target));
      },
      py::arg("pursuer"), py::arg("rho"), py::arg("pursuer_speed"), py::arg("center"), py::arg("radius"),
      py::arg("target_angle0"), py::arg("target_speed"), py::arg("direction"), py::arg("swept_angles"),
      "Figure 7a data: for swept target angles, (alpha, T_p(alpha) = D(alpha)/v_p, T_t(alpha)).");
}

}  // namespace vistrack::bindings
