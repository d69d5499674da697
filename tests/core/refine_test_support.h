// What the fast hosts' tests (test_refine*.cpp) share: the meshes they run
// on, and the comparisons of a fast result with CGAL's route, table by
// table (a level against the Surface_mesh CGAL's host made) and buffer by
// buffer (subdivide_mesh's two routes).
#pragma once

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_type_config.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/mesh_build.h"
#include "core/mesh_io.h"
#include "core/mesh_types.h"
#include "refine/refine_level.h"

namespace subdivlab {
namespace refine_test {

inline Mesh_buffers read_off(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in.good()) << path << " missing: run node scripts/setup.mjs";
  std::stringstream ss;
  ss << in.rdbuf();
  const Result<Mesh_buffers> r = read_mesh(ss.str(), Mesh_format::off);
  EXPECT_TRUE(r.ok()) << path << ": " << r.status.message;
  return r.value;
}

/// tests/fixtures/`name`.
inline Mesh_buffers fixture(const std::string& name) {
  return read_off(std::string(FIXTURES_DIR) + "/" + name);
}

/// One of CGAL's meshes (set-up extracts them into public/meshes/cgal).
inline Mesh_buffers cgal_mesh(const std::string& name) {
  return read_off(std::string(FIXTURES_DIR) + "/../../public/meshes/cgal/" +
                  name);
}

/// Every fixture a valid mesh is in: closed and open, triangles, quads and
/// both.
inline const char* const kFixtures[] = {
    "cube.off",        "tetrahedron.off",         "octahedron.off",
    "icosahedron.off", "rhombicuboctahedron.off", "torus-quad.off",
    "torus-tri.off",   "two-tetrahedra.off",      "disk-tri.off",
    "grid-open.off",   "mixed-open.off"};

/// CGAL's meshes: open with holes, closed with high valences, quads.
inline const char* const kCgalMeshes[] = {"holes.off", "fandisk.off",
                                          "mannequin-devil.off",
                                          "cube_quad.off", "torus_quad.off"};

/// A triangle and a quad sharing two edges at a two-valent vertex (0):
/// quad-triangle refines it, where it refuses two triangles so joined.
inline Mesh_buffers two_valent_triangle_and_quad() {
  Mesh_buffers mixed;
  mixed.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 1};
  mixed.face_sizes = {3, 4};
  mixed.face_indices = {0, 1, 2, 1, 0, 2, 3};
  return mixed;
}

/// Two quads sharing all four edges: every vertex is two-valent.
inline Mesh_buffers two_valent_quads() {
  Mesh_buffers quads;
  quads.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  quads.face_sizes = {4, 4};
  quads.face_indices = {0, 1, 2, 3, 0, 3, 2, 1};
  return quads;
}

/// A pentagonal prism: two pentagons (the first the bottom), five quads.
inline Mesh_buffers pentagonal_prism() {
  Mesh_buffers prism;
  for (int i = 0; i < 5; ++i) {
    const double a = 2 * CGAL_PI * i / 5;
    for (double z : {0.0, 1.0}) {
      prism.positions.push_back(std::cos(a));
      prism.positions.push_back(std::sin(a));
      prism.positions.push_back(z);
    }
  }
  prism.face_sizes = {5, 5, 4, 4, 4, 4, 4};
  prism.face_indices = {8, 6, 4, 2, 0, 1, 3, 5, 7, 9};
  for (std::uint32_t i = 0; i < 5; ++i) {
    const std::uint32_t j = (i + 1) % 5;
    for (std::uint32_t v : {2 * i, 2 * j, 2 * j + 1, 2 * i + 1})
      prism.face_indices.push_back(v);
  }
  return prism;
}

/// The largest coordinate: the scale of the 1e-12 tolerance.
inline double size_of(const std::vector<double>& p) {
  double s = 0;
  for (double x : p) s = std::max(s, std::abs(x));
  return s;
}

/// `level` is the Surface_mesh `reference` (no garbage) table by table:
/// counts, border edges, each face's corners from halfedge(f) (vertices and
/// halfedges), every halfedge's target and face corner, and the points to
/// 1e-12 of the mesh's size.
inline void expect_same_tables(const refine::Level& level,
                               const Mesh& reference, const std::string& at) {
  ASSERT_EQ(level.vertex_count, reference.number_of_vertices()) << at;
  ASSERT_EQ(level.edge_count, reference.number_of_edges()) << at;
  ASSERT_EQ(level.face_count, reference.number_of_faces()) << at;
  std::uint32_t border_edges = 0;
  for (Mesh::Edge_index e : reference.edges())
    border_edges += reference.is_border(e) ? 1 : 0;
  ASSERT_EQ(level.border_edge_count, border_edges) << at;
  for (Mesh::Face_index f : reference.faces()) {
    std::uint32_t i = level.face_begin(f.idx());
    ASSERT_EQ(level.face_end(f.idx()) - i, reference.degree(f))
        << at << ", face " << f;
    for (Mesh::Halfedge_index h :
         CGAL::halfedges_around_face(reference.halfedge(f), reference)) {
      ASSERT_EQ(level.face_halfedges[i], h.idx()) << at << ", face " << f;
      ASSERT_EQ(level.face_vertices[i], reference.target(h).idx())
          << at << ", face " << f;
      ++i;
    }
  }
  for (Mesh::Halfedge_index h : reference.halfedges()) {
    ASSERT_EQ(level.halfedge_target[h.idx()], reference.target(h).idx())
        << at << ", halfedge " << h.idx();
    if (reference.is_border(h))
      ASSERT_EQ(level.halfedge_corner[h.idx()], refine::kNone) << at;
    else
      ASSERT_EQ(level.face_halfedges[level.halfedge_corner[h.idx()]], h.idx())
          << at;
  }
  const Mesh_buffers expected = to_buffers(reference);
  const double tol = 1e-12 * size_of(expected.positions);
  ASSERT_EQ(level.positions.size(), expected.positions.size()) << at;
  for (std::size_t i = 0; i < expected.positions.size(); ++i)
    ASSERT_NEAR(level.positions[i], expected.positions[i], tol)
        << at << ", vertex " << i / 3;
}

/// A fast result equals CGAL's route's: faces, points (1e-12 of the mesh's
/// size) and control edges (as sets of pairs).
inline void expect_same_buffers(const Mesh_buffers& fast,
                                const Mesh_buffers& cgal,
                                const std::string& what) {
  ASSERT_EQ(fast.face_sizes, cgal.face_sizes) << what;
  ASSERT_EQ(fast.face_indices, cgal.face_indices) << what;
  ASSERT_EQ(fast.positions.size(), cgal.positions.size()) << what;
  const double tol = 1e-12 * size_of(cgal.positions);
  for (std::size_t i = 0; i < cgal.positions.size(); ++i)
    ASSERT_NEAR(fast.positions[i], cgal.positions[i], tol)
        << what << ", vertex " << i / 3;
  auto pairs = [](const std::vector<std::uint32_t>& e) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> p;
    for (std::size_t i = 0; i + 1 < e.size(); i += 2)
      p.emplace_back(std::min(e[i], e[i + 1]), std::max(e[i], e[i + 1]));
    std::sort(p.begin(), p.end());
    return p;
  };
  EXPECT_EQ(pairs(fast.control_edges), pairs(cgal.control_edges)) << what;
}

}  // namespace refine_test
}  // namespace subdivlab
