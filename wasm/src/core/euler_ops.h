// CGAL's Euler operators applied to a picked element of a mesh, one at a
// time, as the halfedge tutorials teach them (issue 13): split a face along
// a diagonal, join two faces, add or remove a centre vertex, split an edge,
// flip an edge; and one √3 step written with them, as the tutorial writes
// it (a centre vertex in every face, then a flip of every old edge, then
// the smoothing of the old vertices), stopped after any number of
// operators. Every operator's preconditions are checked first (CGAL's own
// are assertions), and the result must build as a valid mesh, else the
// request fails naming why. Halfedges are numbered as halfedge_table
// numbers them (halfedges.h). Owner: euler_ops.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "mesh_facts.h"
#include "mesh_types.h"

namespace subdivlab {

enum class Euler_op {
  split_face,            ///< CGAL::Euler::split_face(h, h2): a new edge
                         ///< from target(h) to target(h2), inside their face
  join_face,             ///< CGAL::Euler::join_face(h): removes h's edge
  add_center_vertex,     ///< at the centroid of h's face, joined to its corners
  remove_center_vertex,  ///< removes target(h) and its edges
  split_edge,            ///< a new vertex at the midpoint of h's edge
  flip_edge,             ///< h's edge between the two far corners of its
                         ///< triangles
};

/// Parses "split_face", "join_face", ... (the names above); false otherwise.
bool parse_euler_op(const std::string& name, Euler_op& op);

struct Euler_request {
  Euler_op op = Euler_op::split_face;
  std::uint32_t h = 0;
  std::uint32_t h2 = 0;  ///< split_face's second halfedge
};

struct Euler_result {
  /// The edited mesh, vertices and faces renumbered in CGAL's iteration
  /// order (removed ones skipped).
  Mesh_buffers mesh;
  Mesh_facts facts;
  /// CGAL::is_valid_polygon_mesh on the edited mesh.
  bool valid = false;
  /// The halfedge the operator returns (CGAL's), in the result's numbering;
  /// for flip_edge, h after the flip.
  std::uint32_t halfedge = 0;
};

/// Applies `request` to `mesh`. Fails with invalid_argument naming the
/// broken precondition ("halfedge 5 and halfedge 9 are not on one face"),
/// or invalid_mesh if the mesh itself is not valid.
Result<Euler_result> apply_euler_op(const Mesh_buffers& mesh,
                                    const Euler_request& request);

struct Sqrt3_walk {
  /// The mesh after the first `done` operators.
  Mesh_buffers mesh;
  std::size_t done = 0;
  /// Operators of the whole step: F centre vertices, E flips, V moves.
  std::size_t total = 0;
  /// The last operator applied, as the tutorial would call it
  /// ("add_center_vertex (face 3)", "flip_edge (edge 7)", "smooth vertex 2,
  /// valence 5"); empty when none.
  std::string last;
};

/// One √3 step of a closed triangle mesh by Euler operators, stopped after
/// `steps` of them (all: at least `total`). After all of them the mesh
/// equals the √3 scheme's level 1 (to rounding). Fails with
/// invalid_argument on a mesh with a border or other faces than triangles.
Result<Sqrt3_walk> sqrt3_by_hand(const Mesh_buffers& mesh, std::size_t steps);

}  // namespace subdivlab
