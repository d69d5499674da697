// The dual refinement host on flat tables: DQQ (Doo-Sabin's construction,
// a face per face, per interior edge and per vertex), numbered as the
// route CGAL's hosts take numbers it: CGAL's DQQ_1step followed by
// Surface_mesh::collect_garbage on closed meshes, SubdivLab's
// DQQ_border_1step (core/dqq_border_3.h) on open ones. Topology only: the
// points come from dual_points.h. Owner: dual_hosts.cpp.
//
// A DQQ level has mixed face degrees (F-faces keep their parent's, V-faces
// have their vertex's valence, E-faces are quads): face_offsets always.
// Each new vertex is a corner of the parent (a non-border halfedge x: the
// corner of face(x) at target(x)). The points read which from the child's
// F-faces (closed) or Dual_scratch::corner_vertex (open).
//
// Memory: the step frees its scratch when the topology is done, before
// refine_dual_points allocates the child's positions, which take its
// place (the memory model counts the larger of the two).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "refine_level.h"

namespace subdivlab {
namespace refine {

/// A scratch table whose elements start unset (the step writes each one
/// before it reads it), where std::vector's resize would zero-fill it
/// first. Its block is kept while big enough.
template <class T>
class Scratch_array {
 public:
  T* data() { return data_.get(); }
  const T* data() const { return data_.get(); }
  std::size_t size() const { return size_; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }
  /// n elements; the old block goes before a bigger one is taken.
  void size_to(std::size_t n) {
    if (capacity_ < n) {
      release();
      data_.reset(new T[n]);
      capacity_ = n;
    }
    size_ = n;
  }
  void release() {
    data_.reset();
    size_ = capacity_ = 0;
  }

 private:
  std::unique_ptr<T[]> data_;
  std::size_t size_ = 0, capacity_ = 0;
};

/// Per-parent tables a step fills; kept between steps so that their memory
/// is reused.
struct Dual_scratch {
  /// Open, per parent halfedge: the child vertex of its corner (kNone on
  /// the border; a border corner of an ear has a second vertex, this + 1),
  /// the only table refine_dual_points reads. The others are freed when the
  /// topology is done, before the child's positions are allocated.
  Scratch_array<std::uint32_t> corner_vertex;
  Scratch_array<std::uint32_t> next, prev;  ///< open: per non-border halfedge
  /// Open: the F-face halfedge into each corner's vertex.
  Scratch_array<std::uint32_t> edge_of;
  /// Open: rank of each interior edge; closed: valence of each vertex.
  Scratch_array<std::uint32_t> rank;
  /// Closed, per halfedge h: prev(h), the child vertex of h's corner and
  /// the child vertex and cut edge of prev(h)'s corner, side by side: a
  /// circulation reads and writes them in the cache lines it visits.
  struct Closed_halfedge {
    std::uint32_t prev, vertex, prev_vertex, prev_cut;
  };
  Scratch_array<Closed_halfedge> halfedges;
  /// Closed, per corner in vertex order: its spoke's edge slot (where
  /// collect_garbage moves the slots past the kept edges) and its cut
  /// edge's final index.
  Scratch_array<std::uint32_t> spoke, cut;
};

/// Bytes the scratch adds to a step's peak for a parent with these counts
/// (`child_vertices` after it): the topology's tables, which the child's
/// positions replace, or the corner vertices beside them.
double dual_scratch_bytes(double vertices, double edges, double child_vertices,
                          bool border);

/// level.vertex_halfedge as Surface_mesh::add_face leaves it after adding
/// the level's faces in order (build_mesh, DQQ_border_1step): on the border
/// the border halfedge into v, inside the halfedge into v of the last face
/// around v. Precondition: the halfedge tables.
void add_face_vertex_halfedges(Level& level);

/// Frees what a DQQ step does not read of its parent: the halfedge
/// targets and, on a closed mesh, the halfedges' corners (the step reads
/// them on open meshes, for the border).
void release_unread_tables(Level& parent);

/// The child level's topology (everything but positions): counts, face
/// offsets and vertices; unless `last`, its halfedge tables and vertex
/// halfedges. `child`'s vectors are reused. Preconditions: a valid level
/// with vertex_halfedge; no interior vertex of valence 2.
void refine_dqq_topology(const Level& parent, Dual_scratch& scratch,
                         Level& child, bool last);

}  // namespace refine
}  // namespace subdivlab
