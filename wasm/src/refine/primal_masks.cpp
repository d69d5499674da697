#include "primal_masks.h"

#include <CGAL/number_type_config.h>

#include <cmath>

namespace subdivlab {
namespace refine {

Vertex_weights loop_vertex_weights(double n) {
  double beta = 1.0 / 16.0;
  if (n != 6) {
    const double t = 3 + 2 * std::cos(2 * CGAL_PI / n);
    beta = (5.0 / 8.0 - t * t / 64.0) / n;
  }
  return {1 - n * beta, beta, 0.0};
}

Vertex_weights sqrt3_vertex_weights(double n) {
  const double a = (4.0 - 2.0 * std::cos(2.0 * CGAL_PI / n)) / 9.0;
  return {1 - a, a / n, 0.0};
}

namespace {

Vertex_weights linear_vertex_weights(double) { return {1.0, 0.0, 0.0}; }

}  // namespace

Primal_mask_lookup primal_mask(const std::string& scheme,
                               const Custom_rules& custom) {
  Primal_mask_lookup r;
  Primal_mask& m = r.mask;
  r.ok = true;
  if (scheme == "catmull-clark") {
    m.rule = catmull_clark_vertex_weights;
    m.edge_end = 0.25;
    m.edge_wing = 0.25;
  } else if (scheme == "loop") {
    m.pqq = false;
    m.rule = loop_vertex_weights;
    m.edge_end = 3.0 / 8.0;
    m.edge_wing = 1.0 / 8.0;
  } else if (scheme == "linear" || scheme == "linear-tri") {
    // linear_masks_3.h: midpoints, centroids, vertices and border kept.
    m.pqq = scheme == "linear";
    m.rule = linear_vertex_weights;
    m.border_vertex = {0.0, 1.0, 0.0};
  } else if (scheme == "custom" &&
             (custom.host == "pqq" || custom.host == "ptq")) {
    m.pqq = custom.host == "pqq";
    m.edge_end = custom.edge_end;
    m.edge_wing = custom.edge_wing;
    m.border_vertex = custom.border_vertex;
    m.border_edge = custom.border_edge;
    m.first_valence = custom.first_valence;
    m.vertex = custom.vertex;
  } else {
    r.ok = false;
  }
  return r;
}

Primal_mask_lookup sqrt3_mask(const std::string& scheme,
                              const Custom_rules& custom) {
  Primal_mask_lookup r;
  Primal_mask& m = r.mask;
  m.pqq = false;
  r.ok = true;
  if (scheme == "sqrt3") {
    m.rule = sqrt3_vertex_weights;
    m.border_edge = {1.0 / 27, 16.0 / 27, 10.0 / 27, 0.0};
    m.border_vertex = {4.0 / 27, 19.0 / 27, 4.0 / 27};
  } else if (scheme == "custom" && custom.host == "sqrt3") {
    m.border_vertex = custom.border_vertex;
    m.border_edge = custom.border_edge;
    m.first_valence = custom.first_valence;
    m.vertex = custom.vertex;
  } else {
    r.ok = false;
  }
  return r;
}

double quad_triangle_relaxation(std::size_t nq, std::size_t nt) {
  const double span = 3.0 * double(nq) + 2.0 * double(nt);  // angle / 30 deg
  if (span == 12.0) return 1.0;
  double lambda = 0.0;
  if (nq > 0) {
    // Catmull-Clark at valence n: (4 + 3n) / n^2.
    const double n = span / 3.0;
    lambda += double(nq) * (4.0 + 3.0 * n) / (n * n);
  }
  if (nt > 0) {
    // Loop at valence n: (4 + 2n) c(n) / n, c(n) = n beta(n).
    const double n = span / 2.0;
    const double t = 3.0 + 2.0 * std::cos(2.0 * CGAL_PI / n);
    const double c = 5.0 / 8.0 - t * t / 64.0;
    lambda += double(nt) * (4.0 + 2.0 * n) * c / n;
  }
  return lambda / double(nq + nt);
}

Quad_triangle_mask_lookup quad_triangle_mask(const std::string& scheme,
                                             bool smooth_boundary) {
  Quad_triangle_mask_lookup r;
  r.ok = scheme == "quad-triangle";
  r.mask.smooth_boundary = smooth_boundary;
  return r;
}

}  // namespace refine
}  // namespace subdivlab
