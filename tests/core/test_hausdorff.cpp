// The symmetric Hausdorff distance (core/hausdorff.h): exact on shapes
// whose distance is known, zero from a mesh to itself.
#include <gtest/gtest.h>

#include "core/hausdorff.h"
#include "core/subdivide.h"
#include "refine_test_support.h"

namespace subdivlab {
namespace {

Mesh_buffers square(double z, double side = 1) {
  Mesh_buffers m;
  m.positions = {0, 0, z, side, 0, z, side, side, z, 0, side, z};
  m.face_sizes = {4};
  m.face_indices = {0, 1, 2, 3};
  return m;
}

TEST(Hausdorff, KnownDistances) {
  // Two parallel unit squares 0.1 apart: every point is 0.1 from the other.
  const auto parallel = hausdorff_distance(square(0), square(0.1));
  ASSERT_TRUE(parallel.ok()) << parallel.status.message;
  EXPECT_NEAR(parallel.value.distance, 0.1, parallel.value.error_bound);
  // A unit square and a 2 x 2 one in the same plane: the far corner (2, 2)
  // is sqrt(2) from (1, 1).
  const auto bigger = hausdorff_distance(square(0), square(0, 2));
  ASSERT_TRUE(bigger.ok());
  EXPECT_NEAR(bigger.value.distance, std::sqrt(2.0), bigger.value.error_bound);
  // A mesh and itself; a mesh and its own subdivision (linear keeps the
  // surface).
  const Mesh_buffers cube = refine_test::fixture("cube.off");
  EXPECT_NEAR(hausdorff_distance(cube, cube).value.distance, 0, 1e-9);
  Subdivide_options o;
  o.scheme = "linear";
  o.levels = 2;
  const auto linear = hausdorff_distance(cube, subdivide_mesh(cube, o).value);
  EXPECT_NEAR(linear.value.distance, 0, linear.value.error_bound);
}

TEST(Hausdorff, VertexDistances) {
  // Parallel squares: every corner is 0.1 from the other square.
  const auto parallel = hausdorff_distance(square(0), square(0.1), 1e-4, true);
  ASSERT_TRUE(parallel.ok());
  ASSERT_EQ(parallel.value.a_to_b.size(), 4u);
  ASSERT_EQ(parallel.value.b_to_a.size(), 4u);
  for (double d : parallel.value.a_to_b) EXPECT_NEAR(d, 0.1, 1e-15);
  for (double d : parallel.value.b_to_a) EXPECT_NEAR(d, 0.1, 1e-15);
  // The unit square lies in the 2 x 2 one (0 each); the larger one's
  // corners (0,0), (2,0), (2,2), (0,2) are 0, 1, sqrt 2, 1 from it.
  const auto bigger = hausdorff_distance(square(0), square(0, 2), 1e-4, true);
  for (double d : bigger.value.a_to_b) EXPECT_EQ(d, 0);
  const std::vector<double> expected = {0, 1, std::sqrt(2.0), 1};
  for (int v = 0; v < 4; ++v)
    EXPECT_NEAR(bigger.value.b_to_a[v], expected[v], 1e-15) << v;
  // Without asking, none are computed.
  EXPECT_TRUE(hausdorff_distance(square(0), square(0.1)).value.a_to_b.empty());
}

TEST(Hausdorff, VertexDistancesStayWithinTheDistance) {
  // Catmull-Clark against Loop on the cube (triangulated), level 2: no
  // vertex is farther from the other surface than the Hausdorff distance,
  // and the farthest vertex comes close to it.
  const Mesh_buffers cube = refine_test::fixture("cube.off");
  Subdivide_options cc, loop;
  cc.scheme = "catmull-clark";
  cc.levels = 2;
  loop.scheme = "loop";
  loop.levels = 2;
  loop.triangulate = true;
  const auto h =
      hausdorff_distance(subdivide_mesh(cube, cc).value,
                         subdivide_mesh(cube, loop).value, 1e-4, true);
  ASSERT_TRUE(h.ok());
  double farthest = 0;
  for (double d : h.value.a_to_b) farthest = std::max(farthest, d);
  for (double d : h.value.b_to_a) farthest = std::max(farthest, d);
  EXPECT_LE(farthest, h.value.distance + h.value.error_bound);
  EXPECT_GT(farthest, 0.5 * h.value.distance);
}

TEST(Hausdorff, RefusesAnInvalidMesh) {
  Mesh_buffers bad = square(0);
  bad.face_indices = {0, 1, 2, 7};
  const auto r = hausdorff_distance(bad, square(0));
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.status.code, Status_code::invalid_mesh);
}

}  // namespace
}  // namespace subdivlab
