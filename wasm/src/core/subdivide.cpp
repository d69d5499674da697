// Subdividing a mesh: the options checked, the run's size predicted
// (size_model.h) and refused at once when a later level would not fit, then
// the steps on one of two routes, each step preceded by a size check:
//   fast_driver.h: the fast hosts (refine/) of the PQQ, PTQ, DQQ, sqrt3 and
//     PQT (quad-triangle) schemes and custom rules on them
//     (scheme_table.h);
//   cgal_driver.h: CGAL's hosts (Subdivision_method_3 and this project's
//     hosts in its style), the reference the fast hosts are tested
//     against, with option cgal_hosts.
// What both check first is in subdivide_prepare.h. Here: the dispatch, the
// size predictions and the stencils of a step.

#include "subdivide.h"

#include <CGAL/exceptions.h>

#include <exception>
#include <new>
#include <string>
#include <utility>
#include <vector>

#include "cgal_driver.h"
#include "control_edges.h"
#include "fast_driver.h"
#include "mesh_check.h"
#include "refine/crease.h"
#include "refine/level_convert.h"
#include "scheme_table.h"
#include "size_model.h"
#include "stencils.h"
#include "subdivide_prepare.h"

namespace subdivlab {

using namespace detail;

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
    const double input =
        buffers_bytes(static_cast<double>(in.vertex_count()),
                      static_cast<double>(in.face_count()),
                      static_cast<double>(in.face_indices.size()));
    Status s;
    if (runs_fast(options)) {
      s = run_fast_hosts(in, options, input, result.value, level, stencils);
    } else if (stencils) {
      stencils->error =
          options.levels > 0
              ? "stencils come from the fast hosts, and CGAL's were asked for"
              : "stencils are of a step, and no step was asked for";
      return result;
    } else {
      s = run_cgal_hosts(in, options, input, result.value, level);
    }
    if (!s.ok()) result = Result<Mesh_buffers>{s, {}};
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
