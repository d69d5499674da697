// Quad/Triangle subdivision (Stam & Loop, "Quad/Triangle Subdivision",
// Computer Graphics Forum 22(1), 2003; A. Levin & D. Levin's 2003 analysis
// of the regular quad/triangle boundary) written as a CGAL
// Subdivision_method_3 host (connectivity) and mask (geometry).
//
// One step is a linear refinement followed by one averaging pass:
//  - refinement (host PQT_1step): every edge gets its midpoint; a triangle is
//    split 1 -> 4 by its edge midpoints (as CGAL's PTQ host does), any other
//    polygon is split into quads around its centroid (as CGAL's PQQ host
//    does), so after one step the mesh holds only triangles and quads. Old
//    vertices keep their indices, new ones are appended (edge points in edge
//    order, then face points in face order), exactly as CGAL's hosts number
//    them; control edges and the reduction tests rely on that.
//  - averaging (mask vertex_node / border_node, read on the refined mesh):
//    an interior vertex v with ne edges and nq incident quads goes to
//        A = alpha (v + 1/2 sum(edge neighbours) + 1/4 sum(opposite quad
//        corners)), alpha = 1 / (1 + ne/2 + nq/4),
//    then the correction  v' = v + lambda (A - v).
//
// The correction. lambda = 1 at regular configurations: 4 quads, 6 triangles,
// or any mix whose corner angles (quad 90 deg, triangle 60 deg) add up to 360
// deg (2 quads + 3 triangles, the regular quad/triangle boundary). At an
// all-quad vertex of valence n, lambda_q(n) = (4 + 3n) / n^2 makes the step
// exactly Catmull-Clark's vertex rule ((n-2)/n v + 1/n^2 sum(edge neighbours +
// face points)); at an all-triangle vertex of valence n, lambda_t(n) = (4 +
// 2n) c(n) / n with c(n) = 5/8 - (3 + 2 cos(2 pi / n))^2 / 64 makes it exactly
// Loop's (1 - c(n)) v + c(n)/n sum(neighbours). The paper derives its own
// weights for mixed extraordinary vertices from an eigen-analysis that is not
// reproduced here; SubdivLab instead blends the two pure rules by corner
// count, each evaluated at the valence that spans the same total angle:
//        lambda = (nq lambda_q(s/3) + nt lambda_t(s/2)) / (nq + nt),
//        s = 3 nq + 2 nt   (the angle sum in units of 30 deg),
// which is 1 at every regular configuration, equals Catmull-Clark on all-quad
// meshes and Loop on all-triangle meshes of any valence (tests/core/
// test_extra.cpp checks both against CGAL's masks), and is a convex blend of
// two stable rules elsewhere.
//
// Border vertices (smooth_boundary = true) move to 1/4 prev + 1/2 v + 1/4 next
// along the refined border: the cubic B-spline rule, the same as CGAL's
// Catmull-Clark and Loop border masks (old border vertex (1, 6, 1)/8, border
// edge point at the midpoint). With smooth_boundary = false they keep their
// refined (linear) positions, so the border polygon does not change.
//
// The weights (1, 1/2, 1/4, lambda, the border's 1/4, 1/2, 1/4) are defined
// once, in refine/primal_masks.h (Quad_triangle_mask): this mask and the
// fast PQT host (refine/primal_hosts.h, refine/primal_points.h) read them.
#pragma once

#include <CGAL/Subdivision_method_3/internal/subdivision_hosts_impl_3.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/circulator.h>

#include <cmath>
#include <cstddef>
#include <vector>

#include "refine/primal_masks.h"

namespace subdivlab {

using refine::quad_triangle_relaxation;

/// Geometry mask of quad/triangle subdivision, for the host PQT_1step.
/// face_node and edge_node are the linear refinement (read on the control
/// mesh); vertex_node and border_node are the averaging (read on the refined
/// mesh, before any vertex has moved).
template <class PolygonMesh,
          class VertexPointMap = typename boost::property_map<
              PolygonMesh, CGAL::vertex_point_t>::type>
class Quad_triangle_mask_3 {
 public:
  typedef PolygonMesh Mesh;
  typedef
      typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor
      halfedge_descriptor;
  typedef typename boost::graph_traits<Mesh>::face_descriptor face_descriptor;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel Kernel;
  typedef typename Kernel::FT FT;
  typedef typename Kernel::Vector_3 Vector;

  Mesh* pmesh;
  VertexPointMap vpmap;
  refine::Quad_triangle_mask weights;

  Quad_triangle_mask_3(Mesh* pmesh, bool smooth_boundary = true)
      : pmesh(pmesh), vpmap(get(CGAL::vertex_point, *pmesh)) {
    weights.smooth_boundary = smooth_boundary;
  }
  Quad_triangle_mask_3(Mesh* pmesh, VertexPointMap vpmap,
                       bool smooth_boundary = true)
      : pmesh(pmesh), vpmap(vpmap) {
    weights.smooth_boundary = smooth_boundary;
  }

  /// Refinement: centroid of a face that is not a triangle.
  void face_node(face_descriptor f, Point& pt) {
    Vector s(0, 0, 0);
    int n = 0;
    for (vertex_descriptor v :
         vertices_around_face(halfedge(f, *pmesh), *pmesh)) {
      s = s + (get(vpmap, v) - CGAL::ORIGIN);
      ++n;
    }
    pt = CGAL::ORIGIN + s / FT(n);
  }

  /// Refinement: midpoint of an edge.
  void edge_node(halfedge_descriptor h, Point& pt) {
    pt = CGAL::midpoint(get(vpmap, source(h, *pmesh)),
                        get(vpmap, target(h, *pmesh)));
  }

  /// Averaging of an interior vertex of the refined mesh.
  void vertex_node(vertex_descriptor v, Point& pt) {
    const Mesh& m = *pmesh;
    const Vector s = get(vpmap, v) - CGAL::ORIGIN;
    Vector ring(0, 0, 0), opposite_corners(0, 0, 0);
    std::size_t ne = 0, nq = 0;
    for (halfedge_descriptor h : halfedges_around_target(v, m)) {
      ring = ring + (get(vpmap, source(h, m)) - CGAL::ORIGIN);
      ++ne;
      // h runs u -> v inside face(h); in a quad the corner opposite v is the
      // target of next(next(h)).
      const halfedge_descriptor h2 = next(next(h, m), m);
      if (next(next(h2, m), m) == h) {
        opposite_corners =
            opposite_corners + (get(vpmap, target(h2, m)) - CGAL::ORIGIN);
        ++nq;
      }
    }
    // Interior: one face per edge, so the triangles are the other faces.
    const refine::Quad_triangle_mask::Averaging w = weights.averaging(
        static_cast<std::uint32_t>(ne), static_cast<std::uint32_t>(nq));
    const Vector a = w.alpha * (weights.self * s + weights.ring * ring +
                                weights.opposite * opposite_corners);
    pt = CGAL::ORIGIN + (s + w.lambda * (a - s));
  }

  /// Averaging of a border vertex; `h` is the border halfedge ending at it.
  void border_node(halfedge_descriptor h, Point& pt) {
    const Mesh& m = *pmesh;
    const Point& p = get(vpmap, target(h, m));
    if (!weights.smooth_boundary) {
      pt = p;
      return;
    }
    const Vector prev = get(vpmap, source(h, m)) - CGAL::ORIGIN;
    const Vector next_v = get(vpmap, target(next(h, m), m)) - CGAL::ORIGIN;
    const auto& b = weights.border;
    pt = CGAL::ORIGIN +
         (b[0] * prev + b[1] * (p - CGAL::ORIGIN) + b[2] * next_v);
  }
};

/// The primal quad/triangle quadrisection host: linear refinement of mixed
/// meshes (triangles 1 -> 4 as PTQ, other faces into quads as PQQ) followed
/// by the averaging pass of `mask`. Written after CGAL's internal PQQ_1step /
/// PTQ_1step so that a mesh of only quads (only triangles) gets exactly their
/// connectivity and vertex numbering.
/// Precondition: `p` is a valid polygon mesh without garbage.
template <class Poly, class VertexPointMap, class Mask>
void PQT_1step(Poly& p, VertexPointMap vpm, Mask mask) {
  namespace SM = CGAL::Subdivision_method_3::internal;
  typedef
      typename boost::graph_traits<Poly>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<Poly>::halfedge_descriptor
      halfedge_descriptor;
  typedef typename boost::graph_traits<Poly>::edge_descriptor edge_descriptor;
  typedef typename boost::graph_traits<Poly>::face_descriptor face_descriptor;
  typedef CGAL::Halfedge_around_face_circulator<Poly>
      Halfedge_around_facet_circulator;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;

  const std::vector<face_descriptor> p_faces(faces(p).first, faces(p).second);
  const std::vector<edge_descriptor> p_edges(edges(p).first, edges(p).second);
  const std::size_t num_v = num_vertices(p), num_e = p_edges.size(),
                    num_f = p_faces.size();

  // Refinement points, computed on the control mesh.
  std::vector<Point> edge_points(num_e), face_points(num_f);
  std::vector<bool> is_triangle(num_f);
  std::size_t new_faces = 0, new_edges = 2 * num_e, face_points_count = 0;
  for (std::size_t i = 0; i < num_f; ++i) {
    const std::size_t k = degree(p_faces[i], p);
    is_triangle[i] = (k == 3);
    new_faces += is_triangle[i] ? 4 : k;
    new_edges += is_triangle[i] ? 3 : k;
    if (!is_triangle[i]) {
      mask.face_node(p_faces[i], face_points[i]);
      ++face_points_count;
    }
  }
  for (std::size_t i = 0; i < num_e; ++i)
    mask.edge_node(halfedge(p_edges[i], p), edge_points[i]);

  SM::call_reserve(p, num_v + num_e + face_points_count, new_edges, new_faces);

  // Split every edge at its midpoint.
  for (std::size_t i = 0; i < num_e; ++i) {
    const vertex_descriptor vh = SM::insert_vertex(p, halfedge(p_edges[i], p));
    put(vpm, vh, edge_points[i]);
  }

  for (std::size_t i = 0; i < num_f; ++i) {
    Halfedge_around_facet_circulator hcir_begin(halfedge(p_faces[i], p), p);
    Halfedge_around_facet_circulator hcir = hcir_begin;
    if (is_triangle[i]) {
      // PTQ: join the three midpoints.
      halfedge_descriptor e1 = *(++hcir);
      ++hcir;
      halfedge_descriptor e2 = *(++hcir);
      ++hcir;
      halfedge_descriptor e3 = *(++hcir);
      e2 = SM::insert_edge(p, e1, e2);
      e3 = SM::insert_edge(p, e2, e3);
      SM::insert_edge(p, e3, e1);
    } else {
      // PQQ: a face point joined to every midpoint.
      halfedge_descriptor e1 = *++hcir;
      ++hcir;
      halfedge_descriptor e2 = *++hcir;
      ++hcir;
      const halfedge_descriptor newe = SM::insert_edge(p, e1, e2);
      halfedge_descriptor newv = SM::insert_vertex_return_edge(p, newe);
      newv = prev(opposite(newv, p), p);
      put(vpm, target(newv, p), face_points[i]);
      while (hcir != hcir_begin) {
        e1 = *++hcir;
        ++hcir;
        SM::insert_edge(p, e1, newv);
      }
    }
  }

  // Averaging: all new positions from the refined positions, then written.
  const std::vector<vertex_descriptor> r_vertices(vertices(p).first,
                                                  vertices(p).second);
  std::vector<Point> averaged(r_vertices.size());
  for (std::size_t i = 0; i < r_vertices.size(); ++i) {
    const vertex_descriptor v = r_vertices[i];
    halfedge_descriptor border = boost::graph_traits<Poly>::null_halfedge();
    for (halfedge_descriptor h : halfedges_around_target(v, p))
      if (is_border(h, p)) {
        border = h;
        break;
      }
    if (border != boost::graph_traits<Poly>::null_halfedge())
      mask.border_node(border, averaged[i]);
    else
      mask.vertex_node(v, averaged[i]);
  }
  for (std::size_t i = 0; i < r_vertices.size(); ++i)
    put(vpm, r_vertices[i], averaged[i]);

  CGAL_postcondition(CGAL::is_valid_polygon_mesh(p));
}

/// `steps` steps of quad/triangle subdivision of `pmesh` (any polygon mesh,
/// open or closed). Border vertices follow the cubic B-spline rule when
/// `smooth_boundary`, else stay on the control border polygon.
/// Precondition: a valid polygon mesh without garbage.
template <class PolygonMesh>
void QuadTriangle_subdivision(PolygonMesh& pmesh, int steps = 1,
                              bool smooth_boundary = true) {
  auto vpm = get(CGAL::vertex_point, pmesh);
  Quad_triangle_mask_3<PolygonMesh> mask(&pmesh, vpm, smooth_boundary);
  for (int i = 0; i < steps; ++i) PQT_1step(pmesh, vpm, mask);
}

}  // namespace subdivlab
