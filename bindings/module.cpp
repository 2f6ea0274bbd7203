// The single extension module vistrack._core; each area binds itself in bind_<area>.cpp.
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "vistrack/error.hpp"

PYBIND11_MODULE(_core, m) {
  m.doc() = "vistrack C++ core: environment, Dubins, visibility, orbits, guidance, simulation, flight, waypoint navigation.";
  m.attr("__version__") = VISTRACK_VERSION;
  // One error type, a ValueError, for every invalid input (DESIGN.md, Conventions).
  pybind11::register_exception<vistrack::Error>(m, "VistrackError", PyExc_ValueError);

  vistrack::bindings::bind_geometry(m);
  vistrack::bindings::bind_parameters(m);
  vistrack::bindings::bind_environment(m);
  vistrack::bindings::bind_dubins(m);
  vistrack::bindings::bind_visibility(m);
  vistrack::bindings::bind_volume(m);
  vistrack::bindings::bind_xor(m);
  vistrack::bindings::bind_orbit(m);
  vistrack::bindings::bind_guidance(m);
  vistrack::bindings::bind_ode(m);
  vistrack::bindings::bind_simulate(m);
  vistrack::bindings::bind_flight(m);
  vistrack::bindings::bind_waypoint_nav(m);
  vistrack::bindings::bind_path_following(m);
  vistrack::bindings::bind_loiter(m);
  vistrack::bindings::bind_follow(m);
}
