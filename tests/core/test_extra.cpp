// Issue 4 in the core: quad-triangle, linear / linear-tri, custom rule tables
// and control edges. Reference positions come from CGAL's own masks
// (CatmullClark_mask_3, Loop_mask_3, Sqrt3_mask_3) and from the border-aware
// Doo-Sabin of dqq_border_3.h, or are worked out in the test from the
// control mesh.

#include <CGAL/Subdivision_method_3/internal/subdivision_hosts_impl_3.h>
#include <CGAL/subdivision_method_3.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "core/control_edges.h"
#include "core/custom_rules.h"
#include "core/dqq_border_3.h"
#include "core/linear_masks_3.h"
#include "core/mesh_build.h"
#include "core/mesh_facts.h"
#include "core/mesh_io.h"
#include "core/quad_triangle_3.h"
#include "core/subdivide.h"
#include "refine_test_support.h"

namespace subdivlab {
namespace {

namespace params = CGAL::parameters;

Mesh load(const std::string& name) {
  std::ifstream in(std::string(FIXTURES_DIR) + "/" + name, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  const Mesh_format format =
      name.size() > 4 && name.substr(name.size() - 4) == ".obj"
          ? Mesh_format::obj
          : Mesh_format::off;
  Result<Mesh_buffers> r = read_mesh(ss.str(), format);
  EXPECT_TRUE(r.ok()) << name << ": " << r.status.message;
  Mesh m;
  const Status s = build_mesh(r.value, m);
  EXPECT_TRUE(s.ok()) << name << ": " << s.message;
  return m;
}

Mesh_buffers load_buffers(const std::string& name) {
  return to_buffers(load(name));
}

/// Same counts, and vertex i of a at vertex i of b within tol (max norm).
void expect_same_points(const Mesh& a, const Mesh& b, double tol,
                        const std::string& what) {
  ASSERT_EQ(a.number_of_vertices(), b.number_of_vertices()) << what;
  ASSERT_EQ(a.number_of_faces(), b.number_of_faces()) << what;
  ASSERT_EQ(a.number_of_edges(), b.number_of_edges()) << what;
  double worst = 0.0;
  std::size_t worst_v = 0;
  auto ia = a.vertices().begin();
  auto ib = b.vertices().begin();
  for (std::size_t i = 0; ia != a.vertices().end(); ++ia, ++ib, ++i) {
    const Point &p = a.point(*ia), &q = b.point(*ib);
    for (int c = 0; c < 3; ++c) {
      const double d = std::abs(p[c] - q[c]);
      if (!(d <= worst)) {
        worst = d;
        worst_v = i;
      }
    }
  }
  EXPECT_LE(worst, tol) << what << ": vertex " << worst_v << " differs by "
                        << worst;
}

struct Face_counts {
  std::size_t triangles = 0, quads = 0, other = 0;
};
Face_counts face_counts(const Mesh& m) {
  Face_counts c;
  for (auto f : m.faces()) {
    const auto k = m.degree(f);
    (k == 3 ? c.triangles : k == 4 ? c.quads : c.other)++;
  }
  return c;
}

std::size_t border_edges(const Mesh& m) {
  std::size_t n = 0;
  for (auto e : m.edges())
    if (m.is_border(e)) ++n;
  return n;
}

// ----------------------------------------------------------------
// quad-triangle

TEST(ExtraQuadTriangle, EqualsCatmullClarkOnRegularQuadTorus) {
  const Mesh torus = load("torus-quad.off");
  for (const auto& v : torus.vertices()) ASSERT_EQ(torus.degree(v), 4u);
  for (int levels = 1; levels <= 3; ++levels) {
    Mesh qt = torus, cc = torus;
    QuadTriangle_subdivision(qt, levels);
    CGAL::Subdivision_method_3::CatmullClark_subdivision(
        cc, params::number_of_iterations(levels));
    expect_same_points(qt, cc, 1e-12,
                       "torus-quad level " + std::to_string(levels));
    EXPECT_EQ(face_counts(qt).quads, 48u << (2 * levels));
  }
}

TEST(ExtraQuadTriangle, EqualsLoopOnRegularTriangleTorus) {
  const Mesh torus = load("torus-tri.off");
  for (const auto& v : torus.vertices()) ASSERT_EQ(torus.degree(v), 6u);
  for (int levels = 1; levels <= 3; ++levels) {
    Mesh qt = torus, loop = torus;
    QuadTriangle_subdivision(qt, levels);
    CGAL::Subdivision_method_3::Loop_subdivision(
        loop, params::number_of_iterations(levels));
    expect_same_points(qt, loop, 1e-12,
                       "torus-tri level " + std::to_string(levels));
    EXPECT_EQ(face_counts(qt).triangles, 96u << (2 * levels));
  }
}

// The correction makes the scheme Catmull-Clark / Loop at extraordinary
// vertices too, and its border rule is theirs.
TEST(ExtraQuadTriangle, EqualsCatmullClarkAtValence3AndOnOpenQuadMeshes) {
  for (const char* name : {"cube.off", "grid-open.off"}) {
    const Mesh m = load(name);
    Mesh qt = m, cc = m;
    QuadTriangle_subdivision(qt, 3);
    CGAL::Subdivision_method_3::CatmullClark_subdivision(
        cc, params::number_of_iterations(3));
    expect_same_points(qt, cc, 1e-12, name);
  }
}

TEST(ExtraQuadTriangle, EqualsLoopAtValences3To5AndOnOpenTriangleMeshes) {
  for (const char* name : {"tetrahedron.off", "octahedron.off",
                           "icosahedron.off", "disk-tri.off"}) {
    const Mesh m = load(name);
    Mesh qt = m, loop = m;
    QuadTriangle_subdivision(qt, 3);
    CGAL::Subdivision_method_3::Loop_subdivision(
        loop, params::number_of_iterations(3));
    expect_same_points(qt, loop, 1e-12, name);
  }
}

TEST(ExtraQuadTriangle, RhombicuboctahedronOneStepGives32TrianglesAnd72Quads) {
  const Mesh m = load("rhombicuboctahedron.off");
  const Face_counts c0 = face_counts(m);
  ASSERT_EQ(c0.triangles, 8u);
  ASSERT_EQ(c0.quads, 18u);
  Mesh qt = m;
  QuadTriangle_subdivision(qt, 1);
  const Face_counts c = face_counts(qt);
  EXPECT_EQ(c.triangles, 32u);
  EXPECT_EQ(c.quads, 72u);
  EXPECT_EQ(c.other, 0u);
  EXPECT_EQ(qt.number_of_vertices(), 24u + 48u + 18u);  // V + E + quads
  EXPECT_EQ(qt.number_of_edges(), 2u * 48u + 3u * 8u + 4u * 18u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(qt));
  EXPECT_EQ(border_edges(qt), 0u);
  // Level 2: every triangle and every quad splits into four of its kind.
  QuadTriangle_subdivision(qt, 1);
  EXPECT_EQ(face_counts(qt).triangles, 128u);
  EXPECT_EQ(face_counts(qt).quads, 288u);
}

// Old vertex of the rhombicuboctahedron: 1 triangle + 3 quads (angle sum
// 330 deg, not regular), so the correction applies. Position worked out
// from the control mesh: after the split its neighbours are the 4 edge
// midpoints and its opposite quad corners the 3 quad centroids.
TEST(ExtraQuadTriangle, IrregularMixedVertexFollowsTheDocumentedCorrection) {
  const Mesh m = load("rhombicuboctahedron.off");
  Mesh qt = m;
  QuadTriangle_subdivision(qt, 1);
  for (Mesh::Vertex_index v : m.vertices()) {
    const Kernel::Vector_3 s = m.point(v) - CGAL::ORIGIN;
    Kernel::Vector_3 ring(0, 0, 0), corners(0, 0, 0);
    int ne = 0, nq = 0;
    for (auto h : CGAL::halfedges_around_target(v, m)) {
      ring = ring + ((m.point(m.source(h)) - CGAL::ORIGIN) + s) / 2.0;
      ++ne;
      if (m.degree(m.face(h)) == 4) {
        Kernel::Vector_3 c(0, 0, 0);
        for (auto u : CGAL::vertices_around_face(h, m))
          c = c + (m.point(u) - CGAL::ORIGIN);
        corners = corners + c / 4.0;
        ++nq;
      }
    }
    ASSERT_EQ(ne, 4);
    ASSERT_EQ(nq, 3);
    const double alpha = 1.0 / (1.0 + ne / 2.0 + nq / 4.0);
    const Kernel::Vector_3 a = alpha * (s + ring / 2.0 + corners / 4.0);
    // lambda = (3 lambda_q(11/3) + lambda_t(11/2)) / 4
    const double nQ = 11.0 / 3.0, nT = 11.0 / 2.0;
    const double lq = (4 + 3 * nQ) / (nQ * nQ);
    const double t = 3 + 2 * std::cos(2 * CGAL_PI / nT);
    const double lt = (4 + 2 * nT) * (5.0 / 8.0 - t * t / 64.0) / nT;
    const double lambda = (3 * lq + lt) / 4;
    const Kernel::Vector_3 expected = s + lambda * (a - s);
    const Point& got = qt.point(v);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(got[c], expected[c], 1e-12) << "vertex " << v.idx();
  }
}

TEST(ExtraQuadTriangle, RelaxationIsOneExactlyAtRegularConfigurations) {
  EXPECT_EQ(quad_triangle_relaxation(4, 0), 1.0);
  EXPECT_EQ(quad_triangle_relaxation(0, 6), 1.0);
  EXPECT_EQ(quad_triangle_relaxation(2, 3), 1.0);
  EXPECT_DOUBLE_EQ(quad_triangle_relaxation(3, 0), 13.0 / 9.0);  // (4 + 9) / 9
  EXPECT_DOUBLE_EQ(quad_triangle_relaxation(0, 3), 10.0 * (9.0 / 16.0) / 3.0);
}

TEST(ExtraQuadTriangle, PolygonsBecomeQuadsAroundTheirCentroid) {
  const Mesh m = load("mixed-open.off");  // 2 quads, 6 triangles, 1 pentagon
  Mesh qt = m;
  QuadTriangle_subdivision(qt, 1);
  const Face_counts c = face_counts(qt);
  EXPECT_EQ(c.triangles, 24u);
  EXPECT_EQ(c.quads, 8u + 5u);
  EXPECT_EQ(c.other, 0u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(qt));
  EXPECT_EQ(border_edges(qt), 2 * border_edges(m));
}

TEST(ExtraQuadTriangle, FixedBoundaryKeepsTheBorderPolygon) {
  for (const char* name : {"grid-open.off", "mixed-open.off", "disk-tri.off"}) {
    const Mesh m = load(name);
    Mesh fixed = m, smooth = m;
    QuadTriangle_subdivision(fixed, 1, /*smooth_boundary=*/false);
    QuadTriangle_subdivision(smooth, 1, /*smooth_boundary=*/true);
    // Old border vertices keep their indices and positions; the edge point
    // of a border edge i (numbered num_v + i) is its midpoint.
    const std::size_t nv = m.number_of_vertices();
    std::size_t i = 0, moved = 0;
    for (Mesh::Edge_index e : m.edges()) {
      if (m.is_border(e)) {
        const auto a = m.vertex(e, 0), b = m.vertex(e, 1);
        const Point mid = CGAL::midpoint(m.point(a), m.point(b));
        const Point& got =
            fixed.point(Mesh::Vertex_index(static_cast<std::uint32_t>(nv + i)));
        EXPECT_EQ(fixed.point(a), m.point(a)) << name;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], mid[c], 1e-15) << name;
        if (smooth.point(a) != m.point(a)) ++moved;
      }
      ++i;
    }
    EXPECT_GT(moved, 0u) << name << ": the smooth border rule moved nothing";
  }
}

// ---------------------------------------------------------------- linear

/// New points of a primal linear step, as the control mesh predicts them:
/// old vertices stay, edge point i = midpoint of edge i, then (PQQ) face
/// point j = centroid of face j.
void expect_linear_step(const Mesh& m, const Mesh& r, bool face_points,
                        const std::string& what) {
  const std::size_t nv = m.number_of_vertices();
  for (Mesh::Vertex_index v : m.vertices())
    EXPECT_EQ(r.point(v), m.point(v)) << what;
  std::uint32_t next = static_cast<std::uint32_t>(nv);
  for (Mesh::Edge_index e : m.edges()) {
    const Point mid =
        CGAL::midpoint(m.point(m.vertex(e, 0)), m.point(m.vertex(e, 1)));
    const Point& got = r.point(Mesh::Vertex_index(next++));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], mid[c], 1e-15) << what;
  }
  if (!face_points) {
    EXPECT_EQ(r.number_of_vertices(), next) << what;
    return;
  }
  for (Mesh::Face_index f : m.faces()) {
    Kernel::Vector_3 s(0, 0, 0);
    int k = 0;
    for (auto u : CGAL::vertices_around_face(m.halfedge(f), m)) {
      s = s + (m.point(u) - CGAL::ORIGIN);
      ++k;
    }
    const Point& got = r.point(Mesh::Vertex_index(next++));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], s[c] / k, 1e-15) << what;
  }
  EXPECT_EQ(r.number_of_vertices(), next) << what;
}

TEST(ExtraLinear,
     PqqKeepsVerticesAndSplitsAtMidpointsAndCentroidsOnOpenMeshes) {
  for (const char* name : {"grid-open.off", "mixed-open.off", "cube.off"}) {
    const Mesh m = load(name);
    Mesh r = m;
    Linear_subdivision(r);
    expect_linear_step(m, r, true, name);
    EXPECT_EQ(face_counts(r).quads, r.number_of_faces()) << name;
    EXPECT_EQ(border_edges(r), 2 * border_edges(m)) << name;
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(r)) << name;
  }
}

TEST(ExtraLinear, PtqKeepsVerticesAndSplitsTrianglesAtMidpointsOnOpenMeshes) {
  for (const char* name : {"disk-tri.off", "icosahedron.off"}) {
    const Mesh m = load(name);
    Mesh r = m;
    Linear_triangle_subdivision(r);
    expect_linear_step(m, r, false, name);
    EXPECT_EQ(face_counts(r).triangles, 4 * m.number_of_faces()) << name;
    EXPECT_EQ(border_edges(r), 2 * border_edges(m)) << name;
  }
}

// ---------------------------------------------------------------- custom

/// `steps` steps of the custom rules, level indices from 0.
Mesh run_custom(Mesh m, const Custom_rules& rules, int steps) {
  for (int i = 0; i < steps; ++i) {
    EXPECT_TRUE(check_custom_rules_cover(rules, m).ok());
    custom_subdivision_step(m, rules, i);
  }
  return m;
}

TEST(ExtraCustom, PresetsPassTheirOwnChecks) {
  for (const char* name : {"catmull-clark", "loop", "doo-sabin", "sqrt3",
                           "improved-loop", "linear"}) {
    const Custom_rules r = custom_rules_preset(name, 64);
    const Status s = check_custom_rules(r);
    EXPECT_TRUE(s.ok()) << name << ": " << s.message;
  }
  EXPECT_EQ(custom_rules_preset("no-such", 64).host, "");
}

TEST(ExtraCustom, CatmullClarkPresetEqualsCatmullClark) {
  const Custom_rules rules = custom_rules_preset("catmull-clark", 16);
  for (const char* name :
       {"cube.off", "torus-quad.off", "grid-open.off", "mixed-open.off"}) {
    const Mesh m = load(name);
    Mesh cc = m;
    CGAL::Subdivision_method_3::CatmullClark_subdivision(
        cc, params::number_of_iterations(3));
    expect_same_points(run_custom(m, rules, 3), cc, 1e-12, name);
  }
}

TEST(ExtraCustom, LoopPresetEqualsLoop) {
  const Custom_rules rules = custom_rules_preset("loop", 16);
  for (const char* name : {"tetrahedron.off", "icosahedron.off",
                           "torus-tri.off", "disk-tri.off"}) {
    const Mesh m = load(name);
    Mesh loop = m;
    CGAL::Subdivision_method_3::Loop_subdivision(
        loop, params::number_of_iterations(3));
    expect_same_points(run_custom(m, rules, 3), loop, 1e-12, name);
  }
}

TEST(ExtraCustom, DooSabinPresetEqualsDooSabin) {
  const Custom_rules rules = custom_rules_preset("doo-sabin", 16);
  // Closed: CGAL's DQQ host and DooSabin_mask_3.
  for (const char* name :
       {"cube.off", "tetrahedron.off", "rhombicuboctahedron.off"}) {
    const Mesh m = load(name);
    Mesh ds = m;
    CGAL::Subdivision_method_3::DooSabin_subdivision(
        ds, params::number_of_iterations(3));
    expect_same_points(run_custom(m, rules, 3), ds, 1e-12, name);
  }
  // Open: the border-aware host of dqq_border_3.h.
  for (const char* name : {"grid-open.off", "mixed-open.off"}) {
    const Mesh m = load(name);
    Mesh ds = m;
    DooSabin_border_subdivision(ds, params::number_of_iterations(3));
    expect_same_points(run_custom(m, rules, 3), ds, 1e-12, name);
  }
}

TEST(ExtraCustom, Sqrt3PresetEqualsSqrt3WithBorderParity) {
  const Custom_rules rules = custom_rules_preset("sqrt3", 16);
  for (const char* name :
       {"icosahedron.off", "torus-tri.off", "disk-tri.off"}) {
    const Mesh m = load(name);
    Mesh s3 = m;
    CGAL::Subdivision_method_3::Sqrt3_subdivision(
        s3, params::number_of_iterations(3));
    expect_same_points(run_custom(m, rules, 3), s3, 1e-12, name);
  }
}

TEST(ExtraCustom, LinearPresetEqualsLinear) {
  const Custom_rules rules = custom_rules_preset("linear", 16);
  for (const char* name : {"grid-open.off", "mixed-open.off"}) {
    const Mesh m = load(name);
    Mesh lin = m;
    for (int i = 0; i < 2; ++i) Linear_subdivision(lin);
    expect_same_points(run_custom(m, rules, 2), lin, 0.0, name);
  }
}

TEST(ExtraCustom, ImprovedLoopPresetFollowsWarrenAwayFromValence6) {
  const Custom_rules rules = custom_rules_preset("improved-loop", 16);
  // Valence 4 (octahedron): v' = 5/8 v + 3/32 sum(neighbours).
  const Mesh m = load("octahedron.off");
  const Mesh r = run_custom(m, rules, 1);
  for (Mesh::Vertex_index v : m.vertices()) {
    Kernel::Vector_3 ring(0, 0, 0);
    for (auto u : CGAL::vertices_around_target(m.halfedge(v), m))
      ring = ring + (m.point(u) - CGAL::ORIGIN);
    const Kernel::Vector_3 expected =
        0.625 * (m.point(v) - CGAL::ORIGIN) + (3.0 / 32.0) * ring;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(r.point(v)[c], expected[c], 1e-15);
  }
}

TEST(ExtraCustom, RefusesNonFiniteWeightsNamingRuleAndValence) {
  Custom_rules r = custom_rules_preset("catmull-clark", 8);
  r.vertex[5 - 3].neighbour = std::numeric_limits<double>::quiet_NaN();
  Status s = check_custom_rules(r);
  EXPECT_EQ(s.code, Status_code::invalid_argument);
  EXPECT_EQ(s.message,
            "custom rules: the vertex rule at valence 5 has a weight that is "
            "not finite (nan)");

  r = custom_rules_preset("doo-sabin", 8);
  r.corner[6 - 3][2] = std::numeric_limits<double>::infinity();
  s = check_custom_rules(r);
  EXPECT_EQ(s.code, Status_code::invalid_argument);
  EXPECT_EQ(s.message,
            "custom rules: the corner rule at degree 6 has a weight that is "
            "not finite (inf)");

  r = custom_rules_preset("loop", 8);
  r.edge_wing = std::numeric_limits<double>::infinity();
  s = check_custom_rules(r);
  EXPECT_EQ(
      s.message,
      "custom rules: the edge rule has a weight that is not finite (inf)");
}

TEST(ExtraCustom, RefusesStencilsThatDoNotSumToOne) {
  Custom_rules r = custom_rules_preset("catmull-clark", 8);
  r.vertex[4 - 3].self += 0.1;
  Status s = check_custom_rules(r);
  EXPECT_EQ(s.code, Status_code::invalid_argument);
  EXPECT_EQ(s.message,
            "custom rules: the vertex rule at valence 4 sums to 1.1, not 1");

  r = custom_rules_preset("loop", 8);
  r.edge_end = 0.4;  // 2 (0.4 + 0.125) = 1.05
  EXPECT_EQ(check_custom_rules(r).message,
            "custom rules: the edge rule sums to 1.05, not 1");

  r = custom_rules_preset("doo-sabin", 8);
  r.corner[0] = {0.5, 0.25, 0.2};
  EXPECT_EQ(check_custom_rules(r).message,
            "custom rules: the corner rule at degree 3 sums to 0.95, not 1");

  r = custom_rules_preset("sqrt3", 8);
  r.border_vertex = {0.2, 0.5, 0.2};
  EXPECT_EQ(check_custom_rules(r).message,
            "custom rules: the border vertex rule sums to 0.9, not 1");

  // Within 1e-9 is accepted.
  r = custom_rules_preset("catmull-clark", 8);
  r.vertex[0].self += 5e-10;
  EXPECT_TRUE(check_custom_rules(r).ok());

  r = custom_rules_preset("loop", 8);
  r.vertex[0].face = 0.01;
  r.vertex[0].self -= 3 * 0.01;
  EXPECT_EQ(check_custom_rules(r).message,
            "custom rules: the vertex rule at valence 3 has a face weight "
            "(0.01), which the ptq host "
            "does not use; it must be 0");

  r.host = "bogus";
  EXPECT_EQ(
      check_custom_rules(r).message,
      "custom rules: unknown host \"bogus\" (expected pqq, ptq, dqq or sqrt3)");
}

TEST(ExtraCustom, RefusesTablesThatDoNotCoverTheMesh) {
  const Custom_rules r = custom_rules_preset("loop", 5);  // valences 3..5
  const Status s = check_custom_rules_cover(r, load("torus-tri.off"));
  EXPECT_EQ(s.code, Status_code::invalid_argument);
  EXPECT_EQ(s.message,
            "custom rules: the vertex rule has no weights for valence 6 (the "
            "table covers valences 3 "
            "to 5)");
  const Custom_rules d = custom_rules_preset("doo-sabin", 4);
  EXPECT_EQ(check_custom_rules_cover(d, load("mixed-open.off")).message,
            "custom rules: the corner rule has no weights for faces of degree "
            "5 (the table covers "
            "degrees 3 to 4)");
  // Border vertices use the border rule, whatever their valence.
  EXPECT_TRUE(check_custom_rules_cover(custom_rules_preset("loop", 3),
                                       load("disk-tri.off"))
                  .ok() == false);  // the centre has valence 6
  EXPECT_TRUE(check_custom_rules_cover(custom_rules_preset("loop", 6),
                                       load("disk-tri.off"))
                  .ok());
}

// ---------------------------------------------------------------- control
// edges

/// Checks that `edges` (pairs of vertex indices of `m`) form exactly one
/// chain of `length` edges per edge of `control`, between its two corners
/// (the control vertices keep their indices).
void expect_chains(const Mesh& control, const Mesh& m,
                   const Control_edges& edges, std::size_t length) {
  ASSERT_EQ(edges.size(), control.number_of_edges() * length);
  std::map<std::uint32_t, std::vector<std::uint32_t>> adj;
  for (const auto& [a, b] : edges) {
    ASSERT_NE(m.halfedge(Mesh::Vertex_index(a), Mesh::Vertex_index(b)),
              Mesh::null_halfedge());
    adj[a].push_back(b);
    adj[b].push_back(a);
  }
  const std::uint32_t nv =
      static_cast<std::uint32_t>(control.number_of_vertices());
  for (const auto& [v, n] : adj) {
    if (v < nv)
      EXPECT_EQ(n.size(), control.degree(Mesh::Vertex_index(v)))
          << "corner " << v;
    else
      EXPECT_EQ(n.size(), 2u) << "vertex " << v << " inside a chain";
  }
  std::set<std::pair<std::uint32_t, std::uint32_t>> found;
  for (std::uint32_t c = 0; c < nv; ++c) {
    for (std::uint32_t first : adj[c]) {
      std::uint32_t prev = c, cur = first;
      std::size_t steps = 1;
      while (cur >= nv) {
        const auto& n = adj[cur];
        const std::uint32_t nxt = n[0] == prev ? n[1] : n[0];
        prev = cur;
        cur = nxt;
        ++steps;
      }
      EXPECT_EQ(steps, length);
      EXPECT_NE(
          control.halfedge(Mesh::Vertex_index(c), Mesh::Vertex_index(cur)),
          Mesh::null_halfedge())
          << "chain from " << c << " ends at " << cur << ", not a neighbour";
      found.insert({std::min(c, cur), std::max(c, cur)});
    }
  }
  EXPECT_EQ(found.size(), control.number_of_edges());
}

TEST(ExtraControlEdges, CubeCatmullClarkLevel3Has96EdgesIn12Chains) {
  const Mesh cube = load("cube.off");
  Mesh m = cube;
  Mesh_buffers in = to_buffers(cube);
  Result<Control_edges> ce = initial_control_edges(in, m, 0);
  ASSERT_TRUE(ce.ok());
  ASSERT_EQ(ce.value.size(), 12u);
  Control_edges edges = ce.value;
  for (int i = 0; i < 3; ++i) {
    const auto old_end = static_cast<std::uint32_t>(m.number_of_vertices());
    CGAL::Subdivision_method_3::CatmullClark_subdivision(
        m, params::number_of_iterations(1));
    edges = refine_control_edges(m, old_end, edges);
  }
  EXPECT_EQ(edges.size(), 12u * 8u);
  expect_chains(cube, m, edges, 8);
}

TEST(ExtraControlEdges, QuadTriangleAndLinearTriKeepChains) {
  const Mesh rh = load("rhombicuboctahedron.off");
  Mesh m = rh;
  Control_edges edges = initial_control_edges(to_buffers(rh), m, 0).value;
  for (int i = 0; i < 2; ++i) {
    const auto old_end = static_cast<std::uint32_t>(m.number_of_vertices());
    QuadTriangle_subdivision(m, 1);
    edges = refine_control_edges(m, old_end, edges);
  }
  expect_chains(rh, m, edges, 4);

  const Mesh disk = load("disk-tri.off");
  Mesh d = disk;
  edges = initial_control_edges(to_buffers(disk), d, 0).value;
  for (int i = 0; i < 3; ++i) {
    const auto old_end = static_cast<std::uint32_t>(d.number_of_vertices());
    Linear_triangle_subdivision(d);
    edges = refine_control_edges(d, old_end, edges);
  }
  expect_chains(disk, d, edges, 8);
}

TEST(ExtraControlEdges, GivenPairsAreCheckedAndMapped) {
  const Mesh cube = load("cube.off");
  Mesh_buffers in = to_buffers(cube);
  // An isolated vertex in front shifts every index by one in the mesh.
  Mesh_buffers shifted = in;
  shifted.positions.insert(shifted.positions.begin(), {9.0, 9.0, 9.0});
  for (auto& i : shifted.face_indices) ++i;
  shifted.control_edges = {1, 2, 2, 4};  // cube vertices 0-1 and 1-3
  Mesh m;
  ASSERT_TRUE(build_mesh(shifted, m).ok());
  Result<Control_edges> r = initial_control_edges(shifted, m, 2);
  ASSERT_TRUE(r.ok()) << r.status.message;
  ASSERT_EQ(r.value.size(), 2u);
  EXPECT_EQ(r.value[0], std::make_pair(0u, 1u));
  EXPECT_EQ(r.value[1], std::make_pair(1u, 3u));

  in.control_edges = {0, 7};
  r = initial_control_edges(in, cube, 0);
  EXPECT_EQ(r.status.code, Status_code::invalid_argument);
  EXPECT_EQ(r.status.message,
            "control edge 0 (0, 7) is not an edge of the mesh");
  in.control_edges = {0, 1, 5};
  EXPECT_EQ(
      initial_control_edges(in, cube, 0).status.message,
      "control edges must come in pairs of vertex indices (got 3 numbers)");
  in.control_edges = {0, 100};
  EXPECT_EQ(initial_control_edges(in, cube, 0).status.message,
            "control edge 0 (0, 100) names a vertex that is not in the mesh");
  // Not tracked: empty input above level 0.
  in.control_edges.clear();
  EXPECT_TRUE(initial_control_edges(in, cube, 1).value.empty());
}

// ----------------------------------------------------------------
// subdivide_mesh

Mesh_buffers run(const Mesh_buffers& in, Subdivide_options o) {
  Result<Mesh_buffers> r = subdivide_mesh(in, o);
  EXPECT_TRUE(r.ok()) << o.scheme << ": " << r.status.message;
  return r.value;
}

Subdivide_options options(const std::string& scheme, int levels) {
  Subdivide_options o;
  o.scheme = scheme;
  o.levels = levels;
  return o;
}

Subdivide_options custom_options(const std::string& preset, int levels) {
  Subdivide_options o = options("custom", levels);
  o.custom = custom_rules_preset(preset, 64);
  return o;
}

void expect_same_buffers(const Mesh_buffers& a, const Mesh_buffers& b,
                         double tol, const std::string& what) {
  ASSERT_EQ(a.vertex_count(), b.vertex_count()) << what;
  ASSERT_EQ(a.face_count(), b.face_count()) << what;
  EXPECT_EQ(a.face_indices, b.face_indices) << what;
  double worst = 0;
  for (std::size_t i = 0; i < a.positions.size(); ++i)
    worst = std::max(worst, std::abs(a.positions[i] - b.positions[i]));
  EXPECT_LE(worst, tol) << what;
}

TEST(ExtraSubdivide, SchemeNamesIncludeIssue4Schemes) {
  const std::vector<std::string> names = scheme_names();
  for (const char* n : {"catmull-clark", "loop", "doo-sabin", "sqrt3",
                        "quad-triangle", "linear", "linear-tri", "custom"})
    EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
}

TEST(ExtraSubdivide, QuadTriangleEqualsCatmullClarkAndLoopOnTheTori) {
  const Mesh_buffers quad = load_buffers("torus-quad.off"),
                     tri = load_buffers("torus-tri.off");
  expect_same_buffers(run(quad, options("quad-triangle", 3)),
                      run(quad, options("catmull-clark", 3)), 1e-12,
                      "torus-quad");
  expect_same_buffers(run(tri, options("quad-triangle", 3)),
                      run(tri, options("loop", 3)), 1e-12, "torus-tri");
}

TEST(ExtraSubdivide, CustomPresetsEqualTheBuiltInSchemes) {
  struct Case {
    const char* preset;
    const char* scheme;
    const char* mesh;
  };
  for (const Case& c :
       {Case{"catmull-clark", "catmull-clark", "cube.off"},
        Case{"catmull-clark", "catmull-clark", "mixed-open.off"},
        Case{"loop", "loop", "icosahedron.off"},
        Case{"loop", "loop", "disk-tri.off"},
        Case{"doo-sabin", "doo-sabin", "cube.off"},
        Case{"doo-sabin", "doo-sabin", "grid-open.off"},
        Case{"sqrt3", "sqrt3", "icosahedron.off"},
        Case{"sqrt3", "sqrt3", "disk-tri.off"},
        Case{"linear", "linear", "mixed-open.off"}}) {
    const Mesh_buffers in = load_buffers(c.mesh);
    const std::string what = std::string(c.preset) + " on " + c.mesh;
    expect_same_buffers(run(in, custom_options(c.preset, 3)),
                        run(in, options(c.scheme, 3)), 1e-12, what);
  }
  // √3 level by level (start_level carries the border parity) equals one call.
  const Mesh_buffers disk = load_buffers("disk-tri.off");
  Mesh_buffers step = disk;
  for (int level = 0; level < 3; ++level) {
    Subdivide_options o = custom_options("sqrt3", 1);
    o.start_level = level;
    step = run(step, o);
  }
  expect_same_buffers(step, run(disk, options("sqrt3", 3)), 1e-12,
                      "sqrt3 level by level");
}

TEST(ExtraSubdivide, CustomRulesAreCheckedBeforeAnyStep) {
  const Mesh_buffers cube = load_buffers("cube.off");
  Subdivide_options o = custom_options("catmull-clark", 1);
  o.custom.vertex[0].self = std::numeric_limits<double>::infinity();
  Result<Mesh_buffers> r = subdivide_mesh(cube, o);
  EXPECT_EQ(r.status.code, Status_code::invalid_argument);
  EXPECT_EQ(r.status.message,
            "custom rules: the vertex rule at valence 3 has a weight that is "
            "not finite (inf)");
  EXPECT_EQ(predict_size(cube, o).status.message, r.status.message);

  o = custom_options("loop", 1);
  r = subdivide_mesh(cube, o);
  EXPECT_EQ(r.status.code, Status_code::not_triangles);
  o.triangulate = true;
  EXPECT_TRUE(subdivide_mesh(cube, o).ok());

  // Valence 4 appears only after one Catmull-Clark step of a cube with a
  // table for valence 3 alone: the second step is refused.
  o = options("custom", 2);
  o.custom = custom_rules_preset("catmull-clark", 3);
  r = subdivide_mesh(cube, o);
  EXPECT_EQ(r.status.code, Status_code::invalid_argument);
  EXPECT_EQ(r.status.message,
            "custom rules: the vertex rule has no weights for valence 4 (the "
            "table covers valences "
            "3 to 3)");
}

TEST(ExtraSubdivide, PredictedCountsMatchTheResult) {
  struct Case {
    Subdivide_options o;
    const char* mesh;
  };
  Subdivide_options fixed = options("quad-triangle", 2);
  fixed.smooth_boundary = false;
  for (const Case& c :
       {Case{options("quad-triangle", 3), "rhombicuboctahedron.off"},
        Case{options("quad-triangle", 2), "mixed-open.off"},
        Case{fixed, "grid-open.off"},
        Case{options("linear", 3), "mixed-open.off"},
        Case{options("linear-tri", 3), "disk-tri.off"},
        Case{custom_options("doo-sabin", 2), "grid-open.off"},
        Case{custom_options("sqrt3", 3), "disk-tri.off"}}) {
    const Mesh_buffers in = load_buffers(c.mesh);
    const Result<Size_prediction> p = predict_size(in, c.o);
    ASSERT_TRUE(p.ok()) << p.status.message;
    Mesh out;
    ASSERT_TRUE(build_mesh(run(in, c.o), out).ok());
    EXPECT_EQ(p.value.vertices, out.number_of_vertices())
        << c.o.scheme << " " << c.mesh;
    EXPECT_EQ(p.value.edges, out.number_of_edges())
        << c.o.scheme << " " << c.mesh;
    EXPECT_EQ(p.value.faces, out.number_of_faces())
        << c.o.scheme << " " << c.mesh;
  }
}

TEST(ExtraSubdivide, FixedBoundaryOptionKeepsTheBorderPolygon) {
  const Mesh_buffers grid = load_buffers("grid-open.off");
  Subdivide_options o = options("quad-triangle", 2);
  o.smooth_boundary = false;
  const Mesh_buffers fixed = run(grid, o);
  // grid-open is the unit grid [0, 3]^2: the border stays on its square.
  Mesh m;
  ASSERT_TRUE(build_mesh(fixed, m).ok());
  std::size_t border_vertices = 0;
  for (Mesh::Vertex_index v : m.vertices()) {
    if (!m.is_border(v)) continue;
    ++border_vertices;
    const Point& p = m.point(v);
    const bool on_square = p.x() == 0 || p.x() == 3 || p.y() == 0 || p.y() == 3;
    EXPECT_TRUE(on_square) << p;
  }
  EXPECT_EQ(border_vertices, 48u);  // 12 border edges, split twice
  // Smooth: the corner (0, 0) moves inside.
  const Mesh_buffers smooth = run(grid, options("quad-triangle", 2));
  EXPECT_GT(smooth.positions[0] + smooth.positions[1], 0.0);
  EXPECT_EQ(fixed.positions[0], 0.0);
}

TEST(ExtraSubdivide, ControlEdgesOfACubeAtLevel3OfCatmullClark) {
  const Mesh_buffers cube = load_buffers("cube.off");
  const Mesh_buffers out = run(cube, options("catmull-clark", 3));
  ASSERT_EQ(out.control_edges.size(), 2u * 96u);
  Control_edges pairs;
  for (std::size_t i = 0; i < out.control_edges.size(); i += 2)
    pairs.emplace_back(out.control_edges[i], out.control_edges[i + 1]);
  Mesh control, refined;
  ASSERT_TRUE(build_mesh(cube, control).ok());
  ASSERT_TRUE(build_mesh(out, refined).ok());
  expect_chains(control, refined, pairs, 8);
  Result<Mesh_facts> facts = compute_facts(out);
  ASSERT_TRUE(facts.ok());
  EXPECT_EQ(facts.value.control_edges, 96u);

  // Level by level, handing the marks on, marks the same segments (the
  // vertex numbering differs: each call renumbers edges from its buffers).
  Mesh_buffers step = cube;
  for (int level = 0; level < 3; ++level) {
    Subdivide_options o = options("catmull-clark", 1);
    o.start_level = level;
    step = run(step, o);
  }
  auto segments = [](const Mesh_buffers& b) {
    std::set<std::array<long long, 6>> set;
    for (std::size_t i = 0; i < b.control_edges.size(); i += 2) {
      std::array<long long, 3> p, q;
      for (int c = 0; c < 3; ++c) {
        p[c] = std::llround(b.positions[3 * b.control_edges[i] + c] * 1e9);
        q[c] = std::llround(b.positions[3 * b.control_edges[i + 1] + c] * 1e9);
      }
      if (q < p) std::swap(p, q);
      set.insert({p[0], p[1], p[2], q[0], q[1], q[2]});
    }
    return set;
  };
  EXPECT_EQ(segments(step).size(), 96u);
  EXPECT_EQ(segments(step), segments(out));
  // Level 0 marks every edge; dual schemes drop the marks.
  EXPECT_EQ(run(cube, options("catmull-clark", 0)).control_edges.size(), 24u);
  EXPECT_TRUE(run(cube, options("doo-sabin", 1)).control_edges.empty());
}

TEST(ExtraSubdivide, ControlEdgesOfEveryPrimalScheme) {
  const Mesh_buffers rh = load_buffers("rhombicuboctahedron.off");  // 48 edges
  const Mesh_buffers ico = load_buffers("icosahedron.off");         // 30 edges
  EXPECT_EQ(run(rh, options("quad-triangle", 2)).control_edges.size(),
            2u * 48u * 4u);
  EXPECT_EQ(run(rh, options("linear", 2)).control_edges.size(), 2u * 48u * 4u);
  EXPECT_EQ(run(rh, custom_options("catmull-clark", 2)).control_edges.size(),
            2u * 48u * 4u);
  EXPECT_EQ(run(ico, options("loop", 2)).control_edges.size(), 2u * 30u * 4u);
  EXPECT_EQ(run(ico, options("linear-tri", 2)).control_edges.size(),
            2u * 30u * 4u);
  EXPECT_EQ(run(ico, custom_options("loop", 2)).control_edges.size(),
            2u * 30u * 4u);
  EXPECT_TRUE(run(ico, custom_options("sqrt3", 2)).control_edges.empty());
  // Triangulating a quad mesh for loop keeps only the quads' edges.
  Subdivide_options o = options("loop", 1);
  o.triangulate = true;
  EXPECT_EQ(run(load_buffers("cube.off"), o).control_edges.size(),
            2u * 12u * 2u);
  // Marks that are not edges are refused.
  Mesh_buffers bad = load_buffers("cube.off");
  bad.control_edges = {0, 7};
  const Result<Mesh_buffers> r =
      subdivide_mesh(bad, options("catmull-clark", 1));
  EXPECT_EQ(r.status.code, Status_code::invalid_argument);
  EXPECT_EQ(r.status.message,
            "control edge 0 (0, 7) is not an edge of the mesh");
}

TEST(ExtraSubdivide, QuadTriangleRefusesOnlyTwoValentVerticesBetweenTriangles) {
  // Two triangles glued along all three edges: PTQ-style splitting would
  // join the same two midpoints in both faces.
  Mesh_buffers pillow;
  pillow.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  pillow.face_sizes = {3, 3};
  pillow.face_indices = {0, 1, 2, 0, 2, 1};
  const Result<Mesh_buffers> r =
      subdivide_mesh(pillow, options("quad-triangle", 1));
  EXPECT_EQ(r.status.code, Status_code::invalid_mesh);
  EXPECT_EQ(
      r.status.message,
      "quad-triangle cannot refine vertex 0: it has only 2 edges, so its two "
      "faces share two edges and the result would repeat edges "
      "(catmull-clark can refine it)");
  // A triangle and a quad, or two quads, at such a vertex are fine.
  const Mesh_buffers mixed = refine_test::two_valent_triangle_and_quad();
  const Mesh_buffers quads = refine_test::two_valent_quads();
  for (const Mesh_buffers* in : {&mixed, &quads}) {
    const Mesh_buffers out = run(*in, options("quad-triangle", 3));
    Mesh m;
    const Status s = build_mesh(out, m);
    EXPECT_TRUE(s.ok()) << s.message;
    EXPECT_TRUE(predict_size(*in, options("quad-triangle", 3)).ok());
  }
  // The prediction refuses what the step refuses, in the same words.
  EXPECT_EQ(predict_size(pillow, options("quad-triangle", 1)).status.message,
            r.status.message);
}

}  // namespace
}  // namespace subdivlab
