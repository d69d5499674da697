#include "crease.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/mesh_check.h"
#include "level_convert.h"

namespace subdivlab {
namespace refine {
namespace {

bool is_sharp(float s) { return s > 0.0f; }
bool is_semi_sharp(float s) { return s > 0.0f && s < kInfinitelySharp; }

/// Sdc::Crease::decrementSharpness.
float decrement(float s) {
  if (s <= 0.0f) return 0.0f;
  if (s >= kInfinitelySharp) return kInfinitelySharp;
  return s > 1.0f ? s - 1.0f : 0.0f;
}

/// Sdc::Crease's vertex rules, as bits in its order.
enum Rule { kSmooth = 1, kDart = 2, kCrease = 4, kCorner = 8 };

Rule vertex_rule(float vertex_sharpness, std::uint32_t sharp_edges) {
  if (is_sharp(vertex_sharpness)) return kCorner;
  return sharp_edges > 2 ? kCorner : static_cast<Rule>(1u << sharp_edges);
}

std::string tag_error(const char* tag, std::size_t i, const std::string& why) {
  return std::string(tag) + " " + std::to_string(i + 1) + ": " + why;
}

bool bad_sharpness(float s) { return !std::isfinite(s) || s < 0.0f; }

std::string sharpness_text(float s) {
  if (std::isnan(s)) return "not a number";
  char text[32];
  std::snprintf(text, sizeof text, "%g", static_cast<double>(s));
  return text;
}

/// The edge's sharpness at this level: a border edge is infinitely sharp
/// (OpenSubdiv's factory sharpens them at level 0; their halves stay so).
inline float effective(float stored, bool border) {
  return border ? kInfinitelySharp : stored;
}

}  // namespace

std::string apply_tags(const Mesh_buffers& in, const Mesh_tags& tags,
                       const Creasing& creasing, bool faces_renumbered,
                       Level& l) {
  const std::size_t nv = in.vertex_count();
  // The level's index of each input vertex (unused ones are dropped; the
  // tags keep the input's numbers for the messages).
  std::uint32_t used = 0;
  std::vector<std::uint32_t> rank;
  if (l.vertex_count != nv) rank = detail::used_vertex_ranks(in, used);
  const auto level_vertex = [&](std::uint32_t v) {
    if (v >= nv) return kNone;
    return rank.empty() ? v : rank[v];
  };
  l.creased = true;
  l.edge_sharpness.assign(l.edge_count, 0.0f);
  l.vertex_sharpness.assign(l.vertex_count, 0.0f);
  l.face_holes.assign(l.face_count, 0);
  if (tags.crease_sharpness.size() * 2 != tags.crease_edges.size())
    return "creases: one sharpness per pair of vertices is needed";
  if (tags.corner_sharpness.size() != tags.corner_vertices.size())
    return "corners: one sharpness per vertex is needed";
  if (!tags.crease_edges.empty()) {
    const Vertex_halfedges around = vertex_halfedges(l);
    for (std::size_t i = 0; i < tags.crease_sharpness.size(); ++i) {
      const std::uint32_t a = tags.crease_edges[2 * i],
                          b = tags.crease_edges[2 * i + 1];
      const float s = tags.crease_sharpness[i];
      const std::uint32_t la = level_vertex(a), lb = level_vertex(b);
      const std::uint32_t e =
          la == kNone || lb == kNone ? kNone : around.edge(l, la, lb);
      if (e == kNone)
        return tag_error("crease", i,
                         "vertices " + std::to_string(a) + " and " +
                             std::to_string(b) +
                             " are not the ends of an edge of the mesh");
      if (bad_sharpness(s))
        return tag_error(
            "crease", i,
            "the sharpness must be 0 or more, not " + sharpness_text(s));
      l.edge_sharpness[e] = s;
    }
  }
  for (std::size_t i = 0; i < tags.corner_vertices.size(); ++i) {
    const std::uint32_t v = level_vertex(tags.corner_vertices[i]);
    const float s = tags.corner_sharpness[i];
    if (v == kNone)
      return tag_error("corner", i,
                       "vertex " + std::to_string(tags.corner_vertices[i]) +
                           " is not a vertex of a face of the mesh");
    if (bad_sharpness(s))
      return tag_error(
          "corner", i,
          "the sharpness must be 0 or more, not " + sharpness_text(s));
    l.vertex_sharpness[v] = s;
  }
  if (!tags.holes.empty() && faces_renumbered)
    return "holes name faces of the mesh as given, which had to be "
           "triangulated first: triangulate the mesh and tag its triangles";
  for (std::size_t i = 0; i < tags.holes.size(); ++i) {
    const std::uint32_t f = tags.holes[i];
    if (f >= l.face_count)
      return tag_error("hole", i,
                       "face " + std::to_string(f) +
                           " is not a face of the "
                           "mesh, which has " +
                           std::to_string(l.face_count));
    l.face_holes[f] = 1;
  }
  if (creasing.boundary == Boundary_interpolation::none &&
      l.border_edge_count > 0) {
    // OpenSubdiv's factory: the faces at a border vertex whose border
    // edges are not all infinitely sharp become holes.
    std::vector<std::uint8_t> excluded(l.vertex_count, 0);
    const std::uint32_t* t = l.halfedge_target.data();
    for (std::uint32_t x = 0; x < 2 * l.edge_count; ++x) {
      if (l.halfedge_corner[x] != kNone) continue;
      if (l.edge_sharpness[x >> 1] >= kInfinitelySharp) continue;
      excluded[t[x]] = 1;
      excluded[t[x ^ 1]] = 1;
    }
    for (std::uint32_t f = 0; f < l.face_count; ++f)
      for (std::uint32_t c = l.face_begin(f); c < l.face_end(f); ++c)
        if (excluded[l.face_vertices[c]] != 0) l.face_holes[f] = 1;
  }
  return {};
}

void refine_crease_tables(const Level& p, const Creasing& creasing, bool pqq,
                          Level& c) {
  const std::uint32_t V = p.vertex_count, E = p.edge_count, F = p.face_count;
  c.creased = true;
  size_to(c.edge_sharpness, c.edge_count);
  std::fill(c.edge_sharpness.begin(), c.edge_sharpness.end(), 0.0f);
  const float* ps = p.edge_sharpness.data();
  float* cs = c.edge_sharpness.data();
  const std::uint32_t* t = p.halfedge_target.data();
  const std::uint32_t* corner = p.halfedge_corner.data();
  if (creasing.method == Crease_method::uniform) {
    for (std::uint32_t e = 0; e < E; ++e) cs[e] = cs[E + e] = decrement(ps[e]);
  } else {
    // Chaikin (Sdc::Crease::SubdivideEdgeSharpnessAtVertex): a half gets
    // 3/4 of its edge's sharpness and 1/4 of the mean of the other
    // semi-sharp edges at its end vertex, less one.
    std::vector<float> sum(V, 0.0f);
    std::vector<std::uint32_t> count(V, 0), valence(V, 0);
    for (std::uint32_t e = 0; e < E; ++e) {
      const std::uint32_t a = t[2 * e + 1], b = t[2 * e];
      ++valence[a];
      ++valence[b];
      const bool border = corner[2 * e] == kNone || corner[2 * e + 1] == kNone;
      const float s = effective(ps[e], border);
      if (!is_semi_sharp(s)) continue;
      sum[a] += s;
      sum[b] += s;
      ++count[a];
      ++count[b];
    }
    const auto at_vertex = [&](float s, std::uint32_t v) {
      if (valence[v] < 2) return decrement(s);
      if (!is_sharp(s)) return 0.0f;
      if (s >= kInfinitelySharp) return kInfinitelySharp;
      if (count[v] > 1) {
        const float others = (sum[v] - s) / static_cast<float>(count[v] - 1);
        s = (0.75f * s) + (0.25f * others);
      }
      s -= 1.0f;
      return is_sharp(s) ? s : 0.0f;
    };
    for (std::uint32_t e = 0; e < E; ++e) {
      const bool border = corner[2 * e] == kNone || corner[2 * e + 1] == kNone;
      if (border) {
        // Infinitely sharp whatever they hold: the tag's value decays.
        cs[e] = cs[E + e] = decrement(ps[e]);
        continue;
      }
      cs[e] = at_vertex(ps[e], t[2 * e + 1]);
      cs[E + e] = at_vertex(ps[e], t[2 * e]);
    }
  }
  size_to(c.vertex_sharpness, c.vertex_count);
  std::fill(c.vertex_sharpness.begin(), c.vertex_sharpness.end(), 0.0f);
  for (std::uint32_t v = 0; v < V; ++v)
    c.vertex_sharpness[v] = decrement(p.vertex_sharpness[v]);
  size_to(c.face_holes, c.face_count);
  std::fill(c.face_holes.begin(), c.face_holes.end(), 0);
  for (std::uint32_t f = 0; f < F; ++f) {
    if (p.face_holes[f] == 0) continue;
    // A hole's children (primal_hosts.h's numbering): f keeps its index,
    // the others follow F + (its first corner) - f (PQQ) or F + 3f (PTQ).
    const std::uint32_t begin = p.face_begin(f), k = p.face_end(f) - begin;
    const std::uint32_t first = pqq ? F + begin - f : F + 3 * f;
    const std::uint32_t more = pqq ? k - 1 : 3;
    c.face_holes[f] = 1;
    for (std::uint32_t i = 0; i < more; ++i) c.face_holes[first + i] = 1;
  }
}

void apply_crease_rules(const Level& p, const Creasing& creasing,
                        Crease_scratch& s, Level& c) {
  const std::uint32_t V = p.vertex_count, E = p.edge_count;
  const std::uint32_t* t = p.halfedge_target.data();
  const std::uint32_t* corner = p.halfedge_corner.data();
  const double* in = p.positions.data();
  double* out = c.positions.data();
  const auto border = [&](std::uint32_t e) {
    return corner[2 * e] == kNone || corner[2 * e + 1] == kNone;
  };
  const auto parent_sharpness = [&](std::uint32_t e) {
    return effective(p.edge_sharpness[e], border(e));
  };

  // Edge points (Sdc::Scheme::ComputeEdgeVertexMask): a sharp edge whose
  // halves both stay sharp gives its midpoint; one whose sharpness decays
  // to nothing blends the midpoint with the smooth point by its sharpness.
  for (std::uint32_t e = 0; e < E; ++e) {
    const float sharpness = parent_sharpness(e);
    if (!is_sharp(sharpness)) continue;
    const bool b = border(e);
    const bool crease = is_sharp(effective(c.edge_sharpness[e], b)) &&
                        is_sharp(effective(c.edge_sharpness[E + e], b));
    const double* pa = in + 3 * std::size_t{t[2 * e + 1]};
    const double* pb = in + 3 * std::size_t{t[2 * e]};
    double* o = out + 3 * (std::size_t{V} + e);
    const double w = crease ? 1.0 : static_cast<double>(sharpness);
    for (int i = 0; i < 3; ++i)
      o[i] = w * (0.5 * (pa[i] + pb[i])) + (1.0 - w) * o[i];
  }

  // Vertex points (Sdc::Scheme::ComputeVertexVertexMask), around each
  // vertex's edges.
  vertex_halfedges(p, s.around);
  const std::vector<std::uint32_t>& out_of = s.around.halfedges;
  const bool corners =
      creasing.boundary == Boundary_interpolation::edge_and_corner;
  const bool uniform = creasing.method == Crease_method::uniform;
  for (std::uint32_t v = 0; v < V; ++v) {
    const std::uint32_t first = s.around.begin[v], last = s.around.begin[v + 1];
    float pv = p.vertex_sharpness[v], cv = c.vertex_sharpness[v];
    std::uint32_t parent_sharp = 0, child_sharp = 0, border_edges = 0;
    for (std::uint32_t i = first; i < last; ++i) {
      const std::uint32_t h = out_of[i], e = h >> 1;
      const bool b = border(e);
      border_edges += b;
      parent_sharp += is_sharp(effective(p.edge_sharpness[e], b));
      // v's half of e: e when v is its source (even h), else E + e.
      child_sharp +=
          is_sharp(effective(c.edge_sharpness[(h & 1) ? E + e : e], b));
    }
    if (corners && border_edges > 0 && last - first == 2) {
      // A vertex of one face: a corner (OpenSubdiv's factory sharpens it).
      pv = cv = kInfinitelySharp;
    }
    const Rule parent_rule = vertex_rule(pv, parent_sharp);
    if (parent_rule == kSmooth || parent_rule == kDart) continue;
    const Rule child_rule = vertex_rule(cv, child_sharp);
    const double* x = in + 3 * std::size_t{v};
    double* o = out + 3 * std::size_t{v};
    // The crease mask over the sharp edges' far ends (parent's, or the
    // child's sharp halves).
    const auto crease_point = [&](double* q, bool child) {
      double ends[3] = {0, 0, 0};
      for (std::uint32_t i = first; i < last; ++i) {
        const std::uint32_t h = out_of[i], e = h >> 1;
        const bool b = border(e);
        const float sharpness =
            child ? effective(c.edge_sharpness[(h & 1) ? E + e : e], b)
                  : effective(p.edge_sharpness[e], b);
        if (!is_sharp(sharpness)) continue;
        const double* y = in + 3 * std::size_t{t[h]};
        for (int k = 0; k < 3; ++k) ends[k] += y[k];
      }
      for (int k = 0; k < 3; ++k) q[k] = 0.75 * x[k] + 0.125 * ends[k];
    };
    double parent_point[3];
    if (parent_rule == kCrease)
      crease_point(parent_point, false);
    else
      std::copy(x, x + 3, parent_point);
    if (child_rule == parent_rule) {
      std::copy(parent_point, parent_point + 3, o);
      continue;
    }
    double child_point[3];
    if (child_rule == kCrease)
      crease_point(child_point, true);
    else if (child_rule == kCorner)
      std::copy(x, x + 3, child_point);
    else
      std::copy(o, o + 3, child_point);  // the smooth point, already there
    // Sdc::Crease::ComputeFractionalWeightAtVertex.
    std::uint32_t transitions = 0;
    float sum = 0.0f;
    if (is_sharp(pv) && !is_sharp(cv)) {
      transitions = 1;
      sum = pv;
    }
    for (std::uint32_t i = first; i < last; ++i) {
      const std::uint32_t h = out_of[i], e = h >> 1;
      const bool b = border(e);
      const float ps = effective(p.edge_sharpness[e], b);
      const bool decays =
          uniform
              ? is_sharp(ps) && ps <= 1.0f
              : is_sharp(ps) && !is_sharp(effective(
                                    c.edge_sharpness[(h & 1) ? E + e : e], b));
      if (!decays) continue;
      sum += ps;
      ++transitions;
    }
    float fraction = 0.0f;
    if (transitions > 0) {
      fraction = sum / static_cast<float>(transitions);
      if (fraction > 1.0f) fraction = 1.0f;
    }
    const double pw = fraction, cw = 1.0 - pw;
    for (int k = 0; k < 3; ++k)
      o[k] = pw * parent_point[k] + cw * child_point[k];
  }
}

Mesh_tags crease_tags(const Level& l, const Creasing& creasing,
                      const Mesh_tags& input) {
  Mesh_tags tags;
  const std::uint32_t* t = l.halfedge_target.data();
  for (std::uint32_t e = 0; e < l.edge_count; ++e) {
    const float s = l.edge_sharpness[e];
    if (!is_sharp(s)) continue;
    tags.crease_edges.push_back(t[2 * e + 1]);
    tags.crease_edges.push_back(t[2 * e]);
    tags.crease_sharpness.push_back(s);
  }
  for (std::uint32_t v = 0; v < l.vertex_count; ++v) {
    if (!is_sharp(l.vertex_sharpness[v])) continue;
    tags.corner_vertices.push_back(v);
    tags.corner_sharpness.push_back(l.vertex_sharpness[v]);
  }
  for (std::uint32_t f = 0; f < l.face_count; ++f)
    if (l.face_holes[f] != 0) tags.holes.push_back(f);
  tags.boundary = creasing.boundary;
  tags.boundary_given = input.boundary_given ||
                        creasing.boundary != Boundary_interpolation::edge_only;
  tags.crease_method = creasing.method;
  tags.crease_method_given =
      input.crease_method_given || creasing.method != Crease_method::uniform;
  return tags;
}

double crease_level_bytes(double vertices, double edges, double faces) {
  return 4 * edges + 4 * vertices + faces;
}

double crease_scratch_bytes(double vertices, double edges) {
  // The larger of apply_crease_rules' vertex runs and Chaikin's sums,
  // counts and valences.
  return std::max(4 * (vertices + 1) + 8 * edges, 12 * vertices);
}

}  // namespace refine
}  // namespace subdivlab
