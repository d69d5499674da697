#include "dual_points.h"

#include <vector>

#include "primal_hosts.h"

namespace subdivlab {
namespace refine {

std::uint32_t dual_uncovered_degree(const Level& p, const Dual_mask& mask) {
  for (std::uint32_t f = 0; f < p.face_count; ++f) {
    const std::uint32_t k = p.face_end(f) - p.face_begin(f);
    if (!mask.covers(k)) return k;
  }
  return 0;
}

namespace {

/// Weights by degree, computed once each.
class Weights {
 public:
  explicit Weights(const Dual_mask& mask) : mask_(mask) {}
  const double* at(std::uint32_t k) {
    if (by_degree_.size() <= k) by_degree_.resize(k + 1);
    if (by_degree_[k].empty()) by_degree_[k] = mask_.corner_weights(k);
    return by_degree_[k].data();
  }

 private:
  const Dual_mask& mask_;
  std::vector<std::vector<double>> by_degree_;
};

/// Closed: F-face f of the child lists the child vertices of parent face
/// f's corners from its first corner (dual_hosts.cpp), so the points are
/// written in the child's F-face order. The faces go in batches: first the
/// batch's points are gathered (independent reads, which overlap), then
/// its corners are computed from the copies.
void closed_points(const Level& p, Weights& weights, Level& c) {
  const double* in = p.positions.data();
  double* out = c.positions.data();
  const std::uint32_t* fv = p.face_vertices.data();
  const std::uint32_t* fh = p.face_halfedges.data();
  const std::uint32_t* child = c.face_vertices.data();
  constexpr std::uint32_t kBatch = 512;  // corners
  std::vector<double> copies;
  for (std::uint32_t f0 = 0; f0 < p.face_count;) {
    // The batch: faces f0..f1, at least one.
    const std::uint32_t first = p.face_begin(f0);
    std::uint32_t f1 = f0 + 1;
    while (f1 < p.face_count && p.face_end(f1) - first <= kBatch) ++f1;
    const std::uint32_t corners = p.face_begin(f1 - 1) +
                                  (p.face_end(f1 - 1) - p.face_begin(f1 - 1)) -
                                  first;
    if (copies.size() < 3 * std::size_t{corners})
      copies.resize(3 * std::size_t{corners});
    double* q = copies.data();
    for (std::uint32_t i = 0; i < corners; ++i) {
      const double* pt = in + 3 * std::size_t{fv[first + i]};
      q[3 * i] = pt[0];
      q[3 * i + 1] = pt[1];
      q[3 * i + 2] = pt[2];
    }
    for (std::uint32_t f = f0; f < f1; ++f) {
      const std::uint32_t begin = p.face_begin(f), k = p.face_end(f) - begin;
      const double* w = weights.at(k);
      const std::uint32_t start = first_corner_offset(fh + begin, k);
      const double* face = q + 3 * std::size_t{begin - first};
      for (std::uint32_t t = 0; t < k; ++t) {
        double x = 0, y = 0, z = 0;
        for (std::uint32_t j = 0, i = start + t < k ? start + t : start + t - k;
             j < k; ++j, i = i + 1 == k ? 0 : i + 1) {
          x += w[j] * face[3 * i];
          y += w[j] * face[3 * i + 1];
          z += w[j] * face[3 * i + 2];
        }
        double* o = out + 3 * std::size_t{child[begin + t]};
        o[0] = x;
        o[1] = y;
        o[2] = z;
      }
    }
    f0 = f1;
  }
}

}  // namespace

void refine_dual_points(const Level& p, const Dual_mask& mask,
                        const Dual_scratch& s, Level& c) {
  size_to(c.positions, 3 * std::size_t{c.vertex_count});
  Weights weights(mask);
  if (p.border_edge_count == 0) {
    closed_points(p, weights, c);
    return;
  }
  const double* in = p.positions.data();
  double* out = c.positions.data();
  const std::uint32_t* fv = p.face_vertices.data();
  const std::uint32_t* fh = p.face_halfedges.data();
  const std::uint32_t* pc = p.halfedge_corner.data();
  const std::uint32_t* cv = s.corner_vertex.data();
  const double w0 = mask.border_corner[0], w1 = mask.border_corner[1];
  for (std::uint32_t f = 0; f < p.face_count; ++f) {
    const std::uint32_t begin = p.face_begin(f), k = p.face_end(f) - begin;
    const double* w = weights.at(k);
    for (std::uint32_t i = 0; i < k; ++i) {
      const std::uint32_t x = fh[begin + i];
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
