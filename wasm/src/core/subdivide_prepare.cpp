// What both routes of a run check and prepare (subdivide_prepare.h).

#include "subdivide_prepare.h"

#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "custom_rules.h"
#include "mesh_build.h"
#include "refine/level_convert.h"
#include "scheme_table.h"

namespace subdivlab::detail {
namespace {

/// An interior vertex of degree 2 means its two faces share two edges (a
/// "pillow"). Splitting faces by edge points (PTQ), joining face centres
/// across edges (sqrt3) or building a face per vertex (DQQ) then repeats an
/// edge between the same two vertices, or makes a 2-gon: CGAL builds it, but
/// it is no polygon mesh (it cannot be read back). PQQ handles it;
/// quad-triangle splits triangles as PTQ does, quads as PQQ, so only a
/// vertex between two triangles repeats an edge.
enum class Two_valent_rule { allowed, refused, refused_between_triangles };

Two_valent_rule two_valent_rule(const Subdivide_options& options) {
  if (options.scheme == "quad-triangle")
    return Two_valent_rule::refused_between_triangles;
  const std::string model = size_model(options);
  return model == "loop" || model == "sqrt3" || model == "doo-sabin"
             ? Two_valent_rule::refused
             : Two_valent_rule::allowed;
}

Status two_valent_refusal(const Subdivide_options& options,
                          std::size_t vertex) {
  return Status::error(
      Status_code::invalid_mesh,
      options.scheme + " cannot refine vertex " + std::to_string(vertex) +
          ": it has only 2 edges, so its two faces share two edges and the "
          "result would repeat edges (catmull-clark can refine it)");
}

Status check_two_valent_vertices(const Mesh& mesh,
                                 const Subdivide_options& options) {
  const Two_valent_rule rule = two_valent_rule(options);
  if (rule == Two_valent_rule::allowed) return Status::success();
  for (Mesh::Vertex_index v : mesh.vertices()) {
    if (mesh.degree(v) != 2 || mesh.is_border(v)) continue;
    if (rule == Two_valent_rule::refused_between_triangles) {
      const Mesh::Halfedge_index h = mesh.halfedge(v);
      if (mesh.degree(mesh.face(h)) != 3 ||
          mesh.degree(mesh.face(mesh.opposite(mesh.next(h)))) != 3)
        continue;
    }
    return two_valent_refusal(options, v.idx());
  }
  return Status::success();
}

/// Collects the triangles triangulate_face makes of one polygon.
struct Subface_collector {
  std::vector<Mesh::Face_index>* subfaces;
  void before_subface_creations(Mesh::Face_index) { subfaces->clear(); }
  void after_subface_created(Mesh::Face_index f) { subfaces->push_back(f); }
  void after_subface_creations() {}
};

/// Whether `subfaces`, what triangulate_face made of a polygon of `degree`
/// vertices, are degree − 2 triangles whose halfedge cycles are whole and
/// disjoint. CGAL's constrained triangulation accepts a polygon that touches
/// itself (a corner on another side) and then links halfedges of two
/// triangles into one cycle: a broken mesh, whose next walk may never end.
/// Every walk here is bounded.
bool whole_triangles(const Mesh& mesh,
                     const std::vector<Mesh::Face_index>& subfaces,
                     std::size_t degree) {
  if (subfaces.size() + 2 != degree) return false;
  std::vector<Mesh::Halfedge_index> seen;
  for (Mesh::Face_index f : subfaces) {
    Mesh::Halfedge_index h = mesh.halfedge(f);
    for (int i = 0; i < 3; ++i) {
      if (mesh.face(h) != f || mesh.prev(mesh.next(h)) != h) return false;
      seen.push_back(h);
      h = mesh.next(h);
    }
    if (h != mesh.halfedge(f)) return false;
  }
  std::sort(seen.begin(), seen.end());
  return std::adjacent_find(seen.begin(), seen.end()) == seen.end();
}

/// Triangulates every polygon as triangulate_faces does (CGAL's
/// triangulate_face, face by face), naming the first it refuses: one whose
/// normal is zero (degenerate), or past 4 vertices one whose projection is
/// not a simple polygon, or one that touches itself (see whole_triangles).
/// Faces are numbered as in the input buffers.
Status triangulate_all(Mesh& mesh, const std::string& scheme) {
  std::vector<Mesh::Face_index> polygons;
  for (Mesh::Face_index f : mesh.faces())
    if (mesh.degree(f) > 3) polygons.push_back(f);
  std::vector<Mesh::Face_index> subfaces;
  for (Mesh::Face_index f : polygons) {
    const std::size_t degree = mesh.degree(f);
    subfaces.clear();
    if (CGAL::Polygon_mesh_processing::triangulate_face(
            f, mesh, CGAL::parameters::visitor(Subface_collector{&subfaces})) &&
        whole_triangles(mesh, subfaces, degree))
      continue;
    return Status::error(
        Status_code::invalid_mesh,
        "face " + std::to_string(f.idx()) + " (" + std::to_string(degree) +
            " vertices) could not be triangulated: it is degenerate (no "
            "area), self-intersecting or touches itself; " +
            scheme + " needs triangles");
  }
  return Status::success();
}

}  // namespace

Status check_options(const Subdivide_options& options) {
  if (find_scheme(options.scheme) == nullptr)
    return Status::error(Status_code::invalid_argument,
                         "unknown scheme \"" + options.scheme +
                             "\"; known schemes: " + scheme_list());
  if (options.levels < 0)
    return Status::error(
        Status_code::invalid_argument,
        "levels must be 0 or more (got " + std::to_string(options.levels) +
            ") for " + options.scheme + "; known schemes: " + scheme_list());
  if (options.start_level < 0)
    return Status::error(Status_code::invalid_argument,
                         "start_level must be 0 or more (got " +
                             std::to_string(options.start_level) + ")");
  if (options.scheme == "custom") return check_custom_rules(options.custom);
  return Status::success();
}

Status not_triangles(const std::string& scheme, const Counts& c) {
  return Status::error(
      Status_code::not_triangles,
      scheme + " needs a triangle mesh: " + format_count(c.non_triangles) +
          " of " + format_count(c.faces) +
          " faces are not triangles; triangulate first (option triangulate)");
}

void collect_removed(Mesh& mesh) {
  if (mesh.number_of_removed_vertices() + mesh.number_of_removed_halfedges() +
          mesh.number_of_removed_faces() >
      0)
    mesh.collect_garbage();
}

Status check_two_valent_vertices(const refine::Level& l,
                                 const Subdivide_options& options) {
  const Two_valent_rule rule = two_valent_rule(options);
  if (rule == Two_valent_rule::allowed) return Status::success();
  const bool two_triangles_only =
      rule == Two_valent_rule::refused_between_triangles;
  std::vector<std::uint32_t> valence;
  std::vector<bool> border, polygon(l.vertex_count, false);
  refine::vertex_valences(l, valence, border);
  if (two_triangles_only) {
    // A vertex a face other than a triangle comes into.
    for (std::uint32_t f = 0; f < l.face_count; ++f) {
      const std::uint32_t begin = l.face_begin(f), end = l.face_end(f);
      if (end - begin == 3) continue;
      for (std::uint32_t i = begin; i < end; ++i)
        polygon[l.face_vertices[i]] = true;
    }
  }
  for (std::uint32_t v = 0; v < l.vertex_count; ++v)
    if (valence[v] == 2 && !border[v] && !polygon[v])
      return two_valent_refusal(options, v);
  return Status::success();
}

Status prepare(const Mesh_buffers& in, const Subdivide_options& options,
               Mesh& mesh, Counts& counts) {
  Status s = check_options(options);
  if (!s.ok()) return s;
  s = build_mesh(in, mesh);
  if (!s.ok()) return s;
  // Exact capacities to start from (the memory model's assumption).
  mesh.shrink_to_fit();
  counts = counts_of(mesh);
  if (needs_triangles(options) && counts.non_triangles > 0) {
    if (!options.triangulate) return not_triangles(options.scheme, counts);
    s = triangulate_all(mesh, options.scheme);
    if (!s.ok()) return s;
    collect_removed(mesh);
    mesh.shrink_to_fit();
    counts = counts_of(mesh);
  }
  return check_two_valent_vertices(mesh, options);
}

Status sqrt3_border_refusal(const Subdivide_options& options, int global_step,
                            double multi) {
  if (options.scheme == "custom")
    return Status::error(
        Status_code::invalid_argument,
        "start_level " + std::to_string(global_step) +
            " of custom (sqrt3 host) refines the border, which needs a mesh "
            "from an even level, but some faces have more than one border "
            "edge; start from level 0");
  return Status::error(
      Status_code::invalid_argument,
      "start_level " + std::to_string(global_step) +
          " of sqrt3 refines the border, which needs a mesh from an even "
          "level of sqrt3, but " +
          format_count(multi) +
          " faces have more than one border edge; start from level 0");
}

Status overflow(const Mesh_buffers& in, const std::string& scheme, int level) {
  double largest = 0.0;
  for (double x : in.positions) largest = std::max(largest, std::abs(x));
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", largest);
  return Status::error(
      Status_code::invalid_mesh,
      "level " + std::to_string(level) + " of " + scheme +
          " overflows: a new coordinate is not finite (the input's "
          "coordinates reach " +
          buf +
          "; coordinates or weights this large exceed double precision "
          "arithmetic, scale the mesh down)");
}

bool creasing_of(const Mesh_buffers& in, const Subdivide_options& options,
                 refine::Creasing& creasing) {
  if (!applies_creases(options)) return false;
  creasing.method = options.crease_method.value_or(in.tags.crease_method);
  creasing.boundary = options.boundary.value_or(in.tags.boundary);
  return !in.tags.crease_edges.empty() || !in.tags.corner_vertices.empty() ||
         !in.tags.holes.empty() ||
         creasing.boundary != Boundary_interpolation::edge_only;
}

}  // namespace subdivlab::detail
