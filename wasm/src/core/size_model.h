// The size model: exact counts after each step of every scheme, and the
// peak memory of each step, predicted from the counts before anything is
// allocated (CGAL's hosts simulated allocation by allocation, the fast
// hosts from their tables). Internal to the core. Owner: size_model.cpp.
#pragma once

#include <cstdint>
#include <string>

#include "mesh_types.h"
#include "refine/refine_level.h"
#include "subdivide.h"

namespace subdivlab::detail {

/// Everything a step's result size depends on, in doubles so that
/// predictions far beyond 2^32 (and beyond size_t under wasm32) stay finite.
struct Counts {
  double vertices = 0, edges = 0, faces = 0;
  double border_edges = 0;   ///< = border vertices (vertices are manifold)
  double border_ears = 0;    ///< border vertices of degree 2
  double border_fans = 0;    ///< border vertices of degree >= 4
  double non_triangles = 0;  ///< faces of degree != 3
  double degree_excess = 0;  ///< sum over faces of (degree - 3)
  /// Faces with two or more border edges (sqrt3's border step needs none).
  double multi_border_faces = 0;
  /// The run applies OpenSubdiv's creasing (refine/crease.h): its levels
  /// carry crease tables.
  bool creased = false;
  /// How a fast run's level 0 is made (its first step's peak): from the
  /// mesh CGAL triangulated, else from the buffers; with control edges
  /// given as pairs (found through each vertex's halfedges, and held as
  /// pairs), else every edge marked.
  bool from_triangulated_mesh = false;
  bool control_edge_pairs = false;

  double degree_sum() const { return 2 * edges - border_edges; }
};

Counts counts_of(const Mesh& mesh);
Counts counts_of(const refine::Level& level);

/// Counts after Polygon_mesh_processing::triangulate_faces.
Counts triangulated(Counts c);

/// Element capacities of a Surface_mesh's arrays (halfedges counted apart).
struct Caps {
  double v = 0, h = 0, e = 0, f = 0;
  static Caps exact(const Counts& c) {
    return {c.vertices, 2 * c.edges, c.edges, c.faces};
  }
};

/// Bytes of Mesh_buffers with these counts.
double buffers_bytes(double vertices, double faces, double corners);

/// Memory one step needs, everything included.
struct Step_need {
  Counts after;
  Caps caps_after;
  double peak_bytes = 0;
};

/// The step from `c` (mesh arrays at `caps`) with the input buffers
/// (`input_bytes`) and `marks` control edges alive; `first` is the first
/// step of the call, `last` its last (which adds the output buffers).
Step_need step_need(const Subdivide_options& options, const Counts& c,
                    const Caps& caps, int global_step, bool first, bool last,
                    double marks, double input_bytes);

/// Fails with too_large when the step would not fit under `limit` (0: no
/// limit) or would need more than 2^32 halfedges.
Status check_step(const std::string& scheme, const Step_need& need,
                  int global_step, std::size_t limit);

/// Counts after the last step of a run and its largest peak.
struct Run_prediction {
  Counts after;
  double peak_bytes = 0;
};

/// Predicts every step of a run from the counts `c` of the mesh it starts
/// from. With `refuse`, the first step that would not fit ends it with
/// too_large, so a run is refused before its first step.
Status predict_run(const Subdivide_options& options, Counts c, double input,
                   double marks, bool refuse, Run_prediction& out);

/// "12345", "1.57 M", "3.2 G" for messages.
std::string format_count(double n);

/// x as a 64-bit count, saturated.
std::uint64_t to_size(double x);

}  // namespace subdivlab::detail
