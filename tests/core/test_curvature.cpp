// vertex_curvature (curvature.h) against values known in closed form: a
// sphere's 1/r² and 1/r, a flat grid's zeros, a cube's corners (π/2 each)
// and Gauss-Bonnet (the defects of a closed mesh sum to 2π χ).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <utility>

#include "core/curvature.h"

namespace subdivlab {
namespace {

const double pi = std::acos(-1.0);

double sum(const std::vector<double>& values) {
  double s = 0;
  for (double x : values) s += x;
  return s;
}

/// An icosahedron split `levels` times at edge midpoints (each triangle
/// into four), every vertex pushed out to radius `r`: faces turn outward.
Mesh_buffers icosphere(int levels, double r) {
  const double g = (1 + std::sqrt(5.0)) / 2;
  std::vector<std::array<double, 3>> p = {{-1, g, 0},  {1, g, 0},   {-1, -g, 0},
                                          {1, -g, 0},  {0, -1, g},  {0, 1, g},
                                          {0, -1, -g}, {0, 1, -g},  {g, 0, -1},
                                          {g, 0, 1},   {-g, 0, -1}, {-g, 0, 1}};
  std::vector<std::array<std::uint32_t, 3>> f = {
      {0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
      {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
      {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
      {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    const auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      const auto found = mid.find(key);
      if (found != mid.end()) return found->second;
      p.push_back({(p[a][0] + p[b][0]) / 2, (p[a][1] + p[b][1]) / 2,
                   (p[a][2] + p[b][2]) / 2});
      const auto v = static_cast<std::uint32_t>(p.size() - 1);
      mid.emplace(key, v);
      return v;
    };
    std::vector<std::array<std::uint32_t, 3>> next;
    for (const auto& t : f) {
      const std::uint32_t ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]),
                          ca = midpoint(t[2], t[0]);
      next.push_back({t[0], ab, ca});
      next.push_back({t[1], bc, ab});
      next.push_back({t[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    f = next;
  }
  Mesh_buffers mesh;
  for (const auto& q : p) {
    const double s = r / std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    for (double x : q) mesh.positions.push_back(x * s);
  }
  for (const auto& t : f) {
    mesh.face_sizes.push_back(3);
    mesh.face_indices.insert(mesh.face_indices.end(), t.begin(), t.end());
  }
  return mesh;
}

/// An n × n grid of unit quads in the plane z = 0 (integer coordinates).
Mesh_buffers flat_grid(std::uint32_t n) {
  Mesh_buffers mesh;
  for (std::uint32_t j = 0; j <= n; ++j)
    for (std::uint32_t i = 0; i <= n; ++i)
      mesh.positions.insert(mesh.positions.end(), {double(i), double(j), 0});
  for (std::uint32_t j = 0; j < n; ++j) {
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t v = j * (n + 1) + i;
      mesh.face_sizes.push_back(4);
      mesh.face_indices.insert(mesh.face_indices.end(),
                               {v, v + 1, v + n + 2, v + n + 1});
    }
  }
  return mesh;
}

/// The cube [0, 2]³ as six quads turned outward.
Mesh_buffers cube() {
  Mesh_buffers mesh;
  for (int v = 0; v < 8; ++v)
    mesh.positions.insert(
        mesh.positions.end(),
        {2.0 * (v & 1), 2.0 * ((v >> 1) & 1), 2.0 * (v >> 2)});
  mesh.face_sizes.assign(6, 4);
  mesh.face_indices = {0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4,
                       2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5};
  return mesh;
}

TEST(Curvature, SphereGivesOneOverRSquaredAndOneOverR) {
  const double r = 2.5;
  const Mesh_buffers sphere = icosphere(4, r);  // 2562 vertices
  const Result<Vertex_curvature> c = vertex_curvature(sphere);
  ASSERT_TRUE(c.ok()) << c.status.message;
  ASSERT_EQ(c.value.gaussian.size(), 2562u);
  EXPECT_EQ(c.value.border_vertices, 0u);
  double worst_k = 0, worst_h = 0;
  for (std::size_t v = 0; v < sphere.vertex_count(); ++v) {
    worst_k = std::max(worst_k, std::abs(c.value.gaussian[v] * r * r - 1));
    worst_h = std::max(worst_h, std::abs(c.value.mean[v] * r - 1));
  }
  // Within 0.5% (K) and 0.1% (H) at every vertex, the twelve of valence 5
  // included (measured at this level: 0.14% and under 0.005%).
  EXPECT_LT(worst_k, 0.005);
  EXPECT_LT(worst_h, 0.001);
  // The mixed areas tile the surface: their sum is the mesh's area, a
  // little under the sphere's 4π r².
  EXPECT_NEAR(sum(c.value.area) / (4 * pi * r * r), 1, 0.01);
  EXPECT_NEAR(sum(c.value.angle_defect), 4 * pi, 1e-12);
}

TEST(Curvature, InwardFacesTurnTheMeanCurvatureNegative) {
  Mesh_buffers sphere = icosphere(2, 1);
  for (std::size_t f = 0; f < sphere.face_count(); ++f)
    std::swap(sphere.face_indices[3 * f + 1], sphere.face_indices[3 * f + 2]);
  const Result<Vertex_curvature> c = vertex_curvature(sphere);
  ASSERT_TRUE(c.ok());
  for (std::size_t v = 0; v < sphere.vertex_count(); ++v) {
    EXPECT_NEAR(c.value.mean[v], -1, 0.05) << v;
    EXPECT_NEAR(c.value.gaussian[v], 1, 0.1) << v;
  }
}

TEST(Curvature, FlatGridInteriorIsZeroAndBorderIsLeftOut) {
  const Mesh_buffers grid = flat_grid(4);  // 25 vertices, 9 inside
  const Result<Vertex_curvature> c = vertex_curvature(grid);
  ASSERT_TRUE(c.ok());
  EXPECT_EQ(c.value.border_vertices, 16u);
  int inside = 0;
  for (std::uint32_t j = 0; j <= 4; ++j) {
    for (std::uint32_t i = 0; i <= 4; ++i) {
      const std::size_t v = j * 5 + i;
      const bool on_border = i == 0 || j == 0 || i == 4 || j == 4;
      if (on_border) {
        EXPECT_TRUE(std::isnan(c.value.gaussian[v])) << v;
        EXPECT_TRUE(std::isnan(c.value.mean[v])) << v;
        continue;
      }
      ++inside;
      // Integer coordinates: the cotangents (0 and 1) and the angles
      // (π/2 and π/4, multiples of π/4 summed) are exact.
      EXPECT_EQ(c.value.gaussian[v], 0) << v;
      EXPECT_EQ(c.value.mean[v], 0) << v;
      EXPECT_DOUBLE_EQ(c.value.area[v], 1) << v;
    }
  }
  EXPECT_EQ(inside, 9);
}

TEST(Curvature, CubeCornersHaveDefectHalfPiAndGaussBonnetHolds) {
  const Mesh_buffers box = cube();
  const Result<Vertex_curvature> c = vertex_curvature(box);
  ASSERT_TRUE(c.ok());
  for (std::size_t v = 0; v < 8; ++v) {
    EXPECT_NEAR(c.value.angle_defect[v], pi / 2, 1e-15) << v;
    // Each right triangle (area 2) gives 1 to its right-angled corner and
    // 1/2 to the others: every face gives each of its corners 1.
    EXPECT_NEAR(c.value.area[v], 3, 1e-12) << v;
    EXPECT_NEAR(c.value.gaussian[v], pi / 6, 1e-12) << v;
  }
  // χ = 2: the defects sum to 4π.
  EXPECT_NEAR(sum(c.value.angle_defect), 4 * pi, 1e-12);
}

TEST(Curvature, GaussBonnetOnATorusSumsToZero) {
  // A 8 × 6 torus of quads (χ = 0), radii 3 and 1.
  Mesh_buffers torus;
  const std::uint32_t m = 8, k = 6;
  for (std::uint32_t i = 0; i < m; ++i) {
    for (std::uint32_t j = 0; j < k; ++j) {
      const double u = 2 * pi * i / m, w = 2 * pi * j / k;
      torus.positions.insert(torus.positions.end(),
                             {(3 + std::cos(w)) * std::cos(u),
                              (3 + std::cos(w)) * std::sin(u), std::sin(w)});
    }
  }
  for (std::uint32_t i = 0; i < m; ++i) {
    for (std::uint32_t j = 0; j < k; ++j) {
      const std::uint32_t i1 = (i + 1) % m, j1 = (j + 1) % k;
      torus.face_sizes.push_back(4);
      torus.face_indices.insert(
          torus.face_indices.end(),
          {i * k + j, i1 * k + j, i1 * k + j1, i * k + j1});
    }
  }
  const Result<Vertex_curvature> c = vertex_curvature(torus);
  ASSERT_TRUE(c.ok());
  EXPECT_EQ(c.value.border_vertices, 0u);
  EXPECT_NEAR(sum(c.value.angle_defect), 0, 1e-12);
  // Outer equator (j = 0) bends like a sphere, the inner one (j = k/2) is a
  // saddle.
  EXPECT_GT(c.value.gaussian[0], 0);
  EXPECT_LT(c.value.gaussian[k / 2], 0);
}

TEST(Curvature, AFaceNamingAMissingVertexIsRefused) {
  Mesh_buffers bad = cube();
  bad.face_indices[5] = 8;
  const Result<Vertex_curvature> c = vertex_curvature(bad);
  ASSERT_FALSE(c.ok());
  EXPECT_EQ(c.status.code, Status_code::invalid_argument);
  EXPECT_EQ(c.status.message,
            "A face names vertex 8 of a mesh with 8 vertices.");
}

}  // namespace
}  // namespace subdivlab
