// Reading and writing OFF and OBJ text. Owner: mesh_io.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "mesh_types.h"

namespace subdivlab {

enum class Mesh_format { off, obj };

/// Parses OFF (OFF, COFF, NOFF, CNOFF, STOFF ... variants, comments, colours)
/// or OBJ text into buffers, then checks that the result is a valid oriented
/// 2-manifold polygon mesh (see build_mesh). Never throws; never allocates
/// more than the data in `text` backs, whatever counts a header declares.
/// Errors name the problem and, where it applies, the 1-based line.
/// Syntax errors are parse_error; index, face-size and manifold problems are
/// invalid_mesh. Vertices no face uses are dropped, as build_mesh drops them.
/// OpenSubdiv's tag lines ("t crease 2/1/0 0 1 2.5", indices from 0; in OFF
/// as comments "# t ..." after the faces) are checked and kept in
/// Mesh_buffers::tags; a malformed one is a parse_error on its line, even
/// where the check needs the whole mesh (a crease that is not an edge), and
/// a well-formed one the product does not apply leaves a note.
/// With `corner_halfedges`, also each corner's halfedge as the checks
/// number it (mesh_check.h), for build_checked_mesh.
Result<Mesh_buffers> read_mesh(
    std::string_view text, Mesh_format format,
    std::vector<std::uint32_t>* corner_halfedges = nullptr);

namespace detail {
/// read_mesh with the fast path off: every data line split into tokens and
/// read by the general path, the reference the fast path must agree with
/// (same buffers, same messages and lines). For the tests.
Result<Mesh_buffers> read_mesh_general(
    std::string_view text, Mesh_format format,
    std::vector<std::uint32_t>* corner_halfedges = nullptr);
}  // namespace detail

/// Whether write_mesh can write `mesh` so that read_mesh takes it back:
/// positions in threes and finite, face sizes that add up to the indices,
/// every index naming a vertex, and tags that read back (sizes that match,
/// indices in range, sharpness finite and 0 or more, creases on edges).
/// O(n) (it does not check manifoldness), allocating only to look creases up
/// among the edges, for buffers from outside the core. Fails with
/// invalid_mesh.
Status check_writable(const Mesh_buffers& mesh);

/// Takes one piece of written text; returns false to stop the writing.
using Chunk_sink = std::function<bool(std::string_view)>;

/// Smallest chunk write_mesh_chunks makes room for (a smaller bound is
/// raised to it).
constexpr std::size_t min_chunk_bytes = 64;

/// OFF / OBJ text of the mesh, handed to `sink` in consecutive pieces of at
/// most max(max_chunk_bytes, min_chunk_bytes) bytes (a piece may end inside
/// a line; the pieces joined are write_mesh's text), so that a text larger
/// than any one string or buffer can be saved. Returns false if the sink
/// stopped it. Precondition: check_writable(mesh) succeeds.
bool write_mesh_chunks(const Mesh_buffers& mesh, Mesh_format format,
                       std::size_t max_chunk_bytes, const Chunk_sink& sink);

/// OFF / OBJ text of the mesh. Coordinates are written as printf's "%.17g"
/// writes them (17 significant digits) so that reading the text back gives
/// the same doubles. Tags follow the faces as tag lines (OFF: "# t ..."
/// comments), sharpness in the fewest digits that give the same float; a
/// mesh without tags is written as before tags existed.
/// Precondition: check_writable(mesh) succeeds (else it reads past the
/// index array).
std::string write_mesh(const Mesh_buffers& mesh, Mesh_format format);

}  // namespace subdivlab
