// Reading and writing OFF, OBJ, PLY and STL. Owner: mesh_io.cpp (OFF, OBJ
// and the dispatch); ply_io.cpp and stl_io.cpp read and write their formats.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "mesh_types.h"

namespace subdivlab {

enum class Mesh_format { off, obj, ply, stl };

/// Choices for read_mesh.
struct Read_options {
  /// When faces are turned inconsistently on an orientable surface (the
  /// error inconsistent_orientation), turn them to agree (CGAL's
  /// orient_polygon_soup, fewest faces reversed) and leave a note; a
  /// non-orientable surface is still refused.
  bool repair_orientation = false;
};

/// Parses OFF (OFF, COFF, NOFF, CNOFF, STOFF ... variants, comments, colours),
/// OBJ, PLY (ASCII and binary, ply_io.h) or STL (ASCII and binary, corners
/// welded, stl_io.h) into buffers, then checks that the result is a valid
/// oriented 2-manifold polygon mesh (see build_mesh). Never throws; never
/// allocates more than the data in `text` backs, whatever counts a header
/// declares. Errors name the problem and, where it applies, the 1-based line
/// (binary files: the byte offset and element in the message, line 0). Whatever
/// the format, a file that is something else altogether (PNG, JPEG, GIF, PDF,
/// ZIP, glTF, gzip; file_kind.h) is a parse_error saying what it is. Syntax
/// errors are parse_error; index, face-size and manifold problems are
/// invalid_mesh. Vertices no face uses are dropped, as build_mesh drops them.
/// OpenSubdiv's tag lines ("t crease 2/1/0 0 1 2.5", indices from 0; in OFF
/// as comments "# t ..." after the faces) are checked and kept in
/// Mesh_buffers::tags; a malformed one is a parse_error on its line, even
/// where the check needs the whole mesh (a crease that is not an edge), and
/// a well-formed one the product does not apply leaves a note.
/// With `corner_halfedges`, also each corner's halfedge as the checks
/// number it (mesh_check.h), for build_checked_mesh.
/// Faces turned inconsistently are inconsistent_orientation (repaired with
/// options.repair_orientation), a non-orientable surface invalid_mesh.
Result<Mesh_buffers> read_mesh(
    std::string_view text, Mesh_format format,
    std::vector<std::uint32_t>* corner_halfedges = nullptr,
    const Read_options& options = {});

/// The format of a file from its first bytes: "ply", an OFF header, "solid"
/// followed by "facet" (ASCII STL), a size of 84 + 50 n bytes with n in
/// bytes 80..83 (binary STL), else OBJ statements. Fails (parse_error) with
/// what the file is when it is a known non-mesh (file_kind.h), or with the
/// formats read when it is none of these.
Result<Mesh_format> detect_format(std::string_view bytes);

/// Lower-case name of a format ("off", "obj", "ply", "stl").
const char* format_name(Mesh_format format);

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

/// The file of the mesh (OFF / OBJ / PLY text, binary STL), handed to
/// `sink` in consecutive pieces of at most max(max_chunk_bytes,
/// min_chunk_bytes) bytes (a piece may end inside a line; the pieces joined
/// are write_mesh's bytes), so that a file larger than any one string or
/// buffer can be saved. A non-empty `comment` (one line; line breaks become
/// spaces) goes in as a comment: "# ..." after OFF's first line or first in
/// OBJ, "comment ..." in PLY's header, the 80-byte header of STL (cut to
/// fit). Returns false if the sink stopped it. Precondition:
/// check_writable(mesh) succeeds.
bool write_mesh_chunks(const Mesh_buffers& mesh, Mesh_format format,
                       std::size_t max_chunk_bytes, const Chunk_sink& sink,
                       std::string_view comment = {});

/// OFF / OBJ text of the mesh. Coordinates are written as printf's "%.17g"
/// writes them (17 significant digits) so that reading the text back gives
/// the same doubles. Tags follow the faces as tag lines (OFF: "# t ..."
/// comments), sharpness in the fewest digits that give the same float; a
/// mesh without tags is written as before tags existed.
/// Precondition: check_writable(mesh) succeeds (else it reads past the
/// index array).
/// PLY is written as ASCII (vertex x y z as doubles, face vertex_indices
/// as a uchar/uint list); STL as binary, polygons split into fans from
/// their first corner, each facet with its unit normal, coordinates as
/// floats (STL has no others), tags not written.
std::string write_mesh(const Mesh_buffers& mesh, Mesh_format format,
                       std::string_view comment = {});

}  // namespace subdivlab
