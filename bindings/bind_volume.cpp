#include "bindings.hpp"

namespace py = pybind11;

namespace vistrack::bindings {

void bind_volume(py::module_& m) {
  (void)m;  // filled in by the volume area
}

}  // namespace vistrack::bindings
