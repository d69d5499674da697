// subdivide_mesh / predict_size / scheme_names: exact counts per level,
// validity, topology, positions against plain reference implementations
// (reference_schemes.h) and hand-computed values, the Doo-Sabin border, the
// sqrt3 parity, errors, and the memory model against measured allocations.

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/subdivision_method_3.h>
#include <gtest/gtest.h>
#include <malloc.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <new>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/dqq_border_3.h"
#include "core/level_view.h"
#include "core/mesh_build.h"
#include "core/mesh_facts.h"
#include "core/mesh_io.h"
#include "core/subdivide.h"
#include "reference_schemes.h"

// ---------------------------------------------------------------------------
// A counting global operator new: live and peak bytes (as malloc hands them
// out, malloc_usable_size), to measure what a step really allocates.

namespace {
std::atomic<std::size_t> g_live{0}, g_peak{0};

/// When non-zero, an allocation that would take the live bytes above this
/// fails with std::bad_alloc (to test that nothing throws out).
std::atomic<std::size_t> g_fail_above{0};

void* counted_alloc(std::size_t n) {
  const std::size_t limit = g_fail_above;
  if (limit != 0 && g_live + n > limit) throw std::bad_alloc();
  void* p = std::malloc(n == 0 ? 1 : n);
  if (p == nullptr) throw std::bad_alloc();
  const std::size_t live = g_live += malloc_usable_size(p);
  std::size_t peak = g_peak.load();
  while (live > peak && !g_peak.compare_exchange_weak(peak, live)) {
  }
  return p;
}
void counted_free(void* p) noexcept {
  if (p == nullptr) return;
  g_live -= malloc_usable_size(p);
  std::free(p);
}
}  // namespace

void* operator new(std::size_t n) { return counted_alloc(n); }
void* operator new[](std::size_t n) { return counted_alloc(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  try {
    return counted_alloc(n);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
  try {
    return counted_alloc(n);
  } catch (...) {
    return nullptr;
  }
}
void operator delete(void* p) noexcept { counted_free(p); }
void operator delete[](void* p) noexcept { counted_free(p); }
void operator delete(void* p, std::size_t) noexcept { counted_free(p); }
void operator delete[](void* p, std::size_t) noexcept { counted_free(p); }

namespace subdivlab {
namespace {

using reference::Poly_mesh;
using reference::Vec;
using reference::operator+;
using reference::operator*;

// ---------------------------------------------------------------------------
// Helpers.

Mesh_buffers load(const std::string& name) {
  std::ifstream file(std::string(FIXTURES_DIR) + "/" + name);
  std::stringstream text;
  text << file.rdbuf();
  const Result<Mesh_buffers> r = read_mesh(text.str(), Mesh_format::off);
  EXPECT_TRUE(r.ok()) << name << ": " << r.status.message;
  return r.value;
}

Poly_mesh to_poly(const Mesh_buffers& b) {
  Poly_mesh m;
  for (std::size_t i = 0; i < b.vertex_count(); ++i)
    m.points.push_back(
        {b.positions[3 * i], b.positions[3 * i + 1], b.positions[3 * i + 2]});
  std::size_t o = 0;
  for (std::uint32_t d : b.face_sizes) {
    m.faces.emplace_back(b.face_indices.begin() + o,
                         b.face_indices.begin() + o + d);
    o += d;
  }
  return m;
}

Mesh_buffers poly_to_buffers(const Poly_mesh& m) {
  Mesh_buffers b;
  for (const Vec& p : m.points)
    b.positions.insert(b.positions.end(), p.begin(), p.end());
  for (const auto& f : m.faces) {
    b.face_sizes.push_back(static_cast<std::uint32_t>(f.size()));
    b.face_indices.insert(b.face_indices.end(), f.begin(), f.end());
  }
  return b;
}

Subdivide_options options_for(const std::string& scheme, int levels,
                              int start_level = 0, bool triangulate = false) {
  Subdivide_options o;
  o.scheme = scheme;
  o.levels = levels;
  o.start_level = start_level;
  o.triangulate = triangulate;
  return o;
}

Mesh_buffers subdivided(const Mesh_buffers& in, const Subdivide_options& o) {
  const Result<Mesh_buffers> r = subdivide_mesh(in, o);
  EXPECT_TRUE(r.ok()) << o.scheme << " x" << o.levels << ": "
                      << r.status.message;
  return r.value;
}

/// Valid as CGAL sees it (is_valid_polygon_mesh) and as build_mesh checks
/// it (manifold, oriented).
void expect_valid(const Mesh_buffers& b, const std::string& what) {
  Mesh mesh;
  const Status s = build_mesh(b, mesh);
  ASSERT_TRUE(s.ok()) << what << ": " << s.message;
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh)) << what;
  EXPECT_EQ(mesh.number_of_vertices(), b.vertex_count()) << what;
}

/// The counts a step must give, worked out from the definitions of each
/// refinement on the mesh itself (not from the core's formulas).
struct Counts3 {
  std::size_t v = 0, e = 0, f = 0;
};

Counts3 counts_of(const Poly_mesh& m) {
  const reference::Edges e(m);
  return {m.points.size(), e.list.size(), m.faces.size()};
}

Counts3 expected_after_step(const Poly_mesh& m, const std::string& scheme,
                            int global_step) {
  const reference::Edges edges(m);
  const reference::Neighbours nb(m, edges);
  const std::size_t V = m.points.size(), E = edges.list.size(),
                    F = m.faces.size();
  std::size_t degree_sum = 0, B = 0;
  for (const auto& f : m.faces) degree_sum += f.size();
  for (const auto& e : edges.list) B += e.border() ? 1 : 0;
  if (scheme == "catmull-clark")  // a quad per corner
    return {V + E + F, 2 * E + degree_sum, degree_sum};
  if (scheme == "loop")  // every triangle into 4
    return {V + E, 2 * E + 3 * F, 4 * F};
  if (scheme == "sqrt3") {
    // A centre per face, edges flipped; on odd steps each border edge is
    // trisected and its face split in three.
    const std::size_t b = global_step % 2 == 1 ? B : 0;
    return {V + F + b, E + 3 * F + b, 3 * F};
  }
  // doo-sabin: an F-face per face (with two points at a valence-2 border
  // corner), an E-face per interior edge, a V-face per interior vertex and
  // per border vertex with 3 or more faces.
  std::size_t ears = 0, fans = 0, interior_degrees = 0, border_degrees = 0;
  for (std::size_t v = 0; v < V; ++v) {
    const std::size_t d = nb.of[v].size();
    if (nb.border_of[v].empty()) {
      interior_degrees += d;
    } else {
      border_degrees += d - 2;  // E-face edges across the interior edges
      if (d == 2) ++ears;
      if (d - 1 >= 3) ++fans;
    }
  }
  const std::size_t v_new = degree_sum + ears;
  // F-face edges + edges between corners around each vertex + the V-face
  // edges that close a border fan.
  const std::size_t e_new = v_new + interior_degrees + border_degrees + fans;
  const std::size_t f_new = F + (E - B) + (V - B) + fans;
  return {v_new, e_new, f_new};
}

struct Topology {
  long genus;
  std::size_t components, boundaries;
};

Topology topology(const Mesh_buffers& b) {
  const Result<Mesh_facts> f = compute_facts(b);
  EXPECT_TRUE(f.ok()) << f.status.message;
  return {f.value.genus, f.value.components, f.value.boundaries};
}

/// a and b are the same mesh up to vertex and face order: a one-to-one
/// vertex match by position (to `tol` per coordinate) under which the faces
/// are the same cycles.
void expect_same_mesh(const Mesh_buffers& a, const Mesh_buffers& b, double tol,
                      const std::string& what) {
  ASSERT_EQ(a.vertex_count(), b.vertex_count()) << what;
  ASSERT_EQ(a.face_count(), b.face_count()) << what;
  const std::size_t n = a.vertex_count();
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    return b.positions[3 * i] < b.positions[3 * j];
  });
  std::vector<std::uint32_t> match(n, 0xffffffffu);
  std::vector<bool> taken(n, false);
  std::size_t mismatches = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = a.positions[3 * i];
    auto lo = std::lower_bound(order.begin(), order.end(), x - tol,
                               [&](std::size_t j, double value) {
                                 return b.positions[3 * j] < value;
                               });
    for (auto it = lo; it != order.end() && b.positions[3 * *it] <= x + tol;
         ++it) {
      const std::size_t j = *it;
      if (taken[j]) continue;
      if (std::abs(b.positions[3 * j + 1] - a.positions[3 * i + 1]) <= tol &&
          std::abs(b.positions[3 * j + 2] - a.positions[3 * i + 2]) <= tol) {
        match[i] = static_cast<std::uint32_t>(j);
        taken[j] = true;
        break;
      }
    }
    if (match[i] == 0xffffffffu && ++mismatches <= 5)
      ADD_FAILURE() << what << ": no vertex at (" << a.positions[3 * i] << ", "
                    << a.positions[3 * i + 1] << ", " << a.positions[3 * i + 2]
                    << ")";
  }
  ASSERT_EQ(mismatches, 0u) << what;
  auto canonical = [](std::vector<std::uint32_t> f) {
    std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
    return f;
  };
  std::multiset<std::vector<std::uint32_t>> fa, fb;
  std::size_t o = 0;
  for (std::uint32_t d : a.face_sizes) {
    std::vector<std::uint32_t> f;
    for (std::uint32_t k = 0; k < d; ++k)
      f.push_back(match[a.face_indices[o + k]]);
    fa.insert(canonical(f));
    o += d;
  }
  o = 0;
  for (std::uint32_t d : b.face_sizes) {
    fb.insert(canonical(
        {b.face_indices.begin() + o, b.face_indices.begin() + o + d}));
    o += d;
  }
  EXPECT_TRUE(fa == fb) << what << ": same points, different faces";
}

bool has_point(const Mesh_buffers& b, const Vec& p, double tol = 1e-12) {
  for (std::size_t i = 0; i < b.vertex_count(); ++i)
    if (std::abs(b.positions[3 * i] - p[0]) <= tol &&
        std::abs(b.positions[3 * i + 1] - p[1]) <= tol &&
        std::abs(b.positions[3 * i + 2] - p[2]) <= tol)
      return true;
  return false;
}

const std::vector<std::string> kSchemes = {"catmull-clark", "loop", "doo-sabin",
                                           "sqrt3"};

struct Case {
  const char* fixture;
  bool triangles;  // all faces are triangles
  bool closed;
};

const std::vector<Case> kCases = {
    {"tetrahedron.off", true, true},
    {"octahedron.off", true, true},
    {"icosahedron.off", true, true},
    {"torus-tri.off", true, true},
    {"two-tetrahedra.off", true, true},
    {"disk-tri.off", true, false},
    {"cube.off", false, true},
    {"torus-quad.off", false, true},
    {"rhombicuboctahedron.off", false, true},
    {"grid-open.off", false, false},
    {"mixed-open.off", false, false},
};

// ---------------------------------------------------------------------------
// Counts, validity, topology, prediction: every scheme on every fixture
// (loop and sqrt3 triangulate the non-triangle ones), levels 1 to 3.

TEST(SubdivideCounts, EverySchemeEveryFixtureLevelsOneToThree) {
  for (const std::string& scheme : kSchemes) {
    const bool needs_triangles = scheme == "loop" || scheme == "sqrt3";
    for (const Case& c : kCases) {
      SCOPED_TRACE(scheme + " on " + c.fixture);
      const Mesh_buffers in = load(c.fixture);
      const bool triangulate = needs_triangles && !c.triangles;
      const Topology topo0 = topology(in);
      // Level 0 (after triangulation when asked): the chain's start.
      Mesh_buffers previous =
          subdivided(in, options_for(scheme, 0, 0, triangulate));
      if (triangulate) {
        std::size_t expected_f = 0;
        for (std::uint32_t d : in.face_sizes) expected_f += d - 2;
        EXPECT_EQ(previous.face_count(), expected_f);
      } else {
        EXPECT_EQ(previous.face_count(), in.face_count());
      }
      for (int level = 1; level <= 3; ++level) {
        const Subdivide_options o = options_for(scheme, level, 0, triangulate);
        const Mesh_buffers out = subdivided(in, o);
        const std::string what =
            scheme + " level " + std::to_string(level) + " of " + c.fixture;
        const Counts3 expected =
            expected_after_step(to_poly(previous), scheme, level - 1);
        const Counts3 got = counts_of(to_poly(out));
        EXPECT_EQ(got.v, expected.v) << what;
        EXPECT_EQ(got.e, expected.e) << what;
        EXPECT_EQ(got.f, expected.f) << what;
        // The closed-mesh face counts as the issue states them.
        const Counts3 prev = counts_of(to_poly(previous));
        if (c.closed) {
          if (scheme == "catmull-clark") {
            std::size_t sum = 0;
            for (std::uint32_t d : previous.face_sizes) sum += d;
            EXPECT_EQ(got.f, sum) << what;
          }
          if (scheme == "loop") EXPECT_EQ(got.f, 4 * prev.f) << what;
          if (scheme == "sqrt3") EXPECT_EQ(got.f, 3 * prev.f) << what;
          if (scheme == "doo-sabin")
            EXPECT_EQ(got.f, prev.v + prev.e + prev.f) << what;
        }
        expect_valid(out, what);
        const Topology topo = topology(out);
        EXPECT_EQ(topo.genus, topo0.genus) << what;
        EXPECT_EQ(topo.components, topo0.components) << what;
        EXPECT_EQ(topo.boundaries, topo0.boundaries) << what;
        // The prediction is exact.
        const Result<Size_prediction> p = predict_size(in, o);
        ASSERT_TRUE(p.ok()) << p.status.message;
        EXPECT_EQ(p.value.vertices, got.v) << what;
        EXPECT_EQ(p.value.edges, got.e) << what;
        EXPECT_EQ(p.value.faces, got.f) << what;
        EXPECT_GT(p.value.peak_bytes, 0u);
        previous = out;
      }
    }
  }
}

// The app predicts the next step of a level it keeps from the level's counts
// (facts), without its arrays: the same figures as from the mesh, for every
// scheme and custom host, on the closed fixtures' levels 1 and 2, control
// edges included.
TEST(SubdivideCounts, ClosedLevelsPredictedFromTheirCountsAsFromTheirArrays) {
  std::vector<std::pair<std::string, std::string>> runs;  // scheme, preset
  for (const std::string& scheme : scheme_names())
    if (scheme != "custom") runs.emplace_back(scheme, "");
  for (const char* preset : {"catmull-clark", "loop", "doo-sabin", "sqrt3"})
    runs.emplace_back("custom", preset);
  int compared = 0;
  for (const auto& [scheme, preset] : runs) {
    for (const Case& c : kCases) {
      if (!c.closed) continue;
      Subdivide_options o = options_for(scheme, 1, 0, true);
      if (!preset.empty()) o.custom = custom_rules_preset(preset);
      Mesh_buffers level = load(c.fixture);
      for (int k = 1; k <= 2; ++k) {
        o.start_level = k - 1;
        level = subdivided(level, o);
        const std::string what = scheme + " " + preset + " level " +
                                 std::to_string(k) + " of " + c.fixture;
        const Mesh_facts facts = compute_facts(level).value;
        ASSERT_TRUE(facts.closed) << what;
        Closed_mesh_counts counts;
        counts.vertices = facts.vertices;
        counts.edges = facts.edges;
        counts.faces = facts.faces;
        counts.triangles = facts.triangles;
        counts.control_edges = level.control_edges.size() / 2;
        Subdivide_options next = o;
        next.start_level = k;
        for (int levels : {1, 2}) {
          next.levels = levels;
          const Result<Size_prediction> a = predict_size(level, next);
          const Result<Size_prediction> b = predict_size(counts, next);
          ASSERT_TRUE(a.ok()) << what << ": " << a.status.message;
          ASSERT_TRUE(b.ok()) << what << ": " << b.status.message;
          EXPECT_EQ(b.value.vertices, a.value.vertices) << what;
          EXPECT_EQ(b.value.edges, a.value.edges) << what;
          EXPECT_EQ(b.value.faces, a.value.faces) << what;
          EXPECT_EQ(b.value.peak_bytes, a.value.peak_bytes) << what;
          ++compared;
        }
      }
    }
  }
  // 7 schemes and 4 custom hosts, 8 closed fixtures, 2 levels, 2 predictions.
  EXPECT_EQ(compared, 11 * 8 * 2 * 2);
}

TEST(SubdivideCounts, CountsOfQuadsRefuseTrianglesAsTheArraysDo) {
  const Mesh_buffers cube = load("cube.off");
  Closed_mesh_counts counts;
  counts.vertices = 8;
  counts.edges = 12;
  counts.faces = 6;
  const Subdivide_options loop = options_for("loop", 1);
  const Result<Size_prediction> a = predict_size(cube, loop);
  const Result<Size_prediction> b = predict_size(counts, loop);
  ASSERT_FALSE(a.ok());
  ASSERT_FALSE(b.ok());
  EXPECT_EQ(b.status.code, a.status.code);
  EXPECT_EQ(b.status.message, a.status.message);
  // Triangulating first needs the faces: said, not guessed.
  const Result<Size_prediction> c =
      predict_size(counts, options_for("loop", 1, 0, true));
  ASSERT_FALSE(c.ok());
  EXPECT_EQ(c.status.code, Status_code::invalid_argument);
  EXPECT_EQ(c.status.message,
            "a mesh to triangulate first is predicted from its faces");
  counts.triangles = 7;
  const Result<Size_prediction> d =
      predict_size(counts, options_for("catmull-clark", 1));
  EXPECT_EQ(d.status.code, Status_code::invalid_argument);
  EXPECT_EQ(d.status.message, "counts: more triangles than faces, or none");
  // With the counts right, the cube's Catmull-Clark step: 26, 48, 24.
  counts.triangles = 0;
  const Result<Size_prediction> cc =
      predict_size(counts, options_for("catmull-clark", 1));
  ASSERT_TRUE(cc.ok());
  EXPECT_EQ(cc.value.vertices, 26u);
  EXPECT_EQ(cc.value.edges, 48u);
  EXPECT_EQ(cc.value.faces, 24u);
}

TEST(SubdivideCounts, CubeCatmullClarkAbsoluteNumbers) {
  // 8/12/6 -> 26/48/24 -> 98/192/96 -> 386/768/384.
  const Mesh_buffers cube = load("cube.off");
  const std::size_t v[] = {26, 98, 386}, e[] = {48, 192, 768},
                    f[] = {24, 96, 384};
  for (int level = 1; level <= 3; ++level) {
    const Counts3 c = counts_of(
        to_poly(subdivided(cube, options_for("catmull-clark", level))));
    EXPECT_EQ(c.v, v[level - 1]);
    EXPECT_EQ(c.e, e[level - 1]);
    EXPECT_EQ(c.f, f[level - 1]);
  }
}

TEST(SubdivideCounts, LevelZeroReturnsTheSameMesh) {
  const Mesh_buffers cube = load("cube.off");
  for (const std::string& scheme : {"catmull-clark", "doo-sabin"}) {
    const Mesh_buffers out = subdivided(cube, options_for(scheme, 0));
    EXPECT_EQ(out.positions, cube.positions);
    EXPECT_EQ(out.face_sizes, cube.face_sizes);
    EXPECT_EQ(out.face_indices, cube.face_indices);
  }
}

TEST(SubdivideCounts, SchemeNamesInDisplayOrder) {
  const std::vector<std::string> names = scheme_names();
  ASSERT_GE(names.size(), 4u);
  EXPECT_EQ(std::vector<std::string>(names.begin(), names.begin() + 4),
            kSchemes);
}

// ---------------------------------------------------------------------------
// Positions against the plain reference implementations.

TEST(SubdividePositions, CatmullClarkMatchesReferenceOnClosedAndOpenMeshes) {
  for (const char* fixture : {"cube.off", "tetrahedron.off", "torus-quad.off",
                              "rhombicuboctahedron.off", "grid-open.off",
                              "mixed-open.off", "disk-tri.off"}) {
    const Mesh_buffers in = load(fixture);
    Poly_mesh ref = to_poly(in);
    for (int level = 1; level <= 2; ++level) {
      ref = reference::catmull_clark(ref);
      const Mesh_buffers out =
          subdivided(in, options_for("catmull-clark", level));
      expect_same_mesh(out, poly_to_buffers(ref), 1e-12,
                       std::string("catmull-clark level ") +
                           std::to_string(level) + " of " + fixture);
    }
  }
}

TEST(SubdividePositions, LoopMatchesReferenceOnClosedAndOpenMeshes) {
  for (const char* fixture :
       {"tetrahedron.off", "octahedron.off", "icosahedron.off", "torus-tri.off",
        "disk-tri.off", "two-tetrahedra.off"}) {
    const Mesh_buffers in = load(fixture);
    Poly_mesh ref = to_poly(in);
    for (int level = 1; level <= 2; ++level) {
      ref = reference::loop(ref);
      const Mesh_buffers out = subdivided(in, options_for("loop", level));
      expect_same_mesh(out, poly_to_buffers(ref), 1e-12,
                       std::string("loop level ") + std::to_string(level) +
                           " of " + fixture);
    }
  }
  // An open triangle mesh with valence-2 and valence-3 border vertices:
  // the triangulated grid.
  const Mesh_buffers grid =
      subdivided(load("grid-open.off"), options_for("loop", 0, 0, true));
  Poly_mesh ref = to_poly(grid);
  for (int level = 1; level <= 2; ++level) {
    ref = reference::loop(ref);
    expect_same_mesh(subdivided(grid, options_for("loop", level)),
                     poly_to_buffers(ref), 1e-12,
                     "loop level " + std::to_string(level) + " of the grid");
  }
}

TEST(SubdividePositions, HandComputedValues) {
  // Catmull-Clark, cube [-1,1]^3, corner S = (-1,-1,-1), valence n = 3:
  // adjacent face points (-1,0,0), (0,-1,0), (0,0,-1) -> Q = -(1/3)(1,1,1);
  // adjacent edge midpoints (0,-1,-1), (-1,0,-1), (-1,-1,0) -> R =
  // -(2/3)(1,1,1); vertex point (Q + 2R + (n-3) S) / n = -(5/9)(1,1,1).
  // Edge (-1,-1,-1)-(1,-1,-1): (v1 + v2 + f1 + f2)/4 with face points
  // (0,-1,0) and (0,0,-1) -> (0, -3/4, -3/4).
  const Mesh_buffers cc =
      subdivided(load("cube.off"), options_for("catmull-clark", 1));
  EXPECT_TRUE(has_point(cc, {-5.0 / 9, -5.0 / 9, -5.0 / 9}));
  EXPECT_TRUE(has_point(cc, {5.0 / 9, 5.0 / 9, 5.0 / 9}));
  EXPECT_TRUE(has_point(cc, {0, -0.75, -0.75}));
  EXPECT_TRUE(has_point(cc, {0, 0, -1}));  // a face point

  // Loop, octahedron: vertex (1,0,0) has valence 4 and neighbours summing to
  // 0; alpha(4) = 5/8 - (3/8 + 1/4 cos(pi/2))^2 = 31/64, so it goes to
  // (1 - 31/64)(1,0,0) = (33/64, 0, 0). Edge (1,0,0)-(0,1,0) with opposite
  // vertices (0,0,1), (0,0,-1): 3/8 (1,1,0) + 1/8 (0,0,0) = (3/8, 3/8, 0).
  const Mesh_buffers loop =
      subdivided(load("octahedron.off"), options_for("loop", 1));
  EXPECT_TRUE(has_point(loop, {33.0 / 64, 0, 0}));
  EXPECT_TRUE(has_point(loop, {0, 0, -33.0 / 64}));
  EXPECT_TRUE(has_point(loop, {0.375, 0.375, 0}));

  // sqrt3, tetrahedron (+-1 coordinates): valence 3, a = (4 - 2 cos(2pi/3))/9
  // = 5/9; (1,1,1) goes to (1 - a) v + a/3 sum(neighbours) = 4/9 (1,1,1) +
  // 5/27 (-1,-1,-1) = 7/27 (1,1,1); face points are centroids.
  const Mesh_buffers s3 =
      subdivided(load("tetrahedron.off"), options_for("sqrt3", 1));
  EXPECT_TRUE(has_point(s3, {7.0 / 27, 7.0 / 27, 7.0 / 27}));
  EXPECT_TRUE(has_point(s3, {1.0 / 3, 1.0 / 3, -1.0 / 3}));  // face 0,1,2

  // Doo-Sabin, cube: the corner of face x = -1 at (-1,-1,-1) is
  // (9 v + 3 (two face neighbours) + opposite) / 16 = -(1, 1/2, 1/2).
  const Mesh_buffers ds =
      subdivided(load("cube.off"), options_for("doo-sabin", 1));
  EXPECT_TRUE(has_point(ds, {-1, -0.5, -0.5}));
  EXPECT_TRUE(has_point(ds, {0.5, 1, 0.5}));
}

// ---------------------------------------------------------------------------
// Doo-Sabin: CGAL's host on closed meshes, the border host on open ones.

TEST(SubdivideDooSabin, BorderHostEqualsCgalOnClosedMeshes) {
  for (const char* fixture : {"cube.off", "tetrahedron.off", "torus-quad.off",
                              "rhombicuboctahedron.off", "icosahedron.off"}) {
    const Mesh_buffers in = load(fixture);
    Mesh cgal, ours;
    ASSERT_TRUE(build_mesh(in, cgal).ok());
    ASSERT_TRUE(build_mesh(in, ours).ok());
    for (int level = 1; level <= 2; ++level) {
      CGAL::Subdivision_method_3::DooSabin_subdivision(
          cgal, CGAL::parameters::number_of_iterations(1));
      DooSabin_border_subdivision(ours,
                                  CGAL::parameters::number_of_iterations(1));
      cgal.collect_garbage();
      expect_same_mesh(to_buffers(ours), to_buffers(cgal), 1e-12,
                       std::string("doo-sabin level ") + std::to_string(level) +
                           " of " + fixture);
    }
  }
}

/// The control border of `in` and the border of `out` as point loops.
std::vector<Vec> border_points(const Mesh_buffers& b) {
  const Poly_mesh m = to_poly(b);
  const auto loops = reference::border_loops(m);
  EXPECT_EQ(loops.size(), 1u);
  std::vector<Vec> points;
  if (!loops.empty())
    for (auto v : loops[0]) points.push_back(m.points[v]);
  return points;
}

/// `got` equals `want` as a cyclic sequence (same direction), to 1e-12.
void expect_same_loop(const std::vector<Vec>& got, const std::vector<Vec>& want,
                      const std::string& what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  auto near = [](const Vec& a, const Vec& b) {
    return std::abs(a[0] - b[0]) <= 1e-12 && std::abs(a[1] - b[1]) <= 1e-12 &&
           std::abs(a[2] - b[2]) <= 1e-12;
  };
  for (std::size_t shift = 0; shift < want.size(); ++shift) {
    if (!near(got[0], want[shift])) continue;
    bool all = true;
    for (std::size_t i = 0; i < got.size() && all; ++i)
      all = near(got[i], want[(i + shift) % want.size()]);
    if (all) return;
  }
  ADD_FAILURE() << what << ": the border is not the expected polygon";
}

TEST(SubdivideDooSabin, OpenGridBorderFollowsTheQuadraticBSpline) {
  const Mesh_buffers grid = load("grid-open.off");  // 3 x 3 quads, 16 vertices
  const std::vector<Vec> control = border_points(grid);
  ASSERT_EQ(control.size(), 12u);
  std::vector<Vec> chaikin = control;
  for (int level = 1; level <= 3; ++level) {
    const std::string what = "doo-sabin level " + std::to_string(level);
    const Mesh_buffers out = subdivided(grid, options_for("doo-sabin", level));
    expect_valid(out, what);
    const Result<Mesh_facts> facts = compute_facts(out);
    ASSERT_TRUE(facts.ok());
    EXPECT_EQ(facts.value.boundaries, 1u) << what;
    EXPECT_EQ(facts.value.components, 1u) << what;
    EXPECT_EQ(facts.value.genus, 0) << what;
    if (level == 1) {
      // 9 F-faces (the 4 corner ones get a 5th point), 12 E-faces, 4
      // V-faces: V' = 36 + 4, E' = 64, F' = 25.
      EXPECT_EQ(facts.value.vertices, 40u);
      EXPECT_EQ(facts.value.edges, 64u);
      EXPECT_EQ(facts.value.faces, 25u);
      EXPECT_EQ(facts.value.quads, 5u + 12u + 4u);
      EXPECT_EQ(facts.value.other_faces, 4u);  // the corner pentagons
    }
    // The border is k Chaikin steps of the control border: a control
    // polygon of the same uniform quadratic B-spline ...
    chaikin = reference::chaikin(chaikin);
    const std::vector<Vec> border = border_points(out);
    expect_same_loop(border, chaikin, what);
    // ... so the midpoints of its edges lie on that B-spline of the
    // control border: at t = j / 2^level on the piece of each control
    // point.
    std::vector<Vec> on_curve;
    const int steps = 1 << level;
    for (std::size_t i = 0; i < control.size(); ++i)
      for (int j = 0; j < steps; ++j)
        on_curve.push_back(reference::quadratic_bspline(
            control, i, static_cast<double>(j) / steps));
    std::vector<Vec> midpoints;
    for (std::size_t i = 0; i < border.size(); ++i)
      midpoints.push_back(0.5 * (border[i] + border[(i + 1) % border.size()]));
    expect_same_loop(midpoints, on_curve, what + " midpoints on the B-spline");
  }
  // Interior corners keep CGAL's Doo-Sabin mask: the centre face's corner at
  // (1,1): (9 (1,1) + 3 (2,1) + 3 (1,2) + (2,2)) / 16 = (1.25, 1.25).
  const Mesh_buffers one = subdivided(grid, options_for("doo-sabin", 1));
  EXPECT_TRUE(has_point(one, {1.25, 1.25, 0}));
  // The corner (0,0) is cut by two points on its border edges.
  EXPECT_TRUE(has_point(one, {0.25, 0, 0}));
  EXPECT_TRUE(has_point(one, {0, 0.25, 0}));
}

TEST(SubdivideDooSabin, OpenMeshesWithFansAndMixedFaces) {
  // disk-tri: the rim vertices have 2 faces; mixed-open has quads,
  // triangles, a pentagon and border vertices with up to 4 faces.
  for (const char* fixture : {"disk-tri.off", "mixed-open.off"}) {
    const Mesh_buffers in = load(fixture);
    const std::vector<Vec> control = border_points(in);
    std::vector<Vec> chaikin = control;
    for (int level = 1; level <= 3; ++level) {
      const Mesh_buffers out = subdivided(in, options_for("doo-sabin", level));
      const std::string what =
          std::string(fixture) + " level " + std::to_string(level);
      expect_valid(out, what);
      chaikin = reference::chaikin(chaikin);
      expect_same_loop(border_points(out), chaikin, what);
    }
  }
}

TEST(SubdivideDooSabin, SinglePolygonsBecomeTheirChaikinPolygon) {
  // Every corner of a lone polygon is an ear: one F-face through two points
  // per corner, at 3/4 v + 1/4 (neighbour) -- Chaikin's cut polygon.
  Mesh_buffers triangle;
  triangle.positions = {0, 0, 0, 4, 0, 0, 0, 4, 0};
  triangle.face_sizes = {3};
  triangle.face_indices = {0, 1, 2};
  Mesh_buffers quad;
  quad.positions = {0, 0, 0, 4, 0, 0, 4, 4, 1, 0, 4, 0};
  quad.face_sizes = {4};
  quad.face_indices = {0, 1, 2, 3};
  for (const Mesh_buffers* in : {&triangle, &quad}) {
    const std::vector<Vec> control = border_points(*in);
    const Mesh_buffers one = subdivided(*in, options_for("doo-sabin", 1));
    ASSERT_EQ(one.face_count(), 1u);
    EXPECT_EQ(one.face_sizes[0], 2 * in->face_sizes[0]);
    expect_same_loop(border_points(one), reference::chaikin(control),
                     "doo-sabin of a lone polygon");
    const Mesh_buffers two = subdivided(*in, options_for("doo-sabin", 2));
    EXPECT_EQ(two.face_count(), 1u);
    expect_same_loop(border_points(two),
                     reference::chaikin(reference::chaikin(control)),
                     "doo-sabin level 2 of a lone polygon");
  }
}

// ---------------------------------------------------------------------------
// sqrt3: level k is the same in one call or k calls of one level.

TEST(SubdivideSqrt3, StepwiseEqualsOneCallOnOpenMeshes) {
  for (const char* fixture : {"disk-tri.off", "tetrahedron.off"}) {
    Mesh_buffers in = load(fixture);
    if (std::string(fixture) == "tetrahedron.off") {
      // Open it: drop a face.
      in.face_sizes.pop_back();
      in.face_indices.resize(in.face_indices.size() - 3);
    }
    Mesh_buffers stepwise = in;
    Mesh cgal;
    for (int level = 1; level <= 4; ++level) {
      const std::string what =
          std::string(fixture) + " level " + std::to_string(level);
      stepwise = subdivided(stepwise, options_for("sqrt3", 1, level - 1));
      const Mesh_buffers at_once = subdivided(in, options_for("sqrt3", level));
      expect_valid(stepwise, what);
      expect_same_mesh(stepwise, at_once, 1e-12, what);
      // And CGAL's own k-level call agrees.
      ASSERT_TRUE(build_mesh(in, cgal).ok());
      CGAL::Subdivision_method_3::Sqrt3_subdivision(
          cgal, CGAL::parameters::number_of_iterations(level));
      cgal.collect_garbage();
      expect_same_mesh(at_once, to_buffers(cgal), 1e-12, what + " vs CGAL");
      // The border is trisected on odd steps only.
      const Result<Mesh_facts> facts = compute_facts(at_once);
      ASSERT_TRUE(facts.ok());
      EXPECT_EQ(facts.value.boundaries, 1u);
    }
  }
}

TEST(SubdivideSqrt3, OddStartLevelOnAMeshNotFromSqrt3IsRefused) {
  // disk-tri's faces have one border edge each, so an odd start is fine;
  // the triangulated grid has corner triangles with two border edges.
  const Mesh_buffers grid =
      subdivided(load("grid-open.off"), options_for("sqrt3", 0, 0, true));
  const Result<Mesh_buffers> r =
      subdivide_mesh(grid, options_for("sqrt3", 1, 1));
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status.code, Status_code::invalid_argument);
  EXPECT_NE(r.status.message.find("more than one border edge"),
            std::string::npos)
      << r.status.message;
  EXPECT_TRUE(subdivide_mesh(grid, options_for("sqrt3", 2, 0)).ok());
}

// ---------------------------------------------------------------------------
// Errors.

TEST(SubdivideErrors, LoopAndSqrt3NeedTrianglesUnlessTriangulating) {
  const Mesh_buffers cube = load("cube.off");
  for (const std::string& scheme : {"loop", "sqrt3"}) {
    const Result<Mesh_buffers> r = subdivide_mesh(cube, options_for(scheme, 1));
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.status.code, Status_code::not_triangles);
    EXPECT_EQ(r.status.message,
              scheme +
                  " needs a triangle mesh: 6 of 6 faces are not "
                  "triangles; triangulate first (option triangulate)");
    const Result<Size_prediction> p =
        predict_size(cube, options_for(scheme, 1));
    EXPECT_EQ(p.status.code, Status_code::not_triangles);
    EXPECT_EQ(p.status.message, r.status.message);
    const Mesh_buffers t = subdivided(cube, options_for(scheme, 1, 0, true));
    EXPECT_EQ(t.face_count(), scheme == "loop" ? 48u : 36u);
  }
  const Result<Mesh_buffers> mixed =
      subdivide_mesh(load("mixed-open.off"), options_for("loop", 1));
  EXPECT_EQ(mixed.status.message,
            "loop needs a triangle mesh: 3 of 9 faces are not triangles; "
            "triangulate first (option triangulate)");
}

TEST(SubdivideErrors, UnknownSchemeAndNegativeLevels) {
  const Mesh_buffers cube = load("cube.off");
  Result<Mesh_buffers> r = subdivide_mesh(cube, options_for("butterfly", 1));
  EXPECT_EQ(r.status.code, Status_code::invalid_argument);
  EXPECT_EQ(
      r.status.message.rfind("unknown scheme \"butterfly\"; known schemes: "
                             "catmull-clark, loop, doo-sabin, sqrt3",
                             0),
      0u)
      << r.status.message;
  EXPECT_EQ(predict_size(cube, options_for("butterfly", 1)).status.code,
            Status_code::invalid_argument);
  r = subdivide_mesh(cube, options_for("loop", -1));
  EXPECT_EQ(r.status.code, Status_code::invalid_argument);
  EXPECT_NE(r.status.message.find("levels must be 0 or more (got -1)"),
            std::string::npos);
  EXPECT_NE(r.status.message.find("catmull-clark, loop, doo-sabin, sqrt3"),
            std::string::npos);
  r = subdivide_mesh(cube, options_for("loop", 1, -2));
  EXPECT_EQ(r.status.code, Status_code::invalid_argument);
}

TEST(SubdivideErrors, TwoValentVerticesOnlyForCatmullClark) {
  // A "pillow": two triangles glued along all three edges. Every vertex has
  // 2 edges; loop, sqrt3 and doo-sabin would repeat edges.
  Mesh_buffers pillow;
  pillow.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  pillow.face_sizes = {3, 3};
  pillow.face_indices = {0, 1, 2, 0, 2, 1};
  for (const std::string& scheme : {"loop", "sqrt3", "doo-sabin"}) {
    const Result<Mesh_buffers> r =
        subdivide_mesh(pillow, options_for(scheme, 1));
    EXPECT_EQ(r.status.code, Status_code::invalid_mesh) << scheme;
    EXPECT_EQ(r.status.message,
              scheme +
                  " cannot refine vertex 0: it has only 2 edges, so its two "
                  "faces share two edges and the result would repeat edges "
                  "(catmull-clark can refine it)");
    EXPECT_EQ(predict_size(pillow, options_for(scheme, 1)).status.message,
              r.status.message);
  }
  for (int level = 1; level <= 3; ++level) {
    const Mesh_buffers cc =
        subdivided(pillow, options_for("catmull-clark", level));
    expect_valid(cc, "catmull-clark of the pillow");
    EXPECT_EQ(cc.face_count(), 6u << (2 * (level - 1)));
  }
}

TEST(SubdivideErrors, InvalidMeshIsReportedByBuildMesh) {
  Mesh_buffers bad = load("cube.off");
  bad.face_indices[0] = 99;
  const Result<Mesh_buffers> r =
      subdivide_mesh(bad, options_for("catmull-clark", 1));
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.status.code, Status_code::invalid_mesh);
}

// ---------------------------------------------------------------------------
// Memory: too_large before anything is allocated, and the model against
// measured peaks.

TEST(SubdivideMemory, TooLargeFailsBeforeAllocatingAndLeavesNothingBehind) {
  const Mesh_buffers cube = load("cube.off");
  Subdivide_options o = options_for("catmull-clark", 6);
  // Levels 1-4 of the cube fit in 512 kB, level 5 (6144 faces) does not.
  o.memory_limit_bytes = 512 << 10;
  (void)subdivide_mesh(cube, options_for("catmull-clark", 1));  // warm up
  const std::size_t before = g_live;
  g_peak = g_live.load();
  {
    const Result<Mesh_buffers> r = subdivide_mesh(cube, o);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.status.code, Status_code::too_large);
  }
  EXPECT_EQ(g_live.load(), before) << "something stayed allocated";
  // The run was refused before its first step: the peak stayed below what
  // level 1 alone needs.
  const std::size_t peak = g_peak.load() - before;
  const Result<Size_prediction> level1 =
      predict_size(cube, options_for("catmull-clark", 1));
  EXPECT_LE(peak, level1.value.peak_bytes);
  const std::string message = subdivide_mesh(cube, o).status.message;
  EXPECT_EQ(message.rfind("level 5 of catmull-clark would need about ", 0), 0u)
      << message;
  EXPECT_NE(message.find("(predicted 6146 vertices, 6144 faces)"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("more than the 512 kB available"), std::string::npos)
      << message;
  // The next call works.
  o.memory_limit_bytes = 0;
  o.levels = 5;
  const Result<Mesh_buffers> ok = subdivide_mesh(cube, o);
  ASSERT_TRUE(ok.ok());
  EXPECT_EQ(ok.value.face_count(), 6144u);
  // 20 levels are refused at once, naming the first level that would not
  // fit: level 8 (393216 faces) fits in 100 MB, level 9 does not.
  o.levels = 20;
  o.memory_limit_bytes = std::size_t{100} << 20;
  const std::size_t live = g_live.load();
  g_peak = live;
  const Result<Mesh_buffers> huge = subdivide_mesh(cube, o);
  EXPECT_LE(g_peak.load() - live, level1.value.peak_bytes)
      << "levels 1-8 were computed before the refusal";
  EXPECT_EQ(huge.status.code, Status_code::too_large);
  EXPECT_EQ(huge.status.message.rfind("level 9 of catmull-clark would need "
                                      "about ",
                                      0),
            0u)
      << huge.status.message;
  EXPECT_NE(huge.status.message.find("(predicted 1.57 M vertices, 1.57 M "
                                     "faces), more than the 100 MB available"),
            std::string::npos)
      << huge.status.message;
}

TEST(SubdivideMemory, BadAllocInsideCgalBecomesAnErrorAndLeaksNothing) {
  const Mesh_buffers cube = load("cube.off");
  Subdivide_options o = options_for("catmull-clark", 5);  // no memory limit
  (void)subdivide_mesh(cube, options_for("catmull-clark", 1));  // warm up
  const std::size_t before = g_live;
  {
    g_fail_above = before + 200 * 1024;  // level 4 or 5 runs out
    const Result<Mesh_buffers> r = subdivide_mesh(cube, o);
    g_fail_above = 0;
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.status.code, Status_code::too_large);
    EXPECT_NE(r.status.message.find("out of memory at level "),
              std::string::npos)
        << r.status.message;
    EXPECT_NE(r.status.message.find(" of catmull-clark"), std::string::npos);
  }
  EXPECT_EQ(g_live.load(), before) << "something stayed allocated";
  const Result<Mesh_buffers> ok = subdivide_mesh(cube, o);
  ASSERT_TRUE(ok.ok());
  EXPECT_EQ(ok.value.face_count(), 6144u);
}

TEST(SubdivideMemory, SizesPast32BitsStayExactOnEveryTarget) {
  // Counts and bytes of a run past 2^32 are 64-bit on every target: on wasm32
  // (size_t of 32 bits) a size_t anywhere on the way would wrap them.
  // Catmull-Clark on a closed genus-0 quad mesh: F = 6 * 4^n, E = 2F,
  // V = F + 2.
  const Mesh_buffers cube = load("cube.off");
  const Result<Size_prediction> p16 =
      predict_size(cube, options_for("catmull-clark", 16));
  ASSERT_TRUE(p16.ok()) << p16.status.message;
  const std::uint64_t faces = std::uint64_t{6} << 32;  // 6 * 4^16
  EXPECT_EQ(p16.value.faces, faces);
  EXPECT_EQ(p16.value.edges, 2 * faces);
  EXPECT_EQ(p16.value.vertices, faces + 2);
  // The step's bytes per face do not depend on the level once the fixed
  // allocations vanish: level 16 (past 2^32 bytes) costs what level 8 does.
  const Result<Size_prediction> p8 =
      predict_size(cube, options_for("catmull-clark", 8));
  ASSERT_TRUE(p8.ok()) << p8.status.message;
  const double per_face_16 =
      static_cast<double>(p16.value.peak_bytes) / static_cast<double>(faces);
  const double per_face_8 = static_cast<double>(p8.value.peak_bytes) /
                            static_cast<double>(p8.value.faces);
  EXPECT_GT(p16.value.peak_bytes, std::uint64_t{1} << 32);
  EXPECT_NEAR(per_face_16, per_face_8, 0.05 * per_face_8);
  // Without a memory limit the run is refused before its first step, at the
  // first level whose halfedges 32-bit indices cannot number: level 14
  // (2E = 24 * 4^14 > 2^32 - 2).
  const Result<Mesh_buffers> r =
      subdivide_mesh(cube, options_for("catmull-clark", 16));
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status.code, Status_code::too_large);
  EXPECT_EQ(
      r.status.message.rfind("level 14 of catmull-clark would need about ", 0),
      0u)
      << r.status.message;
  EXPECT_NE(r.status.message.find("(predicted 1.61 G vertices, 1.61 G "
                                  "faces), more elements than a mesh can "
                                  "index (2^32)"),
            std::string::npos)
      << r.status.message;
}

/// Quads of a torus, nu x nv; as triangles (two per quad), or with
/// `mixed` every other quad (a checkerboard) as two triangles.
Mesh_buffers torus(int nu, int nv, bool triangles, bool mixed = false) {
  Poly_mesh m;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv;
      m.points.push_back({(3 + std::cos(v)) * std::cos(u),
                          (3 + std::cos(v)) * std::sin(u), std::sin(v)});
    }
  auto at = [&](int i, int j) {
    return static_cast<std::uint32_t>(((i + nu) % nu) * nv + (j + nv) % nv);
  };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const auto a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1),
                 d = at(i, j + 1);
      if (triangles || (mixed && (i + j) % 2 == 0)) {
        m.faces.push_back({a, b, c});
        m.faces.push_back({a, c, d});
      } else {
        m.faces.push_back({a, b, c, d});
      }
    }
  return poly_to_buffers(m);
}

/// An open nx x ny grid of quads (or triangles, or a checkerboard of both
/// when `mixed`) in z = 0, slightly bent.
Mesh_buffers grid(int nx, int ny, bool triangles, bool mixed = false) {
  Poly_mesh m;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      m.points.push_back(
          {double(i), double(j), std::sin(0.1 * i) * std::cos(0.1 * j)});
  auto at = [&](int i, int j) {
    return static_cast<std::uint32_t>(j * (nx + 1) + i);
  };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const auto a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1),
                 d = at(i, j + 1);
      if (triangles || (mixed && (i + j) % 2 == 0)) {
        m.faces.push_back({a, b, c});
        m.faces.push_back({a, c, d});
      } else {
        m.faces.push_back({a, b, c, d});
      }
    }
  return poly_to_buffers(m);
}

TEST(SubdivideMemory, ModelBoundsTheMeasuredPeakOfEveryStep) {
  struct Probe {
    const char* scheme;
    const char* mesh;
    Mesh_buffers in;
    int start_level;
    int levels = 1;
    bool triangulate = false;
  };
  // Control edges given as pairs (every face's first edge): found through
  // the halfedges around each vertex, held as pairs until marked.
  const auto with_control_edges = [](Mesh_buffers m) {
    std::size_t o = 0;
    for (std::uint32_t f = 0; f < m.face_count(); ++f) {
      m.control_edges.insert(m.control_edges.end(),
                             {m.face_indices[o], m.face_indices[o + 1]});
      o += m.face_sizes[f];
    }
    return m;
  };
  std::vector<Probe> probes = {
      {"catmull-clark", "quad torus 160x80", torus(160, 80, false), 0},
      {"catmull-clark", "quad torus 160x80, pairs",
       with_control_edges(torus(160, 80, false)), 0},
      {"loop", "tri torus 160x80, pairs",
       with_control_edges(torus(160, 80, true)), 0},
      {"loop", "quad torus 120x60, triangulated", torus(120, 60, false), 0, 1,
       true},
      {"catmull-clark", "quad grid 120x100", grid(120, 100, false), 0},
      {"catmull-clark", "tri torus 120x60", torus(120, 60, true), 0},
      {"loop", "tri torus 160x80", torus(160, 80, true), 0},
      {"loop", "tri grid 120x100", grid(120, 100, true), 0},
      {"doo-sabin", "quad torus 160x80", torus(160, 80, false), 0},
      {"doo-sabin", "tri torus 120x60", torus(120, 60, true), 0},
      {"doo-sabin", "quad grid 120x100", grid(120, 100, false), 0},
      {"doo-sabin", "tri grid 120x100", grid(120, 100, true), 0},
      {"sqrt3", "tri torus 160x80", torus(160, 80, true), 0},
      {"sqrt3", "tri grid 120x100 (even)", grid(120, 100, true), 0},
  };
  // An odd sqrt3 step on a mesh from an even one.
  probes.push_back({"sqrt3", "tri grid 120x100 (odd)",
                    subdivided(grid(120, 100, true), options_for("sqrt3", 1)),
                    1});
  // Several levels in one call: the capacities CGAL's hosts leave behind
  // carry over to the next step.
  probes.push_back(
      {"catmull-clark", "quad torus 40x20 x3", torus(40, 20, false), 0, 3});
  probes.push_back(
      {"catmull-clark", "mixed-open x3", load("mixed-open.off"), 0, 5});
  probes.push_back({"loop", "tri torus 40x20 x3", torus(40, 20, true), 0, 3});
  probes.push_back({"loop", "tri grid 30x20 x3", grid(30, 20, true), 0, 3});
  probes.push_back(
      {"doo-sabin", "quad torus 40x20 x3", torus(40, 20, false), 0, 3});
  probes.push_back(
      {"doo-sabin", "quad grid 30x20 x3", grid(30, 20, false), 0, 3});
  probes.push_back({"sqrt3", "tri torus 40x20 x4", torus(40, 20, true), 0, 4});
  probes.push_back({"sqrt3", "tri grid 30x20 x4", grid(30, 20, true), 0, 4});
  // Quad/triangle: triangles, quads, both (a level with face offsets and a
  // parent with polygon counts), open and closed, one and several levels.
  probes.push_back(
      {"quad-triangle", "tri torus 160x80", torus(160, 80, true), 0});
  probes.push_back(
      {"quad-triangle", "quad torus 160x80", torus(160, 80, false), 0});
  probes.push_back(
      {"quad-triangle", "mixed torus 160x80", torus(160, 80, false, true), 0});
  probes.push_back(
      {"quad-triangle", "mixed grid 120x100", grid(120, 100, false, true), 0});
  probes.push_back(
      {"quad-triangle", "tri grid 120x100", grid(120, 100, true), 0});
  probes.push_back({"quad-triangle", "mixed torus 40x20 x3",
                    torus(40, 20, false, true), 0, 3});
  probes.push_back({"quad-triangle", "mixed grid 30x20 x3",
                    grid(30, 20, false, true), 0, 3});
  probes.push_back(
      {"quad-triangle", "tri torus 40x20 x3", torus(40, 20, true), 0, 3});
  // Creased runs (OpenSubdiv's tags): a sharp first edge on every third
  // face, a corner on every fifth vertex, a hole every 50th face; Chaikin
  // on the triangles, the border mode none on the grid.
  const auto creased = [](Mesh_buffers m, Crease_method method,
                          Boundary_interpolation boundary) {
    std::size_t o = 0;
    for (std::uint32_t f = 0; f < m.face_count(); ++f) {
      if (f % 3 == 0) {
        m.tags.crease_edges.insert(m.tags.crease_edges.end(),
                                   {m.face_indices[o], m.face_indices[o + 1]});
        m.tags.crease_sharpness.push_back(0.5f + static_cast<float>(f % 4));
      }
      if (f % 50 == 0) m.tags.holes.push_back(f);
      o += m.face_sizes[f];
    }
    for (std::uint32_t v = 0; v < m.vertex_count(); v += 5) {
      m.tags.corner_vertices.push_back(v);
      m.tags.corner_sharpness.push_back(1.5f);
    }
    m.tags.crease_method = method;
    m.tags.boundary = boundary;
    return m;
  };
  probes.push_back({"catmull-clark", "creased quad torus 160x80",
                    creased(torus(160, 80, false), Crease_method::uniform,
                            Boundary_interpolation::edge_only),
                    0});
  probes.push_back({"loop", "creased tri torus 40x20 x3",
                    creased(torus(40, 20, true), Crease_method::chaikin,
                            Boundary_interpolation::edge_only),
                    0, 3});
  probes.push_back({"catmull-clark", "creased quad grid 30x20 x3",
                    creased(grid(30, 20, false), Crease_method::uniform,
                            Boundary_interpolation::none),
                    0, 3});
  for (const Probe& p : probes) {
    Subdivide_options o = options_for(p.scheme, p.levels, p.start_level);
    o.triangulate = p.triangulate;
    const Result<Size_prediction> predicted = predict_size(p.in, o);
    ASSERT_TRUE(predicted.ok());
    // The input buffers count: they live through the call.
    const std::size_t input = p.in.positions.size() * 8 +
                              p.in.face_sizes.size() * 4 +
                              p.in.face_indices.size() * 4;
    const std::size_t before = g_live;
    g_peak = before;
    std::size_t faces = 0;
    {
      const Result<Mesh_buffers> r = subdivide_mesh(p.in, o);
      ASSERT_TRUE(r.ok());
      faces = r.value.face_count();
    }
    const double measured = static_cast<double>(g_peak - before + input);
    const double model = static_cast<double>(predicted.value.peak_bytes);
    std::printf(
        "  %-14s %-26s %8zu faces: measured %9.0f B, model %9.0f B (%.2fx), "
        "%.0f B/face\n",
        p.scheme, p.mesh, faces, measured, model, model / measured,
        measured / faces);
    EXPECT_GE(model, measured) << p.scheme << " on " << p.mesh;
    EXPECT_LE(model, 1.5 * measured) << p.scheme << " on " << p.mesh;
  }
}

// A step for the viewer (level_view.h) builds the render arrays while the
// result and the input are alive: the model with render_buffers bounds it.
TEST(SubdivideMemory, ModelBoundsTheMeasuredPeakOfAViewedStep) {
  struct Probe {
    const char* scheme;
    const char* mesh;
    Mesh_buffers in;
  };
  const std::vector<Probe> probes = {
      {"catmull-clark", "quad torus 160x80", torus(160, 80, false)},
      {"loop", "tri torus 160x80", torus(160, 80, true)},
      {"loop", "tri grid 120x100", grid(120, 100, true)},
      {"doo-sabin", "quad grid 120x100", grid(120, 100, false)},
      {"sqrt3", "tri torus 160x80", torus(160, 80, true)},
      {"quad-triangle", "mixed torus 160x80", torus(160, 80, false, true)},
  };
  // The bindings copy each array out of the heap: a sink that keeps none.
  struct Discard : Render_sink {
    void floats(Render_array, const std::vector<float>&) override {}
    void indices(Render_array, const std::vector<std::uint32_t>&) override {}
  } discard;
  for (const Probe& p : probes) {
    Subdivide_options o = options_for(p.scheme, 1);
    Subdivide_options viewed = o;
    viewed.render_buffers = true;
    const Result<Size_prediction> plain = predict_size(p.in, o);
    const Result<Size_prediction> predicted = predict_size(p.in, viewed);
    ASSERT_TRUE(predicted.ok());
    EXPECT_GE(predicted.value.peak_bytes, plain.value.peak_bytes);
    const Mesh_facts facts = compute_facts(p.in).value;
    const std::size_t input = p.in.positions.size() * 8 +
                              p.in.face_sizes.size() * 4 +
                              p.in.face_indices.size() * 4;
    const std::size_t before = g_live;
    g_peak = before;
    std::size_t faces = 0;
    {
      Mesh_buffers out;
      const Result<Mesh_facts> r = view_step(p.in, o, facts, out, discard);
      ASSERT_TRUE(r.ok());
      faces = r.value.faces;
    }
    const double measured = static_cast<double>(g_peak - before + input);
    const double model = static_cast<double>(predicted.value.peak_bytes);
    std::printf(
        "  %-14s %-26s %8zu faces, viewed: measured %9.0f B, model %9.0f B "
        "(%.2fx, without the arrays %9.0f B), %.0f B/face\n",
        p.scheme, p.mesh, faces, measured, model, model / measured,
        static_cast<double>(plain.value.peak_bytes), measured / faces);
    EXPECT_GE(model, measured) << p.scheme << " on " << p.mesh;
    EXPECT_LE(model, 1.5 * measured) << p.scheme << " on " << p.mesh;
  }
}

}  // namespace
}  // namespace subdivlab
