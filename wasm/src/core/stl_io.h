// STL in and out. Owner: stl_io.cpp; read_mesh and write_mesh_chunks
// (mesh_io.h) dispatch here.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "mesh_io.h"
#include "mesh_types.h"

namespace subdivlab::detail {

/// Whether `bytes` has the size of a binary STL: 84 + 50 n bytes, n the
/// little-endian uint32 at byte 80. Binary files whose header starts with
/// "solid" exist, so this, not the first word, tells the two apart.
bool is_binary_stl(std::string_view bytes);

/// An STL file, ASCII ("solid ... facet normal ... outer loop vertex ...
/// endloop endfacet ... endsolid", several solids allowed) or binary (see
/// is_binary_stl). STL stores each triangle's corners: corners with exactly
/// equal coordinates become one vertex (the first one's place), in order of
/// first appearance. A triangle with two corners at one point after that
/// (no area, an edge of length 0) is dropped with a note: CAD exports often
/// hold such slivers, and dropping one joins its two long sides' neighbours
/// as they meet. The facet normals are ignored (the corner order gives the
/// orientation). Errors on their line (ASCII) or by triangle and byte
/// offset (binary); then read_mesh's checks.
Result<Mesh_buffers> read_stl(std::string_view bytes,
                              std::vector<std::uint32_t>* corner_halfedges,
                              const Read_options& options);

/// Binary STL of `mesh` (see write_mesh).
bool write_stl_chunks(const Mesh_buffers& mesh, std::size_t max_chunk_bytes,
                      const Chunk_sink& sink, std::string_view comment);

}  // namespace subdivlab::detail
