// Conversion between Mesh_buffers and CGAL::Surface_mesh, with the checks
// that make a buffer a mesh the schemes can work on. Owner: mesh_build.cpp.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh_types.h"

namespace subdivlab {

/// Checks the buffers (indices in range, faces of 3+ distinct vertices,
/// finite coordinates, at least one face, every edge used by at most two
/// faces and in opposite directions, manifold vertices) and builds `out`.
/// On failure `out` is left empty and the status names the first problem
/// (face number, vertex numbers, 0-based as in the buffers).
/// Vertices that no face uses are dropped; the others keep their relative
/// order (so to_buffers of a fresh build gives back the input exactly when
/// every vertex is used).
Status build_mesh(const Mesh_buffers& in, Mesh& out);

/// build_mesh without the checks, from the corner halfedges they gave.
/// Precondition: detail::check_buffers(in, ..., &corner_halfedges)
/// succeeded (read_mesh gives them too).
void build_checked_mesh(const Mesh_buffers& in,
                        const std::vector<std::uint32_t>& corner_halfedges,
                        Mesh& out);

/// Buffers of a Surface_mesh; vertices renumbered 0..n-1 in iteration order,
/// faces in iteration order. Control edges are not filled in here.
Mesh_buffers to_buffers(const Mesh& mesh);

}  // namespace subdivlab
