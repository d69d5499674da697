// Mesh_buffers <-> Surface_mesh, and the checks that keep
// Surface_mesh::add_face from ever seeing a face it would refuse.
//
// Isolated vertices (used by no face) are dropped when a mesh is built and
// the others renumbered in their original order, so the facts count what the
// surface has and an index stays valid for every vertex before the first
// dropped one. read_mesh drops them too, so its buffers match the mesh.

#include "mesh_build.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#include "mesh_check.h"

namespace subdivlab {
namespace detail {
namespace {

constexpr std::size_t npos = static_cast<std::size_t>(-1);

/// Words for faces and vertices in messages, per Check_naming.
class Namer {
 public:
  explicit Namer(const Check_naming& n) : n_(n) {}

  bool by_line() const { return n_.face_lines != nullptr; }
  int line(std::size_t f) const {
    return by_line() && f < n_.face_lines->size() ? (*n_.face_lines)[f] : 0;
  }
  std::string vertex(std::uint64_t v) const {
    return std::to_string(v + n_.vertex_offset);
  }
  /// "face 3" for buffers; "the face on line 9" for files.
  std::string face(std::size_t f) const {
    if (by_line()) return "the face on line " + std::to_string(line(f));
    return "face " + std::to_string(f);
  }
  /// "faces 3, 4 and 7" or "the faces on lines 9, 10 and 14".
  std::string faces(const std::vector<std::size_t>& fs) const {
    std::string s = by_line() ? "the faces on lines " : "faces ";
    for (std::size_t i = 0; i < fs.size(); ++i) {
      if (i > 0) s += (i + 1 == fs.size()) ? " and " : ", ";
      s += std::to_string(by_line() ? line(fs[i]) : fs[i]);
    }
    return s;
  }
  /// Prefix "line N: " for problems found at face f of a file.
  std::string where(std::size_t f) const {
    return by_line() ? "line " + std::to_string(line(f)) + ": " : "";
  }
  Check_result fail(std::size_t f, const std::string& what) const {
    Check_result r;
    r.status = Status::error(Status_code::invalid_mesh, where(f) + what,
                             f == npos ? 0 : line(f));
    r.face = f;
    return r;
  }

 private:
  const Check_naming& n_;
};

Check_result fail_plain(Status_code c, const std::string& what) {
  Check_result r;
  r.status = Status::error(c, what);
  return r;
}

struct Union_find {
  std::vector<std::uint32_t> parent;
  explicit Union_find(std::size_t n) : parent(n) {
    std::iota(parent.begin(), parent.end(), 0u);
  }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) {
      parent[x] = parent[parent[x]];
      x = parent[x];
    }
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

/// One side of an edge: face corner `corner` (index into face_indices) goes
/// from vertex `from` to the next vertex of its face.
struct Half_edge {
  std::uint64_t key;  // min(a,b) << 32 | max(a,b)
  std::uint32_t corner;
};

/// A corner leaving its vertex, as manifold_fast lists it: the vertex it
/// goes to and the one the corner before it comes from; with `Numbered`,
/// also the corner itself and the one before it (arriving), to pair them
/// (K: the degree of every face, or 0).
template <bool Numbered, std::uint32_t K>
struct Leaving {
  std::uint32_t to, from;
};
template <>
struct Leaving<true, 0> {
  std::uint32_t to, from;
  std::uint32_t corner, arriving;
  std::uint32_t arriving_corner() const { return arriving; }
};
/// Faces all of degree K: the corner before is found by arithmetic, and
/// an entry is 12 bytes instead of 16 (the lists are a third of the pass).
template <std::uint32_t K>
struct Leaving<true, K> {
  std::uint32_t to, from;
  std::uint32_t corner;
  std::uint32_t arriving_corner() const {
    return corner % K == 0 ? corner + K - 1 : corner - 1;
  }
};

/// The edge and vertex checks of check_buffers, fast, on faces that passed
/// theirs: true when every edge joins at most two faces in opposite
/// directions and every vertex's faces form one fan, with each corner's
/// halfedge numbered as check_buffers promises; false at the first doubt,
/// leaving the problem's naming to the careful pass below it.
///
/// One pass over each vertex's corners instead of sorted half-edges and a
/// union-find. The corners are listed by the vertex v they leave (a
/// counting sort), each with its end, the corner before it (arriving at v)
/// and that corner's start. At v: the ends must be distinct (an edge used
/// twice in one direction, or by 3+ faces, repeats one); the corner a -> v
/// arriving before each corner leaving v takes v -> a as its opposite; and
/// that step, from a corner leaving v to the one leaving v after the
/// opposite of its predecessor, must chain all of v's corners from one
/// start (the one nothing leads to, on a border): one fan. A vertex with a
/// few corners (most) finds ends in its own list, by pairs; one with many
/// marks them in a table by vertex (stamped with v). The chain is walked in
/// v's own list, so that the work is linear in the corners whatever the
/// valences (a fan of a million triangles included) and mostly reads the
/// list in order. `Numbered` (corner_halfedges given) also pairs the corners
/// and numbers their halfedges; without it only the checks run. K: the
/// degree of every face, or 0 when they differ (or for the checks alone).
template <bool Numbered, std::uint32_t K>
bool manifold_fast(const std::vector<std::uint32_t>& sizes,
                   const std::vector<std::uint32_t>& idx, std::size_t nv,
                   std::vector<std::uint32_t>* corner_halfedges) {
  constexpr std::uint32_t none = 0xffffffffu;
  const std::uint32_t corners = static_cast<std::uint32_t>(idx.size());
  std::vector<std::uint32_t> start(nv + 1, 0);
  for (std::uint32_t v : idx) ++start[v + 1];
  std::uint32_t most = 0;  // the largest valence
  for (std::size_t v = 0; v < nv; ++v) {
    most = std::max(most, start[v + 1]);
    start[v + 1] += start[v];
  }
  // Not zeroed: every entry is written by the counting sort. Without
  // numbering an entry is 8 bytes, and the check alone (read_mesh) moves
  // half the memory.
  using Entry = Leaving<Numbered, K>;
  const std::unique_ptr<Entry[]> leaving(new Entry[corners]);
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    std::uint32_t o = 0;
    for (std::uint32_t k : sizes) {
      for (std::uint32_t i = 0; i < k; ++i) {
        const std::uint32_t c = o + i;
        const std::uint32_t n = i + 1 == k ? o : c + 1;
        const std::uint32_t p = i == 0 ? o + k - 1 : c - 1;
        Entry& l = leaving[fill[idx[c]]++];
        l.to = idx[n];
        l.from = idx[p];
        if constexpr (Numbered) l.corner = c;
        if constexpr (Numbered && K == 0) l.arriving = p;
      }
      o += k;
    }
  }
  std::vector<std::uint32_t> opposite(Numbered ? corners : 0, none);
  // Per vertex: the vertex stamp it was last marked for and its position in
  // that vertex's list, side by side (one cache line per lookup). Only
  // vertices with many corners use it: a few corners are searched in their
  // own list, which is in cache, where a mark is a miss in a table by vertex.
  struct Mark {
    std::uint32_t stamp, at;
  };
  constexpr std::uint32_t kFew = 16;
  std::vector<Mark> mark(most > kFew ? nv : 0, Mark{none, 0});
  // The chain at the vertex at hand, by position in its list. Sized once:
  // a call that may throw, such as a resize, costs a JavaScript round trip
  // per vertex in WebAssembly (Emscripten's exceptions).
  std::vector<std::uint32_t> many_step(most > kFew ? most : 0);
  std::vector<std::uint8_t> many_led_to(most > kFew ? most : 0);
  std::uint32_t few_step[kFew];
  // Whether the chain `step` from `first` (the corner nothing leads to, on
  // a border; any, closed) goes through all n corners.
  const auto one_chain = [](const std::uint32_t* step, std::uint32_t n,
                            std::uint32_t first) {
    std::uint32_t walked = 1;
    for (std::uint32_t i = step[first]; i != none && i != first; i = step[i]) {
      if (++walked > n) return false;
    }
    return walked == n;
  };
  // Pairs the n corners leaving a vertex (`list`) with the corners before
  // them and walks the chain; `find(u)` is where in the list the corner to
  // u is, or none. False when they do not make one fan.
  const auto pair_and_walk = [&](const Entry* list, std::uint32_t n,
                                 std::uint32_t* step, std::uint8_t* led_to,
                                 auto&& find) {
    std::fill(step, step + n, none);
    std::fill(led_to, led_to + n, 0);
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t j = find(list[i].from);
      if (j == none) continue;  // a border edge arrives here
      if constexpr (Numbered)
        opposite[list[i].arriving_corner()] = list[j].corner;
      step[i] = j;
      led_to[j] = 1;
    }
    if (n < 2) return true;
    std::uint32_t first = 0;
    for (std::uint32_t i = 0; i < n; ++i) {
      if (led_to[i] != 0) continue;
      first = i;
      break;
    }
    return one_chain(step, n, first);
  };
  for (std::size_t v = 0; v < nv; ++v) {
    const std::uint32_t b = start[v], n = start[v + 1] - b;
    if (n < 2 && !Numbered) continue;
    const Entry* list = &leaving[b];
    bool fan = false;
    if (n <= kFew) {
      // pair_and_walk in one pass over the pairs: the ends distinct, and
      // each corner's predecessor's opposite found (the only one, then);
      // a bit for each corner led to.
      std::uint32_t led = 0;
      for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t to = list[i].to, from = list[i].from;
        std::uint32_t found = none;
        for (std::uint32_t j = 0; j < n; ++j) {
          if (j > i && list[j].to == to) return false;
          if (list[j].to == from) found = j;
        }
        few_step[i] = found;
        if (found == none) continue;  // a border edge arrives here
        if constexpr (Numbered)
          opposite[list[i].arriving_corner()] = list[found].corner;
        led |= 1u << found;
      }
      if (n < 2) continue;
      std::uint32_t first = 0;
      while (first < n && (led >> first & 1u) != 0) ++first;
      fan = one_chain(few_step, n, first == n ? 0 : first);
    } else {
      const auto stamp = static_cast<std::uint32_t>(v);
      for (std::uint32_t i = 0; i < n; ++i) {
        Mark& m = mark[list[i].to];
        if (m.stamp == stamp) return false;
        m = Mark{stamp, i};
      }
      fan = pair_and_walk(list, n, many_step.data(), many_led_to.data(),
                          [&](std::uint32_t u) {
                            const Mark m = mark[u];
                            return m.stamp == stamp ? m.at : none;
                          });
    }
    if (!fan) return false;
  }
  if constexpr (Numbered) {
    std::vector<std::uint32_t>& out = *corner_halfedges;
    out.resize(corners);
    std::uint32_t edges = 0;
    for (std::uint32_t c = 0; c < corners; ++c) {
      const std::uint32_t o = opposite[c];
      out[c] = o == none || o > c ? 2 * edges++ : out[o] + 1;
    }
  }
  return true;
}

}  // namespace

Check_result check_buffers(const Mesh_buffers& in, const Check_naming& naming,
                           std::vector<std::uint32_t>* corner_halfedges) {
  const Namer name(naming);
  const auto& sizes = in.face_sizes;
  const auto& idx = in.face_indices;

  if (sizes.empty())
    return fail_plain(Status_code::invalid_mesh, "the mesh has no faces");
  if (in.positions.size() % 3 != 0) {
    return fail_plain(Status_code::invalid_mesh,
                      "positions hold " + std::to_string(in.positions.size()) +
                          " numbers, not a multiple of 3");
  }
  std::uint64_t total = 0;
  for (auto s : sizes) total += s;
  if (total != idx.size()) {
    return fail_plain(Status_code::invalid_mesh,
                      "face sizes add up to " + std::to_string(total) +
                          " indices but there are " +
                          std::to_string(idx.size()));
  }
  if (idx.size() >= 0xffffffffu) {
    return fail_plain(Status_code::too_large,
                      "the mesh has too many face corners");
  }

  const std::size_t nv = in.vertex_count();
  for (std::size_t i = 0; i < in.positions.size(); ++i) {
    if (!std::isfinite(in.positions[i])) {
      return fail_plain(
          Status_code::invalid_mesh,
          "vertex " + name.vertex(i / 3) + " has a non-finite coordinate");
    }
  }

  // Per-face checks, first failing face wins.
  {
    std::vector<std::uint32_t> scratch;
    std::uint32_t o = 0;
    for (std::size_t f = 0; f < sizes.size(); ++f) {
      const std::uint32_t k = sizes[f];
      if (k < 3) {
        return name.fail(
            f, (name.by_line() ? std::string("the face") : name.face(f)) +
                   " has " + std::to_string(k) +
                   (k == 1 ? " vertex" : " vertices") +
                   "; a face needs at least 3");
      }
      for (std::uint32_t c = o; c < o + k; ++c) {
        if (idx[c] >= nv) {
          return name.fail(f,
                           (name.by_line() ? std::string("face index ")
                                           : name.face(f) + ": vertex index ") +
                               name.vertex(idx[c]) + " is out of range (" +
                               std::to_string(nv) + " vertices)");
        }
      }
      // The smallest vertex the face repeats: pairs for small faces, a
      // sorted copy for large ones.
      std::uint32_t dup = 0xffffffffu;
      if (k <= 8) {
        for (std::uint32_t a = o; a + 1 < o + k; ++a)
          for (std::uint32_t b = a + 1; b < o + k; ++b)
            if (idx[a] == idx[b] && idx[a] < dup) dup = idx[a];
      } else {
        scratch.assign(idx.begin() + o, idx.begin() + o + k);
        std::sort(scratch.begin(), scratch.end());
        const auto it = std::adjacent_find(scratch.begin(), scratch.end());
        if (it != scratch.end()) dup = *it;
      }
      if (dup != 0xffffffffu) {
        return name.fail(
            f, (name.by_line() ? std::string("the face") : name.face(f)) +
                   " uses vertex " + name.vertex(dup) + " more than once");
      }
      o += k;
    }
  }
  const std::uint32_t degree =
      corner_halfedges != nullptr ? in.uniform_face_degree() : 0;
  bool manifold = false;
  if (corner_halfedges == nullptr)
    manifold = manifold_fast<false, 0>(sizes, idx, nv, nullptr);
  else if (degree == 3)
    manifold = manifold_fast<true, 3>(sizes, idx, nv, corner_halfedges);
  else if (degree == 4)
    manifold = manifold_fast<true, 4>(sizes, idx, nv, corner_halfedges);
  else
    manifold = manifold_fast<true, 0>(sizes, idx, nv, corner_halfedges);
  if (manifold) return {};

  // The careful pass, which names the problem.
  std::vector<std::uint32_t> offset(sizes.size());
  for (std::size_t f = 0, o = 0; f < sizes.size(); o += sizes[f++])
    offset[f] = static_cast<std::uint32_t>(o);
  std::vector<std::uint32_t> face_of(idx.size());
  for (std::size_t f = 0; f < sizes.size(); ++f) {
    std::fill(face_of.begin() + offset[f],
              face_of.begin() + offset[f] + sizes[f],
              static_cast<std::uint32_t>(f));
  }
  auto next_corner = [&](std::uint32_t c) {
    const std::uint32_t f = face_of[c];
    return c + 1 < offset[f] + sizes[f] ? c + 1 : offset[f];
  };

  // Edges: group the half-edges by undirected edge, in corner order, i.e.
  // sorted by (key, corner): a counting sort by the smaller vertex (stable,
  // so corners stay in order), then an insertion sort of each vertex's few
  // half-edges by key.
  std::vector<Half_edge> he(idx.size());
  {
    std::vector<std::uint32_t> bucket(nv + 1, 0);
    for (std::uint32_t c = 0; c < idx.size(); ++c)
      ++bucket[std::min(idx[c], idx[next_corner(c)]) + 1];
    for (std::size_t v = 0; v < nv; ++v) bucket[v + 1] += bucket[v];
    for (std::uint32_t c = 0; c < idx.size(); ++c) {
      const std::uint64_t a = idx[c], b = idx[next_corner(c)];
      he[bucket[std::min(a, b)]++] = {(std::min(a, b) << 32) | std::max(a, b),
                                      c};
    }
    // bucket[v] is now where vertex v's half-edges end.
    std::size_t begin = 0;
    for (std::size_t v = 0; v < nv; ++v) {
      const std::size_t end = bucket[v];
      for (std::size_t i = begin + 1; i < end; ++i) {
        const Half_edge h = he[i];
        std::size_t j = i;
        for (; j > begin && he[j - 1].key > h.key; --j) he[j] = he[j - 1];
        he[j] = h;
      }
      begin = end;
    }
  }

  // An edge of 3+ faces, reported where its third face appears.
  std::size_t best = npos, best_begin = 0, best_end = 0;
  for (std::size_t i = 0; i < he.size();) {
    std::size_t j = i;
    while (j < he.size() && he[j].key == he[i].key) ++j;
    if (j - i > 2 && (best == npos || he[i + 2].corner < best)) {
      best = he[i + 2].corner;
      best_begin = i;
      best_end = j;
    }
    i = j;
  }
  if (best != npos) {
    std::vector<std::size_t> fs;
    for (std::size_t i = best_begin; i < best_end; ++i)
      fs.push_back(face_of[he[i].corner]);
    const std::uint64_t key = he[best_begin].key;
    return name.fail(
        face_of[best],
        "non-manifold edge between vertices " + name.vertex(key >> 32) +
            " and " + name.vertex(key & 0xffffffffu) + ": used by " +
            std::to_string(fs.size()) + " faces (" + name.faces(fs) + ")");
  }

  // An edge used twice in the same direction, reported at its second face.
  best = npos;
  std::size_t first_corner = 0;
  for (std::size_t i = 0; i + 1 < he.size(); ++i) {
    if (he[i].key != he[i + 1].key) continue;
    const std::uint32_t c1 = he[i].corner, c2 = he[i + 1].corner;
    if (idx[c1] == idx[c2] && (best == npos || c2 < best)) {
      best = c2;
      first_corner = c1;
    }
  }
  if (best != npos) {
    const std::uint32_t c1 = static_cast<std::uint32_t>(first_corner);
    const std::uint32_t c2 = static_cast<std::uint32_t>(best);
    Check_result r = name.fail(
        face_of[c2],
        "inconsistent orientation: " + name.faces({face_of[c1], face_of[c2]}) +
            " both use edge " + name.vertex(idx[c1]) + "\u2192" +
            name.vertex(idx[next_corner(c1)]) + " in the same direction");
    r.inconsistent_orientation = true;
    return r;
  }

  // Vertices: corners around a vertex joined across shared edges must form
  // one fan; two fans meeting only at the vertex make it non-manifold.
  Union_find uf(idx.size());
  for (std::size_t i = 0; i + 1 < he.size(); ++i) {
    if (he[i].key != he[i + 1].key) continue;
    const std::uint32_t c1 = he[i].corner, c2 = he[i + 1].corner;  // a→b, b→a
    uf.unite(c1, next_corner(c2));
    uf.unite(next_corner(c1), c2);
  }
  std::vector<std::uint32_t> start(nv + 1, 0);
  for (auto v : idx) ++start[v + 1];
  for (std::size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<std::uint32_t> corners(idx.size());
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::uint32_t c = 0; c < idx.size(); ++c) corners[fill[idx[c]]++] = c;
  }
  for (std::size_t v = 0; v < nv; ++v) {
    const std::uint32_t b = start[v], e = start[v + 1];
    if (e - b < 2) continue;
    const std::uint32_t root = uf.find(corners[b]);  // fan of the first corner
    std::uint32_t other = 0xffffffffu;  // first corner in another fan
    for (std::uint32_t i = b; i < e && other == 0xffffffffu; ++i) {
      if (uf.find(corners[i]) != root) other = corners[i];
    }
    if (other == 0xffffffffu) continue;
    std::vector<std::uint32_t> roots;
    for (std::uint32_t i = b; i < e; ++i) roots.push_back(uf.find(corners[i]));
    std::sort(roots.begin(), roots.end());
    const auto fans = std::unique(roots.begin(), roots.end()) - roots.begin();
    return name.fail(face_of[other],
                     "non-manifold vertex " + name.vertex(v) +
                         ": its faces form " + std::to_string(fans) +
                         " separate fans that meet only at this vertex (" +
                         name.faces({face_of[corners[b]], face_of[other]}) +
                         ")");
  }
  if (corner_halfedges != nullptr) {
    // he is sorted by (edge, corner): a group's first corner is the edge's
    // first use. Number those in corner order, then give the second use
    // the odd halfedge.
    std::vector<std::uint32_t>& out = *corner_halfedges;
    constexpr std::uint32_t kFirst = 0xffffffffu;
    out.assign(idx.size(), 0);
    for (std::size_t i = 0; i < he.size(); ++i)
      if (i == 0 || he[i].key != he[i - 1].key) out[he[i].corner] = kFirst;
    std::uint32_t edges = 0;
    for (std::uint32_t& h : out)
      if (h == kFirst) h = 2 * edges++;
    for (std::size_t i = 1; i < he.size(); ++i)
      if (he[i].key == he[i - 1].key)
        out[he[i].corner] = out[he[i - 1].corner] + 1;
  }
  return {};
}

std::vector<std::uint32_t> used_vertex_ranks(const Mesh_buffers& in,
                                             std::uint32_t& used) {
  std::vector<std::uint32_t> rank(in.vertex_count(), kUnusedVertex);
  for (std::uint32_t v : in.face_indices) rank[v] = 0;
  used = 0;
  for (std::uint32_t& r : rank)
    if (r == 0) r = used++;
  return rank;
}

namespace {

/// `t` with its vertices numbered by `map` (used_vertex_ranks). A crease
/// or corner on a dropped vertex goes with it (a crease never has one: it
/// is an edge of a face). Faces keep their numbers, so holes stay as they
/// are.
Mesh_tags remap_tags(const Mesh_tags& t,
                     const std::vector<std::uint32_t>& map) {
  const auto kept = [&](std::uint32_t v) {
    return v < map.size() && map[v] != kUnusedVertex;
  };
  Mesh_tags out = t;
  out.crease_edges.clear();
  out.crease_sharpness.clear();
  for (std::size_t i = 0; i + 1 < t.crease_edges.size(); i += 2) {
    const auto a = t.crease_edges[i], b = t.crease_edges[i + 1];
    if (!kept(a) || !kept(b) || i / 2 >= t.crease_sharpness.size()) continue;
    out.crease_edges.push_back(map[a]);
    out.crease_edges.push_back(map[b]);
    out.crease_sharpness.push_back(t.crease_sharpness[i / 2]);
  }
  out.corner_vertices.clear();
  out.corner_sharpness.clear();
  for (std::size_t i = 0; i < t.corner_vertices.size(); ++i) {
    const auto v = t.corner_vertices[i];
    if (!kept(v) || i >= t.corner_sharpness.size()) continue;
    out.corner_vertices.push_back(map[v]);
    out.corner_sharpness.push_back(t.corner_sharpness[i]);
  }
  return out;
}

}  // namespace

Mesh_tags tags_without_isolated_vertices(const Mesh_buffers& in) {
  std::uint32_t used = 0;
  const std::vector<std::uint32_t> map = used_vertex_ranks(in, used);
  return used == in.vertex_count() ? in.tags : remap_tags(in.tags, map);
}

Mesh_buffers drop_isolated_vertices(Mesh_buffers in) {
  const std::size_t nv = in.vertex_count();
  std::uint32_t n = 0;
  const std::vector<std::uint32_t> map = used_vertex_ranks(in, n);
  if (n == nv) return in;
  Mesh_buffers out;
  out.positions.reserve(3 * std::size_t(n));
  for (std::size_t v = 0; v < nv; ++v) {
    if (map[v] == kUnusedVertex) continue;
    out.positions.insert(out.positions.end(), in.positions.begin() + 3 * v,
                         in.positions.begin() + 3 * v + 3);
  }
  out.face_sizes = in.face_sizes;
  out.face_indices.reserve(in.face_indices.size());
  for (auto v : in.face_indices) out.face_indices.push_back(map[v]);
  for (std::size_t i = 0; i + 1 < in.control_edges.size(); i += 2) {
    const auto a = in.control_edges[i], b = in.control_edges[i + 1];
    if (a >= nv || b >= nv || map[a] == kUnusedVertex ||
        map[b] == kUnusedVertex)
      continue;
    out.control_edges.push_back(map[a]);
    out.control_edges.push_back(map[b]);
  }
  out.tags = remap_tags(in.tags, map);
  return out;
}

}  // namespace detail

Status build_mesh(const Mesh_buffers& in, Mesh& out) {
  out.clear();
  std::vector<std::uint32_t> ch;
  const detail::Check_result check = detail::check_buffers(in, {}, &ch);
  if (!check.status.ok()) return check.status;
  build_checked_mesh(in, ch, out);
  return Status::success();
}

/// The mesh is built from its tables, each element set once, rather than
/// by Surface_mesh::add_face, whose bookkeeping circulates the vertices of
/// every face it adds (quadratic in a valence: 0.6 s for a fan of 20 000
/// triangles, and half a 1 M-face load). The result is the one add_face,
/// called face by face, leaves behind, element for element:
///   - vertices: those a face uses, in order; faces in order;
///   - edges and halfedges: corner_halfedges, numbered as add_face numbers
///     them (check_buffers promises it): corner c's halfedge goes from its
///     vertex to the next corner's, the border halfedge is its opposite;
///   - halfedge(f): the halfedge into the face's first corner (add_face
///     takes its last halfedge);
///   - next around a face: the next corner's; next along the border: the
///     border halfedge leaving the vertex (a manifold vertex has one);
///   - halfedge(v): on the border, the border halfedge into v (add_face
///     moves it there after each face); inside, the halfedge into v of the
///     last face around v, which closed v's fan: both its halfedges at v
///     were border halfedges, and the one into v was halfedge(v).
/// A test builds every fixture both ways and compares them element by
/// element, the faces also in shuffled orders.
void build_checked_mesh(const Mesh_buffers& in,
                        const std::vector<std::uint32_t>& ch, Mesh& out) {
  out.clear();
  using V = Mesh::Vertex_index;
  using H = Mesh::Halfedge_index;
  using F = Mesh::Face_index;
  const std::size_t nv = in.vertex_count();
  const auto& idx = in.face_indices;
  std::uint32_t halfedges = 0;
  for (std::uint32_t h : ch) halfedges = std::max(halfedges, (h | 1u) + 1);

  std::vector<std::uint8_t> used(nv, 0);
  for (std::uint32_t v : idx) used[v] = 1;
  const std::size_t n_used =
      static_cast<std::size_t>(std::count(used.begin(), used.end(), 1));
  out.reserve(n_used, halfedges / 2, in.face_count());
  constexpr std::uint32_t none = 0xffffffffu;
  std::vector<std::uint32_t> vmap(nv, none);
  for (std::size_t v = 0; v < nv; ++v) {
    if (!used[v]) continue;
    const double* p = &in.positions[3 * v];
    vmap[v] =
        static_cast<std::uint32_t>(out.add_vertex(Point(p[0], p[1], p[2])));
  }
  std::vector<std::uint8_t>().swap(used);
  for (std::uint32_t e = 0; 2 * e < halfedges; ++e) out.add_edge();

  // Faces: targets, faces and next around each; a halfedge a corner owns
  // is marked, the others are the border's.
  std::vector<std::uint8_t> inner(halfedges, 0);
  std::vector<std::uint32_t> into(n_used, none);  // last face's, then border's
  {
    std::uint32_t o = 0;
    for (std::uint32_t k : in.face_sizes) {
      const F f = out.add_face();
      for (std::uint32_t i = 0; i < k; ++i) {
        const std::uint32_t c = o + i, n = i + 1 == k ? o : c + 1;
        const H h(ch[c]);
        out.set_target(h, V(vmap[idx[n]]));
        out.set_face(h, f);
        out.set_next(h, H(ch[n]));
        inner[ch[c]] = 1;
        into[vmap[idx[n]]] = ch[c];
      }
      out.set_halfedge(f, H(ch[o + k - 1]));
      o += k;
    }
  }
  // The border: the opposite of a corner's halfedge that no corner owns
  // goes from the next corner's vertex back to the corner's.
  std::vector<std::uint32_t> leaving(n_used, none);
  {
    std::uint32_t o = 0;
    for (std::uint32_t k : in.face_sizes) {
      for (std::uint32_t i = 0; i < k; ++i) {
        const std::uint32_t c = o + i, n = i + 1 == k ? o : c + 1;
        const std::uint32_t b = ch[c] ^ 1u;
        if (inner[b]) continue;
        out.set_target(H(b), V(vmap[idx[c]]));
        out.set_face(H(b), Mesh::null_face());
        into[vmap[idx[c]]] = b;
        leaving[vmap[idx[n]]] = b;
      }
      o += k;
    }
  }
  for (std::uint32_t h = 0; h < halfedges; ++h)
    if (!inner[h]) out.set_next(H(h), H(leaving[out.target(H(h))]));
  for (std::uint32_t v = 0; v < n_used; ++v) out.set_halfedge(V(v), H(into[v]));
}

Mesh_buffers to_buffers(const Mesh& mesh) {
  Mesh_buffers out;
  std::vector<std::uint32_t> number(mesh.num_vertices(), 0xffffffffu);
  out.positions.reserve(3 * mesh.number_of_vertices());
  std::uint32_t n = 0;
  for (Mesh::Vertex_index v : mesh.vertices()) {
    number[v.idx()] = n++;
    const Point& p = mesh.point(v);
    out.positions.push_back(p.x());
    out.positions.push_back(p.y());
    out.positions.push_back(p.z());
  }
  out.face_sizes.reserve(mesh.number_of_faces());
  out.face_indices.reserve(mesh.number_of_halfedges() / 2 +
                           mesh.number_of_faces());
  for (Mesh::Face_index f : mesh.faces()) {
    std::uint32_t k = 0;
    for (Mesh::Vertex_index v :
         CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      out.face_indices.push_back(number[v.idx()]);
      ++k;
    }
    out.face_sizes.push_back(k);
  }
  return out;
}

}  // namespace subdivlab
