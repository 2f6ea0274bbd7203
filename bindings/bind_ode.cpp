#include "bindings.hpp"

namespace py = pybind11;

namespace vistrack::bindings {

void bind_ode(py::module_& m) {
  (void)m;  // filled in by the ode area
}

}  // namespace vistrack::bindings
