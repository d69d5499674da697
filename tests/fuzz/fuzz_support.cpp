// What the targets share (fuzz_targets.h).

#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "core/mesh_build.h"
#include "core/mesh_check.h"
#include "core/render_buffers.h"
#include "core/subdivide.h"
#include "fuzz_targets.h"

namespace subdivlab::fuzz {

void fuzz_fail(const std::string& what, const std::string& detail) {
  std::fprintf(stderr, "fuzz finding: %s%s%s\n", what.c_str(),
               detail.empty() ? "" : ": ", detail.c_str());
  std::fflush(stderr);
  __builtin_trap();
}

void require_sane_status(const Status& s, const char* where) {
  if (s.ok()) return;
  if (s.code == Status_code::internal_error)
    fuzz_fail(std::string(where) + " gave internal_error", s.message);
  if (s.message.empty())
    fuzz_fail(std::string(where) + " failed without a message");
  for (const char c : s.message)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
      fuzz_fail(std::string(where) + "'s message holds a control byte",
                s.message);
  if (s.line < 0) fuzz_fail(std::string(where) + " named a negative line");
}

bool same_tags(const Mesh_tags& a, const Mesh_tags& b) {
  return a.crease_edges == b.crease_edges &&
         a.crease_sharpness == b.crease_sharpness &&
         a.corner_vertices == b.corner_vertices &&
         a.corner_sharpness == b.corner_sharpness && a.holes == b.holes &&
         a.boundary == b.boundary && a.boundary_given == b.boundary_given &&
         a.crease_method == b.crease_method &&
         a.crease_method_given == b.crease_method_given;
}

bool same_mesh(const Mesh_buffers& a, const Mesh_buffers& b) {
  return a.positions == b.positions && a.face_sizes == b.face_sizes &&
         a.face_indices == b.face_indices && same_tags(a.tags, b.tags);
}

bool same_surface_mesh(const Mesh& a, const Mesh& b) {
  if (a.number_of_vertices() != b.number_of_vertices() ||
      a.number_of_halfedges() != b.number_of_halfedges() ||
      a.number_of_faces() != b.number_of_faces())
    return false;
  for (const Mesh::Halfedge_index h : a.halfedges())
    if (a.target(h) != b.target(h) || a.next(h) != b.next(h) ||
        a.face(h) != b.face(h))
      return false;
  for (const Mesh::Vertex_index v : a.vertices())
    if (a.point(v) != b.point(v) || a.halfedge(v) != b.halfedge(v))
      return false;
  for (const Mesh::Face_index f : a.faces())
    if (a.halfedge(f) != b.halfedge(f)) return false;
  return true;
}

bool read_any(std::string_view bytes, Mesh_buffers& mesh) {
  const Result<Mesh_format> format = detect_format(bytes);
  require_sane_status(format.status, "detect_format");
  if (!format.ok()) return false;
  Result<Mesh_buffers> r = read_mesh(bytes, format.value);
  require_sane_status(r.status, "read_mesh");
  if (!r.ok()) return false;
  mesh = std::move(r.value);
  return true;
}

namespace {

using Edge = std::pair<std::uint32_t, std::uint32_t>;

/// Keeps the edges and the border a sink is handed.
struct Edge_sink : Render_sink {
  std::vector<std::uint32_t> edges, border;
  void floats(Render_array, const std::vector<float>&) override {}
  void indices(Render_array which,
               const std::vector<std::uint32_t>& v) override {
    if (which == Render_array::edges) edges = v;
    if (which == Render_array::border_edges) border = v;
  }
};

/// The edges of `edges` (pairs, smaller vertex first) that one corner goes
/// along, in the order of `edges`.
std::vector<std::uint32_t> border_of(const std::vector<std::uint32_t>& edges,
                                     const std::map<Edge, int>& corners) {
  std::vector<std::uint32_t> out;
  for (std::size_t i = 0; i + 1 < edges.size(); i += 2) {
    const auto at = corners.find({edges[i], edges[i + 1]});
    if (at != corners.end() && at->second == 1)
      out.insert(out.end(), {edges[i], edges[i + 1]});
  }
  return out;
}

/// The pairs of `edges` as they are listed (not reordered: a pair with the
/// larger vertex first stays so, and differs from the mesh's edge).
std::set<Edge> listed_pairs(const std::vector<std::uint32_t>& edges) {
  std::set<Edge> out;
  for (std::size_t i = 0; i + 1 < edges.size(); i += 2)
    out.emplace(edges[i], edges[i + 1]);
  return out;
}

/// The render arrays of a valid mesh, against a map of its corners: the
/// fan of the faces drawn (holes are not), their edges once each, smaller
/// vertex first, and among those the edges one corner of the whole mesh
/// goes along, in edge order; told the number of edges (as a step's view
/// is), the same edges and border.
void require_render_buffers(const Mesh_buffers& mesh, const std::string& w) {
  std::vector<std::uint8_t> hole(mesh.face_count(), 0);
  for (const std::uint32_t f : mesh.tags.holes)
    if (f < hole.size()) hole[f] = 1;
  std::map<Edge, int> corners;
  std::set<Edge> shown;
  std::vector<std::uint32_t> fan_face;
  std::size_t at = 0;
  for (std::uint32_t f = 0; f < mesh.face_count(); ++f) {
    const std::uint32_t k = mesh.face_sizes[f];
    for (std::uint32_t c = 0; c < k; ++c) {
      const Edge e = std::minmax(mesh.face_indices[at + c],
                                 mesh.face_indices[at + (c + 1) % k]);
      ++corners[e];
      if (!hole[f]) shown.insert(e);
    }
    if (!hole[f]) fan_face.insert(fan_face.end(), k - 2, f);
    at += k;
  }
  const Render_buffers r = render_buffers(mesh);
  require(r.edges.size() == 2 * shown.size() && listed_pairs(r.edges) == shown,
          "the render edges are not the drawn faces' edges, once each", w);
  require(r.border_edges == border_of(r.edges, corners),
          "the render border is not the edges of one corner, in edge order", w);
  require(
      r.triangle_face == fan_face && r.triangles.size() == 3 * fan_face.size(),
      "the render fan is not k - 2 triangles per face drawn", w);
  for (const std::uint32_t v : r.triangles)
    require(v < mesh.vertex_count(), "a render triangle names no vertex", w);
  Edge_sink told;
  require(build_render_buffers(mesh, told, corners.size()) == corners.size(),
          "build_render_buffers told the edges counts others", w);
  require(told.edges.size() == r.edges.size() &&
              listed_pairs(told.edges) == shown &&
              told.border == border_of(told.edges, corners),
          "told the number of edges, other render edges or border", w);
}

}  // namespace

void require_valid_mesh(const Mesh_buffers& mesh, const char* what) {
  const std::string w = what;
  for (const double x : mesh.positions)
    require(std::isfinite(x), "a coordinate is not finite", w);
  const detail::Check_result check = detail::check_buffers(mesh);
  require(check.status.ok(), "check_buffers refuses",
          w + ": " + check.status.message);
  const Status writable = check_writable(mesh);
  require(writable.ok(), "check_writable refuses", w + ": " + writable.message);
  std::uint32_t used = 0;
  detail::used_vertex_ranks(mesh, used);
  require(used == mesh.vertex_count(), "a vertex no face uses", w);
  Mesh built;
  const Status s = build_mesh(mesh, built);
  require(s.ok(), "build_mesh refuses", w + ": " + s.message);
  require(CGAL::is_valid_polygon_mesh(built), "not a valid polygon mesh", w);
  require(built.number_of_faces() == mesh.face_count(), "faces lost", w);
  require_render_buffers(mesh, w);
}

namespace {

std::set<std::pair<std::uint32_t, std::uint32_t>> edge_set(
    const std::vector<std::uint32_t>& pairs) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> s;
  for (std::size_t i = 0; i + 1 < pairs.size(); i += 2)
    s.emplace(std::min(pairs[i], pairs[i + 1]),
              std::max(pairs[i], pairs[i + 1]));
  return s;
}

}  // namespace

bool same_result(const Mesh_buffers& a, const Mesh_buffers& b) {
  double scale = 0;
  for (const double x : a.positions) scale = std::max(scale, std::fabs(x));
  const double tolerance = 1e-9 * scale + 1e-300;
  if (a.face_sizes != b.face_sizes || a.face_indices != b.face_indices ||
      a.positions.size() != b.positions.size() ||
      edge_set(a.control_edges) != edge_set(b.control_edges))
    return false;
  for (std::size_t i = 0; i < a.positions.size(); ++i)
    if (!(std::fabs(a.positions[i] - b.positions[i]) <= tolerance))
      return false;
  return true;
}

void require_result(const Mesh_buffers& in, const Subdivide_options& o,
                    const Mesh_buffers& out, const std::string& what) {
  require_valid_mesh(out, what.c_str());
  const Result<Size_prediction> p = predict_size(in, o);
  require(p.ok(), "predict_size refuses a run that succeeded",
          what + ": " + p.status.message);
  Mesh built;
  build_mesh(out, built);
  require(p.value.vertices == out.vertex_count() &&
              p.value.faces == out.face_count() &&
              p.value.edges == built.number_of_edges(),
          "predict_size's counts are not the result's", what);
  const auto edges = edge_set(out.control_edges);
  for (const auto& [a, b] : edges) {
    const auto h = built.halfedge(Mesh::Vertex_index(a), Mesh::Vertex_index(b));
    require(a < out.vertex_count() && b < out.vertex_count() &&
                h != Mesh::null_halfedge(),
            "a control edge is not an edge of the result", what);
  }
}

}  // namespace subdivlab::fuzz
