// PLY and STL in and out, files that are not meshes, the format guessed
// from the content, orientation repair and the comment written on export:
// hand-made fixtures (tests/fixtures/make_format_fixtures.py) with their
// counts and coordinates, hostile bytes with their messages, round trips.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "core/mesh_io.h"
#include "fixture_text.h"

namespace subdivlab {
namespace {

Mesh_buffers read_ok(const std::string& bytes, Mesh_format format,
                     const Read_options& options = {}) {
  Result<Mesh_buffers> r = read_mesh(bytes, format, nullptr, options);
  EXPECT_TRUE(r.ok()) << r.status.message;
  return r.value;
}

/// Reads bytes that must fail; checks code and line, returns the message.
std::string read_error(const std::string& bytes, Mesh_format format,
                       Status_code code, int line) {
  Result<Mesh_buffers> r = read_mesh(bytes, format);
  EXPECT_EQ(r.status.code, code) << r.status.message;
  EXPECT_EQ(r.status.line, line) << r.status.message;
  return r.status.message;
}

const std::vector<double> cube_positions = {-1, -1, -1, 1,  -1, -1, -1, 1,
                                            -1, 1,  1,  -1, -1, -1, 1,  1,
                                            -1, 1,  -1, 1,  1,  1,  1,  1};
const std::vector<std::uint32_t> cube_indices = {
    1, 0, 2, 3, 2, 0, 4, 6, 3, 2, 6, 7, 4, 0, 1, 5, 5, 1, 3, 7, 6, 4, 5, 7};

void expect_cube(const Mesh_buffers& m) {
  EXPECT_EQ(m.positions, cube_positions);
  EXPECT_EQ(m.face_sizes, std::vector<std::uint32_t>(6, 4));
  EXPECT_EQ(m.face_indices, cube_indices);
}

// ------------------------------------------------------------------ PLY

TEST(Ply, AsciiCubeSkipsCommentsExtraPropertiesListsAndElements) {
  expect_cube(read_ok(fixture_text("cube.ply"), Mesh_format::ply));
}

TEST(Ply, BinaryLittleAndBigEndianCubesGiveTheSameCube) {
  expect_cube(read_ok(fixture_text("cube-le.ply"), Mesh_format::ply));
  expect_cube(read_ok(fixture_text("cube-be.ply"), Mesh_format::ply));
}

TEST(Ply, DoubleCoordinatesAndVertexIndexListOfUintWithCrlf) {
  const std::string text =
      "ply\r\nformat ascii 1.0\r\nelement vertex 4\r\nproperty double z\r\n"
      "property double y\r\nproperty double x\r\nelement face 4\r\n"
      "property list uint uint vertex_index\r\nend_header\r\n"
      "0 0 0.1\r\n0 0 1\r\n0 1 0\r\n1 0 0\r\n"
      "3 0 2 1\r\n3 0 1 3\r\n3 0 3 2\r\n3 1 2 3\r\n";
  const Mesh_buffers m = read_ok(text, Mesh_format::ply);
  // x, y, z are found by name whatever their order.
  EXPECT_EQ(m.positions,
            (std::vector<double>{0.1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}));
  EXPECT_EQ(m.face_count(), 4u);
}

std::string tetra_ply_header(
    const std::string& format,
    const std::string& face_list = "property list uchar int vertex_indices\n") {
  return "ply\nformat " + format +
         " 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
         "property float z\nelement face 4\n" +
         face_list + "end_header\n";
}

const std::string tetra_ascii_data =
    "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

TEST(Ply, HostileHeadersNameTheirLine) {
  EXPECT_EQ(read_error("plyx\n", Mesh_format::ply, Status_code::parse_error, 1),
            "line 1: a PLY file starts with the line 'ply', not 'plyx'");
  EXPECT_EQ(read_error("ply\nformat ascii 2.0\n", Mesh_format::ply,
                       Status_code::parse_error, 2),
            "line 2: expected 'format <ascii | binary_little_endian | "
            "binary_big_endian> 1.0', not 'format ascii 2.0'");
  EXPECT_EQ(read_error("ply\nformat ascii 1.0\nelement vertex 1\n",
                       Mesh_format::ply, Status_code::parse_error, 3),
            "line 3: the header ends without an end_header line");
  EXPECT_EQ(read_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty "
                       "int128 x\n",
                       Mesh_format::ply, Status_code::parse_error, 4),
            "line 4: unknown PLY type 'int128'");
  // Wrong list types: float indices, float counts, a single number.
  EXPECT_EQ(read_error(tetra_ply_header("ascii",
                                        "property list uchar float "
                                        "vertex_indices\n") +
                           tetra_ascii_data,
                       Mesh_format::ply, Status_code::parse_error, 7),
            "line 7: the face list 'vertex_indices' holds floating-point "
            "numbers; vertex indices must be of an integer type");
  EXPECT_EQ(read_error(tetra_ply_header("ascii",
                                        "property list float int "
                                        "vertex_indices\n") +
                           tetra_ascii_data,
                       Mesh_format::ply, Status_code::parse_error, 8),
            "line 8: the list 'vertex_indices' has a count of type 'float'; "
            "a list count must be an integer type");
  EXPECT_EQ(read_error(tetra_ply_header("ascii",
                                        "property int "
                                        "vertex_indices\n") +
                           tetra_ascii_data,
                       Mesh_format::ply, Status_code::parse_error, 7),
            "line 7: the face property 'vertex_indices' is a single number, "
            "not a list of vertices");
  EXPECT_EQ(read_error("ply\nformat ascii 1.0\nelement vertex 0\nproperty "
                       "float x\nproperty float y\nproperty float z\n"
                       "end_header\n",
                       Mesh_format::ply, Status_code::parse_error, 0),
            "the header declares no 'face' element: a point cloud is not a "
            "polygon mesh");
}

TEST(Ply, CountsLargerThanTheDataAreRefusedBeforeAnyAllocation) {
  const std::string header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n"
      "property float x\nproperty float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n";
  EXPECT_EQ(read_error(header + std::string(20, '\0'), Mesh_format::ply,
                       Status_code::parse_error, 3),
            "line 3: the header declares 4000000000 'vertex' elements of at "
            "least 12 bytes each, but only 20 bytes of data follow");
}

TEST(Ply, AnElementWithoutPropertiesCostsNothingWhateverItsCount) {
  // Found by the fuzzers: 10^16 empty elements were read one by one (hours).
  for (const char* encoding : {"ascii", "binary_little_endian"}) {
    SCOPED_TRACE(encoding);
    std::string cube = fixture_text(
        std::string(encoding) == "ascii" ? "cube.ply" : "cube-le.ply");
    const std::size_t at = cube.find("element vertex");
    ASSERT_NE(at, std::string::npos);
    cube.insert(at, "element nothing 10000000000000000\n");
    const Result<Mesh_buffers> r = read_mesh(cube, Mesh_format::ply);
    ASSERT_TRUE(r.ok()) << r.status.message;
    EXPECT_EQ(r.value.vertex_count(), 8u);
    EXPECT_EQ(r.value.face_count(), 6u);
  }
}

TEST(Ply, TruncatedBinaryNamesTheByteAndTheElement) {
  std::string le = fixture_text("cube-le.ply");
  const std::size_t data = le.find("end_header\n") + 11;
  // Cut inside face 2: 8 vertices of 13 bytes, 2 faces of 17 + 9 bytes,
  // then 1 + 4 bytes of face 2.
  const std::size_t cut = data + 8 * 13 + 2 * 26 + 5;
  const std::string message = read_error(le.substr(0, cut), Mesh_format::ply,
                                         Status_code::parse_error, 0);
  EXPECT_EQ(message,
            "byte " + std::to_string(cut - 4) +
                ": the list 'vertex_indices' of "
                "face 2 (of 6) has 4 entries, more than the data holds");
  // Lists longer than the header's least size pass its check and end
  // early all the same: 4 vertices, 3 faces of 3, nothing for face 3.
  std::string tetra = tetra_ply_header("binary_big_endian");
  const std::size_t data_begin = tetra.size();
  tetra += std::string(4 * 12, '\0');
  for (int f = 0; f < 3; ++f)
    tetra += std::string("\3\0\0\0\0\0\0\0\1\0\0\0\2", 13);
  EXPECT_EQ(read_error(tetra, Mesh_format::ply, Status_code::parse_error, 0),
            "byte " + std::to_string(data_begin + 48 + 39) +
                ": the data ends before the count of list 'vertex_indices' of "
                "face 3 (of 4) (the header declares 4)");
  // ASCII: the line where the data ran out.
  const std::string ascii = tetra_ply_header("ascii") + tetra_ascii_data;
  EXPECT_EQ(read_error(ascii.substr(0, ascii.find("3 1 2 3")), Mesh_format::ply,
                       Status_code::parse_error, 17),
            "line 17: the data ends before the count of list "
            "'vertex_indices' of face 3 (of 4) (the header declares 4)");
}

TEST(Ply, NotFiniteCoordinatesNegativeIndicesAndBadTokens) {
  std::string nan_data = tetra_ascii_data;
  nan_data.replace(nan_data.find("0 1 0"), 5, "0 nan 0");
  EXPECT_EQ(read_error(tetra_ply_header("ascii") + nan_data, Mesh_format::ply,
                       Status_code::parse_error, 12),
            "line 12: coordinate 'y' of vertex 2 (of 4) is not a finite "
            "number");
  std::string negative = tetra_ascii_data;
  negative.replace(negative.find("3 0 1 3"), 7, "3 0 -1 3");
  EXPECT_EQ(read_error(tetra_ply_header("ascii") + negative, Mesh_format::ply,
                       Status_code::parse_error, 15),
            "line 15: face 1 (of 4) has the negative vertex index -1");
  std::string word = tetra_ascii_data;
  word.replace(word.find("3 1 2 3"), 7, "3 1 two 3");
  EXPECT_EQ(read_error(tetra_ply_header("ascii") + word, Mesh_format::ply,
                       Status_code::parse_error, 17),
            "line 17: 'two' is not a int value for an entry of list "
            "'vertex_indices' of face 3 (of 4)");
  EXPECT_EQ(read_error(tetra_ply_header("ascii") + tetra_ascii_data + "7\n",
                       Mesh_format::ply, Status_code::parse_error, 18),
            "line 18: data after the last element the header declares: '7'");
  // Binary NaN: vertex 1's x at its offset.
  std::string bin = tetra_ply_header("binary_little_endian");
  const std::size_t data = bin.size();
  bin += std::string(48, '\0');
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(&bin[data + 12], &nan, 4);
  for (const char* f :
       {"\3\0\0\0\0\2\0\0\0\1\0\0\0", "\3\0\0\0\0\1\0\0\0\3\0\0\0",
        "\3\0\0\0\0\3\0\0\0\2\0\0\0", "\3\1\0\0\0\2\0\0\0\3\0\0\0"})
    bin.append(f, 13);
  EXPECT_EQ(read_error(bin, Mesh_format::ply, Status_code::parse_error, 0),
            "byte " + std::to_string(data + 12) +
                ": coordinate 'x' of vertex 1 (of 4) is not a finite number");
}

TEST(Ply, ManifoldChecksNameAsciiLinesAndBinaryFaceNumbers) {
  std::string twice = tetra_ascii_data;
  twice.replace(twice.find("3 0 1 3"), 7, "3 0 2 3");
  const std::string m =
      read_error(tetra_ply_header("ascii") + twice, Mesh_format::ply,
                 Status_code::invalid_mesh, 16);
  EXPECT_EQ(m.rfind("line 16: ", 0), 0u) << m;
}

TEST(Ply, WrittenAsciiReadsBackTheSameWithItsComment) {
  Mesh_buffers cube = read_ok(fixture_text("cube.off"), Mesh_format::off);
  cube.positions[0] = 0.1;  // a double no float holds
  const std::string text =
      write_mesh(cube, Mesh_format::ply, "SubdivLab: cube.off, Loop, level 0");
  EXPECT_EQ(text.substr(0, 81),
            "ply\nformat ascii 1.0\ncomment SubdivLab: cube.off, Loop, level "
            "0\nelement vertex 8\n");
  EXPECT_NE(text.find("property list uchar uint vertex_indices\nend_header\n"
                      "0.10000000000000001 -1 -1\n"),
            std::string::npos)
      << text;
  const Mesh_buffers back = read_ok(text, Mesh_format::ply);
  EXPECT_EQ(back.positions, cube.positions);
  EXPECT_EQ(back.face_sizes, cube.face_sizes);
  EXPECT_EQ(back.face_indices, cube.face_indices);
}

// ------------------------------------------------------------------ STL

const std::vector<double> tetra_positions = {0, 0, 0, 0, 1, 0,
                                             1, 0, 0, 0, 0, 1};

TEST(Stl, AsciiTetrahedronWeldsTwelveCornersIntoFourVertices) {
  const Mesh_buffers m =
      read_ok(fixture_text("tetrahedron.stl"), Mesh_format::stl);
  // Vertices in order of first appearance: (0,0,0), (0,1,0), (1,0,0), ...
  EXPECT_EQ(m.positions, tetra_positions);
  EXPECT_EQ(m.face_sizes, std::vector<std::uint32_t>(4, 3));
  EXPECT_EQ(m.face_indices,
            (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3, 0, 3, 1, 2, 1, 3}));
  EXPECT_TRUE(m.tags.notes.empty());
}

TEST(Stl, BinaryWithAHeaderStartingWithSolidIsReadAsBinary) {
  const std::string bytes = fixture_text("tetrahedron-binary.stl");
  ASSERT_EQ(bytes.size(), 84u + 4 * 50);
  ASSERT_EQ(bytes.substr(0, 5), "solid");
  const Mesh_buffers m = read_ok(bytes, Mesh_format::stl);
  EXPECT_EQ(m.positions, tetra_positions);
  EXPECT_EQ(m.face_indices,
            (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3, 0, 3, 1, 2, 1, 3}));
}

TEST(Stl, DegenerateTrianglesAreDroppedWithANote) {
  std::string text = fixture_text("tetrahedron.stl");
  const std::string sliver =
      "facet normal 0 0 0\nouter loop\nvertex 1 0 0\nvertex 1 0 0\nvertex -0 "
      "1 0\nendloop\nendfacet\nendsolid";
  text.replace(text.find("endsolid"), 8, sliver);
  const Mesh_buffers m = read_ok(text, Mesh_format::stl);
  EXPECT_EQ(m.face_count(), 4u);
  EXPECT_EQ(m.vertex_count(), 4u);  // -0 welds with 0
  EXPECT_EQ(m.tags.notes, std::vector<std::string>{
                              "1 degenerate triangle (two corners at the "
                              "same point) dropped"});
}

TEST(Stl, HostileInputsSayWhatIsWrongWhere) {
  const std::string text = fixture_text("tetrahedron.stl");
  EXPECT_EQ(read_error(text.substr(0, text.find("endloop")), Mesh_format::stl,
                       Status_code::parse_error, 7),
            "line 7: expected 'vertex' or 'endloop', not the end of the file");
  std::string nan = text;
  nan.replace(nan.find("vertex 0 1 0"), 12, "vertex 0 NaN 0");
  EXPECT_EQ(read_error(nan, Mesh_format::stl, Status_code::parse_error, 5),
            "line 5: the vertex's y is not finite: 'NaN'");
  std::string word = text;
  word.replace(word.find("outer loop"), 10, "outer lop");
  EXPECT_EQ(read_error(word, Mesh_format::stl, Status_code::parse_error, 3),
            "line 3: expected 'loop' after 'outer', not 'lop'");
  // A binary file cut short: its count says 4 triangles.
  const std::string bin = fixture_text("tetrahedron-binary.stl");
  std::string cut = bin.substr(0, 84 + 3 * 50 + 10);
  cut.replace(0, 5, "SOLID");  // not "solid": no ASCII reading either
  EXPECT_EQ(read_error(cut, Mesh_format::stl, Status_code::parse_error, 0),
            "byte 80: a binary STL of 4 triangles has 84 + 50 \u00d7 4 = 284 "
            "bytes, but the file has 244 (cut short, or not an STL file)");
  // A count far larger than the file: refused the same way, nothing read.
  std::string huge = bin;
  huge.replace(0, 5, "SOLID");
  huge[83] = '\x7f';
  EXPECT_NE(read_error(huge, Mesh_format::stl, Status_code::parse_error, 0)
                .find("but the file has 284"),
            std::string::npos);
  std::string bad = bin;
  const float inf = std::numeric_limits<float>::infinity();
  std::memcpy(&bad[84 + 50 + 12 + 12 + 8], &inf, 4);
  EXPECT_EQ(read_error(bad, Mesh_format::stl, Status_code::parse_error, 0),
            "byte 166: corner 2 of triangle 1 (of 4) has a coordinate that "
            "is not a finite number");
  EXPECT_EQ(read_error("abc", Mesh_format::stl, Status_code::parse_error, 0),
            "the file has 3 bytes: too short for a binary STL (84 bytes and "
            "more) and it does not start with 'solid' (ASCII STL)");
}

TEST(Stl, WrittenBinaryFansPolygonsWithUnitNormalsAndReadsBack) {
  const Mesh_buffers cube = read_ok(fixture_text("cube.off"), Mesh_format::off);
  const std::string bytes =
      write_mesh(cube, Mesh_format::stl, "SubdivLab: cube.off, Loop, level 0");
  ASSERT_EQ(bytes.size(), 84u + 12 * 50);
  EXPECT_EQ(bytes.substr(0, 34), "SubdivLab: cube.off, Loop, level 0");
  EXPECT_EQ(bytes[34], ' ');
  std::uint32_t n;
  std::memcpy(&n, &bytes[80], 4);
  EXPECT_EQ(n, 12u);
  // Face 0 (1 0 2 3) lies in z = -1 facing -z: its fan triangle 1 0 2.
  float rec[12];
  std::memcpy(rec, &bytes[84], 48);
  EXPECT_EQ(std::vector<float>(rec, rec + 12),
            (std::vector<float>{0, 0, -1, 1, -1, -1, -1, -1, -1, -1, 1, -1}));
  const Mesh_buffers back = read_ok(bytes, Mesh_format::stl);
  EXPECT_EQ(back.vertex_count(), 8u);
  EXPECT_EQ(back.face_count(), 12u);
}

// ------------------------------------------------- not meshes, detection

TEST(FileKind, NonMeshFilesSayWhatTheyAreWhateverTheFormatAsked) {
  const std::string png = fixture_text("not-a-mesh.png");
  for (const Mesh_format f : {Mesh_format::off, Mesh_format::obj,
                              Mesh_format::ply, Mesh_format::stl}) {
    EXPECT_EQ(read_error(png, f, Status_code::parse_error, 0),
              "This is a PNG image, not a mesh. SubdivLab reads OFF, OBJ, "
              "PLY and STL.");
  }
  const std::pair<std::string, std::string> kinds[] = {
      {"\xFF\xD8\xFF\xE0", "a JPEG image"},
      {"GIF89a....", "a GIF image"},
      {"%PDF-1.7\n", "a PDF document"},
      {std::string("PK\3\4\x14\0", 6),
       "a ZIP archive (.zip, .docx, .3mf, ...)"},
      {"glTF\2\0\0\0", "a binary glTF model (.glb)"},
      {" {\n \"asset\": {\"version\": \"2.0\"}}", "a glTF model"}};
  for (const auto& [bytes, kind] : kinds) {
    EXPECT_EQ(read_error(bytes, Mesh_format::off, Status_code::parse_error, 0),
              "This is " + kind +
                  ", not a mesh. SubdivLab reads OFF, OBJ, "
                  "PLY and STL.");
  }
  EXPECT_EQ(read_error("\x1F\x8B\x08\0", Mesh_format::obj,
                       Status_code::parse_error, 0),
            "This is gzip-compressed data, not a mesh: unpack it first. "
            "SubdivLab reads OFF, OBJ, PLY and STL.");
}

TEST(FileKind, BinaryOrOtherFormatIsNamedNotQuoted) {
  // Every byte value once: 28 control bytes and 128 bytes in no UTF-8
  // sequence, 156 of 256. As OFF its first "line" was quoted as a header.
  std::string all(256, '\0');
  for (int i = 0; i < 256; ++i) all[i] = static_cast<char>(i);
  // (As STL it is a binary STL cut short, which its reader says by byte.)
  for (const auto& [format, name] :
       {std::pair{Mesh_format::off, "OFF text"},
        std::pair{Mesh_format::obj, "OBJ text"},
        std::pair{Mesh_format::ply, "a PLY file"}}) {
    EXPECT_EQ(read_error(all, format, Status_code::parse_error, 0),
              std::string("This looks like a binary file, not ") + name +
                  ": 156 of its first 256 bytes are control bytes or "
                  "no UTF-8 text. SubdivLab reads OFF, OBJ, PLY and STL.");
  }
  // UTF-16 text (Notepad's "Unicode"), with and without a byte-order
  // mark, little and big endian: text in another encoding, not binary.
  const std::string off = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  std::string le, be;
  for (char c : off) {
    le += {c, '\0'};
    be += {'\0', c};
  }
  for (const std::string& utf16 : {std::string("\xFF\xFE", 2) + le, le,
                                   std::string("\xFE\xFF", 2) + be, be})
    EXPECT_EQ(read_error(utf16, Mesh_format::off, Status_code::parse_error, 0),
              "This looks like UTF-16 text (what Windows Notepad saves as "
              "\"Unicode\"), not OFF text in UTF-8 or ASCII: save it again "
              "as UTF-8 and open that.");
  // Files of another format under this one's extension.
  EXPECT_EQ(read_error(fixture_text("tetrahedron-binary.stl"), Mesh_format::off,
                       Status_code::parse_error, 0),
            "This looks like a binary STL file, not OFF text: give it the "
            ".stl extension to read it as STL.");
  EXPECT_EQ(read_error(fixture_text("cube-le.ply"), Mesh_format::obj,
                       Status_code::parse_error, 0),
            "This looks like a PLY file, not OBJ: give it the .ply extension "
            "to read it as PLY.");
  EXPECT_EQ(read_error(fixture_text("cube.obj"), Mesh_format::off,
                       Status_code::parse_error, 0),
            "This looks like an OBJ file, not OFF: give it the .obj extension "
            "to read it as OBJ.");
  EXPECT_EQ(read_error(fixture_text("tetrahedron.stl"), Mesh_format::obj,
                       Status_code::parse_error, 0),
            "This looks like an STL file, not OBJ: give it the .stl extension "
            "to read it as STL.");
  // A text file with a stray byte stays text: the token is quoted, the
  // byte that is no UTF-8 written as \xNN, not passed on raw.
  EXPECT_EQ(read_error("OFF\n3 1 0\n0 0 \xFFz\n1 0 0\n0 1 0\n3 0 1 2\n",
                       Mesh_format::off, Status_code::parse_error, 3),
            "line 3: z coordinate of vertex 0 is not a number: '\\xFFz'");
  // Errors in a file of the format keep their line.
  EXPECT_EQ(read_error("OFF\n3 1 0\n0 0 q\n1 0 0\n0 1 0\n3 0 1 2\n",
                       Mesh_format::off, Status_code::parse_error, 3),
            "line 3: z coordinate of vertex 0 is not a number: 'q'");
}

TEST(FileKind, FormatFromContent) {
  const auto detected = [](const std::string& bytes) {
    const Result<Mesh_format> r = detect_format(bytes);
    EXPECT_TRUE(r.ok()) << r.status.message;
    return std::string(format_name(r.value));
  };
  EXPECT_EQ(detected(fixture_text("cube.off")), "off");
  EXPECT_EQ(detected("# comment\n\nCOFF\n"), "off");
  EXPECT_EQ(detected(fixture_text("cube.obj")), "obj");
  EXPECT_EQ(detected(fixture_text("cube-be.ply")), "ply");
  EXPECT_EQ(detected(fixture_text("tetrahedron.stl")), "stl");
  EXPECT_EQ(detected(fixture_text("tetrahedron-binary.stl")), "stl");
  EXPECT_EQ(detect_format(fixture_text("not-a-mesh.png")).status.message,
            "This is a PNG image, not a mesh. SubdivLab reads OFF, OBJ, PLY "
            "and STL.");
  EXPECT_EQ(detect_format("hello\n").status.message,
            "This is not a mesh file: no OFF, OBJ, PLY or STL header or "
            "statement at its start. SubdivLab reads OFF, OBJ, PLY and STL.");
}

// ------------------------------------------------------------ orientation

TEST(Orientation, OneFlippedFaceIsRepairableAndRepairedOnRequest) {
  const std::string text = fixture_text("cube-flipped-face.off");
  Result<Mesh_buffers> r = read_mesh(text, Mesh_format::off);
  EXPECT_EQ(r.status.code, Status_code::inconsistent_orientation);
  EXPECT_EQ(r.status.line, 13) << r.status.message;
  EXPECT_NE(
      r.status.message.find("; turning 1 face around makes them agree (repair "
                            "orientation)"),
      std::string::npos)
      << r.status.message;
  Read_options repair;
  repair.repair_orientation = true;
  const Mesh_buffers m = read_ok(text, Mesh_format::off, repair);
  // The flipped face is turned back, the other five stay: cube.off exactly.
  expect_cube(m);
  EXPECT_EQ(m.tags.notes,
            std::vector<std::string>{"orientation repaired: 1 face was "
                                     "reversed to agree with their "
                                     "neighbours"});
}

TEST(Orientation, MoebiusStripIsNonOrientableEvenWithRepair) {
  const std::string text = fixture_text("moebius.off");
  Read_options repair;
  repair.repair_orientation = true;
  for (const Read_options& o : {Read_options{}, repair}) {
    Result<Mesh_buffers> r = read_mesh(text, Mesh_format::off, nullptr, o);
    EXPECT_EQ(r.status.code, Status_code::invalid_mesh);
    EXPECT_EQ(r.status.line, 18);
    EXPECT_EQ(r.status.message,
              "line 18: the surface is non-orientable (like a M\u00f6bius "
              "strip): the faces on lines 14 and 18 both use edge 0\u21925 "
              "in the same direction, whichever way each face is turned");
  }
}

TEST(Orientation, RepairWorksForPlyAndStlToo) {
  std::string stl = fixture_text("tetrahedron.stl");
  // Reverse the first facet's corners: swap its second and third vertices.
  stl.replace(stl.find("vertex 0 1 0"), 12, "vertex 0 X 0");
  stl.replace(stl.find("vertex 1 0 0"), 12, "vertex 0 1 0");
  stl.replace(stl.find("vertex 0 X 0"), 12, "vertex 1 0 0");
  EXPECT_EQ(read_mesh(stl, Mesh_format::stl).status.code,
            Status_code::inconsistent_orientation);
  Read_options repair;
  repair.repair_orientation = true;
  const Mesh_buffers m = read_ok(stl, Mesh_format::stl, repair);
  // Welded in the order met: (0,0,0), (1,0,0), (0,1,0), (0,0,1); the first
  // face, given as 0 1 2, turned back.
  EXPECT_EQ(m.face_indices,
            (std::vector<std::uint32_t>{2, 1, 0, 0, 1, 3, 0, 3, 2, 1, 2, 3}));
}

// --------------------------------------------------------- export comment

TEST(ExportComment, OffAfterItsFirstLineObjFirstReadersSkipIt) {
  const Mesh_buffers cube = read_ok(fixture_text("cube.off"), Mesh_format::off);
  const std::string off =
      write_mesh(cube, Mesh_format::off, "SubdivLab: cube.off, Loop, level 2");
  EXPECT_EQ(off.substr(0, 49),
            "OFF\n# SubdivLab: cube.off, Loop, level 2\n8 6 0\n-1");
  const std::string obj = write_mesh(cube, Mesh_format::obj, "SubdivLab: a\nb");
  EXPECT_EQ(obj.substr(0, 22), "# SubdivLab: a b\nv -1 ");
  for (const auto& [text, format] :
       {std::pair{off, Mesh_format::off}, std::pair{obj, Mesh_format::obj}}) {
    const Mesh_buffers back = read_ok(text, format);
    EXPECT_EQ(back.positions, cube.positions);
    EXPECT_EQ(back.face_indices, cube.face_indices);
  }
  // Without a comment: the bytes as before.
  EXPECT_EQ(write_mesh(cube, Mesh_format::off).substr(0, 10), "OFF\n8 6 0\n");
}

}  // namespace
}  // namespace subdivlab
