// The subdivision driver: options checked, the run's size predicted
// (size_model.h), then one step at a time, each preceded by a size check,
// on one of two routes:
//   fast hosts (refine/) for the PQQ, PTQ, DQQ, sqrt3 and PQT
//     (quad-triangle) schemes (scheme_table.h):
//     level 0 taken from the checked buffers, or from CGAL's mesh when
//     polygons must be triangulated first; the levels' tables derived in
//     CGAL's numbering; the last level's arrays moved into the result.
//   CGAL's hosts with cgal_hosts (the reference the fast hosts are tested
//     against): a Surface_mesh built, refined by Subdivision_method_3 --
//     Doo-Sabin on open meshes by the border-aware DQQ host of
//     dqq_border_3.h, sqrt(3) refining the border on every second step (the
//     parity carried through Subdivide_options::start_level), quad-triangle
//     by quad_triangle_3.h -- then back to buffers.

#include "subdivide.h"

#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Subdivision_method_3/subdivision_hosts_3.h>
#include <CGAL/Subdivision_method_3/subdivision_masks_3.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/exceptions.h>
#include <CGAL/subdivision_method_3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <new>
#include <string>
#include <vector>

#include "control_edges.h"
#include "custom_rules.h"
#include "dqq_border_3.h"
#include "linear_masks_3.h"
#include "mesh_build.h"
#include "mesh_check.h"
#include "quad_triangle_3.h"
#include "refine/crease.h"
#include "refine/dual_hosts.h"
#include "refine/dual_masks.h"
#include "refine/dual_points.h"
#include "refine/level_convert.h"
#include "refine/primal_hosts.h"
#include "refine/primal_masks.h"
#include "refine/primal_points.h"
#include "refine/sqrt3_host.h"
#include "scheme_table.h"
#include "size_model.h"
#include "stencils.h"

namespace subdivlab {
namespace {

namespace SM3 = CGAL::Subdivision_method_3;
using namespace detail;

// ---------------------------------------------------------------------------
// Steps.

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

/// Frees the elements a host removed (CGAL's DQQ removes the old vertices;
/// sqrt3's flips recycle what they remove). Not shrink_to_fit: it copies
/// every array, a peak above most steps', and the next step's reserve
/// reallocates anyway. collect_garbage shrinks the arrays itself.
void collect_removed(Mesh& mesh) {
  if (mesh.number_of_removed_vertices() + mesh.number_of_removed_halfedges() +
          mesh.number_of_removed_faces() >
      0)
    mesh.collect_garbage();
}

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

/// Builds and checks the mesh the steps start from: valid, and triangles for
/// the schemes that need them (triangulated here if asked to).
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

/// The refusal of a border step (sqrt3 or custom rules on its host) on a
/// mesh with `multi` faces that have more than one border edge: the host
/// assumes at most one, which holds for the output of a non-border step
/// but not for arbitrary input.
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

Status sqrt3_step(Mesh& mesh, const Subdivide_options& options,
                  int global_step) {
  if (!sqrt3_refines_border(global_step) || CGAL::is_closed(mesh)) {
    SM3::Sqrt3_subdivision(mesh, CGAL::parameters::number_of_iterations(1));
    return Status::success();
  }
  const Counts c = counts_of(mesh);
  if (c.multi_border_faces > 0)
    return sqrt3_border_refusal(options, global_step, c.multi_border_faces);
  // The public Sqrt3_subdivision ties the border parity to its own loop
  // counter, so a single border step needs the host CGAL's loop calls.
  SM3::internal::Sqrt3_1step(
      mesh, get(CGAL::vertex_point, mesh),
      CGAL::Sqrt3_mask_3<Mesh>(&mesh, get(CGAL::vertex_point, mesh)),
      /*refine_border=*/true);
  return Status::success();
}

/// Averaging overflows near the largest double: a file's 1e308 is finite and
/// accepted, but a sum of such coordinates is not (and custom weights can be
/// large too). A step must not hand out inf or nan, which no file can hold.
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

Status check_finite_points(const Mesh& mesh, const Mesh_buffers& in,
                           const std::string& scheme, int level) {
  for (Mesh::Vertex_index v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      return overflow(in, scheme, level);
  }
  return Status::success();
}

/// check_two_valent_vertices on a level.
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

/// The level a fast run starts from, its counts and its marked control
/// edges (`marks` of them). From the buffers directly (check_buffers pairs
/// the edges as build_mesh's Surface_mesh would number them), or, when
/// polygons must be triangulated first, from CGAL's triangulated mesh.
Status prepare_level(const Mesh_buffers& in, const Subdivide_options& options,
                     refine::Level& level, Counts& counts, double& marks) {
  Status s = check_options(options);
  if (!s.ok()) return s;
  {
    std::vector<std::uint32_t> corner_halfedges;
    const detail::Check_result check =
        detail::check_buffers(in, {}, &corner_halfedges);
    if (!check.status.ok()) return check.status;
    level = refine::level_from_buffers(in, corner_halfedges);
  }
  counts = counts_of(level);
  bool all_edges_are_face_edges = true;
  if (needs_triangles(options) && counts.non_triangles > 0) {
    if (!options.triangulate) return not_triangles(options.scheme, counts);
    Mesh mesh;
    s = prepare(in, options, mesh, counts);
    if (!s.ok()) return s;
    level = refine::level_from_mesh(mesh);
    counts.from_triangulated_mesh = true;
    all_edges_are_face_edges = false;
  } else {
    s = check_two_valent_vertices(level, options);
    if (!s.ok()) return s;
  }
  marks = 0;
  if (!scheme_keeps_control_edges(options)) return Status::success();
  counts.control_edge_pairs = !in.control_edges.empty();
  if (in.control_edges.empty() && all_edges_are_face_edges) {
    if (options.start_level == 0) level.edge_marks.assign(level.edge_count, 1);
    marks = options.start_level == 0 ? level.edge_count : 0;
    return Status::success();
  }
  const refine::Vertex_halfedges around = refine::vertex_halfedges(level);
  // Every edge found is a control edge (or the run is refused): marked as
  // it is found.
  level.edge_marks.assign(level.edge_count, 0);
  const auto edge_of = [&](std::uint32_t a, std::uint32_t b) {
    const std::uint32_t e = around.edge(level, a, b);
    if (e != kNoEdge) level.edge_marks[e] = 1;
    return e;
  };
  const Result<Control_edges> control =
      initial_control_edges(in, level.edge_count, edge_of, options.start_level);
  if (!control.ok()) return control.status;
  marks = static_cast<double>(control.value.size());
  return Status::success();
}

/// What step_stencils asks of a run: the stencils of its last step
/// (stencils.h), or why there are none.
struct Stencil_request {
  Stencil_table table;
  std::string error;
};

/// Runs the steps of `options` on a fast host (refine/) from `parent`
/// (level 0 from prepare_level, with `counts` and `marks` control edges).
/// Each step is checked against the memory limit first, as the CGAL steps
/// are; then `step(parent, child, global_step, last)` refines `parent` into
/// `child` or refuses with its status; a point that is not finite ends the
/// run. `free_scratch` lets the host's scratch go before the output buffers
/// are made (the memory model counts it gone). `level` follows the step for
/// messages.
template <class Step, class Free_scratch>
Status run_fast_steps(refine::Level& parent, Counts counts, double marks,
                      const Subdivide_options& options, const Mesh_buffers& in,
                      double input, Mesh_buffers& out, int& level, Step&& step,
                      Free_scratch&& free_scratch) {
  const Caps mesh_caps = Caps::exact(counts);
  refine::Level child;
  for (int i = 0; i < options.levels; ++i) {
    const int global_step = options.start_level + i;
    level = global_step + 1;
    const bool last = i + 1 == options.levels;
    const Step_need need = step_need(options, counts, mesh_caps, global_step,
                                     i == 0, last, marks, input);
    Status s = check_step(options.scheme, need, global_step,
                          options.memory_limit_bytes);
    if (s.ok()) s = step(parent, child, global_step, last);
    if (!s.ok()) return s;
    for (double x : child.positions)
      if (!std::isfinite(x)) return overflow(in, options.scheme, level);
    std::swap(parent, child);
    counts = need.after;
    marks *= 2;
  }
  child = refine::Level();
  free_scratch();
  out = refine::level_to_buffers(std::move(parent));
  return Status::success();
}

/// The last step of an uncreased PQQ, PTQ or PQT run: its points first
/// (they need only the child's vertex count) and the stencils probed when
/// asked; then the scratch and what the child's corners do not read of the
/// parent (refine::release_before_last_topology) go before `topology`
/// makes those corners, so that they never coexist.
template <class Points, class Probe, class Topology>
void points_then_topology(refine::Level& p, refine::Level& c,
                          std::uint32_t child_vertices, Points&& points,
                          Probe&& probe, refine::Primal_scratch& scratch,
                          Topology&& topology) {
  c = refine::Level();  // the level before p: smaller, of no use now
  c.vertex_count = child_vertices;
  points(p, c);
  probe();
  scratch = refine::Primal_scratch();
  refine::release_before_last_topology(p, c);
  topology();
}

/// The primal hosts (`mask` from refine::primal_mask); with OpenSubdiv's
/// creasing when level 0 is creased (apply_tags).
Status run_primal_steps(refine::Level& parent, Counts counts, double marks,
                        const refine::Primal_mask& mask,
                        const refine::Creasing& creasing,
                        const Subdivide_options& options,
                        const Mesh_buffers& in, double input, Mesh_buffers& out,
                        int& level, Stencil_request* stencils) {
  refine::Primal_scratch scratch;
  refine::Crease_scratch crease_scratch;
  const Status s = run_fast_steps(
      parent, counts, marks, options, in, input, out, level,
      [&](refine::Level& p, refine::Level& c, int, bool last) {
        const std::uint32_t uncovered =
            refine::primal_uncovered_valence(p, mask, scratch);
        if (uncovered != 0)
          return custom_rules_valence_refusal(options.custom, uncovered);
        const auto points = [&](const refine::Level& from, refine::Level& to) {
          refine::refine_primal_points(from, mask, scratch, to);
          if (from.creased)
            refine::apply_crease_rules(from, creasing, crease_scratch, to);
        };
        const auto probe = [&] {
          if (last && stencils)
            stencils->error = detail::probe_stencils(
                p, c, mask.pqq ? "pqq" : "ptq", false, points, stencils->table);
        };
        const auto topology = [&] {
          if (mask.pqq)
            refine::refine_pqq_topology(p, c, last);
          else
            refine::refine_ptq_topology(p, c, last);
        };
        // The creasing rules read the child's crease tables, made with its
        // topology: a creased run keeps that order to its end.
        if (last && !p.creased) {
          points_then_topology(p, c,
                               mask.pqq ? refine::pqq_child_vertex_count(p)
                                        : refine::ptq_child_vertex_count(p),
                               points, probe, scratch, topology);
          return Status::success();
        }
        topology();
        if (p.creased) refine::refine_crease_tables(p, creasing, mask.pqq, c);
        points(p, c);
        probe();
        return Status::success();
      },
      [&] {
        scratch = refine::Primal_scratch();
        crease_scratch = refine::Crease_scratch();
      });
  // level_to_buffers took the positions and faces; the crease tables and
  // halfedge targets are still there.
  if (s.ok() && parent.creased)
    out.tags = refine::crease_tags(parent, creasing, in.tags);
  return s;
}

/// The tags of `in` for `mesh`, which is `in` as built for no step: the
/// vertices no face uses dropped (tags renumbered past them); none when it
/// had to be triangulated (its faces, which holes name, changed).
Mesh_tags unchanged_mesh_tags(const Mesh_buffers& in, const Mesh& mesh) {
  if (mesh.number_of_faces() != in.face_count()) return {};
  Mesh_tags tags = detail::tags_without_isolated_vertices(in);
  tags.notes.clear();  // the reader's, for the user who loaded the file
  return tags;
}

/// Whether a run applies OpenSubdiv's creasing: a scheme that applies tags
/// (applies_creases) on a mesh with tags, or with a border mode other than
/// CGAL's; `creasing`
/// gets the tags' options overridden by the run's.
bool creasing_of(const Mesh_buffers& in, const Subdivide_options& options,
                 refine::Creasing& creasing) {
  if (!applies_creases(options)) return false;
  creasing.method = options.crease_method.value_or(in.tags.crease_method);
  creasing.boundary = options.boundary.value_or(in.tags.boundary);
  return !in.tags.crease_edges.empty() || !in.tags.corner_vertices.empty() ||
         !in.tags.holes.empty() ||
         creasing.boundary != Boundary_interpolation::edge_only;
}

/// The DQQ host (`mask` from refine::dual_mask).
Status run_dual_steps(refine::Level& parent, Counts counts,
                      const refine::Dual_mask& mask,
                      const Subdivide_options& options, const Mesh_buffers& in,
                      double input, Mesh_buffers& out, int& level,
                      Stencil_request* stencils) {
  refine::add_face_vertex_halfedges(parent);
  refine::Dual_scratch scratch;
  return run_fast_steps(
      parent, counts, 0, options, in, input, out, level,
      [&](refine::Level& p, refine::Level& c, int, bool last) {
        const std::uint32_t uncovered = refine::dual_uncovered_degree(p, mask);
        if (uncovered != 0)
          return custom_rules_degree_refusal(options.custom, uncovered);
        // Before the child is allocated (the memory model counts them
        // gone).
        refine::release_unread_tables(p);
        refine::refine_dqq_topology(p, scratch, c, last);
        const auto points = [&](const refine::Level& from, refine::Level& to) {
          refine::refine_dual_points(from, mask, scratch, to);
        };
        points(p, c);
        if (last && stencils)
          stencils->error = detail::probe_stencils(p, c, "dqq", false, points,
                                                   stencils->table);
        return Status::success();
      },
      [&] { scratch = refine::Dual_scratch(); });
}

/// The sqrt(3) host (`mask` from refine::sqrt3_mask): the border refined
/// on odd global steps of an open mesh, refused there when a face has two
/// border edges, as sqrt3_step and run_step refuse it.
Status run_sqrt3_steps(refine::Level& parent, Counts counts,
                       const refine::Primal_mask& mask,
                       const Subdivide_options& options, const Mesh_buffers& in,
                       double input, Mesh_buffers& out, int& level,
                       Stencil_request* stencils) {
  refine::Sqrt3_scratch scratch;
  refine::Primal_scratch points;
  return run_fast_steps(
      parent, counts, 0, options, in, input, out, level,
      [&](refine::Level& p, refine::Level& c, int global_step, bool last) {
        const std::uint32_t uncovered =
            refine::primal_uncovered_valence(p, mask, points);
        if (uncovered != 0)
          return custom_rules_valence_refusal(options.custom, uncovered);
        const bool border_step =
            sqrt3_refines_border(global_step) && p.border_edge_count > 0;
        if (border_step) {
          const std::uint32_t multi = refine::sqrt3_multi_border_faces(p);
          if (multi > 0)
            return sqrt3_border_refusal(options, global_step, multi);
        }
        refine::refine_sqrt3_topology(p, border_step, scratch, c, last);
        const auto step_points = [&](const refine::Level& from,
                                     refine::Level& to) {
          refine::refine_sqrt3_points(from, mask, border_step, scratch, points,
                                      to);
        };
        step_points(p, c);
        if (last && stencils)
          stencils->error = detail::probe_stencils(
              p, c, "sqrt3", border_step, step_points, stencils->table);
        return Status::success();
      },
      [&] {
        scratch = refine::Sqrt3_scratch();
        points = refine::Primal_scratch();
      });
}

/// The PQT host (quad-triangle; `mask` from refine::quad_triangle_mask).
Status run_pqt_steps(refine::Level& parent, Counts counts, double marks,
                     const refine::Quad_triangle_mask& mask,
                     const Subdivide_options& options, const Mesh_buffers& in,
                     double input, Mesh_buffers& out, int& level,
                     Stencil_request* stencils) {
  refine::Primal_scratch scratch;
  return run_fast_steps(
      parent, counts, marks, options, in, input, out, level,
      [&](refine::Level& p, refine::Level& c, int, bool last) {
        const auto points = [&](const refine::Level& from, refine::Level& to) {
          refine::refine_pqt_points(from, mask, scratch, to);
        };
        const auto probe = [&] {
          if (last && stencils)
            stencils->error = detail::probe_stencils(p, c, "pqt", false, points,
                                                     stencils->table);
        };
        const auto topology = [&] { refine::refine_pqt_topology(p, c, last); };
        if (last) {
          points_then_topology(p, c, refine::pqt_child_vertex_count(p), points,
                               probe, scratch, topology);
          return Status::success();
        }
        topology();
        points(p, c);
        return Status::success();
      },
      [&] { scratch = refine::Primal_scratch(); });
}

}  // namespace

/// Runs ONE step of `options.scheme` on `mesh`. `level_index` counts the
/// steps of this call from 0; the step's level in the mesh's history is
/// options.start_level + level_index (sqrt3's border parity). May throw
/// (CGAL, bad_alloc): subdivide_mesh catches.
Status run_step(Mesh& mesh, const Subdivide_options& options, int level_index) {
  const std::string& scheme = options.scheme;
  const int global_step = options.start_level + level_index;
  const auto one_step = CGAL::parameters::number_of_iterations(1);
  Status s = Status::success();
  if (scheme == "catmull-clark") {
    SM3::CatmullClark_subdivision(mesh, one_step);
  } else if (scheme == "loop") {
    SM3::Loop_subdivision(mesh, one_step);
  } else if (scheme == "doo-sabin") {
    if (CGAL::is_closed(mesh))
      SM3::DooSabin_subdivision(mesh, one_step);
    else
      DooSabin_border_subdivision(mesh, one_step);
  } else if (scheme == "sqrt3") {
    s = sqrt3_step(mesh, options, global_step);
  } else if (scheme == "quad-triangle") {
    QuadTriangle_subdivision(mesh, 1, options.smooth_boundary);
  } else if (scheme == "linear") {
    Linear_subdivision(mesh);
  } else if (scheme == "linear-tri") {
    Linear_triangle_subdivision(mesh);
  } else if (scheme == "custom") {
    // Valences and face degrees grow with the steps: check every step.
    s = check_custom_rules_cover(options.custom, mesh);
    if (s.ok() && options.custom.host == "sqrt3" &&
        sqrt3_refines_border(global_step) && !CGAL::is_closed(mesh) &&
        counts_of(mesh).multi_border_faces > 0)
      s = sqrt3_border_refusal(options, global_step, 0);
    if (s.ok()) custom_subdivision_step(mesh, options.custom, global_step);
  } else {
    return Status::error(
        Status_code::invalid_argument,
        "unknown scheme \"" + scheme + "\"; known schemes: " + scheme_list());
  }
  collect_removed(mesh);
  return s;
}

namespace {

/// predict_size once the mesh's counts `c` (creasing included) are known;
/// `given_marks`: the control edges given with the mesh; `input`: the bytes
/// of its buffers, which the run holds beside its steps.
Result<Size_prediction> predict_counts(Counts c, double given_marks,
                                       double input,
                                       const Subdivide_options& options) {
  Result<Size_prediction> result;
  // Marks the primal schemes carry (before any triangulation).
  double marks = 0;
  if (scheme_keeps_control_edges(options))
    marks = given_marks > 0            ? given_marks
            : options.start_level == 0 ? c.edges
                                       : 0;
  c.control_edge_pairs = marks > 0 && given_marks > 0;
  if (needs_triangles(options) && c.non_triangles > 0) {
    if (!options.triangulate) {
      result.status = not_triangles(options.scheme, c);
      return result;
    }
    c = triangulated(c);
  }
  Run_prediction run;
  predict_run(options, c, input, marks, false, run);
  c = run.after;
  result.value.vertices = to_size(c.vertices);
  result.value.edges = to_size(c.edges);
  result.value.faces = to_size(c.faces);
  result.value.peak_bytes = to_size(run.peak_bytes);
  return result;
}

}  // namespace

Result<Size_prediction> predict_size(const Closed_mesh_counts& mesh,
                                     const Subdivide_options& options) {
  Result<Size_prediction> result;
  result.status = check_options(options);
  if (!result.status.ok()) return result;
  if (mesh.triangles > mesh.faces || mesh.faces == 0) {
    result.status = Status::error(Status_code::invalid_argument,
                                  "counts: more triangles than faces, or none");
    return result;
  }
  Counts c;
  c.vertices = static_cast<double>(mesh.vertices);
  c.edges = static_cast<double>(mesh.edges);
  c.faces = static_cast<double>(mesh.faces);
  c.non_triangles = static_cast<double>(mesh.faces - mesh.triangles);
  // Closed: every edge in two faces, so the degrees sum to 2E.
  c.degree_excess = 2 * c.edges - 3 * c.faces;
  if (needs_triangles(options) && options.triangulate && c.non_triangles > 0) {
    result.status = Status::error(
        Status_code::invalid_argument,
        "a mesh to triangulate first is predicted from its faces");
    return result;
  }
  // No tags: creasing only where the options ask for a border mode.
  refine::Creasing creasing;
  c.creased = creasing_of(Mesh_buffers{}, options, creasing);
  return predict_counts(c, static_cast<double>(mesh.control_edges),
                        buffers_bytes(c.vertices, c.faces, 2 * c.edges),
                        options);
}

Result<Size_prediction> predict_size(const Mesh_buffers& in,
                                     const Subdivide_options& options) {
  Result<Size_prediction> result;
  try {
    Counts c;
    {
      // The counts of the mesh build_mesh would build, from its tables.
      Status s = check_options(options);
      std::vector<std::uint32_t> corner_halfedges;
      if (s.ok()) s = detail::check_buffers(in, {}, &corner_halfedges).status;
      refine::Level level;
      if (s.ok()) {
        level = refine::level_from_buffers(in, corner_halfedges);
        // A mesh triangulated first is checked as the run checks it, once
        // triangulated (prepare): a diagonal can give a vertex of two
        // edges a third.
        if (!(needs_triangles(options) && options.triangulate &&
              counts_of(level).non_triangles > 0)) {
          s = check_two_valent_vertices(level, options);
        } else {
          Mesh mesh;
          Counts triangulated_counts;
          s = prepare(in, options, mesh, triangulated_counts);
        }
      }
      if (!s.ok()) {
        result.status = s;
        return result;
      }
      c = counts_of(level);
    }
    refine::Creasing creasing;
    c.creased = creasing_of(in, options, creasing);
    result = predict_counts(
        c, static_cast<double>(in.control_edges.size() / 2),
        buffers_bytes(static_cast<double>(in.vertex_count()),
                      static_cast<double>(in.face_count()),
                      static_cast<double>(in.face_indices.size())),
        options);
  } catch (const std::exception& e) {
    result.status = Status::error(Status_code::internal_error,
                                  std::string("internal error: ") + e.what());
  } catch (...) {
    result.status = Status::error(Status_code::internal_error,
                                  "internal error: unknown exception");
  }
  return result;
}

namespace {

/// subdivide_mesh; with `stencils`, also the last step's stencils (fast
/// hosts only: `stencils->error` says so otherwise).
Result<Mesh_buffers> run_subdivision(const Mesh_buffers& in,
                                     const Subdivide_options& options,
                                     Stencil_request* stencils) {
  Result<Mesh_buffers> result;
  int level = options.start_level;  // for messages
  try {
    const refine::Primal_mask_lookup fast =
        refine::primal_mask(options.scheme, options.custom);
    const double input =
        buffers_bytes(static_cast<double>(in.vertex_count()),
                      static_cast<double>(in.face_count()),
                      static_cast<double>(in.face_indices.size()));
    const refine::Dual_mask_lookup dual =
        refine::dual_mask(options.scheme, options.custom);
    const refine::Primal_mask_lookup sqrt3 =
        refine::sqrt3_mask(options.scheme, options.custom);
    const refine::Quad_triangle_mask_lookup pqt =
        refine::quad_triangle_mask(options.scheme, options.smooth_boundary);
    if ((fast.ok || dual.ok || sqrt3.ok || pqt.ok) &&
        runs_on_fast_host(options) && options.levels > 0) {
      refine::Level level0;
      Counts counts;
      double marks = 0;
      Status s = prepare_level(in, options, level0, counts, marks);
      refine::Creasing creasing;
      if (s.ok() && fast.ok && creasing_of(in, options, creasing)) {
        const bool triangulated = level0.face_count != in.face_count();
        const std::string why =
            refine::apply_tags(in, in.tags, creasing, triangulated, level0);
        if (!why.empty())
          s = Status::error(Status_code::invalid_argument,
                            "The mesh's tags do not fit it: " + why + ".");
        counts.creased = true;
      }
      // Refuse at once a run whose later level would not fit.
      Run_prediction run;
      if (s.ok()) s = predict_run(options, counts, input, marks, true, run);
      if (s.ok() && fast.ok)
        s = run_primal_steps(level0, counts, marks, fast.mask, creasing,
                             options, in, input, result.value, level, stencils);
      else if (s.ok() && sqrt3.ok)
        s = run_sqrt3_steps(level0, counts, sqrt3.mask, options, in, input,
                            result.value, level, stencils);
      else if (s.ok() && pqt.ok)
        s = run_pqt_steps(level0, counts, marks, pqt.mask, options, in, input,
                          result.value, level, stencils);
      else if (s.ok())
        s = run_dual_steps(level0, counts, dual.mask, options, in, input,
                           result.value, level, stencils);
      if (!s.ok()) result = Result<Mesh_buffers>{s, {}};
      return result;
    }
    if (stencils) {
      stencils->error =
          options.levels > 0
              ? "stencils come from the fast hosts, and CGAL's were asked for"
              : "stencils are of a step, and no step was asked for";
      return result;
    }
    Mesh mesh;
    Counts counts;
    Status s = prepare(in, options, mesh, counts);
    // Control edges (primal schemes): old vertices keep their indices.
    const bool track = s.ok() && scheme_keeps_control_edges(options);
    Control_edges control;
    if (track) {
      Result<Control_edges> ce =
          initial_control_edges(in, mesh, options.start_level);
      s = ce.status;
      control = std::move(ce.value);
    }
    // Refuse at once a run whose later level would not fit.
    Run_prediction run;
    if (s.ok())
      s = predict_run(options, counts, input,
                      static_cast<double>(control.size()), true, run);
    // The model follows the real mesh: its counts are re-read after every
    // step, the array capacities simulated (they are not observable).
    Caps caps = Caps::exact(counts);
    for (int i = 0; s.ok() && i < options.levels; ++i) {
      level = options.start_level + i + 1;
      const Step_need need = step_need(
          options, counts, caps, options.start_level + i, i == 0,
          i + 1 == options.levels, static_cast<double>(control.size()), input);
      s = check_step(options.scheme, need, options.start_level + i,
                     options.memory_limit_bytes);
      const auto old_end =
          static_cast<std::uint32_t>(mesh.number_of_vertices());
      if (s.ok()) s = run_step(mesh, options, i);
      if (s.ok()) s = check_finite_points(mesh, in, options.scheme, level);
      if (s.ok() && track)
        control = refine_control_edges(mesh, old_end, control);
      if (s.ok()) {
        counts = counts_of(mesh);
        caps = need.caps_after;
      }
    }
    if (!s.ok()) {
      result.status = s;
      return result;
    }
    result.value = to_buffers(mesh);
    if (track)
      result.value.control_edges = control_edges_to_buffers(mesh, control);
    if (options.levels == 0) result.value.tags = unchanged_mesh_tags(in, mesh);
  } catch (const CGAL::Failure_exception& e) {
    result.status =
        Status::error(Status_code::internal_error,
                      "CGAL failed at level " + std::to_string(level) + " of " +
                          options.scheme + ": " + e.what());
  } catch (const std::bad_alloc& e) {
    // The prediction should have refused the step; this is the last guard.
    result.status =
        Status::error(Status_code::too_large,
                      "out of memory at level " + std::to_string(level) +
                          " of " + options.scheme + " (" + e.what() + ")");
  } catch (const std::exception& e) {
    result.status =
        Status::error(Status_code::internal_error,
                      "internal error at level " + std::to_string(level) +
                          " of " + options.scheme + ": " + e.what());
  } catch (...) {
    result.status =
        Status::error(Status_code::internal_error,
                      "internal error at level " + std::to_string(level) +
                          " of " + options.scheme + ": unknown exception");
  }
  return result;
}

}  // namespace

Result<Mesh_buffers> subdivide_mesh(const Mesh_buffers& in,
                                    const Subdivide_options& options) {
  return run_subdivision(in, options, nullptr);
}

Result<Stencil_table> step_stencils(const Mesh_buffers& in,
                                    const Subdivide_options& options) {
  Stencil_request request;
  const Result<Mesh_buffers> run = run_subdivision(in, options, &request);
  if (!run.ok()) return {run.status, {}};
  if (!request.error.empty() || request.table.offsets.empty())
    return {Status::error(Status_code::invalid_argument,
                          "No stencils for " + options.scheme + ": " +
                              (request.error.empty() ? "no step was made"
                                                     : request.error) +
                              "."),
            {}};
  // The formula of each kind that occurs.
  std::vector<bool> seen(16, false);
  for (const Stencil_origin& o : request.table.origins) {
    const auto k = static_cast<std::size_t>(o.kind);
    if (seen[k]) continue;
    seen[k] = true;
    const std::string f = stencil_formula(
        options.scheme == "custom" ? "custom" : options.scheme, o.kind);
    if (!f.empty())
      request.table.formulas.push_back({stencil_kind_name(o.kind), f});
  }
  return {Status::success(), std::move(request.table)};
}

std::vector<std::string> scheme_names() {
  std::vector<std::string> names;
  for (const Scheme_info& s : scheme_table()) names.push_back(s.name);
  return names;
}

}  // namespace subdivlab
