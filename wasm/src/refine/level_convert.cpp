#include "level_convert.h"

#include <CGAL/boost/graph/iterator.h>

namespace subdivlab {
namespace refine {

double level_bytes(double vertices, double edges, double corners, bool marks) {
  return 24 * vertices + 2 * 2 * 4 * edges + 4 * corners + (marks ? edges : 0);
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
  std::uint32_t degree = 0;
  bool uniform = true;
  for (Mesh::Face_index f : mesh.faces()) {
    l.face_offsets.push_back(l.corner_count());
    for (Mesh::Halfedge_index h :
         CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      l.halfedge_corner[h.idx()] = l.corner_count();
      l.face_halfedges.push_back(h.idx());
    }
    const std::uint32_t k = l.corner_count() - l.face_offsets.back();
    if (degree == 0) degree = k;
    uniform = uniform && k == degree;
  }
  l.face_offsets.push_back(l.corner_count());
  if (uniform) {
    l.uniform_degree = degree;
    l.face_offsets = {};
  }
  return l;
}

void mark_edges(
    const Mesh& mesh,
    const std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges,
    Level& level) {
  level.edge_marks.assign(level.edge_count, 0);
  for (const auto& [a, b] : edges) {
    const Mesh::Halfedge_index h =
        mesh.halfedge(Mesh::Vertex_index(a), Mesh::Vertex_index(b));
    if (h != Mesh::null_halfedge()) level.edge_marks[h.idx() / 2] = 1;
  }
}

Mesh_buffers level_to_buffers(Level&& level) {
  Mesh_buffers out;
  out.positions = std::move(level.positions);
  const std::uint32_t corners = level.corner_count();
  out.face_indices.resize(corners);
  const std::uint32_t* fh = level.face_halfedges.data();
  const std::uint32_t* target = level.halfedge_target.data();
  std::uint32_t* fi = out.face_indices.data();
  for (std::uint32_t c = 0; c < corners; ++c) fi[c] = target[fh[c]];
  if (level.uniform_degree != 0) {
    out.face_sizes.assign(level.face_count, level.uniform_degree);
  } else {
    out.face_sizes.resize(level.face_count);
    for (std::uint32_t f = 0; f < level.face_count; ++f)
      out.face_sizes[f] = level.face_offsets[f + 1] - level.face_offsets[f];
  }
  if (!level.edge_marks.empty()) {
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
