// The fast refinement hosts (wasm/src/refine) against CGAL's: the same
// numbering of vertices and faces, the same face corners in the same order,
// and the same points to 1e-12 of the mesh's size, at levels 1-3 of every
// fixture, closed and open, for each primal scheme, Doo-Sabin and their
// custom twins.

#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Subdivision_method_3/internal/subdivision_hosts_impl_3.h>
#include <CGAL/subdivision_method_3.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "core/custom_rules.h"
#include "core/dqq_border_3.h"
#include "core/linear_masks_3.h"
#include "core/mesh_build.h"
#include "core/mesh_check.h"
#include "core/mesh_io.h"
#include "core/subdivide.h"
#include "core/table_masks_3.h"
#include "refine/dual_hosts.h"
#include "refine/dual_masks.h"
#include "refine/dual_points.h"
#include "refine/level_convert.h"
#include "refine/primal_hosts.h"
#include "refine/primal_masks.h"
#include "refine/primal_points.h"
#include "refine_test_support.h"

namespace subdivlab {
namespace {

namespace SM3 = CGAL::Subdivision_method_3;
using namespace refine_test;

Mesh load(const std::string& name, bool triangulate) {
  std::ifstream in(std::string(FIXTURES_DIR) + "/" + name, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  const Result<Mesh_buffers> r = read_mesh(ss.str(), Mesh_format::off);
  EXPECT_TRUE(r.ok()) << name << ": " << r.status.message;
  Mesh m;
  EXPECT_TRUE(build_mesh(r.value, m).ok()) << name;
  if (triangulate) {
    CGAL::Polygon_mesh_processing::triangulate_faces(m);
    m.collect_garbage();
  }
  return m;
}

/// One CGAL step of a primal scheme, as cgal_driver.cpp runs it.
void cgal_step(const std::string& scheme, const Custom_rules& rules, Mesh& m) {
  const auto one = CGAL::parameters::number_of_iterations(1);
  if (scheme == "catmull-clark") SM3::CatmullClark_subdivision(m, one);
  if (scheme == "loop") SM3::Loop_subdivision(m, one);
  if (scheme == "linear") Linear_subdivision(m);
  if (scheme == "linear-tri") Linear_triangle_subdivision(m);
  if (scheme == "custom") custom_subdivision_step(m, rules, 0);
}

/// Fast levels 1..3 of `mesh` equal CGAL's, index for index.
void expect_cgal_levels(const std::string& scheme, const Custom_rules& rules,
                        const std::string& fixture, bool triangulate) {
  const std::string what =
      scheme + (scheme == "custom" ? "/" + rules.host : std::string()) +
      " on " + fixture;
  Mesh reference = load(fixture, triangulate);
  refine::Level level = refine::level_from_mesh(reference);
  const refine::Primal_mask_lookup mask = refine::primal_mask(scheme, rules);
  ASSERT_TRUE(mask.ok) << what;
  refine::Primal_scratch scratch;
  for (int k = 1; k <= 3; ++k) {
    cgal_step(scheme, rules, reference);
    const Mesh_buffers expected = to_buffers(reference);
    refine::Level child;
    ASSERT_EQ(refine::primal_uncovered_valence(level, mask.mask, scratch), 0u);
    if (mask.mask.pqq)
      refine::refine_pqq_topology(level, child, false);
    else
      refine::refine_ptq_topology(level, child, false);
    refine::refine_primal_points(level, mask.mask, scratch, child);
    level = child;
    const Mesh_buffers got = refine::level_to_buffers(std::move(child));
    const std::string at = what + ", level " + std::to_string(k);
    ASSERT_EQ(level.edge_count, reference.number_of_edges()) << at;
    expect_same_buffers(got, expected, at);
    if (testing::Test::HasFatalFailure()) return;
    // The halfedges too: same targets, edge by edge.
    for (Mesh::Halfedge_index h : reference.halfedges())
      ASSERT_EQ(level.halfedge_target[h.idx()], reference.target(h).idx())
          << at << ", halfedge " << h.idx();
  }
}

TEST(FastPrimalHosts, LevelFromBuffersEqualsTheSurfaceMeshBuildMeshBuilds) {
  // Surface_mesh::add_face's numbering, worked out without the mesh; the
  // last case has an isolated vertex (dropped) and mixed degrees.
  std::vector<Mesh_buffers> cases;
  for (const char* f : kFixtures) cases.push_back(to_buffers(load(f, false)));
  Mesh_buffers odd = cases.back();
  odd.positions.insert(odd.positions.begin(), {9.0, 9.0, 9.0});
  for (std::uint32_t& v : odd.face_indices) ++v;
  cases.push_back(odd);
  for (const Mesh_buffers& in : cases) {
    std::vector<std::uint32_t> corner_halfedges;
    ASSERT_TRUE(detail::check_buffers(in, {}, &corner_halfedges).status.ok());
    const refine::Level got = refine::level_from_buffers(in, corner_halfedges);
    Mesh m;
    ASSERT_TRUE(build_mesh(in, m).ok());
    const refine::Level want = refine::level_from_mesh(m);
    EXPECT_EQ(got.vertex_count, want.vertex_count);
    EXPECT_EQ(got.edge_count, want.edge_count);
    EXPECT_EQ(got.border_edge_count, want.border_edge_count);
    EXPECT_EQ(got.uniform_degree, want.uniform_degree);
    EXPECT_EQ(got.face_offsets, want.face_offsets);
    EXPECT_EQ(got.face_halfedges, want.face_halfedges);
    EXPECT_EQ(got.halfedge_target, want.halfedge_target);
    EXPECT_EQ(got.halfedge_corner, want.halfedge_corner);
    EXPECT_EQ(got.positions, want.positions);
  }
}

TEST(FastPrimalHosts, CatmullClarkAndLinearEqualCgal) {
  for (const char* f : kFixtures) {
    expect_cgal_levels("catmull-clark", {}, f, false);
    expect_cgal_levels("linear", {}, f, false);
    expect_cgal_levels("custom", custom_rules_preset("catmull-clark", 64), f,
                       false);
  }
}

TEST(FastPrimalHosts, FacePointsWeighedApartFromNeighboursEqualCgal) {
  // Face points weigh 2/n^2 and edge neighbours 1/(2 n^2) (Catmull-Clark
  // gives both 1/n^2): the PQQ points sum face points apart.
  Custom_rules apart = custom_rules_preset("catmull-clark", 64);
  for (std::size_t i = 0; i < apart.vertex.size(); ++i) {
    const double n = static_cast<double>(apart.first_valence + i);
    apart.vertex[i] = {(n - 2.5) / n, 0.5 / (n * n), 2 / (n * n)};
  }
  ASSERT_TRUE(refine::primal_mask("custom", apart).mask.separate_face_sums());
  ASSERT_FALSE(
      refine::primal_mask("catmull-clark", {}).mask.separate_face_sums());
  for (const char* f : kFixtures) expect_cgal_levels("custom", apart, f, false);
}

TEST(FastPrimalHosts, LoopAndLinearTriEqualCgal) {
  for (const char* f : kFixtures) {
    expect_cgal_levels("loop", {}, f, true);
    expect_cgal_levels("linear-tri", {}, f, true);
    expect_cgal_levels("custom", custom_rules_preset("improved-loop", 64), f,
                       true);
  }
}

TEST(FastPrimalHosts, CustomBorderRulesReadTheBorderChainInCgalOrder) {
  // Border rules with all four weights, on open meshes.
  Custom_rules pqq = custom_rules_preset("catmull-clark", 64);
  pqq.border_edge = {-0.0625, 0.5625, 0.5625, -0.0625};  // four-point
  pqq.border_vertex = {0.2, 0.5, 0.3};                   // asymmetric
  Custom_rules ptq = custom_rules_preset("loop", 64);
  ptq.border_edge = pqq.border_edge;
  ptq.border_vertex = pqq.border_vertex;
  for (const char* f : {"disk-tri.off", "grid-open.off", "mixed-open.off"}) {
    expect_cgal_levels("custom", pqq, f, false);
    expect_cgal_levels("custom", ptq, f, true);
  }
}

Mesh_buffers fixture_buffers(const std::string& name) {
  return to_buffers(load(name, false));
}

/// subdivide_mesh on the fast hosts and on CGAL's give the same buffers:
/// points (1e-12), faces, and control edges (as sets of pairs).
void expect_same_run(const Mesh_buffers& in, Subdivide_options o,
                     const std::string& what) {
  const Result<Mesh_buffers> fast = subdivide_mesh(in, o);
  o.cgal_hosts = true;
  const Result<Mesh_buffers> cgal = subdivide_mesh(in, o);
  ASSERT_TRUE(cgal.ok()) << what << ": " << cgal.status.message;
  ASSERT_TRUE(fast.ok()) << what << ": " << fast.status.message;
  expect_same_buffers(fast.value, cgal.value, what);
}

TEST(FastPrimalHosts, SubdivideMeshEqualsItsCgalHostsOnEveryFixture) {
  for (const char* f : kFixtures) {
    const Mesh_buffers in = fixture_buffers(f);
    for (const char* scheme :
         {"catmull-clark", "loop", "linear", "linear-tri", "custom"}) {
      for (int levels = 1; levels <= 3; ++levels) {
        Subdivide_options o;
        o.scheme = scheme;
        o.levels = levels;
        o.triangulate = true;  // loop on polygons: CGAL triangulates first
        if (o.scheme == "custom")
          o.custom =
              custom_rules_preset(levels == 2 ? "loop" : "catmull-clark");
        expect_same_run(
            in, o,
            std::string(scheme) + " x" + std::to_string(levels) + " on " + f);
      }
    }
  }
}

TEST(FastPrimalHosts, SubdivideMeshEqualsItsCgalHostsOnCgalsMeshes) {
  // Larger meshes from CGAL's data set (set-up extracts them): open with
  // holes, closed with high valences.
  for (const char* f : {"holes.off", "fandisk.off", "mannequin-devil.off"}) {
    const Mesh_buffers in = cgal_mesh(f);
    for (const char* scheme : {"catmull-clark", "loop"}) {
      Subdivide_options o;
      o.scheme = scheme;
      o.levels = 2;
      expect_same_run(in, o, std::string(scheme) + " x2 on " + f);
    }
  }
}

TEST(FastPrimalHosts, LevelByLevelCarriesTheControlEdgesAsCgalDoes) {
  // A level-2 mesh with its marks, subdivided once more from start_level 2.
  for (const char* f : {"rhombicuboctahedron.off", "mixed-open.off"}) {
    Subdivide_options o;
    o.levels = 2;
    Mesh_buffers level2 = subdivide_mesh(fixture_buffers(f), o).value;
    o.levels = 1;
    o.start_level = 2;
    expect_same_run(level2, o,
                    std::string("catmull-clark from level 2 of ") + f);
  }
}

TEST(FastPrimalHosts,
     CustomTablesThatStopShortAreRefusedAtTheLevelThatNeedsMore) {
  // Valences 3-4 only: the cube's level 0 (valence 3) and level 1 (4) are
  // covered; the rhombicuboctahedron's are too, but level 1 of a pentagon
  // prism has a face point of valence 5.
  Subdivide_options o;
  o.scheme = "custom";
  o.custom = custom_rules_preset("catmull-clark", 4);
  o.levels = 3;
  EXPECT_TRUE(subdivide_mesh(fixture_buffers("cube.off"), o).ok());
  const Mesh_buffers prism = pentagonal_prism();
  const Result<Mesh_buffers> r = subdivide_mesh(prism, o);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status.code, Status_code::invalid_argument);
  EXPECT_EQ(r.status.message,
            "custom rules: the vertex rule has no weights for valence 5 (the "
            "table covers valences 3 to 4)");
  o.cgal_hosts = true;
  EXPECT_EQ(subdivide_mesh(prism, o).status.message, r.status.message);
}

// ---------------------------------------------------------------------------
// The DQQ host (Doo-Sabin): closed meshes against CGAL's DQQ_1step, open
// ones against dqq_border_3.h, through subdivide_mesh's two routes.

TEST(FastDualHost, VertexHalfedgesAreTheOnesAddFaceLeaves) {
  for (const char* f : kFixtures) {
    const Mesh m = load(f, false);
    refine::Level l = refine::level_from_mesh(m);
    refine::add_face_vertex_halfedges(l);
    for (Mesh::Vertex_index v : m.vertices())
      ASSERT_EQ(l.vertex_halfedge[v.idx()], m.halfedge(v).idx())
          << f << ", vertex " << v.idx();
  }
}

/// Levels 1..3 of the DQQ host equal CGAL's route (DQQ_1step and
/// collect_garbage closed, DQQ_border_1step open), tables included:
/// halfedge targets and each vertex's halfedge, which the next step reads.
void expect_cgal_dqq_levels(const Custom_rules* rules, const Mesh& mesh,
                            const std::string& what) {
  Mesh reference = mesh;
  refine::Level level = refine::level_from_mesh(reference);
  refine::add_face_vertex_halfedges(level);
  const refine::Dual_mask_lookup mask =
      refine::dual_mask(rules != nullptr ? "custom" : "doo-sabin",
                        rules != nullptr ? *rules : Custom_rules());
  ASSERT_TRUE(mask.ok) << what;
  refine::Dual_scratch scratch;
  for (int k = 1; k <= 3; ++k) {
    const bool closed = CGAL::is_closed(reference);
    if (rules != nullptr)
      custom_subdivision_step(reference, *rules, 0);
    else if (closed)
      SM3::DooSabin_subdivision(reference,
                                CGAL::parameters::number_of_iterations(1));
    else
      DooSabin_border_subdivision(reference,
                                  CGAL::parameters::number_of_iterations(1));
    reference.collect_garbage();
    const Mesh_buffers expected = to_buffers(reference);
    refine::Level child;
    ASSERT_EQ(refine::dual_uncovered_degree(level, mask.mask), 0u);
    refine::refine_dqq_topology(level, scratch, child, false);
    refine::refine_dual_points(level, mask.mask, scratch, child);
    const std::string at = what + ", level " + std::to_string(k);
    ASSERT_EQ(child.edge_count, reference.number_of_edges()) << at;
    ASSERT_EQ(child.border_edge_count * 2 == 0, closed) << at;
    for (Mesh::Halfedge_index h : reference.halfedges()) {
      ASSERT_EQ(child.halfedge_target[h.idx()], reference.target(h).idx())
          << at << ", halfedge " << h.idx();
      ASSERT_EQ(child.halfedge_corner[h.idx()] == refine::kNone,
                reference.is_border(h))
          << at << ", halfedge " << h.idx();
    }
    for (Mesh::Vertex_index v : reference.vertices())
      ASSERT_EQ(child.vertex_halfedge[v.idx()], reference.halfedge(v).idx())
          << at << ", vertex " << v.idx();
    level = child;
    const Mesh_buffers got = refine::level_to_buffers(std::move(child));
    expect_same_buffers(got, expected, at);
    if (testing::Test::HasFatalFailure()) return;
  }
}

TEST(FastDualHost, TablesEqualCgalsLevelByLevel) {
  const Custom_rules preset = custom_rules_preset("doo-sabin", 64);
  for (const char* f : kFixtures) {
    expect_cgal_dqq_levels(nullptr, load(f, false),
                           std::string("doo-sabin on ") + f);
    expect_cgal_dqq_levels(&preset, load(f, false),
                           std::string("custom dqq on ") + f);
  }
}

/// Rule sets on the dqq host: the preset, and one whose weights differ by
/// corner and whose border rule is asymmetric.
std::vector<Custom_rules> dqq_rules() {
  Custom_rules odd = custom_rules_preset("doo-sabin", 64);
  for (auto& w : odd.corner) {
    w[0] -= 0.05;
    w[1] += 0.05;
  }
  odd.border_corner = {0.6, 0.4};
  return {custom_rules_preset("doo-sabin", 64), odd};
}

TEST(FastDualHost, SubdivideMeshEqualsItsCgalHostsOnEveryFixture) {
  for (const char* f : kFixtures) {
    const Mesh_buffers in = fixture_buffers(f);
    for (int levels = 1; levels <= 3; ++levels) {
      Subdivide_options o;
      o.scheme = "doo-sabin";
      o.levels = levels;
      expect_same_run(in, o,
                      "doo-sabin x" + std::to_string(levels) + " on " + f);
      o.scheme = "custom";
      for (const Custom_rules& rules : dqq_rules()) {
        o.custom = rules;
        expect_same_run(in, o,
                        "custom dqq x" + std::to_string(levels) + " on " + f);
      }
    }
  }
}

TEST(FastDualHost, AClosedAndAnOpenComponentTogetherTakeTheBorderHost) {
  // CGAL's route picks its host by CGAL::is_closed on the whole mesh: the
  // cube beside the open grid is refined by the border host too.
  Mesh_buffers in = fixture_buffers("cube.off");
  const Mesh_buffers grid = fixture_buffers("grid-open.off");
  const auto shift = static_cast<std::uint32_t>(in.vertex_count());
  in.positions.insert(in.positions.end(), grid.positions.begin(),
                      grid.positions.end());
  in.face_sizes.insert(in.face_sizes.end(), grid.face_sizes.begin(),
                       grid.face_sizes.end());
  for (std::uint32_t v : grid.face_indices)
    in.face_indices.push_back(v + shift);
  for (int levels = 1; levels <= 3; ++levels) {
    Subdivide_options o;
    o.scheme = "doo-sabin";
    o.levels = levels;
    expect_same_run(in, o,
                    "doo-sabin x" + std::to_string(levels) + " on cube + grid");
  }
}

TEST(FastDualHost, SubdivideMeshEqualsItsCgalHostsOnCgalsMeshes) {
  for (const char* f : kCgalMeshes) {
    const Mesh_buffers in = cgal_mesh(f);
    for (int levels = 1; levels <= 2; ++levels) {
      Subdivide_options o;
      o.scheme = "doo-sabin";
      o.levels = levels;
      expect_same_run(in, o,
                      "doo-sabin x" + std::to_string(levels) + " on " + f);
    }
  }
}

TEST(FastDualHost, LevelByLevelEqualsOneRun) {
  // A level-2 mesh subdivided once more from start_level 2: level 0 from
  // the buffers of a DQQ level (mixed degrees, ears on the open grid).
  for (const char* f :
       {"rhombicuboctahedron.off", "mixed-open.off", "grid-open.off"}) {
    Subdivide_options o;
    o.scheme = "doo-sabin";
    o.levels = 2;
    Mesh_buffers level2 = subdivide_mesh(fixture_buffers(f), o).value;
    o.levels = 1;
    o.start_level = 2;
    expect_same_run(level2, o, std::string("doo-sabin from level 2 of ") + f);
  }
}

TEST(FastDualHost, CustomTablesThatStopShortAreRefusedAsOnCgalsHosts) {
  // Degrees 3-4 only. The cube's levels have triangles and quads; the
  // mixed fixture has a pentagon at level 0; the icosahedron's level 1 has
  // a pentagon per vertex (its V-faces), refused before step 2.
  Subdivide_options o;
  o.scheme = "custom";
  o.custom = custom_rules_preset("doo-sabin", 4);
  o.levels = 2;
  EXPECT_TRUE(subdivide_mesh(fixture_buffers("cube.off"), o).ok());
  for (const char* f : {"mixed-open.off", "icosahedron.off"}) {
    const Result<Mesh_buffers> fast = subdivide_mesh(fixture_buffers(f), o);
    ASSERT_FALSE(fast.ok()) << f;
    EXPECT_EQ(fast.status.code, Status_code::invalid_argument) << f;
    EXPECT_EQ(fast.status.message,
              "custom rules: the corner rule has no weights for faces of "
              "degree 5 (the table covers degrees 3 to 4)")
        << f;
    Subdivide_options c = o;
    c.cgal_hosts = true;
    EXPECT_EQ(subdivide_mesh(fixture_buffers(f), c).status.message,
              fast.status.message)
        << f;
  }
}

}  // namespace
}  // namespace subdivlab
