// CGAL's geometry around a mesh (core/inspect.h) against closed forms:
// self-intersection pairs of meshes built to cross (and of meshes whose
// faces only meet at shared edges), the smallest enclosing sphere, the
// convex hull and the minimum width of a cube and of a regular simplex.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "core/inspect.h"
#include "core/subdivide.h"
#include "refine_test_support.h"

namespace subdivlab {
namespace {

Inspect_options everything() {
  Inspect_options o;
  o.self_intersections = o.sphere = o.hull = o.width = true;
  return o;
}

Inspection inspect(const Mesh_buffers& mesh,
                   const Inspect_options& o = everything()) {
  const Result<Inspection> r = inspect_mesh(mesh, o);
  EXPECT_TRUE(r.ok()) << r.status.message;
  return r.value;
}

TEST(Inspect, StellaOctangulaCrossesTwelvePairs) {
  // Each face of one tetrahedron crosses three faces of the other (along
  // the edges of the octahedron they share); the parallel fourth it misses.
  const Inspection i = inspect(refine_test::fixture("stella-octangula.off"));
  EXPECT_EQ(i.self_intersections.pairs, 12u);
  EXPECT_EQ(i.self_intersections.faces.size(), 8u);
  ASSERT_EQ(i.self_intersections.first_pairs.size(), 24u);
  for (std::size_t k = 0; k < 24; k += 2) {
    // A face of the first tetrahedron (0-3) with one of the second (4-7).
    EXPECT_LT(i.self_intersections.first_pairs[k], 4u);
    EXPECT_GE(i.self_intersections.first_pairs[k + 1], 4u);
  }
  Inspect_options few = everything();
  few.max_pairs = 5;
  const Inspection first =
      inspect(refine_test::fixture("stella-octangula.off"), few);
  EXPECT_EQ(first.self_intersections.pairs, 12u);
  EXPECT_EQ(first.self_intersections.first_pairs.size(), 10u);
}

TEST(Inspect, CrossingSquaresArePairsOfFacesNotOfTriangles) {
  // The two squares cross along the x axis: one pair of faces, although
  // four pairs of their triangles meet.
  const Inspection i = inspect(refine_test::fixture("crossing-squares.off"));
  EXPECT_EQ(i.self_intersections.pairs, 1u);
  EXPECT_EQ(i.self_intersections.first_pairs,
            (std::vector<std::uint32_t>{0, 1}));
}

TEST(Inspect, FacesMeetingAtEdgesAndVerticesDoNotCount) {
  for (const char* name : {"cube.off", "icosahedron.off", "torus-tri.off",
                           "mixed-open.off", "two-tetrahedra.off"}) {
    EXPECT_EQ(inspect(refine_test::fixture(name)).self_intersections.pairs, 0u)
        << name;
  }
  // Nor do Catmull-Clark's level 2 of the cube, and Loop's of the torus.
  Subdivide_options o;
  o.levels = 2;
  EXPECT_EQ(inspect(subdivide_mesh(refine_test::fixture("cube.off"), o).value)
                .self_intersections.pairs,
            0u);
}

TEST(Inspect, CubeAgainstClosedForms) {
  // The cube [-1, 1]^3 with two points inside it (unused by faces: the
  // hull and sphere take every point).
  Mesh_buffers cube = refine_test::fixture("cube.off");
  cube.positions.insert(cube.positions.end(), {0.25, 0.5, -0.5, 0, 0, 0});
  const Inspection i = inspect(cube);
  EXPECT_NEAR(i.sphere.radius, std::sqrt(3.0), 1e-12);
  for (double c : i.sphere.center) EXPECT_NEAR(c, 0, 1e-12);
  // convex_hull_3 builds a triangulated hull: 8 vertices, 12 triangles.
  EXPECT_EQ(i.hull.vertices, 8u);
  EXPECT_EQ(i.hull.edges, 18u);
  EXPECT_EQ(i.hull.faces, 12u);
  EXPECT_NEAR(i.hull.area, 24, 1e-12);
  EXPECT_NEAR(i.hull.volume, 8, 1e-12);
  EXPECT_EQ(i.hull.triangles.size(), 36u);
  EXPECT_NEAR(i.width.width, 2, 1e-12);
  // Planes normal to an axis, at -1 and 1 along it.
  int axis = 0;
  for (int k = 0; k < 3; ++k)
    if (std::abs(i.width.normal[k]) > 0.5) axis = k;
  EXPECT_NEAR(std::abs(i.width.normal[axis]), 1, 1e-12);
  EXPECT_NEAR(std::abs(i.width.offsets[0] - i.width.offsets[1]), 2, 1e-12);
  EXPECT_NEAR(std::abs(i.width.offsets[0] + i.width.offsets[1]), 0, 1e-12);
  EXPECT_FALSE(i.width.skipped);
  // The mesh itself: 6 faces of area 4, volume 8, the box [-1, 1]^3.
  EXPECT_NEAR(i.measures.area, 24, 1e-12);
  EXPECT_TRUE(i.measures.closed);
  EXPECT_NEAR(i.measures.volume, 8, 1e-12);
  EXPECT_NEAR(i.measures.diagonal, 2 * std::sqrt(3.0), 1e-12);
  EXPECT_EQ(i.measures.bbox_min, (std::array<double, 3>{-1, -1, -1}));
  EXPECT_EQ(i.measures.bbox_max, (std::array<double, 3>{1, 1, 1}));
}

TEST(Inspect, RegularSimplexAgainstClosedForms) {
  // Vertices (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1): edge a = 2 sqrt 2,
  // circumradius sqrt 3 about the origin, width a / sqrt 2 = 2 (between
  // two opposite edges), area sqrt 3 a^2 = 8 sqrt 3, volume a^3 / (6 sqrt
  // 2) = 8 / 3.
  const Inspection i = inspect(refine_test::fixture("tetrahedron.off"));
  EXPECT_NEAR(i.sphere.radius, std::sqrt(3.0), 1e-12);
  for (double c : i.sphere.center) EXPECT_NEAR(c, 0, 1e-12);
  EXPECT_NEAR(i.width.width, 2, 1e-12);
  // The planes are normal to a coordinate axis (opposite edges (1,1,1)-
  // (1,-1,-1) and (-1,1,-1)-(-1,-1,1) lie in x = 1 and x = -1).
  double largest = 0;
  for (double n : i.width.normal) largest = std::max(largest, std::abs(n));
  EXPECT_NEAR(largest, 1, 1e-12);
  EXPECT_EQ(i.hull.vertices, 4u);
  EXPECT_EQ(i.hull.faces, 4u);
  EXPECT_NEAR(i.hull.area, 8 * std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(i.hull.volume, 8.0 / 3, 1e-12);
  EXPECT_NEAR(i.measures.volume, 8.0 / 3, 1e-12);
  EXPECT_EQ(i.self_intersections.pairs, 0u);
}

TEST(Inspect, FlatMeshHasNoWidthNorVolume) {
  const Inspection i = inspect(refine_test::fixture("grid-open.off"));
  EXPECT_FALSE(i.measures.closed);
  EXPECT_EQ(i.measures.volume, 0);
  EXPECT_NEAR(i.measures.area, 9, 1e-12);
  EXPECT_EQ(i.width.width, 0);
  EXPECT_NEAR(std::abs(i.width.normal[2]), 1, 1e-12);
  EXPECT_EQ(i.hull.volume, 0);
  EXPECT_NEAR(i.sphere.radius, 1.5 * std::sqrt(2.0), 1e-12);
}

TEST(Inspect, WidthIsSkippedAboveItsLimit) {
  Inspect_options o;
  o.width = true;
  o.max_width_vertices = 7;
  const Inspection i = inspect(refine_test::fixture("cube.off"), o);
  EXPECT_TRUE(i.has_width);
  EXPECT_TRUE(i.width.skipped);
  EXPECT_FALSE(i.has_sphere);
  EXPECT_FALSE(i.has_hull);
  EXPECT_FALSE(i.has_self_intersections);
}

TEST(Inspect, ReferenceFiguresHold) {
  // The figures the Node test holds the WebAssembly core to
  // (tests/fixtures/inspect-reference.txt), computed here again.
  std::ifstream file(std::string(FIXTURES_DIR) + "/inspect-reference.txt");
  ASSERT_TRUE(file.good());
  std::string line;
  int cases = 0;
  while (std::getline(file, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream in(line);
    std::string name, scheme, word;
    int levels = 0;
    std::size_t pairs = 0, hv = 0, he = 0, hf = 0;
    double area = 0, volume = 0, radius = 0, cx = 0, cy = 0, cz = 0, harea = 0,
           hvolume = 0, width = 0;
    in >> name >> scheme >> levels >> word >> pairs >> word >> area >> word >>
        volume >> word >> radius >> cx >> cy >> cz >> word >> hv >> he >> hf >>
        harea >> hvolume >> word >> width;
    ASSERT_FALSE(in.fail()) << line;
    Subdivide_options o;
    o.scheme = scheme;
    o.levels = levels;
    o.triangulate = true;
    const Inspection i =
        inspect(subdivide_mesh(refine_test::fixture(name), o).value);
    SCOPED_TRACE(name + " " + scheme);
    EXPECT_EQ(i.self_intersections.pairs, pairs);
    EXPECT_EQ(i.hull.vertices, hv);
    EXPECT_EQ(i.hull.edges, he);
    EXPECT_EQ(i.hull.faces, hf);
    EXPECT_NEAR(i.measures.area, area, 1e-12);
    EXPECT_NEAR(i.measures.volume, volume, 1e-12);
    EXPECT_NEAR(i.sphere.radius, radius, 1e-12);
    EXPECT_NEAR(i.sphere.center[0], cx, 1e-12);
    EXPECT_NEAR(i.sphere.center[1], cy, 1e-12);
    EXPECT_NEAR(i.sphere.center[2], cz, 1e-12);
    EXPECT_NEAR(i.hull.area, harea, 1e-12);
    EXPECT_NEAR(i.hull.volume, hvolume, 1e-12);
    EXPECT_NEAR(i.width.width, width, 1e-12);
    ++cases;
  }
  EXPECT_EQ(cases, 6);
}

TEST(Inspect, RefusesAnInvalidMesh) {
  Mesh_buffers bad = refine_test::fixture("cube.off");
  bad.face_indices[0] = 99;
  EXPECT_EQ(inspect_mesh(bad, everything()).status.code,
            Status_code::invalid_mesh);
}

}  // namespace
}  // namespace subdivlab
