// Writing a VV mesh to OBJ or PLY.
#include <fstream>
#include <iomanip>
#include <string>

#include "vistrack/error.hpp"
#include "vistrack/visibility.hpp"

namespace vistrack {

namespace {

bool ends_with(const std::string& text, const std::string& suffix) {
  if (text.size() < suffix.size()) return false;
  std::string tail = text.substr(text.size() - suffix.size());
  for (char& c : tail) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return tail == suffix;
}

}  // namespace

void VisibilityVolume::save(const std::string& path) const {
  detail::require_mesh(*this, "vv");
  const bool obj = ends_with(path, ".obj");
  const bool ply = ends_with(path, ".ply");
  if (!obj && !ply) detail::fail_field("path", path, "extension must be .obj or .ply");
  std::ofstream out(path);
  if (!out) detail::fail_field("path", path, "cannot open for writing");
  out << std::setprecision(10);
  const Points3& v = mesh.vertices;
  const Faces& f = mesh.faces;
  if (obj) {
    out << "# vistrack visibility volume: poi " << poi.x() << ' ' << poi.y() << ' ' << poi.z() << ", d_max "
        << d_max << ", volume " << volume << " m^3\n";
    for (Eigen::Index i = 0; i < v.rows(); ++i) out << "v " << v(i, 0) << ' ' << v(i, 1) << ' ' << v(i, 2) << '\n';
    for (Eigen::Index i = 0; i < f.rows(); ++i)
      out << "f " << f(i, 0) + 1 << ' ' << f(i, 1) + 1 << ' ' << f(i, 2) + 1 << '\n';
  } else {
    out << "ply\nformat ascii 1.0\ncomment vistrack visibility volume\nelement vertex " << v.rows()
        << "\nproperty double x\nproperty double y\nproperty double z\nelement face " << f.rows()
        << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (Eigen::Index i = 0; i < v.rows(); ++i) out << v(i, 0) << ' ' << v(i, 1) << ' ' << v(i, 2) << '\n';
    for (Eigen::Index i = 0; i < f.rows(); ++i) out << "3 " << f(i, 0) << ' ' << f(i, 1) << ' ' << f(i, 2) << '\n';
  }
  if (!out) detail::fail_field("path", path, "write failed");
}

}  // namespace vistrack
