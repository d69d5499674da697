// A Level from a CGAL::Surface_mesh (the level a run starts from: CGAL
// builds and checks the input, and triangulates it) and a Level out as
// Mesh_buffers. Owner: level_convert.cpp.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "core/mesh_types.h"
#include "refine_level.h"

namespace subdivlab {
namespace refine {

/// The tables of `mesh`, numbered as the mesh numbers its elements.
/// Precondition: no removed elements (Surface_mesh::has_garbage() false),
/// so that its indices are 0..n-1.
Level level_from_mesh(const Mesh& mesh);

/// Marks the edges between the vertex pairs of `edges` (pairs of mesh
/// vertex indices, each an edge of `mesh`, as initial_control_edges gives).
void mark_edges(
    const Mesh& mesh,
    const std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges,
    Level& level);

/// The level as buffers, as to_buffers gives the same Surface_mesh: faces
/// from their first corner, vertices in index order; the marked edges as
/// control edges (a pair per marked edge, in edge order, source first).
/// The positions move out of `level`.
Mesh_buffers level_to_buffers(Level&& level);

}  // namespace refine
}  // namespace subdivlab
