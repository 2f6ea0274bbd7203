#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "vistrack/guidance.hpp"
#include "vistrack/limits.hpp"

namespace py = pybind11;

namespace vistrack::bindings {

namespace {

// The guidance functions trust their arguments (they run inside the integrator): check here.
const OrbitState& checked(const OrbitState& orbit) {
  orbit.validate();
  return orbit;
}
const GuidanceGains& checked(const GuidanceGains& gains) {
  gains.validate();
  return gains;
}
Vec2 checked_xy(const Vec2& xy, const std::string& field) {
  require_coordinate(xy.x(), field + "[0]");
  require_coordinate(xy.y(), field + "[1]");
  return xy;
}
double checked_angle(double angle, const std::string& field) {
  require_angle(angle, field);
  return angle;
}

}  // namespace

void bind_guidance(py::module_& m) {
  py::class_<OrbitState>(m, "OrbitState",
                         "The reference orbit at one instant (Definitions 1-2): centre g, its velocity "
                         "g_dot, radius R and dR/dt.")
      .def(py::init([](const Vec2& center, const Vec2& center_velocity, double radius, double radius_rate,
                       double radius_acceleration) {
             return make_validated(OrbitState{center, center_velocity, radius, radius_rate, radius_acceleration});
           }),
           py::kw_only(), py::arg("center") = Vec2(0.0, 0.0), py::arg("center_velocity") = Vec2(0.0, 0.0),
           py::arg("radius") = 1.0, py::arg("radius_rate") = 0.0, py::arg("radius_acceleration") = 0.0,
           "center g (m), center_velocity g_dot (m/s), radius R (m), radius_rate dR/dt (m/s), "
           "radius_acceleration d2R/dt2 (m/s^2; 0 on the paper's piecewise-linear locus).")
      .def_readwrite("center", &OrbitState::center, "g, (2,)")
      .def_readwrite("center_velocity", &OrbitState::center_velocity, "g_dot, (2,)")
      .def_readwrite("radius", &OrbitState::radius, "R, m")
      .def_readwrite("radius_rate", &OrbitState::radius_rate, "dR/dt, m/s")
      .def_readwrite("radius_acceleration", &OrbitState::radius_acceleration, "d2R/dt2, m/s^2")
      .def("validate", &OrbitState::validate, "Raise VistrackError naming the first field out of range.");

  const GuidanceGains defaults;
  py::class_<GuidanceGains>(m, "GuidanceGains",
                            "Gains of the vector field and steering law: speed v, beta, k_psi, direction "
                            "('ccw' or 'cw'), max_turn_rate = v / r_min.")
      .def(py::init([](double speed, double beta, double k_psi, Circulation direction, double max_turn_rate) {
             return make_validated(GuidanceGains{speed, beta, k_psi, direction, max_turn_rate});
           }),
           py::kw_only(), py::arg("speed") = defaults.speed, py::arg("beta") = defaults.beta,
           py::arg("k_psi") = defaults.k_psi, py::arg("direction") = defaults.direction,
           py::arg("max_turn_rate") = defaults.max_turn_rate, "Validated gains.")
      .def_static("from_parameters", &GuidanceGains::from, py::arg("uav"), py::arg("control"),
                  "Gains from a Uav and a Control (max_turn_rate = speed / min_turn_radius).")
      .def_readwrite("speed", &GuidanceGains::speed, "v, m/s")
      .def_readwrite("beta", &GuidanceGains::beta, "beta of a_1 (59)")
      .def_readwrite("k_psi", &GuidanceGains::k_psi, "heading gain of (86)")
      .def_readwrite("direction", &GuidanceGains::direction, "'ccw' or 'cw'")
      .def_readwrite("max_turn_rate", &GuidanceGains::max_turn_rate, "u_psi,max = v / r_min, rad/s");

  py::class_<VectorField>(m, "VectorField", "The guidance vector field (74) at one point.")
      .def_readonly("r", &VectorField::r, "distance to the POI, m")
      .def_readonly("theta", &VectorField::theta, "polar angle about the POI, rad")
      .def_readonly("e_r", &VectorField::e_r, "radial unit vector")
      .def_readonly("e_theta", &VectorField::e_theta, "tangential unit vector")
      .def_readonly("radial_error", &VectorField::radial_error, "r - R, m")
      .def_readonly("attraction", &VectorField::attraction, "Phi' (70), m/s")
      .def_readonly("u_r", &VectorField::u_r, "radial component of u, m/s")
      .def_readonly("u_theta", &VectorField::u_theta, "circulation component of u, m/s")
      .def_readonly("u", &VectorField::u, "u in x, y (75), |u| = v")
      .def_readonly("heading", &VectorField::heading, "desired heading psi_d (77), rad")
      .def_readonly("attraction_rate", &VectorField::attraction_rate, "dPhi'/dt along the field (83)")
      .def_readonly("polar_rate", &VectorField::polar_rate, "theta_dot along the field (84)")
      .def_readonly("heading_rate", &VectorField::heading_rate, "dpsi_d/dt along the field (85), rad/s");

  py::class_<Steering>(m, "Steering", "The steering law (86) at one configuration.")
      .def_readonly("field", &Steering::field, "the vector field at the UAV")
      .def_readonly("heading_error", &Steering::heading_error, "psi - psi_d wrapped to (-pi, pi]")
      .def_readonly("proportional", &Steering::proportional, "k_psi (psi_d - psi)")
      .def_readonly("feed_forward", &Steering::feed_forward, "dpsi_d/dt (85)")
      .def_readonly("lyapunov", &Steering::lyapunov, "u_lyap, the last term of (86)")
      .def_readonly("unsaturated", &Steering::unsaturated, "sum of the three terms, rad/s")
      .def_readonly("command", &Steering::command, "u_psi clamped to +-max_turn_rate, rad/s")
      .def_readonly("saturated", &Steering::saturated, "whether the clamp was active");

  m.def(
      "vector_field",
      [](const Vec2& xi, const OrbitState& orbit, const GuidanceGains& gains, double heading_hint) {
        return vector_field(checked_xy(xi, "xi"), checked(orbit), checked(gains),
                            checked_angle(heading_hint, "heading_hint"));
      },
      py::arg("xi"), py::arg("orbit"), py::arg("gains"), py::arg("heading_hint") = 0.0,
        "The constant-speed guidance vector field (74) at position xi (2,): desired heading (77) "
        "and its rate along the field (85). heading_hint orients the frame at the exact centre.");
  m.def(
      "steering",
      [](const Vec3& q, const OrbitState& orbit, const GuidanceGains& gains) {
        checked_xy(q.head<2>(), "q");
        checked_angle(q.z(), "q[2]");
        return steering(q, checked(orbit), checked(gains));
      },
      py::arg("q"), py::arg("orbit"), py::arg("gains"),
        "The steering law (86) at configuration q = (x, y, psi), clamped to +-max_turn_rate (2).");
  m.def(
      "sample_vector_field",
      [](const Points2& points, const OrbitState& orbit, const GuidanceGains& gains) {
        gains.validate();
        orbit.validate();
        const Eigen::Index n = points.rows();
        for (Eigen::Index i = 0; i < n; ++i) checked_xy(points.row(i).transpose(), "points[" + std::to_string(i) + "]");
        Points2 u(n, 2);
        Eigen::VectorXd heading(n), rate(n);
        {
          py::gil_scoped_release release;
          for (Eigen::Index i = 0; i < n; ++i) {
            const VectorField f = vector_field(points.row(i).transpose(), orbit, gains);
            u.row(i) = f.u.transpose();
            heading[i] = f.heading;
            rate[i] = f.heading_rate;
          }
        }
        return py::make_tuple(u, heading, rate);
      },
      py::arg("points"), py::arg("orbit"), py::arg("gains"),
      "The field at many points (n, 2): returns (u (n, 2), psi_d (n,), dpsi_d/dt (n,)).");
  m.def(
      "lyapunov_term",
      [](const VectorField& field, const OrbitState& orbit, double beta, double heading_error) {
        require_beta(beta, "beta");
        return lyapunov_term(field, checked(orbit), beta, checked_angle(heading_error, "heading_error"));
      },
      py::arg("field"), py::arg("orbit"), py::arg("beta"), py::arg("heading_error"), "u_lyap of (86) for the field at the UAV and heading error psi - psi_d.");
  m.def(
      "radial_error_rate",
      [](const VectorField& field, const OrbitState& orbit, double heading_error) {
        return radial_error_rate(field, checked(orbit), checked_angle(heading_error, "heading_error"));
      },
      py::arg("field"), py::arg("orbit"), py::arg("heading_error"),
        "d(r - R)/dt of (93) for the Dubins vehicle with the given heading error.");
  m.def("one_minus_cos_over_x", [](double x) { return one_minus_cos_over_x(checked_angle(x, "x")); }, py::arg("x"), "(1 - cos x) / x, 0 at x = 0, accurate near 0.");
  m.def("sinc", [](double x) { return sinc(checked_angle(x, "x")); }, py::arg("x"), "sin(x) / x, 1 at x = 0, accurate near 0.");
  m.def(
      "orbit_polar_rate",
      [](double theta, const OrbitState& orbit, double speed, Circulation direction) {
        require_speed(speed, "speed");
        return orbit_polar_rate(checked_angle(theta, "theta"), checked(orbit), speed, direction);
      },
      py::arg("theta"), py::arg("orbit"), py::arg("speed"),
        py::arg("direction") = Circulation::CounterClockwise, "theta_dot of (13) for a vehicle remaining on the orbit.");
  m.def(
      "orbit_signed_curvature",
      [](double theta, const OrbitState& orbit, double speed, Circulation direction) {
        require_speed(speed, "speed");
        return orbit_signed_curvature(checked_angle(theta, "theta"), checked(orbit), speed, direction);
      },
      py::arg("theta"), py::arg("orbit"), py::arg("speed"),
        py::arg("direction") = Circulation::CounterClockwise,
        "Signed path curvature (31) of a vehicle remaining on the orbit at polar angle theta "
        "(Theorem 1: steering with v * this keeps it there).");
  m.def(
      "orbit_configuration",
      [](double theta0, const OrbitState& orbit, double speed, Circulation direction) {
        require_speed(speed, "speed");
        return orbit_configuration(checked_angle(theta0, "theta0"), checked(orbit), speed, direction);
      },
      py::arg("theta0"), py::arg("orbit"), py::arg("speed"),
        py::arg("direction") = Circulation::CounterClockwise, "Initial configuration (x, y, psi) on the orbit, (38)-(40).");
  m.def("lemma6_curvature_bound", &lemma6_curvature_bound, py::arg("radius"), py::arg("speed"),
        py::arg("poi_speed"), "(v_g + v)^2 / (R v^2), the maximum curvature on an orbit (Lemma 6).");
  m.def("lemma7_min_gain", &lemma7_min_gain, py::arg("speed"), py::arg("beta"),
        "The lower bound (87) on k_psi: v beta 4 / pi^2 eps_max.");
  m.def("epsilon_max", &epsilon_max, "Maximum of atan^2(x) / (1 + x^2), about 0.31483 (98).");
  m.def("lambda_max", &lambda_max, "Maximum of atan(x) / (1 + x^2), about 0.41195 (106).");
}

}  // namespace vistrack::bindings
