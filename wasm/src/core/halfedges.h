// The halfedge structure of a mesh as CGAL's Surface_mesh holds it, as
// plain arrays: for each halfedge its next, previous and opposite
// halfedge, the vertex it points to and the face it bounds (none on the
// border) — the table a student checks an own halfedge implementation
// against (`subdiv halfedges`). Owner: halfedges.cpp.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh_types.h"

namespace subdivlab {

/// Indices as Surface_mesh numbers them on a mesh built from the buffers:
/// vertices and faces in the buffers' order, halfedges 2e and 2e + 1 on edge
/// e (so opposite(h) = h xor 1).
struct Halfedge_table {
  std::vector<std::uint32_t> next;
  std::vector<std::uint32_t> prev;
  std::vector<std::uint32_t> opposite;
  /// The vertex each halfedge points to (CGAL's target).
  std::vector<std::uint32_t> target;
  /// The face each halfedge bounds; -1 on a border halfedge.
  std::vector<std::int32_t> face;

  std::size_t size() const { return next.size(); }
};

/// The halfedge table of `mesh`, checked as build_mesh checks it (fails
/// with invalid_mesh naming the problem).
Result<Halfedge_table> halfedge_table(const Mesh_buffers& mesh);

}  // namespace subdivlab
