#include "primal_points.h"

#include <algorithm>

namespace subdivlab {
namespace refine {
namespace {

inline void add(double* to, const double* p) {
  to[0] += p[0];
  to[1] += p[1];
  to[2] += p[2];
}

/// to = a p + b q (+ ...): the weighted sums of the masks.
inline void weigh2(double* to, double a, const double* p, double b,
                   const double* q) {
  for (int i = 0; i < 3; ++i) to[i] = a * p[i] + b * q[i];
}

}  // namespace

double primal_scratch_bytes(double vertices, bool face_sums, bool border) {
  return vertices * ((face_sums ? 24 : 0) + 4 + (border ? 8 : 0));
}

std::uint32_t primal_uncovered_valence(const Level& p, const Primal_mask& mask,
                                       Primal_scratch& s) {
  const std::uint32_t V = p.vertex_count, E = p.edge_count;
  size_to(s.valence, V);
  std::fill(s.valence.begin(), s.valence.end(), 0);
  const std::uint32_t* t = p.halfedge_target.data();
  std::uint32_t* valence = s.valence.data();
  for (std::uint32_t e = 0; e < E; ++e) {
    ++valence[t[2 * e]];
    ++valence[t[2 * e + 1]];
  }
  if (p.border_edge_count > 0) {
    size_to(s.border_next, V);
    size_to(s.border_prev, V);
    std::fill(s.border_next.begin(), s.border_next.end(), kNone);
    std::fill(s.border_prev.begin(), s.border_prev.end(), kNone);
    const std::uint32_t* corner = p.halfedge_corner.data();
    for (std::uint32_t x = 0; x < 2 * E; ++x) {
      if (corner[x] != kNone) continue;
      const std::uint32_t from = t[x ^ 1], to = t[x];
      s.border_next[from] = to;
      s.border_prev[to] = from;
    }
  } else {
    s.border_next = {};
    s.border_prev = {};
  }
  std::uint32_t most = 0;
  for (std::uint32_t v = 0; v < V; ++v)
    if (p.border_edge_count == 0 || s.border_next[v] == kNone)
      most = std::max(most, valence[v]);
  s.weights.resize(std::size_t{most} + 1);
  for (std::uint32_t n = 1; n <= most; ++n) {
    if (!mask.covers(n)) continue;
    s.weights[n] = mask.vertex_weights(n);
  }
  for (std::uint32_t v = 0; v < V; ++v) {
    if (p.border_edge_count > 0 && s.border_next[v] != kNone) continue;
    if (!mask.covers(valence[v])) return valence[v];
  }
  return 0;
}

void refine_primal_points(const Level& p, const Primal_mask& mask,
                          Primal_scratch& s, Level& c) {
  const std::uint32_t V = p.vertex_count, E = p.edge_count, F = p.face_count;
  const bool border = p.border_edge_count > 0;
  size_to(c.positions, 3 * std::size_t{c.vertex_count});
  const double* in = p.positions.data();
  double* out = c.positions.data();
  // The child's slots of the parent's vertices gather their neighbours'
  // sums (and, unless weighed apart, their face points') before the
  // vertex pass weighs them: no per-vertex scratch.
  double* sum = out;
  std::fill(sum, sum + 3 * std::size_t{V}, 0.0);
  const std::uint32_t* t = p.halfedge_target.data();
  const std::uint32_t* fv = p.face_vertices.data();
  const std::uint32_t* corner = p.halfedge_corner.data();
  const std::uint32_t* next = s.border_next.data();
  const std::uint32_t* prev = s.border_prev.data();

  // Faces: centroids, summed at their vertices (PQQ).
  double* face_sum = nullptr;
  if (mask.pqq) {
    face_sum = sum;
    if (mask.separate_face_sums()) {
      size_to(s.faces, 3 * std::size_t{V});
      std::fill(s.faces.begin(), s.faces.end(), 0.0);
      face_sum = s.faces.data();
    }
    double* face_point = out + 3 * (std::size_t{V} + E);
    for (std::uint32_t f = 0; f < F; ++f, face_point += 3) {
      const std::uint32_t begin = p.face_begin(f), end = p.face_end(f);
      double q[3] = {0, 0, 0};
      for (std::uint32_t i = begin; i < end; ++i)
        add(q, in + 3 * std::size_t{fv[i]});
      const double k = end - begin;
      for (int a = 0; a < 3; ++a) face_point[a] = q[a] / k;
      for (std::uint32_t i = begin; i < end; ++i)
        add(face_sum + 3 * std::size_t{fv[i]}, face_point);
    }
  }

  // Edges: edge points, neighbour sums.
  const double end_w = mask.edge_end, wing_w = mask.edge_wing;
  const auto& be = mask.border_edge;
  const bool border_wide = be[0] != 0 || be[3] != 0;
  double* edge_point = out + 3 * std::size_t{V};
  for (std::uint32_t e = 0; e < E; ++e, edge_point += 3) {
    const std::uint32_t a = t[2 * e + 1], b = t[2 * e];
    const double* pa = in + 3 * std::size_t{a};
    const double* pb = in + 3 * std::size_t{b};
    add(sum + 3 * std::size_t{a}, pb);
    add(sum + 3 * std::size_t{b}, pa);
    const std::uint32_t c0 = corner[2 * e], c1 = corner[2 * e + 1];
    if (c0 != kNone && c1 != kNone) {
      const double *w0, *w1;
      if (mask.pqq) {
        const double* face_points = out + 3 * (std::size_t{V} + E);
        w0 = face_points + 3 * std::size_t{p.corner_face(c0)};
        w1 = face_points + 3 * std::size_t{p.corner_face(c1)};
      } else {
        // Triangles: the vertex opposite is the next corner's.
        const std::uint32_t n0 = c0 % 3 == 2 ? c0 - 2 : c0 + 1,
                            n1 = c1 % 3 == 2 ? c1 - 2 : c1 + 1;
        w0 = in + 3 * std::size_t{fv[n0]};
        w1 = in + 3 * std::size_t{fv[n1]};
      }
      for (int i = 0; i < 3; ++i)
        edge_point[i] = end_w * (pa[i] + pb[i]) + wing_w * (w0[i] + w1[i]);
    } else {
      // The border halfedge runs from s to u; the chain reads prev(s), s,
      // u, next(u).
      const std::uint32_t from = c0 == kNone ? a : b, to = c0 == kNone ? b : a;
      const double* ps = in + 3 * std::size_t{from};
      const double* pu = in + 3 * std::size_t{to};
      weigh2(edge_point, be[1], ps, be[2], pu);
      if (border_wide) {
        const double* pc = in + 3 * std::size_t{prev[from]};
        const double* pd = in + 3 * std::size_t{next[to]};
        for (int i = 0; i < 3; ++i)
          edge_point[i] += be[0] * pc[i] + be[3] * pd[i];
      }
    }
  }

  // Vertices, in place of their sums.
  const auto& bv = mask.border_vertex;
  const std::uint32_t* valence = s.valence.data();
  const Vertex_weights* weights = s.weights.data();
  for (std::uint32_t v = 0; v < V; ++v) {
    const double* pv = in + 3 * std::size_t{v};
    double* o = out + 3 * std::size_t{v};
    if (border && next[v] != kNone) {
      const double* pc = in + 3 * std::size_t{prev[v]};
      const double* pa = in + 3 * std::size_t{next[v]};
      for (int i = 0; i < 3; ++i)
        o[i] = bv[0] * pc[i] + bv[1] * pv[i] + bv[2] * pa[i];
      continue;
    }
    const Vertex_weights& w = weights[valence[v]];
    if (face_sum != nullptr && face_sum != sum) {
      const double* q = face_sum + 3 * std::size_t{v};
      for (int i = 0; i < 3; ++i)
        o[i] = w.self * pv[i] + w.neighbour * o[i] + w.face * q[i];
    } else {
      // One sum: edge neighbours and (PQQ) face points weigh alike.
      for (int i = 0; i < 3; ++i) o[i] = w.self * pv[i] + w.neighbour * o[i];
    }
  }
}

}  // namespace refine
}  // namespace subdivlab
