#include "bindings.hpp"

namespace py = pybind11;

namespace vistrack::bindings {

void bind_guidance(py::module_& m) {
  (void)m;  // filled in by the guidance area
}

}  // namespace vistrack::bindings
