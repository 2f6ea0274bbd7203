#include "bindings.hpp"

namespace py = pybind11;

namespace vistrack::bindings {

void bind_simulate(py::module_& m) {
  (void)m;  // filled in by the simulate area
}

}  // namespace vistrack::bindings
