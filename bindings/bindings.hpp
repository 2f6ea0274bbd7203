// One bind_<area> function per area, each in bindings/bind_<area>.cpp.
#pragma once

#include <pybind11/pybind11.h>

namespace vistrack::bindings {

void bind_environment(pybind11::module_& m);

}  // namespace vistrack::bindings
