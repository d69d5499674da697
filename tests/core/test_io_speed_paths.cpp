// The fast paths of mesh_io.cpp against their references: numbers written
// exactly as printf("%.17g") writes them, numbers read exactly as strtod
// reads them, lines the fast reader hands to the general one (same values,
// same messages and line numbers), and chunked writing that joins up to
// write_mesh's text with no chunk over its bound.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/mesh_io.h"

namespace subdivlab {
namespace {

std::string printf_g17(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

/// A mesh with these coordinates (padded to whole vertices) and one face.
Mesh_buffers mesh_of(std::vector<double> xs) {
  while (xs.size() % 3 != 0 || xs.size() < 9) xs.push_back(0);
  Mesh_buffers m;
  m.positions = std::move(xs);
  m.face_sizes = {3};
  m.face_indices = {0, 1, 2};
  return m;
}

/// The OFF text of mesh_of(xs) with every coordinate written by snprintf.
std::string expected_off(const Mesh_buffers& m) {
  std::string s = "OFF\n" + std::to_string(m.vertex_count()) + " 1 0\n";
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    s += printf_g17(m.positions[3 * v]) + " " +
         printf_g17(m.positions[3 * v + 1]) + " " +
         printf_g17(m.positions[3 * v + 2]) + "\n";
  }
  return s + "3 0 1 2\n";
}

/// Doubles of every kind the writer's exact path and its fallback meet:
/// random bit patterns, mesh-sized values, short binary fractions (ties at
/// the 17th digit, e.g. 1 + 2^-17 = 1.00000762939453125) and the neighbours
/// of powers of ten (where the decimal exponent changes).
std::vector<double> awkward_doubles(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::vector<double> xs = {0.0,
                            -0.0,
                            1.0,
                            0.1,
                            1e-5,
                            9.9999999999999995e-6,
                            1e16,
                            1e17,
                            99999999999999999.0,
                            5e-324,
                            std::numeric_limits<double>::max(),
                            std::numeric_limits<double>::min(),
                            1.00000762939453125,
                            2.5,
                            0.125};
  while (xs.size() < n) {
    std::uint64_t bits = rng();
    double x = 0;
    std::memcpy(&x, &bits, sizeof x);
    if (std::isfinite(x)) xs.push_back(x);
    xs.push_back(std::ldexp(static_cast<double>(rng() >> 11),
                            -static_cast<int>(rng() % 100)));
    xs.push_back((rng() & 1 ? -1 : 1) *
                 std::ldexp(static_cast<double>(rng() % 4096),
                            -static_cast<int>(rng() % 30)));
    const double unit = static_cast<double>(rng() >> 11) / 9007199254740992.0;
    xs.push_back((unit - 0.5) *
                 std::pow(10.0, static_cast<int>(rng() % 40) - 20));
    const double p = std::pow(10.0, static_cast<int>(rng() % 44) - 22);
    xs.push_back(std::nextafter(p, 0.0));
    xs.push_back(std::nextafter(p, 1e300));
  }
  return xs;
}

TEST(IoSpeedPaths, CoordinatesAreWrittenExactlyAsPrintfWritesThem) {
  const Mesh_buffers m = mesh_of(awkward_doubles(300000, 7));
  const std::string text = write_mesh(m, Mesh_format::off);
  const std::string expected = expected_off(m);
  ASSERT_EQ(text.size(), expected.size());
  if (text != expected) {
    std::size_t i = 0;
    while (text[i] == expected[i]) ++i;
    const std::size_t from = i < 60 ? 0 : i - 60;
    FAIL() << "first difference at byte " << i << ":\n"
           << text.substr(from, 120) << "\nvs\n"
           << expected.substr(from, 120);
  }
}

TEST(IoSpeedPaths, ChunksJoinToTheTextAndNeverExceedTheirBound) {
  Mesh_buffers m = mesh_of(awkward_doubles(3000, 11));
  // A face far longer than any chunk: pieces end inside its line.
  m.face_sizes.push_back(static_cast<std::uint32_t>(m.vertex_count()));
  for (std::size_t v = 0; v < m.vertex_count(); ++v)
    m.face_indices.push_back(static_cast<std::uint32_t>(v));
  for (const Mesh_format format : {Mesh_format::off, Mesh_format::obj}) {
    const std::string whole = write_mesh(m, format);
    for (const std::size_t bound :
         {std::size_t{1}, std::size_t{64}, std::size_t{100}, std::size_t{4096},
          std::size_t{1} << 20}) {
      std::string joined;
      std::size_t pieces = 0, largest = 0;
      const bool done =
          write_mesh_chunks(m, format, bound, [&](std::string_view chunk) {
            EXPECT_FALSE(chunk.empty());
            joined.append(chunk);
            largest = std::max(largest, chunk.size());
            ++pieces;
            return true;
          });
      EXPECT_TRUE(done);
      EXPECT_EQ(joined, whole) << "bound " << bound;
      EXPECT_LE(largest, std::max(bound, min_chunk_bytes)) << "bound " << bound;
      if (bound < whole.size()) EXPECT_GT(pieces, 1u) << "bound " << bound;
    }
  }
}

TEST(IoSpeedPaths, ASinkThatSaysStopEndsTheWriting) {
  const Mesh_buffers m = mesh_of(awkward_doubles(30000, 3));
  std::size_t calls = 0;
  const bool done =
      write_mesh_chunks(m, Mesh_format::obj, 1000, [&](std::string_view) {
        ++calls;
        return calls < 3;
      });
  EXPECT_FALSE(done);
  EXPECT_EQ(calls, 3u);
}

/// A decimal number as people and programs write them: sign, digits,
/// point, exponent, in random lengths (up to 40 digits, past what a double
/// holds, so rounding matters).
std::string random_decimal(std::mt19937_64& rng) {
  std::string s;
  switch (rng() % 4) {
    case 0:
      s += '-';
      break;
    case 1:
      s += '+';
      break;
    default:
      break;
  }
  const auto digits = [&](std::size_t n) {
    for (std::size_t i = 0; i < n; ++i)
      s += static_cast<char>('0' + rng() % 10);
  };
  const std::size_t whole = rng() % 21, fraction = rng() % 21;
  digits(whole);
  if (fraction > 0 || whole == 0) {
    s += '.';
    digits(fraction == 0 ? 1 : fraction);
  }
  if (rng() % 3 == 0) {
    s += rng() % 2 ? 'e' : 'E';
    if (rng() % 2) s += rng() % 2 ? '-' : '+';
    s += std::to_string(rng() % 330);
  }
  return s;
}

TEST(IoSpeedPaths, CoordinatesAreReadExactlyAsStrtodReadsThem) {
  std::mt19937_64 rng(5);
  std::vector<std::string> tokens = {
      "4.9406564584124654e-324",
      "2.2250738585072011e-308",
      "-0",
      "-0.0e10",
      "1e-400",
      "0.1",
      "1.00000762939453125",
      "9007199254740993",
      "1797693134862315708145274237317043567981e269",
      "0."
      "000000000000000000000000000000000000000000000000000000000000000000000000"
      "000000001e80"};
  while (tokens.size() < 30000) {
    std::string t = random_decimal(rng);
    if (std::isfinite(std::strtod(t.c_str(), nullptr))) tokens.push_back(t);
  }
  while (tokens.size() % 3 != 0) tokens.push_back("0");
  for (const Mesh_format format : {Mesh_format::off, Mesh_format::obj}) {
    const std::size_t nv = tokens.size() / 3;
    std::string text = format == Mesh_format::off
                           ? "OFF\n" + std::to_string(nv) + " " +
                                 std::to_string(nv / 3) + " 0\n"
                           : "";
    for (std::size_t v = 0; v < nv; ++v) {
      text += (format == Mesh_format::obj ? "v " : "") + tokens[3 * v] + " " +
              tokens[3 * v + 1] + "\t" + tokens[3 * v + 2] + "\n";
    }
    for (std::size_t f = 0; f < nv / 3; ++f) {
      const std::size_t o = format == Mesh_format::obj ? 1 : 0;
      text += (format == Mesh_format::off ? "3 " : "f ") +
              std::to_string(3 * f + o) + " " + std::to_string(3 * f + 1 + o) +
              " " + std::to_string(3 * f + 2 + o) + "\n";
    }
    const Result<Mesh_buffers> r = read_mesh(text, format);
    ASSERT_TRUE(r.ok()) << r.status.message;
    ASSERT_EQ(r.value.positions.size(), 3 * (nv / 3) * 3);
    for (std::size_t i = 0; i < r.value.positions.size(); ++i) {
      const double expected = std::strtod(tokens[i].c_str(), nullptr);
      std::uint64_t a = 0, b = 0;
      std::memcpy(&a, &r.value.positions[i], sizeof a);
      std::memcpy(&b, &expected, sizeof b);
      ASSERT_EQ(a, b) << "token " << tokens[i];
    }
  }
}

TEST(IoSpeedPaths, LinesTheFastReaderDeclinesAreReadByTheGeneralOne) {
  // Signed indices, colours with "inf" and "nan", a '+' before coordinates,
  // comments glued to numbers, OBJ corners with texture and normal indices,
  // negative corners, CR and CRLF line ends and a byte order mark.
  const std::string off =
      "\xEF\xBB\xBF"
      "COFF\r\n4 4 0\r"
      "+0 0 0 1 0 0\n"
      "1 0 0 inf 0 0#colour\n"
      "0 +1 0 1 nan 0\r\n"
      "0 0 1.0e0 1 1 1 1\n"
      "3 +0 2 1\n"
      "3 0 1 3 0.5 0.5 0.5\n"
      "3 0 3 2# glued\n"
      "   3 1 2 3\t\n";
  const Result<Mesh_buffers> a = read_mesh(off, Mesh_format::off);
  ASSERT_TRUE(a.ok()) << a.status.message;
  EXPECT_EQ(a.value.positions,
            (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}));
  EXPECT_EQ(a.value.face_indices,
            (std::vector<std::uint32_t>{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}));

  const std::string obj =
      "v 0 0 0\nv 1 0 0 1\r\nv 0 1 0 inf\rv 0 0 1\n"
      "vt 0 0\nf 1/1 3/1 2/1\nf 1//1 2//1 4//1\n"
      "f -4/1/1 -1/1/1 -2/1/1\nf +2 -2 4\n";
  const Result<Mesh_buffers> b = read_mesh(obj, Mesh_format::obj);
  ASSERT_TRUE(b.ok()) << b.status.message;
  EXPECT_EQ(b.value.face_indices, a.value.face_indices);
  EXPECT_EQ(b.value.positions, a.value.positions);

  // After lines read both ways, errors still name the right line.
  Result<Mesh_buffers> r =
      read_mesh("OFF\r\n3 1 0\n# c\r\n0 0 0 \n+1 0 0\r0 1 x\n3 0 1 2\n",
                Mesh_format::off);
  EXPECT_EQ(r.status.code, Status_code::parse_error);
  EXPECT_EQ(r.status.line, 6);
  EXPECT_EQ(r.status.message,
            "line 6: z coordinate of vertex 2 is not a number: 'x'");
  r = read_mesh("v 0 0 0\nv 1 0 0\r\nv 0 1 0 +2\rf 1 2 3 0\n",
                Mesh_format::obj);
  EXPECT_EQ(r.status.code, Status_code::invalid_mesh);
  EXPECT_EQ(r.status.line, 4);
  EXPECT_EQ(r.status.message,
            "line 4: face index 0 is out of range (OBJ indices start at 1)");
  r = read_mesh("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 1 1 1 1 1\n",
                Mesh_format::off);
  EXPECT_EQ(r.status.line, 6);
  EXPECT_EQ(r.status.message,
            "line 6: face 0 declares 3 vertices but the line has 5 more values "
            "(at most 4, a colour, may follow the indices)");
}

/// Every mesh in tests/fixtures, valid and invalid.
const char* const fixture_names[] = {"cube.off",
                                     "cube.obj",
                                     "disk-tri.off",
                                     "grid-open.off",
                                     "icosahedron.off",
                                     "mixed-open.off",
                                     "octahedron.off",
                                     "rhombicuboctahedron.off",
                                     "tetrahedron.off",
                                     "torus-quad.off",
                                     "torus-tri.off",
                                     "two-tetrahedra.off",
                                     "cube-creased.obj",
                                     "quad-patch-corners.obj",
                                     "torus-holed.obj",
                                     "tetra-crease.obj",
                                     "course.obj",
                                     "invalid/extra-data.off",
                                     "invalid/face-too-small.obj",
                                     "invalid/huge-counts.off",
                                     "invalid/inconsistent-orientation.off",
                                     "invalid/index-out-of-range.off",
                                     "invalid/no-faces.off",
                                     "invalid/non-finite.off",
                                     "invalid/non-manifold-edge.off",
                                     "invalid/non-manifold-vertex.off",
                                     "invalid/non-numeric.obj",
                                     "invalid/repeated-vertex.obj",
                                     "invalid/truncated.off",
                                     "invalid/unknown-header.off"};

/// A fixture's text and its format (by its name).
std::pair<std::string, Mesh_format> read_fixture(const std::string& name) {
  std::ifstream in(std::string(FIXTURES_DIR) + "/" + name, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return {s.str(), name.substr(name.size() - 3) == "obj" ? Mesh_format::obj
                                                         : Mesh_format::off};
}

// read_mesh without corner halfedges runs the check alone (8-byte corner
// records, nothing paired); with them, the numbering check. Both must take
// and refuse the same meshes with the same words and lines.
TEST(IoSpeedPaths, TheCheckAloneAndTheNumberingCheckAgree) {
  std::vector<std::pair<std::string, Mesh_format>> texts;
  for (const char* name : fixture_names) {
    texts.push_back(read_fixture(name));
    ASSERT_FALSE(texts.back().first.empty()) << name;
  }
  const std::string square =
      "OFF\n5 4 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n.5 .5 0\n";
  // Two fans sharing vertex 4 (a bowtie), an edge of three faces, a face
  // turned the wrong way, and the square's four triangles (valid, open).
  texts.push_back(
      {"OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n.5 .5 0\n"
       "3 0 1 4\n3 2 3 4\n",
       Mesh_format::off});
  texts.push_back(
      {"OFF\n5 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n.5 .5 0\n"
       "3 0 1 2\n3 1 0 3\n3 0 1 4\n",
       Mesh_format::off});
  texts.push_back(
      {square + "3 0 1 4\n3 1 2 4\n3 2 4 3\n3 3 0 4\n", Mesh_format::off});
  texts.push_back(
      {square + "3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n", Mesh_format::off});
  int refused = 0;
  for (const auto& [text, format] : texts) {
    const Result<Mesh_buffers> alone = read_mesh(text, format);
    std::vector<std::uint32_t> halfedges;
    const Result<Mesh_buffers> numbered = read_mesh(text, format, &halfedges);
    EXPECT_EQ(alone.status.code, numbered.status.code) << text;
    EXPECT_EQ(alone.status.message, numbered.status.message) << text;
    EXPECT_EQ(alone.status.line, numbered.status.line) << text;
    EXPECT_EQ(alone.value.positions, numbered.value.positions) << text;
    EXPECT_EQ(alone.value.face_indices, numbered.value.face_indices) << text;
    if (alone.ok()) {
      EXPECT_EQ(halfedges.size(), alone.value.face_indices.size()) << text;
    } else {
      ++refused;
    }
  }
  EXPECT_EQ(refused, 13 + 3);
}

/// `mesh` as write_mesh writes it, with every `k`-th vertex line and every
/// `k`-th face line (counting from `first`) in a form the fast path
/// declines and the general path reads to the same values: a vertex line
/// ends in "nan" (an extra value, accepted and not kept), a face's first
/// index is written "+i".
std::string with_general_lines(const Mesh_buffers& mesh, Mesh_format format,
                               std::size_t k, std::size_t first) {
  const std::string text = write_mesh(mesh, format);
  const bool off = format == Mesh_format::off;
  std::string out;
  std::size_t vertex = 0, face = 0, line = 0, at = 0;
  while (at < text.size()) {
    const std::size_t end = text.find('\n', at);
    std::string l = text.substr(at, end - at);
    at = end + 1;
    ++line;
    const bool is_vertex =
        off ? line > 2 && vertex < mesh.vertex_count() : l.rfind("v ", 0) == 0;
    // OFF: the tag comments after the faces stay as they are.
    const bool is_face =
        off ? line > 2 && !is_vertex && face < mesh.face_count()
            : l.rfind("f ", 0) == 0;
    if (is_vertex && vertex++ % k == first % k) l += " nan";
    if (is_face && face++ % k == first % k) {
      const std::size_t space = l.find(' ');
      l.insert(space + 1, "+");
    }
    out += l + "\n";
  }
  return out;
}

void expect_same_reading(const Result<Mesh_buffers>& a,
                         const Result<Mesh_buffers>& b,
                         const std::string& what) {
  EXPECT_EQ(a.status.code, b.status.code) << what;
  EXPECT_EQ(a.status.message, b.status.message) << what;
  EXPECT_EQ(a.status.line, b.status.line) << what;
  EXPECT_EQ(a.value.positions, b.value.positions) << what;
  EXPECT_EQ(a.value.face_sizes, b.value.face_sizes) << what;
  EXPECT_EQ(a.value.face_indices, b.value.face_indices) << what;
  const Mesh_tags &s = a.value.tags, &t = b.value.tags;
  EXPECT_EQ(s.crease_edges, t.crease_edges) << what;
  EXPECT_EQ(s.crease_sharpness, t.crease_sharpness) << what;
  EXPECT_EQ(s.corner_vertices, t.corner_vertices) << what;
  EXPECT_EQ(s.corner_sharpness, t.corner_sharpness) << what;
  EXPECT_EQ(s.holes, t.holes) << what;
  EXPECT_EQ(s.boundary, t.boundary) << what;
  EXPECT_EQ(s.crease_method, t.crease_method) << what;
  EXPECT_EQ(s.notes, t.notes) << what;
}

// The fast path reads runs of lines out of line (mesh_io.cpp: no landing
// pad, no JavaScript round trip per line in WebAssembly) and hands a line it
// declines to the general path, then resumes. With the fast path off, every
// line is read by the general path: both must give the same buffers, the
// same halfedges and the same messages on every fixture, and on texts whose
// general lines come first, last, every other one or all of them.
TEST(IoSpeedPaths, TheFastAndTheGeneralPathAgreeOnEveryFixture) {
  int valid = 0;
  for (const char* name : fixture_names) {
    const auto [text, format] = read_fixture(name);
    ASSERT_FALSE(text.empty()) << name;
    std::vector<std::uint32_t> h_fast, h_general;
    const Result<Mesh_buffers> fast = read_mesh(text, format, &h_fast);
    const Result<Mesh_buffers> general =
        detail::read_mesh_general(text, format, &h_general);
    expect_same_reading(fast, general, name);
    EXPECT_EQ(h_fast, h_general) << name;
    if (!fast.ok()) continue;
    ++valid;
    for (const std::size_t k : {1, 2, 3}) {
      for (std::size_t first = 0; first < k; ++first) {
        const std::string mixed =
            with_general_lines(fast.value, format, k, first);
        const std::string what = std::string(name) + " k=" + std::to_string(k) +
                                 " first=" + std::to_string(first);
        std::vector<std::uint32_t> h_mixed;
        const Result<Mesh_buffers> m = read_mesh(mixed, format, &h_mixed);
        ASSERT_TRUE(m.ok()) << what << ": " << m.status.message;
        expect_same_reading(m, fast, what);
        EXPECT_EQ(h_mixed, h_fast) << what;
        expect_same_reading(detail::read_mesh_general(mixed, format), fast,
                            what);
      }
    }
  }
  EXPECT_EQ(valid, 17);
}

// Where a run stops, the counts and lines in the messages continue from
// where it stopped: a text ending after general and fast lines, an index
// the fast path declines, extra data, an unknown statement after a run.
TEST(IoSpeedPaths, MessagesAfterARunNameTheRightLine) {
  struct Case {
    const char* text;
    Mesh_format format;
    Status_code code;
    int line;
    const char* message;
  };
  const Case cases[] = {
      {"OFF\n4 1 0\n0 0 0\n1 0 0 nan\n0 1 0\n", Mesh_format::off,
       Status_code::parse_error, 5, "line 5: file ends after 3 of 4 vertices"},
      {"OFF\n3 3 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 +0 2 1\n\n",
       Mesh_format::off, Status_code::parse_error, 8,
       "line 8: file ends after 2 of 3 faces"},
      {"OFF\n3 3 0\n0 0 0\n1 0 0 nan\n0 1 0\n3 0 1 2\n3 0 2 1\n3 0 1 3\n",
       Mesh_format::off, Status_code::invalid_mesh, 8,
       "line 8: face index 3 is out of range (3 vertices)"},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n# end\n3 0 2 1\n",
       Mesh_format::off, Status_code::parse_error, 8,
       "line 8: extra data after the 1 faces the header declares (header "
       "counts disagree with the data)"},
      {"OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\nx 0 2 1\n", Mesh_format::off,
       Status_code::parse_error, 7,
       "line 7: face 1 must start with its vertex count, found 'x' (do the "
       "header counts match the data?)"},
      {"v 0 0 0\nv 1 0 0 nan\nv 0 1 0\nf 1 2 3\nvt 0 0\nf +1 3 2\nq 1\n",
       Mesh_format::obj, Status_code::parse_error, 7,
       "line 7: unknown OBJ statement 'q'"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 3\n", Mesh_format::obj,
       Status_code::inconsistent_orientation, 5,
       "line 5: inconsistent orientation: the faces on lines 4 and 5 both "
       "use edge 1\u21922 in the same direction; turning 1 face around "
       "makes them agree (repair orientation)"},
  };
  for (const Case& c : cases) {
    for (const bool fast : {true, false}) {
      const Result<Mesh_buffers> r =
          fast ? read_mesh(c.text, c.format)
               : detail::read_mesh_general(c.text, c.format);
      EXPECT_EQ(r.status.code, c.code) << c.text;
      EXPECT_EQ(r.status.line, c.line) << c.text;
      EXPECT_EQ(r.status.message, c.message) << c.text;
    }
  }
}

}  // namespace
}  // namespace subdivlab
