// The array and point conversions of convert.hpp.
#include "convert.hpp"

namespace py = pybind11;

namespace vistrack::bindings {

Configuration configuration(const Pose& pose) { return {std::get<0>(pose), std::get<1>(pose), std::get<2>(pose)}; }

std::vector<Vec2> to_points(const InputArray& array, const std::string& field) {
  if (array.ndim() != 2 || array.shape(1) != 2)
    throw Error(field + ": expected an array of shape (n, 2) (x, y per row), got ndim = " + std::to_string(array.ndim()) +
                (array.ndim() >= 2 ? ", shape[1] = " + std::to_string(array.shape(1)) : std::string()));
  const auto view = array.unchecked<2>();
  std::vector<Vec2> points;
  points.reserve(static_cast<std::size_t>(array.shape(0)));
  for (py::ssize_t i = 0; i < array.shape(0); ++i) points.emplace_back(view(i, 0), view(i, 1));
  return points;
}

std::vector<double> to_values(const InputArray& array, const std::string& field) {
  if (array.ndim() != 1) throw Error(field + ": expected a 1-D array, got ndim = " + std::to_string(array.ndim()));
  return {array.data(), array.data() + array.shape(0)};
}

Points2 to_array(const std::vector<Vec2>& points) {
  Points2 out(static_cast<Eigen::Index>(points.size()), 2);
  for (std::size_t i = 0; i < points.size(); ++i) out.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
  return out;
}

}  // namespace vistrack::bindings
