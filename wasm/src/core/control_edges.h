// Control edges: the edges of the level-0 (control) mesh, followed through
// the refinement. Every edge of a refined mesh that lies on a control edge is
// marked; after a primal step the two halves of a marked edge are marked.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "mesh_types.h"
#include "subdivide.h"

namespace subdivlab {

/// Marked edges as pairs of Surface_mesh vertex indices.
using Control_edges = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

/// Whether `options` names a primal scheme whose host keeps the old vertex
/// indices first and splits every edge at one new vertex: catmull-clark,
/// loop, quad-triangle, linear, linear-tri, and custom on the pqq or ptq
/// host. Other schemes (doo-sabin, sqrt3, custom on dqq or sqrt3) drop the
/// marks.
bool scheme_keeps_control_edges(const Subdivide_options& options);

/// The edge between vertices a and b of a mesh, or kNoEdge.
using Edge_finder =
    std::function<std::uint32_t(std::uint32_t a, std::uint32_t b)>;
constexpr std::uint32_t kNoEdge = 0xffffffffu;

/// Control edges of `mesh` (built by build_mesh from `in`) at the start of a
/// subdivision: `in.control_edges` mapped to mesh vertex indices (build_mesh
/// drops isolated vertices), or every edge of the faces of `in` when
/// `in.control_edges` is empty and `start_level` is 0 (edges a later
/// triangulation adds are not control edges), or none. Precondition:
/// build_mesh(in, ...) succeeded (`mesh` may since have been triangulated).
/// Fails with invalid_argument when the pairs are odd in number, out of
/// range, or not edges of the mesh.
Result<Control_edges> initial_control_edges(const Mesh_buffers& in,
                                            const Mesh& mesh, int start_level);

/// The same for a mesh given by its edge count and a way to find an edge
/// (vertices numbered as build_mesh numbers them).
Result<Control_edges> initial_control_edges(const Mesh_buffers& in,
                                            std::size_t edge_count,
                                            const Edge_finder& edge_of,
                                            int start_level);

/// The children of `parents` after one primal step on `refined`, where the
/// vertices of the coarse mesh kept their indices and every index from
/// `old_vertex_end` on is new: the child edges of (a, b) are (a, m) and
/// (m, b), m the new vertex adjacent to both. Parents without such an m
/// (which a primal host never produces) are dropped.
Control_edges refine_control_edges(const Mesh& refined,
                                   std::uint32_t old_vertex_end,
                                   const Control_edges& parents);

/// The pairs as Mesh_buffers::control_edges, numbered as to_buffers numbers
/// the vertices (iteration order).
std::vector<std::uint32_t> control_edges_to_buffers(const Mesh& mesh,
                                                    const Control_edges& edges);

}  // namespace subdivlab
