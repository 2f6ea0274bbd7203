#include "bindings.hpp"

namespace py = pybind11;

namespace vistrack::bindings {

void bind_dubins(py::module_& m) {
  (void)m;  // filled in by the dubins area
}

}  // namespace vistrack::bindings
