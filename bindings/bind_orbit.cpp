#include "bindings.hpp"

namespace py = pybind11;

namespace vistrack::bindings {

void bind_orbit(py::module_& m) {
  (void)m;  // filled in by the orbit area
}

}  // namespace vistrack::bindings
