#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <limits>

#include "bindings.hpp"
#include "vistrack/ode.hpp"

namespace py = pybind11;

namespace vistrack::bindings {

namespace {

using VectorX = OdeVector<Eigen::Dynamic>;

struct PyOdeResult {
  Eigen::VectorXd t;
  Eigen::MatrixXd y;  // (n, dim)
  std::vector<std::size_t> event_index;
  Eigen::VectorXd event_t;
  Eigen::MatrixXd event_y;
  bool terminated = false;
  OdeStatistics statistics;
};

}  // namespace

void bind_ode(py::module_& m) {
  py::class_<OdeStatistics>(m, "OdeStatistics", "Work done by the integrator.")
      .def_readonly("rhs_evaluations", &OdeStatistics::rhs_evaluations, "right-hand side evaluations")
      .def_readonly("accepted_steps", &OdeStatistics::accepted_steps, "accepted steps")
      .def_readonly("rejected_steps", &OdeStatistics::rejected_steps, "rejected trial steps")
      .def("__repr__", [](const OdeStatistics& s) {
        return Repr("OdeStatistics")
            .add("rhs_evaluations", s.rhs_evaluations)
            .add("accepted_steps", s.accepted_steps)
            .add("rejected_steps", s.rejected_steps)
            .str();
      });

  py::class_<PyOdeResult>(m, "OdeResult", "Solution of solve_ode.")
      .def_readonly("t", &PyOdeResult::t, "output times (n,)")
      .def_readonly("y", &PyOdeResult::y, "states (n, dim)")
      .def_readonly("event_index", &PyOdeResult::event_index, "which event each crossing belongs to")
      .def_readonly("event_t", &PyOdeResult::event_t, "crossing times, in time order")
      .def_readonly("event_y", &PyOdeResult::event_y, "states at the crossings (k, dim)")
      .def_readonly("terminated", &PyOdeResult::terminated, "stopped by a terminal event")
      .def_readonly("statistics", &PyOdeResult::statistics, "work done");

  m.def(
      "solve_ode",
      [](const std::function<Eigen::VectorXd(double, const Eigen::VectorXd&)>& fun, std::pair<double, double> t_span,
         const Eigen::VectorXd& y0, double rtol, double atol, double max_step, double first_step, double fixed_step,
         const std::vector<double>& t_eval, const std::vector<py::object>& events) {
        OdeOptions options;
        options.rtol = rtol;
        options.atol = atol;
        options.max_step = max_step;
        options.first_step = first_step;
        options.fixed_step = fixed_step;
        const Eigen::Index dim = y0.size();
        auto rhs = [&](double t, const VectorX& y, VectorX& dy) {
          dy = fun(t, y);
          if (dy.size() != dim)
            detail::fail_field("fun(t, y).size", dy.size(), "must equal len(y0) = " + std::to_string(dim));
        };
        std::vector<OdeEvent<Eigen::Dynamic>> ode_events;
        for (const py::object& event : events) {
          OdeEvent<Eigen::Dynamic> e;
          auto f = event;
          e.value = [f](double t, const VectorX& y) { return f(t, y).cast<double>(); };
          if (py::hasattr(event, "direction")) e.direction = static_cast<int>(event.attr("direction").cast<double>());
          if (py::hasattr(event, "terminal")) {
            const py::object terminal = event.attr("terminal");
            e.terminal = py::isinstance<py::bool_>(terminal) ? (terminal.cast<bool>() ? 1 : 0) : terminal.cast<int>();
          }
          ode_events.push_back(std::move(e));
        }
        const OdeResult<Eigen::Dynamic> r =
            solve_ode<Eigen::Dynamic>(rhs, t_span.first, t_span.second, y0, options, t_eval, ode_events);
        PyOdeResult out;
        out.t = Eigen::Map<const Eigen::VectorXd>(r.t.data(), static_cast<Eigen::Index>(r.t.size()));
        out.y.resize(static_cast<Eigen::Index>(r.y.size()), dim);
        for (std::size_t k = 0; k < r.y.size(); ++k) out.y.row(static_cast<Eigen::Index>(k)) = r.y[k].transpose();
        out.event_t.resize(static_cast<Eigen::Index>(r.events.size()));
        out.event_y.resize(static_cast<Eigen::Index>(r.events.size()), dim);
        for (std::size_t k = 0; k < r.events.size(); ++k) {
          out.event_index.push_back(r.events[k].event);
          out.event_t[static_cast<Eigen::Index>(k)] = r.events[k].t;
          out.event_y.row(static_cast<Eigen::Index>(k)) = r.events[k].y.transpose();
        }
        out.terminated = r.terminated;
        out.statistics = r.statistics;
        return out;
      },
      py::arg("fun"), py::arg("t_span"), py::arg("y0"), py::kw_only(), py::arg("rtol") = 1e-6,
      py::arg("atol") = 1e-8, py::arg("max_step") = std::numeric_limits<double>::infinity(),
      py::arg("first_step") = 0.0, py::arg("fixed_step") = 0.0, py::arg("t_eval") = std::vector<double>{},
      py::arg("events") = std::vector<py::object>{},
      "Dormand-Prince 5(4) for dy/dt = fun(t, y) over t_span = (t0, t1), like "
      "scipy.integrate.solve_ivp(method='RK45'): adaptive steps (rtol, atol, max_step, first_step; "
      "0 = automatic), or fixed_step > 0 for fixed steps. Output at t_eval (dense output) or at every "
      "step. events: callables event(t, y) with optional attributes direction (+1, -1, 0) and "
      "terminal (bool or count), located on the dense output.");
}

}  // namespace vistrack::bindings
