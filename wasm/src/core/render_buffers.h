// What the GPU draws for a mesh, built by the core beside the step that
// made the mesh, so that the page gets arrays it uploads as they are (no
// JavaScript pass over a million faces, no normals on the main thread).
// Owner: render_buffers.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "mesh_types.h"

namespace subdivlab {

/// The arrays of a level's picture:
///   positions      x y z per vertex, as float
///   bounding_sphere  centre x y z and radius: the centre of the bounding
///                  box and the largest distance from it, as three.js's
///                  computeBoundingSphere makes it (radius rounded up)
///   normals        per vertex: the sum of the normals of its fan triangles,
///                  each weighted by the triangle's area, normalized (zero
///                  where that sum is zero), as three.js's
///                  computeVertexNormals makes them
///   triangles      each polygon fanned from its first corner: 0 k k+1
///   triangle_face  the polygon each triangle came from
///   edges          every polygon edge once (quads stay quads: no fan
///                  diagonals), as its smaller then larger vertex; in the
///                  order of the corners going from smaller to larger when
///                  they give all the edges the caller expects (a closed
///                  mesh: one pass), otherwise ordered by the smaller
///                  vertex, then by first appearance
///   border_edges   the edges of one face only (the mesh's border, hole
///                  faces counted as faces), as edges gives them; empty on
///                  a closed mesh
enum class Render_array {
  positions,
  bounding_sphere,
  normals,
  triangles,
  triangle_face,
  edges,
  border_edges
};

/// Receives the arrays one at a time; each is freed when the call returns,
/// so that only one of them is in memory beside the mesh.
class Render_sink {
 public:
  virtual ~Render_sink() = default;
  virtual void floats(Render_array which, const std::vector<float>& values) = 0;
  virtual void indices(Render_array which,
                       const std::vector<std::uint32_t>& values) = 0;
};

/// Builds the arrays of `mesh` (a valid mesh: every edge in at most two
/// faces) in the order of Render_array and hands each to `sink`. Returns
/// the number of edges. `expected_edges` (0: unknown) is the mesh's number
/// of edges, which lets a closed mesh skip the sort of its edges.
std::size_t build_render_buffers(const Mesh_buffers& mesh, Render_sink& sink,
                                 std::size_t expected_edges = 0);

/// Bytes the arrays and their scratch take at most at once, beside the
/// mesh, for V vertices, E edges, C corners and T fan triangles.
double render_peak_bytes(double vertices, double edges, double corners,
                         double triangles);

/// All the arrays at once (tests, and callers without a sink).
struct Render_buffers {
  std::vector<float> positions, bounding_sphere, normals;
  std::vector<std::uint32_t> triangles, triangle_face, edges, border_edges;
};
Render_buffers render_buffers(const Mesh_buffers& mesh);

}  // namespace subdivlab
