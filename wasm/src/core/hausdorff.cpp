#include "hausdorff.h"

#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <algorithm>
#include <string>

#include "mesh_build.h"
#include "mesh_facts.h"

namespace subdivlab {

namespace PMP = CGAL::Polygon_mesh_processing;

Result<Hausdorff_distance> hausdorff_distance(const Mesh_buffers& a,
                                              const Mesh_buffers& b,
                                              double relative_error) {
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
  return {Status::success(), h};
}

}  // namespace subdivlab
