// One bind_<area> function per area, each in bindings/bind_<area>.cpp.
#pragma once

#include <pybind11/pybind11.h>

namespace vistrack::bindings {

void bind_parameters(pybind11::module_& m);
void bind_environment(pybind11::module_& m);
void bind_dubins(pybind11::module_& m);
void bind_visibility(pybind11::module_& m);
void bind_volume(pybind11::module_& m);
void bind_orbit(pybind11::module_& m);
void bind_guidance(pybind11::module_& m);
void bind_ode(pybind11::module_& m);
void bind_simulate(pybind11::module_& m);

}  // namespace vistrack::bindings
