// STL in and out. Owner of stl_io.h.
//
// Written by hand rather than with CGAL's STL reader (CGAL/IO/STL.h): that
// one decides ASCII or binary by the first word "solid" (which some binary
// headers start with too), reports failure as a bare false, and reads
// through std::istream; this one keeps read_mesh's promises.

#include "stl_io.h"

#include <fast_float/fast_float.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "file_kind.h"
#include "mesh_check.h"
#include "orientation_repair.h"
#include "parse_failure.h"
#include "text_writer.h"

namespace subdivlab::detail {
namespace {

constexpr std::size_t header_bytes = 80, record_bytes = 50;

std::uint32_t le32(const char* p) {
  const auto* b = reinterpret_cast<const unsigned char*>(p);
  return std::uint32_t{b[0]} | std::uint32_t{b[1]} << 8 |
         std::uint32_t{b[2]} << 16 | std::uint32_t{b[3]} << 24;
}

float le_float(const char* p) {
  const std::uint32_t bits = le32(p);
  float f;
  std::memcpy(&f, &bits, 4);
  return f;
}

/// Joins corners at exactly equal coordinates (+0 and -0 alike) into one
/// vertex, in order of first appearance.
class Welder {
 public:
  explicit Welder(Mesh_buffers& mesh) : mesh_(mesh) {}

  std::uint32_t vertex(const double p[3]) {
    Key k;
    for (int a = 0; a < 3; ++a) {
      const double c = p[a] == 0 ? 0.0 : p[a];  // -0 -> +0
      std::memcpy(&k.bits[a], &c, 8);
    }
    const auto [it, added] =
        index_.try_emplace(k, static_cast<std::uint32_t>(mesh_.vertex_count()));
    if (added) mesh_.positions.insert(mesh_.positions.end(), p, p + 3);
    return it->second;
  }

 private:
  struct Key {
    std::uint64_t bits[3];
    bool operator==(const Key& o) const {
      return bits[0] == o.bits[0] && bits[1] == o.bits[1] &&
             bits[2] == o.bits[2];
    }
  };
  struct Hash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = k.bits[0] * 0x9E3779B97F4A7C15ull;
      h ^= k.bits[1] + 0x7F4A7C159E3779B9ull + (h << 6) + (h >> 2);
      h ^= k.bits[2] + 0x94D049BB133111EBull + (h << 6) + (h >> 2);
      return static_cast<std::size_t>(h ^ (h >> 31));
    }
  };
  Mesh_buffers& mesh_;
  std::unordered_map<Key, std::uint32_t, Hash> index_;
};

/// Adds a polygon of welded corners, or counts it as degenerate (two
/// corners at one point) and leaves it out.
void add_face(Mesh_buffers& mesh, const std::uint32_t* corners, std::size_t k,
              std::size_t& dropped) {
  for (std::size_t i = 0; i < k; ++i) {
    for (std::size_t j = i + 1; j < k; ++j) {
      if (corners[i] == corners[j]) {
        ++dropped;
        return;
      }
    }
  }
  mesh.face_indices.insert(mesh.face_indices.end(), corners, corners + k);
  mesh.face_sizes.push_back(static_cast<std::uint32_t>(k));
}

std::string dropped_note(std::size_t dropped) {
  return std::to_string(dropped) +
         (dropped == 1 ? " degenerate triangle" : " degenerate triangles") +
         " (two corners at the same point) dropped";
}

Result<Mesh_buffers> read_binary(std::string_view bytes,
                                 std::vector<std::uint32_t>* corner_halfedges,
                                 const Read_options& options) {
  const std::uint32_t n = le32(bytes.data() + header_bytes);
  Mesh_buffers mesh;
  // is_binary_stl checked that the file holds the n records.
  mesh.face_sizes.reserve(n);
  mesh.face_indices.reserve(3 * static_cast<std::size_t>(n));
  Welder weld(mesh);
  std::size_t dropped = 0;
  for (std::uint32_t t = 0; t < n; ++t) {
    const std::size_t at = header_bytes + 4 + t * record_bytes;
    const char* rec = bytes.data() + at;
    std::uint32_t corners[3];
    for (int c = 0; c < 3; ++c) {
      double p[3];
      for (int a = 0; a < 3; ++a) {
        p[a] = le_float(rec + 12 + 12 * c + 4 * a);
        if (!std::isfinite(p[a]))
          return parse_failure(
              0, "byte " + std::to_string(at + 12 + 12 * c + 4 * a) +
                     ": corner " + std::to_string(c + 1) + " of triangle " +
                     std::to_string(t) + " (of " + std::to_string(n) +
                     ") has a coordinate that is not a finite number");
      }
      corners[c] = weld.vertex(p);
    }
    add_face(mesh, corners, 3, dropped);
  }
  Result<Mesh_buffers> r = finish_read(std::move(mesh), {}, corner_halfedges,
                                       options.repair_orientation);
  if (r.ok() && dropped > 0)
    r.value.tags.notes.push_back(dropped_note(dropped));
  return r;
}

/// The words of an ASCII STL with their lines.
class Word_reader {
 public:
  explicit Word_reader(std::string_view text) : text_(text) {}

  /// Next word, or an empty view at the end.
  std::string_view next() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\n') ++line_;
      if (c != ' ' && c != '\t' && c != '\r' && c != '\n' && c != '\f' &&
          c != '\v')
        break;
      ++pos_;
    }
    line_of_word_ = line_;
    const std::size_t b = pos_;
    while (pos_ < text_.size() && text_[pos_] != ' ' && text_[pos_] != '\t' &&
           text_[pos_] != '\r' && text_[pos_] != '\n')
      ++pos_;
    return text_.substr(b, pos_ - b);
  }

  /// Skips the rest of the current line (a solid's name).
  void skip_line() {
    while (pos_ < text_.size() && text_[pos_] != '\n' && text_[pos_] != '\r')
      ++pos_;
  }

  int line() const { return line_of_word_; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  int line_ = 1;
  int line_of_word_ = 1;
};

Result<Mesh_buffers> read_ascii(std::string_view text,
                                std::vector<std::uint32_t>* corner_halfedges,
                                const Read_options& options) {
  Word_reader in(text);
  Mesh_buffers mesh;
  std::vector<int> face_lines;
  Welder weld(mesh);
  std::size_t dropped = 0;
  const auto expect = [&](std::string_view want, std::string_view where) {
    const std::string_view w = in.next();
    if (w == want) return Result<Mesh_buffers>{};
    return parse_failure(
        in.line(),
        "expected '" + std::string(want) + "' " + std::string(where) +
            ", not " +
            (w.empty() ? std::string("the end of the file") : quoted(w)));
  };
  std::string_view word = in.next();
  if (word != "solid")
    return parse_failure(
        in.line(),
        "an ASCII STL file starts with 'solid', not " + quoted(word));
  in.skip_line();
  std::vector<std::uint32_t> corners;
  for (;;) {
    word = in.next();
    if (word == "endsolid") {
      in.skip_line();
      word = in.next();
      if (word.empty()) break;
      if (word != "solid")
        return parse_failure(in.line(),
                             "expected 'solid' or the end of the file after "
                             "'endsolid', not " +
                                 quoted(word));
      in.skip_line();
      continue;
    }
    if (word != "facet")
      return parse_failure(in.line(),
                           "expected 'facet' or 'endsolid', not " +
                               (word.empty() ? std::string("the end of the "
                                                           "file")
                                             : quoted(word)));
    const int facet_line = in.line();
    Result<Mesh_buffers> r = expect("normal", "after 'facet'");
    if (!r.ok()) return r;
    // The normal is read to move past it and checked to be numbers; the
    // corner order gives the orientation.
    for (int a = 0; a < 3; ++a) {
      const std::string_view w = in.next();
      double v;
      const auto [end, ec] =
          fast_float::from_chars(w.data(), w.data() + w.size(), v);
      if (w.empty() || ec != std::errc() || end != w.data() + w.size())
        return parse_failure(
            in.line(), "the facet normal's " + std::string(1, "xyz"[a]) +
                           " is " +
                           (w.empty() ? std::string("missing") : quoted(w)) +
                           ", not a number");
    }
    r = expect("outer", "after the facet normal");
    if (!r.ok()) return r;
    r = expect("loop", "after 'outer'");
    if (!r.ok()) return r;
    corners.clear();
    for (;;) {
      word = in.next();
      if (word == "endloop") break;
      if (word != "vertex")
        return parse_failure(in.line(),
                             "expected 'vertex' or 'endloop', not " +
                                 (word.empty() ? std::string("the end of "
                                                             "the file")
                                               : quoted(word)));
      double p[3];
      for (int a = 0; a < 3; ++a) {
        const std::string_view w = in.next();
        const char* b = w.data();
        if (!w.empty() && *b == '+') ++b;
        const auto [end, ec] =
            fast_float::from_chars(b, w.data() + w.size(), p[a]);
        if (w.empty() || ec != std::errc() || end != w.data() + w.size())
          return parse_failure(
              in.line(), std::string("the vertex's ") + "xyz"[a] + " is " +
                             (w.empty() ? std::string("missing") : quoted(w)) +
                             ", not a number");
        if (!std::isfinite(p[a]))
          return parse_failure(in.line(), std::string("the vertex's ") +
                                              "xyz"[a] +
                                              " is not finite: " + quoted(w));
      }
      corners.push_back(weld.vertex(p));
    }
    if (corners.size() < 3)
      return parse_failure(facet_line, "the facet has " +
                                           std::to_string(corners.size()) +
                                           " vertices; a triangle has 3");
    r = expect("endfacet", "after 'endloop'");
    if (!r.ok()) return r;
    const std::size_t before = dropped;
    add_face(mesh, corners.data(), corners.size(), dropped);
    if (dropped == before) face_lines.push_back(facet_line);
  }
  Check_naming naming;
  naming.face_lines = &face_lines;
  Result<Mesh_buffers> r = finish_read(
      std::move(mesh), naming, corner_halfedges, options.repair_orientation);
  if (r.ok() && dropped > 0)
    r.value.tags.notes.push_back(dropped_note(dropped));
  return r;
}

void put_le32(std::uint32_t x, char* p) {
  for (int i = 0; i < 4; ++i) p[i] = static_cast<char>(x >> (8 * i) & 0xFF);
}

void put_float(double x, char* p) {
  const auto f = static_cast<float>(x);
  std::uint32_t bits;
  std::memcpy(&bits, &f, 4);
  put_le32(bits, p);
}

}  // namespace

bool is_binary_stl(std::string_view bytes) {
  if (bytes.size() < header_bytes + 4) return false;
  const std::uint64_t n = le32(bytes.data() + header_bytes);
  return bytes.size() == header_bytes + 4 + n * record_bytes;
}

Result<Mesh_buffers> read_stl(std::string_view bytes,
                              std::vector<std::uint32_t>* corner_halfedges,
                              const Read_options& options) {
  if (is_binary_stl(bytes))
    return read_binary(bytes, corner_halfedges, options);
  const std::size_t first = bytes.find_first_not_of(" \t\r\n");
  if (first != std::string_view::npos && bytes.substr(first, 5) == "solid")
    return read_ascii(bytes, corner_halfedges, options);
  if (bytes.size() < header_bytes + 4)
    return parse_failure(
        0, "the file has " + std::to_string(bytes.size()) +
               " bytes: too short for a binary STL (84 bytes and "
               "more) and it does not start with 'solid' (ASCII STL)");
  const std::uint64_t n = le32(bytes.data() + header_bytes);
  return parse_failure(
      0, "byte 80: a binary STL of " + std::to_string(n) +
             " triangles has 84 + 50 \u00d7 " + std::to_string(n) + " = " +
             std::to_string(84 + 50 * n) + " bytes, but the file has " +
             std::to_string(bytes.size()) + " (cut short, or not an STL file)");
}

bool write_stl_chunks(const Mesh_buffers& mesh, std::size_t max_chunk_bytes,
                      const Chunk_sink& sink, std::string_view comment) {
  Chunk_writer out(std::max(max_chunk_bytes, min_chunk_bytes), sink);
  char header[header_bytes + 4];
  std::memset(header, ' ', header_bytes);
  std::string text(comment.empty() ? "SubdivLab binary STL" : comment);
  // A header starting with "solid" would make readers that go by the first
  // word take the file for ASCII.
  if (text.rfind("solid", 0) == 0) text = "SubdivLab " + text;
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  std::memcpy(header, text.data(), std::min(text.size(), header_bytes));
  std::uint64_t triangles = 0;
  for (const std::uint32_t k : mesh.face_sizes) triangles += k >= 3 ? k - 2 : 0;
  put_le32(static_cast<std::uint32_t>(triangles), header + header_bytes);
  out.put(std::string_view(header, sizeof header));
  const std::uint32_t* index = mesh.face_indices.data();
  const double* p = mesh.positions.data();
  char rec[record_bytes];
  for (std::size_t f = 0; f < mesh.face_count() && out.ok(); ++f) {
    const std::uint32_t k = mesh.face_sizes[f];
    for (std::uint32_t i = 1; i + 1 < k; ++i) {
      const double* c[3] = {p + 3 * index[0], p + 3 * index[i],
                            p + 3 * index[i + 1]};
      const double u[3] = {c[1][0] - c[0][0], c[1][1] - c[0][1],
                           c[1][2] - c[0][2]};
      const double v[3] = {c[2][0] - c[0][0], c[2][1] - c[0][1],
                           c[2][2] - c[0][2]};
      double nrm[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                       u[0] * v[1] - u[1] * v[0]};
      const double len =
          std::sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
      for (double& x : nrm) x = len > 0 ? x / len : 0;
      for (int a = 0; a < 3; ++a) put_float(nrm[a], rec + 4 * a);
      for (int j = 0; j < 3; ++j)
        for (int a = 0; a < 3; ++a)
          put_float(c[j][a], rec + 12 + 12 * j + 4 * a);
      rec[48] = rec[49] = 0;
      out.put(std::string_view(rec, record_bytes));
    }
    index += k;
  }
  return out.finish();
}

}  // namespace subdivlab::detail
