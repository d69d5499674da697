// A level as the viewer takes it (level_view.h, render_buffers.h): fan
// triangles, polygon edges and area-weighted normals against plain
// implementations written here, and the facts of a step, counted and
// carried, equal to CGAL's (compute_facts on a Surface_mesh) for every
// scheme on every fixture, levels 1-3.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/level_view.h"
#include "core/mesh_facts.h"
#include "core/mesh_io.h"
#include "core/render_buffers.h"
#include "core/subdivide.h"

namespace subdivlab {
namespace {

Mesh_buffers load(const std::string& name) {
  std::ifstream in(std::string(FIXTURES_DIR) + "/" + name, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  const Result<Mesh_buffers> r = read_mesh(s.str(), Mesh_format::off);
  EXPECT_TRUE(r.ok()) << name << ": " << r.status.message;
  return r.value;
}

const char* const kFixtures[] = {
    "tetrahedron.off", "octahedron.off",     "icosahedron.off",
    "torus-tri.off",   "two-tetrahedra.off", "disk-tri.off",
    "cube.off",        "torus-quad.off",     "rhombicuboctahedron.off",
    "grid-open.off",   "mixed-open.off",
};

/// Keeps what a sink is handed, in order.
struct Recorder : Render_sink {
  std::vector<Render_array> order;
  Render_buffers out;
  void floats(Render_array which, const std::vector<float>& v) override {
    order.push_back(which);
    if (which == Render_array::positions) out.positions = v;
    if (which == Render_array::bounding_sphere) out.bounding_sphere = v;
    if (which == Render_array::normals) out.normals = v;
  }
  void indices(Render_array which,
               const std::vector<std::uint32_t>& v) override {
    order.push_back(which);
    if (which == Render_array::triangles) out.triangles = v;
    if (which == Render_array::triangle_face) out.triangle_face = v;
    if (which == Render_array::edges) out.edges = v;
    if (which == Render_array::border_edges) out.border_edges = v;
  }
};

/// The polygon edges by a map, in order of first appearance, then stably
/// ordered by the smaller vertex.
std::vector<std::uint32_t> edges_by_map(const Mesh_buffers& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, bool> seen;
  std::vector<std::uint32_t> out;
  std::size_t at = 0;
  for (std::uint32_t size : m.face_sizes) {
    for (std::uint32_t k = 0; k < size; ++k) {
      const std::uint32_t a = m.face_indices[at + k];
      const std::uint32_t b = m.face_indices[at + (k + 1) % size];
      const auto key = std::minmax(a, b);
      if (seen.emplace(key, true).second) {
        out.push_back(key.first);
        out.push_back(key.second);
      }
    }
    at += size;
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (std::size_t i = 0; i < out.size(); i += 2)
    pairs.emplace_back(out[i], out[i + 1]);
  std::stable_sort(
      pairs.begin(), pairs.end(),
      [](const auto& a, const auto& b) { return a.first < b.first; });
  out.clear();
  for (const auto& [a, b] : pairs) {
    out.push_back(a);
    out.push_back(b);
  }
  return out;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> sorted_pairs(
    const std::vector<std::uint32_t>& edges) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (std::size_t i = 0; i < edges.size(); i += 2)
    pairs.emplace_back(edges[i], edges[i + 1]);
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

/// The edges of `edges` that one corner of `m` only goes along, in the
/// order of `edges`: its border, counted by a map.
std::vector<std::uint32_t> border_by_map(
    const Mesh_buffers& m, const std::vector<std::uint32_t>& edges) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> corners;
  std::size_t at = 0;
  for (std::uint32_t size : m.face_sizes) {
    for (std::uint32_t k = 0; k < size; ++k)
      ++corners[std::minmax(m.face_indices[at + k],
                            m.face_indices[at + (k + 1) % size])];
    at += size;
  }
  std::vector<std::uint32_t> out;
  for (std::size_t i = 0; i < edges.size(); i += 2)
    if (corners.at({edges[i], edges[i + 1]}) == 1)
      out.insert(out.end(), {edges[i], edges[i + 1]});
  return out;
}

/// The edges of the corners a -> b with a < b, in corner order.
std::vector<std::uint32_t> edges_going_up(const Mesh_buffers& m) {
  std::vector<std::uint32_t> out;
  std::size_t at = 0;
  for (std::uint32_t size : m.face_sizes) {
    for (std::uint32_t k = 0; k < size; ++k) {
      const std::uint32_t a = m.face_indices[at + k];
      const std::uint32_t b = m.face_indices[at + (k + 1) % size];
      if (a < b) out.insert(out.end(), {a, b});
    }
    at += size;
  }
  return out;
}

/// Vertex normals as (b - a) x (c - a) summed over the fan triangles.
std::vector<double> normals_by_fan(const Mesh_buffers& m) {
  std::vector<double> n(m.positions.size(), 0.0);
  const auto p = [&m](std::uint32_t v, int a) {
    return m.positions[3 * v + a];
  };
  std::size_t at = 0;
  for (std::uint32_t size : m.face_sizes) {
    for (std::uint32_t k = 1; k + 1 < size; ++k) {
      const std::uint32_t a = m.face_indices[at], b = m.face_indices[at + k],
                          c = m.face_indices[at + k + 1];
      double u[3], w[3];
      for (int i = 0; i < 3; ++i) {
        u[i] = p(b, i) - p(a, i);
        w[i] = p(c, i) - p(a, i);
      }
      const double x[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                           u[0] * w[1] - u[1] * w[0]};
      for (std::uint32_t v : {a, b, c})
        for (int i = 0; i < 3; ++i) n[3 * v + i] += x[i];
    }
    at += size;
  }
  for (std::size_t v = 0; 3 * v < n.size(); ++v) {
    const double l =
        std::sqrt(n[3 * v] * n[3 * v] + n[3 * v + 1] * n[3 * v + 1] +
                  n[3 * v + 2] * n[3 * v + 2]);
    for (int i = 0; i < 3; ++i) n[3 * v + i] = l > 0 ? n[3 * v + i] / l : 0;
  }
  return n;
}

TEST(RenderBuffers, BorderEdgesAreTheEdgesOfOneFace) {
  // The open 3 x 3 grid (vertices 0..15 row by row): its border is the
  // 12 unit edges around it, listed as the edges list gives them.
  const Mesh_buffers grid = load("grid-open.off");
  const Render_buffers r = render_buffers(grid);
  std::set<std::pair<std::uint32_t, std::uint32_t>> border;
  for (std::size_t i = 0; i < r.border_edges.size(); i += 2)
    border.emplace(r.border_edges[i], r.border_edges[i + 1]);
  std::set<std::pair<std::uint32_t, std::uint32_t>> expected;
  for (std::uint32_t i = 0; i < 3; ++i) {
    expected.emplace(i, i + 1);              // bottom row
    expected.emplace(12 + i, 13 + i);        // top row
    expected.emplace(4 * i, 4 * i + 4);      // left column
    expected.emplace(4 * i + 3, 4 * i + 7);  // right column
  }
  EXPECT_EQ(r.border_edges.size(), 24u);
  EXPECT_EQ(border, expected);
  // A closed mesh has none.
  EXPECT_TRUE(render_buffers(load("torus-quad.off")).border_edges.empty());
}

TEST(RenderBuffers, CubeIsTwelveTrianglesAndTwelveEdges) {
  const Mesh_buffers cube = load("cube.off");
  Recorder r;
  EXPECT_EQ(build_render_buffers(cube, r), 12u);
  EXPECT_EQ(r.order, (std::vector<Render_array>{
                         Render_array::positions, Render_array::bounding_sphere,
                         Render_array::normals, Render_array::triangles,
                         Render_array::triangle_face, Render_array::edges,
                         Render_array::border_edges}));
  EXPECT_EQ(r.out.triangles.size(), 36u);
  EXPECT_TRUE(r.out.border_edges.empty());
  EXPECT_EQ(r.out.triangle_face,
            (std::vector<std::uint32_t>{0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5}));
  ASSERT_EQ(r.out.edges.size(), 24u);
  // Every edge is a cube edge (its ends differ in one coordinate), never a
  // fan diagonal.
  for (std::size_t i = 0; i < 24; i += 2) {
    int differing = 0;
    for (int a = 0; a < 3; ++a)
      differing += cube.positions[3 * r.out.edges[i] + a] !=
                   cube.positions[3 * r.out.edges[i + 1] + a];
    EXPECT_EQ(differing, 1) << "edge " << i / 2;
  }
  EXPECT_EQ(r.out.positions,
            std::vector<float>(cube.positions.begin(), cube.positions.end()));
  // The cube spans [-1, 1]^3: centred at 0, radius sqrt(3).
  ASSERT_EQ(r.out.bounding_sphere.size(), 4u);
  EXPECT_EQ(r.out.bounding_sphere[0], 0.0f);
  EXPECT_EQ(r.out.bounding_sphere[1], 0.0f);
  EXPECT_EQ(r.out.bounding_sphere[2], 0.0f);
  EXPECT_NEAR(r.out.bounding_sphere[3], std::sqrt(3.0), 1e-5);
  EXPECT_GE(r.out.bounding_sphere[3], std::sqrt(3.0f));
}

TEST(RenderBuffers, HolesAreNotDrawnButTheirEdgesCount) {
  // The cube with faces 1 and 4 as holes: 4 faces drawn, 8 triangles;
  // each of the 12 edges borders a drawn face, so all are drawn and
  // counted.
  Mesh_buffers cube = load("cube.off");
  cube.tags.holes = {1, 4};
  Recorder r;
  EXPECT_EQ(build_render_buffers(cube, r, 12), 12u);
  EXPECT_EQ(r.out.triangle_face,
            (std::vector<std::uint32_t>{0, 0, 2, 2, 3, 3, 5, 5}));
  EXPECT_EQ(r.out.triangles.size(), 24u);
  EXPECT_EQ(r.out.edges.size(), 24u);
  // Faces 1 and 4 no longer in any triangle: drawn triangles are those of
  // faces 0, 2, 3 and 5, fanned as without holes.
  const Render_buffers all = render_buffers(load("cube.off"));
  for (std::size_t t = 0, drawn = 0; t < all.triangle_face.size(); ++t) {
    if (all.triangle_face[t] == 1 || all.triangle_face[t] == 4) continue;
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(r.out.triangles[3 * drawn + c], all.triangles[3 * t + c]);
    ++drawn;
  }
  // A strip of three quads with the middle one a hole: the edge the
  // middle quad shares with nothing else drawn (its top and bottom) goes;
  // the mesh still has 10 edges.
  Mesh_buffers strip;
  strip.positions = {0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0,
                     0, 1, 0, 1, 1, 0, 2, 1, 0, 3, 1, 0};
  strip.face_sizes = {4, 4, 4};
  strip.face_indices = {0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6};
  strip.tags.holes = {1};
  Recorder s;
  EXPECT_EQ(build_render_buffers(strip, s), 10u);
  EXPECT_EQ(s.out.edges, (std::vector<std::uint32_t>{0, 1, 0, 4, 1, 5, 2, 3, 2,
                                                     6, 3, 7, 4, 5, 6, 7}));
  EXPECT_EQ(s.out.triangle_face, (std::vector<std::uint32_t>{0, 0, 2, 2}));
  // Vertex normals from the drawn faces only: all +z (flat strip).
  for (std::size_t v = 0; v < 8; ++v) EXPECT_EQ(s.out.normals[3 * v + 2], 1.0f);
  // Two quads sharing edges 2-4 and 3-4, the first a hole (found by the
  // fuzzers): the 4 edges drawn have 8 corners in the whole mesh, as many
  // as a closed mesh would, yet the drawn quad's edges 1-2 and 1-3 are on
  // the border.
  Mesh_buffers pair;
  pair.positions = {0, 0, 0, 2, 2, 0, 2, 0, 0, 0, 2, 0, 1, 1, 1};
  pair.face_sizes = {4, 4};
  pair.face_indices = {0, 2, 4, 3, 3, 4, 2, 1};
  pair.tags.holes = {0};
  const Render_buffers p = render_buffers(pair);
  EXPECT_EQ(p.edges, (std::vector<std::uint32_t>{1, 2, 1, 3, 2, 4, 3, 4}));
  EXPECT_EQ(p.border_edges, (std::vector<std::uint32_t>{1, 2, 1, 3}));
}

TEST(RenderBuffers, FansAPolygonFromItsFirstCorner) {
  Mesh_buffers pentagon;
  pentagon.positions = {1, 0,    0,    0.3, 0.95, 0,     -0.8, 0.6,
                        0, -0.8, -0.6, 0,   0.3,  -0.95, 0};
  pentagon.face_sizes = {5};
  pentagon.face_indices = {0, 1, 2, 3, 4};
  const Render_buffers r = render_buffers(pentagon);
  EXPECT_EQ(r.triangles,
            (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3, 0, 3, 4}));
  EXPECT_EQ(r.triangle_face, (std::vector<std::uint32_t>{0, 0, 0}));
  EXPECT_EQ(r.edges,
            (std::vector<std::uint32_t>{0, 1, 0, 4, 1, 2, 2, 3, 3, 4}));
  // Open, with its edge 4 -> 0 going down: told 5 edges, it still sorts.
  Recorder told;
  EXPECT_EQ(build_render_buffers(pentagon, told, 5), 5u);
  EXPECT_EQ(told.out.edges, r.edges);
  // A flat counter-clockwise polygon: every normal is +z.
  for (std::size_t v = 0; v < 5; ++v) {
    EXPECT_EQ(r.normals[3 * v], 0.0f);
    EXPECT_EQ(r.normals[3 * v + 1], 0.0f);
    EXPECT_EQ(r.normals[3 * v + 2], 1.0f);
  }
}

TEST(RenderBuffers, EdgesAndNormalsEqualPlainOnesOnFixturesAndTheirLevels) {
  for (const char* fixture : kFixtures) {
    SCOPED_TRACE(fixture);
    const Mesh_buffers base = load(fixture);
    Subdivide_options options;
    options.scheme = "catmull-clark";
    options.levels = 2;
    const Result<Mesh_buffers> refined = subdivide_mesh(base, options);
    ASSERT_TRUE(refined.ok());
    for (const Mesh_buffers* m : {&base, &refined.value}) {
      const Render_buffers r = render_buffers(*m);
      EXPECT_EQ(r.edges, edges_by_map(*m));
      EXPECT_EQ(r.border_edges, border_by_map(*m, r.edges));
      // Told its number of edges, a closed mesh lists them in one pass:
      // the same set, in the order of the corners going up.
      Recorder told;
      const std::size_t edges = r.edges.size() / 2;
      EXPECT_EQ(build_render_buffers(*m, told, edges), edges);
      EXPECT_EQ(sorted_pairs(told.out.edges), sorted_pairs(r.edges));
      EXPECT_EQ(told.out.border_edges, border_by_map(*m, told.out.edges));
      if (compute_facts(*m).value.closed)
        EXPECT_EQ(told.out.edges, edges_going_up(*m));
      const std::vector<double> n = normals_by_fan(*m);
      ASSERT_EQ(r.normals.size(), n.size());
      for (std::size_t i = 0; i < n.size(); ++i)
        EXPECT_NEAR(r.normals[i], n[i], 1e-6) << "coordinate " << i;
    }
  }
}

TEST(RenderBuffers, IsolatedVertexHasAZeroNormalAndNoEdge) {
  Mesh_buffers m = load("tetrahedron.off");
  m.positions.insert(m.positions.end(), {10, 10, 10});
  const Render_buffers r = render_buffers(m);
  EXPECT_EQ(r.edges.size(), 12u);
  ASSERT_EQ(r.normals.size(), 15u);
  EXPECT_EQ(r.normals[12], 0.0f);
  EXPECT_EQ(r.normals[13], 0.0f);
  EXPECT_EQ(r.normals[14], 0.0f);
}

void expect_same_facts(const Mesh_facts& a, const Mesh_facts& b) {
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_EQ(a.faces, b.faces);
  EXPECT_EQ(a.components, b.components);
  EXPECT_EQ(a.boundaries, b.boundaries);
  EXPECT_EQ(a.euler_characteristic, b.euler_characteristic);
  EXPECT_EQ(a.genus, b.genus);
  EXPECT_EQ(a.closed, b.closed);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.quads, b.quads);
  EXPECT_EQ(a.other_faces, b.other_faces);
  EXPECT_EQ(a.bbox_min, b.bbox_min);
  EXPECT_EQ(a.bbox_max, b.bbox_max);
  EXPECT_EQ(a.control_edges, b.control_edges);
}

TEST(LevelView, StepFactsEqualCgalsForEverySchemeAndFixture) {
  const char* const schemes[] = {"catmull-clark", "loop",   "doo-sabin",
                                 "sqrt3",         "linear", "linear-tri",
                                 "quad-triangle"};
  for (const char* scheme : schemes) {
    for (const char* fixture : kFixtures) {
      SCOPED_TRACE(std::string(scheme) + " on " + fixture);
      Mesh_buffers level = load(fixture);
      Result<Mesh_facts> facts = compute_facts(level);
      ASSERT_TRUE(facts.ok());
      for (int k = 1; k <= 3; ++k) {
        Subdivide_options options;
        options.scheme = scheme;
        options.levels = 1;
        options.start_level = k - 1;
        options.triangulate = true;
        Mesh_buffers next;
        Recorder sink;
        const Result<Mesh_facts> step =
            view_step(level, options, facts.value, next, sink);
        ASSERT_TRUE(step.ok()) << step.status.message;
        const Result<Mesh_facts> cgal = compute_facts(next);
        ASSERT_TRUE(cgal.ok());
        expect_same_facts(step.value, cgal.value);
        EXPECT_EQ(sink.out.edges.size(), 2 * cgal.value.edges);
        level = std::move(next);
        facts = step;
      }
    }
  }
}

TEST(LevelView, FactsThatDisagreeWithTheCountsAreCgals) {
  const Mesh_buffers cube = load("cube.off");
  Mesh_facts wrong = compute_facts(cube).value;
  wrong.euler_characteristic = 0;  // as if the parent were a torus
  wrong.components = 7;
  Subdivide_options options;
  options.scheme = "catmull-clark";
  options.levels = 1;
  Mesh_buffers next;
  Recorder sink;
  const Result<Mesh_facts> step = view_step(cube, options, wrong, next, sink);
  ASSERT_TRUE(step.ok());
  EXPECT_EQ(step.value.components, 1u);
  EXPECT_EQ(step.value.genus, 0);
  EXPECT_EQ(step.value.faces, 24u);
  EXPECT_EQ(step.value.edges, 48u);
}

TEST(LevelView, AFailedStepHandsOutNothing) {
  const Mesh_buffers cube = load("cube.off");
  Subdivide_options options;
  options.scheme = "loop";
  options.levels = 1;
  Mesh_buffers next;
  Recorder sink;
  const Result<Mesh_facts> step =
      view_step(cube, options, compute_facts(cube).value, next, sink);
  EXPECT_EQ(step.status.code, Status_code::not_triangles);
  EXPECT_TRUE(sink.order.empty());
  EXPECT_TRUE(next.positions.empty());
}

TEST(LevelView, ALoadedMeshHasCgalsFactsAndItsArrays) {
  Mesh_buffers m = load("mixed-open.off");
  Recorder sink;
  const Result<Mesh_facts> view = view_mesh(m, sink);
  ASSERT_TRUE(view.ok());
  expect_same_facts(view.value, compute_facts(m).value);
  EXPECT_EQ(sink.out.edges, edges_by_map(m));
  m.face_indices[0] = 999;
  Recorder refused;
  EXPECT_EQ(view_mesh(m, refused).status.code, Status_code::invalid_mesh);
  EXPECT_TRUE(refused.order.empty());
}

TEST(LevelView, ReadViewEqualsReadMeshThenViewMesh) {
  for (const char* fixture : kFixtures) {
    SCOPED_TRACE(fixture);
    std::ifstream in(std::string(FIXTURES_DIR) + "/" + fixture,
                     std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    Mesh_buffers mesh;
    Recorder once;
    const Result<Mesh_facts> read =
        read_view(text.str(), Mesh_format::off, mesh, once);
    ASSERT_TRUE(read.ok());
    const Mesh_buffers plain = load(fixture);
    EXPECT_EQ(mesh.positions, plain.positions);
    EXPECT_EQ(mesh.face_indices, plain.face_indices);
    Recorder twice;
    const Result<Mesh_facts> viewed = view_mesh(plain, twice);
    expect_same_facts(read.value, viewed.value);
    EXPECT_EQ(once.out.edges, twice.out.edges);
    EXPECT_EQ(once.out.normals, twice.out.normals);
    EXPECT_EQ(once.out.triangles, twice.out.triangles);
  }
  // A refusal is read_mesh's, line and all, and hands out nothing.
  const std::string bad = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n";
  Mesh_buffers mesh;
  Recorder sink;
  const Result<Mesh_facts> r = read_view(bad, Mesh_format::off, mesh, sink);
  const Result<Mesh_buffers> plain = read_mesh(bad, Mesh_format::off);
  EXPECT_EQ(r.status.code, plain.status.code);
  EXPECT_EQ(r.status.message, plain.status.message);
  EXPECT_EQ(r.status.line, 6);
  EXPECT_TRUE(sink.order.empty());
}

}  // namespace
}  // namespace subdivlab
