// The masks of the primal schemes as weights: the geometry of the PQQ and
// PTQ hosts (primal_hosts.h) and of the sqrt(3) host (sqrt3_host.h), in the
// form of custom rules (custom_rules.h) so that built-in and custom schemes run
// through one kernel. The weights of Catmull-Clark, Loop, sqrt(3) and the
// linear schemes are defined here once; the custom-rule presets read them from
// here. So are quad/triangle's (Quad_triangle_mask, for the PQT host), which
// CGAL's route (core/quad_triangle_3.h) reads too.
//
// Rules (p = the parent points; wings = the face points of the two faces of
// an edge on PQQ, the vertices opposite it on PTQ):
//   face point      centroid (PQQ)
//   edge point      end (a + b) + wing (w1 + w2)
//   vertex point    self(n) v + neighbour(n) sum(edge neighbours)
//                   + face(n) sum(incident face points), n the valence
//   border          along the border chain c -> b -> a -> d (border
//                   halfedges): edge a-b gets border_edge . (c, b, a, d),
//                   vertex b gets border_vertex . (c, b, a)
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/custom_rules.h"

namespace subdivlab {
namespace refine {

/// CatmullClark_mask_3: ((n - 3) v + 2 R + Q) / n, R the mean edge
/// midpoint and Q the mean face point.
inline Vertex_weights catmull_clark_vertex_weights(double n) {
  return {(n - 2) / n, 1 / (n * n), 1 / (n * n)};
}

/// Loop_mask_3: beta = (5/8 - (3 + 2 cos(2 pi / n))^2 / 64) / n, 1/16 at
/// n = 6.
Vertex_weights loop_vertex_weights(double n);

/// Sqrt3_mask_3: a(n) = (4 - 2 cos(2 pi / n)) / 9; (1 - a) v + a / n per
/// neighbour.
Vertex_weights sqrt3_vertex_weights(double n);

struct Primal_mask {
  bool pqq = true;  ///< PQQ host (face points, face wings) or PTQ
  double edge_end = 0.5, edge_wing = 0.0;
  std::array<double, 3> border_vertex{0.125, 0.75, 0.125};
  std::array<double, 4> border_edge{0.0, 0.5, 0.5, 0.0};
  /// Interior vertex weights at valence n: rule(n) when set, else the
  /// table vertex[n - first_valence].
  Vertex_weights (*rule)(double n) = nullptr;
  int first_valence = 3;
  std::vector<Vertex_weights> vertex;

  /// Whether valence n has weights.
  bool covers(std::uint32_t n) const {
    return rule != nullptr || (n >= static_cast<std::uint32_t>(first_valence) &&
                               n - first_valence < vertex.size());
  }
  /// Precondition: covers(n).
  Vertex_weights vertex_weights(std::uint32_t n) const {
    return rule != nullptr ? rule(double(n)) : vertex[n - first_valence];
  }
  /// Whether a PQQ step must sum a vertex's face points apart from its
  /// edge neighbours: some valence weighs them differently. The built-in
  /// rules weigh them alike (Catmull-Clark 1/n^2 both, linear 0 both), so
  /// one sum per vertex serves both.
  bool separate_face_sums() const {
    if (!pqq || rule != nullptr) return false;
    for (const Vertex_weights& w : vertex)
      if (w.neighbour != w.face) return true;
    return false;
  }
};

/// The mask of a scheme with a primal fast host: catmull-clark, loop,
/// linear, linear-tri, or custom with the pqq or ptq host (`custom` then
/// gives the weights). `ok` false for any other.
struct Primal_mask_lookup {
  bool ok = false;
  Primal_mask mask;
};
Primal_mask_lookup primal_mask(const std::string& scheme,
                               const Custom_rules& custom);

/// The mask of the sqrt(3) host (sqrt3_host.h) in the same form: sqrt3, or
/// custom with the sqrt3 host. Read: the vertex weights, border_vertex
/// (c, b, a as above) and border_edge (the new point nearer the border
/// halfedge's source, mirrored for the other); `pqq` and the edge weights
/// are not. Sqrt3_mask_3's border: 1/27 (1, 16, 10, 0) and (4, 19, 4).
Primal_mask_lookup sqrt3_mask(const std::string& scheme,
                              const Custom_rules& custom);

/// Relaxation factor lambda of the quad/triangle averaging at an interior
/// vertex of the refined mesh with `nq` incident quads and `nt` incident
/// triangles: 1 where the corner angles (quad 90 deg, triangle 60 deg) add
/// up to 360 deg, else the corner-count blend of Catmull-Clark's and Loop's
/// corrections (core/quad_triangle_3.h explains it). Precondition:
/// nq + nt > 0.
double quad_triangle_relaxation(std::size_t nq, std::size_t nt);

/// Quad/triangle's averaging (Stam & Loop; core/quad_triangle_3.h), read on
/// the mesh the linear refinement made (edge midpoints, a centroid per face
/// that is not a triangle; PQT host, primal_hosts.h). An interior vertex v
/// with ne edges and nq incident quads goes to
///   A = alpha (self v + ring sum(edge neighbours)
///              + opposite sum(quad corners opposite v)),
///   alpha = 1 / (self + ring ne + opposite nq),
/// then v' = v + lambda (A - v), lambda = quad_triangle_relaxation(nq,
/// ne - nq). A border vertex goes to border . (prev, v, next) along the
/// refined border when smooth_boundary, else stays.
struct Quad_triangle_mask {
  double self = 1.0, ring = 0.5, opposite = 0.25;
  std::array<double, 3> border{0.25, 0.5, 0.25};
  bool smooth_boundary = true;

  struct Averaging {
    double alpha, lambda;
  };
  /// alpha and lambda of an interior vertex (ne edges, nq quads, ne > 0).
  Averaging averaging(std::uint32_t ne, std::uint32_t nq) const {
    return {1.0 / (self + ring * ne + opposite * nq),
            quad_triangle_relaxation(nq, ne - nq)};
  }
  /// The same as v' = self v + neighbour sum(edge neighbours) + face
  /// sum(opposite quad corners).
  Vertex_weights vertex_weights(std::uint32_t ne, std::uint32_t nq) const {
    const Averaging a = averaging(ne, nq);
    const double average = a.lambda * a.alpha;
    return {1.0 - a.lambda + average * self, average * ring,
            average * opposite};
  }
};

/// The mask of quad-triangle (`ok` false for any other scheme).
struct Quad_triangle_mask_lookup {
  bool ok = false;
  Quad_triangle_mask mask;
};
Quad_triangle_mask_lookup quad_triangle_mask(const std::string& scheme,
                                             bool smooth_boundary);

}  // namespace refine
}  // namespace subdivlab
