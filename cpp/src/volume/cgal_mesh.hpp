// CGAL types shared by the volume area's translation units (private).
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include "vistrack/environment.hpp"

namespace vistrack::detail {

using CgalKernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalMesh = CGAL::Surface_mesh<CgalKernel::Point_3>;

// False when the faces are not an oriented 2-manifold polygon mesh.
bool to_surface_mesh(const TriangleMesh& mesh, CgalMesh& out);

}  // namespace vistrack::detail
