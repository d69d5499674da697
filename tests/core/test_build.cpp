// build_mesh / to_buffers: every check with its message, and exact
// round trips between buffers and Surface_mesh.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/mesh_build.h"
#include "core/mesh_check.h"
#include "core/mesh_io.h"

namespace subdivlab {
namespace {

Mesh_buffers cube_buffers() {
  Mesh_buffers b;
  b.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,
                 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
  b.face_sizes = {4, 4, 4, 4, 4, 4};
  b.face_indices = {0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4,
                    1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7};
  return b;
}

/// Builds and expects failure with the given code; returns the message.
std::string build_error(const Mesh_buffers& b,
                        Status_code code = Status_code::invalid_mesh) {
  Mesh m;
  const Status s = build_mesh(b, m);
  EXPECT_EQ(s.code, code) << s.message;
  EXPECT_EQ(s.line, 0);
  EXPECT_EQ(m.number_of_vertices(), 0u)
      << "a failed build leaves the mesh empty";
  EXPECT_EQ(m.number_of_faces(), 0u);
  return s.message;
}

TEST(BuildMesh, CubeBuildsWithItsCounts) {
  Mesh m;
  const Status s = build_mesh(cube_buffers(), m);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_EQ(m.number_of_vertices(), 8u);
  EXPECT_EQ(m.number_of_faces(), 6u);
  EXPECT_EQ(m.number_of_edges(), 12u);
  EXPECT_TRUE(CGAL::is_closed(m));
  EXPECT_TRUE(m.is_valid(false));
}

TEST(BuildMesh, ToBuffersKeepsVertexNumbersPositionsAndFaces) {
  const Mesh_buffers in = cube_buffers();
  Mesh m;
  ASSERT_TRUE(build_mesh(in, m).ok());
  const Mesh_buffers out = to_buffers(m);
  EXPECT_EQ(out.positions,
            in.positions);  // exact: the same doubles in the same order
  EXPECT_EQ(out.face_sizes, in.face_sizes);
  // Each face starts at the same corner: a fresh build gives back its input.
  EXPECT_EQ(out.face_indices, in.face_indices);
  EXPECT_TRUE(out.control_edges.empty());
}

TEST(BuildMesh, ToBuffersRenumbersAfterRemovals) {
  Mesh m;
  ASSERT_TRUE(build_mesh(cube_buffers(), m).ok());
  // Removing a face leaves its vertices; removing vertex 0's faces and the
  // vertex leaves a hole in the index range that to_buffers closes.
  std::vector<Mesh::Face_index> around;
  for (auto f : CGAL::faces_around_target(m.halfedge(Mesh::Vertex_index(0)), m))
    around.push_back(f);
  for (auto f : around) CGAL::Euler::remove_face(m.halfedge(f), m);
  ASSERT_EQ(m.number_of_vertices(), 7u);
  const Mesh_buffers out = to_buffers(m);
  EXPECT_EQ(out.vertex_count(), 7u);
  EXPECT_EQ(out.face_count(), 3u);
  for (auto v : out.face_indices) EXPECT_LT(v, 7u);
  // Old vertex 1 (1,0,0) is now vertex 0.
  EXPECT_EQ(out.positions[0], 1.0);
  EXPECT_EQ(out.positions[1], 0.0);
}

TEST(BuildMesh, IsolatedVerticesAreDroppedAndTheRestKeepTheirOrder) {
  Mesh_buffers b;
  b.positions = {9, 9, 9, 0, 0, 0, 1, 0, 0, 7, 7, 7, 0, 1, 0};
  b.face_sizes = {3};
  b.face_indices = {1, 2, 4};
  Mesh m;
  ASSERT_TRUE(build_mesh(b, m).ok());
  const Mesh_buffers out = to_buffers(m);
  EXPECT_EQ(out.positions, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0}));
  EXPECT_EQ(out.face_indices, (std::vector<std::uint32_t>{0, 1, 2}));
}

TEST(BuildMesh, PolygonsStayPolygons) {
  Mesh_buffers b;
  b.positions = {0, 0, 0, 2, 0, 0, 3, 1, 0, 2, 2, 0, 0, 2, 0, -1, 1, 0};
  b.face_sizes = {6};
  b.face_indices = {0, 1, 2, 3, 4, 5};
  Mesh m;
  ASSERT_TRUE(build_mesh(b, m).ok());
  EXPECT_EQ(m.number_of_faces(), 1u);
  EXPECT_EQ(m.degree(*m.faces().begin()), 6u);
  EXPECT_EQ(to_buffers(m).face_sizes, (std::vector<std::uint32_t>{6}));
}

/// The mesh as Surface_mesh::add_face builds it, face by face: the
/// reference build_mesh's tables are held to.
Mesh built_by_add_face(const Mesh_buffers& in) {
  Mesh m;
  std::vector<Mesh::Vertex_index> vmap(in.vertex_count());
  std::vector<bool> used(in.vertex_count(), false);
  for (std::uint32_t v : in.face_indices) used[v] = true;
  for (std::size_t v = 0; v < in.vertex_count(); ++v)
    if (used[v])
      vmap[v] = m.add_vertex(Point(in.positions[3 * v], in.positions[3 * v + 1],
                                   in.positions[3 * v + 2]));
  std::size_t o = 0;
  for (std::uint32_t k : in.face_sizes) {
    std::vector<Mesh::Vertex_index> face;
    for (std::uint32_t i = 0; i < k; ++i)
      face.push_back(vmap[in.face_indices[o + i]]);
    EXPECT_NE(m.add_face(face), Mesh::null_face());
    o += k;
  }
  return m;
}

/// Every element of `a` and `b`, connectivity and points, equal.
void expect_same_mesh(const Mesh& a, const Mesh& b, const std::string& what) {
  ASSERT_EQ(a.num_vertices(), b.num_vertices()) << what;
  ASSERT_EQ(a.num_halfedges(), b.num_halfedges()) << what;
  ASSERT_EQ(a.num_faces(), b.num_faces()) << what;
  std::size_t differences = 0;
  for (Mesh::Vertex_index v : a.vertices()) {
    differences += a.halfedge(v) != b.halfedge(v);
    differences += a.point(v) != b.point(v);
  }
  for (Mesh::Halfedge_index h : a.halfedges()) {
    differences += a.target(h) != b.target(h);
    differences += a.next(h) != b.next(h);
    differences += a.prev(h) != b.prev(h);
    differences += a.face(h) != b.face(h);
  }
  for (Mesh::Face_index f : a.faces())
    differences += a.halfedge(f) != b.halfedge(f);
  EXPECT_EQ(differences, 0u) << what;
}

Mesh_buffers read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in.good()) << path << " missing: run node scripts/setup.mjs";
  std::stringstream s;
  s << in.rdbuf();
  const Result<Mesh_buffers> r = read_mesh(
      s.str(), path.substr(path.size() - 4) == ".obj" ? Mesh_format::obj
                                                      : Mesh_format::off);
  EXPECT_TRUE(r.ok()) << path << ": " << r.status.message;
  return r.value;
}

/// The faces in another order (their corners kept).
Mesh_buffers shuffled_faces(const Mesh_buffers& in, unsigned seed) {
  std::vector<std::size_t> order(in.face_count()), offset(in.face_count());
  std::size_t o = 0;
  for (std::size_t f = 0; f < in.face_count(); ++f) {
    order[f] = f;
    offset[f] = o;
    o += in.face_sizes[f];
  }
  std::mt19937 random(seed);
  std::shuffle(order.begin(), order.end(), random);
  Mesh_buffers out;
  out.positions = in.positions;
  for (std::size_t f : order) {
    out.face_sizes.push_back(in.face_sizes[f]);
    out.face_indices.insert(
        out.face_indices.end(), in.face_indices.begin() + offset[f],
        in.face_indices.begin() + offset[f] + in.face_sizes[f]);
  }
  return out;
}

// build_mesh sets each element from the tables; it must leave exactly what
// add_face leaves, whatever order the faces come in (fans grown apart and
// joined later included).
TEST(BuildMesh, EqualsAddFaceElementForElement) {
  const std::string fixtures = FIXTURES_DIR;
  std::vector<std::string> paths;
  for (const char* f :
       {"tetrahedron.off", "octahedron.off", "icosahedron.off", "torus-tri.off",
        "two-tetrahedra.off", "disk-tri.off", "cube.off", "cube.obj",
        "torus-quad.off", "rhombicuboctahedron.off", "grid-open.off",
        "mixed-open.off"})
    paths.push_back(fixtures + "/" + f);
  for (const char* f : {"holes.off", "fandisk.off", "mannequin-devil.off",
                        "elephant.off", "cube_quad.off", "torus_quad.off"})
    paths.push_back(fixtures + "/../../public/meshes/cgal/" + f);
  for (const std::string& path : paths) {
    const Mesh_buffers in = read_file(path);
    for (unsigned seed = 0; seed < 4; ++seed) {
      const Mesh_buffers b = seed == 0 ? in : shuffled_faces(in, seed);
      Mesh built;
      ASSERT_TRUE(build_mesh(b, built).ok()) << path;
      EXPECT_TRUE(built.is_valid(false)) << path;
      expect_same_mesh(built, built_by_add_face(b),
                       path + " (shuffle " + std::to_string(seed) + ")");
    }
  }
  // An isolated vertex is dropped by both.
  Mesh_buffers loose = cube_buffers();
  loose.positions.insert(loose.positions.begin(), {9, 9, 9});
  for (std::uint32_t& v : loose.face_indices) ++v;
  Mesh built;
  ASSERT_TRUE(build_mesh(loose, built).ok());
  expect_same_mesh(built, built_by_add_face(loose), "cube with a loose vertex");
}

TEST(BuildErrors, NoFaces) {
  Mesh_buffers b;
  b.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  EXPECT_EQ(build_error(b), "the mesh has no faces");
  EXPECT_EQ(build_error(Mesh_buffers{}), "the mesh has no faces");
}

TEST(BuildErrors, InconsistentArrays) {
  Mesh_buffers b = cube_buffers();
  b.face_indices.pop_back();
  EXPECT_EQ(build_error(b), "face sizes add up to 24 indices but there are 23");
  b = cube_buffers();
  b.positions.push_back(1.0);
  EXPECT_EQ(build_error(b), "positions hold 25 numbers, not a multiple of 3");
}

TEST(BuildErrors, NonFiniteCoordinateNamesTheVertex) {
  Mesh_buffers b = cube_buffers();
  b.positions[3 * 5 + 1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(build_error(b), "vertex 5 has a non-finite coordinate");
  b = cube_buffers();
  b.positions[3 * 2 + 2] = -std::numeric_limits<double>::infinity();
  EXPECT_EQ(build_error(b), "vertex 2 has a non-finite coordinate");
}

TEST(BuildErrors, FaceWithFewerThanThreeVertices) {
  Mesh_buffers b = cube_buffers();
  b.face_sizes = {4, 4, 4, 4, 4, 2, 2};
  EXPECT_EQ(build_error(b), "face 5 has 2 vertices; a face needs at least 3");
  b = cube_buffers();
  b.face_sizes.push_back(0);
  EXPECT_EQ(build_error(b), "face 6 has 0 vertices; a face needs at least 3");
}

TEST(BuildErrors, IndexOutOfRange) {
  Mesh_buffers b = cube_buffers();
  b.face_indices[9] = 12;  // face 2
  EXPECT_EQ(build_error(b),
            "face 2: vertex index 12 is out of range (8 vertices)");
}

TEST(BuildErrors, RepeatedVertexInAFace) {
  Mesh_buffers b = cube_buffers();
  b.face_indices[6] = 4;  // face 1 = 4 5 4 7
  EXPECT_EQ(build_error(b), "face 1 uses vertex 4 more than once");
}

TEST(BuildErrors, FirstFailingFaceWinsAndChecksRunInOrder) {
  Mesh_buffers b = cube_buffers();
  b.face_indices[20] = 99;  // face 5 out of range
  b.face_indices[5] = 4;    // face 1 repeats vertex 4
  EXPECT_EQ(build_error(b), "face 1 uses vertex 4 more than once");
  b.positions[0] =
      std::numeric_limits<double>::infinity();  // coordinates come before faces
  EXPECT_EQ(build_error(b), "vertex 0 has a non-finite coordinate");
}

TEST(BuildErrors, EdgeUsedByThreeFaces) {
  Mesh_buffers b;
  b.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1};
  b.face_sizes = {3, 3, 3};
  b.face_indices = {0, 1, 2, 1, 0, 3, 0, 1, 4};
  EXPECT_EQ(build_error(b),
            "non-manifold edge between vertices 0 and 1: used by 3 faces "
            "(faces 0, 1 and 2)");
}

TEST(BuildErrors, InconsistentOrientation) {
  Mesh_buffers b = cube_buffers();
  std::reverse(b.face_indices.begin() + 4,
               b.face_indices.begin() + 8);  // face 1 flipped
  EXPECT_EQ(build_error(b),
            "inconsistent orientation: faces 1 and 2 both use edge 5\u21924 in "
            "the same direction");
}

TEST(BuildErrors, TwoTrianglesSharingAnEdgeTheSameWay) {
  Mesh_buffers b;
  b.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0};
  b.face_sizes = {3, 3};
  b.face_indices = {0, 1, 2, 0, 1, 3};
  EXPECT_EQ(build_error(b),
            "inconsistent orientation: faces 0 and 1 both use edge 0\u21921 in "
            "the same direction");
}

TEST(BuildErrors, NonManifoldVertexBowtie) {
  // Two triangles that share vertex 0 and nothing else.
  Mesh_buffers b;
  b.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, -1, 0, 0, -1, -1, 0};
  b.face_sizes = {3, 3};
  b.face_indices = {0, 1, 2, 0, 3, 4};
  EXPECT_EQ(build_error(b),
            "non-manifold vertex 0: its faces form 2 separate fans that meet "
            "only at this vertex "
            "(faces 0 and 1)");
}

/// A disc of n triangles around vertex 0 (open: its rim is the border);
/// with `twice`, the first triangle is repeated (an edge used twice the
/// same way).
Mesh_buffers fan(std::uint32_t n, bool twice) {
  Mesh_buffers b;
  b.positions = {0, 0, 0};
  for (std::uint32_t i = 0; i < n; ++i) {
    const double a = 6.283185307179586 * i / n;
    b.positions.insert(b.positions.end(), {std::cos(a), std::sin(a), 0});
  }
  for (std::uint32_t i = 0; i + 1 < n; ++i) {
    b.face_sizes.push_back(3);
    b.face_indices.insert(b.face_indices.end(), {0, i + 1, i + 2});
  }
  if (twice) {
    b.face_sizes.push_back(3);
    b.face_indices.insert(b.face_indices.end(), {0, 1, 2});
  }
  return b;
}

// One vertex of valence 300 000: the checks and the build are linear in the
// corners, not in the square of a valence (the old pairwise end check and
// add_face's circulation took minutes).
TEST(BuildMesh, AFanOfThreeHundredThousandTrianglesAroundOneVertex) {
  std::vector<std::uint32_t> corner_halfedges;
  const Mesh_buffers b = fan(300000, false);
  ASSERT_TRUE(detail::check_buffers(b, {}, &corner_halfedges).status.ok());
  ASSERT_EQ(corner_halfedges.size(), 3 * 299999u);
  // Face i's spoke 0 -> i + 1 is the opposite of face i - 1's i + 1 -> 0.
  EXPECT_EQ(corner_halfedges[3], corner_halfedges[2] ^ 1u);
  EXPECT_EQ(corner_halfedges[3 * 299998],
            corner_halfedges[3 * 299997 + 2] ^ 1u);
  Mesh m;
  ASSERT_TRUE(build_mesh(b, m).ok());
  EXPECT_EQ(m.number_of_vertices(), 300001u);
  EXPECT_EQ(m.number_of_faces(), 299999u);
  EXPECT_EQ(m.degree(Mesh::Vertex_index(0)), 300000u);
  EXPECT_EQ(build_error(fan(300000, true)),
            "non-manifold edge between vertices 0 and 2: used by 3 faces "
            "(faces 0, 1 and 299999)");
}

TEST(BuildErrors, NonManifoldVertexOfTwoFansOfManyTriangles) {
  // Vertex 0 has 18 corners (two fans of 9): the checks mark its ends in a
  // table by vertex rather than searching its few corners, and still see
  // two fans.
  Mesh_buffers b = fan(10, false);
  const Mesh_buffers other = fan(10, false);
  b.positions.insert(b.positions.end(), other.positions.begin() + 3,
                     other.positions.end());
  for (std::uint32_t f = 0; f < 9; ++f) {
    b.face_sizes.push_back(3);
    b.face_indices.insert(b.face_indices.end(), {0, 11 + f, 12 + f});
  }
  EXPECT_EQ(build_error(b),
            "non-manifold vertex 0: its faces form 2 separate fans that meet "
            "only at this vertex (faces 0 and 9)");
}

TEST(BuildErrors, NonManifoldVertexOfTwoClosedCones) {
  // Two tetrahedra glued at one vertex (vertex 0): every edge is fine, the
  // vertex is not.
  Mesh_buffers b;
  b.positions = {0, 0,  0, 1, 0, 0,  0, 1, 0, 0, 0,
                 1, -1, 0, 0, 0, -1, 0, 0, 0, -1};
  b.face_sizes = {3, 3, 3, 3, 3, 3, 3, 3};
  b.face_indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3,   // first tetrahedron
                    0, 4, 5, 0, 5, 6, 0, 6, 4, 4, 6, 5};  // second
  const std::string m = build_error(b);
  EXPECT_NE(m.find("non-manifold vertex 0"), std::string::npos) << m;
  EXPECT_NE(m.find("2 separate fans"), std::string::npos) << m;
}

TEST(BuildErrors, EdgeCheckComesBeforeOrientationCheck) {
  Mesh_buffers b;
  b.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1};
  b.face_sizes = {3, 3, 3};
  b.face_indices = {0, 1, 2, 0, 1,
                    3, 0, 1, 4};  // 3 faces, all the same direction
  EXPECT_NE(build_error(b).find("non-manifold edge between vertices 0 and 1"),
            std::string::npos);
}

TEST(BuildErrors, AFailedBuildClearsAPreviousMesh) {
  Mesh m;
  ASSERT_TRUE(build_mesh(cube_buffers(), m).ok());
  Mesh_buffers bad = cube_buffers();
  bad.face_indices[0] = 100;
  EXPECT_FALSE(build_mesh(bad, m).ok());
  EXPECT_EQ(m.number_of_vertices(), 0u);
  ASSERT_TRUE(build_mesh(cube_buffers(), m).ok());
  EXPECT_EQ(m.number_of_faces(), 6u);
}

}  // namespace
}  // namespace subdivlab
