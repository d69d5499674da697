// The primal refinement hosts on flat tables: PQQ (every k-gon into k quads
// around a face point, as CGAL's PQQ_1step), PTQ (every triangle into
// four, as PTQ_1step) and PQT (quad-triangle's: triangles as PTQ, the other
// faces as PQQ, as core/quad_triangle_3.h's PQT_1step). Topology only: the
// masks (primal_masks.h) compute the points. Owner: primal_hosts.cpp.
//
// A child level's tables come from the parent's by arithmetic, in CGAL's
// numbering (refine_level.h). Vertices: the parent's v keeps v, edge e's
// point is V + e, face f's point (PQQ) V + E + f. Edges: edge e splits
// into e (its source half) and E + e; then every face in order adds its
// spokes (PQQ: one per corner) or its inner triangle's edges (PTQ: three;
// PQT: either, by the face's degree, the face points numbered among the
// faces that are not triangles).
// CGAL splits the edges in index order, and each split points the faces
// beside it at the new half; so a face's corners are taken from the end of
// its edge of highest index (v1 below), and its children are numbered as
// PQQ_1step / PTQ_1step insert them (derivation in primal_hosts.cpp).
#pragma once

#include "refine_level.h"

namespace subdivlab {
namespace refine {

/// The child level's topology (everything but positions): counts,
/// face_halfedges, halfedge_target, halfedge_corner unless `last` (the
/// last level needs no further step), border count, edge marks. `child`'s
/// vectors are reused. Preconditions: a valid level; PTQ: triangles; with
/// `last` on an uncreased level, release_before_last_topology(parent,
/// child) first.
void refine_pqq_topology(const Level& parent, Level& child, bool last);
void refine_ptq_topology(const Level& parent, Level& child, bool last);
/// PQT: any faces; the child holds triangles and quads, its face_offsets
/// set when it holds both (uniform_degree 0).
void refine_pqt_topology(const Level& parent, Level& child, bool last);

/// Faces of `level` that are not triangles (PQT's face points).
std::uint32_t polygon_count(const Level& level);

/// The vertex count of the child each host makes of `parent`: the points
/// need only this of the child, so a step may compute them before its
/// topology.
std::uint32_t pqq_child_vertex_count(const Level& parent);
std::uint32_t ptq_child_vertex_count(const Level& parent);
std::uint32_t pqt_child_vertex_count(const Level& parent);

/// Before the topology of the last level of an uncreased run (its points
/// made): moves the marked edges' ends into `child` (marked_ends) and frees
/// what that topology does not read of `parent`, its positions, halfedge
/// targets and corners and edge marks, so that they never coexist with the
/// child's corners.
void release_before_last_topology(Level& parent, Level& child);

/// Position of the corner, in parent face f (corners [begin, end)), that
/// starts the CGAL corner order v1, v2, ...: the corner after the halfedge
/// whose edge index is highest. g_j (v_j -> v_j+1) is corner
/// begin + (start + j) % k, with start the returned offset.
inline std::uint32_t first_corner_offset(const std::uint32_t* fh,
                                         std::uint32_t k) {
  std::uint32_t best = 0;
  for (std::uint32_t t = 1; t < k; ++t)
    if (fh[t] >> 1 > fh[best] >> 1) best = t;
  return best;
}

}  // namespace refine
}  // namespace subdivlab
