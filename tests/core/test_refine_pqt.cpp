// The fast PQT host (quad-triangle: refine_pqt_topology in
// wasm/src/refine/primal_hosts, refine_pqt_points in primal_points) against
// CGAL's route (core/quad_triangle_3.h's PQT_1step and
// Quad_triangle_mask_3): the same numbering of vertices, edges and faces,
// the same face corners in the same order, the same halfedges, and the same
// points to 1e-12 of the mesh's size, at levels 1-3 of every fixture and of
// CGAL's meshes, closed and open, with the border smoothed and fixed, and
// the same control edges.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core/mesh_build.h"
#include "core/quad_triangle_3.h"
#include "core/subdivide.h"
#include "refine/level_convert.h"
#include "refine/primal_hosts.h"
#include "refine/primal_masks.h"
#include "refine/primal_points.h"
#include "refine_test_support.h"

namespace subdivlab {
namespace {

using namespace refine_test;

/// Meshes no fixture has: two-valent vertices between a triangle and a
/// quad, and between two quads (quad-triangle refines them, test_extra);
/// a pentagonal prism (two pentagons, five quads).
std::vector<std::pair<std::string, Mesh_buffers>> odd_meshes() {
  const Mesh_buffers prism = pentagonal_prism();
  // The prism without one pentagon: open, a border of five quads.
  Mesh_buffers cup = prism;
  cup.face_sizes.erase(cup.face_sizes.begin());
  cup.face_indices.erase(cup.face_indices.begin(),
                         cup.face_indices.begin() + 5);
  return {{"triangle and quad at a two-valent vertex",
           two_valent_triangle_and_quad()},
          {"two quads at a two-valent vertex", two_valent_quads()},
          {"pentagonal prism", prism},
          {"open pentagonal cup", cup}};
}

/// Levels 1-3 of the fast host equal PQT_1step's on `reference`, table by
/// table: counts, each face's corners from halfedge(f) (vertices and
/// halfedges), the face offsets of a mixed level, every halfedge's target
/// and face corner, and the points.
void expect_cgal_levels(Mesh reference, bool smooth, const std::string& what) {
  refine::Level level = refine::level_from_mesh(reference);
  refine::Quad_triangle_mask mask;
  mask.smooth_boundary = smooth;
  refine::Primal_scratch scratch;
  for (int k = 1; k <= 3; ++k) {
    const std::string at = what + ", level " + std::to_string(k);
    QuadTriangle_subdivision(reference, 1, smooth);
    refine::Level child;
    refine::refine_pqt_topology(level, child, false);
    refine::refine_pqt_points(level, mask, scratch, child);
    level = child;
    expect_same_tables(level, reference, at);
    if (testing::Test::HasFatalFailure()) return;
    // Triangles and quads only, offsets exactly when both are there.
    std::uint32_t triangles = 0, quads = 0;
    for (Mesh::Face_index f : reference.faces())
      (reference.degree(f) == 3 ? triangles : quads) += 1;
    ASSERT_EQ(triangles + quads, level.face_count) << at;
    ASSERT_EQ(level.uniform_degree, quads == 0       ? 3u
                                    : triangles == 0 ? 4u
                                                     : 0u)
        << at;
    ASSERT_EQ(level.face_offsets.size(),
              level.uniform_degree == 0 ? level.face_count + 1 : 0u)
        << at;
  }
}

Mesh built(const Mesh_buffers& in) {
  Mesh m;
  EXPECT_TRUE(build_mesh(in, m).ok());
  return m;
}

TEST(FastPqtHost, TablesEqualCgalsLevelByLevel) {
  for (const char* f : kFixtures)
    for (bool smooth : {true, false})
      expect_cgal_levels(built(fixture(f)), smooth,
                         std::string(f) + (smooth ? "" : ", fixed border"));
  for (const auto& [name, in] : odd_meshes())
    for (bool smooth : {true, false})
      expect_cgal_levels(built(in), smooth,
                         name + (smooth ? "" : ", fixed border"));
}

TEST(FastPqtHost, TablesEqualCgalsLevelByLevelOnCgalsMeshes) {
  // holes.off is open: its border both ways; the others are closed.
  for (const char* f : kCgalMeshes) {
    const Mesh_buffers in = cgal_mesh(f);
    expect_cgal_levels(built(in), true, f);
    if (std::string(f) == "holes.off")
      expect_cgal_levels(built(in), false, std::string(f) + ", fixed border");
  }
}

TEST(FastPqtHost, FollowsItsMaskWhenTheWeightsChange) {
  // Quad/triangle's weights make every interior edge point regular (the
  // same alpha and lambda whatever its sides) and its border rule
  // symmetric: other weights, read by both routes from the one mask, check
  // that the fast host counts each edge point's sides and reads the border
  // chain in CGAL's direction.
  refine::Quad_triangle_mask odd;
  odd.ring = 0.45;
  odd.opposite = 0.3;
  odd.border = {0.2, 0.5, 0.3};
  for (const char* f : {"rhombicuboctahedron.off", "mixed-open.off",
                        "grid-open.off", "disk-tri.off"}) {
    Mesh reference = built(fixture(f));
    refine::Level level = refine::level_from_mesh(reference);
    refine::Primal_scratch scratch;
    auto vpm = get(CGAL::vertex_point, reference);
    Quad_triangle_mask_3<Mesh> cgal_mask(&reference, vpm);
    cgal_mask.weights = odd;
    for (int k = 1; k <= 3; ++k) {
      PQT_1step(reference, vpm, cgal_mask);
      refine::Level child;
      refine::refine_pqt_topology(level, child, false);
      refine::refine_pqt_points(level, odd, scratch, child);
      level = child;
      expect_same_tables(
          level, reference,
          std::string(f) + ", other weights, level " + std::to_string(k));
      if (testing::Test::HasFatalFailure()) return;
    }
  }
}

TEST(FastPqtHost, EqualsThePrimalHostsOnTrianglesAndOnPolygons) {
  // On triangles the PQT host numbers as PTQ, on other faces as PQQ.
  for (const char* f : {"icosahedron.off", "disk-tri.off", "cube.off",
                        "grid-open.off", "mixed-open.off"}) {
    refine::Level level = refine::level_from_mesh(built(fixture(f)));
    bool triangles = true, polygons = true;
    for (std::uint32_t g = 0; g < level.face_count; ++g) {
      const bool triangle = level.face_end(g) - level.face_begin(g) == 3;
      triangles = triangles && triangle;
      polygons = polygons && !triangle;
    }
    if (!triangles && !polygons) {
      EXPECT_EQ(refine::polygon_count(level), 3u) << f;  // 2 quads, a pentagon
      continue;
    }
    refine::Level pqt, primal;
    refine::refine_pqt_topology(level, pqt, false);
    if (triangles)
      refine::refine_ptq_topology(level, primal, false);
    else
      refine::refine_pqq_topology(level, primal, false);
    EXPECT_EQ(pqt.vertex_count, primal.vertex_count) << f;
    EXPECT_EQ(pqt.uniform_degree, primal.uniform_degree) << f;
    EXPECT_EQ(pqt.face_vertices, primal.face_vertices) << f;
    EXPECT_EQ(pqt.face_halfedges, primal.face_halfedges) << f;
    EXPECT_EQ(pqt.halfedge_target, primal.halfedge_target) << f;
    EXPECT_EQ(pqt.halfedge_corner, primal.halfedge_corner) << f;
  }
}

/// subdivide_mesh on the fast host and on CGAL's: both succeed, with the
/// same faces, points and control edges.
void expect_same_run(const Mesh_buffers& in, Subdivide_options o,
                     const std::string& what) {
  ASSERT_FALSE(o.cgal_hosts);
  const Result<Mesh_buffers> fast = subdivide_mesh(in, o);
  o.cgal_hosts = true;
  const Result<Mesh_buffers> cgal = subdivide_mesh(in, o);
  ASSERT_TRUE(cgal.ok()) << what << ": " << cgal.status.message;
  ASSERT_TRUE(fast.ok()) << what << ": " << fast.status.message;
  expect_same_buffers(fast.value, cgal.value, what);
}

/// Levels 1-`max_levels` with the border smoothed and fixed, every edge a
/// control edge (start_level 0), some given as control edges, and none
/// (start_level 1).
void expect_same_runs(const Mesh_buffers& in, const std::string& name,
                      int max_levels) {
  Mesh_buffers some = in;
  // Every third edge of the faces as given (a face's edges, deduplicated by
  // the smaller end first: each edge is named once).
  std::size_t o = 0, n = 0;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> named;
  for (std::uint32_t k : in.face_sizes) {
    for (std::uint32_t i = 0; i < k; ++i) {
      const std::uint32_t a = in.face_indices[o + i],
                          b = in.face_indices[o + (i + 1) % k];
      const std::pair<std::uint32_t, std::uint32_t> key{std::min(a, b),
                                                        std::max(a, b)};
      if (std::find(named.begin(), named.end(), key) != named.end()) continue;
      named.push_back(key);
      if (n++ % 3 == 0)
        some.control_edges.insert(some.control_edges.end(), {a, b});
    }
    o += k;
    if (named.size() > 300) break;
  }
  for (int levels = 1; levels <= max_levels; ++levels) {
    for (bool smooth : {true, false}) {
      Subdivide_options opt;
      opt.scheme = "quad-triangle";
      opt.levels = levels;
      opt.smooth_boundary = smooth;
      const std::string run = " x" + std::to_string(levels) + " on " + name +
                              (smooth ? "" : ", fixed border");
      expect_same_run(in, opt, "all control edges" + run);
      expect_same_run(some, opt, "some control edges" + run);
      opt.start_level = 1;
      expect_same_run(in, opt, "from start_level 1" + run);
    }
  }
}

TEST(FastPqtHost, SubdivideMeshEqualsItsCgalHostsOnEveryFixture) {
  for (const char* f : kFixtures) expect_same_runs(fixture(f), f, 3);
  for (const auto& [name, in] : odd_meshes()) expect_same_runs(in, name, 3);
}

TEST(FastPqtHost, SubdivideMeshEqualsItsCgalHostsOnCgalsMeshes) {
  for (const char* f : kCgalMeshes) {
    const Mesh_buffers in = cgal_mesh(f);
    for (int levels = 1; levels <= 3; ++levels) {
      Subdivide_options o;
      o.scheme = "quad-triangle";
      o.levels = levels;
      expect_same_run(in, o, "x" + std::to_string(levels) + " on " + f);
    }
  }
  Subdivide_options fixed;
  fixed.scheme = "quad-triangle";
  fixed.levels = 2;
  fixed.smooth_boundary = false;
  expect_same_run(cgal_mesh("holes.off"), fixed, "x2 on holes, fixed border");
}

TEST(FastPqtHost, LevelByLevelCarriesTheControlEdgesAsCgalDoes) {
  // A level-1 mesh (triangles and quads from the buffers, a mixed level 0)
  // with its marks, refined twice more from start_level 1.
  for (const char* f :
       {"rhombicuboctahedron.off", "mixed-open.off", "grid-open.off"}) {
    Subdivide_options o;
    o.scheme = "quad-triangle";
    o.levels = 1;
    const Result<Mesh_buffers> level1 = subdivide_mesh(fixture(f), o);
    ASSERT_TRUE(level1.ok()) << f;
    ASSERT_FALSE(level1.value.control_edges.empty()) << f;
    o.levels = 2;
    o.start_level = 1;
    expect_same_run(level1.value, o,
                    std::string("quad-triangle from level 1 of ") + f);
  }
}

TEST(FastPqtHost, TheTwoValentRefusalIsTheCgalRoutesOnBoth) {
  Mesh_buffers pillow;
  pillow.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  pillow.face_sizes = {3, 3};
  pillow.face_indices = {0, 1, 2, 0, 2, 1};
  Subdivide_options o;
  o.scheme = "quad-triangle";
  o.levels = 1;
  const Result<Mesh_buffers> fast = subdivide_mesh(pillow, o);
  o.cgal_hosts = true;
  const Result<Mesh_buffers> cgal = subdivide_mesh(pillow, o);
  ASSERT_FALSE(fast.ok());
  EXPECT_EQ(fast.status.code, cgal.status.code);
  EXPECT_EQ(fast.status.message, cgal.status.message);
}

TEST(FastPqtHost, PredictedCountsMatchTheFastResult) {
  for (const char* f : {"rhombicuboctahedron.off", "mixed-open.off",
                        "grid-open.off", "icosahedron.off"}) {
    Subdivide_options o;
    o.scheme = "quad-triangle";
    o.levels = 3;
    const Result<Size_prediction> p = predict_size(fixture(f), o);
    const Result<Mesh_buffers> r = subdivide_mesh(fixture(f), o);
    ASSERT_TRUE(p.ok() && r.ok()) << f;
    EXPECT_EQ(p.value.vertices, r.value.vertex_count()) << f;
    EXPECT_EQ(p.value.faces, r.value.face_count()) << f;
  }
}

}  // namespace
}  // namespace subdivlab
