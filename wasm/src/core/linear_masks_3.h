// Linear (interpolating, piecewise-flat) subdivision as CGAL masks: the PQQ
// host with the averaging rule (face centroid, edge midpoint, vertex kept) --
// the CGAL subdivision tutorial's example of a custom policy -- and its PTQ
// twin (midpoint split of triangles). The shape never changes; only the
// connectivity is refined.
//
// CGAL 5.5's own Linear_mask_3::border_node leaves the border vertex point
// unset, so on open meshes the hosts would write an uninitialised point into
// every border vertex. Linear_border_mask_3 keeps border vertices where they
// are and splits border edges at their midpoints.
#pragma once

#include <CGAL/Subdivision_method_3/subdivision_hosts_3.h>
#include <CGAL/Subdivision_method_3/subdivision_masks_3.h>

namespace subdivlab {

/// CGAL::Linear_mask_3 with a border rule: border edge point at the
/// midpoint, border vertex unchanged. Models PQQMask_3 and PTQMask_3.
template <class PolygonMesh,
          class VertexPointMap = typename boost::property_map<
              PolygonMesh, CGAL::vertex_point_t>::type>
class Linear_border_mask_3
    : public CGAL::Linear_mask_3<PolygonMesh, VertexPointMap> {
  typedef CGAL::Linear_mask_3<PolygonMesh, VertexPointMap> Base;

 public:
  typedef typename Base::halfedge_descriptor halfedge_descriptor;
  typedef typename Base::Point Point;

  explicit Linear_border_mask_3(PolygonMesh* pmesh)
      : Base(pmesh, get(CGAL::vertex_point, *pmesh)) {}
  Linear_border_mask_3(PolygonMesh* pmesh, VertexPointMap vpmap)
      : Base(pmesh, vpmap) {}

  /// `edge` is the non-border halfedge of a border edge; `vpt` is the new
  /// point of its target.
  void border_node(halfedge_descriptor edge, Point& ept, Point& vpt) {
    this->edge_node(edge, ept);
    vpt = get(this->vpmap, target(edge, *(this->pmesh)));
  }
};

/// One step of `linear`: PQQ refinement, positions unchanged, new points at
/// edge midpoints and face centroids. Any polygon mesh, open or closed.
template <class PolygonMesh>
void Linear_subdivision(PolygonMesh& pmesh) {
  CGAL::Subdivision_method_3::PQQ(pmesh,
                                  Linear_border_mask_3<PolygonMesh>(&pmesh),
                                  CGAL::parameters::number_of_iterations(1));
}

/// One step of `linear-tri`: PTQ refinement (each triangle into four by its
/// edge midpoints), positions unchanged. Precondition: all faces triangles.
template <class PolygonMesh>
void Linear_triangle_subdivision(PolygonMesh& pmesh) {
  CGAL::Subdivision_method_3::PTQ(pmesh,
                                  Linear_border_mask_3<PolygonMesh>(&pmesh),
                                  CGAL::parameters::number_of_iterations(1));
}

}  // namespace subdivlab
