// Validation of Mesh_buffers shared by build_mesh and read_mesh, so that a
// buffer from JS and a file from disk fail with the same words. Internal to
// the core (mesh_build.cpp, mesh_io.cpp); not part of the public API.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "mesh_types.h"

namespace subdivlab::detail {

/// How to name things in messages. Buffers name faces by their 0-based
/// number; files name them by the 1-based line they were read from and
/// number vertices as the file does (OBJ counts from 1).
struct Check_naming {
  /// Line of each face in the source text; empty for buffers.
  const std::vector<int>* face_lines = nullptr;
  /// Added to vertex numbers in messages (1 for OBJ).
  std::uint32_t vertex_offset = 0;
};

/// The first problem found, or ok. `line` is set from `face_lines` for
/// problems that belong to a face; `face` is that face, or npos.
struct Check_result {
  Status status;
  std::size_t face = static_cast<std::size_t>(-1);
  /// The problem is an edge two faces use in the same direction (all the
  /// checks before that one passed).
  bool inconsistent_orientation = false;
};

/// Checks, in this order: at least one face, consistent array sizes,
/// finite coordinates, per face (in face order) at least 3 vertices,
/// indices in range and no repeated vertex, then edges used by at most two
/// faces, edges used in opposite directions, and vertices whose faces form a
/// single fan. Isolated vertices are not an error (build_mesh drops them).
///
/// On success, `corner_halfedges` (when given) receives for each corner c
/// (index into face_indices) the halfedge from its vertex to the next one
/// as build_mesh's Surface_mesh numbers it: Surface_mesh::add_face creates
/// an edge where a face first uses it, faces and corners in order, its
/// halfedge 2e in that first direction, so edge e is the e-th first use
/// and the other side is 2e + 1.
Check_result check_buffers(
    const Mesh_buffers& in, const Check_naming& naming = {},
    std::vector<std::uint32_t>* corner_halfedges = nullptr);

/// Marks a vertex no face uses in used_vertex_ranks.
constexpr std::uint32_t kUnusedVertex = 0xffffffffu;

/// Each vertex's index among the vertices a face uses (kUnusedVertex for
/// the others); `used` gets their number. The numbering build_mesh,
/// drop_isolated_vertices and a fast level from buffers give the vertices.
std::vector<std::uint32_t> used_vertex_ranks(const Mesh_buffers& in,
                                             std::uint32_t& used);

/// `in`'s tags numbered as drop_isolated_vertices numbers the vertices
/// (creases and corners on a vertex no face uses dropped; holes as they
/// are).
Mesh_tags tags_without_isolated_vertices(const Mesh_buffers& in);

/// Copy of `in` without the vertices no face uses; the others keep their
/// relative order. Returns `in` itself (moved, not copied, when passed as an
/// rvalue) when all are used. Precondition: check_buffers(in) succeeded.
/// control_edges and the tags' creases and corners are remapped, and those
/// touching a dropped vertex are removed.
Mesh_buffers drop_isolated_vertices(Mesh_buffers in);

}  // namespace subdivlab::detail
