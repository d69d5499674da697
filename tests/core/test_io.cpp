// read_mesh / write_mesh: the OFF and OBJ variants people have, every kind
// of invalid file with its line and message, and exact round trips.

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "core/mesh_build.h"
#include "core/mesh_io.h"
#include "fixture_text.h"

namespace subdivlab {
namespace {

Mesh_buffers read_ok(const std::string& text, Mesh_format format) {
  Result<Mesh_buffers> r = read_mesh(text, format);
  EXPECT_TRUE(r.ok()) << r.status.message;
  return r.value;
}

/// Reads text that must fail; checks code and line, returns the message.
std::string read_error(const std::string& text, Mesh_format format,
                       Status_code code, int line) {
  Result<Mesh_buffers> r = read_mesh(text, format);
  EXPECT_EQ(r.status.code, code) << r.status.message;
  EXPECT_EQ(r.status.line, line) << r.status.message;
  if (line > 0) {
    const std::string prefix = "line " + std::to_string(line) + ": ";
    EXPECT_EQ(r.status.message.rfind(prefix, 0), 0u) << r.status.message;
  }
  return r.status.message;
}

const std::string tetra_vertices = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
const std::string tetra_faces = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

// ------------------------------------------------------------ valid OFF

TEST(IoOff, ReadsTheCubeFixture) {
  const Mesh_buffers m = read_ok(fixture_text("cube.off"), Mesh_format::off);
  EXPECT_EQ(m.vertex_count(), 8u);
  EXPECT_EQ(m.face_count(), 6u);
  EXPECT_EQ(m.face_indices.size(), 24u);
  EXPECT_EQ(m.positions[0], -1.0);
  EXPECT_EQ(m.positions[21], 1.0);
  EXPECT_EQ((std::vector<std::uint32_t>(m.face_indices.begin(),
                                        m.face_indices.begin() + 4)),
            (std::vector<std::uint32_t>{1, 0, 2, 3}));
}

TEST(IoOff, ReadsEveryFixture) {
  struct Expect {
    const char* name;
    std::size_t v, f, corners;
  };
  for (const Expect& e :
       {Expect{"tetrahedron.off", 4, 4, 12}, Expect{"octahedron.off", 6, 8, 24},
        Expect{"icosahedron.off", 12, 20, 60},
        Expect{"torus-quad.off", 48, 48, 192},
        Expect{"torus-tri.off", 48, 96, 288},
        Expect{"grid-open.off", 16, 9, 36}, Expect{"disk-tri.off", 7, 6, 18},
        Expect{"mixed-open.off", 13, 9, 31},
        Expect{"rhombicuboctahedron.off", 24, 26, 96},
        Expect{"two-tetrahedra.off", 8, 8, 24}}) {
    const Mesh_buffers m = read_ok(fixture_text(e.name), Mesh_format::off);
    EXPECT_EQ(m.vertex_count(), e.v) << e.name;
    EXPECT_EQ(m.face_count(), e.f) << e.name;
    EXPECT_EQ(m.face_indices.size(), e.corners) << e.name;
  }
}

TEST(IoOff, CountsOnTheHeaderLine) {
  const Mesh_buffers m =
      read_ok("OFF 4 4 6\n" + tetra_vertices + tetra_faces, Mesh_format::off);
  EXPECT_EQ(m.vertex_count(), 4u);
  EXPECT_EQ(m.face_count(), 4u);
  EXPECT_EQ(m.positions,
            (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}));
}

TEST(IoOff, CountsOnTheNextLineAfterCommentsAndBlankLines) {
  const std::string text =
      "# made by hand\n\nOFF # the header\n# counts follow\n\n4 4 0\n" +
      tetra_vertices + "# faces\n\n" + tetra_faces + "\n# end\n\n";
  const Mesh_buffers m = read_ok(text, Mesh_format::off);
  EXPECT_EQ(m.vertex_count(), 4u);
  EXPECT_EQ(m.face_count(), 4u);
  EXPECT_EQ(m.face_indices,
            (std::vector<std::uint32_t>{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}));
}

TEST(IoOff, CountsWithoutTheEdgeCount) {
  const Mesh_buffers m =
      read_ok("OFF\n4 4\n" + tetra_vertices + tetra_faces, Mesh_format::off);
  EXPECT_EQ(m.face_count(), 4u);
}

TEST(IoOff, CoffWithVertexAndFaceColours) {
  const std::string text =
      "COFF\n4 4 6\n"
      "0 0 0 1 0 0 1\n"
      "1 0 0 0 1 0 1\n"
      "0 1 0 0 0 1 0.5\n"
      "0 0 1 255 255 255 255\n"
      "3 0 2 1 255 0 0\n"
      "3 0 1 3 0.1 0.2 0.3 1\n"
      "3 0 3 2 7\n"
      "3 1 2 3\n";
  const Mesh_buffers m = read_ok(text, Mesh_format::off);
  EXPECT_EQ(m.positions,
            (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}));
  EXPECT_EQ(m.face_sizes, (std::vector<std::uint32_t>{3, 3, 3, 3}));
  EXPECT_EQ(m.face_indices,
            (std::vector<std::uint32_t>{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}));
}

TEST(IoOff, NoffCnoffAndStoffKeepOnlyPositions) {
  const std::string faces = tetra_faces;
  const Mesh_buffers n = read_ok(
      "NOFF\n4 4 0\n0 0 0 0 0 -1\n1 0 0 1 0 0\n0 1 0 0 1 0\n0 0 1 0 0 1\n" +
          faces,
      Mesh_format::off);
  EXPECT_EQ(n.positions,
            (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}));
  const Mesh_buffers cn = read_ok(
      "CNOFF\n4 4 0\n0 0 0 0 0 -1 1 0 0 1\n1 0 0 1 0 0 0 1 0 1\n0 1 0 0 1 0 0 "
      "0 1 1\n"
      "0 0 1 0 0 1 1 1 1 1\n" +
          faces,
      Mesh_format::off);
  EXPECT_EQ(cn.positions, n.positions);
  const Mesh_buffers st = read_ok(
      "STOFF\n4 4 0\n0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n0 0 1 1 1\n" + faces,
      Mesh_format::off);
  EXPECT_EQ(st.positions, n.positions);
}

TEST(IoOff, CrlfBomAndTabs) {
  const std::string text =
      "\xEF\xBB\xBFOFF\r\n4\t4\t0\r\n0\t0 0\r\n1 0\t0\r\n0 1 0\r\n\t0 0 1 \r\n"
      "3\t0 2 1\r\n3 0 1 3\r\n3 0 3 2\r\n3 1 2 3\r\n";
  const Mesh_buffers m = read_ok(text, Mesh_format::off);
  EXPECT_EQ(m.positions,
            (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}));
  EXPECT_EQ(m.face_count(), 4u);
}

TEST(IoOff, LoneCarriageReturnsEndLinesToo) {
  const std::string text =
      "OFF\r4 4 0\r0 0 0\r1 0 0\r0 1 0\r0 0 1\r3 0 2 1\r3 0 1 3\r3 0 3 2\r3 1 "
      "2 3\r";
  EXPECT_EQ(read_ok(text, Mesh_format::off).face_count(), 4u);
  // ... and lines are counted on them.
  const std::string bad = "OFF\r4 4 0\r0 0 0\r1 0 0\r0 1 0\r0 0 x\r";
  read_error(bad, Mesh_format::off, Status_code::parse_error, 6);
}

TEST(IoOff, ScientificNotationAndSigns) {
  const std::string text =
      "OFF\n4 4 0\n"
      "1e5 -0.5 +2\n"
      "2.5E-3 .25 -1.e2\n"
      "-0 1E+2 3\n"
      "0.000001 -7.5e-310 1\n" +
      tetra_faces;
  const Mesh_buffers m = read_ok(text, Mesh_format::off);
  ASSERT_EQ(m.positions.size(), 12u);
  EXPECT_EQ(m.positions[0], 100000.0);
  EXPECT_EQ(m.positions[1], -0.5);
  EXPECT_EQ(m.positions[2], 2.0);
  EXPECT_EQ(m.positions[3], 0.0025);
  EXPECT_EQ(m.positions[4], 0.25);
  EXPECT_EQ(m.positions[5], -100.0);
  EXPECT_EQ(m.positions[6], 0.0);
  EXPECT_TRUE(std::signbit(m.positions[6]));
  EXPECT_EQ(m.positions[7], 100.0);
  EXPECT_EQ(m.positions[9], 1e-6);
  EXPECT_EQ(m.positions[10], -7.5e-310);  // subnormal: finite, kept
}

TEST(IoOff, IsolatedVerticesAreDropped) {
  const std::string text = "OFF\n6 4 0\n9 9 9\n" + tetra_vertices +
                           "8 8 8\n3 1 3 2\n3 1 2 4\n3 1 4 3\n3 2 3 4\n";
  const Mesh_buffers m = read_ok(text, Mesh_format::off);
  EXPECT_EQ(m.vertex_count(), 4u);
  EXPECT_EQ(m.positions,
            (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}));
  EXPECT_EQ(m.face_indices,
            (std::vector<std::uint32_t>{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}));
}

// ------------------------------------------------------------ invalid OFF

TEST(IoOffErrors, IndexOutOfRange) {
  const std::string text =
      "OFF\n4 4 0\n" + tetra_vertices + "3 0 2 1\n3 0 12 3\n3 0 3 2\n3 1 2 3\n";
  EXPECT_EQ(read_error(text, Mesh_format::off, Status_code::invalid_mesh, 8),
            "line 8: face index 12 is out of range (4 vertices)");
  const std::string negative =
      "OFF\n4 4 0\n" + tetra_vertices + "3 0 2 -1\n" + tetra_faces;
  EXPECT_EQ(
      read_error(negative, Mesh_format::off, Status_code::invalid_mesh, 7),
      "line 7: face index -1 is out of range (4 vertices)");
}

TEST(IoOffErrors, HugeIndicesQuoteTheFile) {
  const std::string text = "OFF\n4 4 0\n" + tetra_vertices +
                           "3 0 2 123456789012345678901234567890\n" +
                           tetra_faces;
  EXPECT_EQ(read_error(text, Mesh_format::off, Status_code::invalid_mesh, 7),
            "line 7: face index 123456789012345678901234567890 is out of "
            "range (4 vertices)");
  EXPECT_EQ(read_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999/1\n",
                       Mesh_format::obj, Status_code::invalid_mesh, 4),
            "line 4: face index 99999999999 is out of range (more than any "
            "mesh can hold)");
  EXPECT_EQ(read_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 "
                       "-99999999999999999999999//2\n",
                       Mesh_format::obj, Status_code::invalid_mesh, 4),
            "line 4: relative face index -99999999999999999999999 is out of "
            "range (3 vertices defined so far)");
  EXPECT_EQ(read_error("OFF\n4 123456789012345678901234567890 0\n",
                       Mesh_format::off, Status_code::parse_error, 2),
            "line 2: face count 123456789012345678901234567890 is too large");
}

TEST(IoOffErrors, IndexNotAnInteger) {
  const std::string text =
      "OFF\n4 4 0\n" + tetra_vertices + "3 0 2 1.5\n" + tetra_faces;
  const std::string m =
      read_error(text, Mesh_format::off, Status_code::parse_error, 7);
  EXPECT_EQ(m, "line 7: face index '1.5' is not an integer");
}

TEST(IoOffErrors, FaceWithFewerThanThreeVertices) {
  const std::string text =
      "OFF\n4 5 0\n" + tetra_vertices + tetra_faces + "2 0 1\n";
  EXPECT_EQ(read_error(text, Mesh_format::off, Status_code::invalid_mesh, 11),
            "line 11: the face has 2 vertices; a face needs at least 3");
}

TEST(IoOffErrors, RepeatedVertexInAFace) {
  const std::string text =
      "OFF\n4 4 0\n" + tetra_vertices + "3 0 2 1\n3 0 1 0\n3 0 3 2\n3 1 2 3\n";
  EXPECT_EQ(read_error(text, Mesh_format::off, Status_code::invalid_mesh, 8),
            "line 8: the face uses vertex 0 more than once");
}

TEST(IoOffErrors, NonFiniteCoordinates) {
  for (const char* bad :
       {"inf", "-inf", "nan", "NaN", "Infinity", "1e999", "-1e400"}) {
    const std::string text = "OFF\n4 4 0\n0 0 0\n1 " + std::string(bad) +
                             " 0\n0 1 0\n0 0 1\n" + tetra_faces;
    const std::string m =
        read_error(text, Mesh_format::off, Status_code::parse_error, 4);
    EXPECT_EQ(m, "line 4: y coordinate of vertex 1 is not finite: '" +
                     std::string(bad) + "'");
  }
}

TEST(IoOffErrors, NonNumericCoordinates) {
  for (const char* bad :
       {"abc", "1.2.3", "1e", "0x10", "--1", "1,5", "2e5x", "."}) {
    const std::string text = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 " +
                             std::string(bad) + "\n" + tetra_faces;
    const std::string m =
        read_error(text, Mesh_format::off, Status_code::parse_error, 6);
    EXPECT_EQ(m, "line 6: z coordinate of vertex 3 is not a number: '" +
                     std::string(bad) + "'");
  }
}

TEST(IoOffErrors, TooFewValuesOnAVertexLine) {
  const std::string text =
      "OFF\n4 4 0\n0 0 0\n1 0\n0 1 0\n0 0 1\n" + tetra_faces;
  EXPECT_EQ(read_error(text, Mesh_format::off, Status_code::parse_error, 4),
            "line 4: vertex 1 has 2 values; OFF needs at least 3 (x y z)");
  const std::string noff =
      "NOFF\n4 4 0\n0 0 0 0 0 1\n1 0 0\n0 1 0 0 0 1\n0 0 1 0 0 1\n" +
      tetra_faces;
  EXPECT_EQ(
      read_error(noff, Mesh_format::off, Status_code::parse_error, 4),
      "line 4: vertex 1 has 3 values; NOFF needs at least 6 (x y z, a normal)");
}

TEST(IoOffErrors, TruncatedInTheVertices) {
  const std::string text = "OFF\n8 6 12\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n";
  const std::string m =
      read_error(text, Mesh_format::off, Status_code::parse_error, 7);
  EXPECT_EQ(m, "line 7: file ends after 5 of 8 vertices");
}

TEST(IoOffErrors, TruncatedInTheFaces) {
  const std::string text =
      "OFF\n4 4 0\n" + tetra_vertices + "3 0 2 1\n3 0 1 3\n\n";
  EXPECT_EQ(read_error(text, Mesh_format::off, Status_code::parse_error, 9),
            "line 9: file ends after 2 of 4 faces");
}

TEST(IoOffErrors, ExtraDataAfterTheDeclaredFaces) {
  const std::string text = "OFF\n4 3 0\n" + tetra_vertices + tetra_faces;
  EXPECT_EQ(read_error(text, Mesh_format::off, Status_code::parse_error, 10),
            "line 10: extra data after the 3 faces the header declares (header "
            "counts disagree "
            "with the data)");
}

TEST(IoOffErrors, FaceListsFewerOrMoreValuesThanItDeclares) {
  const std::string fewer =
      "OFF\n4 4 0\n" + tetra_vertices + "4 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  EXPECT_EQ(read_error(fewer, Mesh_format::off, Status_code::parse_error, 7),
            "line 7: face 0 declares 4 vertices but lists only 3");
  const std::string more = "OFF\n4 4 0\n" + tetra_vertices +
                           "3 0 2 1\n3 0 1 3 1 2 3 0 1\n3 0 3 2\n3 1 2 3\n";
  EXPECT_EQ(read_error(more, Mesh_format::off, Status_code::parse_error, 8),
            "line 8: face 1 declares 3 vertices but the line has 5 more values "
            "(at most 4, a "
            "colour, may follow the indices)");
}

TEST(IoOffErrors, HeaderDeclaresFewerVerticesThanTheDataHas) {
  const std::string text =
      "OFF\n3 4 0\n0 0 0\n1 0 0\n0 1 0\n0.5 0 1\n" + tetra_faces;
  EXPECT_EQ(read_error(text, Mesh_format::off, Status_code::parse_error, 6),
            "line 6: face 0 must start with its vertex count, found '0.5' (do "
            "the header counts "
            "match the data?)");
}

TEST(IoOffErrors, BadCountsLine) {
  EXPECT_EQ(
      read_error("OFF\n4\n", Mesh_format::off, Status_code::parse_error, 2),
      "line 2: expected the counts 'vertices faces edges', found 1 values");
  EXPECT_EQ(
      read_error("OFF\n4 x 0\n", Mesh_format::off, Status_code::parse_error, 2),
      "line 2: face count 'x' is not a non-negative integer");
  EXPECT_EQ(
      read_error("OFF -4 4 0\n", Mesh_format::off, Status_code::parse_error, 1),
      "line 1: vertex count '-4' is not a non-negative integer");
  EXPECT_EQ(read_error("OFF\n# nothing else\n", Mesh_format::off,
                       Status_code::parse_error, 2),
            "line 2: file ends before the counts line");
}

TEST(IoOffErrors, NonManifoldEdge) {
  const std::string text =
      "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n"
      "3 0 1 2\n3 1 0 3\n# third face on the same edge\n3 0 1 4\n";
  EXPECT_EQ(read_error(text, Mesh_format::off, Status_code::invalid_mesh, 11),
            "line 11: non-manifold edge between vertices 0 and 1: used by 3 "
            "faces (the faces on "
            "lines 8, 9 and 11)");
}

TEST(IoOffErrors, NonManifoldVertex) {
  const std::string text =
      "OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n-1 0 0\n-1 -1 0\n3 0 1 2\n3 0 3 4\n";
  EXPECT_EQ(read_error(text, Mesh_format::off, Status_code::invalid_mesh, 9),
            "line 9: non-manifold vertex 0: its faces form 2 separate fans "
            "that meet only at this "
            "vertex (the faces on lines 8 and 9)");
}

TEST(IoOffErrors, InconsistentOrientation) {
  // The cube with its last face flipped.
  std::string text = fixture_text("cube.off");
  const std::string last = "4 6 4 5 7\n";
  ASSERT_EQ(text.substr(text.size() - last.size()), last);
  text.replace(text.size() - last.size(), last.size(), "4 7 5 4 6\n");
  const std::string m = read_error(text, Mesh_format::off,
                                   Status_code::inconsistent_orientation, 17);
  EXPECT_NE(m.find("inconsistent orientation: the faces on lines "),
            std::string::npos)
      << m;
  EXPECT_NE(m.find(" and 17 both use edge "), std::string::npos) << m;
  EXPECT_NE(m.find(" in the same direction; turning 1 face around makes "
                   "them agree (repair orientation)"),
            std::string::npos)
      << m;
}

TEST(IoOffErrors, NoFaces) {
  const std::string text = "OFF\n4 0 0\n" + tetra_vertices;
  EXPECT_EQ(read_error(text, Mesh_format::off, Status_code::invalid_mesh, 0),
            "the mesh has no faces");
}

TEST(IoOffErrors, UnknownOrUnsupportedHeaders) {
  std::string m =
      read_error("PLY\n4 4 0\n", Mesh_format::off, Status_code::parse_error, 1);
  EXPECT_NE(m.find("unknown OFF header 'PLY'"), std::string::npos) << m;
  m = read_error("# comment\n8 6 0\n", Mesh_format::off,
                 Status_code::parse_error, 2);
  EXPECT_NE(m.find("unknown OFF header '8'"), std::string::npos) << m;
  m = read_error("NCOFF\n4 4 0\n", Mesh_format::off, Status_code::parse_error,
                 1);  // letters out of order
  EXPECT_NE(m.find("unknown OFF header 'NCOFF'"), std::string::npos) << m;
  m = read_error("4OFF\n4 4 0\n", Mesh_format::off, Status_code::parse_error,
                 1);
  EXPECT_EQ(
      m, "line 1: 4D OFF (4OFF) is not supported: SubdivLab reads 3D meshes");
  m = read_error("nOFF\n3\n4 4 0\n", Mesh_format::off, Status_code::parse_error,
                 1);
  EXPECT_NE(m.find("nOFF (nOFF, dimension given in the file) is not supported"),
            std::string::npos)
      << m;
  m = read_error("OFF BINARY\n", Mesh_format::off, Status_code::parse_error, 1);
  EXPECT_NE(m.find("binary OFF is not supported"), std::string::npos) << m;
  m = read_error("", Mesh_format::off, Status_code::parse_error, 0);
  EXPECT_EQ(m, "the file is empty: no OFF header");
  m = read_error("\n# only a comment\n", Mesh_format::off,
                 Status_code::parse_error, 0);
  EXPECT_EQ(m, "the file is empty: no OFF header");
}

TEST(IoOffErrors, HugeDeclaredCountsDoNotAllocate) {
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(read_error("OFF 2000000000 2000000000 0\n", Mesh_format::off,
                       Status_code::parse_error, 1),
            "line 1: file ends after 0 of 2000000000 vertices");
  // Declared far beyond the data, with real data after it: still a clean
  // error, not bad_alloc (reserve is bounded by the text length).
  EXPECT_EQ(read_error("OFF\n2000000000 2000000000 0\n" + tetra_vertices,
                       Mesh_format::off, Status_code::parse_error, 6),
            "line 6: file ends after 4 of 2000000000 vertices");
  EXPECT_EQ(read_error("OFF\n4 4000000000 0\n" + tetra_vertices + tetra_faces,
                       Mesh_format::off, Status_code::parse_error, 10),
            "line 10: file ends after 4 of 4000000000 faces");
  EXPECT_EQ(read_error("OFF\n99999999999 1 0\n", Mesh_format::off,
                       Status_code::parse_error, 2),
            "line 2: vertex count 99999999999 is too large");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
}

TEST(IoOffErrors, ModuleKeepsWorkingAfterAnError) {
  EXPECT_FALSE(
      read_mesh("OFF\n1 1 0\nnan 0 0\n3 0 0 0\n", Mesh_format::off).ok());
  EXPECT_EQ(read_ok(fixture_text("cube.off"), Mesh_format::off).face_count(),
            6u);
}

// ------------------------------------------------------------ valid OBJ

TEST(IoObj, ReadsTheCubeFixtureWithTextureAndNormalIndices) {
  const Mesh_buffers obj = read_ok(fixture_text("cube.obj"), Mesh_format::obj);
  const Mesh_buffers off = read_ok(fixture_text("cube.off"), Mesh_format::off);
  EXPECT_EQ(obj.positions, off.positions);
  EXPECT_EQ(obj.face_sizes, off.face_sizes);
  EXPECT_EQ(obj.face_indices, off.face_indices);
}

TEST(IoObj, AllCornerFormsGiveTheSameFace) {
  const std::string v =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n";
  const std::string text = v +
                           "f 1 3 2\n"
                           "f 1/1 2/2 4/3\n"
                           "f 1//1 4//1 3//1\n"
                           "f 2/2/1 3/3/1 4/1/1\n";
  const Mesh_buffers m = read_ok(text, Mesh_format::obj);
  EXPECT_EQ(m.face_indices,
            (std::vector<std::uint32_t>{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}));
}

TEST(IoObj, NegativeRelativeIndices) {
  const std::string text =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n"
      "v 5 5 5\nv 6 5 5\nv 5 6 5\nf -3/-1 -2/-1 -1/-1\n";
  const Mesh_buffers m = read_ok(text, Mesh_format::obj);
  EXPECT_EQ(m.vertex_count(), 6u);
  EXPECT_EQ(m.face_indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(m.positions[9], 5.0);
}

TEST(IoObj, QuadsAndNgons) {
  const std::string text =
      "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 0 1 0\nv 1 2 0\n"
      "f 1 2 5 6\n"
      "f 2 3 4 5\n"
      "f 6 5 4 7\n";
  const Mesh_buffers m = read_ok(text, Mesh_format::obj);
  EXPECT_EQ(m.face_sizes, (std::vector<std::uint32_t>{4, 4, 4}));
  const std::string hexagon =
      "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 2 2 0\nv 0 2 0\nv -1 1 0\nf 1 2 3 4 5 6\n";
  EXPECT_EQ(read_ok(hexagon, Mesh_format::obj).face_sizes,
            (std::vector<std::uint32_t>{6}));
}

TEST(IoObj, IgnoredStatementsAndExtraVertexValues) {
  const std::string text =
      "# exported\nmtllib scene.mtl\no thing\ng group1 group2\ns 1\nusemtl "
      "red\n"
      "v 0 0 0 1\n"               // w
      "v 1 0 0 0.5 0.25 0.125\n"  // vertex colour
      "v 0 1 0\n"
      "vt 0.5 0.5\nvn 0 0 1\nvp 0.1 0.2\n"
      "l 1 2\np 3\ns off\n"
      "f 1 2 3\n";
  const Mesh_buffers m = read_ok(text, Mesh_format::obj);
  EXPECT_EQ(m.positions, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0}));
  EXPECT_EQ(m.face_count(), 1u);
}

TEST(IoObj, CrlfBomTabsAndScientificNotation) {
  const std::string text =
      "\xEF\xBB\xBFv\t1e-3 -2.5E2 +0.5\r\nv 1 0 0\r\nv 0 1 0\r\n\r\nf\t1 "
      "2\t3\r\n";
  const Mesh_buffers m = read_ok(text, Mesh_format::obj);
  EXPECT_EQ(m.positions[0], 0.001);
  EXPECT_EQ(m.positions[1], -250.0);
  EXPECT_EQ(m.positions[2], 0.5);
}

TEST(IoObj, FacesMayUseVerticesDefinedLater) {
  const Mesh_buffers m =
      read_ok("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", Mesh_format::obj);
  EXPECT_EQ(m.face_indices, (std::vector<std::uint32_t>{0, 1, 2}));
}

// ------------------------------------------- OBJ as course files write it

// tests/fixtures/course.obj (make_fixtures.py): a house, a 2 x 2 x 2 box with
// a ridge roof, in every form at once (mtllib, o, g, s, usemtl, v with w and
// with a colour, vt, vn, v/vt/vn, v//vn, v/vt, negative indices, backslash
// continuations, comments, CRLF). Counted by hand: 10 vertices, 7 faces
// (floor, two pentagonal gables, two roof quads, two walls), 30 corners.
TEST(IoObjCourse, TheCourseFixtureReadsWithItsCountsAndNumbers) {
  const std::string text = fixture_text("course.obj");
  ASSERT_NE(text.find("\r\n"), std::string::npos) << "CRLF lost";
  for (const Result<Mesh_buffers>& r :
       {read_mesh(text, Mesh_format::obj),
        detail::read_mesh_general(text, Mesh_format::obj)}) {
    ASSERT_TRUE(r.ok()) << r.status.message;
    const Mesh_buffers& m = r.value;
    EXPECT_EQ(m.vertex_count(), 10u);
    EXPECT_EQ(m.face_count(), 7u);
    EXPECT_EQ(m.face_sizes, (std::vector<std::uint32_t>{4, 5, 5, 4, 4, 4, 4}));
    EXPECT_EQ(m.face_indices,
              (std::vector<std::uint32_t>{0, 3, 2, 1,     // floor, v/vt/vn
                                          0, 1, 5, 8, 4,  // v//vn, continued
                                          2, 3, 7, 9, 6,  // v/vt
                                          5, 6, 9, 8,     // -5 -4 -1 -2
                                          4, 8, 9, 7,     // -6/-1/-1 ...
                                          1, 2, 6, 5,     // plain, comment
                                          3, 0, 4, 7}));  // continued twice
    EXPECT_EQ(m.positions, (std::vector<double>{0, 0, 0, 2, 0, 0, 2, 2, 0, 0,
                                                2, 0, 0, 0, 2, 2, 0, 2, 2, 2,
                                                2, 0, 2, 2, 1, 0, 3, 1, 2, 3}));
  }
}

TEST(IoObjCourse, ABackslashContinuesTheStatementOnTheNextLine) {
  const std::string v = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
  const std::vector<std::uint32_t> quad = {0, 1, 2, 3};
  // The backslash separates tokens ("2\" then "3" is 2 and 3, not 23);
  // blanks and a comment may follow it; LF, CRLF and lone CR end lines; a
  // continuation line may be empty; the file may end after the backslash.
  for (const std::string& face :
       {std::string("f 1 2 \\\n3 4\n"), std::string("f 1 2\\\n3 4\n"),
        std::string("f 1 2 \\  \t\n  3 4\n"),
        std::string("f 1 2 \\ # more below\n3 4\n"),
        std::string("f 1 2 \\\r\n3 4\r\n"), std::string("f 1 2 \\\r3 4\r"),
        std::string("f 1 \\\n2 \\\n\\\n3 \\\n4"),
        std::string("f \\\n 1 2 3 4\n"), std::string("f 1 2 3 4 \\"),
        std::string("f 1 2 3 4 \\\n"), std::string("\\\nf 1 2 3 4\n")}) {
    for (const bool fast : {true, false}) {
      const std::string text = v + face;
      const Result<Mesh_buffers> r =
          fast ? read_mesh(text, Mesh_format::obj)
               : detail::read_mesh_general(text, Mesh_format::obj);
      ASSERT_TRUE(r.ok()) << face << ": " << r.status.message;
      EXPECT_EQ(r.value.face_indices, quad) << face;
    }
  }
  // A continued vertex; a backslash inside a comment continues nothing.
  const Mesh_buffers m = read_ok(
      "v 0 0 \\\n 0 1\nv 1 0 0 # not continued \\\nv 1 1 0\nv 0 1 0\n"
      "f 1 2 3 4\n",
      Mesh_format::obj);
  EXPECT_EQ(m.positions,
            (std::vector<double>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}));
}

TEST(IoObjCourse, LinesAfterAContinuationKeepTheirNumbers) {
  const std::string v = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
  // Lines 5-7 are one face; line 8 is the next statement.
  EXPECT_EQ(read_error(v + "f 1 2 \\\n3 \\\r\n4\nq 1\n", Mesh_format::obj,
                       Status_code::parse_error, 8),
            "line 8: unknown OBJ statement 'q'");
  // A face read by the fast path after a continued one names its own line.
  EXPECT_EQ(read_error(v + "f 1 2 \\\n3 4\nf 1 2 3\n", Mesh_format::obj,
                       Status_code::inconsistent_orientation, 7),
            "line 7: inconsistent orientation: the faces on lines 5 and 7 both "
            "use edge 1\u21922 in the same direction; turning 1 face around "
            "makes them agree (repair orientation)");
  // A continued face is named by the line it starts on.
  EXPECT_EQ(read_error(v + "f 1 2 3\nf 1 \\\n2 4\n", Mesh_format::obj,
                       Status_code::inconsistent_orientation, 6),
            "line 6: inconsistent orientation: the faces on lines 5 and 6 both "
            "use edge 1\u21922 in the same direction; turning 1 face around "
            "makes them agree (repair orientation)");
}

TEST(IoObjCourse, AContinuedStatementRefusedNamesItsLines) {
  const std::string v = "v 0 0 0\nv 1 0 0\nv 1 1 0\n";
  // The status keeps the first line; the message says where it runs to.
  for (const bool fast : {true, false}) {
    const auto read = [fast](const std::string& text) {
      return fast ? read_mesh(text, Mesh_format::obj)
                  : detail::read_mesh_general(text, Mesh_format::obj);
    };
    Result<Mesh_buffers> r = read(v + "f 1 2 \\\n x\n");
    EXPECT_EQ(r.status.code, Status_code::parse_error);
    EXPECT_EQ(r.status.line, 4);
    EXPECT_EQ(r.status.message,
              "line 4 (continued to line 5): 'x' is not a face vertex "
              "(expected v, v/vt, v//vn or v/vt/vn)");
    r = read(v + "v 1 \\\r\n2 \\\r\n\\\r\nabc\r\n");
    EXPECT_EQ(r.status.line, 4);
    EXPECT_EQ(r.status.message,
              "line 4 (continued to line 7): z coordinate of vertex 4 is not a "
              "number: 'abc'");
    r = read(v + "f 1 2 \\\n-9\n");
    EXPECT_EQ(r.status.code, Status_code::invalid_mesh);
    EXPECT_EQ(r.status.line, 4);
    EXPECT_EQ(r.status.message,
              "line 4 (continued to line 5): relative face index -9 is out of "
              "range (3 vertices defined so far)");
    // Only the statement's lines count: the file's last line does not.
    r = read(v + "v 1 2 \\\n\n\n");
    EXPECT_EQ(r.status.message,
              "line 4 (continued to line 5): vertex needs 3 coordinates, "
              "found 2");
  }
}

TEST(IoObjCourse, OtherFormsAreStillRefusedWithTheirLine) {
  const std::string v = "v 0 0 0\nv 1 0 0\nv 1 1 0\n";
  EXPECT_EQ(read_error(v + "f 1 2 3/2/3/4\n", Mesh_format::obj,
                       Status_code::parse_error, 4),
            "line 4: '3/2/3/4' is not a face vertex (expected v, v/vt, v//vn "
            "or v/vt/vn)");
  EXPECT_EQ(read_error(v + "f 1 2 -0\n", Mesh_format::obj,
                       Status_code::invalid_mesh, 4),
            "line 4: face index -0 is out of range (OBJ indices start at 1)");
  EXPECT_EQ(
      read_error(v + "v 1 2\n", Mesh_format::obj, Status_code::parse_error, 4),
      "line 4: vertex needs 3 coordinates, found 2");
  // A backslash that is not at the end of the data is a token of its own.
  EXPECT_EQ(read_error(v + "f 1 \\ 2 3\n", Mesh_format::obj,
                       Status_code::parse_error, 4),
            "line 4: '\\' is not a face vertex (expected v, v/vt, v//vn or "
            "v/vt/vn)");
  EXPECT_EQ(read_error(v + "f 1 2 3\\4\n", Mesh_format::obj,
                       Status_code::parse_error, 4),
            "line 4: '3\\4' is not a face vertex (expected v, v/vt, v//vn or "
            "v/vt/vn)");
  // A continuation joins lines; it does not make a comment's line data.
  EXPECT_EQ(read_error(v + "f 1 2 \\\n# the rest\n3\n", Mesh_format::obj,
                       Status_code::parse_error, 6),
            "line 6: unknown OBJ statement '3'");
}

TEST(IoObjCourse, OffHasNoContinuations) {
  // OFF's reader is untouched: a backslash there is a value, refused.
  EXPECT_EQ(read_error("OFF\n3 1 0\n0 0 \\\n0\n1 0 0\n0 1 0\n3 0 1 2\n",
                       Mesh_format::off, Status_code::parse_error, 3),
            "line 3: z coordinate of vertex 0 is not a number: '\\'");
}

// ------------------------------------------------------------ invalid OBJ

TEST(IoObjErrors, IndexOutOfRange) {
  const std::string text =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n# faces\n\nf 1 2 12\n";
  EXPECT_EQ(read_error(text, Mesh_format::obj, Status_code::invalid_mesh, 7),
            "line 7: face index 12 is out of range (4 vertices)");
  EXPECT_EQ(read_error("v 0 0 0\nv 1 0 0\nf 1 2 0\n", Mesh_format::obj,
                       Status_code::invalid_mesh, 3),
            "line 3: face index 0 is out of range (OBJ indices start at 1)");
  EXPECT_EQ(read_error("v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n",
                       Mesh_format::obj, Status_code::invalid_mesh, 3),
            "line 3: relative face index -3 is out of range (2 vertices "
            "defined so far)");
}

TEST(IoObjErrors, MalformedFaceVertex) {
  for (const char* bad : {"a", "1/2/3/4", "1.5", "1//", "/1", "1/x"}) {
    const std::string text =
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 " + std::string(bad) + "\n";
    EXPECT_EQ(
        read_error(text, Mesh_format::obj, Status_code::parse_error, 4),
        "line 4: '" + std::string(bad) +
            "' is not a face vertex (expected v, v/vt, v//vn or v/vt/vn)");
  }
}

TEST(IoObjErrors, FaceWithFewerThanThreeVertices) {
  EXPECT_EQ(read_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2\n",
                       Mesh_format::obj, Status_code::invalid_mesh, 5),
            "line 5: the face has 2 vertices; a face needs at least 3");
  EXPECT_EQ(read_error("v 0 0 0\nf\n", Mesh_format::obj,
                       Status_code::invalid_mesh, 2),
            "line 2: the face has 0 vertices; a face needs at least 3");
}

TEST(IoObjErrors, RepeatedVertexUsesTheFilesNumbers) {
  EXPECT_EQ(read_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 -2\n",
                       Mesh_format::obj, Status_code::invalid_mesh, 4),
            "line 4: the face uses vertex 2 more than once");
}

TEST(IoObjErrors, NonFiniteAndNonNumericCoordinates) {
  EXPECT_EQ(read_error("v 0 0 0\nv nan 0 0\n", Mesh_format::obj,
                       Status_code::parse_error, 2),
            "line 2: x coordinate of vertex 2 is not finite: 'nan'");
  EXPECT_EQ(read_error("v 0 0 0\nv 0 1e309 0\n", Mesh_format::obj,
                       Status_code::parse_error, 2),
            "line 2: y coordinate of vertex 2 is not finite: '1e309'");
  EXPECT_EQ(read_error("v 0 0 1.2.3\n", Mesh_format::obj,
                       Status_code::parse_error, 1),
            "line 1: z coordinate of vertex 1 is not a number: '1.2.3'");
  EXPECT_EQ(read_error("v 0 0 0 abc\n", Mesh_format::obj,
                       Status_code::parse_error, 1),
            "line 1: value 4 of vertex 1 is not a number: 'abc'");
  EXPECT_EQ(
      read_error("v 0 0\n", Mesh_format::obj, Status_code::parse_error, 1),
      "line 1: vertex needs 3 coordinates, found 2");
}

TEST(IoObjErrors, UnknownStatement) {
  EXPECT_EQ(read_error("v 0 0 0\nhello world\n", Mesh_format::obj,
                       Status_code::parse_error, 2),
            "line 2: unknown OBJ statement 'hello'");
}

TEST(IoObjErrors, TopologyProblemsUseTheFilesNumbersAndLines) {
  const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\n";
  EXPECT_EQ(read_error(v + "f 1 2 3\nf 2 1 4\nf 1 2 5\n", Mesh_format::obj,
                       Status_code::invalid_mesh, 8),
            "line 8: non-manifold edge between vertices 1 and 2: used by 3 "
            "faces (the faces on lines "
            "6, 7 and 8)");
  EXPECT_EQ(read_error(v + "f 1 2 3\nf 1 2 4\n", Mesh_format::obj,
                       Status_code::inconsistent_orientation, 7),
            "line 7: inconsistent orientation: the faces on lines 6 and 7 both "
            "use edge 1\u21922 in the "
            "same direction; turning 1 face around makes them agree (repair "
            "orientation)");
  const std::string bowtie =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv -1 0 0\nv -1 -1 0\nf 1 2 3\nf 1 4 5\n";
  EXPECT_EQ(read_error(bowtie, Mesh_format::obj, Status_code::invalid_mesh, 7),
            "line 7: non-manifold vertex 1: its faces form 2 separate fans "
            "that meet only at this "
            "vertex (the faces on lines 6 and 7)");
}

TEST(IoObjErrors, NoFaces) {
  EXPECT_EQ(read_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2 3\n", Mesh_format::obj,
                       Status_code::invalid_mesh, 0),
            "the mesh has no faces");
  EXPECT_EQ(read_error("", Mesh_format::obj, Status_code::invalid_mesh, 0),
            "the mesh has no faces");
}

// ------------------------------------------------------------ writing

TEST(IoWrite, OffTextIsExactlyAsSpecified) {
  Mesh_buffers m;
  m.positions = {0, 0, 0, 1, 0, 0, 0.1, 1.0 / 3.0, -2.5};
  m.face_sizes = {3};
  m.face_indices = {0, 1, 2};
  EXPECT_EQ(write_mesh(m, Mesh_format::off),
            "OFF\n3 1 0\n0 0 0\n1 0 0\n0.10000000000000001 0.33333333333333331 "
            "-2.5\n3 0 1 2\n");
  EXPECT_EQ(write_mesh(m, Mesh_format::obj),
            "v 0 0 0\nv 1 0 0\nv 0.10000000000000001 0.33333333333333331 "
            "-2.5\nf 1 2 3\n");
}

void expect_round_trip(const Mesh_buffers& m, Mesh_format format,
                       const std::string& what) {
  const Result<Mesh_buffers> back = read_mesh(write_mesh(m, format), format);
  ASSERT_TRUE(back.ok()) << what << ": " << back.status.message;
  EXPECT_EQ(back.value.face_sizes, m.face_sizes) << what;
  EXPECT_EQ(back.value.face_indices, m.face_indices) << what;
  ASSERT_EQ(back.value.positions.size(), m.positions.size()) << what;
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    // Bitwise equal, sign of zero included.
    EXPECT_EQ(back.value.positions[i], m.positions[i])
        << what << " coordinate " << i;
    EXPECT_EQ(std::signbit(back.value.positions[i]),
              std::signbit(m.positions[i]))
        << what;
  }
}

TEST(IoWrite, ReadBuildToBuffersGivesBackTheFileExactly) {
  for (const char* name :
       {"cube.off", "torus-tri.off", "mixed-open.off",
        "rhombicuboctahedron.off", "grid-open.off", "two-tetrahedra.off"}) {
    const Mesh_buffers in = read_ok(fixture_text(name), Mesh_format::off);
    Mesh mesh;
    ASSERT_TRUE(build_mesh(in, mesh).ok()) << name;
    const Mesh_buffers out = to_buffers(mesh);
    EXPECT_EQ(out.positions, in.positions) << name;
    EXPECT_EQ(out.face_sizes, in.face_sizes) << name;
    EXPECT_EQ(out.face_indices, in.face_indices) << name;
    EXPECT_EQ(write_mesh(out, Mesh_format::off),
              write_mesh(in, Mesh_format::off))
        << name;
  }
}

TEST(IoWrite, RoundTripOfEveryFixtureIsExact) {
  for (const char* name :
       {"tetrahedron.off", "cube.off", "octahedron.off", "icosahedron.off",
        "torus-quad.off", "torus-tri.off", "grid-open.off", "disk-tri.off",
        "mixed-open.off", "rhombicuboctahedron.off", "two-tetrahedra.off"}) {
    const Mesh_buffers m = read_ok(fixture_text(name), Mesh_format::off);
    expect_round_trip(m, Mesh_format::off, std::string(name) + " as OFF");
    expect_round_trip(m, Mesh_format::obj, std::string(name) + " as OBJ");
  }
}

TEST(IoWrite, RoundTripOfAwkwardDoublesIsExact) {
  Mesh_buffers m;
  m.positions = {0.1,
                 1.0 / 3.0,
                 -2.0 / 7.0,
                 1e-300,
                 -0.0,
                 123456789.123456789,
                 std::numeric_limits<double>::max(),
                 std::numeric_limits<double>::denorm_min(),
                 -std::numeric_limits<double>::min(),
                 6.02214076e23,
                 std::nextafter(1.0, 2.0),
                 -1e-17};
  m.face_sizes = {4};
  m.face_indices = {0, 1, 2, 3};
  expect_round_trip(m, Mesh_format::off, "awkward OFF");
  expect_round_trip(m, Mesh_format::obj, "awkward OBJ");
}

}  // namespace
}  // namespace subdivlab

namespace subdivlab {
namespace {

// The files in tests/fixtures/invalid serve the Node and CLI tests too;
// this pins what each one must report.
TEST(IoInvalidFixtures, EachFileReportsItsProblem) {
  struct Expect {
    const char* name;
    Status_code code;
    int line;
    const char* message;
  };
  const Expect cases[] = {
      {"index-out-of-range.off", Status_code::invalid_mesh, 8,
       "line 8: face index 12 is out of range (4 vertices)"},
      {"truncated.off", Status_code::parse_error, 7,
       "line 7: file ends after 5 of 8 vertices"},
      {"non-finite.off", Status_code::parse_error, 4,
       "line 4: y coordinate of vertex 1 is not finite: 'nan'"},
      {"non-manifold-edge.off", Status_code::invalid_mesh, 10,
       "line 10: non-manifold edge between vertices 0 and 1: used by 3 faces "
       "(the faces on lines 8, 9 and 10)"},
      {"non-manifold-vertex.off", Status_code::invalid_mesh, 9,
       "line 9: non-manifold vertex 0: its faces form 2 separate fans that "
       "meet only at this vertex (the faces on lines 8 and 9)"},
      {"inconsistent-orientation.off", Status_code::inconsistent_orientation, 8,
       "line 8: inconsistent orientation: the faces on lines 7 and 8 both use "
       "edge 0\u21921 in the same direction; turning 1 face around makes "
       "them agree (repair orientation)"},
      {"extra-data.off", Status_code::parse_error, 10,
       "line 10: extra data after the 3 faces the header declares (header "
       "counts disagree with the data)"},
      {"no-faces.off", Status_code::invalid_mesh, 0, "the mesh has no faces"},
      {"huge-counts.off", Status_code::parse_error, 1,
       "line 1: file ends after 0 of 2000000000 vertices"},
      {"unknown-header.off", Status_code::parse_error, 1,
       "line 1: unknown OFF header 'PLY' (expected OFF, COFF, NOFF, CNOFF, "
       "STOFF or another [ST][C][N]OFF variant)"},
      {"repeated-vertex.obj", Status_code::invalid_mesh, 4,
       "line 4: the face uses vertex 3 more than once"},
      {"face-too-small.obj", Status_code::invalid_mesh, 4,
       "line 4: the face has 2 vertices; a face needs at least 3"},
      {"non-numeric.obj", Status_code::parse_error, 2,
       "line 2: y coordinate of vertex 2 is not a number: 'abc'"},
  };
  for (const Expect& e : cases) {
    const std::string name = e.name;
    const Mesh_format format = name.substr(name.size() - 4) == ".obj"
                                   ? Mesh_format::obj
                                   : Mesh_format::off;
    const Result<Mesh_buffers> r =
        read_mesh(fixture_text("invalid/" + name), format);
    EXPECT_EQ(r.status.code, e.code) << name << ": " << r.status.message;
    EXPECT_EQ(r.status.line, e.line) << name;
    EXPECT_EQ(r.status.message, e.message) << name;
  }
}

}  // namespace
}  // namespace subdivlab
