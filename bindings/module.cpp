// The single extension module vistrack._core; each area binds itself in bind_<area>.cpp.
#include <pybind11/pybind11.h>

#include <cstring>

#include "bindings.hpp"
#include "vistrack/error.hpp"

namespace {

PyObject* vistrack_error_type = nullptr;  // vistrack.VistrackError, alive as long as the module

// The message as Python text whatever bytes it holds: a message quoting a file's bytes that are
// not UTF-8 must not turn into a UnicodeDecodeError (PyErr_SetString decodes strictly).
void set_error(PyObject* type, const char* what) {
  PyObject* message = PyUnicode_DecodeUTF8(what, static_cast<Py_ssize_t>(std::strlen(what)), "backslashreplace");
  if (!message) {
    PyErr_Clear();
    message = PyUnicode_FromString("(message not decodable)");
  }
  PyErr_SetObject(type, message);
  Py_XDECREF(message);
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "vistrack C++ core: environment, Dubins, visibility, orbits, guidance, simulation, flight, waypoint navigation.";
  m.attr("__version__") = VISTRACK_VERSION;
  // One error type, a ValueError, for every invalid input (DESIGN.md, Conventions).
  vistrack_error_type = pybind11::register_exception<vistrack::Error>(m, "VistrackError", PyExc_ValueError).ptr();
  // Tried before the translator register_exception installed (later ones are tried first).
  pybind11::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const vistrack::Error& e) {
      set_error(vistrack_error_type, e.what());
    }
  });

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
  vistrack::bindings::bind_follow_horizon(m);
}
