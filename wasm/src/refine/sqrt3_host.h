// The sqrt(3) refinement host on flat tables (Kobbelt's sqrt(3): a point
// per face, the old edges flipped; on a border step each border edge gets
// two points instead of its face's), numbered as CGAL's Sqrt3_1step numbers
// it on Surface_mesh (derivation in sqrt3_host.cpp), and its points from a
// Primal_mask holding the Sqrt3 weights (primal_masks.h: sqrt3_mask).
// Owner: sqrt3_host.cpp.
//
// A step is a border step when it refines the border (CGAL's route: an odd
// global step of an open mesh, scheme_table.h's sqrt3_refines_border); it
// then needs at most one border edge per face (sqrt3_multi_border_faces).
#pragma once

#include <cstdint>
#include <vector>

#include "primal_masks.h"
#include "primal_points.h"
#include "refine_level.h"

namespace subdivlab {
namespace refine {

/// Per-face table of a border step; kept between steps for its memory.
struct Sqrt3_scratch {
  /// Per parent face: 4 * (border faces before it) + the corner position
  /// (0-2) of its border halfedge, or + 3 when it has none.
  std::vector<std::uint32_t> face_code;
};

/// Bytes of the topology's scratch for a parent with F faces.
double sqrt3_scratch_bytes(double faces, bool border_step);

/// Faces of a triangle level with two or three border edges.
std::uint32_t sqrt3_multi_border_faces(const Level& level);

/// The child level's topology (everything but positions): counts, face
/// vertices and, unless `last`, the halfedge tables. Preconditions: a
/// valid triangle level with halfedge tables; on a border step
/// sqrt3_multi_border_faces(parent) == 0.
void refine_sqrt3_topology(const Level& parent, bool border_step,
                           Sqrt3_scratch& scratch, Level& child, bool last);

/// child.positions from `parent` (child's topology from
/// refine_sqrt3_topology with the same `border_step` and `scratch`).
/// Precondition: primal_uncovered_valence(parent, mask, points) returned 0.
void refine_sqrt3_points(const Level& parent, const Primal_mask& mask,
                         bool border_step, const Sqrt3_scratch& scratch,
                         Primal_scratch& points, Level& child);

}  // namespace refine
}  // namespace subdivlab
