// PLY in and out. Owner: ply_io.cpp; read_mesh and write_mesh_chunks
// (mesh_io.h) dispatch here.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "mesh_io.h"
#include "mesh_types.h"

namespace subdivlab::detail {

/// A PLY file (ascii, binary_little_endian or binary_big_endian 1.0): the
/// vertex element's x, y, z (any numeric type) and the face element's
/// vertex_indices (or vertex_index) list (any integer count and index
/// types); every other property and element (lists too) skipped, comments
/// and obj_info ignored. The header's counts are trusted only as far as the
/// data backs them. Errors: header problems on their line; ASCII data on
/// the line of the element; binary data by byte offset and element number.
/// Then read_mesh's checks (faces named by line in ASCII, by number in
/// binary).
Result<Mesh_buffers> read_ply(std::string_view bytes,
                              std::vector<std::uint32_t>* corner_halfedges,
                              const Read_options& options);

/// ASCII PLY of `mesh` (see write_mesh).
bool write_ply_chunks(const Mesh_buffers& mesh, std::size_t max_chunk_bytes,
                      const Chunk_sink& sink, std::string_view comment);

}  // namespace subdivlab::detail
