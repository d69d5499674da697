// The fast hosts' driver (fast_driver.h).

#include "fast_driver.h"

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "control_edges.h"
#include "custom_rules.h"
#include "mesh_check.h"
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
#include "subdivide_prepare.h"

namespace subdivlab::detail {
namespace {

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

bool runs_fast(const Subdivide_options& options) {
  return (refine::primal_mask(options.scheme, options.custom).ok ||
          refine::dual_mask(options.scheme, options.custom).ok ||
          refine::sqrt3_mask(options.scheme, options.custom).ok ||
          refine::quad_triangle_mask(options.scheme, options.smooth_boundary)
              .ok) &&
         runs_on_fast_host(options) && options.levels > 0;
}

Status run_fast_hosts(const Mesh_buffers& in, const Subdivide_options& options,
                      double input, Mesh_buffers& out, int& level,
                      Stencil_request* stencils) {
  const refine::Primal_mask_lookup fast =
      refine::primal_mask(options.scheme, options.custom);
  const refine::Dual_mask_lookup dual =
      refine::dual_mask(options.scheme, options.custom);
  const refine::Primal_mask_lookup sqrt3 =
      refine::sqrt3_mask(options.scheme, options.custom);
  const refine::Quad_triangle_mask_lookup pqt =
      refine::quad_triangle_mask(options.scheme, options.smooth_boundary);
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
    s = run_primal_steps(level0, counts, marks, fast.mask, creasing, options,
                         in, input, out, level, stencils);
  else if (s.ok() && sqrt3.ok)
    s = run_sqrt3_steps(level0, counts, sqrt3.mask, options, in, input, out,
                        level, stencils);
  else if (s.ok() && pqt.ok)
    s = run_pqt_steps(level0, counts, marks, pqt.mask, options, in, input, out,
                      level, stencils);
  else if (s.ok())
    s = run_dual_steps(level0, counts, dual.mask, options, in, input, out,
                       level, stencils);
  return s;
}

}  // namespace subdivlab::detail
