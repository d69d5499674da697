// The fast sqrt(3) host (wasm/src/refine/sqrt3_host) against CGAL's
// Sqrt3_1step: the same numbering of vertices, edges and faces, the same
// face corners in the same order, the same halfedges, and the same points to
// 1e-12 of the mesh's size, at levels 1-3 from either border parity, on
// every fixture, closed and open.

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

namespace subdivlab {
namespace {

namespace SMI = CGAL::Subdivision_method_3::internal;

Mesh_buffers read_off(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in.good()) << path << " missing: run node scripts/setup.mjs";
  std::stringstream ss;
  ss << in.rdbuf();
  const Result<Mesh_buffers> r = read_mesh(ss.str(), Mesh_format::off);
  EXPECT_TRUE(r.ok()) << path << ": " << r.status.message;
  return r.value;
}

Mesh_buffers fixture(const std::string& name) {
  return read_off(std::string(FIXTURES_DIR) + "/" + name);
}

Mesh triangulated(const Mesh_buffers& in) {
  Mesh m;
  EXPECT_TRUE(build_mesh(in, m).ok());
  CGAL::Polygon_mesh_processing::triangulate_faces(m);
  m.collect_garbage();
  return m;
}

double size_of(const std::vector<double>& p) {
  double s = 0;
  for (double x : p) s = std::max(s, std::abs(x));
  return s;
}

const char* const kFixtures[] = {
    "cube.off",        "tetrahedron.off",         "octahedron.off",
    "icosahedron.off", "rhombicuboctahedron.off", "torus-quad.off",
    "torus-tri.off",   "two-tetrahedra.off",      "disk-tri.off",
    "grid-open.off",   "mixed-open.off"};

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
    ASSERT_EQ(level.vertex_count, reference.number_of_vertices()) << at;
    ASSERT_EQ(level.edge_count, reference.number_of_edges()) << at;
    ASSERT_EQ(level.face_count, reference.number_of_faces()) << at;
    std::uint32_t border_edges = 0;
    for (Mesh::Edge_index e : reference.edges())
      border_edges += reference.is_border(e) ? 1 : 0;
    ASSERT_EQ(level.border_edge_count, border_edges) << at;
    for (Mesh::Face_index f : reference.faces()) {
      std::uint32_t i = 3 * f.idx();
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
    for (std::size_t i = 0; i < expected.positions.size(); ++i)
      ASSERT_NEAR(level.positions[i], expected.positions[i], tol)
          << at << ", vertex " << i / 3;
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

}  // namespace
}  // namespace subdivlab
