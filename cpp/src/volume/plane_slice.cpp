// The VP of a VV at one altitude by walking the mesh edges that cross the plane: O(faces), no
// spatial tree. The VV mesh is closed and 2-manifold, so every crossing edge borders exactly two
// crossing faces and the walk always closes. Vertices are classified strictly (z_v > z: above,
// else below; simulation of simplicity), so a plane through a vertex needs no nudging.
#include <algorithm>
#include <array>
#include <unordered_map>

#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"
#include "vistrack/volume.hpp"

namespace vistrack {
namespace {

std::uint64_t edge_key(std::int32_t a, std::int32_t b) {
  const auto lo = static_cast<std::uint32_t>(std::min(a, b)), hi = static_cast<std::uint32_t>(std::max(a, b));
  return (static_cast<std::uint64_t>(lo) << 32) | hi;
}

}  // namespace

std::vector<Ring> plane_slice_rings(const TriangleMesh& mesh, double altitude) {
  require_coordinate(altitude, "altitude");
  const Eigen::Index n = mesh.vertices.rows();
  auto above = [&](std::int32_t v) { return mesh.vertices(v, 2) > altitude; };
  // Crossing edges -> the (up to two) crossing faces that share them.
  std::unordered_map<std::uint64_t, std::array<std::int64_t, 2>> edge_faces;
  std::vector<std::array<std::uint64_t, 2>> face_edges;
  std::vector<Eigen::Index> faces;
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f) {
    std::uint64_t crossing[2];
    int count = 0;
    for (int c = 0; c < 3; ++c) {
      const std::int32_t a = mesh.faces(f, c), b = mesh.faces(f, (c + 1) % 3);
      if (a < 0 || a >= n || b < 0 || b >= n)
        detail::fail_field("mesh.faces[" + std::to_string(f) + "]", a, "vertex index out of range");
      if (above(a) != above(b) && count < 2) crossing[count++] = edge_key(a, b);
    }
    if (count != 2) continue;
    const auto id = static_cast<std::int64_t>(face_edges.size());
    face_edges.push_back({crossing[0], crossing[1]});
    for (std::uint64_t e : crossing) {
      auto [it, inserted] = edge_faces.try_emplace(e, std::array<std::int64_t, 2>{id, -1});
      if (!inserted) {
        if (it->second[1] != -1) throw Error("slice: the mesh is not 2-manifold (an edge has more than two faces)");
        it->second[1] = id;
      }
    }
  }
  auto point_on = [&](std::uint64_t e) {
    const auto a = static_cast<Eigen::Index>(e >> 32), b = static_cast<Eigen::Index>(e & 0xffffffffu);
    const double za = mesh.vertices(a, 2), zb = mesh.vertices(b, 2);
    const double s = (altitude - za) / (zb - za);
    return Vec2(mesh.vertices(a, 0) + s * (mesh.vertices(b, 0) - mesh.vertices(a, 0)),
                mesh.vertices(a, 1) + s * (mesh.vertices(b, 1) - mesh.vertices(a, 1)));
  };
  std::vector<Ring> rings;
  std::vector<char> used(face_edges.size(), 0);
  for (std::size_t start = 0; start < face_edges.size(); ++start) {
    if (used[start]) continue;
    Ring ring;
    std::int64_t face = static_cast<std::int64_t>(start);
    std::uint64_t edge = face_edges[start][0];
    while (face >= 0 && !used[static_cast<std::size_t>(face)]) {
      used[static_cast<std::size_t>(face)] = 1;
      const Vec2 p = point_on(edge);
      if (ring.empty() || (p - ring.back()).norm() > 1e-9) ring.push_back(p);
      const auto& pair = face_edges[static_cast<std::size_t>(face)];
      edge = pair[0] == edge ? pair[1] : pair[0];
      const auto& owners = edge_faces.at(edge);
      face = owners[0] == face ? owners[1] : owners[0];
    }
    if (face < 0) throw Error("slice: the mesh is not closed (the cut runs into a border edge)");
    if (ring.size() > 1 && (ring.front() - ring.back()).norm() <= 1e-9) ring.pop_back();
    if (ring.size() >= 3) rings.push_back(std::move(ring));
  }
  return rings;
}

std::vector<Polygon> plane_visibility_polygon(const VisibilityVolume& vv, double altitude) {
  detail::require_mesh(vv, "vv");
  const std::optional<double> z = visibility_slice_height(vv, altitude);
  if (!z) return {};
  std::vector<Polygon> kept;
  const Vec2 centre = vv.poi.head<2>();
  for (Polygon& p : nest_rings(plane_slice_rings(vv.mesh, *z)))
    if (contains(p, centre)) kept.push_back(std::move(p));
  return kept;
}

}  // namespace vistrack
