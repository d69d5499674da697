// Creasing in the core (refine/crease.h), natively and as wasm32: tags that
// do not fit the mesh are refused with the tag named, the schemes without
// creasing rules leave tags out, and an untagged mesh is untouched. The
// rules themselves are compared with OpenSubdiv in tests/opensubdiv/.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "core/subdivide.h"

namespace subdivlab {
namespace {

/// Two unit quads side by side (an open strip), vertices 0-5.
Mesh_buffers strip() {
  Mesh_buffers m;
  m.positions = {0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0};
  m.face_sizes = {4, 4};
  m.face_indices = {0, 1, 4, 3, 1, 2, 5, 4};
  return m;
}

Result<Mesh_buffers> run(const Mesh_buffers& m, const std::string& scheme,
                         int levels = 1) {
  Subdivide_options options;
  options.scheme = scheme;
  options.levels = levels;
  options.triangulate = true;
  return subdivide_mesh(m, options);
}

std::string refusal(const Mesh_buffers& m, const std::string& scheme) {
  const Result<Mesh_buffers> r = run(m, scheme);
  EXPECT_EQ(r.status.code, Status_code::invalid_argument);
  return r.status.message;
}

TEST(Creasing, RefusesACreaseBetweenVerticesThatShareNoEdge) {
  Mesh_buffers m = strip();
  m.tags.crease_edges = {1, 4, 0, 2};
  m.tags.crease_sharpness = {2.0f, 1.0f};
  EXPECT_EQ(refusal(m, "catmull-clark"),
            "The mesh's tags do not fit it: crease 2: vertices 0 and 2 are "
            "not the ends of an edge of the mesh.");
}

TEST(Creasing, RefusesIndicesOutOfRange) {
  Mesh_buffers m = strip();
  m.tags.corner_vertices = {9};
  m.tags.corner_sharpness = {1.0f};
  EXPECT_EQ(refusal(m, "catmull-clark"),
            "The mesh's tags do not fit it: corner 1: vertex 9 is not a "
            "vertex of a face of the mesh.");
  m = strip();
  m.tags.holes = {2};
  EXPECT_EQ(refusal(m, "catmull-clark"),
            "The mesh's tags do not fit it: hole 1: face 2 is not a face of "
            "the mesh, which has 2.");
}

TEST(Creasing, RefusesNegativeAndNonFiniteSharpness) {
  Mesh_buffers m = strip();
  m.tags.crease_edges = {1, 4};
  m.tags.crease_sharpness = {-1.0f};
  EXPECT_EQ(refusal(m, "loop"),
            "The mesh's tags do not fit it: crease 1: the sharpness must be "
            "0 or more, not -1.");
  m.tags.crease_sharpness = {std::numeric_limits<float>::quiet_NaN()};
  EXPECT_EQ(refusal(m, "catmull-clark"),
            "The mesh's tags do not fit it: crease 1: the sharpness must be "
            "0 or more, not not a number.");
}

TEST(Creasing, RefusesHolesOnFacesThatLoopMustTriangulate) {
  Mesh_buffers m = strip();
  m.tags.holes = {0};
  EXPECT_EQ(refusal(m, "loop"),
            "The mesh's tags do not fit it: holes name faces of the mesh as "
            "given, which had to be triangulated first: triangulate the mesh "
            "and tag its triangles.");
}

TEST(Creasing, MapsTagsPastVerticesNoFaceUses) {
  // Vertex 0 unused: the level numbers the others from 0, so the crease
  // on input vertices 2 and 5 is the strip's middle edge (x = 1); taken
  // unmapped it would be the border edge at x = 2.
  Mesh_buffers m = strip();
  m.positions.insert(m.positions.begin(), {5, 5, 5});
  for (std::uint32_t& v : m.face_indices) ++v;
  m.tags.crease_edges = {2, 5};
  m.tags.crease_sharpness = {10.0f};
  const Result<Mesh_buffers> r = run(m, "catmull-clark");
  ASSERT_TRUE(r.ok()) << r.status.message;
  ASSERT_EQ(r.value.tags.crease_sharpness.size(), 2u);
  // The sharp edge's halves, each from one of its ends to its midpoint
  // (1, 0.5, 0), in the result's numbering (vertex 1 of the level is
  // input vertex 2, at (1, 0, 0)).
  for (int i = 0; i < 2; ++i) {
    const std::uint32_t a = r.value.tags.crease_edges[2 * i],
                        b = r.value.tags.crease_edges[2 * i + 1];
    const double* pa = &r.value.positions[3 * a];
    const double* pb = &r.value.positions[3 * b];
    EXPECT_DOUBLE_EQ(pa[0], 1.0);
    EXPECT_DOUBLE_EQ(pb[0], 1.0);
    EXPECT_EQ(r.value.tags.crease_sharpness[i], 10.0f);
  }
}

TEST(Creasing, SchemesWithoutCreaseRulesLeaveTagsOut) {
  Mesh_buffers m = strip();
  m.tags.crease_edges = {1, 4};
  m.tags.crease_sharpness = {3.0f};
  m.tags.holes = {1};
  Mesh_buffers untagged = strip();
  for (const char* scheme : {"doo-sabin", "linear", "quad-triangle"}) {
    SCOPED_TRACE(scheme);
    const Result<Mesh_buffers> tagged = run(m, scheme),
                               plain = run(untagged, scheme);
    ASSERT_TRUE(tagged.ok()) << tagged.status.message;
    EXPECT_TRUE(tagged.value.tags.empty());
    EXPECT_EQ(tagged.value.positions, plain.value.positions);
    EXPECT_EQ(tagged.value.face_indices, plain.value.face_indices);
  }
}

TEST(Creasing, SharpnessDecaysByOnePerLevelInTheResultsTags) {
  // Catmull-Clark, uniform creasing: 2.5 -> 1.5 -> 0.5 -> gone; a corner
  // of 1.25 -> 0.25 -> gone.
  Mesh_buffers m = strip();
  m.tags.crease_edges = {1, 4};
  m.tags.crease_sharpness = {2.5f};
  m.tags.corner_vertices = {4};
  m.tags.corner_sharpness = {1.25f};
  const float expected_crease[] = {1.5f, 0.5f};
  const float expected_corner[] = {0.25f};
  for (int levels = 1; levels <= 3; ++levels) {
    SCOPED_TRACE(levels);
    const Result<Mesh_buffers> r = run(m, "catmull-clark", levels);
    ASSERT_TRUE(r.ok()) << r.status.message;
    // Each level splits the sharp edges in two: 2, then 4, then none left.
    const std::size_t creases = levels == 1 ? 2 : levels == 2 ? 4 : 0;
    ASSERT_EQ(r.value.tags.crease_sharpness.size(), creases);
    for (float s : r.value.tags.crease_sharpness)
      EXPECT_EQ(s, expected_crease[levels - 1]);
    ASSERT_EQ(r.value.tags.corner_sharpness.size(), levels == 1 ? 1u : 0u);
    if (levels == 1) {
      EXPECT_EQ(r.value.tags.corner_vertices[0], 4u);
      EXPECT_EQ(r.value.tags.corner_sharpness[0], expected_corner[0]);
    }
    EXPECT_TRUE(r.value.tags.boundary == Boundary_interpolation::edge_only);
  }
}

// No step: the mesh comes back as it is, tags included (renumbered past
// a vertex no face uses, whose own tag goes).
TEST(Creasing, NoStepKeepsTheTags) {
  Mesh_buffers m = strip();
  m.positions.insert(m.positions.begin(), {5, 5, 5});
  for (std::uint32_t& v : m.face_indices) ++v;
  m.tags.crease_edges = {2, 5};
  m.tags.crease_sharpness = {2.5f};
  m.tags.corner_vertices = {0, 6};
  m.tags.corner_sharpness = {1.0f, 3.0f};
  m.tags.holes = {1};
  m.tags.crease_method = Crease_method::chaikin;
  const Result<Mesh_buffers> r = run(m, "catmull-clark", 0);
  ASSERT_TRUE(r.ok()) << r.status.message;
  EXPECT_EQ(r.value.tags.crease_edges, (std::vector<std::uint32_t>{1, 4}));
  EXPECT_EQ(r.value.tags.crease_sharpness, (std::vector<float>{2.5f}));
  EXPECT_EQ(r.value.tags.corner_vertices, (std::vector<std::uint32_t>{5}));
  EXPECT_EQ(r.value.tags.corner_sharpness, (std::vector<float>{3.0f}));
  EXPECT_EQ(r.value.tags.holes, (std::vector<std::uint32_t>{1}));
  EXPECT_TRUE(r.value.tags.crease_method == Crease_method::chaikin);
}

// Where OpenSubdiv's rules and CGAL's differ on an untagged mesh: CGAL's
// border rule moves a corner of a quad patch (one face, two border edges)
// as any border vertex, 3/4 of it and 1/8 of each border neighbour;
// OpenSubdiv's edge-and-corner mode pins it. The default (edge only)
// follows CGAL.
TEST(Creasing, EdgeAndCornerPinsThePatchCornersCgalMoves) {
  const Mesh_buffers m = strip();
  Subdivide_options options;
  options.scheme = "catmull-clark";
  const Result<Mesh_buffers> cgal = subdivide_mesh(m, options);
  options.boundary = Boundary_interpolation::edge_and_corner;
  const Result<Mesh_buffers> pinned = subdivide_mesh(m, options);
  ASSERT_TRUE(cgal.ok() && pinned.ok());
  // Vertex 0 at (0, 0, 0), border neighbours (1, 0, 0) and (0, 1, 0).
  EXPECT_DOUBLE_EQ(cgal.value.positions[0], 0.125);
  EXPECT_DOUBLE_EQ(cgal.value.positions[1], 0.125);
  EXPECT_DOUBLE_EQ(pinned.value.positions[0], 0.0);
  EXPECT_DOUBLE_EQ(pinned.value.positions[1], 0.0);
  // Vertex 1 (1, 0, 0), on the border between the quads: the same in both.
  for (int i = 3; i < 6; ++i)
    EXPECT_DOUBLE_EQ(cgal.value.positions[i], pinned.value.positions[i]);
  // The result says which mode made it.
  EXPECT_TRUE(pinned.value.tags.boundary ==
              Boundary_interpolation::edge_and_corner);
  EXPECT_TRUE(pinned.value.tags.boundary_given);
  EXPECT_TRUE(cgal.value.tags.empty());
}

}  // namespace
}  // namespace subdivlab
