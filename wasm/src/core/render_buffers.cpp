// The render arrays of a mesh: fan triangles, area-weighted vertex normals
// and the polygon edges, from the flat buffers alone.

#include "render_buffers.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace subdivlab {
namespace {

/// Marks a corner whose edge an earlier corner gave.
constexpr std::uint32_t kNoEdge = 0xffffffffu;

/// The faces drawn: all of a mesh's, or those that are not holes
/// (Mesh_tags::holes), with the index each had in the mesh.
struct Faces {
  const std::vector<std::uint32_t>& sizes;
  const std::vector<std::uint32_t>& indices;
  const std::vector<std::uint32_t>* original = nullptr;  ///< null: all

  explicit Faces(const Mesh_buffers& mesh)
      : sizes(mesh.face_sizes), indices(mesh.face_indices) {}
  Faces(const std::vector<std::uint32_t>& s,
        const std::vector<std::uint32_t>& i,
        const std::vector<std::uint32_t>& o)
      : sizes(s), indices(i), original(&o) {}
};

/// Centre of the bounding box and the largest distance from it (empty: a
/// zero sphere), the radius rounded up so that the float sphere holds
/// every point.
std::vector<float> bounding_sphere(const Mesh_buffers& mesh) {
  const std::size_t n = mesh.vertex_count();
  const double* p = mesh.positions.data();
  if (n == 0) return {0, 0, 0, 0};
  double lo[3] = {p[0], p[1], p[2]}, hi[3] = {p[0], p[1], p[2]};
  for (std::size_t v = 1; v < n; ++v)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], p[3 * v + a]);
      hi[a] = std::max(hi[a], p[3 * v + a]);
    }
  const double c[3] = {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2,
                       (lo[2] + hi[2]) / 2};
  double r2 = 0;
  for (std::size_t v = 0; v < n; ++v) {
    const double x = p[3 * v] - c[0], y = p[3 * v + 1] - c[1],
                 z = p[3 * v + 2] - c[2];
    r2 = std::max(r2, x * x + y * y + z * z);
  }
  return {static_cast<float>(c[0]), static_cast<float>(c[1]),
          static_cast<float>(c[2]),
          static_cast<float>(std::sqrt(r2) * (1 + 1e-6))};
}

std::size_t fan_triangle_count(const Faces& faces) {
  std::size_t count = 0;
  for (std::uint32_t size : faces.sizes) count += size - 2;
  return count;
}

void fan_triangles(const Faces& faces, std::vector<std::uint32_t>& out) {
  out.resize(3 * fan_triangle_count(faces));
  std::uint32_t* t = out.data();
  const std::uint32_t* corner = faces.indices.data();
  for (std::uint32_t size : faces.sizes) {
    for (std::uint32_t k = 1; k + 1 < size; ++k) {
      *t++ = corner[0];
      *t++ = corner[k];
      *t++ = corner[k + 1];
    }
    corner += size;
  }
}

void triangle_faces(const Faces& faces, std::vector<std::uint32_t>& out) {
  out.resize(fan_triangle_count(faces));
  std::uint32_t* t = out.data();
  const std::uint32_t count = static_cast<std::uint32_t>(faces.sizes.size());
  for (std::uint32_t f = 0; f < count; ++f) {
    const std::uint32_t face = faces.original ? (*faces.original)[f] : f;
    for (std::uint32_t k = 2; k < faces.sizes[f]; ++k) *t++ = face;
  }
}

/// Each triangle's normal (computed in double) summed in the float output,
/// then normalized as three.js's Vector3.normalize does: a zero sum stays
/// zero. (A double sum would double the memory the scatter touches, for
/// nothing a picture shows.)
void vertex_normals(const Mesh_buffers& mesh, const Faces& faces,
                    std::vector<float>& out) {
  const std::size_t n = mesh.vertex_count();
  out.assign(3 * n, 0.0f);
  float* sum = out.data();
  const double* p = mesh.positions.data();
  const std::uint32_t* corner = faces.indices.data();
  for (std::uint32_t size : faces.sizes) {
    const std::uint32_t a = corner[0];
    for (std::uint32_t k = 1; k + 1 < size; ++k) {
      const std::uint32_t b = corner[k], c = corner[k + 1];
      // (c - b) x (a - b): the triangle's normal, twice its area long.
      const double cb[3] = {p[3 * c] - p[3 * b], p[3 * c + 1] - p[3 * b + 1],
                            p[3 * c + 2] - p[3 * b + 2]};
      const double ab[3] = {p[3 * a] - p[3 * b], p[3 * a + 1] - p[3 * b + 1],
                            p[3 * a + 2] - p[3 * b + 2]};
      const float nx = static_cast<float>(cb[1] * ab[2] - cb[2] * ab[1]);
      const float ny = static_cast<float>(cb[2] * ab[0] - cb[0] * ab[2]);
      const float nz = static_cast<float>(cb[0] * ab[1] - cb[1] * ab[0]);
      for (std::uint32_t v : {a, b, c}) {
        sum[3 * v] += nx;
        sum[3 * v + 1] += ny;
        sum[3 * v + 2] += nz;
      }
    }
    corner += size;
  }
  for (std::size_t v = 0; v < n; ++v) {
    const double x = sum[3 * v], y = sum[3 * v + 1], z = sum[3 * v + 2];
    const double length = std::sqrt(x * x + y * y + z * z);
    const double scale = length > 0 ? 1 / length : 0;
    sum[3 * v] = static_cast<float>(x * scale);
    sum[3 * v + 1] = static_cast<float>(y * scale);
    sum[3 * v + 2] = static_cast<float>(z * scale);
  }
}

/// Calls visit(a, b) for the edge from each corner a to the next one b,
/// face by face.
template <class Visit>
void for_each_corner_edge(const Faces& faces, Visit&& visit) {
  const std::uint32_t* fv = faces.indices.data();
  std::size_t at = 0;
  for (std::uint32_t size : faces.sizes) {
    for (std::uint32_t k = 0; k < size; ++k)
      visit(fv[at + k], fv[at + (k + 1 == size ? 0 : k + 1)]);
    at += size;
  }
}

/// The edges of the corners that go from a smaller to a larger vertex, in
/// corner order, when they are all `expected` edges (every edge of a closed
/// mesh has one such corner, and one only); otherwise false, `out` unset.
bool edges_going_up(const Faces& faces, std::size_t expected,
                    std::vector<std::uint32_t>& out) {
  std::size_t up = 0;
  for_each_corner_edge(
      faces, [&up](std::uint32_t a, std::uint32_t b) { up += a < b; });
  if (up != expected) return false;
  out.resize(2 * up);
  std::uint32_t* e = out.data();
  for_each_corner_edge(faces, [&e](std::uint32_t a, std::uint32_t b) {
    if (a >= b) return;
    *e++ = a;
    *e++ = b;
  });
  return true;
}

/// Marks, in polygon_edges' buckets, an edge that a second corner goes
/// along: with a border to list, vertex indices must stay below it.
constexpr std::uint32_t kPaired = 0x80000000u;

/// Every polygon edge once, bucketed by its smaller vertex: the larger
/// end of each corner's edge goes to the bucket of the smaller (a counting
/// sort, corner order kept in each bucket); a stamp per vertex says where in
/// the bucket at hand it was first seen, so that a vertex of any valence
/// costs one pass. Returns the number of edges. With `border`, also lists
/// there the edges that one corner only goes along (those met once in
/// their bucket), in the order of `out`: the border falls out of the same
/// sort. A border is listed for fewer than kPaired vertices only.
std::size_t polygon_edges(std::size_t n, const Faces& faces,
                          std::vector<std::uint32_t>& out,
                          std::vector<std::uint32_t>* border = nullptr) {
  // Calls visit(lo, hi) for the edge from each corner to the next.
  const auto each_corner_edge = [&faces](auto&& visit) {
    for_each_corner_edge(faces, [&visit](std::uint32_t a, std::uint32_t b) {
      visit(std::min(a, b), std::max(a, b));
    });
  };
  // end[lo] ends bucket lo once the corners are placed (it starts as the
  // bucket's start and moves past each corner put in it).
  std::vector<std::uint32_t> end(n + 1, 0);
  each_corner_edge([&end](std::uint32_t lo, std::uint32_t) { ++end[lo + 1]; });
  for (std::size_t v = 0; v < n; ++v) end[v + 1] += end[v];
  std::vector<std::uint32_t> larger(faces.indices.size());
  each_corner_edge([&end, &larger](std::uint32_t lo, std::uint32_t hi) {
    larger[end[lo]++] = hi;
  });
  // seen[hi] is 1 + where hi was last met: past the bucket's start, it was
  // met in this bucket, at seen[hi] - 1.
  const std::uint32_t paired = border != nullptr ? kPaired : 0;
  std::vector<std::uint32_t> seen(n, 0);
  std::size_t edges = 0;
  for (std::size_t lo = 0, i = 0; lo < n; ++lo) {
    const std::uint32_t start = static_cast<std::uint32_t>(i);
    for (; i < end[lo]; ++i) {
      const std::uint32_t hi = larger[i];
      if (seen[hi] > start) {
        larger[seen[hi] - 1] |= paired;
        larger[i] = kNoEdge;
        continue;
      }
      seen[hi] = static_cast<std::uint32_t>(i) + 1;
      ++edges;
    }
  }
  std::vector<std::uint32_t>().swap(seen);
  out.resize(2 * edges);
  if (border != nullptr) border->clear();
  std::uint32_t* e = out.data();
  for (std::size_t lo = 0, i = 0; lo < n; ++lo) {
    for (; i < end[lo]; ++i) {
      if (larger[i] == kNoEdge) continue;
      const std::uint32_t hi = larger[i] & ~paired;
      *e++ = static_cast<std::uint32_t>(lo);
      *e++ = hi;
      if (border != nullptr && (larger[i] & kPaired) == 0)
        border->insert(border->end(), {static_cast<std::uint32_t>(lo), hi});
    }
  }
  return edges;
}

/// The edges of `edges` (smaller vertex first) that only one corner of
/// `faces` goes along: the border. Each face's corner edges are bucketed by
/// their smaller vertex as polygon_edges does; an edge met once in its
/// bucket is on the border. (`edges` may be fewer than the edges of
/// `faces`: those of the faces drawn, holes left out.)
void border_edges(std::size_t n, const Faces& faces,
                  const std::vector<std::uint32_t>& edges,
                  std::vector<std::uint32_t>& out) {
  out.clear();
  std::vector<std::uint32_t> end(n + 1, 0);
  for_each_corner_edge(faces, [&end](std::uint32_t a, std::uint32_t b) {
    ++end[std::min(a, b) + 1];
  });
  for (std::size_t v = 0; v < n; ++v) end[v + 1] += end[v];
  std::vector<std::uint32_t> larger(faces.indices.size());
  {
    std::vector<std::uint32_t> fill(end.begin(), end.end() - 1);
    for_each_corner_edge(faces, [&](std::uint32_t a, std::uint32_t b) {
      larger[fill[std::min(a, b)]++] = std::max(a, b);
    });
  }
  for (std::size_t i = 0; i < edges.size(); i += 2) {
    const std::uint32_t lo = edges[i], hi = edges[i + 1];
    std::uint32_t corners = 0;
    for (std::uint32_t j = end[lo]; j < end[lo + 1]; ++j)
      corners += larger[j] == hi;
    if (corners == 1) out.insert(out.end(), {lo, hi});
  }
}

}  // namespace

std::size_t build_render_buffers(const Mesh_buffers& mesh, Render_sink& sink,
                                 std::size_t expected_edges) {
  {
    std::vector<float> positions(mesh.positions.begin(), mesh.positions.end());
    sink.floats(Render_array::positions, positions);
  }
  sink.floats(Render_array::bounding_sphere, bounding_sphere(mesh));
  // Holes shape their neighbours but are not drawn: the picture has the
  // other faces, their normals and their edges (the count returned is
  // still the mesh's).
  std::vector<std::uint32_t> shown_sizes, shown_indices, original;
  if (!mesh.tags.holes.empty()) {
    std::vector<std::uint8_t> hole(mesh.face_count(), 0);
    for (std::uint32_t f : mesh.tags.holes)
      if (f < hole.size()) hole[f] = 1;
    std::size_t o = 0;
    for (std::uint32_t f = 0; f < mesh.face_count(); ++f) {
      const std::uint32_t k = mesh.face_sizes[f];
      if (hole[f] == 0) {
        shown_sizes.push_back(k);
        shown_indices.insert(shown_indices.end(), mesh.face_indices.begin() + o,
                             mesh.face_indices.begin() + o + k);
        original.push_back(f);
      }
      o += k;
    }
  }
  const Faces all(mesh);
  const Faces faces = mesh.tags.holes.empty()
                          ? all
                          : Faces(shown_sizes, shown_indices, original);
  {
    std::vector<float> normals;
    vertex_normals(mesh, faces, normals);
    sink.floats(Render_array::normals, normals);
  }
  {
    std::vector<std::uint32_t> triangles;
    fan_triangles(faces, triangles);
    sink.indices(Render_array::triangles, triangles);
  }
  {
    std::vector<std::uint32_t> triangle_face;
    triangle_faces(faces, triangle_face);
    sink.indices(Render_array::triangle_face, triangle_face);
  }
  // The edges drawn, and among them those of one face of the whole mesh.
  const std::size_t n = mesh.vertex_count();
  std::vector<std::uint32_t> edges, border;
  std::size_t count = 0;
  if (faces.original != nullptr) {
    count = polygon_edges(n, all, edges);
    polygon_edges(n, faces, edges);
    // Closed (every edge of the whole mesh has two corners): no border.
    if (all.indices.size() != 2 * count) border_edges(n, all, edges, border);
  } else if (expected_edges > 0 && faces.indices.size() == 2 * expected_edges &&
             edges_going_up(faces, expected_edges, edges)) {
    count = expected_edges;  // closed: no border
  } else if (n < kPaired) {
    count = polygon_edges(n, faces, edges, &border);
  } else {
    count = polygon_edges(n, faces, edges);
    border_edges(n, all, edges, border);
  }
  sink.indices(Render_array::edges, edges);
  sink.indices(Render_array::border_edges, border);
  return count;
}

double render_peak_bytes(double vertices, double edges, double corners,
                         double triangles) {
  // One array at a time: float positions, then float normals summed in
  // place; the fan; the edges (polygon_edges' bucket ends and larger ends
  // beside its output, its stamps freed before the output is made).
  const double floats = 12 * vertices;
  const double fan = 12 * triangles;
  const double edge_list = 4 * corners + 4 * vertices + 8 * edges;
  return std::max({floats, fan, edge_list});
}

Render_buffers render_buffers(const Mesh_buffers& mesh) {
  struct Collect : Render_sink {
    Render_buffers out;
    void floats(Render_array which, const std::vector<float>& v) override {
      if (which == Render_array::positions)
        out.positions = v;
      else if (which == Render_array::bounding_sphere)
        out.bounding_sphere = v;
      else
        out.normals = v;
    }
    void indices(Render_array which,
                 const std::vector<std::uint32_t>& v) override {
      if (which == Render_array::triangles)
        out.triangles = v;
      else if (which == Render_array::triangle_face)
        out.triangle_face = v;
      else if (which == Render_array::edges)
        out.edges = v;
      else
        out.border_edges = v;
    }
  } collect;
  build_render_buffers(mesh, collect);
  return std::move(collect.out);
}

}  // namespace subdivlab
