// Counts, topology and bounding box of a mesh.

#include "mesh_facts.h"

#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "mesh_build.h"

namespace subdivlab {
namespace {

/// Euler characteristic, genus and closedness from the counts, components
/// and boundary loops.
void derive_topology(Mesh_facts& facts) {
  facts.euler_characteristic = static_cast<long>(facts.vertices) -
                               static_cast<long>(facts.edges) +
                               static_cast<long>(facts.faces);
  facts.genus =
      (2 * static_cast<long>(facts.components) - facts.euler_characteristic -
       static_cast<long>(facts.boundaries)) /
      2;
  facts.closed = facts.boundaries == 0;
}

void count_degree(std::size_t degree, Mesh_facts& facts) {
  switch (degree) {
    case 3:
      ++facts.triangles;
      break;
    case 4:
      ++facts.quads;
      break;
    default:
      ++facts.other_faces;
      break;
  }
}

void extend_box(const double (&c)[3], bool first, Mesh_facts& facts) {
  for (int a = 0; a < 3; ++a) {
    if (first || c[a] < facts.bbox_min[a]) facts.bbox_min[a] = c[a];
    if (first || c[a] > facts.bbox_max[a]) facts.bbox_max[a] = c[a];
  }
}

}  // namespace

Mesh_facts compute_facts(const Mesh& mesh) {
  Mesh_facts facts;
  facts.vertices = mesh.number_of_vertices();
  facts.edges = mesh.number_of_edges();
  facts.faces = mesh.number_of_faces();
  if (facts.faces > 0) {
    std::vector<std::size_t> component(mesh.num_faces(), 0);
    facts.components = CGAL::Polygon_mesh_processing::connected_components(
        mesh, CGAL::make_property_map(component));
  }

  // Each boundary loop is a cycle of border halfedges; walk each once.
  std::vector<bool> seen(mesh.num_halfedges(), false);
  for (Mesh::Halfedge_index h : mesh.halfedges()) {
    if (!mesh.is_border(h) || seen[h.idx()]) continue;
    ++facts.boundaries;
    for (Mesh::Halfedge_index g = h; !seen[g.idx()]; g = mesh.next(g))
      seen[g.idx()] = true;
  }
  derive_topology(facts);

  for (Mesh::Face_index f : mesh.faces()) count_degree(mesh.degree(f), facts);
  bool first = true;
  for (Mesh::Vertex_index v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    extend_box({p.x(), p.y(), p.z()}, first, facts);
    first = false;
  }
  return facts;
}

Result<Mesh_facts> compute_facts(const Mesh_buffers& buffers) {
  Result<Mesh_facts> r;
  Mesh mesh;
  r.status = build_mesh(buffers, mesh);
  if (!r.ok()) return r;
  r.value = compute_facts(mesh);
  r.value.control_edges = buffers.control_edges.size() / 2;
  return r;
}

bool refined_facts(const Mesh_buffers& child, std::size_t edges,
                   const Mesh_facts& parent, Mesh_facts& out) {
  Mesh_facts facts;
  facts.vertices = child.vertex_count();
  facts.edges = edges;
  facts.faces = child.face_count();
  facts.components = parent.components;
  facts.boundaries = parent.boundaries;
  derive_topology(facts);
  if (facts.euler_characteristic != parent.euler_characteristic) return false;
  for (std::uint32_t degree : child.face_sizes) count_degree(degree, facts);
  const double* p = child.positions.data();
  for (std::size_t v = 0; v < facts.vertices; ++v, p += 3)
    extend_box({p[0], p[1], p[2]}, v == 0, facts);
  facts.control_edges = child.control_edges.size() / 2;
  out = facts;
  return true;
}

double bbox_diagonal(std::initializer_list<const Mesh_buffers*> meshes) {
  double lo[3] = {INFINITY, INFINITY, INFINITY},
         hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (const Mesh_buffers* m : meshes)
    for (std::size_t i = 0; i < m->positions.size(); ++i) {
      lo[i % 3] = std::min(lo[i % 3], m->positions[i]);
      hi[i % 3] = std::max(hi[i % 3], m->positions[i]);
    }
  double d = 0;
  for (int i = 0; i < 3; ++i)
    if (hi[i] > lo[i]) d += (hi[i] - lo[i]) * (hi[i] - lo[i]);
  return std::sqrt(d);
}

}  // namespace subdivlab
