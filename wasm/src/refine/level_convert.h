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

/// The tables of the Surface_mesh build_mesh would build from `in`, without
/// building it: vertices no face uses dropped, the others in their order;
/// faces in order, each from its first corner; edges numbered as
/// check_buffers' `corner_halfedges` (which must come from `in`) say.
/// Precondition: check_buffers(in) succeeded.
Level level_from_buffers(const Mesh_buffers& in,
                         const std::vector<std::uint32_t>& corner_halfedges);

/// Each vertex's valence and whether it is on the border.
void vertex_valences(const Level& level, std::vector<std::uint32_t>& valence,
                     std::vector<bool>& border);

/// The halfedges leaving each vertex, for finding the edge between two
/// vertices: begin[v] .. begin[v + 1] in `halfedges`.
struct Vertex_halfedges {
  std::vector<std::uint32_t> begin, halfedges;
  /// The edge from a to b or b to a, or kNone.
  std::uint32_t edge(const Level& level, std::uint32_t a,
                     std::uint32_t b) const;
};
Vertex_halfedges vertex_halfedges(const Level& level);
/// The same into `out`, whose memory is reused.
void vertex_halfedges(const Level& level, Vertex_halfedges& out);

/// The level as buffers, as to_buffers gives the same Surface_mesh: faces
/// from their first corner, vertices in index order; the marked edges as
/// control edges (a pair per marked edge, in edge order, source first).
/// The positions and face vertices move out of `level`.
Mesh_buffers level_to_buffers(Level&& level);

}  // namespace refine
}  // namespace subdivlab
