// SubdivLab's creasing against OpenSubdiv 3.5 (Debian's libosd-dev), the
// reference for tagged meshes as CGAL is for the others: Catmull-Clark and
// Loop on meshes with creases, corners, holes and each border mode, levels
// 1-3, uniform and Chaikin creasing. Native only (OpenSubdiv is not built
// for WebAssembly; tests/unit/opensubdiv.test.ts holds the WASM core to the
// same points through osd_reference).
//
// Each level's vertices are matched through their origin (osd_harness.h).
// Through that map, points must agree to 1e-12 and the faces and holes must
// be the same sets.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "core/mesh_io.h"
#include "core/subdivide.h"
#include "osd_harness.h"

namespace {

using namespace OpenSubdiv;
using subdivlab::Boundary_interpolation;
using subdivlab::Crease_method;
using subdivlab::Mesh_buffers;
using subdivlab::osd::cycle;
using subdivlab::osd::Point;

Mesh_buffers subdivide(const Mesh_buffers& in, bool loop, int levels) {
  subdivlab::Subdivide_options options;
  options.scheme = loop ? "loop" : "catmull-clark";
  options.levels = levels;
  const auto result = subdivlab::subdivide_mesh(in, options);
  EXPECT_TRUE(result.ok()) << result.status.message;
  return result.value;
}

/// Vertex indices in the order of their positions.
std::vector<std::uint32_t> by_position(const Mesh_buffers& m) {
  std::vector<std::uint32_t> order(m.vertex_count());
  for (std::uint32_t v = 0; v < order.size(); ++v) order[v] = v;
  const auto key = [&](std::uint32_t v) {
    std::array<double, 3> k;
    for (int i = 0; i < 3; ++i) k[i] = std::round(m.positions[3 * v + i] * 1e9);
    return k;
  };
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return key(a) < key(b);
  });
  return order;
}

/// The same mesh, tags included, up to the numbering of its vertices and
/// faces (matched by position; the meshes here have no two vertices at
/// one place).
void expect_same_mesh(const Mesh_buffers& a, const Mesh_buffers& b) {
  ASSERT_EQ(a.vertex_count(), b.vertex_count());
  ASSERT_EQ(a.face_count(), b.face_count());
  const std::vector<std::uint32_t> oa = by_position(a), ob = by_position(b);
  std::vector<int> to_b(a.vertex_count());
  for (std::size_t i = 0; i < oa.size(); ++i) {
    to_b[oa[i]] = static_cast<int>(ob[i]);
    for (int k = 0; k < 3; ++k)
      ASSERT_NEAR(a.positions[3 * oa[i] + k], b.positions[3 * ob[i] + k],
                  1e-13 * std::max(1.0, std::fabs(b.positions[3 * ob[i] + k])));
  }
  const auto faces = [](const Mesh_buffers& m, const std::vector<int>& map,
                        bool holes) {
    std::set<std::uint32_t> hole_set(m.tags.holes.begin(), m.tags.holes.end());
    std::set<std::vector<int>> out;
    std::size_t o = 0;
    for (std::uint32_t f = 0; f < m.face_count(); ++f) {
      std::vector<int> face;
      for (std::uint32_t j = 0; j < m.face_sizes[f]; ++j)
        face.push_back(map.empty() ? static_cast<int>(m.face_indices[o + j])
                                   : map[m.face_indices[o + j]]);
      o += m.face_sizes[f];
      if (!holes || hole_set.count(f) != 0) out.insert(cycle(face));
    }
    return out;
  };
  EXPECT_EQ(faces(a, to_b, false), faces(b, {}, false));
  EXPECT_EQ(faces(a, to_b, true), faces(b, {}, true));
  const auto creases = [](const Mesh_buffers& m, const std::vector<int>& map) {
    std::set<std::tuple<int, int, float>> out;
    for (std::size_t i = 0; i < m.tags.crease_sharpness.size(); ++i) {
      int x = static_cast<int>(m.tags.crease_edges[2 * i]),
          y = static_cast<int>(m.tags.crease_edges[2 * i + 1]);
      if (!map.empty()) x = map[x], y = map[y];
      out.insert({std::min(x, y), std::max(x, y), m.tags.crease_sharpness[i]});
    }
    return out;
  };
  EXPECT_EQ(creases(a, to_b), creases(b, {}));
  EXPECT_EQ(a.tags.corner_sharpness.size(), b.tags.corner_sharpness.size());
}

/// Compares SubdivLab's level `levels` of `in` (one call, and one step at
/// a time through the tags each step writes) with OpenSubdiv's.
void expect_same_as_opensubdiv(const Mesh_buffers& in, bool loop,
                               int levels) {
  const subdivlab::osd::Run osd = subdivlab::osd::refine(in, loop, levels);
  ASSERT_TRUE(osd.refiner);
  // map[v]: OpenSubdiv's index of SubdivLab's vertex v at this level.
  std::vector<int> map(in.vertex_count());
  for (std::size_t v = 0; v < map.size(); ++v) map[v] = static_cast<int>(v);
  Mesh_buffers parent = in;
  for (int level = 1; level <= levels; ++level) {
    SCOPED_TRACE("level " + std::to_string(level));
    std::string error;
    const Mesh_buffers child = subdivlab::osd::step(parent, loop, error);
    ASSERT_EQ(error, "");
    const Far::TopologyLevel& cl = osd.refiner->GetLevel(level);
    ASSERT_EQ(child.vertex_count(), static_cast<std::size_t>(cl.GetNumVertices()));
    ASSERT_EQ(child.face_count(), static_cast<std::size_t>(cl.GetNumFaces()));
    const std::vector<int> child_map = subdivlab::osd::child_origins(
        osd, level - 1, parent, child, map, loop, error);
    ASSERT_EQ(error, "");
    // Points.
    const std::vector<Point>& expected = osd.points[level];
    for (std::size_t v = 0; v < child.vertex_count(); ++v) {
      const Point& q = expected[child_map[v]];
      const double want[3] = {q.x, q.y, q.z};
      for (int i = 0; i < 3; ++i)
        ASSERT_NEAR(child.positions[3 * v + i], want[i],
                    1e-12 * std::max(1.0, std::fabs(want[i])))
            << "vertex " << v << " (OpenSubdiv's " << child_map[v] << ")";
    }
    // Faces and holes, as sets of cycles in OpenSubdiv's numbering.
    std::set<std::vector<int>> ours, theirs, our_holes, their_holes;
    std::set<std::uint32_t> hole_set(child.tags.holes.begin(),
                                     child.tags.holes.end());
    std::size_t o = 0;
    for (std::uint32_t f = 0; f < child.face_count(); ++f) {
      std::vector<int> face;
      for (std::uint32_t j = 0; j < child.face_sizes[f]; ++j)
        face.push_back(child_map[child.face_indices[o + j]]);
      o += child.face_sizes[f];
      ours.insert(cycle(face));
      if (hole_set.count(f) != 0) our_holes.insert(cycle(face));
    }
    for (int f = 0; f < cl.GetNumFaces(); ++f) {
      const Far::ConstIndexArray fv = cl.GetFaceVertices(f);
      const std::vector<int> face = cycle({fv.begin(), fv.end()});
      theirs.insert(face);
      if (cl.IsFaceHole(f)) their_holes.insert(face);
    }
    EXPECT_EQ(ours, theirs);
    EXPECT_EQ(our_holes, their_holes);
    // The same level from one call of `level` steps: numbered otherwise
    // (a level read back from buffers numbers its edges anew), so matched
    // by position.
    expect_same_mesh(subdivide(in, loop, level), child);
    map = std::move(child_map);
    parent = child;
  }
}

// ---------------------------------------------------------------------------
// Meshes.

Mesh_buffers cube() {
  Mesh_buffers m;
  m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0,
                 0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1};
  m.face_sizes.assign(6, 4);
  m.face_indices = {0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4,
                    2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5};
  return m;
}

/// An n x n grid of unit quads in the plane z = 0 (open), slightly bent
/// so that its points are not all coplanar.
Mesh_buffers grid(std::uint32_t n) {
  Mesh_buffers m;
  for (std::uint32_t j = 0; j <= n; ++j)
    for (std::uint32_t i = 0; i <= n; ++i) {
      const double x = i, y = j;
      m.positions.insert(m.positions.end(), {x, y, 0.1 * x * y - 0.05 * x * x});
    }
  for (std::uint32_t j = 0; j < n; ++j)
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t a = j * (n + 1) + i;
      m.face_sizes.push_back(4);
      m.face_indices.insert(m.face_indices.end(),
                            {a, a + 1, a + n + 2, a + n + 1});
    }
  return m;
}

/// The same grid split into triangles (for Loop).
Mesh_buffers triangle_grid(std::uint32_t n) {
  const Mesh_buffers q = grid(n);
  Mesh_buffers m;
  m.positions = q.positions;
  for (std::size_t f = 0; f < q.face_count(); ++f) {
    const std::uint32_t* v = &q.face_indices[4 * f];
    m.face_sizes.insert(m.face_sizes.end(), {3, 3});
    m.face_indices.insert(m.face_indices.end(),
                          {v[0], v[1], v[2], v[0], v[2], v[3]});
  }
  return m;
}

/// A torus of n x m quads.
Mesh_buffers torus(std::uint32_t n, std::uint32_t k) {
  Mesh_buffers m;
  const double pi = 3.14159265358979323846;
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = 0; j < k; ++j) {
      const double u = 2 * pi * i / n, w = 2 * pi * j / k;
      const double r = 2 + 0.7 * std::cos(w);
      m.positions.insert(m.positions.end(),
                         {r * std::cos(u), r * std::sin(u), 0.7 * std::sin(w)});
    }
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = 0; j < k; ++j) {
      const std::uint32_t a = i * k + j, b = ((i + 1) % n) * k + j,
                          c = ((i + 1) % n) * k + (j + 1) % k,
                          d = i * k + (j + 1) % k;
      m.face_sizes.push_back(4);
      m.face_indices.insert(m.face_indices.end(), {a, b, c, d});
    }
  return m;
}

Mesh_buffers tetrahedron() {
  Mesh_buffers m;
  m.positions = {1, 1, 1, -1, -1, 1, -1, 1, -1, 1, -1, -1};
  m.face_sizes.assign(4, 3);
  m.face_indices = {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2};
  return m;
}

Mesh_buffers octahedron() {
  Mesh_buffers m;
  m.positions = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
  m.face_sizes.assign(8, 3);
  m.face_indices = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4,
                    2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
  return m;
}

void crease(Mesh_buffers& m, std::uint32_t a, std::uint32_t b, float s) {
  m.tags.crease_edges.insert(m.tags.crease_edges.end(), {a, b});
  m.tags.crease_sharpness.push_back(s);
}

void corner(Mesh_buffers& m, std::uint32_t v, float s) {
  m.tags.corner_vertices.push_back(v);
  m.tags.corner_sharpness.push_back(s);
}

struct Method_case : ::testing::TestWithParam<Crease_method> {
  Mesh_buffers with_method(Mesh_buffers m) const {
    m.tags.crease_method = GetParam();
    return m;
  }
};

// A cube with a loop of sharpness 2 around its bottom face, a fractional
// edge (0.5) and an infinitely sharp one (10): crease and corner vertices,
// decay to smooth, a transition at 1.
TEST_P(Method_case, CatmullClarkCreasedCube) {
  Mesh_buffers m = cube();
  crease(m, 0, 2, 2.0f);
  crease(m, 2, 3, 2.0f);
  crease(m, 3, 1, 2.0f);
  crease(m, 1, 0, 2.0f);
  crease(m, 4, 5, 0.5f);
  crease(m, 6, 7, 10.0f);
  expect_same_as_opensubdiv(with_method(m), false, 3);
}

// One sharp edge of sharpness 1.5 on a cube: both its ends are darts.
TEST_P(Method_case, CatmullClarkDart) {
  Mesh_buffers m = cube();
  crease(m, 4, 5, 1.5f);
  expect_same_as_opensubdiv(with_method(m), false, 3);
}

// A chain of edges of sharpness 1, 2, 3 and 4 around a face: Chaikin
// blends each with its neighbours along the chain.
TEST_P(Method_case, CatmullClarkCreaseChainOfMixedSharpness) {
  Mesh_buffers m = cube();
  crease(m, 4, 5, 1.0f);
  crease(m, 5, 7, 2.0f);
  crease(m, 7, 6, 3.0f);
  crease(m, 6, 4, 4.0f);
  crease(m, 0, 4, 2.5f);
  expect_same_as_opensubdiv(with_method(m), false, 3);
}

// Sharpness 1.25 beside 0.25 along a chain: Chaikin takes the 1.25 to
// nothing in one step (its neighbour pulls it down), where uniform
// creasing leaves 0.25 of it: a transition from above 1.
TEST_P(Method_case, CatmullClarkChainDecayingFromAboveOne) {
  Mesh_buffers m = cube();
  crease(m, 4, 5, 1.25f);
  crease(m, 5, 7, 0.25f);
  crease(m, 7, 6, 0.25f);
  expect_same_as_opensubdiv(with_method(m), false, 3);
}

// Semi-sharp corners: 1.5 on a cube vertex, 2.25 on a vertex that is also
// on a crease.
TEST_P(Method_case, CatmullClarkCornersOnACube) {
  Mesh_buffers m = cube();
  corner(m, 7, 1.5f);
  corner(m, 0, 2.25f);
  crease(m, 0, 1, 1.25f);
  crease(m, 0, 2, 0.75f);
  expect_same_as_opensubdiv(with_method(m), false, 3);
}

// A torus with two holes next to each other and a crease ring.
TEST_P(Method_case, CatmullClarkHoledTorus) {
  Mesh_buffers m = torus(8, 6);
  m.tags.holes = {3, 4};
  for (std::uint32_t i = 0; i < 8; ++i)
    crease(m, i * 6, ((i + 1) % 8) * 6, 2.5f);
  expect_same_as_opensubdiv(with_method(m), false, 3);
}

// A quad patch with a pinned interior corner and a crease to the border,
// in each border mode.
TEST_P(Method_case, CatmullClarkQuadPatchInEachBorderMode) {
  for (Boundary_interpolation mode :
       {Boundary_interpolation::edge_only,
        Boundary_interpolation::edge_and_corner, Boundary_interpolation::none}) {
    SCOPED_TRACE("boundary mode " + std::to_string(static_cast<int>(mode)));
    Mesh_buffers m = grid(4);
    corner(m, 6, 1.5f);
    crease(m, 12, 13, 2.0f);
    crease(m, 13, 14, 2.0f);
    // Border edges infinitely sharp by tag: with the border mode none,
    // the faces along them are kept (their other border vertices aside).
    crease(m, 0, 1, 10.0f);
    crease(m, 1, 2, 10.0f);
    crease(m, 2, 3, 10.0f);
    crease(m, 3, 4, 10.0f);
    m.tags.boundary = mode;
    expect_same_as_opensubdiv(with_method(m), false, 3);
  }
}

// Loop on a tetrahedron with one sharp edge of sharpness 1.5.
TEST_P(Method_case, LoopTetrahedronWithASharpEdge) {
  Mesh_buffers m = tetrahedron();
  crease(m, 0, 1, 1.5f);
  expect_same_as_opensubdiv(with_method(m), true, 3);
}

// Loop on an octahedron: a crease ring around its equator of mixed
// sharpness, a corner, a hole.
TEST_P(Method_case, LoopOctahedronCreaseRing) {
  Mesh_buffers m = octahedron();
  crease(m, 0, 2, 2.25f);
  crease(m, 2, 1, 1.25f);
  crease(m, 1, 3, 3.0f);
  crease(m, 3, 0, 0.5f);
  corner(m, 4, 2.0f);
  m.tags.holes = {6};
  expect_same_as_opensubdiv(with_method(m), true, 3);
}

// Loop on an open triangle grid in each border mode, with a crease.
TEST_P(Method_case, LoopTriangleGridInEachBorderMode) {
  for (Boundary_interpolation mode :
       {Boundary_interpolation::edge_only,
        Boundary_interpolation::edge_and_corner, Boundary_interpolation::none}) {
    SCOPED_TRACE("boundary mode " + std::to_string(static_cast<int>(mode)));
    Mesh_buffers m = triangle_grid(4);
    crease(m, 6, 12, 1.5f);
    crease(m, 12, 18, 2.0f);
    m.tags.boundary = mode;
    expect_same_as_opensubdiv(with_method(m), true, 3);
  }
}

INSTANTIATE_TEST_SUITE_P(Creasing, Method_case,
                         ::testing::Values(Crease_method::uniform,
                                           Crease_method::chaikin),
                         [](const auto& info) {
                           return info.param == Crease_method::uniform
                                      ? std::string("Uniform")
                                      : std::string("Chaikin");
                         });

// Untagged meshes: OpenSubdiv's edge-only border mode is CGAL's border
// rule (SubdivLab's untagged result, CGAL's), including at the corners of
// a quad patch (one face, two border edges: the crease rule on both).
TEST(OpenSubdivAndCgal, AgreeOnUntaggedMeshesWithTheEdgeOnlyBorder) {
  expect_same_as_opensubdiv(grid(3), false, 2);
  expect_same_as_opensubdiv(triangle_grid(3), true, 2);
  expect_same_as_opensubdiv(torus(6, 5), false, 2);
  expect_same_as_opensubdiv(octahedron(), true, 2);
}

std::string file_text(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << "cannot read " << path;
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The app's crease-editing test (tests/e2e/crease-editing.spec.ts) sets
// edge 1-5 of the Creased cube sample to sharpness 2, subdivides twice and
// compares the level-0 vertices' level-2 points with the values in
// tests/fixtures/crease-edit.osd.txt. Those values are OpenSubdiv's: checked
// here against Far, and SubdivLab's core against both.
TEST(OpenSubdivReference, CreaseEditOfTheCreasedCubeSample) {
  auto read = subdivlab::read_mesh(
      file_text(ROOT_DIR "/public/meshes/cube-creased.obj"),
      subdivlab::Mesh_format::obj);
  ASSERT_TRUE(read.ok()) << read.status.message;
  Mesh_buffers m = read.value;
  crease(m, 1, 5, 2.0f);
  const subdivlab::osd::Run osd = subdivlab::osd::refine(m, false, 2);
  const Mesh_buffers ours = subdivide(m, false, 2);
  std::istringstream reference(
      file_text(ROOT_DIR "/tests/fixtures/crease-edit.osd.txt"));
  std::string line;
  int rows = 0;
  while (std::getline(reference, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream row(line);
    int v = -1;
    double want[3];
    ASSERT_TRUE(row >> v >> want[0] >> want[1] >> want[2]) << line;
    const Far::Index c1 = osd.refiner->GetLevel(0).GetVertexChildVertex(v);
    const Point& q =
        osd.points[2][osd.refiner->GetLevel(1).GetVertexChildVertex(c1)];
    const double theirs[3] = {q.x, q.y, q.z};
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(theirs[i], want[i], 1e-12) << "vertex " << v;
      EXPECT_NEAR(ours.positions[3 * v + i], want[i], 1e-12) << "vertex " << v;
    }
    ++rows;
  }
  EXPECT_EQ(rows, 8);
}

}  // namespace
