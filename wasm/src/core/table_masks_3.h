// Geometry masks whose weights come from a Custom_rules table, one per
// refinement host of CGAL's Subdivision_method_3: PQQ (CGAL's PQQ_1step),
// PTQ (PTQ_1step), DQQ (SubdivLab's border-aware DQQ_border_1step,
// dqq_border_3.h) and Sqrt3 (Sqrt3_1step). Each reads like its CGAL
// counterpart (CatmullClark_mask_3, Loop_mask_3, DooSabin_mask_3,
// Sqrt3_mask_3) with the constants replaced by table look-ups, so that the
// built-in presets reproduce those masks.
//
// Border order: a border edge's non-border halfedge h runs a -> b; its border
// halfedge runs b -> a and the border chain (next on border halfedges) reads
// c, b, a, d with c = source(prev(opposite(h))), d = target(next(opposite(h))).
// Border weights are applied in that chain order.
//
// Preconditions (checked by check_custom_rules / check_custom_rules_cover):
// weights finite and summing to 1, tables covering the mesh. A missing table
// row throws std::out_of_range (reported as an internal error).
#pragma once

#include <CGAL/Subdivision_method_3/subdivision_masks_3.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <cstddef>
#include <vector>

#include "custom_rules.h"

namespace subdivlab {

/// Shared look-ups of the table masks.
template <class PolygonMesh, class VertexPointMap>
class Table_mask_base_3 {
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
  const Custom_rules* rules;

  Table_mask_base_3(Mesh* pmesh, VertexPointMap vpmap,
                    const Custom_rules* rules)
      : pmesh(pmesh), vpmap(vpmap), rules(rules) {}

 protected:
  Vector at(vertex_descriptor v) const { return get(vpmap, v) - CGAL::ORIGIN; }

  const Vertex_weights& vertex_weights(std::size_t n) const {
    return rules->vertex.at(n - static_cast<std::size_t>(rules->first_valence));
  }

  Vector centroid(face_descriptor f) const {
    Vector s(0, 0, 0);
    int n = 0;
    for (vertex_descriptor v :
         vertices_around_face(halfedge(f, *pmesh), *pmesh)) {
      s = s + at(v);
      ++n;
    }
    return s / FT(n);
  }

  /// self v + neighbour sum(neighbours) [+ face sum(centroids)].
  Vector vertex_rule(vertex_descriptor v, bool with_faces) const {
    const Mesh& m = *pmesh;
    Vector ring(0, 0, 0), faces_sum(0, 0, 0);
    std::size_t n = 0;
    for (halfedge_descriptor h : halfedges_around_target(v, m)) {
      ring = ring + at(source(h, m));
      if (with_faces) faces_sum = faces_sum + centroid(face(h, m));
      ++n;
    }
    const Vertex_weights& w = vertex_weights(n);
    Vector r = w.self * at(v) + w.neighbour * ring;
    if (with_faces) r = r + w.face * faces_sum;
    return r;
  }

  /// Border vertex rule for b = target(h), h the non-border halfedge of a
  /// border edge (chain order c, b, a).
  Vector border_vertex_rule(halfedge_descriptor h) const {
    const Mesh& m = *pmesh;
    const halfedge_descriptor bh = opposite(h, m);
    const auto& w = rules->border_vertex;
    return w[0] * at(source(prev(bh, m), m)) + w[1] * at(target(h, m)) +
           w[2] * at(source(h, m));
  }

  /// Border edge rule for the border edge of h (chain order c, b, a, d).
  Vector border_edge_rule(halfedge_descriptor h) const {
    const Mesh& m = *pmesh;
    const halfedge_descriptor bh = opposite(h, m);
    const auto& w = rules->border_edge;
    return w[0] * at(source(prev(bh, m), m)) + w[1] * at(target(h, m)) +
           w[2] * at(source(h, m)) + w[3] * at(target(next(bh, m), m));
  }
};

/// PQQ mask from tables (Catmull-Clark shape): face point = centroid; edge
/// point = edge_end (a + b) + edge_wing (f1 + f2); vertex rule from the
/// valence table with the incident face centroids.
template <class PolygonMesh,
          class VertexPointMap = typename boost::property_map<
              PolygonMesh, CGAL::vertex_point_t>::type>
class Table_PQQ_mask_3 : public Table_mask_base_3<PolygonMesh, VertexPointMap> {
  typedef Table_mask_base_3<PolygonMesh, VertexPointMap> Base;

 public:
  using typename Base::face_descriptor;
  using typename Base::halfedge_descriptor;
  using typename Base::Point;
  using typename Base::vertex_descriptor;

  Table_PQQ_mask_3(PolygonMesh* pmesh, VertexPointMap vpmap,
                   const Custom_rules* rules)
      : Base(pmesh, vpmap, rules) {}

  void face_node(face_descriptor f, Point& pt) {
    pt = CGAL::ORIGIN + this->centroid(f);
  }

  void edge_node(halfedge_descriptor h, Point& pt) {
    const PolygonMesh& m = *this->pmesh;
    pt = CGAL::ORIGIN +
         (this->rules->edge_end *
              (this->at(source(h, m)) + this->at(target(h, m))) +
          this->rules->edge_wing * (this->centroid(face(h, m)) +
                                    this->centroid(face(opposite(h, m), m))));
  }

  void vertex_node(vertex_descriptor v, Point& pt) {
    pt = CGAL::ORIGIN + this->vertex_rule(v, true);
  }

  void border_node(halfedge_descriptor h, Point& ept, Point& vpt) {
    ept = CGAL::ORIGIN + this->border_edge_rule(h);
    vpt = CGAL::ORIGIN + this->border_vertex_rule(h);
  }
};

/// PTQ mask from tables (Loop shape): edge point = edge_end (a + b) +
/// edge_wing (c + d) with c, d the vertices opposite the edge; vertex rule
/// from the valence table.
template <class PolygonMesh,
          class VertexPointMap = typename boost::property_map<
              PolygonMesh, CGAL::vertex_point_t>::type>
class Table_PTQ_mask_3 : public Table_mask_base_3<PolygonMesh, VertexPointMap> {
  typedef Table_mask_base_3<PolygonMesh, VertexPointMap> Base;

 public:
  using typename Base::halfedge_descriptor;
  using typename Base::Point;
  using typename Base::vertex_descriptor;

  Table_PTQ_mask_3(PolygonMesh* pmesh, VertexPointMap vpmap,
                   const Custom_rules* rules)
      : Base(pmesh, vpmap, rules) {}

  void edge_node(halfedge_descriptor h, Point& pt) {
    const PolygonMesh& m = *this->pmesh;
    pt = CGAL::ORIGIN + (this->rules->edge_end *
                             (this->at(source(h, m)) + this->at(target(h, m))) +
                         this->rules->edge_wing *
                             (this->at(target(next(h, m), m)) +
                              this->at(target(next(opposite(h, m), m), m))));
  }

  void vertex_node(vertex_descriptor v, Point& pt) {
    pt = CGAL::ORIGIN + this->vertex_rule(v, false);
  }

  void border_node(halfedge_descriptor h, Point& ept, Point& vpt) {
    ept = CGAL::ORIGIN + this->border_edge_rule(h);
    vpt = CGAL::ORIGIN + this->border_vertex_rule(h);
  }
};

/// DQQ mask from tables (Doo-Sabin shape): the corner point of corner
/// target(he) in face(he) of degree k is sum_j corner[k][j] target(next^j(he)).
/// Border (for DQQ_border_1step): the corner points on a border edge are
/// border_corner[0] own vertex + border_corner[1] other end.
template <class PolygonMesh,
          class VertexPointMap = typename boost::property_map<
              PolygonMesh, CGAL::vertex_point_t>::type>
class Table_DQQ_mask_3 : public Table_mask_base_3<PolygonMesh, VertexPointMap> {
  typedef Table_mask_base_3<PolygonMesh, VertexPointMap> Base;

 public:
  using typename Base::halfedge_descriptor;
  using typename Base::Point;
  using typename Base::Vector;

  Table_DQQ_mask_3(PolygonMesh* pmesh, VertexPointMap vpmap,
                   const Custom_rules* rules)
      : Base(pmesh, vpmap, rules) {}

  void corner_node(halfedge_descriptor he, Point& pt) {
    const PolygonMesh& m = *this->pmesh;
    std::size_t k = 0;
    halfedge_descriptor h = he;
    do {
      h = next(h, m);
      ++k;
    } while (h != he);
    const std::vector<double>& w = this->rules->corner.at(
        k - static_cast<std::size_t>(this->rules->first_degree));
    Vector s(0, 0, 0);
    for (std::size_t j = 0; j < k; ++j, h = next(h, m))
      s = s + w[j] * this->at(target(h, m));
    pt = CGAL::ORIGIN + s;
  }

  void border_node(halfedge_descriptor hd, Point& at_target, Point& at_source) {
    const PolygonMesh& m = *this->pmesh;
    const auto& w = this->rules->border_corner;
    const Vector t = this->at(target(hd, m)), s = this->at(source(hd, m));
    at_target = CGAL::ORIGIN + (w[0] * t + w[1] * s);
    at_source = CGAL::ORIGIN + (w[0] * s + w[1] * t);
  }
};

/// Sqrt3 mask from tables: face point = centroid; vertex rule from the
/// valence table; on border-refining steps the two new points of a border
/// edge s -> t (chain order prev_s, s, t, next_t) are border_edge and its
/// mirror image, and s moves by border_vertex.
template <class PolygonMesh,
          class VertexPointMap = typename boost::property_map<
              PolygonMesh, CGAL::vertex_point_t>::type>
class Table_Sqrt3_mask_3
    : public Table_mask_base_3<PolygonMesh, VertexPointMap> {
  typedef Table_mask_base_3<PolygonMesh, VertexPointMap> Base;

 public:
  using typename Base::face_descriptor;
  using typename Base::halfedge_descriptor;
  using typename Base::Point;
  using typename Base::Vector;
  using typename Base::vertex_descriptor;

  Table_Sqrt3_mask_3(PolygonMesh* pmesh, VertexPointMap vpmap,
                     const Custom_rules* rules)
      : Base(pmesh, vpmap, rules) {}

  void face_node(face_descriptor f, Point& pt) {
    pt = CGAL::ORIGIN + this->centroid(f);
  }

  void vertex_node(vertex_descriptor v, Point& pt) {
    pt = CGAL::ORIGIN + this->vertex_rule(v, false);
  }

  /// `hd` is the non-border halfedge of a border edge, as in Sqrt3_mask_3.
  void border_node(halfedge_descriptor hd, Point& ept1, Point& ept2,
                   Point& vpt) {
    const PolygonMesh& m = *this->pmesh;
    const halfedge_descriptor bhd = opposite(hd, m);
    const Vector prev_s = this->at(source(prev(bhd, m), m));
    const Vector s = this->at(source(bhd, m));
    const Vector t = this->at(target(bhd, m));
    const Vector next_t = this->at(target(next(bhd, m), m));
    const auto& e = this->rules->border_edge;
    const auto& w = this->rules->border_vertex;
    ept1 = CGAL::ORIGIN + (e[0] * prev_s + e[1] * s + e[2] * t + e[3] * next_t);
    ept2 = CGAL::ORIGIN + (e[3] * prev_s + e[2] * s + e[1] * t + e[0] * next_t);
    vpt = CGAL::ORIGIN + (w[0] * prev_s + w[1] * s + w[2] * t);
  }
};

}  // namespace subdivlab
