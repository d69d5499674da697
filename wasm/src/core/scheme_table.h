// Look-ups in the scheme and host tables (subdivide.h: host_table,
// scheme_table). Internal to the core. Owner: scheme_table.cpp.
#pragma once

#include <string>

#include "subdivide.h"

namespace subdivlab::detail {

const Scheme_info* find_scheme(const std::string& name);
const Host_info* find_host(const std::string& name);

/// The host a step of `o` runs on: the scheme's, or custom's rule set's;
/// nullptr for an unknown scheme or host.
const Host_info* host_of(const Subdivide_options& o);

/// Whether the scheme of `o` needs a triangle mesh.
bool needs_triangles(const Subdivide_options& o);

/// The scheme whose counts and memory model a step of `o` follows (its
/// host's: linear refines as catmull-clark, custom as its host's scheme).
std::string size_model(const Subdivide_options& o);

/// "catmull-clark, loop, ..." for messages.
std::string scheme_list();

/// True when step `global_step` (0-based, counted from the control mesh) of
/// sqrt3 refines the border: CGAL's Sqrt3 does it on the odd steps of one
/// call (i % 2 == 1); counting from the control mesh makes k calls of one
/// level equal one call of k levels.
bool sqrt3_refines_border(int global_step);

/// Whether the scheme of `o` runs on the fast primal hosts (refine/), as
/// its host does unless CGAL's hosts are asked for.
bool runs_on_fast_host(const Subdivide_options& o);

/// Whether a step of `o` applies a mesh's tags (Scheme_info::creases; on
/// the fast hosts only: CGAL's have no creasing).
bool applies_creases(const Subdivide_options& o);

}  // namespace subdivlab::detail
