// One bind_<area> function per area, each in bindings/bind_<area>.cpp.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

#include "vistrack/geometry.hpp"

namespace vistrack::bindings {

// Rings cross the boundary as (n, 2) numpy arrays.
Ring ring_from_array(const Points2& points, const std::string& field);
Points2 ring_to_array(const Ring& ring);

void bind_geometry(pybind11::module_& m);
void bind_parameters(pybind11::module_& m);
void bind_environment(pybind11::module_& m);
void bind_dubins(pybind11::module_& m);
void bind_visibility(pybind11::module_& m);
void bind_volume(pybind11::module_& m);
void bind_orbit(pybind11::module_& m);
void bind_xor(pybind11::module_& m);  // XOR volume (eq. 56), bindings/bind_xor.cpp
void bind_guidance(pybind11::module_& m);
void bind_ode(pybind11::module_& m);
void bind_simulate(pybind11::module_& m);

}  // namespace vistrack::bindings
