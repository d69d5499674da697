// Owner of euler_ops.h.
#include "euler_ops.h"

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "mesh_build.h"

namespace subdivlab {
namespace {

using H = Mesh::Halfedge_index;
using V = Mesh::Vertex_index;

Status refused(const std::string& message) {
  return {Status_code::invalid_argument, message, 0};
}

std::string name_of(std::uint32_t h) { return "halfedge " + std::to_string(h); }

/// Why `r` cannot be applied to `m` (empty: it can). CGAL's preconditions,
/// and those that keep the result a mesh the product accepts.
std::string precondition_failure(const Mesh& m, const Euler_request& r) {
  const std::size_t n = m.number_of_halfedges();
  if (r.h >= n)
    return name_of(r.h) + " does not exist (" + std::to_string(n) +
           " halfedges)";
  const H h(r.h);
  const auto degree = [&](V v) { return m.degree(v); };
  switch (r.op) {
    case Euler_op::split_face: {
      if (r.h2 >= n) return name_of(r.h2) + " does not exist";
      const H h2(r.h2);
      if (m.is_border(h) || m.face(h) != m.face(h2))
        return name_of(r.h) + " and " + name_of(r.h2) + " are not on one face";
      if (h == h2 || m.next(h) == h2 || m.next(h2) == h)
        return "a face is split between two corners that are not neighbours";
      if (m.halfedge(m.target(h), m.target(h2)) != Mesh::null_halfedge())
        return "vertices " + std::to_string(m.target(h).idx()) + " and " +
               std::to_string(m.target(h2).idx()) +
               " are already joined by an edge";
      return {};
    }
    case Euler_op::join_face:
      if (m.is_border(h) || m.is_border(m.opposite(h)))
        return "a border edge has one face: there is nothing to join";
      if (m.face(h) == m.face(m.opposite(h)))
        return "the edge has the same face on both sides";
      if (degree(m.source(h)) < 3 || degree(m.target(h)) < 3)
        return "an end of the edge has fewer than 3 edges: joining would leave "
               "a dangling vertex";
      return {};
    case Euler_op::add_center_vertex:
      if (m.is_border(h))
        return name_of(r.h) + " is on the border: it has no face";
      return {};
    case Euler_op::remove_center_vertex: {
      const V v = m.target(h);
      if (m.is_border(v))
        return "vertex " + std::to_string(v.idx()) + " is on the border";
      if (degree(v) < 3)
        return "vertex " + std::to_string(v.idx()) + " has fewer than 3 edges";
      // CGAL's precondition: the faces around v's faces are at least two,
      // else the merged face would be glued onto the one left (a vertex of
      // a tetrahedron).
      std::vector<Mesh::Face_index> beyond;
      for (H g : CGAL::halfedges_around_target(h, m)) {
        for (H e : CGAL::halfedges_around_face(g, m)) {
          if (m.target(e) == v || m.source(e) == v) continue;
          const Mesh::Face_index f = m.face(m.opposite(e));
          if (std::find(beyond.begin(), beyond.end(), f) == beyond.end())
            beyond.push_back(f);
        }
      }
      if (beyond.size() < 2)
        return "removing vertex " + std::to_string(v.idx()) +
               " would fold its faces onto the one face left";
      return {};
    }
    case Euler_op::split_edge:
      return {};
    case Euler_op::flip_edge: {
      if (m.is_border(h) || m.is_border(m.opposite(h)))
        return "a border edge cannot be flipped";
      if (m.degree(m.face(h)) != 3 || m.degree(m.face(m.opposite(h))) != 3)
        return "only an edge between two triangles can be flipped";
      const V a = m.target(m.next(h)), b = m.target(m.next(m.opposite(h)));
      if (a == b || m.halfedge(a, b) != Mesh::null_halfedge())
        return "the far corners " + std::to_string(a.idx()) + " and " +
               std::to_string(b.idx()) + " are already joined by an edge";
      return {};
    }
  }
  return "unknown operator";
}

Point centroid(const Mesh& m, H h) {
  double x = 0, y = 0, z = 0;
  std::size_t k = 0;
  for (V v : CGAL::vertices_around_face(h, m)) {
    const Point& p = m.point(v);
    x += p.x();
    y += p.y();
    z += p.z();
    ++k;
  }
  return {x / k, y / k, z / k};
}

/// Runs `r` on `m` (preconditions checked); returns CGAL's returned halfedge.
H run(Mesh& m, const Euler_request& r) {
  const H h(r.h);
  switch (r.op) {
    case Euler_op::split_face:
      return CGAL::Euler::split_face(h, H(r.h2), m);
    case Euler_op::join_face:
      return CGAL::Euler::join_face(h, m);
    case Euler_op::add_center_vertex: {
      const Point c = centroid(m, h);
      const H out = CGAL::Euler::add_center_vertex(h, m);
      m.point(m.target(out)) = c;
      return out;
    }
    case Euler_op::remove_center_vertex:
      return CGAL::Euler::remove_center_vertex(h, m);
    case Euler_op::split_edge: {
      const Point& a = m.point(m.source(h));
      const Point& b = m.point(m.target(h));
      const Point mid((a.x() + b.x()) / 2, (a.y() + b.y()) / 2,
                      (a.z() + b.z()) / 2);
      const H out = CGAL::Euler::split_edge(h, m);
      m.point(m.target(out)) = mid;
      return out;
    }
    case Euler_op::flip_edge:
      CGAL::Euler::flip_edge(h, m);
      return h;
  }
  return h;
}

/// Rank of each live vertex in iteration order (to_buffers' numbering).
std::vector<std::uint32_t> vertex_numbers(const Mesh& m) {
  std::vector<std::uint32_t> number(m.num_vertices(), 0);
  std::uint32_t n = 0;
  for (V v : m.vertices()) number[v.idx()] = n++;
  return number;
}

}  // namespace

bool parse_euler_op(const std::string& name, Euler_op& op) {
  static const std::pair<const char*, Euler_op> names[] = {
      {"split_face", Euler_op::split_face},
      {"join_face", Euler_op::join_face},
      {"add_center_vertex", Euler_op::add_center_vertex},
      {"remove_center_vertex", Euler_op::remove_center_vertex},
      {"split_edge", Euler_op::split_edge},
      {"flip_edge", Euler_op::flip_edge}};
  for (const auto& [n, o] : names) {
    if (name == n) {
      op = o;
      return true;
    }
  }
  return false;
}

Result<Euler_result> apply_euler_op(const Mesh_buffers& buffers,
                                    const Euler_request& request) {
  Mesh m;
  const Status built = build_mesh(buffers, m);
  if (!built.ok()) return {built, {}};
  const std::string why = precondition_failure(m, request);
  if (!why.empty()) return {refused(why), {}};
  const H out = run(m, request);
  Euler_result r;
  r.valid = CGAL::is_valid_polygon_mesh(m);
  const std::vector<std::uint32_t> number = vertex_numbers(m);
  const std::uint32_t from = number[m.source(out).idx()],
                      to = number[m.target(out).idx()];
  r.mesh = to_buffers(m);
  Mesh again;
  const Status rebuilt = build_mesh(r.mesh, again);
  if (!rebuilt.ok()) {
    return {refused("the result would not be a valid mesh: " + rebuilt.message),
            {}};
  }
  r.halfedge = again.halfedge(V(from), V(to)).idx();
  r.facts = compute_facts(again);
  return {Status::success(), std::move(r)};
}

Result<Sqrt3_walk> sqrt3_by_hand(const Mesh_buffers& buffers,
                                 std::size_t steps) {
  Mesh m;
  const Status built = build_mesh(buffers, m);
  if (!built.ok()) return {built, {}};
  for (Mesh::Face_index f : m.faces()) {
    if (m.degree(f) != 3)
      return {refused("the walk-through follows the tutorial on triangle "
                      "meshes: face " +
                      std::to_string(f.idx()) + " has " +
                      std::to_string(m.degree(f)) + " corners"),
              {}};
  }
  if (!CGAL::is_closed(m))
    return {refused("the walk-through follows the tutorial on closed meshes: "
                    "this one has a border"),
            {}};
  const std::size_t faces = m.number_of_faces(), edges = m.number_of_edges(),
                    vertices = m.number_of_vertices();
  Sqrt3_walk w;
  w.total = faces + edges + vertices;
  // The old vertices' new places, from the old points: (1 − a) p + a/n Σ
  // neighbours, a = (4 − 2 cos(2π/n)) / 9, as CGAL's Sqrt3_mask_3 has it.
  std::vector<Point> smoothed(vertices);
  for (V v : m.vertices()) {
    const std::size_t n = m.degree(v);
    const double a =
        (4.0 - 2.0 * std::cos(2.0 * CGAL_PI / static_cast<double>(n))) / 9.0;
    Kernel::Vector_3 cv = (1.0 - a) * (m.point(v) - CGAL::ORIGIN);
    for (H h : CGAL::halfedges_around_target(m.halfedge(v), m))
      cv = cv +
           (a / static_cast<double>(n)) * (m.point(m.source(h)) - CGAL::ORIGIN);
    smoothed[v.idx()] = CGAL::ORIGIN + cv;
  }
  const std::vector<Mesh::Face_index> old_faces(m.faces().begin(),
                                                m.faces().end());
  const std::vector<Mesh::Edge_index> old_edges(m.edges().begin(),
                                                m.edges().end());
  const std::vector<V> old_vertices(m.vertices().begin(), m.vertices().end());
  for (Mesh::Face_index f : old_faces) {
    if (w.done == steps) break;
    const H h = m.halfedge(f);
    const Point c = centroid(m, h);
    m.point(m.target(CGAL::Euler::add_center_vertex(h, m))) = c;
    w.last = "add_center_vertex (face " + std::to_string(f.idx()) + ")";
    ++w.done;
  }
  for (Mesh::Edge_index e : old_edges) {
    if (w.done == steps) break;
    CGAL::Euler::flip_edge(m.halfedge(e), m);
    w.last = "flip_edge (edge " + std::to_string(e.idx()) + ")";
    ++w.done;
  }
  for (V v : old_vertices) {
    if (w.done == steps) break;
    m.point(v) = smoothed[v.idx()];
    w.last = "smooth vertex " + std::to_string(v.idx()) + ", valence " +
             std::to_string(m.degree(v));
    ++w.done;
  }
  w.mesh = to_buffers(m);
  return {Status::success(), std::move(w)};
}

}  // namespace subdivlab
