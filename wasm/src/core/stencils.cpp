#include "stencils.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "refine/level_convert.h"

namespace subdivlab {

using refine::kNone;
using refine::Level;

const char* stencil_kind_name(Stencil_kind kind) {
  switch (kind) {
    case Stencil_kind::vertex_point:
      return "vertex point";
    case Stencil_kind::border_vertex:
      return "border vertex";
    case Stencil_kind::edge_point:
      return "edge point";
    case Stencil_kind::border_edge_point:
      return "border edge point";
    case Stencil_kind::face_point:
      return "face point";
    case Stencil_kind::corner_point:
      return "corner point";
    case Stencil_kind::border_corner_point:
      return "border corner point";
    case Stencil_kind::relaxed_vertex:
      return "relaxed vertex";
    case Stencil_kind::border_point:
      return "border point";
    case Stencil_kind::crease_vertex:
      return "crease vertex";
    case Stencil_kind::corner_vertex:
      return "corner vertex";
    case Stencil_kind::sharp_edge_point:
      return "sharp edge point";
  }
  return "";
}

std::string stencil_formula(const std::string& scheme, Stencil_kind kind) {
  using K = Stencil_kind;
  const bool primal_border =
      kind == K::border_vertex || kind == K::border_edge_point;
  if (kind == K::crease_vertex)
    return "(v_a + 6 v + v_b) / 8, v_a and v_b its neighbours along the "
           "sharp edges (blended with the smooth rule where the sharpness "
           "is below 1)";
  if (kind == K::corner_vertex)
    return "v stays (blended with the smooth rule where the sharpness is "
           "below 1)";
  if (kind == K::sharp_edge_point)
    return "(v0 + v1) / 2 (blended with the smooth rule where the sharpness "
           "is below 1)";
  if (scheme == "custom") return "the rule set's weights for this kind";
  if (scheme == "catmull-clark") {
    if (kind == K::vertex_point)
      return "(Q + 2R + (n - 3) S) / n: Q the mean of the n face points "
             "around S, R the mean of the n edge midpoints";
    if (kind == K::edge_point)
      return "(v0 + v1 + f0 + f1) / 4: the edge's ends and its two faces' "
             "points";
    if (kind == K::face_point) return "the mean of the face's n vertices";
  }
  if (scheme == "loop") {
    if (kind == K::vertex_point)
      return "(1 - n beta(n)) v + beta(n) (sum of the n neighbours), "
             "beta(n) = (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n";
    if (kind == K::edge_point)
      return "3/8 (v0 + v1) + 1/8 (the two opposite vertices)";
  }
  if ((scheme == "catmull-clark" || scheme == "loop") && primal_border) {
    return kind == K::border_vertex ? "(v_prev + 6 v + v_next) / 8"
                                    : "(v0 + v1) / 2";
  }
  if (scheme == "linear" || scheme == "linear-tri") {
    if (kind == K::vertex_point || kind == K::border_vertex)
      return "v: the vertex stays";
    if (kind == K::edge_point || kind == K::border_edge_point)
      return "(v0 + v1) / 2";
    if (kind == K::face_point) return "the mean of the face's n vertices";
  }
  if (scheme == "doo-sabin") {
    if (kind == K::corner_point)
      return "sum over the face's n vertices v_j of w_j v_j, w_0 = (n + 5) / "
             "(4n), w_j = (3 + 2 cos(2 pi j / n)) / (4n), j counted from "
             "the corner's vertex";
    if (kind == K::border_corner_point)
      return "on a border edge: (3 v + v_other) / 4 along it";
  }
  if (scheme == "sqrt3") {
    if (kind == K::relaxed_vertex)
      return "(1 - a(n)) v + a(n) / n (sum of the n neighbours), a(n) = "
             "(4 - 2 cos(2 pi / n)) / 9";
    if (kind == K::face_point) return "(v0 + v1 + v2) / 3";
    if (kind == K::border_vertex)
      return "(4 v_prev + 19 v + 4 v_next) / 27 on a step that refines the "
             "border (every second one); v itself on the others";
    if (kind == K::border_point)
      return "(16 a + 10 b + c) / 27: a the border edge's nearer end, b its "
             "other end, c the border vertex beyond a";
  }
  if (scheme == "quad-triangle") {
    return "the quad-triangle split's point (vertex, edge midpoint or face "
           "centroid), then averaged over its ring in the split mesh";
  }
  return "";
}

namespace {

/// The faces at each vertex of `level` (vertex v's are [at[v], at[v + 1])
/// of faces).
struct Vertex_faces {
  std::vector<std::uint32_t> at, faces;
};

Vertex_faces vertex_faces(const Level& level) {
  Vertex_faces vf;
  vf.at.assign(level.vertex_count + 1, 0);
  for (std::uint32_t v : level.face_vertices) ++vf.at[v + 1];
  for (std::uint32_t v = 0; v < level.vertex_count; ++v)
    vf.at[v + 1] += vf.at[v];
  vf.faces.resize(level.face_vertices.size());
  std::vector<std::uint32_t> next(vf.at.begin(), vf.at.end() - 1);
  for (std::uint32_t f = 0; f < level.face_count; ++f)
    for (std::uint32_t c = level.face_begin(f); c < level.face_end(f); ++c)
      vf.faces[next[level.face_vertices[c]]++] = f;
  return vf;
}

/// The colours of the parent's vertices (no two within `reach` steps over
/// "shares a face"), greedily in vertex order; returns their count.
std::uint32_t colour_vertices(const Level& level, int reach,
                              std::vector<std::uint32_t>& colour) {
  const Vertex_faces vf = vertex_faces(level);
  const std::uint32_t V = level.vertex_count;
  colour.assign(V, kNone);
  std::vector<std::uint32_t> seen(V, kNone), used;
  std::vector<std::uint32_t> frontier, next;
  std::uint32_t colours = 0;
  for (std::uint32_t v = 0; v < V; ++v) {
    // The colours already given within `reach` of v.
    used.clear();
    frontier.assign(1, v);
    seen[v] = v;
    for (int step = 0; step < reach && !frontier.empty(); ++step) {
      next.clear();
      for (std::uint32_t u : frontier)
        for (std::uint32_t i = vf.at[u]; i < vf.at[u + 1]; ++i) {
          const std::uint32_t f = vf.faces[i];
          for (std::uint32_t c = level.face_begin(f); c < level.face_end(f);
               ++c) {
            const std::uint32_t w = level.face_vertices[c];
            if (seen[w] == v) continue;
            seen[w] = v;
            next.push_back(w);
            if (colour[w] != kNone) used.push_back(colour[w]);
          }
        }
      std::swap(frontier, next);
    }
    std::sort(used.begin(), used.end());
    std::uint32_t k = 0;
    for (std::uint32_t u : used) {
      if (u == k) ++k;
      if (u > k) break;
    }
    colour[v] = k;
    colours = std::max(colours, k + 1);
  }
  return colours;
}

/// Each refined vertex's origin, by the host's numbering (primal_hosts.h,
/// sqrt3_host.h; Doo-Sabin's corners by their largest weight).
void origins_of(const Level& parent, const std::string& host, bool border_step,
                Stencil_table& table) {
  using K = Stencil_kind;
  const std::uint32_t V = parent.vertex_count, E = parent.edge_count;
  // Valences and border vertices (the DQQ host has dropped its halfedge
  // tables by now, and names its corners otherwise).
  std::vector<std::uint32_t> valence;
  std::vector<bool> on_border;
  if (host != "dqq") refine::vertex_valences(parent, valence, on_border);
  // Creasing: the sharp edges at each vertex (OpenSubdiv's vertex rules).
  std::vector<std::uint32_t> sharp(parent.creased ? V : 0, 0);
  if (parent.creased)
    for (std::size_t h = 0; h < parent.halfedge_target.size(); ++h)
      if (parent.edge_sharpness[h / 2] > 0) ++sharp[parent.halfedge_target[h]];
  const bool primal = host == "pqq" || host == "ptq" || host == "pqt";
  // PQT: face points for the faces that are not triangles, in face order.
  std::vector<std::uint32_t> point_faces;
  for (std::uint32_t f = 0; f < parent.face_count; ++f) {
    const std::uint32_t degree = parent.face_end(f) - parent.face_begin(f);
    if (host == "pqq" || (host == "pqt" && degree != 3) ||
        (host == "sqrt3" && !border_step))
      point_faces.push_back(f);
  }
  const std::size_t n = table.offsets.size() - 1;
  table.origins.assign(n, {});
  for (std::uint32_t c = 0; c < n; ++c) {
    Stencil_origin& o = table.origins[c];
    if (host == "dqq") {
      // The corner's vertex weighs most (Doo-Sabin's w_0); on a border
      // edge it has that edge's other end only (the DQQ host has dropped
      // its halfedge tables by now).
      std::uint32_t best = kNone;
      double top = -1;
      for (std::uint32_t i = table.offsets[c]; i < table.offsets[c + 1]; ++i)
        if (table.weights[i] > top) {
          top = table.weights[i];
          best = table.parents[i];
        }
      o.element = best;
      o.size = table.offsets[c + 1] - table.offsets[c];
      o.kind = o.size == 2 ? K::border_corner_point : K::corner_point;
      continue;
    }
    if (c < V) {
      o.element = c;
      o.size = valence[c];
      o.kind = on_border[c] ? K::border_vertex
               : primal     ? K::vertex_point
                            : K::relaxed_vertex;
      if (parent.creased && !on_border[c]) {
        if (parent.vertex_sharpness[c] > 0 || sharp[c] > 2)
          o.kind = K::corner_vertex;
        else if (sharp[c] == 2)
          o.kind = K::crease_vertex;
      }
      continue;
    }
    if (primal && c < V + E) {
      const std::uint32_t e = c - V;
      o.element = e;
      o.ends[0] = parent.halfedge_target[2 * e + 1];
      o.ends[1] = parent.halfedge_target[2 * e];
      const bool border = parent.halfedge_corner[2 * e] == kNone ||
                          parent.halfedge_corner[2 * e + 1] == kNone;
      o.kind = border ? K::border_edge_point : K::edge_point;
      if (!border && parent.creased && parent.edge_sharpness[e] > 0)
        o.kind = K::sharp_edge_point;
      o.size = 2;
      continue;
    }
    const std::uint32_t k = primal ? c - V - E : c - V;
    if (k < point_faces.size()) {
      o.kind = K::face_point;
      o.element = point_faces[k];
      o.size = parent.face_end(o.element) - parent.face_begin(o.element);
      continue;
    }
    // A √3 border step's points: the faces' (a third of each of three
    // vertices) and the border edges', in the order CGAL inserts them;
    // named by their weights.
    const std::uint32_t n_parents = table.offsets[c + 1] - table.offsets[c];
    bool thirds = n_parents == 3;
    for (std::uint32_t i = table.offsets[c]; thirds && i < table.offsets[c + 1];
         ++i)
      thirds = std::fabs(table.weights[i] - 1.0 / 3) < 1e-12;
    if (thirds) {
      o.kind = K::face_point;
      o.size = 3;
      continue;
    }
    bool all_border = true;
    for (std::uint32_t i = table.offsets[c]; i < table.offsets[c + 1]; ++i)
      all_border = all_border && on_border[table.parents[i]];
    o.kind = all_border ? K::border_point : K::face_point;
    o.size = table.offsets[c + 1] - table.offsets[c];
  }
}

}  // namespace

namespace detail {

std::string probe_stencils(
    Level& parent, Level& child, const std::string& host, bool border_step,
    const std::function<void(const Level&, Level&)>& points,
    Stencil_table& table) {
  const std::uint32_t V = parent.vertex_count;
  if (V > kMaxStencilParents)
    return "the level before has " + std::to_string(V) +
           " vertices; stencils are made for at most " +
           std::to_string(kMaxStencilParents);
  const std::vector<double> parent_points = parent.positions;
  const std::vector<double> child_points = child.positions;
  const std::size_t n = child_points.size() / 3;
  // Two parents of one refined vertex share a face with a common vertex,
  // or (quad-triangle, which averages over the split mesh) are at most
  // four face steps apart.
  std::vector<std::uint32_t> colour;
  const std::uint32_t colours =
      colour_vertices(parent, host == "pqt" ? 4 : 2, colour);
  std::vector<std::vector<std::pair<std::uint32_t, double>>> rows(n);
  std::string error;
  for (std::uint32_t k = 0; k < colours && error.empty(); ++k) {
    for (std::uint32_t j = 0; j < V; ++j) {
      const bool in = colour[j] == k;
      parent.positions[3 * j] = in ? 1.0 : 0.0;
      parent.positions[3 * j + 1] = in ? j + 1.0 : 0.0;
      parent.positions[3 * j + 2] = 0;
    }
    points(parent, child);
    for (std::size_t c = 0; c < n; ++c) {
      const double x = child.positions[3 * c];
      if (std::fabs(x) <= 1e-15) continue;
      const double r = child.positions[3 * c + 1] / x;
      const double j = std::round(r) - 1;
      if (j < 0 || j >= V || colour[static_cast<std::uint32_t>(j)] != k ||
          std::fabs(r - (j + 1)) > 1e-6 * (j + 1)) {
        error = "internal error: the stencil of vertex " + std::to_string(c) +
                " mixes two parents";
        break;
      }
      rows[c].push_back({static_cast<std::uint32_t>(j), x});
    }
  }
  parent.positions = parent_points;
  child.positions = child_points;
  if (!error.empty()) return error;

  table.parent_vertices = V;
  table.offsets.assign(1, 0);
  for (std::size_t c = 0; c < n; ++c) {
    auto& row = rows[c];
    std::sort(row.begin(), row.end());
    // The table reproduces the step's real points.
    double p[3] = {0, 0, 0};
    for (const auto& [j, w] : row) {
      table.parents.push_back(j);
      table.weights.push_back(w);
      for (int i = 0; i < 3; ++i) p[i] += w * parent_points[3 * j + i];
    }
    for (int i = 0; i < 3; ++i) {
      const double want = child_points[3 * c + i];
      if (std::fabs(p[i] - want) > 1e-9 * std::max(1.0, std::fabs(want)))
        return "internal error: the stencil of vertex " + std::to_string(c) +
               " does not give its point";
    }
    table.offsets.push_back(static_cast<std::uint32_t>(table.parents.size()));
  }
  origins_of(parent, host, border_step, table);
  return "";
}

}  // namespace detail
}  // namespace subdivlab
