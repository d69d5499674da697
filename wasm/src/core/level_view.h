// A level as a viewer takes it: the mesh, its facts and its render arrays,
// made in one call of the core so that the page does no pass over the
// mesh itself. Owner: level_view.cpp.
#pragma once

#include <string_view>

#include "mesh_facts.h"
#include "mesh_io.h"
#include "mesh_types.h"
#include "render_buffers.h"
#include "subdivide.h"

namespace subdivlab {

/// Facts (CGAL's, from a Surface_mesh: the load checks the mesh once
/// more) of a loaded mesh, and its render arrays handed to `sink`.
Result<Mesh_facts> view_mesh(const Mesh_buffers& mesh, Render_sink& sink);

/// read_mesh(text, format, options) into `out`, its facts (CGAL's, from
/// the Surface_mesh built from the reader's checked tables: one check, not
/// two) and its render arrays handed to `sink`.
Result<Mesh_facts> read_view(std::string_view text, Mesh_format format,
                             Mesh_buffers& out, Render_sink& sink,
                             const Read_options& options = {});

/// `subdivide_mesh(in, options)` into `out` (its memory check counting
/// the render arrays: Subdivide_options::render_buffers), its render arrays
/// handed to `sink`, and its facts: counted from the result and carried from
/// `parent` (the facts of `in`), CGAL's only if the counts disagree.
Result<Mesh_facts> view_step(const Mesh_buffers& in,
                             const Subdivide_options& options,
                             const Mesh_facts& parent, Mesh_buffers& out,
                             Render_sink& sink);

}  // namespace subdivlab
