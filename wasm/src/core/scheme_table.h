// What the core knows of each scheme: its name, whether it needs triangles,
// whose counts and memory model it follows, and which hosts run it.
// Internal to the core. Owner: scheme_table.cpp.
#pragma once

#include <string>
#include <vector>

#include "subdivide.h"

namespace subdivlab::detail {

struct Scheme_entry {
  const char* name;
  bool needs_triangles;
};

/// The schemes, in display order.
const std::vector<Scheme_entry>& scheme_table();
const Scheme_entry* find_scheme(const std::string& name);

/// Whether the scheme of `o` needs a triangle mesh.
bool needs_triangles(const Subdivide_options& o);

/// The scheme whose counts and memory model a step of `o` follows: linear
/// refines as catmull-clark, linear-tri as loop, custom as its host's scheme.
std::string size_model(const Subdivide_options& o);

/// "catmull-clark, loop, ..." for messages.
std::string scheme_list();

/// True when step `global_step` (0-based, counted from the control mesh) of
/// sqrt3 refines the border.
bool sqrt3_refines_border(int global_step);

/// Whether the scheme of `o` runs on the fast primal hosts (refine/).
bool runs_on_fast_host(const Subdivide_options& o);

}  // namespace subdivlab::detail
