// Facts and render arrays beside the mesh they describe.

#include "level_view.h"

#include <cstdint>
#include <utility>
#include <vector>

#include "mesh_build.h"

namespace subdivlab {

Result<Mesh_facts> view_mesh(const Mesh_buffers& mesh, Render_sink& sink) {
  Result<Mesh_facts> facts = compute_facts(mesh);
  if (facts.ok()) build_render_buffers(mesh, sink, facts.value.edges);
  return facts;
}

Result<Mesh_facts> read_view(std::string_view text, Mesh_format format,
                             Mesh_buffers& out, Render_sink& sink,
                             const Read_options& options) {
  Result<Mesh_facts> r;
  std::vector<std::uint32_t> corner_halfedges;
  Result<Mesh_buffers> read =
      read_mesh(text, format, &corner_halfedges, options);
  if (!read.ok()) {
    r.status = read.status;
    return r;
  }
  out = std::move(read.value);
  {
    Mesh mesh;
    build_checked_mesh(out, corner_halfedges, mesh);
    r.value = compute_facts(mesh);
  }
  r.value.control_edges = out.control_edges.size() / 2;
  build_render_buffers(out, sink, r.value.edges);
  return r;
}

Result<Mesh_facts> view_step(const Mesh_buffers& in,
                             const Subdivide_options& options,
                             const Mesh_facts& parent, Mesh_buffers& out,
                             Render_sink& sink) {
  Result<Mesh_facts> r;
  Subdivide_options viewed = options;
  viewed.render_buffers = true;
  Result<Mesh_buffers> step = subdivide_mesh(in, viewed);
  if (!step.ok()) {
    r.status = step.status;
    return r;
  }
  out = std::move(step.value);
  // Every scheme keeps the Euler characteristic: E = V + F - chi (in
  // double: the parent's may be any number).
  const double expected = static_cast<double>(out.vertex_count()) +
                          static_cast<double>(out.face_count()) -
                          static_cast<double>(parent.euler_characteristic);
  const std::size_t edges =
      build_render_buffers(out, sink,
                           expected > 0 && expected < 4294967296.0
                               ? static_cast<std::size_t>(expected)
                               : 0);
  if (!refined_facts(out, edges, parent, r.value)) r = compute_facts(out);
  return r;
}

}  // namespace subdivlab
