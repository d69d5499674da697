// The stencils of a step (core/stencils.h): for every scheme, custom rules
// on the four hosts included, on closed and open meshes, every vertex of
// levels 1-2 is the weighted sum of its parents' points (to 1e-12) with
// weights that sum to 1; the known masks come out exactly; each vertex is
// named by its origin.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/custom_rules.h"
#include "core/stencils.h"
#include "core/subdivide.h"
#include "refine_test_support.h"

namespace subdivlab {
namespace {

using refine_test::fixture;

Subdivide_options options_of(const std::string& scheme, int levels,
                             const std::string& preset = "") {
  Subdivide_options o;
  o.scheme = scheme;
  o.levels = levels;
  if (!preset.empty()) o.custom = custom_rules_preset(preset);
  return o;
}

/// Level `levels` of `in` under `o`, as subdivide_mesh makes it.
Mesh_buffers level_of(const Mesh_buffers& in, Subdivide_options o, int levels) {
  if (levels == 0) return in;
  o.levels = levels;
  const Result<Mesh_buffers> r = subdivide_mesh(in, o);
  EXPECT_TRUE(r.ok()) << r.status.message;
  return r.value;
}

/// The weights of refined vertex v as {parent: weight}.
std::vector<std::pair<std::uint32_t, double>> row(const Stencil_table& t,
                                                  std::uint32_t v) {
  std::vector<std::pair<std::uint32_t, double>> out;
  for (std::uint32_t i = t.offsets[v]; i < t.offsets[v + 1]; ++i)
    out.push_back({t.parents[i], t.weights[i]});
  return out;
}

void expect_stencils_give_points_of(const Mesh_buffers& in,
                                    const Subdivide_options& o) {
  for (int k = 1; k <= 2; ++k) {
    SCOPED_TRACE(o.scheme + " level " + std::to_string(k));
    Subdivide_options step = o;
    step.levels = k;
    const Result<Stencil_table> t = step_stencils(in, step);
    ASSERT_TRUE(t.ok()) << t.status.message;
    const Mesh_buffers parent = level_of(in, o, k - 1);
    const Mesh_buffers child = level_of(in, o, k);
    ASSERT_EQ(t.value.parent_vertices, parent.vertex_count());
    ASSERT_EQ(t.value.offsets.size(), child.vertex_count() + 1);
    ASSERT_EQ(t.value.origins.size(), child.vertex_count());
    for (std::uint32_t v = 0; v < child.vertex_count(); ++v) {
      double sum = 0, p[3] = {0, 0, 0};
      for (const auto& [j, w] : row(t.value, v)) {
        ASSERT_LT(j, parent.vertex_count());
        sum += w;
        for (int i = 0; i < 3; ++i) p[i] += w * parent.positions[3 * j + i];
      }
      EXPECT_NEAR(sum, 1.0, 1e-12) << "vertex " << v;
      for (int i = 0; i < 3; ++i) {
        const double want = child.positions[3 * v + i];
        EXPECT_NEAR(p[i], want, 1e-12 * std::max(1.0, std::fabs(want)))
            << "vertex " << v;
      }
    }
  }
}

void expect_stencils_give_points(const std::string& name,
                                 const Subdivide_options& o) {
  SCOPED_TRACE(name);
  expect_stencils_give_points_of(fixture(name), o);
}

TEST(Stencils, GiveEveryPointOfEverySchemeOnClosedAndOpenMeshes) {
  const char* quads[] = {"cube.off", "grid-open.off", "mixed-open.off",
                         "torus-quad.off"};
  const char* triangles[] = {"octahedron.off", "disk-tri.off", "torus-tri.off",
                             "icosahedron.off"};
  for (const char* f : quads)
    for (const char* scheme :
         {"catmull-clark", "doo-sabin", "quad-triangle", "linear"})
      expect_stencils_give_points(f, options_of(scheme, 1));
  for (const char* f : triangles)
    for (const char* scheme : {"loop", "sqrt3", "linear-tri", "doo-sabin",
                               "catmull-clark", "quad-triangle"})
      expect_stencils_give_points(f, options_of(scheme, 1));
  // Custom rules on the four hosts (the presets of the built-in schemes).
  for (const char* f : quads) {
    expect_stencils_give_points(f, options_of("custom", 1, "catmull-clark"));
    expect_stencils_give_points(f, options_of("custom", 1, "doo-sabin"));
  }
  for (const char* f : triangles) {
    expect_stencils_give_points(f, options_of("custom", 1, "loop"));
    expect_stencils_give_points(f, options_of("custom", 1, "sqrt3"));
  }
}

TEST(Stencils, CatmullClarkRegularMasksExactly) {
  // The 3 x 3 grid: vertex 5 (inside, valence 4) keeps 9/16 of itself,
  // 3/32 of each edge neighbour and 1/64 of each diagonal one.
  const Result<Stencil_table> t =
      step_stencils(fixture("grid-open.off"), options_of("catmull-clark", 1));
  ASSERT_TRUE(t.ok()) << t.status.message;
  const auto r = row(t.value, 5);
  ASSERT_EQ(r.size(), 9u);
  for (const auto& [j, w] : r) {
    const bool edge = j == 1 || j == 4 || j == 6 || j == 9;
    const double want = j == 5 ? 9.0 / 16 : edge ? 3.0 / 32 : 1.0 / 64;
    EXPECT_EQ(w, want) << "parent " << j;
  }
  const Stencil_origin& o = t.value.origins[5];
  EXPECT_EQ(o.kind, Stencil_kind::vertex_point);
  EXPECT_EQ(o.size, 4u);
  // A border vertex: (1, 6, 1) / 8 along the border.
  const auto b = row(t.value, 1);
  ASSERT_EQ(b.size(), 3u);
  EXPECT_EQ(b[0], std::make_pair(0u, 0.125));
  EXPECT_EQ(b[1], std::make_pair(1u, 0.75));
  EXPECT_EQ(b[2], std::make_pair(2u, 0.125));
  EXPECT_EQ(t.value.origins[1].kind, Stencil_kind::border_vertex);
}

TEST(Stencils, LoopMasksExactly) {
  // The triangulated torus: valence 6 everywhere, beta(6) = 1/16.
  const Result<Stencil_table> t =
      step_stencils(fixture("torus-tri.off"), options_of("loop", 1));
  ASSERT_TRUE(t.ok()) << t.status.message;
  const auto r = row(t.value, 0);
  ASSERT_EQ(r.size(), 7u);
  for (const auto& [j, w] : r)
    EXPECT_DOUBLE_EQ(w, j == 0 ? 10.0 / 16 : 1.0 / 16) << "parent " << j;
  EXPECT_EQ(t.value.origins[0].size, 6u);
  // Every edge point: 3/8 of each end, 1/8 of each opposite vertex.
  const std::uint32_t V = 48;
  for (std::uint32_t v = V; v < t.value.origins.size(); ++v) {
    const Stencil_origin& o = t.value.origins[v];
    ASSERT_EQ(o.kind, Stencil_kind::edge_point);
    const auto e = row(t.value, v);
    ASSERT_EQ(e.size(), 4u);
    for (const auto& [j, w] : e) {
      const bool end = j == o.ends[0] || j == o.ends[1];
      EXPECT_EQ(w, end ? 0.375 : 0.125) << "edge point " << v;
    }
  }
}

TEST(Stencils, NameEachVertexByItsOrigin) {
  // Catmull-Clark on the cube: 8 vertex points (valence 3), 12 edge
  // points with the edge's ends, 6 face points of degree 4.
  const Result<Stencil_table> t =
      step_stencils(fixture("cube.off"), options_of("catmull-clark", 1));
  ASSERT_TRUE(t.ok()) << t.status.message;
  ASSERT_EQ(t.value.origins.size(), 26u);
  for (std::uint32_t v = 0; v < 26; ++v) {
    const Stencil_origin& o = t.value.origins[v];
    if (v < 8) {
      EXPECT_EQ(o.kind, Stencil_kind::vertex_point);
      EXPECT_EQ(o.element, v);
      EXPECT_EQ(o.size, 3u);
    } else if (v < 20) {
      EXPECT_EQ(o.kind, Stencil_kind::edge_point);
      // An edge point weighs its ends 3/8 each.
      for (const auto& [j, w] : row(t.value, v))
        EXPECT_EQ(w, j == o.ends[0] || j == o.ends[1] ? 0.375 : 0.0625);
    } else {
      EXPECT_EQ(o.kind, Stencil_kind::face_point);
      EXPECT_EQ(o.size, 4u);
      EXPECT_EQ(row(t.value, v).size(), 4u);
    }
  }
  EXPECT_FALSE(t.value.formulas.empty());
  // Doo-Sabin: every new vertex a corner, its own vertex weighing
  // (n + 5) / 4n = 9/16 on a quad.
  const Result<Stencil_table> ds =
      step_stencils(fixture("cube.off"), options_of("doo-sabin", 1));
  ASSERT_TRUE(ds.ok()) << ds.status.message;
  for (std::uint32_t v = 0; v < ds.value.origins.size(); ++v) {
    const Stencil_origin& o = ds.value.origins[v];
    EXPECT_EQ(o.kind, Stencil_kind::corner_point);
    EXPECT_EQ(o.size, 4u);
    for (const auto& [j, w] : row(ds.value, v))
      if (j == o.element) EXPECT_EQ(w, 9.0 / 16);
  }
  // On the open grid's border edges: Chaikin's 3/4 and 1/4 along the edge.
  const Result<Stencil_table> open =
      step_stencils(fixture("grid-open.off"), options_of("doo-sabin", 1));
  ASSERT_TRUE(open.ok()) << open.status.message;
  EXPECT_EQ(open.value.origins[0].kind, Stencil_kind::border_corner_point);
  EXPECT_EQ(open.value.origins[0].element, 1u);
  const auto b = row(open.value, 0);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0], std::make_pair(0u, 0.25));
  EXPECT_EQ(b[1], std::make_pair(1u, 0.75));
  // sqrt3 on the open disk: no border refinement on the first step (border
  // vertices stay), CGAL's 4, 19, 4 (/27) on the second.
  const Result<Stencil_table> s1 =
      step_stencils(fixture("disk-tri.off"), options_of("sqrt3", 1));
  const Result<Stencil_table> s2 =
      step_stencils(fixture("disk-tri.off"), options_of("sqrt3", 2));
  ASSERT_TRUE(s1.ok() && s2.ok());
  EXPECT_EQ(s1.value.origins[1].kind, Stencil_kind::border_vertex);
  EXPECT_EQ(row(s1.value, 1),
            (std::vector<std::pair<std::uint32_t, double>>{{1u, 1.0}}));
  const auto b2 = row(s2.value, 1);
  ASSERT_EQ(b2.size(), 3u);
  EXPECT_DOUBLE_EQ(b2[0].second, 19.0 / 27);
  EXPECT_DOUBLE_EQ(b2[1].second, 4.0 / 27);
  EXPECT_EQ(s1.value.origins[0].kind, Stencil_kind::relaxed_vertex);
}

TEST(Stencils, FollowTheCreaseRules) {
  // The cube with its front loop (4 5 7 6) infinitely sharp: a vertex on it
  // takes the crease rule, 3/4 of itself and 1/8 of each sharp neighbour;
  // an edge point on it the midpoint.
  Mesh_buffers m = fixture("cube.off");
  m.tags.crease_edges = {4, 5, 5, 7, 7, 6, 6, 4};
  m.tags.crease_sharpness = {10, 10, 10, 10};
  const Result<Stencil_table> t =
      step_stencils(m, options_of("catmull-clark", 1));
  ASSERT_TRUE(t.ok()) << t.status.message;
  const auto r = row(t.value, 5);
  ASSERT_EQ(r.size(), 3u);
  EXPECT_EQ(r[0], std::make_pair(4u, 0.125));
  EXPECT_EQ(r[1], std::make_pair(5u, 0.75));
  EXPECT_EQ(r[2], std::make_pair(7u, 0.125));
  EXPECT_EQ(t.value.origins[5].kind, Stencil_kind::crease_vertex);
  EXPECT_EQ(t.value.origins[0].kind, Stencil_kind::vertex_point);
  for (std::uint32_t v = 8; v < 20; ++v) {
    const Stencil_origin& o = t.value.origins[v];
    const bool sharp = o.ends[0] >= 4 && o.ends[1] >= 4;
    EXPECT_EQ(o.kind, sharp ? Stencil_kind::sharp_edge_point
                            : Stencil_kind::edge_point);
    if (sharp) EXPECT_EQ(row(t.value, v).size(), 2u) << "edge point " << v;
  }
  expect_stencils_give_points_of(m, options_of("catmull-clark", 1));
}

TEST(Stencils, RefusedWhereThereIsNoStepOrNoFastHost) {
  Subdivide_options o = options_of("catmull-clark", 0);
  const Result<Stencil_table> none = step_stencils(fixture("cube.off"), o);
  EXPECT_EQ(none.status.code, Status_code::invalid_argument);
  EXPECT_NE(none.status.message.find("no step"), std::string::npos)
      << none.status.message;
  o.levels = 1;
  o.cgal_hosts = true;
  const Result<Stencil_table> cgal = step_stencils(fixture("cube.off"), o);
  EXPECT_EQ(cgal.status.code, Status_code::invalid_argument);
  EXPECT_NE(cgal.status.message.find("CGAL"), std::string::npos);
}

}  // namespace
}  // namespace subdivlab
