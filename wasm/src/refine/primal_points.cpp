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

/// scratch.valence and, on a level with a border, the border chain.
void count_valences(const Level& p, Primal_scratch& s) {
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
    release(s.border_next);
    release(s.border_prev);
  }
}

/// Largest valence of a vertex of `p` not on the border.
std::uint32_t largest_interior_valence(const Level& p,
                                       const Primal_scratch& s) {
  std::uint32_t most = 0;
  for (std::uint32_t v = 0; v < p.vertex_count; ++v)
    if (p.border_edge_count == 0 || s.border_next[v] == kNone)
      most = std::max(most, s.valence[v]);
  return most;
}

}  // namespace

double primal_scratch_bytes(double vertices, bool face_sums, bool border) {
  return vertices * ((face_sums ? 24 : 0) + 4 + (border ? 8 : 0));
}

double pqt_scratch_bytes(double vertices, double edges, bool polygons,
                         bool border) {
  // The ring sums, and with polygons their face sums and counts.
  return primal_scratch_bytes(vertices, polygons, border) + 24 * vertices +
         (polygons ? 4 * vertices + edges : 0);
}

std::uint32_t primal_uncovered_valence(const Level& p, const Primal_mask& mask,
                                       Primal_scratch& s) {
  const std::uint32_t V = p.vertex_count;
  count_valences(p, s);
  const std::uint32_t* valence = s.valence.data();
  const std::uint32_t most = largest_interior_valence(p, s);
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
  const std::uint32_t* fh = p.face_halfedges.data();
  const std::uint32_t* corner = p.halfedge_corner.data();
  const std::uint32_t* next = s.border_next.data();
  const std::uint32_t* prev = s.border_prev.data();
  // The edge points' slots gather their wings (the face points, or the
  // triangles' opposite vertices) from the face pass, which reads the
  // faces in order: the edge pass then reads no face.
  double* const edge_points = out + 3 * std::size_t{V};
  std::fill(edge_points, edge_points + 3 * std::size_t{E}, 0.0);
  const auto wing = [&](std::uint32_t h, const double* point) {
    add(edge_points + 3 * std::size_t{h >> 1}, point);
  };

  // Faces: centroids, summed at their vertices and edges (PQQ); the
  // vertex opposite each edge (PTQ).
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
      for (std::uint32_t i = begin; i < end; ++i) {
        add(face_sum + 3 * std::size_t{fv[i]}, face_point);
        wing(fh[i], face_point);
      }
    }
  } else {
    // Triangles: corner i's halfedge ends at its vertex; the next corner's
    // is opposite.
    for (std::uint32_t c = 0; c < 3 * F; c += 3) {
      const double* p0 = in + 3 * std::size_t{fv[c]};
      const double* p1 = in + 3 * std::size_t{fv[c + 1]};
      const double* p2 = in + 3 * std::size_t{fv[c + 2]};
      wing(fh[c], p1);
      wing(fh[c + 1], p2);
      wing(fh[c + 2], p0);
    }
  }

  // Edges: edge points, neighbour sums.
  const double end_w = mask.edge_end, wing_w = mask.edge_wing;
  const auto& be = mask.border_edge;
  const bool border_wide = be[0] != 0 || be[3] != 0;
  double* edge_point = edge_points;
  for (std::uint32_t e = 0; e < E; ++e, edge_point += 3) {
    const std::uint32_t a = t[2 * e + 1], b = t[2 * e];
    const double* pa = in + 3 * std::size_t{a};
    const double* pb = in + 3 * std::size_t{b};
    add(sum + 3 * std::size_t{a}, pb);
    add(sum + 3 * std::size_t{b}, pa);
    const std::uint32_t c0 = border ? corner[2 * e] : 0,
                        c1 = border ? corner[2 * e + 1] : 0;
    if (c0 != kNone && c1 != kNone) {
      // The slot holds its two wings' sum.
      for (int i = 0; i < 3; ++i)
        edge_point[i] = end_w * (pa[i] + pb[i]) + wing_w * edge_point[i];
    } else {
      // The border halfedge runs from s to u; the chain reads prev(s), s,
      // u, next(u). The one wing the face pass added is not used.
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

// Quad/triangle. The refined mesh around each of its vertices, in the
// parent's terms (M_j the midpoint of a face's halfedge j, which runs
// v_j-1 -> v_j; c a polygon's centroid):
//   old vertex v: edge neighbours the midpoints of its edges, opposite quad
//     corners the centroids of its polygons;
//   edge point M_j: edge neighbours its edge's ends and, on each side, the
//     triangle's two other midpoints, or the polygon's c (opposite corners
//     M_j-1 and M_j+1, one per quad);
//   face point c: edge neighbours the polygon's midpoints, opposite corners
//     its vertices.
// The face pass sums each side of an edge point's ring (ring and opposite
// weights applied) in the edge point's place, the edge pass adds its ends
// and averages; the polygons beside an edge give its counts.
void refine_pqt_points(const Level& p, const Quad_triangle_mask& mask,
                       Primal_scratch& s, Level& c) {
  const std::uint32_t V = p.vertex_count, E = p.edge_count, F = p.face_count;
  const bool border = p.border_edge_count > 0;
  const bool polygons = c.vertex_count > V + E;
  count_valences(p, s);
  size_to(c.positions, 3 * std::size_t{c.vertex_count});
  size_to(s.ring, 3 * std::size_t{V});
  std::fill(s.ring.begin(), s.ring.end(), 0.0);
  if (polygons) {
    size_to(s.faces, 3 * std::size_t{V});
    std::fill(s.faces.begin(), s.faces.end(), 0.0);
    size_to(s.polygons, V);
    std::fill(s.polygons.begin(), s.polygons.end(), 0);
    size_to(s.edge_polygons, E);
    std::fill(s.edge_polygons.begin(), s.edge_polygons.end(), 0);
  } else {
    release(s.faces);
    release(s.polygons);
    release(s.edge_polygons);
  }
  const double* in = p.positions.data();
  double* out = c.positions.data();
  double* ring = s.ring.data();
  double* face_sum = s.faces.data();
  std::uint32_t* vertex_polygons = s.polygons.data();
  std::uint8_t* edge_polygons = s.edge_polygons.data();
  const std::uint32_t* t = p.halfedge_target.data();
  const std::uint32_t* fv = p.face_vertices.data();
  const std::uint32_t* fh = p.face_halfedges.data();
  const std::uint32_t* corner = p.halfedge_corner.data();
  const std::uint32_t* next = s.border_next.data();
  const std::uint32_t* prev = s.border_prev.data();
  auto at = [&](std::uint32_t v) { return in + 3 * std::size_t{v}; };
  auto midpoint = [&](double* m, std::uint32_t a, std::uint32_t b) {
    const double *pa = at(a), *pb = at(b);
    for (int i = 0; i < 3; ++i) m[i] = 0.5 * (pa[i] + pb[i]);
  };
  const double ring_w = mask.ring, opposite_w = mask.opposite;

  // Faces: the sides of the edge points' rings; polygons' face points and
  // their centroids summed at their vertices.
  double* edge_sum = out + 3 * std::size_t{V};
  std::fill(edge_sum, edge_sum + 3 * std::size_t{E}, 0.0);
  auto side = [&](std::uint32_t h) {
    return edge_sum + 3 * std::size_t{h >> 1};
  };
  double* face_point = out + 3 * (std::size_t{V} + E);
  std::uint32_t polygon_k = 0;
  Vertex_weights polygon_w;
  for (std::uint32_t f = 0; f < F; ++f) {
    const std::uint32_t begin = p.face_begin(f), k = p.face_end(f) - begin;
    const std::uint32_t* v = fv + begin;
    const std::uint32_t* h = fh + begin;
    if (k == 3) {
      double m0[3], m1[3], m2[3];
      midpoint(m0, v[2], v[0]);
      midpoint(m1, v[0], v[1]);
      midpoint(m2, v[1], v[2]);
      double *s0 = side(h[0]), *s1 = side(h[1]), *s2 = side(h[2]);
      for (int i = 0; i < 3; ++i) {
        s0[i] += ring_w * (m1[i] + m2[i]);
        s1[i] += ring_w * (m2[i] + m0[i]);
        s2[i] += ring_w * (m0[i] + m1[i]);
      }
      continue;
    }
    double centre[3] = {0, 0, 0};
    for (std::uint32_t j = 0; j < k; ++j) {
      const double* pj = at(v[j]);
      for (int i = 0; i < 3; ++i) centre[i] += pj[i];
    }
    for (int i = 0; i < 3; ++i) centre[i] /= k;
    // M_j-1, M_j, M_j+1 rolling round the face.
    double before[3], here[3], after[3], midpoints[3] = {0, 0, 0};
    midpoint(before, v[k - 2], v[k - 1]);
    midpoint(here, v[k - 1], v[0]);
    for (std::uint32_t j = 0; j < k; ++j) {
      midpoint(after, v[j], v[j + 1 < k ? j + 1 : 0]);
      double* sj = side(h[j]);
      for (int i = 0; i < 3; ++i) {
        sj[i] += ring_w * centre[i] + opposite_w * (before[i] + after[i]);
        midpoints[i] += here[i];
        before[i] = here[i];
        here[i] = after[i];
      }
      ++edge_polygons[h[j] >> 1];
      double* q = face_sum + 3 * std::size_t{v[j]};
      for (int i = 0; i < 3; ++i) q[i] += centre[i];
      ++vertex_polygons[v[j]];
    }
    // The face point: k edge neighbours (the midpoints), k quads whose
    // corners opposite it are the face's vertices.
    if (k != polygon_k) {
      polygon_w = mask.vertex_weights(k, k);
      polygon_k = k;
    }
    double corners[3] = {0, 0, 0};
    for (std::uint32_t j = 0; j < k; ++j) {
      const double* pj = at(v[j]);
      for (int i = 0; i < 3; ++i) corners[i] += pj[i];
    }
    for (int i = 0; i < 3; ++i)
      face_point[i] = polygon_w.self * centre[i] +
                      polygon_w.neighbour * midpoints[i] +
                      polygon_w.face * corners[i];
    face_point += 3;
  }

  // Edges: the edge points (the linear midpoints averaged), and the
  // midpoints summed at the edges' ends. Inside, with n polygons beside
  // the edge (n = 0, 1, 2), the edge point has 6 - n edges and 2n quads.
  Quad_triangle_mask::Averaging sides[3];
  for (std::uint32_t n = 0; n < 3; ++n) sides[n] = mask.averaging(6 - n, 2 * n);
  const auto& bw = mask.border;
  const bool smooth = mask.smooth_boundary;
  for (std::uint32_t e = 0; e < E; ++e) {
    const std::uint32_t a = t[2 * e + 1], b = t[2 * e];
    const double *pa = at(a), *pb = at(b);
    double m[3];
    midpoint(m, a, b);
    double* ra = ring + 3 * std::size_t{a};
    double* rb = ring + 3 * std::size_t{b};
    for (int i = 0; i < 3; ++i) {
      ra[i] += m[i];
      rb[i] += m[i];
    }
    double* o = edge_sum + 3 * std::size_t{e};
    const std::uint32_t c0 = corner[2 * e], c1 = corner[2 * e + 1];
    if (c0 != kNone && c1 != kNone) {
      const Quad_triangle_mask::Averaging& w =
          sides[polygons ? edge_polygons[e] : 0];
      for (int i = 0; i < 3; ++i) {
        const double average =
            w.alpha * (mask.self * m[i] + ring_w * (pa[i] + pb[i]) + o[i]);
        o[i] = m[i] + w.lambda * (average - m[i]);
      }
    } else if (!smooth) {
      for (int i = 0; i < 3; ++i) o[i] = m[i];
    } else {
      // The refined border runs from -> m -> to along the border halfedge.
      const double* from = c0 == kNone ? pa : pb;
      const double* to = c0 == kNone ? pb : pa;
      for (int i = 0; i < 3; ++i)
        o[i] = bw[0] * from[i] + bw[1] * m[i] + bw[2] * to[i];
    }
  }

  // Old vertices. Inside: n edges (their midpoints summed in `ring`) and
  // the polygons' centroids as opposite corners; weights by valence when
  // no polygon is there.
  const std::uint32_t* valence = s.valence.data();
  s.weights.resize(std::size_t{largest_interior_valence(p, s)} + 1);
  for (std::uint32_t n = 1; n < s.weights.size(); ++n)
    s.weights[n] = mask.vertex_weights(n, 0);
  const Vertex_weights* weights = s.weights.data();
  for (std::uint32_t v = 0; v < V; ++v) {
    const double* pv = at(v);
    double* o = out + 3 * std::size_t{v};
    if (border && next[v] != kNone) {
      if (!smooth) {
        for (int i = 0; i < 3; ++i) o[i] = pv[i];
        continue;
      }
      // Along the refined border: prev's midpoint -> v -> next's midpoint.
      double mp[3], mn[3];
      midpoint(mp, prev[v], v);
      midpoint(mn, v, next[v]);
      for (int i = 0; i < 3; ++i)
        o[i] = bw[0] * mp[i] + bw[1] * pv[i] + bw[2] * mn[i];
      continue;
    }
    const double* r = ring + 3 * std::size_t{v};
    const std::uint32_t nq = polygons ? vertex_polygons[v] : 0;
    if (nq == 0) {
      const Vertex_weights& w = weights[valence[v]];
      for (int i = 0; i < 3; ++i) o[i] = w.self * pv[i] + w.neighbour * r[i];
      continue;
    }
    const Vertex_weights w = mask.vertex_weights(valence[v], nq);
    const double* q = face_sum + 3 * std::size_t{v};
    for (int i = 0; i < 3; ++i)
      o[i] = w.self * pv[i] + w.neighbour * r[i] + w.face * q[i];
  }
}

}  // namespace refine
}  // namespace subdivlab
