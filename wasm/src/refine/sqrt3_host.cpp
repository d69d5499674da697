// The sqrt(3) host's numbering, derived from CGAL's Sqrt3_1step on
// Surface_mesh (CGAL 5.5, Subdivision_method_3/internal/
// subdivision_hosts_impl_3.h, with Euler_operations.h and Surface_mesh.h).
// Parent counts V, E, F; a face's halfedges h0, h1, h2 start at
// halfedge(f), h_k runs t_{k-1} -> t_k.
//
// 1. Faces in index order. A face without a border edge to refine:
//    add_center_vertex(h0) adds vertex c, edges ea, eb, ec (even halfedge
//    of each: t0 -> c, t1 -> c, t2 -> c) and faces F + 2i, F + 2i + 1 (i
//    the face's rank among all faces): face i = (h0, 2ea, 2ec + 1),
//    F + 2i = (h1, 2eb, 2ea + 1), F + 2i + 1 = (h2, 2ec, 2eb + 1), each
//    starting at its old halfedge. So the triangle of h_k is (h_k, spoke
//    t_k -> c, spoke c -> t_{k-1}).
//    A face whose border edge is refined (hd = h_kb: a -> b, x the third
//    vertex): split_edge(hd) twice adds v1 (next to a) and v2 (next to b)
//    and edges E1 (2E1: v1 -> a, on the border), E2 (2E2: v2 -> v1, on the
//    border); hd now runs v2 -> b and its border twin b -> v2. Then
//    split_face(a -> v1, hd_next) adds E3 (2E3: v1 -> x) and a face; and
//    split_face(v1 -> v2, hd_next) adds E4 (2E4: v2 -> x) and another:
//    face i = (2E3, x -> a, 2E1 + 1), F + 2i = (2E4, 2E3 + 1, 2E2 + 1),
//    F + 2i + 1 = (2E4 + 1, hd, hd_next). v1 gets the border point nearer
//    a (Sqrt3_mask_3's ept2), v2 the one nearer b (ept1).
//    Nothing is removed yet, so vertices, edges and faces are appended:
//    face i's first vertex is V + i + (border faces before i), its first
//    edge E + 3i + (border faces before i).
// 2. Old edges in index order, unless on the border: join_face(2e) then
//    split_face(prev, next) flips it. join_face removes edge e and the face
//    of 2e + 1; split_face takes both back from Surface_mesh's free lists
//    (LIFO, one element each), so nothing is left removed, collect_garbage
//    has nothing to do and the step renumbers nothing. With 2e: a -> b in
//    the triangle (c1, a, b) (next(2e) = N1: b -> c1, prev = P1: c1 -> a)
//    and 2e + 1 in (c2, b, a) (N2: a -> c2, P2: c2 -> b), the flip leaves
//    face(2e) = (2e: c1 -> c2, P2, N1) and face(2e + 1) = (2e + 1, P1, N2),
//    each starting at its half of e. Every triangle of step 1 holds one old
//    edge, so each flip reads triangles no other flip has changed.
// Triangles of step 1 no flip takes keep their step-1 form: those of the
// border edges not refined (non-border steps) and F + 2i of each refined
// border face. Checked against a dump of CGAL's result by the tests
// (tests/core/test_refine_sqrt3.cpp, levels 1-3 of every fixture).

#include "sqrt3_host.h"

#include <algorithm>

namespace subdivlab {
namespace refine {
namespace {

constexpr std::uint32_t kNoBorder = 3;

/// A non-border parent halfedge's triangle after step 1: its face, the
/// vertex opposite it, and the halfedges after and before it.
struct Triangle {
  std::uint32_t face, apex, next, prev;
};

struct Writer {
  Level& c;
  bool halfedges;
  void face(std::uint32_t f, std::uint32_t v0, std::uint32_t v1,
            std::uint32_t v2, std::uint32_t h0, std::uint32_t h1,
            std::uint32_t h2) const {
    std::uint32_t* v = c.face_vertices.data() + 3 * std::size_t{f};
    v[0] = v0;
    v[1] = v1;
    v[2] = v2;
    if (!halfedges) return;
    std::uint32_t* h = c.face_halfedges.data() + 3 * std::size_t{f};
    h[0] = h0;
    h[1] = h1;
    h[2] = h2;
    std::uint32_t* corner = c.halfedge_corner.data();
    corner[h0] = 3 * f;
    corner[h1] = 3 * f + 1;
    corner[h2] = 3 * f + 2;
  }
  void edge(std::uint32_t e, std::uint32_t to_even,
            std::uint32_t to_odd) const {
    if (!halfedges) return;
    c.halfedge_target[2 * e] = to_even;
    c.halfedge_target[2 * e + 1] = to_odd;
  }
};

}  // namespace

double sqrt3_scratch_bytes(double faces, bool border_step) {
  return border_step ? 4 * faces : 0;
}

std::uint32_t sqrt3_multi_border_faces(const Level& l) {
  if (l.border_edge_count == 0) return 0;
  std::uint32_t count = 0;
  const std::uint32_t* fh = l.face_halfedges.data();
  const std::uint32_t* corner = l.halfedge_corner.data();
  for (std::uint32_t f = 0; f < l.face_count; ++f) {
    int border = 0;
    for (std::uint32_t k = 0; k < 3; ++k)
      border += corner[fh[3 * f + k] ^ 1] == kNone ? 1 : 0;
    count += border > 1 ? 1 : 0;
  }
  return count;
}

void refine_sqrt3_topology(const Level& p, bool border_step, Sqrt3_scratch& s,
                           Level& c, bool last) {
  const std::uint32_t V = p.vertex_count, E = p.edge_count, F = p.face_count;
  const std::uint32_t* fh = p.face_halfedges.data();
  const std::uint32_t* fv = p.face_vertices.data();
  const std::uint32_t* pt = p.halfedge_target.data();
  const std::uint32_t* pc = p.halfedge_corner.data();
  border_step = border_step && p.border_edge_count > 0;
  const std::uint32_t B = border_step ? p.border_edge_count : 0;

  if (border_step) {
    size_to(s.face_code, F);
    std::uint32_t before = 0;
    for (std::uint32_t f = 0; f < F; ++f) {
      std::uint32_t kb = kNoBorder;
      for (std::uint32_t k = 0; k < 3 && kb == kNoBorder; ++k)
        if (pc[fh[3 * f + k] ^ 1] == kNone) kb = k;
      s.face_code[f] = 4 * before + kb;
      before += kb != kNoBorder ? 1 : 0;
    }
  } else {
    release(s.face_code);
  }
  const std::uint32_t* code = s.face_code.data();

  c.vertex_count = V + F + B;
  c.edge_count = E + 3 * F + B;
  c.face_count = 3 * F;
  c.uniform_degree = 3;
  release(c.face_offsets);
  release(c.vertex_halfedge);
  release(c.edge_marks);
  c.border_edge_count = p.border_edge_count + 2 * B;
  const Writer out{c, !last};
  size_to(c.face_vertices, 9 * std::size_t{F});
  if (out.halfedges) {
    size_to(c.face_halfedges, 9 * std::size_t{F});
    size_to(c.halfedge_corner, 2 * std::size_t{c.edge_count});
    size_to(c.halfedge_target, 2 * std::size_t{c.edge_count});
  } else {
    release(c.face_halfedges);
    release(c.halfedge_corner);
    release(c.halfedge_target);
  }

  // The triangle of non-border parent halfedge x after step 1.
  auto triangle = [&](std::uint32_t x) -> Triangle {
    const std::uint32_t corner = pc[x], f = corner / 3, k = corner % 3;
    const std::uint32_t before = border_step ? code[f] >> 2 : 0,
                        kb = border_step ? code[f] & 3 : kNoBorder;
    const std::uint32_t vb = V + f + before, eb = E + 3 * f + before;
    if (kb == kNoBorder) {
      const std::uint32_t prior = k == 0 ? 2 : k - 1;
      return {k == 0 ? f : F + 2 * f + k - 1, vb, 2 * (eb + k),
              2 * (eb + prior) + 1};
    }
    if (k == (kb + 1) % 3)  // hd_next, in F + 2i + 1 = (2E4 + 1, hd, x)
      return {F + 2 * f + 1, vb + 1, 2 * (eb + 3) + 1, fh[3 * f + kb]};
    return {f, vb, 2 * eb + 1, 2 * (eb + 2)};  // prev(hd), in face i
  };

  // Step 1's new elements: spokes' targets, refined border edges, and the
  // triangles no flip takes.
  for (std::uint32_t f = 0; f < F; ++f) {
    const std::uint32_t before = border_step ? code[f] >> 2 : 0,
                        kb = border_step ? code[f] & 3 : kNoBorder;
    const std::uint32_t vb = V + f + before, eb = E + 3 * f + before;
    const std::uint32_t* h = fh + 3 * f;
    const std::uint32_t* t = fv + 3 * f;
    if (kb == kNoBorder) {
      for (std::uint32_t k = 0; k < 3; ++k) {
        out.edge(eb + k, vb, t[k]);
        const std::uint32_t x = h[k];
        if (pc[x ^ 1] != kNone) continue;
        // A border edge left as it is: its step-1 triangle stays.
        const std::uint32_t prior = k == 0 ? 2 : k - 1;
        out.face(k == 0 ? f : F + 2 * f + k - 1, t[k], vb, t[prior], x,
                 2 * (eb + k), 2 * (eb + prior) + 1);
        if (out.halfedges) c.halfedge_corner[x ^ 1] = kNone;
      }
      continue;
    }
    const std::uint32_t hd = h[kb], b = t[kb], x = t[(kb + 1) % 3],
                        a = t[(kb + 2) % 3];
    const std::uint32_t v1 = vb, v2 = vb + 1, e1 = eb, e2 = eb + 1, e3 = eb + 2,
                        e4 = eb + 3;
    out.edge(e1, a, v1);
    out.edge(e2, v1, v2);
    out.edge(e3, x, v1);
    out.edge(e4, x, v2);
    out.face(F + 2 * f, x, v1, v2, 2 * e4, 2 * e3 + 1, 2 * e2 + 1);
    if (out.halfedges) {
      c.halfedge_target[hd] = b;
      c.halfedge_target[hd ^ 1] = v2;
      c.halfedge_corner[hd ^ 1] = kNone;
      c.halfedge_corner[2 * e1] = kNone;
      c.halfedge_corner[2 * e2] = kNone;
    }
  }

  // Step 2: the flips.
  for (std::uint32_t e = 0; e < E; ++e) {
    const std::uint32_t h = 2 * e;
    if (pc[h] == kNone || pc[h + 1] == kNone) {
      if (out.halfedges && !border_step) {
        c.halfedge_target[h] = pt[h];
        c.halfedge_target[h + 1] = pt[h + 1];
      }
      continue;
    }
    const Triangle t1 = triangle(h), t2 = triangle(h + 1);
    out.face(t1.face, t2.apex, pt[h], t1.apex, h, t2.prev, t1.next);
    out.face(t2.face, t1.apex, pt[h + 1], t2.apex, h + 1, t1.prev, t2.next);
    out.edge(e, t2.apex, t1.apex);
  }
}

void refine_sqrt3_points(const Level& p, const Primal_mask& mask,
                         bool border_step, const Sqrt3_scratch& s,
                         Primal_scratch& ps, Level& c) {
  const std::uint32_t V = p.vertex_count, E = p.edge_count, F = p.face_count;
  border_step = border_step && p.border_edge_count > 0;
  const bool border = p.border_edge_count > 0;
  size_to(c.positions, 3 * std::size_t{c.vertex_count});
  const double* in = p.positions.data();
  double* out = c.positions.data();
  // The neighbour sums gather in the child's slots of the parent's
  // vertices, which the vertex pass overwrites.
  double* ring = out;
  std::fill(ring, ring + 3 * std::size_t{V}, 0.0);
  const std::uint32_t* t = p.halfedge_target.data();
  const std::uint32_t* fv = p.face_vertices.data();
  const std::uint32_t* code = s.face_code.data();
  const std::uint32_t* next = ps.border_next.data();
  const std::uint32_t* prev = ps.border_prev.data();
  auto at = [&](std::uint32_t v) { return in + 3 * std::size_t{v}; };

  // Faces: centroids (Linear_mask_3::face_node), or on a border step the
  // two points of a face's border edge (Sqrt3_mask_3::border_node; the
  // border chain reads prev_s, s, t, next_t along the border halfedge
  // s -> t).
  const auto& be = mask.border_edge;
  for (std::uint32_t f = 0; f < F; ++f) {
    const std::uint32_t* v = fv + 3 * f;
    const std::uint32_t before = border_step ? code[f] >> 2 : 0,
                        kb = border_step ? code[f] & 3 : kNoBorder;
    double* o = out + 3 * (std::size_t{V} + f + before);
    if (kb == kNoBorder) {
      const double *p0 = at(v[0]), *p1 = at(v[1]), *p2 = at(v[2]);
      for (int i = 0; i < 3; ++i) o[i] = (p0[i] + p1[i] + p2[i]) / 3.0;
      continue;
    }
    const std::uint32_t sv = v[kb], tv = v[(kb + 2) % 3];
    const double *pp = at(prev[sv]), *ps_ = at(sv), *pt_ = at(tv),
                 *pn = at(next[tv]);
    for (int i = 0; i < 3; ++i) {
      o[i] = be[3] * pp[i] + be[2] * ps_[i] + be[1] * pt_[i] + be[0] * pn[i];
      o[3 + i] =
          be[0] * pp[i] + be[1] * ps_[i] + be[2] * pt_[i] + be[3] * pn[i];
    }
  }

  // Neighbour sums.
  for (std::uint32_t e = 0; e < E; ++e) {
    const std::uint32_t a = t[2 * e + 1], b = t[2 * e];
    const double *pa = at(a), *pb = at(b);
    for (int i = 0; i < 3; ++i) {
      ring[3 * std::size_t{a} + i] += pb[i];
      ring[3 * std::size_t{b} + i] += pa[i];
    }
  }

  // Vertices: Sqrt3_mask_3::vertex_node inside; on the border kept, or on a
  // border step moved by the border rule.
  const auto& bv = mask.border_vertex;
  const std::uint32_t* valence = ps.valence.data();
  const Vertex_weights* weights = ps.weights.data();
  for (std::uint32_t v = 0; v < V; ++v) {
    const double* pv = at(v);
    double* o = out + 3 * std::size_t{v};
    if (border && next[v] != kNone) {
      if (!border_step) {
        for (int i = 0; i < 3; ++i) o[i] = pv[i];
        continue;
      }
      const double *pc = at(prev[v]), *pa = at(next[v]);
      for (int i = 0; i < 3; ++i)
        o[i] = bv[0] * pc[i] + bv[1] * pv[i] + bv[2] * pa[i];
      continue;
    }
    const Vertex_weights& w = weights[valence[v]];
    for (int i = 0; i < 3; ++i) o[i] = w.self * pv[i] + w.neighbour * o[i];
  }
}

}  // namespace refine
}  // namespace subdivlab
