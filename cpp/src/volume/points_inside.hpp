// Point-in-solid queries on a closed mesh, for tests that check a VV mesh against geometry.
#pragma once

#include <vector>

#include "vistrack/environment.hpp"
#include "vistrack/geometry.hpp"

namespace vistrack::detail {

// For each row of `points`: inside the closed mesh (CGAL Side_of_triangle_mesh; boundary counts
// as inside). Throws Error when the mesh is not a closed 2-manifold.
std::vector<bool> points_inside(const TriangleMesh& mesh, const Points3& points);

}  // namespace vistrack::detail
