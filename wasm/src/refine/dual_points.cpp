#include "dual_points.h"

#include <vector>

namespace subdivlab {
namespace refine {

std::uint32_t dual_uncovered_degree(const Level& p, const Dual_mask& mask) {
  for (std::uint32_t f = 0; f < p.face_count; ++f) {
    const std::uint32_t k = p.face_end(f) - p.face_begin(f);
    if (!mask.covers(k)) return k;
  }
  return 0;
}

void refine_dual_points(const Level& p, const Dual_mask& mask,
                        const Dual_scratch& s, Level& c) {
  size_to(c.positions, 3 * std::size_t{c.vertex_count});
  const double* in = p.positions.data();
  double* out = c.positions.data();
  const std::uint32_t* fv = p.face_vertices.data();
  const std::uint32_t* fh = p.face_halfedges.data();
  const std::uint32_t* pc = p.halfedge_corner.data();
  const std::uint32_t* cv = s.corner_vertex.data();
  const bool open = p.border_edge_count > 0;
  const double w0 = mask.border_corner[0], w1 = mask.border_corner[1];
  std::vector<std::vector<double>> weights;  // by degree
  for (std::uint32_t f = 0; f < p.face_count; ++f) {
    const std::uint32_t begin = p.face_begin(f), k = p.face_end(f) - begin;
    if (weights.size() <= k) weights.resize(k + 1);
    if (weights[k].empty()) weights[k] = mask.corner_weights(k);
    const double* w = weights[k].data();
    for (std::uint32_t i = 0; i < k; ++i) {
      const std::uint32_t x = fh[begin + i];
      if (open) {
        const std::uint32_t after = fh[begin + (i + 1 < k ? i + 1 : 0)];
        if (pc[x ^ 1] == kNone) {
          // A border edge s -> t: its two corners (the one at s is the
          // corner of prev(x), or an ear's second).
          const double* t = in + 3 * std::size_t{fv[begin + i]};
          const double* sp =
              in + 3 * std::size_t{fv[begin + (i > 0 ? i : k) - 1]};
          double* a = out + 3 * std::size_t{cv[x]};
          for (int d = 0; d < 3; ++d) {
            a[d] = w0 * t[d] + w1 * sp[d];
            a[3 + d] = w0 * sp[d] + w1 * t[d];
          }
          continue;
        }
        if (pc[after ^ 1] == kNone) continue;  // written by `after`
      }
      double q[3] = {0, 0, 0};
      for (std::uint32_t j = 0; j < k; ++j) {
        const std::uint32_t at = i + j < k ? i + j : i + j - k;
        const double* pj = in + 3 * std::size_t{fv[begin + at]};
        for (int d = 0; d < 3; ++d) q[d] += w[j] * pj[d];
      }
      double* o = out + 3 * std::size_t{cv[x]};
      for (int d = 0; d < 3; ++d) o[d] = q[d];
    }
  }
}

}  // namespace refine
}  // namespace subdivlab
