// What the fuzz targets (tests/fuzz) found, each pinned on the input they
// found it with (reduced by hand; the files are in tests/fixtures/invalid).

#include <gtest/gtest.h>

#include <string>

#include "core/custom_rules.h"
#include "core/mesh_io.h"
#include "core/subdivide.h"
#include "fixture_text.h"

namespace subdivlab {
namespace {

// fuzz_ply: a message named an element as the header spelt it, control
// bytes and all, into the one line a CLI prints. Now escaped as the tokens
// of the file are.
TEST(FuzzFindings, APlyElementNameIsEscapedInMessages) {
  const Result<Mesh_buffers> r = read_mesh(
      fixture_text("invalid/element-name-control-byte.ply"), Mesh_format::ply);
  EXPECT_EQ(r.status.code, Status_code::parse_error);
  EXPECT_EQ(r.status.line, 16);
  EXPECT_EQ(r.status.message,
            "line 16: '&&&&' is not a float value for 'name' of "
            "ma\\x1Frial 0 (of 1)");
}

// fuzz_obj: faces turned inconsistently were reported first (the app then
// offers to repair them), and the repaired read failed on a corner tag out
// of range. The tag, which no repair mends, is now named first, with the
// repair or without.
TEST(FuzzFindings, ABadTagIsNamedBeforeARepairableOrientation) {
  const std::string text =
      fixture_text("invalid/inconsistent-orientation-bad-tag.obj");
  const char* message =
      "line 10: tag 'corner': vertex 9 is out of range (4 vertices; tag "
      "indices start at 0)";
  const Result<Mesh_buffers> r = read_mesh(text, Mesh_format::obj);
  EXPECT_EQ(r.status.code, Status_code::parse_error);
  EXPECT_EQ(r.status.line, 10);
  EXPECT_EQ(r.status.message, message);
  Read_options repair;
  repair.repair_orientation = true;
  const Result<Mesh_buffers> repaired =
      read_mesh(text, Mesh_format::obj, nullptr, repair);
  EXPECT_EQ(repaired.status.code, Status_code::parse_error);
  EXPECT_EQ(repaired.status.message, message);
  // Without the tag line the same faces are the repairable refusal still.
  const std::string untagged = text.substr(0, text.find("t corner"));
  const Result<Mesh_buffers> u = read_mesh(untagged, Mesh_format::obj);
  EXPECT_EQ(u.status.code, Status_code::inconsistent_orientation);
  EXPECT_EQ(u.status.line, 9);
}

// fuzz_rules: an unknown host was quoted as given, so a rule set could put
// a NUL or a terminal escape into the message.
TEST(FuzzFindings, AnUnknownHostIsEscapedInTheMessage) {
  Custom_rules r = custom_rules_preset("loop", 6);
  r.host = std::string("a\x1b[2J\0b", 7);
  const Status s = check_custom_rules(r);
  EXPECT_EQ(s.code, Status_code::invalid_argument);
  EXPECT_EQ(s.message,
            "custom rules: unknown host \"a\\x1B[2J\\x00b\" (expected pqq, "
            "ptq, dqq or sqrt3)");
}

// fuzz_schemes: predict_size refused a mesh with an interior vertex of two
// edges for loop with triangulate, while the run, which checks the mesh
// once triangulated (the quad's diagonal gives that vertex a third edge),
// refined it. The prediction now checks the triangulated mesh too.
TEST(FuzzFindings, PredictSizeChecksATriangulatedMeshAsTheRunDoes) {
  const Result<Mesh_buffers> in = read_mesh(
      fixture_text("two-edge-vertex-triangulated.obj"), Mesh_format::obj);
  ASSERT_TRUE(in.ok()) << in.status.message;
  Subdivide_options o;
  o.scheme = "loop";
  o.levels = 2;
  o.triangulate = true;
  const Result<Mesh_buffers> run = subdivide_mesh(in.value, o);
  ASSERT_TRUE(run.ok()) << run.status.message;
  const Result<Size_prediction> p = predict_size(in.value, o);
  ASSERT_TRUE(p.ok()) << p.status.message;
  // Triangulated: 4 vertices, 6 edges, 3 triangles (a disk); Loop gives
  // V + E vertices and 4 F faces a step: 10 and 12, then 31 and 48.
  EXPECT_EQ(run.value.vertex_count(), 31u);
  EXPECT_EQ(run.value.face_count(), 48u);
  EXPECT_EQ(p.value.vertices, 31u);
  EXPECT_EQ(p.value.faces, 48u);
  // Not triangulated, loop refuses the mesh in both; Catmull-Clark takes
  // the vertex of two edges as it is.
  o.triangulate = false;
  EXPECT_FALSE(predict_size(in.value, o).ok());
  EXPECT_FALSE(subdivide_mesh(in.value, o).ok());
  o.scheme = "catmull-clark";
  EXPECT_TRUE(predict_size(in.value, o).ok());
  EXPECT_TRUE(subdivide_mesh(in.value, o).ok());
}

// fuzz_schemes: Loop with triangulate never returned on a hexagon that
// touches itself (a corner on another of its sides). CGAL's triangulate_face
// accepted it and linked two triangles' halfedges into one cycle, which a
// later degree() walked forever. Such a face is now refused, named.
TEST(FuzzFindings, AHexagonThatTouchesItselfIsRefusedNotTriangulated) {
  const Result<Mesh_buffers> in =
      read_mesh(fixture_text("touching-hexagon.obj"), Mesh_format::obj);
  ASSERT_TRUE(in.ok()) << in.status.message;
  Subdivide_options o;
  o.scheme = "loop";
  o.levels = 1;
  o.triangulate = true;
  const char* message =
      "face 0 (6 vertices) could not be triangulated: it is degenerate (no "
      "area), self-intersecting or touches itself; loop needs triangles";
  const Result<Mesh_buffers> run = subdivide_mesh(in.value, o);
  EXPECT_EQ(run.status.code, Status_code::invalid_mesh);
  EXPECT_EQ(run.status.message, message);
  const Result<Size_prediction> p = predict_size(in.value, o);
  EXPECT_EQ(p.status.code, Status_code::invalid_mesh);
  EXPECT_EQ(p.status.message, message);
  // Schemes on polygons take it as it is: Catmull-Clark makes 6 + 4 quads
  // of the hexagon and the quad.
  o.scheme = "catmull-clark";
  o.triangulate = false;
  const Result<Mesh_buffers> quads = subdivide_mesh(in.value, o);
  ASSERT_TRUE(quads.ok()) << quads.status.message;
  EXPECT_EQ(quads.value.face_count(), 10u);
}

}  // namespace
}  // namespace subdivlab
