// Checking a result against the reference (core/compare.h): the same level
// in another vertex order matches; one moved vertex is named; another
// scheme's level, other counts or flipped faces do not match.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

#include "core/compare.h"
#include "core/subdivide.h"
#include "refine_test_support.h"

namespace subdivlab {
namespace {

using refine_test::fixture;

Mesh_buffers level(const char* name, const char* scheme, int levels) {
  Subdivide_options o;
  o.scheme = scheme;
  o.levels = levels;
  const Result<Mesh_buffers> r = subdivide_mesh(fixture(name), o);
  EXPECT_TRUE(r.ok()) << r.status.message;
  return r.value;
}

/// `m` with its vertices renumbered by a random permutation and each face
/// starting at another corner: what another implementation may write.
Mesh_buffers shuffled(const Mesh_buffers& m, std::vector<std::uint32_t>& to) {
  const auto n = static_cast<std::uint32_t>(m.vertex_count());
  to.resize(n);
  std::iota(to.begin(), to.end(), 0u);
  std::mt19937 random(7);
  std::shuffle(to.begin(), to.end(), random);
  Mesh_buffers s = m;
  for (std::uint32_t v = 0; v < n; ++v)
    for (int i = 0; i < 3; ++i)
      s.positions[3 * to[v] + i] = m.positions[3 * v + i];
  std::size_t o = 0;
  for (std::uint32_t size : m.face_sizes) {
    for (std::uint32_t j = 0; j < size; ++j)
      s.face_indices[o + j] = to[m.face_indices[o + (j + 1) % size]];
    o += size;
  }
  return s;
}

TEST(CompareMeshes, TheSameLevelMatchesInOrderAndShuffled) {
  const Mesh_buffers ref = level("cube.off", "catmull-clark", 2);
  const Mesh_comparison same = compare_meshes(ref, ref, 1e-9);
  EXPECT_TRUE(same.match);
  EXPECT_EQ(same.matching, "order");
  EXPECT_TRUE(same.same_faces);
  EXPECT_EQ(same.max_error, 0.0);
  std::vector<std::uint32_t> to;
  const Mesh_comparison moved = compare_meshes(ref, shuffled(ref, to), 1e-9);
  EXPECT_TRUE(moved.match) << (moved.reasons.empty() ? "" : moved.reasons[0]);
  EXPECT_EQ(moved.matching, "nearest");
  EXPECT_TRUE(moved.same_faces);
}

TEST(CompareMeshes, NamesAMovedVertex) {
  const Mesh_buffers ref = level("octahedron.off", "loop", 2);
  std::vector<std::uint32_t> to;
  Mesh_buffers result = shuffled(ref, to);
  // Reference vertex 20, now numbered to[20], moved by 1 % of the diagonal.
  const double d = compare_meshes(ref, ref, 0).diagonal;
  result.positions[3 * to[20]] += 0.01 * d;
  const Mesh_comparison c = compare_meshes(ref, result, 1e-6);
  EXPECT_FALSE(c.match);
  ASSERT_EQ(c.reasons.size(), 1u);
  EXPECT_EQ(c.reasons[0],
            "1 vertex of " + std::to_string(ref.vertex_count()) +
                " is farther from the reference than the tolerance");
  ASSERT_FALSE(c.worst.empty());
  EXPECT_EQ(c.worst[0].vertex, to[20]);
  EXPECT_EQ(c.worst[0].reference, 20u);
  EXPECT_NEAR(c.worst[0].error, 0.01 * d, 1e-12);
  EXPECT_TRUE(c.same_faces);
}

TEST(CompareMeshes, AnotherSchemeOrFlippedFacesDoNotMatch) {
  // Doo-Sabin's level 1 of the cube has 24 vertices, Catmull-Clark's 26.
  const Mesh_comparison other =
      compare_meshes(level("cube.off", "catmull-clark", 1),
                     level("cube.off", "doo-sabin", 1), 1e-6);
  EXPECT_FALSE(other.match);
  EXPECT_EQ(other.reasons[0],
            "the result has 24 vertices where the reference has 26");
  EXPECT_GT(other.max_error, 0.01);
  // Loop against linear subdivision of the octahedron: same counts, faces and
  // numbering, other points.
  const Mesh_comparison linear =
      compare_meshes(level("octahedron.off", "loop", 1),
                     level("octahedron.off", "linear-tri", 1), 1e-6);
  EXPECT_FALSE(linear.match);
  EXPECT_GT(linear.max_error, 0.05);
  // Every face turned the other way.
  const Mesh_buffers ref = level("cube.off", "catmull-clark", 1);
  Mesh_buffers flipped = ref;
  std::size_t o = 0;
  for (std::uint32_t size : ref.face_sizes) {
    std::reverse(flipped.face_indices.begin() + o,
                 flipped.face_indices.begin() + o + size);
    o += size;
  }
  const Mesh_comparison turned = compare_meshes(ref, flipped, 1e-9);
  EXPECT_FALSE(turned.match);
  EXPECT_FALSE(turned.same_faces);
  EXPECT_EQ(turned.max_error, 0.0);
}

}  // namespace
}  // namespace subdivlab
