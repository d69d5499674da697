// The points of a primal step: one pass over the parent's faces (face
// points, and their sums at each vertex), one over its edges (edge points,
// neighbour sums), one over its vertices. Scatter, not gather: the passes
// read the parent's tables in order and need no vertex rings; the sums
// gather in the child's slots of the parent's vertices, which the vertex
// pass then overwrites with the vertex points.
// Owner: primal_points.cpp.
//
// Quad/triangle (PQT host) has the same three passes: its averaging reads
// the refined mesh, whose ring around each new vertex is known from the
// parent (the face pass adds each face's side of an edge point's ring), so
// that it needs no table of the child.
#pragma once

#include <cstdint>
#include <vector>

#include "primal_masks.h"
#include "refine_level.h"

namespace subdivlab {
namespace refine {

/// Per-vertex sums a step accumulates; kept between steps so that their
/// memory is reused.
struct Primal_scratch {
  /// 3 per vertex: sum of edge neighbours (PQT's points only; the others
  /// sum in the child's slots).
  std::vector<double> ring;
  /// 3 per vertex: sum of face points, for a PQQ mask that weighs them
  /// apart from the edge neighbours (Primal_mask::separate_face_sums), and
  /// for PQT's polygons.
  std::vector<double> faces;
  std::vector<std::uint32_t> valence;
  /// Border chain (border halfedges): the vertex after and before each
  /// border vertex; kNone inside. Filled only when the level has a border.
  std::vector<std::uint32_t> border_next, border_prev;
  std::vector<Vertex_weights> weights;  ///< by valence
  /// PQT on a level with faces other than triangles ("polygons"): the
  /// polygons at each vertex, and beside each edge (0-2).
  std::vector<std::uint32_t> polygons;
  std::vector<std::uint8_t> edge_polygons;
};

/// Bytes of the scratch for a parent with V vertices (`face_sums`: the
/// mask sums face points apart).
double primal_scratch_bytes(double vertices, bool face_sums, bool border);
/// The same for the PQT points (E edges; `polygons`: faces other than
/// triangles in the parent).
double pqt_scratch_bytes(double vertices, double edges, bool polygons,
                         bool border);

/// Largest valence of an interior vertex of `parent` that `mask` does not
/// cover, or 0 when it covers them all (custom tables end somewhere).
/// Fills scratch.valence and the border chain.
std::uint32_t primal_uncovered_valence(const Level& parent,
                                       const Primal_mask& mask,
                                       Primal_scratch& scratch);

/// child.positions from `parent` (child's topology built by the host of
/// mask.pqq). Precondition: primal_uncovered_valence returned 0 on this
/// parent with this scratch.
void refine_primal_points(const Level& parent, const Primal_mask& mask,
                          Primal_scratch& scratch, Level& child);

/// child.positions of a quad/triangle step from `parent` (child's topology
/// from refine_pqt_topology): the linear refinement's points (midpoints,
/// centroids) averaged by `mask` on the refined mesh, as PQT_1step does.
void refine_pqt_points(const Level& parent, const Quad_triangle_mask& mask,
                       Primal_scratch& scratch, Level& child);

}  // namespace refine
}  // namespace subdivlab
