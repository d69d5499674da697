// CGAL's Euler operators on a picked element (core/euler_ops.h): each
// leaves a valid mesh with the Euler characteristic unchanged and the
// counts the operator's construction gives, the inverse operator restores
// the mesh, broken preconditions are refused with their reason, and the √3
// step written with them (the tutorial's way) ends equal to the √3
// scheme's level 1.
#include <gtest/gtest.h>

#include <string>

#include "core/compare.h"
#include "core/euler_ops.h"
#include "core/halfedges.h"
#include "core/subdivide.h"
#include "refine_test_support.h"

namespace subdivlab {
namespace {

Euler_result apply(const Mesh_buffers& mesh, Euler_op op, std::uint32_t h,
                   std::uint32_t h2 = 0) {
  const Result<Euler_result> r = apply_euler_op(mesh, {op, h, h2});
  EXPECT_TRUE(r.ok()) << r.status.message;
  EXPECT_TRUE(r.value.valid);
  return r.value;
}

std::string refusal(const Mesh_buffers& mesh, Euler_op op, std::uint32_t h,
                    std::uint32_t h2 = 0) {
  const Result<Euler_result> r = apply_euler_op(mesh, {op, h, h2});
  EXPECT_EQ(r.status.code, Status_code::invalid_argument);
  return r.status.message;
}

/// The same mesh, up to the numbering: same counts and points, same faces.
void expect_same_mesh(const Mesh_buffers& a, const Mesh_buffers& b) {
  const Mesh_comparison c = compare_meshes(a, b, 1e-12);
  EXPECT_TRUE(c.match) << (c.reasons.empty() ? "" : c.reasons[0]);
  EXPECT_TRUE(c.same_faces);
}

TEST(EulerOps, SplitAFaceOfTheCubeThenJoinIt) {
  const Mesh_buffers cube = refine_test::fixture("cube.off");
  const Halfedge_table t = halfedge_table(cube).value;
  // Halfedge 0 and the one two steps along its face: a diagonal.
  const std::uint32_t h = 0, h2 = t.next[t.next[0]];
  const Euler_result split = apply(cube, Euler_op::split_face, h, h2);
  EXPECT_EQ(split.facts.vertices, 8u);
  EXPECT_EQ(split.facts.edges, 13u);
  EXPECT_EQ(split.facts.faces, 7u);
  EXPECT_EQ(split.facts.euler_characteristic, 2);
  EXPECT_EQ(split.facts.triangles, 2u);
  // CGAL returns the new edge's halfedge: joining across it gives the cube
  // back.
  const Euler_result joined =
      apply(split.mesh, Euler_op::join_face, split.halfedge);
  expect_same_mesh(cube, joined.mesh);
}

TEST(EulerOps, CentreVertexAddedAndRemoved) {
  const Mesh_buffers cube = refine_test::fixture("cube.off");
  const Euler_result added = apply(cube, Euler_op::add_center_vertex, 0);
  // A quad becomes 4 triangles around a new vertex at its centroid.
  EXPECT_EQ(added.facts.vertices, 9u);
  EXPECT_EQ(added.facts.edges, 16u);
  EXPECT_EQ(added.facts.faces, 9u);
  EXPECT_EQ(added.facts.euler_characteristic, 2);
  const Halfedge_table t = halfedge_table(added.mesh).value;
  const std::uint32_t centre = t.target[added.halfedge];
  EXPECT_EQ(centre, 8u);
  const std::vector<double>& p = added.mesh.positions;
  const Mesh_buffers& c = cube;
  double expected[3] = {0, 0, 0};
  for (std::uint32_t k = 0; k < 4; ++k)
    for (int i = 0; i < 3; ++i)
      expected[i] += c.positions[3 * c.face_indices[k] + i] / 4;
  for (int i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(p[3 * centre + i], expected[i]);
  const Euler_result removed =
      apply(added.mesh, Euler_op::remove_center_vertex, added.halfedge);
  expect_same_mesh(cube, removed.mesh);
}

TEST(EulerOps, SplitEdgeAddsAMidpointAndFlipKeepsCounts) {
  const Mesh_buffers ico = refine_test::fixture("icosahedron.off");
  const Halfedge_table t = halfedge_table(ico).value;
  const Euler_result split = apply(ico, Euler_op::split_edge, 0);
  // The two triangles beside the edge become quads.
  EXPECT_EQ(split.facts.vertices, 13u);
  EXPECT_EQ(split.facts.edges, 31u);
  EXPECT_EQ(split.facts.faces, 20u);
  EXPECT_EQ(split.facts.triangles, 18u);
  EXPECT_EQ(split.facts.quads, 2u);
  const std::uint32_t a = t.target[t.opposite[0]], b = t.target[0];
  const Halfedge_table s = halfedge_table(split.mesh).value;
  const std::uint32_t mid = s.target[split.halfedge];
  for (int i = 0; i < 3; ++i)
    EXPECT_DOUBLE_EQ(split.mesh.positions[3 * mid + i],
                     (ico.positions[3 * a + i] + ico.positions[3 * b + i]) / 2);

  const Euler_result flipped = apply(ico, Euler_op::flip_edge, 0);
  EXPECT_EQ(flipped.facts.vertices, 12u);
  EXPECT_EQ(flipped.facts.edges, 30u);
  EXPECT_EQ(flipped.facts.faces, 20u);
  // The flipped edge joins the two far corners of the triangles beside it.
  const Halfedge_table f = halfedge_table(flipped.mesh).value;
  const std::uint32_t c = t.target[t.next[0]],
                      d = t.target[t.next[t.opposite[0]]];
  const std::uint32_t ends[2] = {f.target[flipped.halfedge],
                                 f.target[f.opposite[flipped.halfedge]]};
  EXPECT_TRUE((ends[0] == c && ends[1] == d) || (ends[0] == d && ends[1] == c));
}

TEST(EulerOps, EveryOperatorKeepsTheEulerCharacteristic) {
  for (const char* name :
       {"cube.off", "icosahedron.off", "torus-tri.off", "grid-open.off"}) {
    SCOPED_TRACE(name);
    const Mesh_buffers mesh = refine_test::fixture(name);
    const long chi = compute_facts(mesh).value.euler_characteristic;
    const Halfedge_table t = halfedge_table(mesh).value;
    // An inner halfedge (both sides faces).
    std::uint32_t inner = 0;
    while (t.face[inner] < 0 || t.face[t.opposite[inner]] < 0) ++inner;
    const bool triangles = compute_facts(mesh).value.quads == 0;
    std::vector<Euler_result> results = {
        apply(mesh, Euler_op::add_center_vertex, inner),
        apply(mesh, Euler_op::split_edge, inner),
        apply(mesh, Euler_op::join_face, inner),
    };
    if (triangles)
      results.push_back(apply(mesh, Euler_op::flip_edge, inner));
    else
      results.push_back(
          apply(mesh, Euler_op::split_face, inner, t.next[t.next[inner]]));
    for (const Euler_result& r : results)
      EXPECT_EQ(r.facts.euler_characteristic, chi);
  }
}

TEST(EulerOps, BrokenPreconditionsAreRefusedWithTheirReason) {
  const Mesh_buffers cube = refine_test::fixture("cube.off");
  const Halfedge_table t = halfedge_table(cube).value;
  EXPECT_EQ(refusal(cube, Euler_op::flip_edge, 0),
            "only an edge between two triangles can be flipped");
  EXPECT_EQ(refusal(cube, Euler_op::split_edge, 24),
            "halfedge 24 does not exist (24 halfedges)");
  EXPECT_EQ(refusal(cube, Euler_op::split_face, 0, t.next[0]),
            "a face is split between two corners that are not neighbours");
  EXPECT_EQ(refusal(cube, Euler_op::split_face, 0, 1),
            "halfedge 0 and halfedge 1 are not on one face");
  const Mesh_buffers grid = refine_test::fixture("grid-open.off");
  const Halfedge_table g = halfedge_table(grid).value;
  std::uint32_t border = 0;
  while (g.face[border] >= 0) ++border;
  EXPECT_EQ(refusal(grid, Euler_op::join_face, border),
            "a border edge has one face: there is nothing to join");
  EXPECT_EQ(refusal(grid, Euler_op::add_center_vertex, border),
            "halfedge " + std::to_string(border) +
                " is on the border: it has no face");
  // A vertex of the tetrahedron: its three faces would fold onto the fourth.
  const Mesh_buffers tetra = refine_test::fixture("tetrahedron.off");
  const Halfedge_table tt = halfedge_table(tetra).value;
  EXPECT_EQ(refusal(tetra, Euler_op::remove_center_vertex, 0),
            "removing vertex " + std::to_string(tt.target[0]) +
                " would fold its faces onto the one face left");
  // Joining two of its faces is allowed: each end keeps 3 edges, and a quad
  // and two triangles are a valid mesh.
  EXPECT_TRUE(apply_euler_op(tetra, {Euler_op::join_face, 0, 0}).ok());
}

TEST(EulerOps, SqrtThreeByHandEndsAtTheSqrtThreeSchemesLevelOne) {
  for (const char* name :
       {"tetrahedron.off", "octahedron.off", "icosahedron.off", "torus-tri.off",
        "two-tetrahedra.off"}) {
    SCOPED_TRACE(name);
    const Mesh_buffers mesh = refine_test::fixture(name);
    const Mesh_facts facts = compute_facts(mesh).value;
    const Result<Sqrt3_walk> all = sqrt3_by_hand(mesh, SIZE_MAX);
    ASSERT_TRUE(all.ok()) << all.status.message;
    EXPECT_EQ(all.value.total, facts.faces + facts.edges + facts.vertices);
    EXPECT_EQ(all.value.done, all.value.total);
    Subdivide_options o;
    o.scheme = "sqrt3";
    const Result<Mesh_buffers> scheme = subdivide_mesh(mesh, o);
    ASSERT_TRUE(scheme.ok());
    expect_same_mesh(scheme.value, all.value.mesh);
    // After the centre vertices: V + F vertices, 3F triangles; the flips
    // keep the counts; the old vertices move only in the last phase.
    const Sqrt3_walk centres = sqrt3_by_hand(mesh, facts.faces).value;
    EXPECT_EQ(centres.mesh.vertex_count(), facts.vertices + facts.faces);
    EXPECT_EQ(centres.mesh.face_count(), 3 * facts.faces);
    EXPECT_EQ(centres.last, "add_center_vertex (face " +
                                std::to_string(facts.faces - 1) + ")");
    const Sqrt3_walk flipped =
        sqrt3_by_hand(mesh, facts.faces + facts.edges).value;
    EXPECT_EQ(flipped.mesh.face_count(), 3 * facts.faces);
    for (std::size_t i = 0; i < 3 * facts.vertices; ++i)
      EXPECT_EQ(flipped.mesh.positions[i], mesh.positions[i]);
    EXPECT_EQ(flipped.last.rfind("flip_edge (edge ", 0), 0u);
  }
}

TEST(EulerOps, SqrtThreeByHandRefusesBordersAndPolygons) {
  EXPECT_EQ(sqrt3_by_hand(refine_test::fixture("cube.off"), 1).status.message,
            "the walk-through follows the tutorial on triangle meshes: face 0 "
            "has 4 corners");
  EXPECT_EQ(
      sqrt3_by_hand(refine_test::fixture("disk-tri.off"), 1).status.message,
      "the walk-through follows the tutorial on closed meshes: this one has a "
      "border");
}

}  // namespace
}  // namespace subdivlab
