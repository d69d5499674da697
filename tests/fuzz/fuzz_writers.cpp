// The writers: what the readers accept (format told by detect_format), under
// a size cap, written as OFF, OBJ, PLY and STL with a comment the last byte
// picks, then read back. What the headers promise:
//   - write_mesh_chunks hands over write_mesh's bytes in pieces of at most
//     the bound, and stops when the sink says so;
//   - detect_format tells each written file's format;
//   - OFF, OBJ and PLY read back to the same mesh: coordinates exactly
//     (17 digits), faces, and for OFF and OBJ the tags;
//   - STL (binary, floats, polygons as fans from their first corner, no
//     tags) reads back to that: the fans' corners at float precision,
//     welded where equal, triangles with two corners at one point dropped,
//     unused vertices dropped; accepted exactly when that is a valid mesh.

#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "core/mesh_check.h"
#include "fuzz_targets.h"

namespace subdivlab::fuzz {
namespace {

constexpr std::size_t kMaxCorners = 4096;

constexpr const char* kComments[] = {
    "",
    "fuzz",
    "two\nlines",
    "solid in the header",
    "end_header",
    "a\rb",
    "OFF",
    "v 1 2 3",
    "ply",
    "\xc3\xa9t\xc3\xa9",
    ("xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx"
     "xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx")};

/// The mesh an STL of `mesh` reads back as, or false when STL's floats
/// cannot hold its coordinates.
bool stl_expectation(const Mesh_buffers& mesh, Mesh_buffers& out) {
  std::map<std::tuple<float, float, float>, std::uint32_t> welded;
  std::vector<std::uint32_t> vertex_of(mesh.vertex_count());
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
    for (int a = 0; a < 3; ++a)
      if (!(std::fabs(mesh.positions[3 * v + a]) <=
            std::numeric_limits<float>::max()))
        return false;
  std::size_t at = 0;
  const auto weld = [&](std::uint32_t v) {
    float p[3];
    for (int a = 0; a < 3; ++a)
      p[a] = static_cast<float>(mesh.positions[3 * v + a]);
    // +0 and -0 weld; the first corner's sign stays.
    const auto key =
        std::make_tuple(p[0] == 0 ? 0.0f : p[0], p[1] == 0 ? 0.0f : p[1],
                        p[2] == 0 ? 0.0f : p[2]);
    const auto [it, added] =
        welded.try_emplace(key, static_cast<std::uint32_t>(out.vertex_count()));
    if (added)
      for (int a = 0; a < 3; ++a) out.positions.push_back(p[a]);
    return it->second;
  };
  for (const std::uint32_t k : mesh.face_sizes) {
    for (std::uint32_t i = 1; i + 1 < k; ++i) {
      const std::uint32_t c[3] = {weld(mesh.face_indices[at]),
                                  weld(mesh.face_indices[at + i]),
                                  weld(mesh.face_indices[at + i + 1])};
      if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2]) continue;
      out.face_sizes.push_back(3);
      out.face_indices.insert(out.face_indices.end(), c, c + 3);
    }
    at += k;
  }
  return true;
}

void check_format(const Mesh_buffers& mesh, Mesh_format format,
                  std::string_view comment) {
  const std::string name = format_name(format);
  const std::string text = write_mesh(mesh, format, comment);
  // In pieces: the same bytes, none over the bound; a sink that stops.
  for (const std::size_t bound : {std::size_t{1}, std::size_t{97}}) {
    std::string joined;
    bool small = true;
    write_mesh_chunks(
        mesh, format, bound,
        [&](std::string_view piece) {
          small = small && piece.size() <= std::max(bound, min_chunk_bytes);
          joined.append(piece);
          return true;
        },
        comment);
    require(joined == text, "write_mesh_chunks differs from write_mesh",
            name + " in pieces of " + std::to_string(bound) + ": " +
                std::to_string(joined.size()) + " bytes, not " +
                std::to_string(text.size()));
    require(small, "write_mesh_chunks hands over a piece over its bound",
            name + " in pieces of " + std::to_string(bound));
  }
  if (text.size() > min_chunk_bytes) {
    int calls = 0;
    const bool finished = write_mesh_chunks(
        mesh, format, min_chunk_bytes,
        [&](std::string_view) {
          ++calls;
          return false;
        },
        comment);
    require(!finished && calls == 1, "a sink's false does not stop writing",
            name);
  }
  const Result<Mesh_format> detected = detect_format(text);
  require(detected.ok() && detected.value == format,
          "detect_format does not tell a written file's format",
          name + ": " + detected.status.message);
  const Result<Mesh_buffers> back = read_mesh(text, format);
  require_sane_status(back.status, "read_mesh of a written file");
  if (format != Mesh_format::stl) {
    require(back.ok(), "a written file does not read back",
            name + ": " + back.status.message);
    require(back.value.positions == mesh.positions &&
                back.value.face_sizes == mesh.face_sizes &&
                back.value.face_indices == mesh.face_indices,
            "a written file reads back to another mesh", name);
    if (format != Mesh_format::ply)
      require(same_tags(back.value.tags, mesh.tags),
              "a written file reads back with other tags", name);
    return;
  }
  Mesh_buffers expected;
  if (!stl_expectation(mesh, expected)) return;
  const bool valid = detail::check_buffers(expected).status.ok();
  require(back.ok() == valid,
          valid ? "an STL file of a valid mesh does not read back"
                : "an STL file of an invalid mesh reads back",
          back.status.message);
  if (!valid) return;
  expected = detail::drop_isolated_vertices(std::move(expected));
  require(back.value.positions == expected.positions &&
              back.value.face_sizes == expected.face_sizes &&
              back.value.face_indices == expected.face_indices,
          "an STL file reads back to another mesh than its fans");
}

}  // namespace

void fuzz_writers(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider bytes(data, size);
  const std::uint8_t pick = bytes.ConsumeIntegral<std::uint8_t>();
  const std::string text = bytes.ConsumeRemainingBytesAsString();
  Mesh_buffers mesh;
  if (!read_any(text, mesh) || mesh.face_indices.size() > kMaxCorners) return;
  require(check_writable(mesh).ok(), "check_writable refuses a read mesh");
  const char* comment = kComments[pick % std::size(kComments)];
  for (const Mesh_format format :
       {Mesh_format::off, Mesh_format::obj, Mesh_format::ply, Mesh_format::stl})
    check_format(mesh, format, comment);
}

}  // namespace subdivlab::fuzz
