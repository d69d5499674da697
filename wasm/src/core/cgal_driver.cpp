// CGAL's hosts' driver (cgal_driver.h).

#include "cgal_driver.h"

#include <CGAL/Subdivision_method_3/subdivision_hosts_3.h>
#include <CGAL/Subdivision_method_3/subdivision_masks_3.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/subdivision_method_3.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

#include "control_edges.h"
#include "custom_rules.h"
#include "dqq_border_3.h"
#include "linear_masks_3.h"
#include "mesh_build.h"
#include "mesh_check.h"
#include "quad_triangle_3.h"
#include "scheme_table.h"
#include "size_model.h"
#include "subdivide_prepare.h"

namespace subdivlab::detail {
namespace {

namespace SM3 = CGAL::Subdivision_method_3;

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

Status check_finite_points(const Mesh& mesh, const Mesh_buffers& in,
                           const std::string& scheme, int level) {
  for (Mesh::Vertex_index v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      return overflow(in, scheme, level);
  }
  return Status::success();
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

}  // namespace

Status run_cgal_hosts(const Mesh_buffers& in, const Subdivide_options& options,
                      double input, Mesh_buffers& out, int& level) {
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
    s = predict_run(options, counts, input, static_cast<double>(control.size()),
                    true, run);
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
    const auto old_end = static_cast<std::uint32_t>(mesh.number_of_vertices());
    if (s.ok()) s = run_step(mesh, options, i);
    if (s.ok()) s = check_finite_points(mesh, in, options.scheme, level);
    if (s.ok() && track) control = refine_control_edges(mesh, old_end, control);
    if (s.ok()) {
      counts = counts_of(mesh);
      caps = need.caps_after;
    }
  }
  if (!s.ok()) return s;
  out = to_buffers(mesh);
  if (track) out.control_edges = control_edges_to_buffers(mesh, control);
  if (options.levels == 0) out.tags = unchanged_mesh_tags(in, mesh);
  return Status::success();
}

}  // namespace subdivlab::detail
