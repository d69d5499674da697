// Plain reference implementations of published subdivision rules, on index
// arrays, with no CGAL: the tests compare the core's CGAL-based output with
// these point by point. Written from the papers and from the rules CGAL's
// masks document, not from CGAL's hosts.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

namespace reference {

using Vec = std::array<double, 3>;

inline Vec operator+(const Vec& a, const Vec& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
inline Vec operator-(const Vec& a, const Vec& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline Vec operator*(double s, const Vec& a) {
  return {s * a[0], s * a[1], s * a[2]};
}

/// A polygon mesh as index arrays: faces list vertex numbers counter-
/// clockwise.
struct Poly_mesh {
  std::vector<Vec> points;
  std::vector<std::vector<std::uint32_t>> faces;
};

/// Edge table of a Poly_mesh: each undirected edge once, with the faces on
/// its two sides (second = -1 on the border).
struct Edges {
  struct Edge {
    std::uint32_t a, b;  // a < b
    long face0 = -1, face1 = -1;
    bool border() const { return face1 < 0; }
  };
  std::vector<Edge> list;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> index;

  explicit Edges(const Poly_mesh& m) {
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
      const auto& face = m.faces[f];
      for (std::size_t i = 0; i < face.size(); ++i) {
        std::uint32_t a = face[i], b = face[(i + 1) % face.size()];
        auto key = std::minmax(a, b);
        auto it = index.find(key);
        if (it == index.end()) {
          index[key] = list.size();
          list.push_back({key.first, key.second, static_cast<long>(f), -1});
        } else {
          list[it->second].face1 = static_cast<long>(f);
        }
      }
    }
  }
  std::size_t of(std::uint32_t a, std::uint32_t b) const {
    return index.at(std::minmax(a, b));
  }
};

/// Neighbour lists of each vertex, and for border vertices their two border
/// neighbours.
struct Neighbours {
  std::vector<std::vector<std::uint32_t>> of;
  std::vector<std::vector<std::uint32_t>> border_of;
  Neighbours(const Poly_mesh& m, const Edges& e)
      : of(m.points.size()), border_of(m.points.size()) {
    for (const auto& edge : e.list) {
      of[edge.a].push_back(edge.b);
      of[edge.b].push_back(edge.a);
      if (edge.border()) {
        border_of[edge.a].push_back(edge.b);
        border_of[edge.b].push_back(edge.a);
      }
    }
  }
};

inline Vec centroid(const Poly_mesh& m, const std::vector<std::uint32_t>& f) {
  Vec c{0, 0, 0};
  for (auto v : f) c = c + m.points[v];
  return (1.0 / static_cast<double>(f.size())) * c;
}

/// The border rule shared by CGAL's Catmull-Clark and Loop masks
/// (CatmullClark_mask_3::border_node, Loop_mask_3::border_node): border edge
/// point = midpoint, border vertex = 3/4 v + 1/8 (its two border
/// neighbours), i.e. the cubic B-spline rules along the border.
inline Vec border_vertex(const Poly_mesh& m, const Neighbours& n,
                         std::uint32_t v) {
  const auto& b = n.border_of[v];
  if (b.size() != 2) throw std::logic_error("non-manifold border vertex");
  return 0.75 * m.points[v] + 0.125 * (m.points[b[0]] + m.points[b[1]]);
}

/// One Catmull-Clark step (Catmull & Clark, "Recursively generated B-spline
/// surfaces on arbitrary topological meshes", CAD 10(6), 1978), with the
/// vertex rule in the form CGAL's CatmullClark_mask_3 documents:
///   face point   centroid
///   edge point   (v1 + v2 + f1 + f2) / 4
///   vertex point (Q + 2R + (n - 3) S) / n, Q = mean of the adjacent face
///                points, R = mean of the adjacent edge midpoints
/// plus the border rule above. New vertices: old ones, then one per edge (in
/// Edges order), then one per face.
inline Poly_mesh catmull_clark(const Poly_mesh& m) {
  const Edges e(m);
  const Neighbours nb(m, e);
  const std::size_t nv = m.points.size(), ne = e.list.size();
  Poly_mesh r;
  r.points.resize(nv + ne + m.faces.size());
  std::vector<Vec> face_point(m.faces.size());
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    face_point[f] = r.points[nv + ne + f] = centroid(m, m.faces[f]);
  for (std::size_t i = 0; i < ne; ++i) {
    const auto& edge = e.list[i];
    const Vec mid = 0.5 * (m.points[edge.a] + m.points[edge.b]);
    r.points[nv + i] =
        edge.border()
            ? mid
            : 0.25 * (m.points[edge.a] + m.points[edge.b] +
                      face_point[edge.face0] + face_point[edge.face1]);
  }
  // Q sums per vertex.
  std::vector<Vec> q(nv, Vec{0, 0, 0});
  std::vector<int> nf(nv, 0);
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    for (auto v : m.faces[f]) {
      q[v] = q[v] + face_point[f];
      ++nf[v];
    }
  for (std::uint32_t v = 0; v < nv; ++v) {
    if (!nb.border_of[v].empty()) {
      r.points[v] = border_vertex(m, nb, v);
      continue;
    }
    const double n = static_cast<double>(nb.of[v].size());
    Vec rsum{0, 0, 0};
    for (auto w : nb.of[v]) rsum = rsum + 0.5 * (m.points[v] + m.points[w]);
    const Vec Q = (1.0 / nf[v]) * q[v], R = (1.0 / n) * rsum;
    r.points[v] = (1.0 / n) * (Q + 2.0 * R + (n - 3) * m.points[v]);
  }
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const auto& face = m.faces[f];
    const std::size_t k = face.size();
    for (std::size_t i = 0; i < k; ++i) {
      const std::uint32_t v = face[i], next = face[(i + 1) % k],
                          prev = face[(i + k - 1) % k];
      r.faces.push_back({v, static_cast<std::uint32_t>(nv + e.of(v, next)),
                         static_cast<std::uint32_t>(nv + ne + f),
                         static_cast<std::uint32_t>(nv + e.of(prev, v))});
    }
  }
  return r;
}

/// Loop's weight for the neighbours of a vertex of valence n, all together
/// (Loop, "Smooth subdivision surfaces based on triangles", MS thesis, Univ.
/// of Utah, 1987): alpha(n) = 5/8 - (3/8 + 1/4 cos(2 pi / n))^2; the vertex
/// goes to (1 - alpha) v + alpha/n sum(neighbours). This is exactly what
/// CGAL's Loop_mask_3::vertex_node computes (its Cn; for n = 6 it uses the
/// equal weights 10/16 and 1/16).
inline double loop_alpha(double n) {
  const double c = 3.0 / 8.0 + 0.25 * std::cos(2 * M_PI / n);
  return 5.0 / 8.0 - c * c;
}

/// One Loop step: edge point 3/8 (a + b) + 1/8 (c + d) (c, d opposite), the
/// vertex rule above, and the border rule above. Faces: each triangle into
/// its three corner triangles and the middle one.
inline Poly_mesh loop(const Poly_mesh& m) {
  const Edges e(m);
  const Neighbours nb(m, e);
  const std::size_t nv = m.points.size(), ne = e.list.size();
  auto opposite = [&](long f, std::uint32_t a, std::uint32_t b) {
    for (auto v : m.faces[f])
      if (v != a && v != b) return v;
    throw std::logic_error("not a triangle");
  };
  Poly_mesh r;
  r.points.resize(nv + ne);
  for (std::size_t i = 0; i < ne; ++i) {
    const auto& edge = e.list[i];
    const Vec& a = m.points[edge.a];
    const Vec& b = m.points[edge.b];
    if (edge.border()) {
      r.points[nv + i] = 0.5 * (a + b);
    } else {
      const Vec& c = m.points[opposite(edge.face0, edge.a, edge.b)];
      const Vec& d = m.points[opposite(edge.face1, edge.a, edge.b)];
      r.points[nv + i] = 0.375 * (a + b) + 0.125 * (c + d);
    }
  }
  for (std::uint32_t v = 0; v < nv; ++v) {
    if (!nb.border_of[v].empty()) {
      r.points[v] = border_vertex(m, nb, v);
      continue;
    }
    const double n = static_cast<double>(nb.of[v].size());
    const double alpha = loop_alpha(n);
    Vec sum{0, 0, 0};
    for (auto w : nb.of[v]) sum = sum + m.points[w];
    r.points[v] = (1 - alpha) * m.points[v] + (alpha / n) * sum;
  }
  for (const auto& f : m.faces) {
    if (f.size() != 3) throw std::logic_error("loop: not a triangle");
    const std::uint32_t a = f[0], b = f[1], c = f[2];
    const auto ab = static_cast<std::uint32_t>(nv + e.of(a, b));
    const auto bc = static_cast<std::uint32_t>(nv + e.of(b, c));
    const auto ca = static_cast<std::uint32_t>(nv + e.of(c, a));
    r.faces.push_back({a, ab, ca});
    r.faces.push_back({b, bc, ab});
    r.faces.push_back({c, ca, bc});
    r.faces.push_back({ab, bc, ca});
  }
  return r;
}

/// The border loops of a mesh as ordered vertex lists, each running the way
/// the faces orient it (a border edge a -> b of a face is followed by the
/// border edge that starts at b).
inline std::vector<std::vector<std::uint32_t>> border_loops(
    const Poly_mesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& f : m.faces)
    for (std::size_t i = 0; i < f.size(); ++i)
      ++directed[{f[i], f[(i + 1) % f.size()]}];
  std::map<std::uint32_t, std::uint32_t> next;  // border edge a -> b
  for (const auto& [edge, count] : directed)
    if (!directed.count({edge.second, edge.first}))
      next[edge.first] = edge.second;
  std::vector<std::vector<std::uint32_t>> loops;
  while (!next.empty()) {
    std::vector<std::uint32_t> loop;
    std::uint32_t v = next.begin()->first;
    while (next.count(v)) {
      loop.push_back(v);
      const std::uint32_t w = next[v];
      next.erase(v);
      v = w;
    }
    loops.push_back(loop);
  }
  return loops;
}

/// One step of Chaikin's corner cutting on a closed polygon (Chaikin, "An
/// algorithm for high-speed curve generation", CGIP 3, 1974): each edge
/// P_i P_i+1 gives 3/4 P_i + 1/4 P_i+1 and 1/4 P_i + 3/4 P_i+1. Its limit is
/// the uniform quadratic B-spline of the polygon.
inline std::vector<Vec> chaikin(const std::vector<Vec>& p) {
  std::vector<Vec> q;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec& a = p[i];
    const Vec& b = p[(i + 1) % p.size()];
    q.push_back(0.75 * a + 0.25 * b);
    q.push_back(0.25 * a + 0.75 * b);
  }
  return q;
}

/// Point of the closed uniform quadratic B-spline of polygon p on the piece
/// around control point i, t in [0, 1] (from the midpoint of P_i-1 P_i to the
/// midpoint of P_i P_i+1).
inline Vec quadratic_bspline(const std::vector<Vec>& p, std::size_t i,
                             double t) {
  const std::size_t n = p.size();
  const Vec& a = p[(i + n - 1) % n];
  const Vec& b = p[i];
  const Vec& c = p[(i + 1) % n];
  return (0.5 * (1 - t) * (1 - t)) * a + (0.5 * (-2 * t * t + 2 * t + 1)) * b +
         (0.5 * t * t) * c;
}

}  // namespace reference
