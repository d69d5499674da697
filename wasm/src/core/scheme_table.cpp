#include "scheme_table.h"

#include "custom_rules.h"

namespace subdivlab::detail {

const std::vector<Scheme_entry>& scheme_table() {
  static const std::vector<Scheme_entry> table = {
      {"catmull-clark", false},
      {"loop", true},
      {"doo-sabin", false},
      {"sqrt3", true},
      // Issue 4. custom's needs depend on its host (needs_triangles below).
      {"quad-triangle", false},
      {"linear", false},
      {"linear-tri", true},
      {"custom", false},
  };
  return table;
}

const Scheme_entry* find_scheme(const std::string& name) {
  for (const Scheme_entry& s : scheme_table())
    if (name == s.name) return &s;
  return nullptr;
}

/// Whether the scheme of `o` needs a triangle mesh.
bool needs_triangles(const Subdivide_options& o) {
  if (o.scheme == "custom") return custom_rules_need_triangles(o.custom);
  const Scheme_entry* e = find_scheme(o.scheme);
  return e != nullptr && e->needs_triangles;
}

/// The scheme whose counts and memory model a step of `o` follows: linear
/// refines as catmull-clark, linear-tri as loop, custom as its host's scheme.
std::string size_model(const Subdivide_options& o) {
  if (o.scheme == "linear") return "catmull-clark";
  if (o.scheme == "linear-tri") return "loop";
  if (o.scheme == "custom") {
    const std::string& h = o.custom.host;
    return h == "pqq"   ? "catmull-clark"
           : h == "ptq" ? "loop"
           : h == "dqq" ? "doo-sabin"
                        : "sqrt3";
  }
  return o.scheme;
}

std::string scheme_list() {
  std::string s;
  for (const Scheme_entry& e : scheme_table()) {
    if (!s.empty()) s += ", ";
    s += e.name;
  }
  return s;
}

/// True when step `global_step` (0-based, counted from the control mesh) of
/// sqrt3 refines the border: CGAL's Sqrt3 does it on the odd steps of one
/// call (i % 2 == 1); counting from the control mesh makes k calls of one
/// level equal one call of k levels.
bool sqrt3_refines_border(int global_step) { return global_step % 2 == 1; }

/// Whether the scheme of `o` runs on the fast primal hosts (refine/): those
/// whose size model is catmull-clark (PQQ) or loop (PTQ), unless CGAL's
/// hosts are asked for.
bool runs_on_fast_host(const Subdivide_options& o) {
  const std::string model = size_model(o);
  return !o.cgal_hosts && (model == "catmull-clark" || model == "loop");
}

}  // namespace subdivlab::detail
