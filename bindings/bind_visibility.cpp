#include "bindings.hpp"

namespace py = pybind11;

namespace vistrack::bindings {

void bind_visibility(py::module_& m) {
  (void)m;  // filled in by the visibility area
}

}  // namespace vistrack::bindings
