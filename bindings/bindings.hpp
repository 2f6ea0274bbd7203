// One bind_<area> function per area, each in bindings/bind_<area>.cpp, and the helpers they
// share (bindings/helpers.cpp): progress callbacks, file paths, validated keyword construction;
// conversions of values (enums, arrays, points, reprs) are in convert.hpp.
#pragma once

#include <pybind11/pybind11.h>

#include <cstddef>
#include <functional>
#include <string>

#include "convert.hpp"
#include "vistrack/geometry.hpp"

namespace vistrack::bindings {

// Rings cross the boundary as (n, 2) numpy arrays (to_array for the way back).
Ring ring_from_array(const Points2& points, const std::string& field);

// A Python progress(done, total) callable, or None, as a C++ callback that takes the GIL to call
// it (long calls run with the GIL released and report from their own thread).
std::function<void(std::size_t, std::size_t)> progress_callback(const pybind11::object& callback);
// A str or os.PathLike as a path ("" for None).
std::string path_string(const pybind11::object& path);

// Keyword constructors: every argument defaults to the C++ default, then the struct validates.
template <class T>
T make_validated(T value) {
  value.validate();
  return value;
}

void bind_geometry(pybind11::module_& m);
void bind_parameters(pybind11::module_& m);
void bind_environment(pybind11::module_& m);
void bind_dubins(pybind11::module_& m);
void bind_visibility(pybind11::module_& m);
void bind_volume(pybind11::module_& m);
void bind_xor(pybind11::module_& m);
void bind_orbit(pybind11::module_& m);
void bind_guidance(pybind11::module_& m);
void bind_ode(pybind11::module_& m);
void bind_simulate(pybind11::module_& m);
void bind_flight(pybind11::module_& m);  // vistrack._core.flight, bindings/bind_flight.cpp
void bind_waypoint_nav(pybind11::module_& m);  // vistrack._core.waypoint_nav
void bind_path_following(pybind11::module_& m);  // flight.PathFollower, bindings/bind_path_following.cpp
void bind_loiter(pybind11::module_& m);  // loiter planners and coverage, bindings/bind_loiter.cpp
void bind_follow(pybind11::module_& m);  // vistrack._core.follow
void bind_follow_horizon(pybind11::module_& m);  // follow.HorizonPlanner, after bind_follow

}  // namespace vistrack::bindings
