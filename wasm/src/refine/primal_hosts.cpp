// The PQQ and PTQ hosts' numbering, derived from CGAL's PQQ_1step and
// PTQ_1step on Surface_mesh (CGAL 5.5,
// Subdivision_method_3/internal/subdivision_hosts_impl_3.h):
//
// Edge split (both hosts; insert_vertex on halfedge 2e, a -> b, through
// Euler::split_vertex): vertex m = V + e and edge E + e are added; 2e runs
// a -> m, 2e + 1 m -> a, 2(E + e) m -> b, 2(E + e) + 1 b -> m. So a parent
// halfedge x splits into first(x) (from its source to m) and second(x)
// (from m to its target): x and x + 2E when x is even, x + 2E and x when it
// is odd. Each split sets the faces beside it to start at the second half,
// so after all splits face f starts at second(g*), g* its halfedge of
// highest edge index; its corners v1, v2, ... vk start at target(g*) and
// g_j runs v_j -> v_j+1 (g_k = g*), split at m_j.
//
// PQQ, per face (k corners, face point c = V + E + f, first new edge
// 2E + offset(f), first new face F + offset(f) - f = b):
//   split_face(v1->m1, v2->m2) adds edge m1-m2 (even halfedge m1 -> m2) and
//   face b = the corner quad at v2; split_vertex on that edge adds c and
//   edge c-m2 (even c -> m2), leaving m1 -> c; then for j = 3..k,
//   split_face(v_j->m_j, m1->c) adds edge m_j-c (even m_j -> c) and cuts
//   the quad at v_j off the rest, the quad keeping the rest's face (f at
//   j = 3, then the face the previous cut added) and the rest getting a new
//   one. Quads: v1 -> b + k - 2, v2 -> b, v3 -> f, v_j -> b + j - 3. Each
//   quad (c, m_j-1, v_j, m_j) starts at c -> m_j-1 for j <= 2 and at
//   m_j -> c after, as the last split_face set it.
// PTQ, per face (first new edge 2E + 3f = 2E + offset(f), first new face
//   F + 3f): split_face(v1->m1, v2->m2) adds
//   m1-m2 (even m1 -> m2) and face F + 3f (corner v2); split_face(m1->m2,
//   v3->m3) adds m2-m3 and F + 3f + 1 (corner v3); split_face(m2->m3,
//   v1->m1) adds m3-m1 and F + 3f + 2 (corner v1); f keeps the middle
//   triangle. Each corner triangle starts at its inner edge's odd halfedge,
//   the middle one at m3 -> m1.
// PQT (core/quad_triangle_3.h's PQT_1step): the same edge splits, then each
//   face in order split as PTQ splits a triangle and as PQQ splits any other
//   face, each adding its new edges, vertex and faces after the previous
//   face's. A triangle adds 3 edges and 3 faces, a k-gon k edges, k - 1
//   faces and a face point; so with q the polygons (faces other than
//   triangles) before f, f's first new edge is 2E + offset(f), its face
//   point V + E + q, its first new face F + offset(f) - q. The child mixes
//   triangles and quads: the kept faces first (face g's corners after
//   3g + q(g)), then the new ones, f's after 3F + Q + 4 offset(f) - 3f - q
//   (Q polygons in all).

#include "primal_hosts.h"

#include <algorithm>
#include <cstring>

namespace subdivlab {
namespace refine {
namespace {

/// The halves of parent halfedge x after the edge splits (E parent edges).
inline std::uint32_t first_half(std::uint32_t x, std::uint32_t E) {
  return (x & 1) != 0 ? x + 2 * E : x;
}
inline std::uint32_t second_half(std::uint32_t x, std::uint32_t E) {
  return (x & 1) != 0 ? x : x + 2 * E;
}

/// What a host builds for a child: every table when it will be refined
/// again; for the last level only what its buffers need, the face vertices
/// and, when edges are marked, the marked edges' ends, or when the run is
/// creased the halfedge targets (its sharp edges' ends, crease.h).
struct Parts {
  bool halfedges, targets;
  Parts(bool last, bool creased)
      : halfedges(!last), targets(!last || creased) {}
};

/// Counts, halfedge targets of the split edges, border halves, marks:
/// everything both hosts do alike.
void split_edges(const Level& p, Level& c, std::uint32_t child_edges,
                 std::size_t child_corners, const Parts& parts) {
  const std::uint32_t V = p.vertex_count, E = p.edge_count;
  c.edge_count = child_edges;
  c.border_edge_count = 2 * p.border_edge_count;
  size_to(c.face_vertices, child_corners);
  if (parts.halfedges) {
    size_to(c.face_halfedges, child_corners);
    size_to(c.halfedge_corner, 2 * std::size_t{child_edges});
  } else {
    release(c.face_halfedges);
    release(c.halfedge_corner);
  }
  if (parts.targets) {
    size_to(c.halfedge_target, 2 * std::size_t{child_edges});
    std::uint32_t* t = c.halfedge_target.data();
    const std::uint32_t* pt = p.halfedge_target.data();
    for (std::uint32_t e = 0; e < E; ++e) {
      const std::uint32_t a = pt[2 * e + 1], b = pt[2 * e], m = V + e;
      t[2 * e] = m;
      t[2 * e + 1] = a;
      t[2 * (E + e)] = b;
      t[2 * (E + e) + 1] = m;
    }
  } else {
    release(c.halfedge_target);
  }
  if (parts.halfedges && p.border_edge_count > 0) {
    // Border halves: the faces below never write them.
    const std::uint32_t* pc = p.halfedge_corner.data();
    std::uint32_t* cc = c.halfedge_corner.data();
    for (std::uint32_t x = 0; x < 2 * E; ++x) {
      if (pc[x] != kNone) continue;
      cc[first_half(x, E)] = kNone;
      cc[second_half(x, E)] = kNone;
    }
  }
  if (!parts.targets) {
    // The last level: release_before_last_topology took its marked edges'
    // ends from the parent.
    release(c.edge_marks);
    return;
  }
  release(c.marked_ends);
  if (p.edge_marks.empty()) {
    release(c.edge_marks);
  } else {
    size_to(c.edge_marks, child_edges);
    std::memcpy(c.edge_marks.data(), p.edge_marks.data(), E);
    std::memcpy(c.edge_marks.data() + E, p.edge_marks.data(), E);
    std::fill(c.edge_marks.begin() + 2 * std::size_t{E}, c.edge_marks.end(), 0);
  }
}

/// Where one parent face's children go: its first new edge, vertex (the
/// face point of a PQQ split) and face (the others follow it), where the
/// face that keeps its index starts its corners, and where its first new
/// face does (the others follow, a face's degree apart).
struct Face_slots {
  std::uint32_t first_edge, centre, first_face, kept_corner, first_corner;
};

/// What the per-face splits write into: the child's tables (null where
/// the child has none: halfedges on the last level, targets there unless
/// edges are marked, offsets unless it mixes degrees).
struct Child {
  std::uint32_t *vertices, *halfedges, *corner, *target, *offsets;
  Child(Level& c, const Parts& parts)
      : vertices(c.face_vertices.data()),
        halfedges(parts.halfedges ? c.face_halfedges.data() : nullptr),
        corner(parts.halfedges ? c.halfedge_corner.data() : nullptr),
        target(parts.targets ? c.halfedge_target.data() : nullptr),
        offsets(c.uniform_degree == 0 ? c.face_offsets.data() : nullptr) {}
};

/// Writes child face `face`, whose corners start at `corner`: its vertices,
/// its offset on a mixed child, and (unless it is the last level) its
/// halfedges and their corners.
template <std::uint32_t K>
inline void put_face(const Child& out, std::uint32_t face, std::uint32_t corner,
                     const std::uint32_t (&v)[K], const std::uint32_t (&h)[K]) {
  std::uint32_t* vertices = out.vertices + corner;
  for (std::uint32_t r = 0; r < K; ++r) vertices[r] = v[r];
  if (out.offsets != nullptr) out.offsets[face] = corner;
  if (out.halfedges == nullptr) return;
  std::uint32_t* fh = out.halfedges + corner;
  for (std::uint32_t r = 0; r < K; ++r) {
    fh[r] = h[r];
    out.corner[h[r]] = corner + r;
  }
}

/// What the per-face splits read: the parent's counts and corner tables,
/// held apart from the Level (the splits' stores could alias its counts).
struct Parent {
  std::uint32_t V, E;
  const std::uint32_t *halfedges, *vertices;
  explicit Parent(const Level& p)
      : V(p.vertex_count),
        E(p.edge_count),
        halfedges(p.face_halfedges.data()),
        vertices(p.face_vertices.data()) {}
};

/// PQQ_1step's split of parent face f (corners [begin, begin + k)): k quads
/// around the face point. Inlined into each host's loop (two callers
/// each: the compiler would call it, 15-25% slower on PTQ's topology).
[[gnu::always_inline]] inline void split_pqq_face(
    const Parent p, const Child& out, std::uint32_t f, std::uint32_t begin,
    std::uint32_t k, const Face_slots& s) {
  const std::uint32_t V = p.V, E = p.E;
  const std::uint32_t* fh = p.halfedges + begin;
  const std::uint32_t* fv = p.vertices + begin;
  const std::uint32_t start = first_corner_offset(fh, k);
  // g(j) for j = 1..k runs v_j -> v_j+1, which ends at corner start + j.
  auto at = [&](std::uint32_t j) {
    const std::uint32_t i = start + j;
    return i < k ? i : i - k;
  };
  auto g = [&](std::uint32_t j) { return fh[at(j)]; };
  auto m = [&](std::uint32_t j) { return V + (g(j) >> 1); };
  auto corner = [&](std::uint32_t face) {
    return face == f ? s.kept_corner
                     : s.first_corner + 4 * (face - s.first_face);
  };
  // Spoke j joins m_j and c: its halfedge m_j -> c (even, but odd for j=2).
  auto into_centre = [&](std::uint32_t j) {
    const std::uint32_t e = s.first_edge + j - 1;
    return j == 2 ? 2 * e + 1 : 2 * e;
  };
  if (out.target != nullptr) {
    for (std::uint32_t j = 1; j <= k; ++j) {
      const std::uint32_t h = into_centre(j);
      out.target[h] = s.centre;
      out.target[h ^ 1] = m(j);
    }
  }
  for (std::uint32_t j = 1; j <= k; ++j) {
    const std::uint32_t before = j == 1 ? k : j - 1;
    const std::uint32_t vj = fv[at(before)], mb = m(before), mj = m(j);
    const std::uint32_t from_centre = into_centre(before) ^ 1,
                        in = second_half(g(before), E),
                        out_half = first_half(g(j), E), back = into_centre(j);
    if (j <= 2) {
      const std::uint32_t face = j == 1 ? s.first_face + k - 2 : s.first_face;
      put_face<4>(out, face, corner(face), {mb, vj, mj, s.centre},
                  {from_centre, in, out_half, back});
    } else {
      const std::uint32_t face = j == 3 ? f : s.first_face + j - 3;
      put_face<4>(out, face, corner(face), {s.centre, mb, vj, mj},
                  {back, from_centre, in, out_half});
    }
  }
}

/// PTQ_1step's split of parent triangle f (corners from `begin`): the
/// middle triangle keeps f, the corner ones follow. Inlined as above.
[[gnu::always_inline]] inline void split_ptq_face(const Parent p,
                                                  const Child& out,
                                                  std::uint32_t f,
                                                  std::uint32_t begin,
                                                  const Face_slots& s) {
  const std::uint32_t V = p.V, E = p.E;
  const std::uint32_t* fh = p.halfedges + begin;
  const std::uint32_t* fv = p.vertices + begin;
  const std::uint32_t start = first_corner_offset(fh, 3);
  const std::uint32_t i1 = start == 2 ? 0 : start + 1,
                      i2 = start == 0 ? 2 : start - 1;
  const std::uint32_t g1 = fh[i1], g2 = fh[i2], g3 = fh[start];
  const std::uint32_t v1 = fv[start], v2 = fv[i1], v3 = fv[i2];
  const std::uint32_t m1 = V + (g1 >> 1), m2 = V + (g2 >> 1),
                      m3 = V + (g3 >> 1);
  const std::uint32_t e = s.first_edge;
  const std::uint32_t h12 = 2 * e, h23 = 2 * (e + 1), h31 = 2 * (e + 2);
  if (out.target != nullptr) {
    std::uint32_t* t = out.target;
    t[h12] = m2;
    t[h12 + 1] = m1;
    t[h23] = m3;
    t[h23 + 1] = m2;
    t[h31] = m1;
    t[h31 + 1] = m3;
  }
  const std::uint32_t a = s.first_corner;
  put_face<3>(out, f, s.kept_corner, {m1, m2, m3}, {h31, h12, h23});
  put_face<3>(out, s.first_face, a, {m1, v2, m2},
              {h12 + 1, second_half(g1, E), first_half(g2, E)});
  put_face<3>(out, s.first_face + 1, a + 3, {m2, v3, m3},
              {h23 + 1, second_half(g2, E), first_half(g3, E)});
  put_face<3>(out, s.first_face + 2, a + 6, {m3, v1, m1},
              {h31 + 1, second_half(g3, E), first_half(g1, E)});
}

}  // namespace

std::uint32_t pqq_child_vertex_count(const Level& p) {
  return p.vertex_count + p.edge_count + p.face_count;
}

std::uint32_t ptq_child_vertex_count(const Level& p) {
  return p.vertex_count + p.edge_count;
}

std::uint32_t pqt_child_vertex_count(const Level& p) {
  return p.vertex_count + p.edge_count + polygon_count(p);
}

void release_before_last_topology(Level& p, Level& c) {
  release(p.halfedge_corner);
  release(p.positions);
  release(c.marked_ends);
  if (!p.edge_marks.empty()) {
    // A marked edge a-b's halves e (a -> m) and E + e (m -> b) are the
    // marked edges, the spokes never are.
    const std::uint32_t V = p.vertex_count, E = p.edge_count;
    const std::uint8_t* marks = p.edge_marks.data();
    const std::uint32_t* pt = p.halfedge_target.data();
    const auto marked = static_cast<std::size_t>(
        std::count(p.edge_marks.begin(), p.edge_marks.end(), 1));
    size_to(c.marked_ends, 4 * marked);
    std::uint32_t* first = c.marked_ends.data();
    std::uint32_t* second = first + 2 * marked;
    for (std::uint32_t e = 0; e < E; ++e) {
      if (marks[e] == 0) continue;
      const std::uint32_t m = V + e;
      *first++ = pt[2 * e + 1];
      *first++ = m;
      *second++ = m;
      *second++ = pt[2 * e];
    }
  }
  release(p.halfedge_target);
  release(p.edge_marks);
}

void refine_pqq_topology(const Level& p, Level& c, bool last) {
  const std::uint32_t V = p.vertex_count, E = p.edge_count, F = p.face_count,
                      S = p.corner_count();
  const Parts parts(last, p.creased);
  split_edges(p, c, 2 * E + S, 4 * std::size_t{S}, parts);
  c.vertex_count = pqq_child_vertex_count(p);
  c.face_count = S;
  c.uniform_degree = 4;
  release(c.face_offsets);
  const Child out(c, parts);
  const Parent in(p);
  for (std::uint32_t f = 0; f < F; ++f) {
    const std::uint32_t begin = p.face_begin(f), k = p.face_end(f) - begin;
    const std::uint32_t first_face = F + begin - f;
    split_pqq_face(
        in, out, f, begin, k,
        {2 * E + begin, V + E + f, first_face, 4 * f, 4 * first_face});
  }
}

void refine_ptq_topology(const Level& p, Level& c, bool last) {
  const std::uint32_t E = p.edge_count, F = p.face_count;
  const Parts parts(last, p.creased);
  split_edges(p, c, 2 * E + 3 * F, 12 * std::size_t{F}, parts);
  c.vertex_count = ptq_child_vertex_count(p);
  c.face_count = 4 * F;
  c.uniform_degree = 3;
  release(c.face_offsets);
  const Child out(c, parts);
  const Parent in(p);
  for (std::uint32_t f = 0; f < F; ++f)
    split_ptq_face(in, out, f, 3 * f,
                   {2 * E + 3 * f, kNone, F + 3 * f, 3 * f, 3 * (F + 3 * f)});
}

std::uint32_t polygon_count(const Level& l) {
  if (l.uniform_degree != 0) return l.uniform_degree == 3 ? 0 : l.face_count;
  std::uint32_t count = 0;
  for (std::uint32_t f = 0; f < l.face_count; ++f)
    count += l.face_offsets[f + 1] - l.face_offsets[f] != 3 ? 1 : 0;
  return count;
}

void refine_pqt_topology(const Level& p, Level& c, bool last) {
  const std::uint32_t V = p.vertex_count, E = p.edge_count, F = p.face_count,
                      S = p.corner_count(), Q = polygon_count(p);
  const Parts parts(last, p.creased);
  split_edges(p, c, 2 * E + S, 4 * std::size_t{S}, parts);
  c.vertex_count = V + E + Q;
  c.face_count = F + S - Q;
  // Triangles give triangles, the others quads.
  c.uniform_degree = Q == 0 ? 3 : Q == F ? 4 : 0;
  if (c.uniform_degree == 0) {
    size_to(c.face_offsets, std::size_t{c.face_count} + 1);
    c.face_offsets[c.face_count] = 4 * S;
  } else {
    release(c.face_offsets);
  }
  const Child out(c, parts);
  const Parent in(p);
  // q: the polygons before f. The kept faces come first (f's 3 or 4
  // corners after 3f + q), then each face's new ones: 3 triangles after a
  // triangle, k - 1 quads after a k-gon, so 4 begin - 3f - q corners
  // before f's.
  std::uint32_t q = 0;
  for (std::uint32_t f = 0; f < F; ++f) {
    const std::uint32_t begin = p.face_begin(f), k = p.face_end(f) - begin;
    const Face_slots s{2 * E + begin, V + E + q, F + begin - q, 3 * f + q,
                       3 * F + Q + 4 * begin - 3 * f - q};
    if (k == 3) {
      split_ptq_face(in, out, f, begin, s);
    } else {
      split_pqq_face(in, out, f, begin, k, s);
      ++q;
    }
  }
}

}  // namespace refine
}  // namespace subdivlab
