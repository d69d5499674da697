// The fuzz targets of tests/fuzz and what they share: each takes the bytes
// libFuzzer hands it, calls the core as the bindings and the CLI do, and
// stops the program (fuzz_fail: a message, then a trap libFuzzer reports
// with the input) when the core breaks a promise its headers make.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/mesh_io.h"
#include "core/mesh_types.h"
#include "core/subdivide.h"

namespace subdivlab::fuzz {

/// OFF, OBJ, PLY and STL readers (fuzz_readers.cpp).
void fuzz_off(const std::uint8_t* data, std::size_t size);
void fuzz_obj(const std::uint8_t* data, std::size_t size);
void fuzz_ply(const std::uint8_t* data, std::size_t size);
void fuzz_stl(const std::uint8_t* data, std::size_t size);
/// build_mesh and its checks on buffers made from the bytes (fuzz_build.cpp).
void fuzz_build(const std::uint8_t* data, std::size_t size);
/// Every scheme at levels 1-2 on what the readers accept (fuzz_schemes.cpp).
void fuzz_schemes(const std::uint8_t* data, std::size_t size);
/// Custom rule sets from the bytes, on the four hosts (fuzz_rules.cpp).
void fuzz_rules(const std::uint8_t* data, std::size_t size);
/// Write in every format, read back, same mesh (fuzz_writers.cpp).
void fuzz_writers(const std::uint8_t* data, std::size_t size);

/// Prints "fuzz finding: `what`" (and `detail`) and traps.
[[noreturn]] void fuzz_fail(const std::string& what,
                            const std::string& detail = {});

/// fuzz_fail(what) unless `condition`.
inline void require(bool condition, const char* what,
                    const std::string& detail = {}) {
  if (!condition) fuzz_fail(what, detail);
}

/// A status a core function may return for any input: anything but
/// internal_error (the core caught what it should not have met), with a
/// message on one line (the CLI prints it so) when it is not ok.
void require_sane_status(const Status& s, const char* where);

/// Same vertices (coordinates exactly), faces and tags (notes aside).
bool same_mesh(const Mesh_buffers& a, const Mesh_buffers& b);

/// Same tags, notes aside.
bool same_tags(const Mesh_tags& a, const Mesh_tags& b);

/// Both Surface_meshes hold the same elements, numbered alike.
bool same_surface_mesh(const Mesh& a, const Mesh& b);

/// The mesh read_mesh gives for `bytes`, the format told by detect_format
/// as the app's "auto" does; false when it is refused. The status must be
/// sane either way.
bool read_any(std::string_view bytes, Mesh_buffers& mesh);

/// What a valid mesh from the core must be: the checks pass (check_buffers,
/// check_writable), build_mesh builds it, CGAL finds it a valid polygon
/// mesh, every coordinate finite and every vertex used; its render arrays
/// (render_buffers.h) are those of its faces, checked against a map.
void require_valid_mesh(const Mesh_buffers& mesh, const char* what);

/// Results of two runs that should agree: same faces and control edges (as
/// sets of vertex pairs), points within 1e-9 of `a`'s largest coordinate.
bool same_result(const Mesh_buffers& a, const Mesh_buffers& b);

/// What a result `out` of subdivide_mesh(in, o) must be: a valid mesh
/// (require_valid_mesh) with predict_size's counts, each control edge an
/// edge of it.
void require_result(const Mesh_buffers& in, const Subdivide_options& o,
                    const Mesh_buffers& out, const std::string& what);

}  // namespace subdivlab::fuzz
