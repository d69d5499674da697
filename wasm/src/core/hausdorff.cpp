#include "hausdorff.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "mesh_build.h"
#include "mesh_facts.h"

namespace subdivlab {

namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

using Triangle_tree = CGAL::AABB_tree<
    CGAL::AABB_traits<Kernel, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;

/// Each point of `points` (x, y, z a vertex) its distance to the
/// triangles of `surface`.
std::vector<double> distances_to(const std::vector<double>& points,
                                 const Mesh& surface) {
  Triangle_tree tree(faces(surface).first, faces(surface).second, surface);
  tree.accelerate_distance_queries();
  std::vector<double> d(points.size() / 3);
  for (std::size_t v = 0; v < d.size(); ++v) {
    const Point p(points[3 * v], points[3 * v + 1], points[3 * v + 2]);
    d[v] = std::sqrt(tree.squared_distance(p));
  }
  return d;
}

}  // namespace

Result<Hausdorff_distance> hausdorff_distance(const Mesh_buffers& a,
                                              const Mesh_buffers& b,
                                              double relative_error,
                                              bool vertex_distances) {
  Mesh ma, mb;
  Status s = build_mesh(a, ma);
  if (!s.ok()) return {s, {}};
  s = build_mesh(b, mb);
  if (!s.ok()) return {s, {}};
  PMP::triangulate_faces(ma);
  PMP::triangulate_faces(mb);
  Hausdorff_distance h;
  h.diagonal = bbox_diagonal({&a, &b});
  h.error_bound = std::max(relative_error * h.diagonal, 1e-12);
  h.distance =
      PMP::bounded_error_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(
          ma, mb, h.error_bound);
  if (vertex_distances) {
    h.a_to_b = distances_to(a.positions, mb);
    h.b_to_a = distances_to(b.positions, ma);
  }
  return {Status::success(), h};
}

}  // namespace subdivlab
