// Discrete curvature (curvature.h): one pass over the fan triangles for the
// angles, mixed areas, cotangent Laplacian and normals, one over the
// corners for the border.
#include "curvature.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace subdivlab {
namespace {

using Vec = std::array<double, 3>;

Vec sub(const Vec& a, const Vec& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
double dot(const Vec& a, const Vec& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
          a[0] * b[1] - a[1] * b[0]};
}

/// Marks the vertices on the border: a vertex with an edge a→b whose twin
/// b→a no face has. Outgoing edges are listed per vertex (a counting
/// sort), and each edge looks for its twin among its head's few.
std::vector<std::uint8_t> border_marks(const Mesh_buffers& mesh) {
  const std::size_t n = mesh.vertex_count();
  std::vector<std::uint32_t> start(n + 1, 0);
  const auto each_edge = [&mesh](auto&& visit) {
    std::size_t at = 0;
    for (std::uint32_t size : mesh.face_sizes) {
      for (std::uint32_t k = 0; k < size; ++k)
        visit(mesh.face_indices[at + k],
              mesh.face_indices[at + (k + 1 == size ? 0 : k + 1)]);
      at += size;
    }
  };
  each_edge([&start](std::uint32_t a, std::uint32_t) { ++start[a + 1]; });
  for (std::size_t v = 0; v < n; ++v) start[v + 1] += start[v];
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  std::vector<std::uint32_t> heads(mesh.face_indices.size());
  each_edge([&](std::uint32_t a, std::uint32_t b) { heads[fill[a]++] = b; });
  std::vector<std::uint8_t> border(n, 0);
  for (std::uint32_t a = 0; a < n; ++a) {
    for (std::uint32_t i = start[a]; i < start[a + 1]; ++i) {
      const std::uint32_t b = heads[i];
      bool twin = false;
      for (std::uint32_t j = start[b]; j < start[b + 1] && !twin; ++j)
        twin = heads[j] == a;
      if (!twin) border[a] = border[b] = 1;
    }
  }
  return border;
}

}  // namespace

Result<Vertex_curvature> vertex_curvature(const Mesh_buffers& mesh) {
  Result<Vertex_curvature> result;
  const std::size_t n = mesh.vertex_count();
  for (std::uint32_t v : mesh.face_indices) {
    if (v >= n) {
      result.status = {Status_code::invalid_argument,
                       "A face names vertex " + std::to_string(v) +
                           " of a mesh with " + std::to_string(n) +
                           " vertices.",
                       0};
      return result;
    }
  }
  const auto point = [&mesh](std::uint32_t v) -> Vec {
    return {mesh.positions[3 * v], mesh.positions[3 * v + 1],
            mesh.positions[3 * v + 2]};
  };
  std::vector<double> angles(n, 0), area(n, 0);
  std::vector<Vec> laplacian(n, Vec{0, 0, 0}), normal(n, Vec{0, 0, 0});
  std::size_t at = 0;
  for (std::uint32_t size : mesh.face_sizes) {
    for (std::uint32_t k = 1; k + 1 < size; ++k) {
      const std::array<std::uint32_t, 3> t = {mesh.face_indices[at],
                                              mesh.face_indices[at + k],
                                              mesh.face_indices[at + k + 1]};
      const std::array<Vec, 3> p = {point(t[0]), point(t[1]), point(t[2])};
      const Vec n2 = cross(sub(p[1], p[0]), sub(p[2], p[0]));
      const double twice_area = std::sqrt(dot(n2, n2));
      std::array<double, 3> angle{}, cot{};
      for (int c = 0; c < 3; ++c) {
        const Vec u = sub(p[(c + 1) % 3], p[c]);
        const Vec w = sub(p[(c + 2) % 3], p[c]);
        // |u × w| is twice the area at every corner; atan2 keeps small and
        // near-straight angles accurate where acos would not.
        angle[c] = std::atan2(twice_area, dot(u, w));
        cot[c] = dot(u, w) / twice_area;
        angles[t[c]] += angle[c];
        for (int i = 0; i < 3; ++i) normal[t[c]][i] += n2[i];
      }
      if (twice_area == 0) continue;  // no area, and no cotangents
      const double half_pi = std::acos(-1.0) / 2;
      const bool obtuse =
          angle[0] > half_pi || angle[1] > half_pi || angle[2] > half_pi;
      for (int c = 0; c < 3; ++c) {
        const int a = (c + 1) % 3, b = (c + 2) % 3;
        // Edge a-b is opposite corner c: weight cot c on both its ends.
        const Vec ab = sub(p[a], p[b]);
        for (int i = 0; i < 3; ++i) {
          laplacian[t[a]][i] += cot[c] * ab[i];
          laplacian[t[b]][i] -= cot[c] * ab[i];
        }
        if (obtuse) {
          area[t[c]] += twice_area / (angle[c] > half_pi ? 4 : 8);
        } else {
          // Voronoi part at c: (|ca|² cot b + |cb|² cot a) / 8.
          const Vec ca = sub(p[a], p[c]), cb = sub(p[b], p[c]);
          area[t[c]] += (dot(ca, ca) * cot[b] + dot(cb, cb) * cot[a]) / 8;
        }
      }
    }
    at += size;
  }
  const std::vector<std::uint8_t> border = border_marks(mesh);
  Vertex_curvature& out = result.value;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  out.angle_defect.assign(n, nan);
  out.area.assign(n, nan);
  out.gaussian.assign(n, nan);
  out.mean.assign(n, nan);
  const double two_pi = 2 * std::acos(-1.0);
  for (std::size_t v = 0; v < n; ++v) {
    if (border[v] != 0) {
      ++out.border_vertices;
      continue;
    }
    if (!(area[v] > 0)) continue;
    out.angle_defect[v] = two_pi - angles[v];
    out.area[v] = area[v];
    out.gaussian[v] = out.angle_defect[v] / area[v];
    const double length = std::sqrt(dot(normal[v], normal[v]));
    if (length > 0)
      out.mean[v] = dot(laplacian[v], normal[v]) / length / (4 * area[v]);
  }
  return result;
}

}  // namespace subdivlab
