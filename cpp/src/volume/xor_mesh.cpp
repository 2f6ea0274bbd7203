// The general XOR volume path of eq. (56): CGAL corefinement of two closed triangle meshes.
// All CGAL code of the XOR metric lives in this translation unit (it compiles slowly).
#include <chrono>
#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"
#include "vistrack/volume.hpp"

namespace vistrack {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

struct TimeLimitExceeded {};

// Aborts the corefinement (by an exception through CGAL) once the deadline has passed: CGAL
// reports progress from every stage that can run long.
struct DeadlineVisitor : PMP::Corefinement::Default_visitor<Mesh> {
  std::chrono::steady_clock::time_point deadline;
  void check() const {
    if (std::chrono::steady_clock::now() > deadline) throw TimeLimitExceeded{};
  }
  void progress_filtering_intersections(double) const { check(); }
  void triangulating_faces_step() const { check(); }
  void intersection_of_coplanar_faces_step() const { check(); }
  void edge_face_intersections_step() const { check(); }
  void build_output_step() const { check(); }
};

// Rotation about the fixed axis (1, 2, 3)/|.| by `angle`: a deterministic general-position nudge.
Eigen::Matrix3d nudge_rotation(double angle) {
  return Eigen::AngleAxisd(angle, Eigen::Vector3d(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
}

// A checked CGAL copy of one input mesh.
Mesh to_cgal(const TriangleMesh& input, const std::string& name, const Eigen::Matrix3d& rotation,
             bool check_self_intersection) {
  Mesh mesh;
  const Eigen::Index n = input.vertices.rows();
  std::vector<Mesh::Vertex_index> index(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) {
    const Vec3 p = rotation * input.vertices.row(i).transpose();
    if (!p.allFinite())
      detail::fail_field(name + ".vertices[" + std::to_string(i) + "]", "non-finite", "coordinates must be finite");
    index[static_cast<std::size_t>(i)] = mesh.add_vertex(Kernel::Point_3(p.x(), p.y(), p.z()));
  }
  for (Eigen::Index f = 0; f < input.faces.rows(); ++f) {
    Mesh::Vertex_index corner[3];
    for (Eigen::Index c = 0; c < 3; ++c) {
      const std::int32_t v = input.faces(f, c);
      if (v < 0 || v >= n)
        detail::fail_field(name + ".faces[" + std::to_string(f) + "]", v,
                           "vertex index out of range [0, " + std::to_string(n) + ")");
      corner[c] = index[static_cast<std::size_t>(v)];
    }
    if (mesh.add_face(corner[0], corner[1], corner[2]) == Mesh::null_face())
      detail::fail_field(name + ".faces[" + std::to_string(f) + "]", "",
                         "not a 2-manifold triangle mesh (degenerate, repeated or non-manifold face)");
  }
  if (!CGAL::is_closed(mesh))
    detail::fail_field(name, "mesh", "is not closed (it has border edges): the XOR volume needs closed meshes");
  if (check_self_intersection && PMP::does_self_intersect(mesh))
    detail::fail_field(name, "mesh", "self-intersects: CGAL corefinement needs meshes without self-intersections");
  if (!PMP::does_bound_a_volume(mesh))
    detail::fail_field(name, "mesh", "does not bound a volume (inconsistent orientation or nested shells)");
  // An inward-oriented closed mesh bounds the complement; Booleans need outward orientation.
  if (!PMP::is_outward_oriented(mesh)) PMP::reverse_face_orientations(mesh);
  return mesh;
}

}  // namespace

double mesh_xor_volume(const TriangleMesh& a, const TriangleMesh& b, const MeshXorOptions& options) {
  // A deadline past 1e6 s overflows the clock's duration; a rotation past 1e-3 rad is no longer a
  // nudge (it moves a point 1 km away by a metre) and the XOR would measure the rotation.
  require_in_range(options.time_limit, 1e-3, 1e6, "s", "options.time_limit");
  const double perturbation = options.perturbation.value_or(0.0);
  require_in_range(perturbation, 0.0, kMaxPerturbation, "rad", "options.perturbation");
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  const bool a_empty = a.faces.rows() == 0, b_empty = b.faces.rows() == 0;
  Mesh ma = a_empty ? Mesh() : to_cgal(a, "a", identity, options.check_self_intersection);
  Mesh mb = b_empty ? Mesh() : to_cgal(b, "b", nudge_rotation(perturbation), options.check_self_intersection);
  const double va = a_empty ? 0.0 : PMP::volume(ma);
  const double vb = b_empty ? 0.0 : PMP::volume(mb);
  if (a_empty || b_empty) return va + vb;

  DeadlineVisitor visitor;
  visitor.deadline = std::chrono::steady_clock::now() +
                     std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                         std::chrono::duration<double>(options.time_limit));
  Mesh both;
  bool ok = false;
  try {
    // corefinement modifies both inputs: ma and mb are our own copies.
    ok = PMP::corefine_and_compute_intersection(ma, mb, both,
                                                PMP::parameters::throw_on_self_intersection(true).visitor(visitor),
                                                PMP::parameters::throw_on_self_intersection(true));
  } catch (const TimeLimitExceeded&) {
    throw Error("mesh XOR volume: CGAL corefinement exceeded options.time_limit = " +
                detail::to_text(options.time_limit) +
                " s (coincident or coplanar faces make it very slow; use the per-direction path "
                "or options.perturbation)");
  } catch (const PMP::Corefinement::Self_intersection_exception&) {
    throw Error("mesh XOR volume: CGAL found self-intersections while corefining the meshes");
  }
  if (!ok) throw Error("mesh XOR volume: CGAL could not build the intersection as a 2-manifold mesh");
  const double common = both.number_of_faces() == 0 ? 0.0 : PMP::volume(both);
  return std::max(va + vb - 2.0 * common, 0.0);
}

}  // namespace vistrack
