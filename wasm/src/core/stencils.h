// The stencils of a step: each refined vertex as a weighted sum of the
// vertices of the level before, for the stencil inspector (issue 9) and
// `subdiv stencil`. Owner: stencils.cpp (the probing), fast_driver.cpp (the
// run that calls it).
//
// The weights are not derived again from the schemes' formulas: every
// point pass is linear in the parent's points, so the step's own point
// pass (the masks, creasing, custom rules, borders) is run again on probe
// points. Parents are coloured so that no refined vertex depends on two of
// one colour (a distance colouring over "shares a face"); a probe gives one
// colour's vertices x = 1 and y = their index + 1, so that a refined
// vertex's x is its weight for that colour's parent and y / x names the
// parent (Jacobian compression, as in automatic differentiation). The
// table is checked against the step's real points before it is returned.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "mesh_types.h"
#include "refine/refine_level.h"
#include "subdivide.h"

namespace subdivlab {

/// What a refined vertex is the point of.
enum class Stencil_kind : std::uint8_t {
  vertex_point,       ///< a parent vertex's new position (primal schemes)
  border_vertex,      ///< the same on the border
  edge_point,         ///< a point on a parent edge
  border_edge_point,  ///< the same on a border edge
  face_point,         ///< a point in a parent face
  corner_point,       ///< Doo-Sabin: a face's corner at a vertex
  border_corner_point,
  relaxed_vertex,    ///< √3: an old vertex, relaxed
  border_point,      ///< √3 on a border step: a new point on a border edge
  crease_vertex,     ///< a vertex point on two sharp edges (creasing)
  corner_vertex,     ///< on three or more sharp edges, or a sharp corner
  sharp_edge_point,  ///< a point on a sharp edge
};

/// How many Stencil_kind values there are.
constexpr int kStencilKinds = 12;

/// "vertex point", "border edge point", ... for messages and JSON.
const char* stencil_kind_name(Stencil_kind kind);

/// The refined vertex's origin in the parent level.
struct Stencil_origin {
  Stencil_kind kind = Stencil_kind::vertex_point;
  /// The vertex (vertex points, relaxed vertices; Doo-Sabin: the corner's
  /// vertex), edge or face; kNoElement where the host's numbering does not
  /// say (a √3 border step's new points).
  std::uint32_t element = kNoElement;
  /// The valence of that vertex (edges at it), or the degree of that face;
  /// an edge's ends for an edge point.
  std::uint32_t size = 0;
  std::uint32_t ends[2] = {kNoElement, kNoElement};

  static constexpr std::uint32_t kNoElement = 0xffffffffu;
};

/// The stencils of one step, parent vertices numbered as the level before
/// it, refined vertices as the step's result.
struct Stencil_table {
  std::uint32_t parent_vertices = 0;
  /// Refined vertex v's parents are [offsets[v], offsets[v + 1]) of
  /// parents and weights, in increasing parent order; zero weights left
  /// out.
  std::vector<std::uint32_t> offsets;
  std::vector<std::uint32_t> parents;
  std::vector<double> weights;
  std::vector<Stencil_origin> origins;  ///< one per refined vertex
  /// The scheme's formula for each kind that occurs, in words and symbols
  /// ("(Q + 2R + (n - 3) S) / n ..."), keyed by stencil_kind_name.
  std::vector<std::pair<std::string, std::string>> formulas;
};

/// The stencils of the last step of `options` on `mesh`: of level
/// options.start_level + options.levels, numbered as subdivide_mesh with
/// the same options numbers its result (and its level before, as
/// subdivide_mesh with one level fewer). Refused where the step runs on
/// CGAL's hosts, and for a parent level of more than kMaxStencilParents
/// vertices.
Result<Stencil_table> step_stencils(const Mesh_buffers& mesh,
                                    const Subdivide_options& options);

/// The largest level before a step whose stencils are made: the table
/// and its probes take about 1 KB per parent vertex.
constexpr std::uint32_t kMaxStencilParents = 250000;

/// The scheme's formula for a kind of refined vertex (empty when it has
/// none of that kind). `scheme`: a Scheme_info name; "custom" speaks of
/// the rule set.
std::string stencil_formula(const std::string& scheme, Stencil_kind kind);

namespace detail {

/// Collects the stencils of a step into `table`: `points(parent, child)` is
/// the step's point pass, run again on probe points (the child's topology
/// built). `host`: the host's name; `border_step`: a √3 step that refines
/// the border. Leaves both levels' points as they were. Returns an empty
/// string, or why the table could not be made.
std::string probe_stencils(
    refine::Level& parent, refine::Level& child, const std::string& host,
    bool border_step,
    const std::function<void(const refine::Level&, refine::Level&)>& points,
    Stencil_table& table);

}  // namespace detail
}  // namespace subdivlab
