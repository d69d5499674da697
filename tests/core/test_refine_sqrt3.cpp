// The fast sqrt(3) host (wasm/src/refine/sqrt3_host) against CGAL's
// Sqrt3_1step: the same numbering of vertices, edges and faces, the same
// face corners in the same order, the same halfedges, and the same points to
// 1e-12 of the mesh's size, at levels 1-3 from either border parity, on
// every fixture and on CGAL's meshes, closed and open; and the same
// refusals (two border edges in a face on a border step, custom tables
// that stop short).

#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Subdivision_method_3/internal/subdivision_hosts_impl_3.h>
#include <CGAL/subdivision_method_3.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "core/custom_rules.h"
#include "core/mesh_build.h"
#include "core/mesh_io.h"
#include "core/subdivide.h"
#include "core/table_masks_3.h"
#include "refine/level_convert.h"
#include "refine/primal_masks.h"
#include "refine/primal_points.h"
#include "refine/sqrt3_host.h"
#include "refine_test_support.h"

namespace subdivlab {
namespace {

namespace SMI = CGAL::Subdivision_method_3::internal;

using namespace refine_test;

Mesh triangulated(const Mesh_buffers& in) {
  Mesh m;
  EXPECT_TRUE(build_mesh(in, m).ok());
  CGAL::Polygon_mesh_processing::triangulate_faces(m);
  m.collect_garbage();
  return m;
}

/// Rule sets on the sqrt3 host: the preset, and one with other interior
/// weights and asymmetric border rules (all four border-edge weights).
std::vector<Custom_rules> sqrt3_rules() {
  Custom_rules odd = custom_rules_preset("sqrt3", 64);
  for (Vertex_weights& w : odd.vertex) {
    w.self -= 0.1;
    w.neighbour += 0.1 / (odd.first_valence + (&w - odd.vertex.data()));
  }
  odd.border_edge = {-0.05, 0.6, 0.5, -0.05};
  odd.border_vertex = {0.2, 0.5, 0.3};
  return {custom_rules_preset("sqrt3", 64), odd};
}

/// Levels 1-3 of the fast host from global step `start` equal CGAL's
/// Sqrt3_1step (border refined on odd steps), table by table: the faces
/// from halfedge(f), every halfedge's target and face corner, the points.
void expect_cgal_levels(const Custom_rules* rules, Mesh reference, int start,
                        const std::string& what) {
  refine::Level level = refine::level_from_mesh(reference);
  const refine::Primal_mask_lookup mask =
      rules ? refine::sqrt3_mask("custom", *rules)
            : refine::sqrt3_mask("sqrt3", {});
  ASSERT_TRUE(mask.ok);
  refine::Primal_scratch points;
  refine::Sqrt3_scratch scratch;
  auto vpm = get(CGAL::vertex_point, reference);
  for (int k = 0; k < 3; ++k) {
    const int step = start + k;
    const bool border = step % 2 == 1 && level.border_edge_count > 0;
    const std::string at = what + ", step " + std::to_string(step);
    if (border && refine::sqrt3_multi_border_faces(level) > 0) return;
    if (rules)
      SMI::Sqrt3_1step(reference, vpm,
                       Table_Sqrt3_mask_3<Mesh>(&reference, vpm, rules),
                       step % 2 == 1);
    else
      SMI::Sqrt3_1step(reference, vpm,
                       CGAL::Sqrt3_mask_3<Mesh>(&reference, vpm),
                       step % 2 == 1);
    // The flips recycle what they remove: nothing to collect.
    ASSERT_EQ(reference.number_of_removed_faces(), 0u) << at;
    ASSERT_EQ(reference.number_of_removed_edges(), 0u) << at;
    ASSERT_EQ(refine::primal_uncovered_valence(level, mask.mask, points), 0u);
    refine::Level child;
    refine::refine_sqrt3_topology(level, border, scratch, child, false);
    refine::refine_sqrt3_points(level, mask.mask, border, scratch, points,
                                child);
    level = child;
    expect_same_tables(level, reference, at);
    if (testing::Test::HasFatalFailure()) return;
  }
}

TEST(FastSqrt3Host, TablesEqualCgalsLevelByLevel) {
  const std::vector<Custom_rules> rules = sqrt3_rules();
  for (const char* f : kFixtures) {
    for (int start = 0; start <= 1; ++start) {
      const std::string what =
          std::string(f) + " from step " + std::to_string(start);
      expect_cgal_levels(nullptr, triangulated(fixture(f)), start,
                         "sqrt3 on " + what);
      for (const Custom_rules& r : rules)
        expect_cgal_levels(&r, triangulated(fixture(f)), start,
                           "custom sqrt3 on " + what);
    }
  }
}

/// subdivide_mesh on the fast host and on CGAL's: the same status, and when
/// it succeeds the same faces and points (1e-12).
void expect_same_run(const Mesh_buffers& in, Subdivide_options o,
                     const std::string& what, bool must_succeed) {
  const Result<Mesh_buffers> fast = subdivide_mesh(in, o);
  o.cgal_hosts = true;
  const Result<Mesh_buffers> cgal = subdivide_mesh(in, o);
  ASSERT_EQ(fast.status.code, cgal.status.code) << what;
  ASSERT_EQ(fast.status.message, cgal.status.message) << what;
  if (must_succeed) {
    ASSERT_TRUE(cgal.ok()) << what << ": " << cgal.status.message;
  }
  if (!cgal.ok()) return;
  expect_same_buffers(fast.value, cgal.value, what);
}

void expect_same_runs(const Mesh_buffers& in, const std::string& name,
                      int max_levels) {
  const std::vector<Custom_rules> rules = sqrt3_rules();
  for (int start = 0; start <= 1; ++start) {
    for (int levels = 1; levels <= max_levels; ++levels) {
      Subdivide_options o;
      o.levels = levels;
      o.start_level = start;
      o.triangulate = true;
      const std::string run = " x" + std::to_string(levels) + " from " +
                              std::to_string(start) + " on " + name;
      // From level 0 every run succeeds; from 1, a face with two border
      // edges is refused, by both routes alike.
      o.scheme = "sqrt3";
      expect_same_run(in, o, "sqrt3" + run, start == 0);
      o.scheme = "custom";
      for (const Custom_rules& r : rules) {
        o.custom = r;
        expect_same_run(in, o, "custom sqrt3" + run, start == 0);
      }
    }
  }
}

TEST(FastSqrt3Host, SubdivideMeshEqualsItsCgalHostsOnEveryFixture) {
  for (const char* f : kFixtures) expect_same_runs(fixture(f), f, 3);
}

TEST(FastSqrt3Host, SubdivideMeshEqualsItsCgalHostsOnCgalsMeshes) {
  for (const char* f : kCgalMeshes) expect_same_runs(cgal_mesh(f), f, 3);
}

TEST(FastSqrt3Host, LevelByLevelEqualsOneRun) {
  // A level-1 mesh (border not refined yet) refined from start_level 1 on
  // the fast host and on CGAL's, and equal to level 3 of one run.
  for (const char* f : {"disk-tri.off", "grid-open.off", "icosahedron.off"}) {
    Subdivide_options o;
    o.scheme = "sqrt3";
    o.triangulate = true;
    o.levels = 1;
    const Result<Mesh_buffers> level1 = subdivide_mesh(fixture(f), o);
    ASSERT_TRUE(level1.ok()) << f;
    o.levels = 2;
    o.start_level = 1;
    expect_same_run(level1.value, o, std::string("sqrt3 from level 1 of ") + f,
                    true);
    const Result<Mesh_buffers> stepped = subdivide_mesh(level1.value, o);
    o.levels = 3;
    o.start_level = 0;
    const Result<Mesh_buffers> whole = subdivide_mesh(fixture(f), o);
    ASSERT_TRUE(stepped.ok() && whole.ok()) << f;
    EXPECT_EQ(stepped.value.face_indices, whole.value.face_indices) << f;
    // Level 1 read back as a level sums its rings in another order.
    ASSERT_EQ(stepped.value.positions.size(), whole.value.positions.size());
    const double tol = 1e-12 * size_of(whole.value.positions);
    for (std::size_t i = 0; i < whole.value.positions.size(); ++i)
      ASSERT_NEAR(stepped.value.positions[i], whole.value.positions[i], tol)
          << f;
  }
}

TEST(FastSqrt3Host, ABorderStepOnTwoBorderEdgesInAFaceIsRefusedAsByCgal) {
  // The triangulated grid's corner triangles have two border edges.
  Subdivide_options o;
  o.scheme = "sqrt3";
  o.triangulate = true;
  o.levels = 2;
  o.start_level = 1;
  const Result<Mesh_buffers> fast = subdivide_mesh(fixture("grid-open.off"), o);
  ASSERT_FALSE(fast.ok());
  EXPECT_EQ(fast.status.code, Status_code::invalid_argument);
  EXPECT_NE(fast.status.message.find("start_level 1 of sqrt3 refines the "
                                     "border"),
            std::string::npos)
      << fast.status.message;
  expect_same_run(fixture("grid-open.off"), o, "sqrt3 on grid from 1", false);
  o.scheme = "custom";
  o.custom = custom_rules_preset("sqrt3", 64);
  expect_same_run(fixture("grid-open.off"), o, "custom on grid from 1", false);
  EXPECT_FALSE(subdivide_mesh(fixture("grid-open.off"), o).ok());
}

TEST(FastSqrt3Host, CustomTablesThatStopShortAreRefusedAsOnCgalsHosts) {
  // Valences 3-5: the icosahedron's vertices pass; its level-1 face points
  // have valence 6: refused before step 2.
  Subdivide_options o;
  o.scheme = "custom";
  o.custom = custom_rules_preset("sqrt3", 5);
  o.levels = 1;
  EXPECT_TRUE(subdivide_mesh(fixture("icosahedron.off"), o).ok());
  o.levels = 2;
  const Result<Mesh_buffers> fast =
      subdivide_mesh(fixture("icosahedron.off"), o);
  ASSERT_FALSE(fast.ok());
  EXPECT_EQ(fast.status.message,
            "custom rules: the vertex rule has no weights for valence 6 (the "
            "table covers valences 3 to 5)");
  expect_same_run(fixture("icosahedron.off"), o, "custom on icosahedron",
                  false);
}

}  // namespace
}  // namespace subdivlab
