#include "hausdorff.h"

#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "mesh_build.h"

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
  double lo[3] = {INFINITY, INFINITY, INFINITY},
         hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (const Mesh_buffers* m : {&a, &b})
    for (std::size_t i = 0; i < m->positions.size(); ++i) {
      lo[i % 3] = std::min(lo[i % 3], m->positions[i]);
      hi[i % 3] = std::max(hi[i % 3], m->positions[i]);
    }
  for (int i = 0; i < 3; ++i) h.diagonal += (hi[i] - lo[i]) * (hi[i] - lo[i]);
  h.diagonal = std::sqrt(h.diagonal);
  h.error_bound = std::max(relative_error * h.diagonal, 1e-12);
  h.distance =
      PMP::bounded_error_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(
          ma, mb, h.error_bound);
  return {Status::success(), h};
}

}  // namespace subdivlab
