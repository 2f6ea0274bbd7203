// Helpers shared by the bind_<area>.cpp files (declared in bindings.hpp).
#include "bindings.hpp"

namespace py = pybind11;

namespace vistrack::bindings {

std::function<void(std::size_t, std::size_t)> progress_callback(const py::object& callback) {
  if (callback.is_none()) return {};
  return [callback](std::size_t done, std::size_t total) {
    py::gil_scoped_acquire acquire;
    callback(done, total);
  };
}

std::string path_string(const py::object& path) {
  if (path.is_none()) return {};
  return py::module_::import("os").attr("fspath")(path).cast<std::string>();
}

}  // namespace vistrack::bindings
