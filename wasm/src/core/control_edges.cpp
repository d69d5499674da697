#include "control_edges.h"

#include <CGAL/boost/graph/iterator.h>

#include "scheme_table.h"

namespace subdivlab {
namespace {

Mesh::Vertex_index vertex(std::uint32_t i) { return Mesh::Vertex_index(i); }

}  // namespace

bool scheme_keeps_control_edges(const Subdivide_options& o) {
  const Host_info* host = detail::host_of(o);
  return host != nullptr && host->keeps_control_edges;
}

Result<Control_edges> initial_control_edges(const Mesh_buffers& in,
                                            const Mesh& mesh, int start_level) {
  return initial_control_edges(
      in, mesh.num_edges(),
      [&](std::uint32_t a, std::uint32_t b) {
        const Mesh::Halfedge_index h = mesh.halfedge(vertex(a), vertex(b));
        return h == Mesh::null_halfedge() ? kNoEdge
                                          : std::uint32_t{mesh.edge(h).idx()};
      },
      start_level);
}

Result<Control_edges> initial_control_edges(const Mesh_buffers& in,
                                            std::size_t edge_count,
                                            const Edge_finder& edge_of,
                                            int start_level) {
  Result<Control_edges> r;
  // build_mesh numbers the vertices that faces use, in their buffer order.
  const std::size_t nv = in.vertex_count();
  std::vector<std::uint32_t> rank(nv, 0xffffffffu);
  for (std::uint32_t v : in.face_indices)
    if (v < nv) rank[v] = 0;
  std::uint32_t next = 0;
  for (std::size_t v = 0; v < nv; ++v)
    if (rank[v] == 0) rank[v] = next++;
  if (in.control_edges.empty()) {
    if (start_level != 0) return r;
    // The edges of the faces as given, so that a mesh triangulated before
    // the first step keeps its polygon edges only. A bit per mesh edge
    // finds the duplicates (the memory model counts 8 bytes per mark).
    std::vector<bool> seen(edge_count, false);
    std::size_t o = 0;
    for (std::uint32_t k : in.face_sizes) {
      for (std::uint32_t i = 0; i < k; ++i) {
        const std::uint32_t a = rank[in.face_indices[o + i]];
        const std::uint32_t b = rank[in.face_indices[o + (i + 1) % k]];
        const std::uint32_t e = edge_of(a, b);
        if (e == kNoEdge || seen[e]) continue;
        seen[e] = true;
        r.value.emplace_back(a, b);
      }
      o += k;
    }
    return r;
  }
  auto fail = [&](const std::string& m) {
    r.status = Status::error(Status_code::invalid_argument, m);
    r.value.clear();
    return r;
  };
  if (in.control_edges.size() % 2 != 0)
    return fail("control edges must come in pairs of vertex indices (got " +
                std::to_string(in.control_edges.size()) + " numbers)");
  r.value.reserve(in.control_edges.size() / 2);
  // A repeated edge would be refined, counted and drawn twice.
  std::vector<bool> seen(edge_count, false);
  for (std::size_t i = 0; i < in.control_edges.size(); i += 2) {
    const std::uint32_t a = in.control_edges[i], b = in.control_edges[i + 1];
    // Named only when refused: a level's hundreds of thousands of edges
    // would spend more on the names than on the checks.
    const auto refuse = [&](const char* why) {
      return fail("control edge " + std::to_string(i / 2) + " (" +
                  std::to_string(a) + ", " + std::to_string(b) + ") " + why);
    };
    if (a >= nv || b >= nv || rank[a] == 0xffffffffu || rank[b] == 0xffffffffu)
      return refuse("names a vertex that is not in the mesh");
    const std::uint32_t e = edge_of(rank[a], rank[b]);
    if (e == kNoEdge) return refuse("is not an edge of the mesh");
    if (seen[e]) return refuse("repeats an earlier control edge");
    seen[e] = true;
    r.value.emplace_back(rank[a], rank[b]);
  }
  return r;
}

Control_edges refine_control_edges(const Mesh& refined,
                                   std::uint32_t old_vertex_end,
                                   const Control_edges& parents) {
  Control_edges children;
  children.reserve(2 * parents.size());
  for (const auto& [a, b] : parents) {
    const Mesh::Vertex_index va = vertex(a), vb = vertex(b);
    for (Mesh::Vertex_index m :
         CGAL::vertices_around_target(refined.halfedge(va), refined)) {
      if (m.idx() < old_vertex_end) continue;
      if (refined.halfedge(m, vb) == Mesh::null_halfedge()) continue;
      children.emplace_back(a, m.idx());
      children.emplace_back(m.idx(), b);
      break;
    }
  }
  return children;
}

std::vector<std::uint32_t> control_edges_to_buffers(
    const Mesh& mesh, const Control_edges& edges) {
  std::vector<std::uint32_t> number(mesh.num_vertices(), 0xffffffffu);
  std::uint32_t n = 0;
  for (Mesh::Vertex_index v : mesh.vertices()) number[v.idx()] = n++;
  std::vector<std::uint32_t> out;
  out.reserve(2 * edges.size());
  for (const auto& [a, b] : edges) {
    out.push_back(number[a]);
    out.push_back(number[b]);
  }
  return out;
}

}  // namespace subdivlab
