// The one table of what the core knows of each scheme and host. The
// options' checks, the size model, the choice of hosts, the control edges,
// the bindings' schemeInfo() (and through it the CLI) read it.

#include "scheme_table.h"

#include "custom_rules.h"

namespace subdivlab {

const std::vector<Host_info>& host_table() {
  static const std::vector<Host_info> hosts = {
      {"pqq", false, true, true, "catmull-clark", "PQQ"},
      {"ptq", true, true, true, "loop", "PTQ"},
      {"dqq", false, false, true, "doo-sabin", "DQQ"},
      {"sqrt3", true, false, true, "sqrt3", "\u221a3"},
      {"pqt", false, true, true, "quad-triangle", "PQT"},
  };
  return hosts;
}

const std::vector<Scheme_info>& scheme_table() {
  static const std::vector<Scheme_info> schemes = {
      {"catmull-clark", "Catmull-Clark", "pqq",
       "Quad refinement (PQQ): every face splits into quads; smooth, "
       "approximating. Any polygons.",
       true},
      {"loop", "Loop", "ptq",
       "Triangle refinement (PTQ): each triangle splits into four; smooth, "
       "approximating. Needs triangles.",
       true},
      {"doo-sabin", "Doo-Sabin", "dqq",
       "Dual quad refinement (DQQ): new faces for every face, edge and "
       "vertex; cuts corners. Any polygons."},
      {"sqrt3", "\u221a3 (Kobbelt)", "sqrt3",
       "Each triangle gets a centre vertex, then old edges flip; triples "
       "faces per step. Needs triangles."},
      {"quad-triangle", "Quad/Triangle", "pqt",
       "Stam & Loop: triangles and quads refined together; after one step "
       "only triangles and quads."},
      {"linear", "Linear (PQQ)", "pqq",
       "Quad refinement with averaging only: centroids and midpoints, "
       "vertices stay. Any polygons."},
      {"linear-tri", "Linear (PTQ)", "ptq",
       "Midpoint split of triangles; the surface does not move. Needs "
       "triangles."},
      {"custom", "Custom rules", "",
       "Your own weights on a refinement host (PQQ, PTQ, DQQ or \u221a3): "
       "edit them in the Rules panel."},
  };
  return schemes;
}

namespace detail {

const Scheme_info* find_scheme(const std::string& name) {
  for (const Scheme_info& s : scheme_table())
    if (name == s.name) return &s;
  return nullptr;
}

const Host_info* find_host(const std::string& name) {
  for (const Host_info& h : host_table())
    if (name == h.name) return &h;
  return nullptr;
}

const Host_info* host_of(const Subdivide_options& o) {
  if (o.scheme == "custom") return find_host(o.custom.host);
  const Scheme_info* s = find_scheme(o.scheme);
  return s != nullptr ? find_host(s->host) : nullptr;
}

bool needs_triangles(const Subdivide_options& o) {
  const Host_info* h = host_of(o);
  return h != nullptr && h->needs_triangles;
}

std::string size_model(const Subdivide_options& o) {
  const Host_info* h = host_of(o);
  return h != nullptr ? h->size_model : o.scheme;
}

std::string scheme_list() {
  std::string s;
  for (const Scheme_info& e : scheme_table()) {
    if (!s.empty()) s += ", ";
    s += e.name;
  }
  return s;
}

bool sqrt3_refines_border(int global_step) { return global_step % 2 == 1; }

bool applies_creases(const Subdivide_options& o) {
  const Scheme_info* s = find_scheme(o.scheme);
  return s != nullptr && s->creases && runs_on_fast_host(o);
}

bool runs_on_fast_host(const Subdivide_options& o) {
  const Host_info* h = host_of(o);
  return !o.cgal_hosts && h != nullptr && h->fast;
}

}  // namespace detail
}  // namespace subdivlab
