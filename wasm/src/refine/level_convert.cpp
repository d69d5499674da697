#include "level_convert.h"

#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <utility>

#include "core/mesh_check.h"

namespace subdivlab {
namespace refine {

double level_bytes(double vertices, double edges, double corners, bool marks,
                   bool last) {
  // Not on the last level: the halfedges of the corners, the halfedges'
  // corners and targets, and the marks.
  const double halfedge_tables = 4 * corners + 2 * 4 * edges + 2 * 4 * edges;
  return 24 * vertices + 4 * corners +
         (last ? 0 : halfedge_tables + (marks ? edges : 0));
}

Level level_from_mesh(const Mesh& mesh) {
  Level l;
  l.vertex_count = static_cast<std::uint32_t>(mesh.number_of_vertices());
  l.edge_count = static_cast<std::uint32_t>(mesh.number_of_edges());
  l.face_count = static_cast<std::uint32_t>(mesh.number_of_faces());
  l.positions.resize(3 * std::size_t{l.vertex_count});
  for (Mesh::Vertex_index v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    double* out = &l.positions[3 * std::size_t{v.idx()}];
    out[0] = p.x();
    out[1] = p.y();
    out[2] = p.z();
  }
  const std::uint32_t halfedges = 2 * l.edge_count;
  l.halfedge_target.resize(halfedges);
  l.halfedge_corner.assign(halfedges, kNone);
  for (Mesh::Halfedge_index h : mesh.halfedges()) {
    l.halfedge_target[h.idx()] = mesh.target(h).idx();
    if (mesh.is_border(h)) ++l.border_edge_count;
  }
  l.face_offsets.reserve(std::size_t{l.face_count} + 1);
  l.face_halfedges.reserve(halfedges - l.border_edge_count);
  l.face_vertices.reserve(halfedges - l.border_edge_count);
  std::uint32_t degree = 0;
  bool uniform = true;
  for (Mesh::Face_index f : mesh.faces()) {
    l.face_offsets.push_back(l.corner_count());
    for (Mesh::Halfedge_index h :
         CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      l.halfedge_corner[h.idx()] = l.corner_count();
      l.face_halfedges.push_back(h.idx());
      l.face_vertices.push_back(mesh.target(h).idx());
    }
    const std::uint32_t k = l.corner_count() - l.face_offsets.back();
    if (degree == 0) degree = k;
    uniform = uniform && k == degree;
  }
  l.face_offsets.push_back(l.corner_count());
  if (uniform) {
    l.uniform_degree = degree;
    release(l.face_offsets);
  }
  return l;
}

namespace {

/// level_from_buffers' corner tables, with `vertex` giving each input
/// vertex's index in the level; the face offsets only on a level that has
/// them (mixed degrees). On a closed level every halfedge is a corner's,
/// whose target it is given; a border halfedge's comes from the other side.
template <class Vertex>
void fill_corners(const Mesh_buffers& in,
                  const std::vector<std::uint32_t>& corner_halfedges,
                  Vertex&& vertex, Level& l) {
  const bool closed = l.border_edge_count == 0;
  const std::uint32_t* idx = in.face_indices.data();
  const std::uint32_t* sizes = in.face_sizes.data();
  std::uint32_t* face_halfedges = l.face_halfedges.data();
  std::uint32_t* face_vertices = l.face_vertices.data();
  std::uint32_t* corner = l.halfedge_corner.data();
  std::uint32_t* target = l.halfedge_target.data();
  std::uint32_t* offsets =
      l.face_offsets.empty() ? nullptr : l.face_offsets.data();
  std::uint32_t o = 0;
  for (std::uint32_t f = 0; f < l.face_count; ++f) {
    const std::uint32_t k = sizes[f];
    if (offsets != nullptr) offsets[f] = o;
    // Surface_mesh::add_face starts the face at its last corner's halfedge:
    // corner j of the level is the input's corner j - 1, which ends at j.
    for (std::uint32_t j = 0; j < k; ++j) {
      const std::uint32_t from = o + (j == 0 ? k - 1 : j - 1);
      const std::uint32_t h = corner_halfedges[from];
      const std::uint32_t v = vertex(idx[o + j]);
      face_halfedges[o + j] = h;
      corner[h] = o + j;
      face_vertices[o + j] = v;
      target[h] = v;
      if (!closed) target[h ^ 1] = vertex(idx[from]);
    }
    o += k;
  }
  if (offsets != nullptr) offsets[l.face_count] = o;
}

}  // namespace

Level level_from_buffers(const Mesh_buffers& in,
                         const std::vector<std::uint32_t>& corner_halfedges) {
  Level l;
  const std::size_t nv = in.vertex_count();
  std::uint32_t used = 0;
  std::vector<std::uint32_t> rank = detail::used_vertex_ranks(in, used);
  l.vertex_count = used;
  // Every vertex used (nearly always): the level keeps the input's indices.
  const bool all_used = used == nv;
  if (all_used) {
    release(rank);
    l.positions = in.positions;
  } else {
    l.positions.resize(3 * std::size_t{used});
    for (std::size_t v = 0; v < nv; ++v) {
      if (rank[v] == kNone) continue;
      for (int i = 0; i < 3; ++i)
        l.positions[3 * std::size_t{rank[v]} + i] = in.positions[3 * v + i];
    }
  }
  std::uint32_t edges = 0;
  for (std::uint32_t h : corner_halfedges) edges += (h & 1) == 0;
  l.edge_count = edges;
  l.face_count = static_cast<std::uint32_t>(in.face_count());
  const std::uint32_t corners =
      static_cast<std::uint32_t>(corner_halfedges.size());
  l.border_edge_count = 2 * edges - corners;
  l.uniform_degree = in.uniform_face_degree();
  if (l.uniform_degree == 0)
    l.face_offsets.resize(std::size_t{l.face_count} + 1);
  l.halfedge_target.resize(2 * std::size_t{edges});
  // Every halfedge of a closed level is a corner's.
  if (l.border_edge_count == 0)
    l.halfedge_corner.resize(2 * std::size_t{edges});
  else
    l.halfedge_corner.assign(2 * std::size_t{edges}, kNone);
  l.face_halfedges.resize(corners);
  l.face_vertices.resize(corners);
  if (all_used)
    fill_corners(
        in, corner_halfedges, [](std::uint32_t v) { return v; }, l);
  else
    fill_corners(
        in, corner_halfedges, [&](std::uint32_t v) { return rank[v]; }, l);
  return l;
}

void vertex_valences(const Level& level, std::vector<std::uint32_t>& valence,
                     std::vector<bool>& border) {
  valence.assign(level.vertex_count, 0);
  border.assign(level.vertex_count, false);
  const std::uint32_t* t = level.halfedge_target.data();
  const std::uint32_t halfedges = 2 * level.edge_count;
  std::uint32_t* count = valence.data();
  for (std::uint32_t h = 0; h < halfedges; ++h) ++count[t[h]];
  if (level.border_edge_count == 0) return;
  const std::uint32_t* corner = level.halfedge_corner.data();
  for (std::uint32_t h = 0; h < halfedges; ++h)
    if (corner[h] == kNone) border[t[h]] = true;
}

void vertex_halfedges(const Level& level, Vertex_halfedges& r) {
  const std::uint32_t V = level.vertex_count, halfedges = 2 * level.edge_count;
  const std::uint32_t* t = level.halfedge_target.data();
  size_to(r.begin, std::size_t{V} + 1);
  std::fill(r.begin.begin(), r.begin.end(), 0);
  for (std::uint32_t h = 0; h < halfedges; ++h) ++r.begin[t[h ^ 1] + 1];
  for (std::uint32_t v = 0; v < V; ++v) r.begin[v + 1] += r.begin[v];
  size_to(r.halfedges, halfedges);
  // Each run is filled from its start, which moves to the next run's; the
  // starts are then moved back.
  for (std::uint32_t h = 0; h < halfedges; ++h)
    r.halfedges[r.begin[t[h ^ 1]]++] = h;
  for (std::uint32_t v = V; v > 0; --v) r.begin[v] = r.begin[v - 1];
  r.begin[0] = 0;
}

Vertex_halfedges vertex_halfedges(const Level& level) {
  Vertex_halfedges r;
  vertex_halfedges(level, r);
  return r;
}

std::uint32_t Vertex_halfedges::edge(const Level& level, std::uint32_t a,
                                     std::uint32_t b) const {
  if (a >= level.vertex_count || b >= level.vertex_count) return kNone;
  for (std::uint32_t i = begin[a]; i < begin[a + 1]; ++i)
    if (level.halfedge_target[halfedges[i]] == b) return halfedges[i] / 2;
  return kNone;
}

Mesh_buffers level_to_buffers(Level&& level) {
  Mesh_buffers out;
  out.positions = std::move(level.positions);
  out.face_indices = std::move(level.face_vertices);
  const std::uint32_t* target = level.halfedge_target.data();
  if (level.uniform_degree != 0) {
    out.face_sizes.assign(level.face_count, level.uniform_degree);
  } else {
    out.face_sizes.resize(level.face_count);
    for (std::uint32_t f = 0; f < level.face_count; ++f)
      out.face_sizes[f] = level.face_offsets[f + 1] - level.face_offsets[f];
  }
  if (!level.marked_ends.empty()) {
    out.control_edges = std::move(level.marked_ends);
  } else if (!level.edge_marks.empty()) {
    std::size_t marked = 0;
    for (std::uint8_t m : level.edge_marks) marked += m;
    out.control_edges.reserve(2 * marked);
    for (std::uint32_t e = 0; e < level.edge_count; ++e) {
      if (level.edge_marks[e] == 0) continue;
      out.control_edges.push_back(target[2 * e + 1]);
      out.control_edges.push_back(target[2 * e]);
    }
  }
  return out;
}

}  // namespace refine
}  // namespace subdivlab
