// OpenSubdiv's tags in OBJ ("t crease 2/1/0 0 1 2") and OFF ("# t ..."
// comments after the faces): each kind read into Mesh_tags, each malformed
// line refused with its message and line, unapplied tags noted, exact
// round trips, and random tag lines that are either read or refused on
// their own line.

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/mesh_io.h"
#include "fixture_text.h"

namespace subdivlab {
namespace {

/// The cube [0,1]^3 as in cube-creased.obj: 8 "v" lines, then 6 "f" lines
/// (lines 1-14); a tag appended to it is on line 15. Its edges: 0-1, 0-2,
/// 0-4, 1-3, 1-5, 2-3, 2-6, 3-7, 4-5, 4-6, 5-7, 6-7.
const std::string cube_obj =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\n"
    "v 1 1 1\nf 2 1 3 4\nf 3 1 5 7\nf 4 3 7 8\nf 5 1 2 6\nf 6 2 4 8\n"
    "f 7 5 6 8\n";
/// The same cube as OFF: header and counts (lines 1-2), vertices (3-10),
/// faces (11-16); a tag comment appended to it is on line 17.
const std::string cube_off =
    "OFF\n8 6 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n"
    "4 1 0 2 3\n4 2 0 4 6\n4 3 2 6 7\n4 4 0 1 5\n4 5 1 3 7\n4 6 4 5 7\n";

Mesh_tags tags_of(const std::string& text, Mesh_format format) {
  const Result<Mesh_buffers> r = read_mesh(text, format);
  EXPECT_TRUE(r.ok()) << r.status.message;
  return r.value.tags;
}

using Indices = std::vector<std::uint32_t>;
using Floats = std::vector<float>;

// ------------------------------------------------------------ each kind

TEST(IoTags, ReadsEachKindFromObj) {
  const Mesh_tags t = tags_of(cube_obj +
                                  "t crease 2/1/0 4 5 2\n"
                                  "t crease 4/2/0 5 7 1 3 3.5 10\n"
                                  "t corner 2/1/0 6 0 4.25\n"
                                  "t hole 3/0/0 5 1 3\n"
                                  "t interpolateboundary 1/0/0 1\n"
                                  "t creasemethod 0/0/1 chaikin\n",
                              Mesh_format::obj);
  EXPECT_EQ(t.crease_edges, (Indices{4, 5, 5, 7, 1, 3}));
  EXPECT_EQ(t.crease_sharpness, (Floats{2.0f, 3.5f, 10.0f}));
  EXPECT_EQ(t.corner_vertices, (Indices{6, 0}));
  EXPECT_EQ(t.corner_sharpness, (Floats{4.25f, 4.25f}));
  EXPECT_EQ(t.holes, (Indices{1, 3, 5}));
  EXPECT_EQ(t.boundary, Boundary_interpolation::edge_and_corner);
  EXPECT_TRUE(t.boundary_given);
  EXPECT_EQ(t.crease_method, Crease_method::chaikin);
  EXPECT_TRUE(t.crease_method_given);
  EXPECT_TRUE(t.notes.empty());
}

TEST(IoTags, InterpolateBoundaryValuesAndNormalCreasing) {
  const Mesh_tags none =
      tags_of(cube_obj + "t interpolateboundary 1/0/0 0\n", Mesh_format::obj);
  EXPECT_EQ(none.boundary, Boundary_interpolation::none);
  const Mesh_tags edge = tags_of(cube_obj +
                                     "t interpolateboundary 1/0/0 2\n"
                                     "t creasemethod 0/0/1 normal\n",
                                 Mesh_format::obj);
  EXPECT_EQ(edge.boundary, Boundary_interpolation::edge_only);
  EXPECT_TRUE(edge.boundary_given);
  EXPECT_EQ(edge.crease_method, Crease_method::uniform);
  EXPECT_TRUE(edge.crease_method_given);
  EXPECT_TRUE(edge.empty());  // the defaults, given
  EXPECT_TRUE(edge.present());
}

TEST(IoTags, AFileWithoutTagsHasNone) {
  const Mesh_tags t = tags_of(cube_obj, Mesh_format::obj);
  EXPECT_TRUE(t.empty());
  EXPECT_FALSE(t.present());
  EXPECT_FALSE(t.boundary_given);
  EXPECT_FALSE(t.crease_method_given);
}

TEST(IoTags, RepeatedEdgeKeepsItsPlaceAndTakesTheLastValue) {
  const Mesh_tags t = tags_of(cube_obj +
                                  "t crease 2/1/0 0 1 1\n"
                                  "t crease 2/1/0 4 5 2\n"
                                  "t crease 2/1/0 1 0 7\n"  // reversed
                                  "t corner 1/1/0 3 1\n"
                                  "t corner 2/2/0 3 3 2 5\n",
                              Mesh_format::obj);
  EXPECT_EQ(t.crease_edges, (Indices{0, 1, 4, 5}));
  EXPECT_EQ(t.crease_sharpness, (Floats{7.0f, 2.0f}));
  EXPECT_EQ(t.corner_vertices, (Indices{3}));
  EXPECT_EQ(t.corner_sharpness, (Floats{5.0f}));
}

TEST(IoTags, SharpnessZeroIsSmoothAndDropped) {
  const Mesh_tags t = tags_of(cube_obj +
                                  "t crease 4/2/0 0 1 4 5 0 2\n"
                                  "t crease 2/1/0 6 7 3\n"
                                  "t crease 2/1/0 6 7 0\n"  // last wins: smooth
                                  "t corner 2/1/0 1 2 0\n",
                              Mesh_format::obj);
  EXPECT_EQ(t.crease_edges, (Indices{4, 5}));
  EXPECT_EQ(t.crease_sharpness, (Floats{2.0f}));
  EXPECT_TRUE(t.corner_vertices.empty());
  EXPECT_TRUE(t.corner_sharpness.empty());
}

TEST(IoTags, InfinitelySharpValuesAreKeptAsGiven) {
  const Mesh_tags t = tags_of(cube_obj +
                                  "t crease 4/2/0 0 1 4 5 10 1e30\n"
                                  "t corner 1/1/0 2 11.5\n",
                              Mesh_format::obj);
  EXPECT_EQ(t.crease_sharpness, (Floats{10.0f, 1e30f}));
  EXPECT_EQ(t.corner_sharpness, (Floats{11.5f}));
}

TEST(IoTags, HolesAscendingOnceEach) {
  const Mesh_tags t = tags_of(
      cube_obj + "t hole 3/0/0 4 0 4\nt hole 2/0/0 2 0\n", Mesh_format::obj);
  EXPECT_EQ(t.holes, (Indices{0, 2, 4}));
}

TEST(IoTags, LastInterpolateBoundaryAndCreaseMethodWin) {
  const Mesh_tags t = tags_of(cube_obj +
                                  "t interpolateboundary 1/0/0 0\n"
                                  "t creasemethod 0/0/1 chaikin\n"
                                  "t interpolateboundary 1/0/0 1\n"
                                  "t creasemethod 0/0/1 normal\n",
                              Mesh_format::obj);
  EXPECT_EQ(t.boundary, Boundary_interpolation::edge_and_corner);
  EXPECT_EQ(t.crease_method, Crease_method::uniform);
}

TEST(IoTags, TagsMayComeBeforeTheVerticesAndFacesTheyName) {
  const Mesh_tags t = tags_of(
      "t crease 2/1/0 6 7 2.5\nt hole 1/0/0 5\n" + cube_obj, Mesh_format::obj);
  EXPECT_EQ(t.crease_edges, (Indices{6, 7}));
  EXPECT_EQ(t.holes, (Indices{5}));
}

TEST(IoTags, TagLinesMayEndInACommentAndUseTabs) {
  const Mesh_tags t =
      tags_of(cube_obj + "t\tcrease  2/1/0\t0 1 2 # the front edge\r\n",
              Mesh_format::obj);
  EXPECT_EQ(t.crease_edges, (Indices{0, 1}));
  EXPECT_EQ(t.crease_sharpness, (Floats{2.0f}));
}

TEST(IoTags, IndicesFollowTheVerticesWhenIsolatedOnesAreDropped) {
  // Vertex 0 is used by no face: the others move down by one.
  const std::string text = "v 9 9 9\n" +
                           cube_obj.substr(0, cube_obj.find('f')) +
                           "f 3 2 4 5\nf 4 2 6 8\nf 5 4 8 9\nf 6 2 3 7\n"
                           "f 7 3 5 9\nf 8 6 7 9\n"
                           "t crease 2/1/0 5 6 2\nt corner 2/1/0 8 0 3\n"
                           "t hole 1/0/0 2\n";
  const Result<Mesh_buffers> r = read_mesh(text, Mesh_format::obj);
  ASSERT_TRUE(r.ok()) << r.status.message;
  EXPECT_EQ(r.value.vertex_count(), 8u);
  EXPECT_EQ(r.value.tags.crease_edges, (Indices{4, 5}));
  EXPECT_EQ(r.value.tags.corner_vertices, (Indices{7}));
  EXPECT_EQ(r.value.tags.corner_sharpness, (Floats{3.0f}));
  EXPECT_EQ(r.value.tags.holes, (Indices{2}));
  EXPECT_EQ(r.value.tags.notes,
            (std::vector<std::string>{
                "line 17: tag 'corner': vertex 0 is used by no face; it and "
                "its corner are dropped"}));
}

TEST(IoTags, UnappliedTagsAreNotedWithTheirLine) {
  const Mesh_tags t = tags_of(cube_obj +
                                  "t smoothtriangles 1/0/0 1\n"
                                  "t facevaryinginterpolateboundary 1/0/0 2\n"
                                  "t facevaryingpropagatecorners 1/0/0 0\n"
                                  "t somethingelse 1/2/1 3 0.5 -1 word\n"
                                  "t crease 2/1/0 0 1 2\n",
                              Mesh_format::obj);
  EXPECT_EQ(t.notes,
            (std::vector<std::string>{
                "line 15: tag 'smoothtriangles' is not applied",
                "line 16: tag 'facevaryinginterpolateboundary' is not applied",
                "line 17: tag 'facevaryingpropagatecorners' is not applied",
                "line 18: tag 'somethingelse' is not applied"}));
  EXPECT_EQ(t.crease_edges, (Indices{0, 1}));
  EXPECT_TRUE(t.present());
}

TEST(IoTags, ManyUnappliedTagsGiveAHundredNotesAndOneLineForTheRest) {
  std::string text = cube_obj;
  for (int i = 0; i < 250; ++i) text += "t smoothtriangles 1/0/0 1\n";
  const Mesh_tags t = tags_of(text, Mesh_format::obj);
  ASSERT_EQ(t.notes.size(), 101u);
  EXPECT_EQ(t.notes[99], "line 114: tag 'smoothtriangles' is not applied");
  EXPECT_EQ(t.notes[100], "and 150 more tags that are not applied");
}

TEST(IoTags, TheFixturesHoldWhatTheirCommentsSay) {
  const Mesh_tags cube =
      tags_of(fixture_text("cube-creased.obj"), Mesh_format::obj);
  EXPECT_EQ(cube.crease_edges, (Indices{4, 5, 5, 7, 0, 1, 1, 3}));
  EXPECT_EQ(cube.crease_sharpness, (Floats{2.0f, 2.0f, 3.5f, 3.5f}));
  EXPECT_EQ(cube.corner_vertices, (Indices{6}));
  EXPECT_EQ(cube.corner_sharpness, (Floats{4.25f}));
  EXPECT_EQ(cube.boundary, Boundary_interpolation::edge_only);
  EXPECT_TRUE(cube.boundary_given);
  EXPECT_FALSE(cube.crease_method_given);

  const Mesh_tags patch =
      tags_of(fixture_text("quad-patch-corners.obj"), Mesh_format::obj);
  EXPECT_EQ(patch.corner_vertices, (Indices{0, 3, 12, 15}));
  EXPECT_EQ(patch.corner_sharpness, (Floats{10, 10, 10, 10}));
  EXPECT_EQ(patch.boundary, Boundary_interpolation::edge_and_corner);

  const Mesh_tags torus =
      tags_of(fixture_text("torus-holed.obj"), Mesh_format::obj);
  EXPECT_EQ(torus.holes, (Indices{3, 14}));
  EXPECT_TRUE(torus.crease_edges.empty());

  const Mesh_tags tetra =
      tags_of(fixture_text("tetra-crease.obj"), Mesh_format::obj);
  EXPECT_EQ(tetra.crease_edges, (Indices{0, 1}));
  EXPECT_EQ(tetra.crease_sharpness, (Floats{1.5f}));
  EXPECT_EQ(tetra.crease_method, Crease_method::chaikin);
  EXPECT_TRUE(tetra.crease_method_given);
}

TEST(IoTags, FastAndGeneralPathsReadTheSameTags) {
  for (const char* name : {"cube-creased.obj", "quad-patch-corners.obj",
                           "torus-holed.obj", "tetra-crease.obj"}) {
    const std::string text = fixture_text(name);
    const Result<Mesh_buffers> fast = read_mesh(text, Mesh_format::obj);
    const Result<Mesh_buffers> general =
        detail::read_mesh_general(text, Mesh_format::obj);
    ASSERT_TRUE(fast.ok() && general.ok()) << name;
    EXPECT_EQ(fast.value.tags.crease_edges, general.value.tags.crease_edges);
    EXPECT_EQ(fast.value.tags.crease_sharpness,
              general.value.tags.crease_sharpness);
    EXPECT_EQ(fast.value.tags.corner_vertices,
              general.value.tags.corner_vertices);
    EXPECT_EQ(fast.value.tags.holes, general.value.tags.holes);
    EXPECT_EQ(fast.value.positions, general.value.positions);
  }
}

// ------------------------------------------------------------ OFF

TEST(IoTagsOff, TagCommentsAfterTheFacesAreRead) {
  const Mesh_tags t = tags_of(cube_off +
                                  "# written by SubdivLab\n"
                                  "# t crease 2/1/0 0 1 2.5\n"
                                  "#t corner 1/1/0 7 10\n"
                                  "  #   t hole 1/0/0 3 # face 3\n"
                                  "# the end\n"
                                  "# t interpolateboundary 1/0/0 0\n",
                              Mesh_format::off);
  EXPECT_EQ(t.crease_edges, (Indices{0, 1}));
  EXPECT_EQ(t.crease_sharpness, (Floats{2.5f}));
  EXPECT_EQ(t.corner_vertices, (Indices{7}));
  EXPECT_EQ(t.holes, (Indices{3}));
  EXPECT_EQ(t.boundary, Boundary_interpolation::none);
}

TEST(IoTagsOff, TagCommentsBeforeTheFacesEndAreOrdinaryComments) {
  std::string text = cube_off;
  text.insert(text.find("8 6 0"), "# t crease 2/1/0 0 1 2\n");
  text.insert(text.find("4 1 0 2 3"), "# t corner 1/1/0 7 10\n# t bad\n");
  const Mesh_tags t = tags_of(text, Mesh_format::off);
  EXPECT_FALSE(t.present());
}

TEST(IoTagsOff, DataThatIsNotATagIsStillExtraData) {
  const Result<Mesh_buffers> r = read_mesh(
      cube_off + "# t crease 2/1/0 0 1 2\n3 0 1 2\n", Mesh_format::off);
  EXPECT_EQ(r.status.code, Status_code::parse_error);
  EXPECT_EQ(r.status.line, 18);
  EXPECT_EQ(r.status.message,
            "line 18: extra data after the 6 faces the header declares "
            "(header counts disagree with the data)");
}

TEST(IoTagsOff, MalformedTagCommentsAreRefusedWithTheirLine) {
  const Result<Mesh_buffers> syntax =
      read_mesh(cube_off + "# t crease 2/1/0 0 1\n", Mesh_format::off);
  EXPECT_EQ(syntax.status.code, Status_code::parse_error);
  EXPECT_EQ(syntax.status.line, 17);
  EXPECT_EQ(syntax.status.message,
            "line 17: tag 'crease' needs 3 values after its counts '2/1/0', "
            "found 2");
  const Result<Mesh_buffers> edge = read_mesh(
      cube_off + "# t crease 2/1/0 0 1 2\n# t crease 2/1/0 0 7 2\n# x\n",
      Mesh_format::off);
  EXPECT_EQ(edge.status.code, Status_code::parse_error);
  EXPECT_EQ(edge.status.line, 18);
  EXPECT_EQ(edge.status.message,
            "line 18: tag 'crease': vertices 0 and 7 are not joined by an "
            "edge of the mesh");
}

TEST(IoTagsOff, UnappliedTagsAreNoted) {
  const Mesh_tags t =
      tags_of(cube_off + "# t smoothtriangles 1/0/0 1\n", Mesh_format::off);
  EXPECT_EQ(t.notes, (std::vector<std::string>{
                         "line 17: tag 'smoothtriangles' is not applied"}));
}

// ------------------------------------------------------------ errors
// One test per message: the tag on line 15 of the cube OBJ.

void expect_tag_error(const std::string& tag, const std::string& message) {
  for (const bool fast : {true, false}) {
    const std::string text = cube_obj + tag + "\nt crease 2/1/0 0 1 2\n";
    const Result<Mesh_buffers> r =
        fast ? read_mesh(text, Mesh_format::obj)
             : detail::read_mesh_general(text, Mesh_format::obj);
    EXPECT_EQ(r.status.code, Status_code::parse_error) << tag;
    EXPECT_EQ(r.status.line, 15) << tag;
    EXPECT_EQ(r.status.message, "line 15: " + message) << tag;
  }
}

TEST(IoTagsErrors, NoNameOrNoCounts) {
  const std::string m =
      "a tag needs a name and its counts: t NAME nint/nfloat/nstring "
      "values...";
  expect_tag_error("t", m);
  expect_tag_error("t crease", m);
}

TEST(IoTagsErrors, CountsThatAreNotThreeNonNegativeIntegers) {
  const auto m = [](const std::string& counts) {
    return "tag 'crease' counts '" + counts +
           "' are not nint/nfloat/nstring (three integers 0 or more, as in "
           "2/1/0)";
  };
  for (const std::string counts : {"2/1", "2/1/0/0", "a/b/c", "2/-1/0",
                                   "+2/1/0", "2//0", "2/1/", "2.0/1/0"})
    expect_tag_error("t crease " + counts + " 0 1 2", m(counts));
}

TEST(IoTagsErrors, FewerOrMoreValuesThanTheCountsSay) {
  expect_tag_error("t crease 2/1/0 0 1",
                   "tag 'crease' needs 3 values after its counts '2/1/0', "
                   "found 2");
  expect_tag_error("t corner 1/1/0 0 2 3",
                   "tag 'corner' needs 2 values after its counts '1/1/0', "
                   "found 3");
  expect_tag_error("t smoothtriangles 1/0/0",
                   "tag 'smoothtriangles' needs 1 values after its counts "
                   "'1/0/0', found 0");
}

TEST(IoTagsErrors, IndexThatIsNotAnInteger) {
  expect_tag_error("t crease 2/1/0 0 1.0 2",
                   "tag 'crease': vertex index '1.0' is not an integer");
  expect_tag_error("t corner 1/1/0 x 2",
                   "tag 'corner': vertex index 'x' is not an integer");
  expect_tag_error("t hole 1/0/0 3a",
                   "tag 'hole': face index '3a' is not an integer");
}

TEST(IoTagsErrors, VertexOutOfRange) {
  expect_tag_error("t corner 1/1/0 8 2",
                   "tag 'corner': vertex 8 is out of range (8 vertices; tag "
                   "indices start at 0)");
  expect_tag_error("t crease 2/1/0 -1 0 2",
                   "tag 'crease': vertex -1 is out of range (8 vertices; tag "
                   "indices start at 0)");
}

TEST(IoTagsErrors, IndexBeyondAnyMesh) {
  expect_tag_error("t corner 1/1/0 99999999999999999999 2",
                   "tag 'corner': vertex '99999999999999999999' is out of "
                   "range (more than any mesh can hold)");
}

TEST(IoTagsErrors, FaceOutOfRange) {
  expect_tag_error("t hole 2/0/0 0 6",
                   "tag 'hole': face 6 is out of range (6 faces; tag indices "
                   "start at 0)");
}

TEST(IoTagsErrors, CreasePairThatIsNotAnEdge) {
  expect_tag_error("t crease 4/1/0 0 1 0 7 2",
                   "tag 'crease': vertices 0 and 7 are not joined by an edge "
                   "of the mesh");
  expect_tag_error("t crease 2/1/0 3 3 2",
                   "tag 'crease': vertices 3 and 3 are not joined by an edge "
                   "of the mesh");
}

TEST(IoTagsErrors, OddNumberOfCreaseVertices) {
  expect_tag_error("t crease 3/1/0 0 1 3 2",
                   "tag 'crease' has 3 vertices: a crease's vertices come in "
                   "pairs, one pair per edge");
}

TEST(IoTagsErrors, SharpnessCountNeitherOneNorOnePerItem) {
  expect_tag_error("t crease 4/3/0 0 1 1 3 1 2 3",
                   "tag 'crease' has 3 sharpness values for 2 edges (give 1 "
                   "for all or one per edge)");
  expect_tag_error("t crease 2/0/0 0 1",
                   "tag 'crease' has 0 sharpness values for 1 edge (give 1 "
                   "for all or one per edge)");
  expect_tag_error("t corner 3/2/0 0 1 2 5 5",
                   "tag 'corner' has 2 sharpness values for 3 vertices (give "
                   "1 for all or one per vertex)");
}

TEST(IoTagsErrors, NegativeSharpness) {
  expect_tag_error("t crease 2/1/0 0 1 -0.5",
                   "tag 'crease': sharpness '-0.5' is negative (0 is smooth, "
                   "10 and more infinitely sharp)");
}

TEST(IoTagsErrors, NonFiniteSharpness) {
  expect_tag_error("t crease 2/1/0 0 1 nan",
                   "tag 'crease': sharpness 'nan' is not finite");
  expect_tag_error("t corner 1/1/0 0 inf",
                   "tag 'corner': sharpness 'inf' is not finite");
  expect_tag_error("t corner 1/1/0 0 1e999",
                   "tag 'corner': sharpness '1e999' is not finite");
}

TEST(IoTagsErrors, SharpnessBeyondAFloat) {
  expect_tag_error("t corner 1/1/0 0 1e39",
                   "tag 'corner': sharpness '1e39' is too large for a float "
                   "(10 and more is infinitely sharp)");
}

TEST(IoTagsErrors, NonNumericSharpness) {
  expect_tag_error("t crease 2/1/0 0 1 sharp",
                   "tag 'crease': sharpness 'sharp' is not a number");
}

TEST(IoTagsErrors, StringsOnCreaseCornerOrHole) {
  expect_tag_error("t crease 2/1/1 0 1 2 x",
                   "tag 'crease' takes no strings, found 1");
}

TEST(IoTagsErrors, SharpnessOnAHole) {
  expect_tag_error("t hole 1/1/0 0 2",
                   "tag 'hole' takes face indices only (counts N/0/0), found "
                   "'1/1/0'");
}

TEST(IoTagsErrors, InterpolateBoundaryCounts) {
  expect_tag_error("t interpolateboundary 2/0/0 1 1",
                   "tag 'interpolateboundary' needs the counts 1/0/0 (one "
                   "integer), found '2/0/0'");
}

TEST(IoTagsErrors, InterpolateBoundaryNotZeroOneOrTwo) {
  const auto m = [](const std::string& v) {
    return "tag 'interpolateboundary': '" + v +
           "' is not 0 (none), 1 (edge and corner) or 2 (edge only)";
  };
  for (const std::string v : {"3", "-1", "edge", "1.0"})
    expect_tag_error("t interpolateboundary 1/0/0 " + v, m(v));
}

TEST(IoTagsErrors, CreaseMethodCounts) {
  expect_tag_error("t creasemethod 1/0/0 1",
                   "tag 'creasemethod' needs the counts 0/0/1 (one string), "
                   "found '1/0/0'");
}

TEST(IoTagsErrors, CreaseMethodNotNormalOrChaikin) {
  expect_tag_error("t creasemethod 0/0/1 uniform",
                   "tag 'creasemethod': 'uniform' is not normal or chaikin");
}

TEST(IoTagsErrors, UnappliedTagWithBadValues) {
  expect_tag_error("t smoothtriangles 1/0/0 yes",
                   "tag 'smoothtriangles': 'yes' is not an integer");
  expect_tag_error("t facevaryingthing 0/1/0 x",
                   "tag 'facevaryingthing': 'x' is not a number");
}

TEST(IoTagsErrors, ChecksThatNeedTheMeshNameTheTagsLineNotTheLastLine) {
  // The hole names a face that never comes; the error is found after the
  // whole file is read but belongs to line 1.
  const Result<Mesh_buffers> r =
      read_mesh("t hole 1/0/0 6\n" + cube_obj + "# end\n", Mesh_format::obj);
  EXPECT_EQ(r.status.code, Status_code::parse_error);
  EXPECT_EQ(r.status.line, 1);
  EXPECT_EQ(r.status.message,
            "line 1: tag 'hole': face 6 is out of range (6 faces; tag "
            "indices start at 0)");
}

TEST(IoTagsErrors, MeshProblemsComeBeforeTagProblems) {
  // A face out of range is the mesh's problem (invalid_mesh) and is told
  // first; the tag is not judged against a mesh that is not one.
  const Result<Mesh_buffers> r = read_mesh(
      "t hole 1/0/0 9\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", Mesh_format::obj);
  EXPECT_EQ(r.status.code, Status_code::invalid_mesh);
  EXPECT_EQ(r.status.line, 5);
}

// ------------------------------------------------------------ writing

Mesh_buffers tagged_cube() {
  Result<Mesh_buffers> r = read_mesh(cube_obj, Mesh_format::obj);
  EXPECT_TRUE(r.ok());
  Mesh_tags& t = r.value.tags;
  t.crease_edges = {4, 5, 7, 5, 0, 1, 3, 1};
  t.crease_sharpness = {2.3f, 0.5f, 10.0f, 11.5f};
  t.corner_vertices = {6, 2};
  t.corner_sharpness = {1.0f / 3.0f, 1e-7f};
  t.holes = {0, 1, 2, 3, 4, 5};
  t.boundary = Boundary_interpolation::none;
  t.boundary_given = true;
  t.crease_method = Crease_method::chaikin;
  t.crease_method_given = true;
  return r.value;
}

void expect_same_tags(const Mesh_tags& a, const Mesh_tags& b) {
  EXPECT_EQ(a.crease_edges, b.crease_edges);
  EXPECT_EQ(a.crease_sharpness, b.crease_sharpness);  // floats, bitwise
  EXPECT_EQ(a.corner_vertices, b.corner_vertices);
  EXPECT_EQ(a.corner_sharpness, b.corner_sharpness);
  EXPECT_EQ(a.holes, b.holes);
  EXPECT_EQ(a.boundary, b.boundary);
  EXPECT_EQ(a.boundary_given, b.boundary_given);
  EXPECT_EQ(a.crease_method, b.crease_method);
  EXPECT_EQ(a.crease_method_given, b.crease_method_given);
}

TEST(IoTagsWrite, ObjTagLinesAreExactlyAsSpecified) {
  const std::string text = write_mesh(tagged_cube(), Mesh_format::obj);
  const std::string tags = text.substr(text.find("\nt ") + 1);
  EXPECT_EQ(tags,
            "t crease 2/1/0 4 5 2.3\n"
            "t crease 2/1/0 7 5 0.5\n"
            "t crease 2/1/0 0 1 10\n"
            "t crease 2/1/0 3 1 11.5\n"
            "t corner 1/1/0 6 0.33333334\n"
            "t corner 1/1/0 2 1e-07\n"
            "t hole 6/0/0 0 1 2 3 4 5\n"
            "t interpolateboundary 1/0/0 0\n"
            "t creasemethod 0/0/1 chaikin\n");
}

TEST(IoTagsWrite, OffTagsAreCommentsAfterTheFaces) {
  const std::string text = write_mesh(tagged_cube(), Mesh_format::off);
  EXPECT_EQ(text.substr(0, 10), "OFF\n8 6 0\n");
  const std::string tags = text.substr(text.find("\n# t ") + 1);
  EXPECT_EQ(tags.substr(0, 50),
            "# t crease 2/1/0 4 5 2.3\n# t crease 2/1/0 7 5 0.5\n");
  EXPECT_EQ(tags.substr(tags.size() - 31), "# t creasemethod 0/0/1 chaikin\n");
}

TEST(IoTagsWrite, RoundTripsAreExactInObjAndOff) {
  const Mesh_buffers m = tagged_cube();
  for (const Mesh_format format : {Mesh_format::obj, Mesh_format::off}) {
    const std::string text = write_mesh(m, format);
    const Result<Mesh_buffers> back = read_mesh(text, format);
    ASSERT_TRUE(back.ok()) << back.status.message;
    expect_same_tags(back.value.tags, m.tags);
    EXPECT_EQ(write_mesh(back.value, format), text);
  }
}

TEST(IoTagsWrite, RoundTripOfEveryTaggedFixtureIsExact) {
  for (const char* name : {"cube-creased.obj", "quad-patch-corners.obj",
                           "torus-holed.obj", "tetra-crease.obj"}) {
    const Mesh_buffers m =
        read_mesh(fixture_text(name), Mesh_format::obj).value;
    for (const Mesh_format format : {Mesh_format::obj, Mesh_format::off}) {
      const Result<Mesh_buffers> back =
          read_mesh(write_mesh(m, format), format);
      ASSERT_TRUE(back.ok()) << name << ": " << back.status.message;
      expect_same_tags(back.value.tags, m.tags);
      EXPECT_EQ(back.value.positions, m.positions) << name;
    }
  }
}

TEST(IoTagsWrite, ManyHolesGoSixteenToALine) {
  Mesh_buffers m =
      read_mesh(fixture_text("torus-holed.obj"), Mesh_format::obj).value;
  m.tags.holes.clear();
  for (std::uint32_t f = 0; f < 20; ++f) m.tags.holes.push_back(f);
  const std::string text = write_mesh(m, Mesh_format::obj);
  EXPECT_NE(text.find("\nt hole 16/0/0 0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 "
                      "15\nt hole 4/0/0 16 17 18 19\n"),
            std::string::npos);
  EXPECT_EQ(read_mesh(text, Mesh_format::obj).value.tags.holes, m.tags.holes);
}

TEST(IoTagsWrite, MeshesWithoutTagsAreWrittenAsBefore) {
  // Notes and tags that were all smooth leave nothing to write.
  const Mesh_buffers plain = read_mesh(cube_obj, Mesh_format::obj).value;
  const Mesh_buffers noted =
      read_mesh(cube_obj + "t smoothtriangles 1/0/0 1\nt crease 2/1/0 0 1 0\n",
                Mesh_format::obj)
          .value;
  EXPECT_FALSE(noted.tags.notes.empty());
  for (const Mesh_format format : {Mesh_format::obj, Mesh_format::off}) {
    const std::string text = write_mesh(plain, format);
    EXPECT_EQ(write_mesh(noted, format), text);
    EXPECT_EQ(text.find("t "), std::string::npos);
  }
  EXPECT_EQ(write_mesh(plain, Mesh_format::obj).substr(0, 16),
            "v 0 0 0\nv 1 0 0\n");
}

TEST(IoTagsWrite, SmallChunksCutTagLinesAnywhereAndJoinToTheSameText) {
  const Mesh_buffers m = tagged_cube();
  std::string joined;
  std::size_t largest = 0;
  write_mesh_chunks(m, Mesh_format::off, min_chunk_bytes,
                    [&](std::string_view chunk) {
                      largest = std::max(largest, chunk.size());
                      joined.append(chunk);
                      return true;
                    });
  EXPECT_LE(largest, min_chunk_bytes);
  EXPECT_EQ(joined, write_mesh(m, Mesh_format::off));
}

TEST(IoTagsWrite, CheckWritableRefusesTagsThatWouldNotReadBack) {
  const auto refused = [](void (*change)(Mesh_tags&)) {
    Mesh_buffers m = tagged_cube();
    change(m.tags);
    const Status s = check_writable(m);
    EXPECT_EQ(s.code, Status_code::invalid_mesh);
    return s.message;
  };
  EXPECT_TRUE(check_writable(tagged_cube()).ok());
  EXPECT_EQ(refused([](Mesh_tags& t) { t.crease_sharpness.pop_back(); }),
            "tags: 8 crease vertices for 3 sharpness values (two vertices per "
            "sharpness)");
  EXPECT_EQ(refused([](Mesh_tags& t) { t.corner_sharpness.push_back(1); }),
            "tags: 2 corner vertices for 3 sharpness values (one vertex per "
            "sharpness)");
  EXPECT_EQ(refused([](Mesh_tags& t) { t.crease_edges[0] = 8; }),
            "tags: crease vertex 8 is out of range (8 vertices)");
  EXPECT_EQ(refused([](Mesh_tags& t) { t.corner_vertices[1] = 9; }),
            "tags: corner vertex 9 is out of range (8 vertices)");
  EXPECT_EQ(refused([](Mesh_tags& t) { t.holes.push_back(6); }),
            "tags: hole face 6 is out of range (6 faces)");
  EXPECT_EQ(refused([](Mesh_tags& t) { t.corner_sharpness[0] = -1; }),
            "tags: corner sharpness -1.000000 is not a finite number 0 or "
            "more");
  EXPECT_EQ(refused([](Mesh_tags& t) { t.crease_edges[1] = 7; }),
            "tags: crease 4 7 is not an edge of the mesh");
}

// ------------------------------------------------------------ random lines

/// Tag lines from a small grammar, mostly almost right: every one must be
/// read, or refused as a parse_error on its own line (never another code,
/// another line or a crash), by both paths alike.
TEST(IoTagsRandom, EveryLineIsReadOrRefusedOnItsOwnLine) {
  std::mt19937 rng(16);
  const auto pick = [&rng](const std::vector<std::string>& from) {
    return from[std::uniform_int_distribution<std::size_t>(
        0, from.size() - 1)(rng)];
  };
  const std::vector<std::string> names = {
      "crease",       "corner",          "hole",   "interpolateboundary",
      "creasemethod", "smoothtriangles", "CREASE", ""};
  const std::vector<std::string> values = {
      "0",     "1",       "2",
      "3",     "5",       "6",
      "7",     "8",       "-1",
      "0.5",   "10",      "1e39",
      "nan",   "inf",     "x",
      "2.3",   "chaikin", "normal",
      "+4",    "1e-45",   "99999999999999999999",
      "0x1",   "",        "/",
      "1/1/0", "#",       "\xC3\xA9"};
  const std::vector<std::string> counts = {
      "2/1/0", "4/1/0", "4/2/0", "1/1/0", "2/1/0", "1/0/0",   "0/0/1",
      "2/0/0", "3/1/0", "0/0/0", "1/1",   "a/1/0", "2/1/0/0", "1/0/1"};
  int accepted = 0, refused = 0;
  for (int i = 0; i < 3000; ++i) {
    std::string line = "t";
    const int shape = i % 4;
    if (shape != 3) line += " " + pick(names);
    if (shape != 2) line += " " + pick(counts);
    const int n = std::uniform_int_distribution<int>(0, 5)(rng);
    for (int k = 0; k < n; ++k) line += " " + pick(values);
    for (const bool off : {false, true}) {
      const std::string text =
          off ? cube_off + "# t crease 2/1/0 0 1 1\n# " + line + "\n# end\n"
              : cube_obj + "t crease 2/1/0 0 1 1\n" + line + "\n# end\n";
      const int tag_line = off ? 18 : 16;
      const Mesh_format format = off ? Mesh_format::off : Mesh_format::obj;
      const Result<Mesh_buffers> r = read_mesh(text, format);
      const Result<Mesh_buffers> g = detail::read_mesh_general(text, format);
      EXPECT_EQ(r.status.code, g.status.code) << line;
      EXPECT_EQ(r.status.message, g.status.message) << line;
      if (r.ok()) {
        ++accepted;
        continue;
      }
      ++refused;
      EXPECT_EQ(r.status.code, Status_code::parse_error)
          << line << ": " << r.status.message;
      EXPECT_EQ(r.status.line, tag_line) << line << ": " << r.status.message;
      EXPECT_EQ(
          r.status.message.rfind("line " + std::to_string(tag_line) + ": ", 0),
          0u)
          << r.status.message;
    }
  }
  // The grammar must exercise both outcomes.
  EXPECT_GT(accepted, 50);
  EXPECT_GT(refused, 1000);
}

}  // namespace
}  // namespace subdivlab
