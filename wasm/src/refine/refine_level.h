// One level of a refinement as flat tables: the fast refinement hosts
// (primal_hosts.h) derive each level's tables from its parent's by
// arithmetic, and the masks (primal_masks.h) compute its points with tight
// loops over them. Owner: refine_level.cpp.
//
// Numbering. A level numbers its vertices, edges, halfedges and faces as
// CGAL::Surface_mesh numbers the same mesh after the same steps of CGAL's
// hosts (edge e has halfedges 2e and 2e + 1, each face starts at its
// Surface_mesh::halfedge(f)), so a fast result equals CGAL's index for
// index: CGAL stays the reference, compared element by element.
//
// Tables, and what the next wave adds to them without a rewrite:
//   face_vertices    a face's vertices in cycle order ("corners"), the
//                    target of each of its halfedges; a per-corner value
//                    (face-varying UVs) is an array beside it, refined
//                    corner by corner as the faces are
//   face_halfedges   a face's halfedges, corner by corner
//   halfedge_target  the vertex a halfedge points to; its source is the
//                    target of h ^ 1
//   halfedge_corner  where a halfedge sits in face_halfedges (kNone on the
//                    border): its face, and next/prev around the face, so
//                    vertex rings (limit masks) circulate without a search
//   vertex_halfedge  the DQQ host's only: Surface_mesh::halfedge(v), a
//                    halfedge into v (the border one on the border), where
//                    CGAL's hosts start circulating around v
//   edge_marks       per-edge data carried to both halves of a split edge
//                    (control edges); the last level lists its marked
//                    edges' ends instead
//   edge_sharpness   OpenSubdiv's creasing (crease.h): per edge, per
//   vertex_sharpness vertex and per face, refined as the faces are
//   face_holes
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace subdivlab {
namespace refine {

constexpr std::uint32_t kNone = 0xffffffffu;

struct Level {
  std::uint32_t vertex_count = 0, edge_count = 0, face_count = 0;
  /// Degree of every face when they all have the same one (the PQQ, PTQ
  /// and sqrt3 hosts' levels), else 0 and face_offsets says (a mixed level
  /// 0, DQQ's levels, PQT's that hold triangles and quads).
  std::uint32_t uniform_degree = 0;
  /// face f's corners are [face_offsets[f], face_offsets[f + 1]); empty
  /// when uniform_degree != 0.
  std::vector<std::uint32_t> face_offsets;
  std::vector<std::uint32_t> face_vertices;  ///< one per corner
  /// One per corner. The last level of a run has no halfedge tables
  /// (face_halfedges, halfedge_target, halfedge_corner): its buffers need
  /// none.
  std::vector<std::uint32_t> face_halfedges;
  std::vector<std::uint32_t> halfedge_target;  ///< 2 * edge_count
  std::vector<std::uint32_t> halfedge_corner;  ///< 2 * edge_count, or kNone
  /// One per vertex on levels the DQQ host refines (dual_hosts.h); else
  /// empty.
  std::vector<std::uint32_t> vertex_halfedge;
  /// Edges with a border halfedge; 0 on a closed mesh.
  std::uint32_t border_edge_count = 0;
  /// One byte per edge (1 = a control edge); empty when not tracked, and
  /// on the last level of a run, which has marked_ends instead.
  std::vector<std::uint8_t> edge_marks;
  /// The last level of a run whose edges are marked: the marked edges'
  /// ends, source then target, in edge order (the output's control edges),
  /// so that this level needs neither marks nor halfedge targets.
  std::vector<std::uint32_t> marked_ends;
  /// OpenSubdiv's creasing (crease.h), on the levels of a run that
  /// applies a mesh's tags; false and the tables empty otherwise. A
  /// sharpness per edge and per vertex (as the tags give them: the border
  /// mode's sharpness is not stored), a hole flag per face. Such a run's
  /// last level keeps its halfedge targets (its sharp edges' ends).
  bool creased = false;
  std::vector<float> edge_sharpness, vertex_sharpness;
  std::vector<std::uint8_t> face_holes;
  std::vector<double> positions;  ///< x y z per vertex

  std::uint32_t corner_count() const {
    return static_cast<std::uint32_t>(face_vertices.size());
  }
  std::uint32_t face_begin(std::uint32_t f) const {
    return uniform_degree != 0 ? f * uniform_degree : face_offsets[f];
  }
  std::uint32_t face_end(std::uint32_t f) const {
    return uniform_degree != 0 ? (f + 1) * uniform_degree : face_offsets[f + 1];
  }
  /// The face of a corner (a search on a mixed level).
  std::uint32_t corner_face(std::uint32_t c) const {
    if (uniform_degree != 0) return c / uniform_degree;
    return static_cast<std::uint32_t>(
        std::upper_bound(face_offsets.begin(), face_offsets.end(), c) -
        face_offsets.begin() - 1);
  }
};

/// Frees v's block (`v = {}` would keep it: that assigns an empty list,
/// keeping the capacity).
template <class T>
void release(std::vector<T>& v) {
  std::vector<T>().swap(v);
}

/// Sizes the vector to n elements; a vector too small is freed before the
/// new block is taken (its contents are not kept), so that old and new
/// blocks never coexist.
template <class T>
void size_to(std::vector<T>& v, std::size_t n) {
  if (v.capacity() < n) std::vector<T>().swap(v);
  v.resize(n);
}

/// Bytes the tables of a level with these counts hold (marks included when
/// `marks`; only the last level's tables when `last`, without its marked
/// edges' ends), for the memory model.
double level_bytes(double vertices, double edges, double corners, bool marks,
                   bool last);

}  // namespace refine
}  // namespace subdivlab
