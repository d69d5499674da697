// OpenSubdiv's creasing on the primal hosts (PQQ for Catmull-Clark, PTQ
// for Loop): semi-sharp and infinitely sharp edges and vertices, holes and
// the border modes of a mesh's tags (Mesh_tags), with the rules of
// OpenSubdiv 3.5's Sdc (crease.cpp, scheme.h) and Vtr (refinement.cpp).
// OpenSubdiv is the reference for tagged meshes as CGAL is for the others:
// an untagged run never comes here. Owner: crease.cpp.
//
// Tables (refine_level.h): a sharpness per edge and per vertex as the tags
// give them (float, as OpenSubdiv's), a hole flag per face. The border
// mode is applied where OpenSubdiv's factory applies it, as the
// "effective" sharpness at each level rather than stored: a border edge is
// infinitely sharp whatever it holds; with edge_and_corner, so is a
// vertex of one face and two border edges; with none, the faces at a
// border vertex are holes at level 0 (stored, as they propagate). So a
// level's tables are what its tags say, and a mesh written with them
// refines as the run would have gone on.
//
// A step: the host refines the topology, crease tables follow
// (refine_crease_tables: a split edge's halves get its sharpness less one,
// or Chaikin's blend at their end vertex; the edges inside a face are
// smooth; a vertex keeps its sharpness less one; a hole's children are
// holes), the primal points are computed as on an untagged mesh (the smooth
// rules), then apply_crease_rules recomputes the points that creasing
// changes: edge points of sharp edges (midpoint, or OpenSubdiv's blend with
// the smooth rule when the sharpness decays below 1), vertex points by
// rule (smooth and dart: kept; crease: 3/4 v + 1/8 (a + b) over the two
// sharp edges' ends; corner: v), blended with the child's rule by the
// fractional weight where the rule changes between parent and child.
//
// Sharpness arithmetic is done in float in OpenSubdiv's order, so results
// match OpenSubdiv's to rounding of the positions. One difference remains:
// Chaikin's average sums the sharpness around a vertex in edge order, not
// in OpenSubdiv's order around the vertex; with three or more semi-sharp
// edges at a vertex whose values are not exact in binary, the float sum
// may differ in its last bit.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/mesh_types.h"
#include "level_convert.h"
#include "refine_level.h"

namespace subdivlab {
namespace refine {

/// OpenSubdiv's Sdc::Crease::SHARPNESS_INFINITE: 10 and above never decay.
constexpr float kInfinitelySharp = 10.0f;

/// The run's creasing options: the mesh's tags, overridden by the
/// subdivision options.
struct Creasing {
  Crease_method method = Crease_method::uniform;
  Boundary_interpolation boundary = Boundary_interpolation::edge_only;
};

/// Sets level 0's crease tables from `tags` (vertex indices of `in`,
/// mapped to the level's: `in` drops the vertices no face uses). Returns
/// an empty string, or why the tags do not fit the mesh (a crease pair
/// that is not an edge, an index out of range, a sharpness that is
/// negative or not finite), naming the tag. `faces_renumbered`: the level
/// was triangulated, so face indices (holes) no longer apply.
std::string apply_tags(const Mesh_buffers& in, const Mesh_tags& tags,
                       const Creasing& creasing, bool faces_renumbered,
                       Level& level);

/// The child's crease tables from the parent's (child's topology from the
/// PQQ host when `pqq`, else PTQ). Precondition: parent.creased.
void refine_crease_tables(const Level& parent, const Creasing& creasing,
                          bool pqq, Level& child);

/// Scratch of apply_crease_rules, kept between steps: the halfedges out of
/// each vertex.
struct Crease_scratch {
  Vertex_halfedges around;
};

/// Recomputes the child's points that creasing changes (the primal points
/// of the smooth rules already in child.positions; the child's crease
/// tables from refine_crease_tables).
void apply_crease_rules(const Level& parent, const Creasing& creasing,
                        Crease_scratch& scratch, Level& child);

/// The level's tags, as a mesh written from it carries them.
Mesh_tags crease_tags(const Level& level, const Creasing& creasing,
                      const Mesh_tags& input);

/// Bytes of a level's crease tables, and of a step's scratch beside them
/// (the memory model's share of a creased run).
double crease_level_bytes(double vertices, double edges, double faces);
double crease_scratch_bytes(double vertices, double edges);

}  // namespace refine
}  // namespace subdivlab
