// The DQQ host's numbering. Corners: x a parent halfedge not on the border,
// the corner of face(x) at target(x); c_0 = halfedge(v) and c_j+1 =
// opposite(next(c_j)) circulate around v (halfedges_around_target); o_v is
// the number of corners of the vertices before v, n_v its valence. F-face
// f, E-face e, V-face v: the faces Doo-Sabin builds per face, edge, vertex.
//
// Closed: CGAL 5.5's DQQ_1step (Subdivision_method_3/internal/
// subdivision_hosts_impl_3.h), then collect_garbage (subdivide_prepare's
// collect_removed). Slots before the garbage is collected:
//   vertices  per vertex, per corner c_j: insert_vertex adds V + o_v + j
//             (the corner's point) and spoke edge E + 2 o_v + j; then, for
//             c_n-1, c_0, ..., c_n-2, split_face cuts the corner off its
//             face: cut edge E + 2 o_v + n_v + (j + 1) mod n_v, even
//             halfedge c_j -> c_j+1, and triangle F + o_v + (j + 1) mod n_v.
//   edges     per old edge e in order: split_face twice (the F-face edges
//             along 2e, then 2e + 1: even halfedge corner(prev x) ->
//             corner(x)), join_face frees edge e and a face, which the next
//             edge's first split reuses (the free lists are LIFO). So the
//             edge along x is e - 1 (x = 2e, e > 0), 5E (x = 0) or
//             5E + 1 + e (x = 2e + 1); edge E - 1 stays free. E-face e
//             lands in F + 2E + 1 + e; F + 2E stays free.
//   removal   remove_center_vertex removes the old vertices, the spokes and
//             every cut triangle but the first (F + o_v, the V-face, which
//             starts at its halfedge into c_n-1 and runs c_n-1, ..., c_0).
// collect_garbage then fills the free slots from the front with the last
// used slots from the back (Surface_mesh's two-pointer swap); the
// halfedges of an edge move with it, parity kept: the k-th used slot from
// the back that lies past the kept count goes to the k-th free slot from
// the front. The host computes where each slot ends without simulating
// this (no flags, no move tables). Vertices: V + k stays below 2E, else
// goes to 2E - 1 - k. Edges: see refine_closed. Faces, in order: the
// F-faces, then per vertex v its V-face (slot F + o_v) and its n_v - 1
// freed triangle slots, which take the E-faces from E - 1 down, then the
// V-faces of the last vertices from V - 1 down. F-face f keeps f and starts at
// the corner of its halfedge of highest edge index (the last join_face sets
// it); E-face e runs corner(2e), corner(prev 2e), corner(2e + 1),
// corner(prev(2e + 1)). Each new vertex's halfedge(v) is its V-face's
// halfedge into it.
//
// Open: DQQ_border_1step builds flat arrays, then add_face in order, so the
// numbering is add_face's: vertices as the host creates them (border
// corners first: per halfedge x in order whose opposite is on the border,
// corner(x), then the corner at its source, which is prev(x)'s or, for an
// ear, its second; then every other corner in halfedge order); faces
// F-faces, E-faces (interior edges), V-faces (interior vertices from
// halfedge(v), border vertices of 3 or more corners from their border
// halfedge, both reverse circulation); each face's new edges in corner
// order with the even halfedge in the face: an F-face's edges are all new,
// an E-face's second and fourth (the V-face's), a border V-face's last (on
// the border). halfedge(v): see add_face_vertex_halfedges.

#include "dual_hosts.h"

#include <algorithm>

#include "primal_hosts.h"

namespace subdivlab {
namespace refine {
namespace {

/// next and prev of every non-border halfedge, from the faces.
void link_faces(const Level& p, Dual_scratch& s) {
  const std::size_t H = 2 * std::size_t{p.edge_count};
  s.next.size_to(H);
  s.prev.size_to(H);
  std::uint32_t* next = s.next.data();
  std::uint32_t* prev = s.prev.data();
  const std::uint32_t* fh = p.face_halfedges.data();
  for (std::uint32_t f = 0; f < p.face_count; ++f) {
    const std::uint32_t begin = p.face_begin(f), end = p.face_end(f);
    std::uint32_t x = fh[end - 1];
    for (std::uint32_t i = begin; i < end; ++i) {
      const std::uint32_t y = fh[i];
      next[x] = y;
      prev[y] = x;
      x = y;
    }
  }
}

/// halfedge_target, halfedge_corner and the border count from the faces.
void link_halfedges(Level& c) {
  const std::size_t H = 2 * std::size_t{c.edge_count};
  size_to(c.halfedge_target, H);
  size_to(c.halfedge_corner, H);
  std::fill(c.halfedge_corner.begin(), c.halfedge_corner.end(), kNone);
  std::uint32_t* t = c.halfedge_target.data();
  std::uint32_t* corner = c.halfedge_corner.data();
  const std::uint32_t* fv = c.face_vertices.data();
  const std::uint32_t* fh = c.face_halfedges.data();
  for (std::uint32_t f = 0; f < c.face_count; ++f) {
    const std::uint32_t begin = c.face_offsets[f], end = c.face_offsets[f + 1];
    for (std::uint32_t i = begin; i < end; ++i) {
      const std::uint32_t h = fh[i];
      t[h] = fv[i];
      t[h ^ 1] = fv[i == begin ? end - 1 : i - 1];
      corner[h] = i;
    }
  }
  c.border_edge_count = c.edge_count * 2 - c.corner_count();
}

void set_offsets(Level& c, std::uint32_t faces) {
  c.face_count = faces;
  c.uniform_degree = 0;
  size_to(c.face_offsets, std::size_t{faces} + 1);
}

/// Degrees in face_offsets[f + 1] -> offsets.
void sum_offsets(Level& c) {
  c.face_offsets[0] = 0;
  for (std::uint32_t f = 0; f < c.face_count; ++f)
    c.face_offsets[f + 1] += c.face_offsets[f];
}

void refine_closed(const Level& p, Dual_scratch& s, Level& c, bool last) {
  const std::uint32_t V = p.vertex_count, E = p.edge_count, F = p.face_count;
  const std::uint32_t H = 2 * E, E2 = 4 * E, F2 = F + E + V;
  const std::uint32_t* vh = p.vertex_halfedge.data();
  s.halfedges.size_to(H);
  s.spoke.size_to(H);
  s.cut.size_to(H);
  s.rank.size_to(V);
  Dual_scratch::Closed_halfedge* hs = s.halfedges.data();
  std::uint32_t* spoke = s.spoke.data();
  std::uint32_t* cut = s.cut.data();
  std::uint32_t* valence = s.rank.data();
  c.vertex_count = H;
  c.edge_count = E2;
  set_offsets(c, F2);
  size_to(c.face_vertices, 4 * std::size_t{H});
  std::uint32_t* offsets = c.face_offsets.data();
  std::uint32_t* fv = c.face_vertices.data();
  std::uint32_t* fh = nullptr;
  std::uint32_t* target = nullptr;
  std::uint32_t* corner_of = nullptr;
  std::uint32_t* vhc = nullptr;
  if (last) {
    release(c.face_halfedges);
    release(c.vertex_halfedge);
    release(c.halfedge_target);
    release(c.halfedge_corner);
  } else {
    size_to(c.face_halfedges, 4 * std::size_t{H});
    size_to(c.vertex_halfedge, H);
    size_to(c.halfedge_target, 2 * std::size_t{E2});
    size_to(c.halfedge_corner, 2 * std::size_t{E2});
    fh = c.face_halfedges.data();
    target = c.halfedge_target.data();
    corner_of = c.halfedge_corner.data();
    vhc = c.vertex_halfedge.data();
  }
  // prev(y), and where y's corner goes in its F-face (the F-faces come
  // first, each from the corner of its halfedge of highest edge index), in
  // `vertex` until the corners are numbered: one cache line per halfedge.
  const std::uint32_t* pfh = p.face_halfedges.data();
  for (std::uint32_t f = 0; f < F; ++f) {
    const std::uint32_t begin = p.face_begin(f), end = p.face_end(f);
    const std::uint32_t start =
        begin + first_corner_offset(pfh + begin, end - begin);
    std::uint32_t x = pfh[end - 1];
    for (std::uint32_t i = begin; i < end; ++i) {
      const std::uint32_t y = pfh[i];
      hs[y].prev = x;
      hs[y].vertex = i >= start ? i - start + begin : i + end - start;
      x = y;
    }
  }
  // Corners, vertex by vertex: each one's vertex and the final index of its
  // cut edge. A cut slot at or past 4E moves to the k-th free slot from the
  // front (k = 3E - o_v - (j + 1) mod n_v, counting the slots from the
  // back); free slot 0 is edge E - 1, free slot r > 0 the spoke of corner
  // r - 1, whose final index spoke[] holds (corner r - 1 <= o_v + n_v - 1).
  // The E-faces read both at prev(y) for y = next(x_j) = opposite(x_j+1):
  // stored at y, so that they read them in edge order. The circulation
  // runs backwards, x_j = prev(opposite(x_j+1)), reading and writing the
  // lines of x_j and its opposite only. It is a chain of dependent reads: a
  // batch of vertices counts its valences in step, so that their reads
  // overlap, then each circulates again in cache.
  constexpr std::uint32_t kBatch = 16;
  std::uint32_t at[kBatch], count[kBatch];
  std::uint32_t o = 0;
  for (std::uint32_t v0 = 0; v0 < V; v0 += kBatch) {
    const std::uint32_t m = std::min(kBatch, V - v0);
    for (std::uint32_t b = 0; b < m; ++b) {
      at[b] = hs[vh[v0 + b] ^ 1].prev;
      count[b] = 1;
    }
    for (bool more = true; more;) {
      more = false;
      for (std::uint32_t b = 0; b < m; ++b) {
        if (at[b] == vh[v0 + b]) continue;
        at[b] = hs[at[b] ^ 1].prev;
        ++count[b];
        more = true;
      }
    }
    for (std::uint32_t b = 0; b < m; ++b) {
      const std::uint32_t n = count[b], first = vh[v0 + b];
      valence[v0 + b] = n;
      for (std::uint32_t j = 0; j < n; ++j) spoke[o + j] = E + 2 * o + j;
      // Corner j at halfedge x, whose successor x_j+1 is `after_x`.
      auto corner_at = [&](std::uint32_t j, std::uint32_t x,
                           std::uint32_t after_x) {
        const std::uint32_t corner = o + j, after = j + 1 == n ? 0 : j + 1;
        const std::uint32_t vertex =
            corner < H - V ? V + corner : H - 1 - corner;
        const std::uint32_t slot = E + 2 * o + n + after;
        const std::uint32_t edge =
            slot < E2 ? slot : spoke[3 * E - 1 - o - after];
        fv[hs[x].vertex] = vertex;
        hs[x].vertex = vertex;
        cut[corner] = edge;
        Dual_scratch::Closed_halfedge& y = hs[after_x ^ 1];
        y.prev_vertex = vertex;
        y.prev_cut = edge;
      };
      std::uint32_t after_x = first, x = hs[first ^ 1].prev;
      for (std::uint32_t j = n - 1; j > 0; --j) {
        const std::uint32_t before = hs[x ^ 1].prev;
        corner_at(j, x, after_x);
        after_x = x;
        x = before;
      }
      corner_at(0, first, after_x);
      o += n;
    }
  }
  // The F-face halfedge along x (the F-face edges' slots past 4E move too).
  auto along = [&](std::uint32_t x) {
    const std::uint32_t e = x >> 1;
    if ((x & 1) == 0) return 2 * (e == 0 ? spoke[E - 1] : e - 1);
    return 2 * (e + 1 == E ? E - 1 : spoke[E - 2 - e]);
  };

  // Every halfedge of a closed child lies in a face: its target and corner
  // come with the face.
  auto close_face = [&](std::uint32_t begin, std::uint32_t end) {
    if (fh == nullptr) return;
    for (std::uint32_t i = begin, before = end - 1; i < end; before = i++) {
      const std::uint32_t h = fh[i];
      target[h] = fv[i];
      target[h ^ 1] = fv[before];
      corner_of[h] = i;
    }
  };
  std::uint32_t f2 = 0, out = 0;
  // F-faces (their vertices are in place): each keeps its parent's index.
  for (std::uint32_t f = 0; f < F; ++f) {
    const std::uint32_t k = p.face_end(f) - out;
    if (fh != nullptr) {
      const std::uint32_t start = first_corner_offset(pfh + out, k);
      for (std::uint32_t i = 0; i < k; ++i)
        fh[out + i] =
            along(pfh[out + (start + i < k ? start + i : start + i - k)]);
      close_face(out, out + k);
    }
    out += k;
    offsets[++f2] = out;
  }
  // The V-face of u (its corners o_u.. in reverse circulation, each
  // entered by its cut edge's odd halfedge).
  auto v_face = [&](std::uint32_t u, std::uint32_t ou) {
    const std::uint32_t n = valence[u];
    for (std::uint32_t j = 0; j < n; ++j) {
      const std::uint32_t corner = ou + j;
      const std::uint32_t vertex = corner < H - V ? V + corner : H - 1 - corner;
      fv[out + n - 1 - j] = vertex;
      if (fh == nullptr) continue;
      const std::uint32_t h = 2 * cut[corner] + 1;
      fh[out + n - 1 - j] = h;
      vhc[vertex] = h;
    }
    close_face(out, out + n);
    out += n;
    offsets[++f2] = out;
  };
  // Then, in slot order after collect_garbage: vertex v's V-face at slot
  // F + o_v, then its cut triangles' slots (freed), which take from the
  // back the E-faces (e = E - 1 down to 0), then the V-faces of the last
  // vertices (from V - 1 down).
  o = 0;
  std::uint32_t r = 0, late = V, late_o = H;
  for (std::uint32_t v = 0; v < V && f2 < F2; ++v) {
    v_face(v, o);
    const std::uint32_t n = valence[v];
    for (std::uint32_t j = 1; j < n && f2 < F2; ++j, ++r) {
      if (r >= E) {
        --late;
        late_o -= valence[late];
        v_face(late, late_o);
        continue;
      }
      const std::uint32_t e = E - 1 - r, h0 = 2 * e, h1 = h0 + 1;
      const Dual_scratch::Closed_halfedge &a = hs[h0], &b = hs[h1];
      fv[out] = a.vertex;
      fv[out + 1] = a.prev_vertex;
      fv[out + 2] = b.vertex;
      fv[out + 3] = b.prev_vertex;
      if (fh != nullptr) {
        fh[out] = 2 * b.prev_cut;
        fh[out + 1] = along(h0) ^ 1;
        fh[out + 2] = 2 * a.prev_cut;
        fh[out + 3] = along(h1) ^ 1;
      }
      close_face(out, out + 4);
      out += 4;
      offsets[++f2] = out;
    }
    o += n;
  }
  offsets[0] = 0;
  c.border_edge_count = 0;
}

void refine_open(const Level& p, Dual_scratch& s, Level& c, bool last) {
  const std::uint32_t V = p.vertex_count, E = p.edge_count, F = p.face_count;
  const std::uint32_t H = 2 * E;
  link_faces(p, s);
  const std::uint32_t* next = s.next.data();
  const std::uint32_t* prev = s.prev.data();
  const std::uint32_t* vh = p.vertex_halfedge.data();
  const std::uint32_t* pc = p.halfedge_corner.data();
  auto border = [&](std::uint32_t x) { return pc[x] == kNone; };
  auto ear = [&](std::uint32_t x) {
    return border(x ^ 1) && border(next[x] ^ 1);
  };
  s.corner_vertex.size_to(H);
  std::fill_n(s.corner_vertex.data(), H, kNone);
  std::uint32_t* cv = s.corner_vertex.data();
  // Vertices: border corners, then the others.
  std::uint32_t n = 0, ears = 0;
  for (std::uint32_t x = 0; x < H; ++x) {
    if (border(x) || !border(x ^ 1)) continue;
    cv[x] = n++;
    const std::uint32_t q = prev[x];
    if (border(q ^ 1))
      ++n, ++ears;
    else
      cv[q] = n++;
  }
  for (std::uint32_t x = 0; x < H; ++x)
    if (!border(x) && cv[x] == kNone) cv[x] = n++;
  c.vertex_count = n;
  // Interior edges' ranks; V-faces' sizes.
  s.rank.size_to(E);
  std::uint32_t interior = 0;
  for (std::uint32_t e = 0; e < E; ++e)
    s.rank[e] = border(2 * e) || border(2 * e + 1) ? kNone : interior++;
  const std::uint32_t SF = p.corner_count() + ears;
  // The V-face of u: its corners h (reverse circulation), its size (0 if
  // none) and whether it closes on the border.
  auto v_face_size = [&](std::uint32_t u, bool& on_border) {
    const std::uint32_t start = vh[u];
    on_border = border(start);
    std::uint32_t m = 0;
    if (on_border) {
      for (std::uint32_t h = prev[start ^ 1];; h = prev[h ^ 1]) {
        ++m;
        if (border(h ^ 1)) break;
      }
      return m >= 3 ? m : 0;
    }
    std::uint32_t h = start;
    do {
      ++m;
      h = prev[h ^ 1];
    } while (h != start);
    return m;
  };
  std::uint32_t v_faces = 0, fans = 0;
  for (std::uint32_t u = 0; u < V; ++u) {
    bool on_border;
    if (v_face_size(u, on_border) == 0) continue;
    ++v_faces;
    fans += on_border;
  }
  const std::uint32_t F2 = F + interior + v_faces;
  c.edge_count = SF + 2 * interior + fans;
  set_offsets(c, F2);
  std::uint32_t* offsets = c.face_offsets.data();
  for (std::uint32_t f = 0; f < F; ++f) {
    std::uint32_t k = 0;
    for (std::uint32_t i = p.face_begin(f); i < p.face_end(f); ++i)
      k += 1 + ear(p.face_halfedges[i]);
    offsets[f + 1] = k;
  }
  for (std::uint32_t r = 0; r < interior; ++r) offsets[F + r + 1] = 4;
  for (std::uint32_t u = 0, i = F + interior; u < V; ++u) {
    bool on_border;
    const std::uint32_t m = v_face_size(u, on_border);
    if (m != 0) offsets[++i] = m;
  }
  sum_offsets(c);
  const std::size_t corners = offsets[F2];
  size_to(c.face_vertices, corners);
  std::uint32_t* fv = c.face_vertices.data();
  std::uint32_t* fh = nullptr;
  if (last) {
    release(c.face_halfedges);
  } else {
    size_to(c.face_halfedges, corners);
    fh = c.face_halfedges.data();
    s.edge_of.size_to(H);
  }
  std::uint32_t* into = s.edge_of.data();
  // F-faces: edge i of the F-faces runs from their corner i to the next.
  for (std::uint32_t f = 0; f < F; ++f) {
    const std::uint32_t out = offsets[f], end = offsets[f + 1];
    std::uint32_t q = out;
    for (std::uint32_t i = p.face_begin(f); i < p.face_end(f); ++i) {
      const std::uint32_t x = p.face_halfedges[i];
      if (fh != nullptr) {
        const std::uint32_t h = 2 * (q == out ? end - 1 : q - 1);
        fh[q] = h;
        into[x] = h;
      }
      fv[q++] = cv[x];
      if (!ear(x)) continue;
      if (fh != nullptr) fh[q] = 2 * (q - 1);
      fv[q++] = cv[next[x]] + 1;
    }
  }
  // E-faces: their second and fourth edges are new.
  for (std::uint32_t e = 0, out = offsets[F]; e < E; ++e) {
    const std::uint32_t r = s.rank[e];
    if (r == kNone) continue;
    const std::uint32_t h0 = 2 * e, h1 = h0 + 1;
    fv[out] = cv[h0];
    fv[out + 1] = cv[prev[h0]];
    fv[out + 2] = cv[h1];
    fv[out + 3] = cv[prev[h1]];
    if (fh != nullptr) {
      fh[out] = 2 * (SF + 2 * r + 1);
      fh[out + 1] = into[h0] ^ 1;
      fh[out + 2] = 2 * (SF + 2 * r);
      fh[out + 3] = into[h1] ^ 1;
    }
    out += 4;
  }
  // V-faces: from corner h to the next, prev(opposite(h)), along the edge
  // an E-face added at the source of y = opposite(h).
  auto across = [&](std::uint32_t h) {
    const std::uint32_t y = h ^ 1;
    return 2 * (SF + 2 * s.rank[y >> 1] + (y & 1)) + 1;
  };
  for (std::uint32_t u = 0, i = F + interior, fan = 0; u < V; ++u) {
    bool on_border;
    const std::uint32_t m = v_face_size(u, on_border);
    if (m == 0) continue;
    std::uint32_t q = offsets[i++];
    const std::uint32_t start = vh[u];
    std::uint32_t h = on_border ? prev[start ^ 1] : start;
    for (std::uint32_t j = 0; j < m; ++j) {
      fv[q + j] = cv[h];
      const std::uint32_t after = prev[h ^ 1];
      if (fh != nullptr) {
        if (j + 1 < m)
          fh[q + j + 1] = across(h);
        else
          fh[q] = on_border ? 2 * (SF + 2 * interior + fan) : across(h);
      }
      h = after;
    }
    fan += on_border;
  }
  if (last) {
    release(c.halfedge_target);
    release(c.halfedge_corner);
    release(c.vertex_halfedge);
    c.border_edge_count = 0;
  } else {
    link_halfedges(c);
    add_face_vertex_halfedges(c);
  }
}

}  // namespace

double dual_scratch_bytes(double vertices, double edges, double child_vertices,
                          bool border) {
  const double halfedges = 2 * edges;
  // Open: corner_vertex, next, prev, edge_of (4 bytes a halfedge each) and
  // the edges' ranks; the points keep corner_vertex. Closed: halfedges (16
  // bytes each), spoke, cut and the vertices' valences; the points keep
  // nothing.
  const double topology =
      border ? 4 * 4 * halfedges + 4 * edges : 6 * 4 * halfedges + 4 * vertices;
  return std::max(topology - 24 * child_vertices, border ? 4 * halfedges : 0.0);
}

void add_face_vertex_halfedges(Level& l) {
  size_to(l.vertex_halfedge, l.vertex_count);
  std::uint32_t* vh = l.vertex_halfedge.data();
  for (std::uint32_t f = 0; f < l.face_count; ++f)
    for (std::uint32_t i = l.face_begin(f); i < l.face_end(f); ++i)
      vh[l.face_vertices[i]] = l.face_halfedges[i];
  if (l.border_edge_count == 0) return;
  for (std::uint32_t h = 0; h < 2 * l.edge_count; ++h)
    if (l.halfedge_corner[h] == kNone) vh[l.halfedge_target[h]] = h;
}

void release_unread_tables(Level& parent) {
  release(parent.halfedge_target);
  if (parent.border_edge_count == 0) release(parent.halfedge_corner);
}

void refine_dqq_topology(const Level& parent, Dual_scratch& scratch,
                         Level& child, bool last) {
  release(child.edge_marks);
  // The child's positions come after the topology, in the place of its
  // scratch (refine_dual_points).
  release(child.positions);
  if (last) {  // the last level has no halfedge tables: free the stale ones
    release(child.face_halfedges);
    release(child.halfedge_target);
    release(child.halfedge_corner);
    release(child.vertex_halfedge);
  }
  if (parent.border_edge_count == 0)
    refine_closed(parent, scratch, child, last);
  else
    refine_open(parent, scratch, child, last);
  // Open, only the corners' vertices stay for the points.
  scratch.next.release();
  scratch.prev.release();
  scratch.edge_of.release();
  scratch.rank.release();
  scratch.spoke.release();
  scratch.cut.release();
  scratch.halfedges.release();
}

}  // namespace refine
}  // namespace subdivlab
