// Inputs a hostile user or a careless exporter produces that are valid by
// the letter of the format but break naive arithmetic or messages.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/mesh_io.h"
#include "core/subdivide.h"

namespace subdivlab {
namespace {

/// A single quad whose corners reach `c` (finite, but near the largest
/// double), read from OFF text as a user's file would be.
Mesh_buffers huge_quad(const std::string& c) {
  const std::string text = "OFF\n4 1 0\n0 0 0\n" + c + " 0 0\n" + c + " " + c +
                           " 0\n0 " + c + " 0\n4 0 1 2 3\n";
  Result<Mesh_buffers> r = read_mesh(text, Mesh_format::off);
  EXPECT_TRUE(r.ok()) << r.status.message;
  return r.value;
}

TEST(HostileInput, CoordinatesNearTheLargestDoubleOverflowWithAMessage) {
  // Catmull-Clark's face point sums the four corners: 2 * 1.7e308 is inf.
  Subdivide_options o;
  o.scheme = "catmull-clark";
  o.levels = 1;
  const Result<Mesh_buffers> r = subdivide_mesh(huge_quad("1.7e308"), o);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status.code, Status_code::invalid_mesh);
  EXPECT_EQ(r.status.message,
            "level 1 of catmull-clark overflows: a new coordinate is not "
            "finite (the input's coordinates reach 1.7e+308; coordinates or "
            "weights this large exceed double precision arithmetic, scale "
            "the mesh down)");
}

TEST(HostileInput, NoSchemeHandsOutNonFiniteCoordinates) {
  for (const char* scheme : {"catmull-clark", "loop", "doo-sabin", "sqrt3",
                             "quad-triangle", "linear", "linear-tri"}) {
    SCOPED_TRACE(scheme);
    Subdivide_options o;
    o.scheme = scheme;
    o.levels = 2;
    o.triangulate = true;
    const Result<Mesh_buffers> r = subdivide_mesh(huge_quad("1.7e308"), o);
    if (r.ok()) {
      for (double x : r.value.positions) ASSERT_TRUE(std::isfinite(x));
    } else {
      EXPECT_EQ(r.status.code, Status_code::invalid_mesh);
      EXPECT_EQ(r.status.message.find(std::string("of ") + scheme +
                                      " overflows: a new coordinate is not "
                                      "finite"),
                std::string("level 1 ").size())
          << r.status.message;
    }
  }
}

TEST(HostileInput, LargeButSafeCoordinatesStillSubdivide) {
  // 1e300 leaves room for the sums: the check must not refuse it.
  Subdivide_options o;
  o.scheme = "catmull-clark";
  o.levels = 2;
  const Result<Mesh_buffers> r = subdivide_mesh(huge_quad("1e300"), o);
  ASSERT_TRUE(r.ok()) << r.status.message;
  EXPECT_EQ(r.value.vertex_count(), 25u);
  // The centre of the square is a face point at level 1 and stays put.
  bool centre = false;
  for (std::size_t v = 0; v < r.value.vertex_count(); ++v)
    centre |= r.value.positions[3 * v] == 0.5e300 &&
              r.value.positions[3 * v + 1] == 0.5e300;
  EXPECT_TRUE(centre);
}

TEST(HostileInput, QuotedTokensCarryNoControlBytes) {
  // ESC [ 2 J clears a terminal; a NUL ends a C string. Both are written as
  // \xNN in the one-line message, which keeps the token recognisable.
  const std::string text = std::string("v 0 0 \x1b[2J\n") + "v 1 0 0\nv 0 1 " +
                           std::string(1, '\0') + "\nf 1 2 3\n";
  Result<Mesh_buffers> r = read_mesh(text, Mesh_format::obj);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status.message,
            "line 1: z coordinate of vertex 1 is not a number: '\\x1B[2J'");
  r = read_mesh("v 0 0 0\nv 1 0 0\nv 0 1 " + std::string(1, '\0') + "\n",
                Mesh_format::obj);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status.message,
            "line 3: z coordinate of vertex 3 is not a number: '\\x00'");
}

TEST(HostileInput, LongTokensAreNotCutInsideAUtf8Character) {
  // 39 ASCII bytes then "\u00e9" (2 bytes): cutting at 40 bytes would leave
  // half a character, which a UTF-8 decoder turns into U+FFFD.
  const std::string token = std::string(39, 'a') + "\xC3\xA9" + "zz";
  const Result<Mesh_buffers> r =
      read_mesh(token + " 1 2 3\n", Mesh_format::obj);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status.message,
            "line 1: unknown OBJ statement '" + std::string(39, 'a') + "...'");
}

TEST(HostileInput, CheckWritableRefusesBuffersWriteMeshWouldReadPast) {
  Mesh_buffers m;
  m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  m.face_sizes = {3};
  m.face_indices = {0, 1, 2};
  EXPECT_TRUE(check_writable(m).ok());

  m.face_sizes = {40};  // write_mesh would read 37 indices past the array
  Status s = check_writable(m);
  EXPECT_EQ(s.code, Status_code::invalid_mesh);
  EXPECT_EQ(s.message, "face sizes add up to 40 indices but there are 3");

  m.face_sizes = {3};
  m.face_indices = {0, 1, 7};
  s = check_writable(m);
  EXPECT_EQ(s.code, Status_code::invalid_mesh);
  EXPECT_EQ(s.message, "vertex index 7 is out of range (3 vertices)");

  m.face_indices = {0, 1, 2};
  m.positions.push_back(5);
  s = check_writable(m);
  EXPECT_EQ(s.code, Status_code::invalid_mesh);
  EXPECT_EQ(s.message, "positions hold 10 numbers, not a multiple of 3");

  m.positions.pop_back();
  m.positions[7] = std::nan("");
  s = check_writable(m);
  EXPECT_EQ(s.code, Status_code::invalid_mesh);
  EXPECT_EQ(s.message, "vertex 2 has a non-finite coordinate");
}

TEST(HostileInput, ARepeatedControlEdgeIsRefusedNotCountedTwice) {
  // The unit square; its edge 0-1 given twice, once in each direction.
  Mesh_buffers m;
  m.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  m.face_sizes = {4};
  m.face_indices = {0, 1, 2, 3};
  m.control_edges = {0, 1, 1, 0};
  Subdivide_options o;
  o.scheme = "catmull-clark";
  o.levels = 2;
  o.start_level = 1;
  Result<Mesh_buffers> r = subdivide_mesh(m, o);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status.code, Status_code::invalid_argument);
  EXPECT_EQ(r.status.message,
            "control edge 1 (1, 0) repeats an earlier control edge");
  // Given once, it becomes 2^2 marked edges.
  m.control_edges = {0, 1};
  r = subdivide_mesh(m, o);
  ASSERT_TRUE(r.ok()) << r.status.message;
  EXPECT_EQ(r.value.control_edges.size(), 2u * 4u);
}

TEST(HostileInput, AFaceTriangulationRefusesIsNamed) {
  // A triangle, then a quad on its edge 0-1 whose corners all lie on the x
  // axis: valid topology, but no normal to triangulate by.
  Mesh_buffers m;
  m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, -1, 0, 0, 2, 0, 0};
  m.face_sizes = {3, 4};
  m.face_indices = {0, 1, 2, 1, 0, 3, 4};
  Subdivide_options o;
  o.scheme = "loop";
  o.triangulate = true;
  Result<Mesh_buffers> r = subdivide_mesh(m, o);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status.code, Status_code::invalid_mesh);
  EXPECT_EQ(r.status.message,
            "face 1 (4 vertices) could not be triangulated: it is degenerate "
            "(no area), self-intersecting or touches itself; loop needs "
            "triangles");

  // A pentagon whose second corner lies far beyond the others: its outline
  // crosses itself, which the constrained Delaunay triangulation refuses.
  const Result<Mesh_buffers> pentagon = read_mesh(
      "OFF\n5 1 0\n1 1 0\n2 12147483648 0\n2 2 0\n1.5 2.25 0\n1 2 0\n"
      "5 0 1 2 3 4\n",
      Mesh_format::off);
  ASSERT_TRUE(pentagon.ok()) << pentagon.status.message;
  o.scheme = "sqrt3";
  r = subdivide_mesh(pentagon.value, o);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status.message,
            "face 0 (5 vertices) could not be triangulated: it is degenerate "
            "(no area), self-intersecting or touches itself; sqrt3 needs "
            "triangles");
}

}  // namespace
}  // namespace subdivlab
