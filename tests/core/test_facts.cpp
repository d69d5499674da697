// compute_facts: exact counts and topology on the fixtures, whose numbers
// are known from their construction (tests/fixtures/make_fixtures.py).

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "core/mesh_build.h"
#include "core/mesh_facts.h"
#include "core/mesh_io.h"

namespace subdivlab {
namespace {

Mesh_buffers load(const std::string& name) {
  std::ifstream in(std::string(FIXTURES_DIR) + "/" + name, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  const Result<Mesh_buffers> r = read_mesh(
      s.str(), name.size() > 4 && name.substr(name.size() - 4) == ".obj"
                   ? Mesh_format::obj
                   : Mesh_format::off);
  EXPECT_TRUE(r.ok()) << name << ": " << r.status.message;
  return r.value;
}

Mesh_facts facts_of(const std::string& name) {
  const Result<Mesh_facts> r = compute_facts(load(name));
  EXPECT_TRUE(r.ok()) << name << ": " << r.status.message;
  return r.value;
}

struct Topology {
  std::size_t v, e, f, components, boundaries;
  long chi, genus;
  bool closed;
  std::size_t triangles, quads, other;
};

void expect_topology(const std::string& name, const Topology& t) {
  const Mesh_facts f = facts_of(name);
  EXPECT_EQ(f.vertices, t.v) << name;
  EXPECT_EQ(f.edges, t.e) << name;
  EXPECT_EQ(f.faces, t.f) << name;
  EXPECT_EQ(f.components, t.components) << name;
  EXPECT_EQ(f.boundaries, t.boundaries) << name;
  EXPECT_EQ(f.euler_characteristic, t.chi) << name;
  EXPECT_EQ(f.genus, t.genus) << name;
  EXPECT_EQ(f.closed, t.closed) << name;
  EXPECT_EQ(f.triangles, t.triangles) << name;
  EXPECT_EQ(f.quads, t.quads) << name;
  EXPECT_EQ(f.other_faces, t.other) << name;
  EXPECT_EQ(f.control_edges, 0u) << name;
}

TEST(FactsFixtures, Cube) {
  expect_topology("cube.off", {8, 12, 6, 1, 0, 2, 0, true, 0, 6, 0});
  expect_topology("cube.obj", {8, 12, 6, 1, 0, 2, 0, true, 0, 6, 0});
}

TEST(FactsFixtures, PlatonicSolids) {
  expect_topology("tetrahedron.off", {4, 6, 4, 1, 0, 2, 0, true, 4, 0, 0});
  expect_topology("octahedron.off", {6, 12, 8, 1, 0, 2, 0, true, 8, 0, 0});
  expect_topology("icosahedron.off", {12, 30, 20, 1, 0, 2, 0, true, 20, 0, 0});
}

TEST(FactsFixtures, Rhombicuboctahedron) {
  expect_topology("rhombicuboctahedron.off",
                  {24, 48, 26, 1, 0, 2, 0, true, 8, 18, 0});
}

TEST(FactsFixtures, ToriHaveGenusOne) {
  expect_topology("torus-quad.off", {48, 96, 48, 1, 0, 0, 1, true, 0, 48, 0});
  expect_topology("torus-tri.off", {48, 144, 96, 1, 0, 0, 1, true, 96, 0, 0});
}

TEST(FactsFixtures, OpenMeshesHaveOneBoundary) {
  expect_topology("grid-open.off", {16, 24, 9, 1, 1, 1, 0, false, 0, 9, 0});
  expect_topology("disk-tri.off", {7, 12, 6, 1, 1, 1, 0, false, 6, 0, 0});
  expect_topology("mixed-open.off", {13, 21, 9, 1, 1, 1, 0, false, 6, 2, 1});
}

TEST(FactsFixtures, TwoTetrahedraAreTwoComponents) {
  expect_topology("two-tetrahedra.off", {8, 12, 8, 2, 0, 4, 0, true, 8, 0, 0});
}

TEST(FactsFixtures, BoundingBoxes) {
  const Mesh_facts cube = facts_of("cube.off");
  EXPECT_EQ(cube.bbox_min, (std::array<double, 3>{-1, -1, -1}));
  EXPECT_EQ(cube.bbox_max, (std::array<double, 3>{1, 1, 1}));
  const Mesh_facts grid = facts_of("grid-open.off");
  EXPECT_EQ(grid.bbox_min, (std::array<double, 3>{0, 0, 0}));
  EXPECT_EQ(grid.bbox_max, (std::array<double, 3>{3, 3, 0}));
  const Mesh_facts two = facts_of("two-tetrahedra.off");
  EXPECT_EQ(two.bbox_min, (std::array<double, 3>{-1, -1, -1}));
  EXPECT_EQ(two.bbox_max, (std::array<double, 3>{4, 1, 1}));
  // Torus: outer radius R + r = 2.75 reached at u = 0 (x) exactly; z = +-r
  // only where sin(w) = +-1, which a 6-step tube does not sample.
  const Mesh_facts torus = facts_of("torus-quad.off");
  EXPECT_DOUBLE_EQ(torus.bbox_max[0], 2.75);
  EXPECT_DOUBLE_EQ(torus.bbox_min[0], -2.75);
  EXPECT_DOUBLE_EQ(torus.bbox_max[2], 0.75 * std::sin(M_PI / 3));
}

TEST(FactsBuffers, AnnulusHasTwoBoundaries) {
  // The 3 x 3 grid without its centre quad: an annulus, chi = 0.
  Mesh_buffers grid = load("grid-open.off");
  Mesh_buffers ring;
  ring.positions = grid.positions;
  for (std::size_t f = 0; f < grid.face_count(); ++f) {
    if (f == 4) continue;
    ring.face_sizes.push_back(4);
    ring.face_indices.insert(ring.face_indices.end(),
                             grid.face_indices.begin() + 4 * f,
                             grid.face_indices.begin() + 4 * f + 4);
  }
  const Result<Mesh_facts> r = compute_facts(ring);
  ASSERT_TRUE(r.ok()) << r.status.message;
  EXPECT_EQ(r.value.vertices, 16u);
  EXPECT_EQ(r.value.edges, 24u);
  EXPECT_EQ(r.value.faces, 8u);
  EXPECT_EQ(r.value.boundaries, 2u);
  EXPECT_EQ(r.value.euler_characteristic, 0);
  EXPECT_EQ(r.value.genus, 0);
  EXPECT_FALSE(r.value.closed);
}

TEST(FactsBuffers, OpenedCubeAndMixedComponents) {
  // A cube without its first face (a box) next to a closed tetrahedron.
  Mesh_buffers cube = load("cube.off");
  Mesh_buffers tet = load("tetrahedron.off");
  Mesh_buffers m;
  m.positions = cube.positions;
  for (std::size_t i = 0; i < tet.positions.size(); ++i)
    m.positions.push_back(tet.positions[i] + (i % 3 == 0 ? 5 : 0));
  m.face_sizes.assign(cube.face_sizes.begin() + 1, cube.face_sizes.end());
  m.face_indices.assign(cube.face_indices.begin() + 4, cube.face_indices.end());
  for (auto s : tet.face_sizes) m.face_sizes.push_back(s);
  for (auto v : tet.face_indices) m.face_indices.push_back(v + 8);
  const Result<Mesh_facts> r = compute_facts(m);
  ASSERT_TRUE(r.ok()) << r.status.message;
  EXPECT_EQ(r.value.vertices, 12u);
  EXPECT_EQ(r.value.edges, 18u);
  EXPECT_EQ(r.value.faces, 9u);
  EXPECT_EQ(r.value.components, 2u);
  EXPECT_EQ(r.value.boundaries, 1u);
  EXPECT_EQ(r.value.euler_characteristic, 3);  // box 1 + tetrahedron 2
  EXPECT_EQ(r.value.genus, 0);
  EXPECT_EQ(r.value.quads, 5u);
  EXPECT_EQ(r.value.triangles, 4u);
  EXPECT_FALSE(r.value.closed);
}

TEST(FactsBuffers, CountsControlEdgePairs) {
  Mesh_buffers m = load("cube.off");
  m.control_edges = {0, 1, 1, 3, 3, 2};
  const Result<Mesh_facts> r = compute_facts(m);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.value.control_edges, 3u);
}

TEST(FactsBuffers, IsolatedVerticesAreNotCounted) {
  Mesh_buffers m = load("tetrahedron.off");
  m.positions.insert(m.positions.end(), {10, 10, 10});
  const Result<Mesh_facts> r = compute_facts(m);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.value.vertices, 4u);
  EXPECT_EQ(r.value.components, 1u);
  EXPECT_EQ(r.value.bbox_max, (std::array<double, 3>{1, 1, 1}));
}

TEST(FactsBuffers, InvalidBuffersFailAsBuildMeshDoes) {
  Mesh_buffers m = load("cube.off");
  m.face_indices[0] = 40;
  const Result<Mesh_facts> r = compute_facts(m);
  EXPECT_EQ(r.status.code, Status_code::invalid_mesh);
  EXPECT_EQ(r.status.message,
            "face 0: vertex index 40 is out of range (8 vertices)");
}

TEST(FactsMesh, EmptyMeshHasZeroFacts) {
  const Mesh_facts f = compute_facts(Mesh{});
  EXPECT_EQ(f.vertices, 0u);
  EXPECT_EQ(f.faces, 0u);
  EXPECT_EQ(f.components, 0u);
  EXPECT_EQ(f.bbox_min, (std::array<double, 3>{0, 0, 0}));
  EXPECT_EQ(f.bbox_max, (std::array<double, 3>{0, 0, 0}));
}

TEST(FactsMesh, SameFactsFromMeshAndFromBuffers) {
  Mesh mesh;
  ASSERT_TRUE(build_mesh(load("mixed-open.off"), mesh).ok());
  const Mesh_facts a = compute_facts(mesh);
  const Mesh_facts b = facts_of("mixed-open.off");
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_EQ(a.boundaries, b.boundaries);
  EXPECT_EQ(a.other_faces, 1u);
  EXPECT_EQ(a.bbox_max, (std::array<double, 3>{3, 2.25, 0}));
}

}  // namespace
}  // namespace subdivlab
