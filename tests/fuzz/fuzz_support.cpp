// What the targets share (fuzz_targets.h).

#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <utility>

#include "core/mesh_build.h"
#include "core/mesh_check.h"
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
