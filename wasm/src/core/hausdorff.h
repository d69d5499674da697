// The symmetric Hausdorff distance between two meshes (side-by-side
// schemes, `subdiv compare`): CGAL's bounded-error algorithm on the two
// meshes triangulated, within a stated share of the diagonal. Owner:
// hausdorff.cpp.
#pragma once

#include <vector>

#include "mesh_types.h"

namespace subdivlab {

struct Hausdorff_distance {
  double distance = 0;
  /// The bounding-box diagonal of both meshes together, and the bound on
  /// the error of `distance` (a share of it).
  double diagonal = 0, error_bound = 0;
  /// With vertex distances asked for: each vertex of `a` its distance to
  /// the surface of `b`, and each of `b` to `a` (exact closest points on
  /// the triangles, so none exceeds `distance` by more than the bound).
  std::vector<double> a_to_b, b_to_a;
};

/// The symmetric Hausdorff distance between `a` and `b` (valid meshes,
/// build_mesh's checks), within `relative_error` times the diagonal; with
/// `vertex_distances`, also every vertex's distance to the other surface
/// (to colour side-by-side panes by it).
Result<Hausdorff_distance> hausdorff_distance(const Mesh_buffers& a,
                                              const Mesh_buffers& b,
                                              double relative_error = 1e-4,
                                              bool vertex_distances = false);

}  // namespace subdivlab
