// A Dual-Quadrilateral-Quadrisection (DQQ) refinement host that supports
// borders, and the Doo-Sabin mask with a border rule, written in the style of
// CGAL's Subdivision_method_3 (host = connectivity, mask = geometry).
//
// CGAL 5.5's DQQ_1step has no border support. This host builds the refined
// mesh as the classic Doo-Sabin construction does (Doo & Sabin, "Behaviour
// of recursive division surfaces near extraordinary points", CAD 10(6),
// 1978):
//   F-face: one per old face, through its corner points (one per corner);
//   E-face: one quad per INTERIOR old edge;
//   V-face: one polygon per INTERIOR old vertex;
// and, for the border (Nasri, "Polyhedral subdivision methods for free-form
// surfaces", ACM TOG 6(1), 1987, whose rule makes the border converge to the
// uniform quadratic B-spline of the control border polygon):
//   - a corner point that lies on a border edge (u, v) is placed by Chaikin's
//     rule 3/4 v + 1/4 u: the new border polygon is one Chaikin (corner
//     cutting) step of the control border, i.e. a control polygon of the
//     same quadratic B-spline;
//   - a border vertex whose two border edges belong to the same face (a
//     valence-2 "ear", e.g. a grid corner) gets two corner points in that
//     face, one per border edge, so the corner is cut as Chaikin cuts it;
//   - a border vertex with k >= 3 incident faces gets a V-face through its k
//     corner points, closed along the border; with k == 2 the single edge
//     between its two corner points is the border.
// So every control border vertex yields exactly two new border vertices and
// the new border follows the control border: one border loop per control
// loop, 2B border edges for B control border edges.
//
// Counts of one step (B border edges = border vertices, B1 ears of valence
// 2, B3 border vertices of valence >= 4):
//   V' = (2E - B) + B1         E' = 4E - 3B + B1 + B3
//   F' = F + (E - B) + (V - B) + B3
// On a closed mesh this is V' = 2E, E' = 4E, F' = V + E + F, as CGAL's DQQ.
#pragma once

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Subdivision_method_3/subdivision_masks_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

namespace subdivlab {

/// Doo-Sabin geometry mask with a border rule: CGAL's DooSabin_mask_3 for
/// interior corners plus `border_node` (Chaikin's 3/4, 1/4 rule, see above).
/// Models CGAL's DQQMask_3 and the border extension used by DQQ_border.
template <class PolygonMesh,
          class VertexPointMap = typename boost::property_map<
              PolygonMesh, CGAL::vertex_point_t>::type>
class DooSabin_border_mask_3
    : public CGAL::DooSabin_mask_3<PolygonMesh, VertexPointMap> {
  using Base = CGAL::DooSabin_mask_3<PolygonMesh, VertexPointMap>;

 public:
  using halfedge_descriptor = typename Base::halfedge_descriptor;
  using Point = typename Base::Point;

  // (CGAL 5.5's one-argument mask constructors do not compile: they call
  // get(vertex_point, pmesh) with a pointer.)
  explicit DooSabin_border_mask_3(PolygonMesh* pmesh)
      : Base(pmesh, get(CGAL::vertex_point, *pmesh)) {}
  DooSabin_border_mask_3(PolygonMesh* pmesh, VertexPointMap vpmap)
      : Base(pmesh, vpmap) {}

  /// Corner points of the face of `hd` on its border edge (`hd` is the
  /// non-border halfedge of a border edge): `at_target` near target(hd),
  /// `at_source` near source(hd).
  void border_node(halfedge_descriptor hd, Point& at_target, Point& at_source) {
    const PolygonMesh& m = *(this->pmesh);
    const Point& t = get(this->vpm, target(hd, m));
    const Point& s = get(this->vpm, source(hd, m));
    at_target = Point(0.75 * t.x() + 0.25 * s.x(), 0.75 * t.y() + 0.25 * s.y(),
                      0.75 * t.z() + 0.25 * s.z());
    at_source = Point(0.75 * s.x() + 0.25 * t.x(), 0.75 * s.y() + 0.25 * t.y(),
                      0.75 * s.z() + 0.25 * t.z());
  }
};

namespace internal {

/// One DQQ step with borders (see the file comment) on a CGAL::Surface_mesh.
/// The mask provides `corner_node(hd, pt)` (CGAL's DQQMask_3) for corners
/// away from the border and `border_node(hd, at_target, at_source)` for
/// border edges. The refined mesh is computed into flat arrays, then `sm` is
/// cleared (its property maps, hence the mask's point map, stay valid) and
/// rebuilt, so the old and the new mesh never coexist and `sm` carries no
/// garbage afterwards.
template <class P, class Mask>
void DQQ_border_1step(CGAL::Surface_mesh<P>& sm, Mask mask) {
  using Mesh = CGAL::Surface_mesh<P>;
  using halfedge_descriptor = typename Mesh::Halfedge_index;
  using vertex_descriptor = typename Mesh::Vertex_index;
  constexpr std::uint32_t none = 0xffffffffu;

  std::vector<P> points;               // new vertex positions
  std::vector<std::uint32_t> sizes;    // new face degrees
  std::vector<std::uint32_t> indices;  // new faces, flat
  std::size_t e_new = 0;
  {
    std::size_t n_b = 0, n_ears = 0, n_fan3 = 0;
    for (halfedge_descriptor h : sm.halfedges()) {
      if (!sm.is_border(h)) continue;
      ++n_b;
      const auto d = sm.degree(sm.target(h));
      if (d == 2) ++n_ears;
      if (d >= 4) ++n_fan3;
    }
    const std::size_t n_v = sm.number_of_vertices();
    const std::size_t n_e = sm.number_of_edges();
    const std::size_t n_f = sm.number_of_faces();
    const std::size_t v_new = 2 * n_e - n_b + n_ears;
    const std::size_t f_new = n_f + (n_e - n_b) + (n_v - n_b) + n_fan3;
    e_new = 4 * n_e - 3 * n_b + n_ears + n_fan3;
    points.reserve(v_new);
    sizes.reserve(f_new);
    // F-faces: sum deg + ears; E-faces: 4 (E - B); V-faces: sum of degrees
    // of interior vertices + (k) for fans: at most 2E.
    indices.reserve(v_new + 4 * (n_e - n_b) + 2 * n_e);

    // corner[h] = new vertex of the corner (face(h), target(h)); for an ear
    // (both face edges at target(h) on the border) corner[h] is the point on
    // edge(h) and ear_second[h] the one on edge(next(h)).
    std::vector<std::uint32_t> corner(sm.num_halfedges(), none);
    std::vector<std::uint32_t> ear_second(sm.num_halfedges(), none);
    auto new_vertex = [&](const P& p) {
      points.push_back(p);
      return static_cast<std::uint32_t>(points.size() - 1);
    };

    // Corner points on border edges: a border edge sets both of its corners.
    P at_target, at_source;
    for (halfedge_descriptor h : sm.halfedges()) {
      if (sm.is_border(h) || !sm.is_border(sm.opposite(h))) continue;
      mask.border_node(h, at_target, at_source);
      corner[h.idx()] = new_vertex(at_target);
      // The corner at source(h) belongs to prev(h); if edge(prev(h)) is a
      // border edge too, that corner is an ear and this is its second point.
      halfedge_descriptor p = sm.prev(h);
      if (sm.is_border(sm.opposite(p)))
        ear_second[p.idx()] = new_vertex(at_source);
      else
        corner[p.idx()] = new_vertex(at_source);
    }
    P pt;
    for (halfedge_descriptor h : sm.halfedges()) {
      if (sm.is_border(h) || corner[h.idx()] != none) continue;
      mask.corner_node(h, pt);
      corner[h.idx()] = new_vertex(pt);
    }

    auto close_face = [&](std::size_t first) {
      sizes.push_back(static_cast<std::uint32_t>(indices.size() - first));
    };
    // F-faces.
    for (auto f : sm.faces()) {
      const std::size_t first = indices.size();
      for (halfedge_descriptor h :
           CGAL::halfedges_around_face(sm.halfedge(f), sm)) {
        indices.push_back(corner[h.idx()]);
        if (ear_second[h.idx()] != none) indices.push_back(ear_second[h.idx()]);
      }
      close_face(first);
    }
    // E-faces: h runs u -> v in face f, o = opposite(h) runs v -> u in g.
    for (auto e : sm.edges()) {
      if (sm.is_border(e)) continue;
      halfedge_descriptor h = sm.halfedge(e), o = sm.opposite(h);
      const std::size_t first = indices.size();
      indices.insert(indices.end(),
                     {corner[h.idx()], corner[sm.prev(h).idx()],
                      corner[o.idx()], corner[sm.prev(o).idx()]});
      close_face(first);
    }
    // V-faces: corners in the reverse order of halfedges_around_target, so
    // that each edge is shared with an E-face in the opposite direction; a
    // border vertex starts at its border halfedge and closes on the border.
    for (vertex_descriptor v : sm.vertices()) {
      halfedge_descriptor start = sm.halfedge(v);
      bool on_border = false;
      for (halfedge_descriptor h : CGAL::halfedges_around_target(start, sm)) {
        if (sm.is_border(h)) {
          start = h;
          on_border = true;
          break;
        }
      }
      const std::size_t first = indices.size();
      halfedge_descriptor h = start;
      do {
        if (!sm.is_border(h)) indices.push_back(corner[h.idx()]);
        h = sm.prev(sm.opposite(h));  // the previous halfedge around v
      } while (h != start);
      if (on_border && indices.size() - first < 3) {
        indices.resize(first);  // an ear or k == 2: no V-face
        continue;
      }
      close_face(first);
    }
  }

  sm.clear_without_removing_property_maps();
  sm.reserve(static_cast<typename Mesh::size_type>(points.size()),
             static_cast<typename Mesh::size_type>(e_new),
             static_cast<typename Mesh::size_type>(sizes.size()));
  for (const P& p : points) sm.add_vertex(p);
  std::vector<vertex_descriptor> polygon;
  std::size_t offset = 0;
  for (std::uint32_t d : sizes) {
    polygon.clear();
    for (std::uint32_t k = 0; k < d; ++k)
      polygon.push_back(vertex_descriptor(indices[offset + k]));
    offset += d;
    if (sm.add_face(polygon) == Mesh::null_face())
      throw std::logic_error("DQQ_border_1step: could not add a face");
  }
}

}  // namespace internal

/// Applies the border-aware DQQ refinement `number_of_iterations` times (named
/// parameter, default 1) with the geometry of `mask`, as CGAL's
/// Subdivision_method_3::DQQ does. Precondition: `pmesh` is a valid polygon
/// Surface_mesh whose vertices are manifold. The mask must refer to `pmesh`
/// and use its internal vertex point map (kept valid across steps).
template <class PolygonMesh, class Mask,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
void DQQ_border(
    PolygonMesh& pmesh, Mask mask,
    const NamedParameters& np = CGAL::parameters::default_values()) {
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const unsigned int steps = choose_parameter(
      get_parameter(np, CGAL::internal_np::number_of_iterations), 1);
  for (unsigned int i = 0; i < steps; ++i)
    internal::DQQ_border_1step(pmesh, mask);
}

/// Doo-Sabin subdivision that works on meshes with borders (see above).
template <class PolygonMesh,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
void DooSabin_border_subdivision(
    PolygonMesh& pmesh,
    const NamedParameters& np = CGAL::parameters::default_values()) {
  DQQ_border(pmesh, DooSabin_border_mask_3<PolygonMesh>(&pmesh), np);
}

}  // namespace subdivlab
