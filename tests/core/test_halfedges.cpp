// The halfedge table (core/halfedges.h) satisfies the structure's
// invariants on every fixture and on levels 1 and 2 of each scheme:
// opposite is an involution without fixed points (h xor 1), prev is next's
// inverse, a halfedge starts where its previous one ends, following next
// from a face's halfedge visits that face's corners in the file's order and
// returns after its degree, and the border halfedges form as many loops as
// the facts count boundaries.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/halfedges.h"
#include "core/mesh_facts.h"
#include "core/subdivide.h"
#include "refine_test_support.h"

namespace subdivlab {
namespace {

/// Number of cycles of `next` over the halfedges with face -1.
std::size_t border_loops(const Halfedge_table& t) {
  std::vector<bool> seen(t.size(), false);
  std::size_t loops = 0;
  for (std::size_t h = 0; h < t.size(); ++h) {
    if (t.face[h] != -1 || seen[h]) continue;
    ++loops;
    for (std::size_t g = h; !seen[g]; g = t.next[g]) {
      EXPECT_EQ(t.face[g], -1) << "a border loop left the border at " << g;
      seen[g] = true;
    }
  }
  return loops;
}

void expect_valid(const Mesh_buffers& mesh, const std::string& what) {
  SCOPED_TRACE(what);
  const Result<Halfedge_table> r = halfedge_table(mesh);
  ASSERT_TRUE(r.ok()) << r.status.message;
  const Halfedge_table& t = r.value;
  const Result<Mesh_facts> facts = compute_facts(mesh);
  ASSERT_TRUE(facts.ok());
  ASSERT_EQ(t.size(), 2 * facts.value.edges);
  for (std::uint32_t h = 0; h < t.size(); ++h) {
    ASSERT_EQ(t.opposite[h], h ^ 1u);
    ASSERT_EQ(t.opposite[t.opposite[h]], h);
    ASSERT_EQ(t.prev[t.next[h]], h);
    ASSERT_EQ(t.next[t.prev[h]], h);
    // h starts at its opposite's target and at its previous one's target.
    ASSERT_EQ(t.target[t.prev[h]], t.target[t.opposite[h]]);
    ASSERT_LT(t.target[h], mesh.vertex_count());
  }
  // Each face: its halfedges, from the one that ends at its first corner,
  // visit its corners in order and come back after its degree.
  std::vector<std::uint32_t> first(mesh.face_count(), UINT32_MAX);
  std::vector<std::uint32_t> count(mesh.face_count(), 0);
  std::vector<std::size_t> offset(mesh.face_count(), 0);
  for (std::size_t f = 1; f < mesh.face_count(); ++f)
    offset[f] = offset[f - 1] + mesh.face_sizes[f - 1];
  for (std::uint32_t h = 0; h < t.size(); ++h) {
    if (t.face[h] < 0) continue;
    const std::size_t f = static_cast<std::size_t>(t.face[h]);
    ASSERT_LT(f, mesh.face_count());
    ++count[f];
    if (t.target[h] == mesh.face_indices[offset[f]]) first[f] = h;
  }
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const std::uint32_t degree = mesh.face_sizes[f];
    ASSERT_EQ(count[f], degree) << "face " << f;
    ASSERT_NE(first[f], UINT32_MAX) << "face " << f;
    std::uint32_t h = first[f];
    for (std::uint32_t k = 0; k < degree; ++k) {
      ASSERT_EQ(t.face[h], static_cast<std::int32_t>(f));
      ASSERT_EQ(t.target[h], mesh.face_indices[offset[f] + k]);
      h = t.next[h];
    }
    ASSERT_EQ(h, first[f]) << "face " << f << " does not close";
  }
  EXPECT_EQ(border_loops(t), facts.value.boundaries);
}

TEST(HalfedgeTable, CubeHas24HalfedgesNoneOnTheBorder) {
  const Result<Halfedge_table> r =
      halfedge_table(refine_test::fixture("cube.off"));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.value.size(), 24u);
  for (std::int32_t f : r.value.face) EXPECT_GE(f, 0);
}

TEST(HalfedgeTable, OpenGridHas12BorderHalfedgesInOneLoop) {
  // 3 x 3 quads: 24 edges, 12 of them on the border.
  const Result<Halfedge_table> r =
      halfedge_table(refine_test::fixture("grid-open.off"));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.value.size(), 48u);
  std::size_t border = 0;
  for (std::int32_t f : r.value.face) border += f == -1 ? 1 : 0;
  EXPECT_EQ(border, 12u);
  EXPECT_EQ(border_loops(r.value), 1u);
}

TEST(HalfedgeTable, RefusesAnInvalidMeshNamingTheProblem) {
  Mesh_buffers m;
  m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  m.face_sizes = {3, 3};
  m.face_indices = {0, 1, 2, 0, 1, 2};  // the same triangle twice
  const Result<Halfedge_table> r = halfedge_table(m);
  EXPECT_EQ(r.status.code, Status_code::invalid_mesh);
  EXPECT_FALSE(r.status.message.empty());
}

TEST(HalfedgeTable, InvariantsOnEveryFixtureAndLevelsOneAndTwoOfEachScheme) {
  std::vector<std::string> names(std::begin(refine_test::kFixtures),
                                 std::end(refine_test::kFixtures));
  for (const char* extra :
       {"triacontahedron.off", "pentagonal-tower.off", "saddle.off"})
    names.push_back(extra);
  const char* const schemes[] = {"catmull-clark", "loop",          "doo-sabin",
                                 "sqrt3",         "quad-triangle", "linear",
                                 "linear-tri"};
  std::size_t checked = 0;
  for (const std::string& name : names) {
    const Mesh_buffers control = refine_test::fixture(name);
    expect_valid(control, name);
    ++checked;
    for (const char* scheme : schemes) {
      Subdivide_options o;
      o.scheme = scheme;
      o.triangulate = true;
      for (int levels = 1; levels <= 2; ++levels) {
        o.levels = levels;
        const Result<Mesh_buffers> r = subdivide_mesh(control, o);
        ASSERT_TRUE(r.ok())
            << name << " " << scheme << ": " << r.status.message;
        expect_valid(r.value,
                     name + " " + scheme + " level " + std::to_string(levels));
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, names.size() * (1 + 7 * 2));
}

}  // namespace
}  // namespace subdivlab
