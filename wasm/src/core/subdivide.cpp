// The subdivision schemes: options checked, mesh built, then one CGAL step
// at a time, each preceded by a size check, then back to buffers.
//
// Schemes run through CGAL's Subdivision_method_3: Catmull-Clark (PQQ host),
// Loop (PTQ), Doo-Sabin (DQQ; on open meshes the border-aware DQQ host of
// dqq_border_3.h, as CGAL's has no border support) and sqrt(3) (its host
// refines the border on every second step; the step parity is carried
// through Subdivide_options::start_level).

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
#include "refine/level_convert.h"
#include "refine/primal_hosts.h"
#include "refine/primal_masks.h"
#include "refine/primal_points.h"

namespace subdivlab {
namespace {

namespace SM3 = CGAL::Subdivision_method_3;

/// The schemes, in display order, and whether they need triangles.
struct Scheme_entry {
  const char* name;
  bool needs_triangles;
};

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

// ---------------------------------------------------------------------------
// Counts. Everything a step's result size depends on, kept in doubles so that
// predictions far beyond 2^32 (and beyond size_t under wasm32) stay finite
// and comparable.

struct Counts {
  double vertices = 0, edges = 0, faces = 0;
  double border_edges = 0;   ///< = border vertices (vertices are manifold)
  double border_ears = 0;    ///< border vertices of degree 2
  double border_fans = 0;    ///< border vertices of degree >= 4
  double non_triangles = 0;  ///< faces of degree != 3
  double degree_excess = 0;  ///< sum over faces of (degree - 3)
  /// Faces with two or more border edges (sqrt3's border step needs none).
  double multi_border_faces = 0;

  double degree_sum() const { return 2 * edges - border_edges; }
};

Counts counts_of(const Mesh& mesh) {
  Counts c;
  c.vertices = static_cast<double>(mesh.number_of_vertices());
  c.edges = static_cast<double>(mesh.number_of_edges());
  c.faces = static_cast<double>(mesh.number_of_faces());
  for (Mesh::Halfedge_index h : mesh.halfedges()) {
    if (!mesh.is_border(h)) continue;
    c.border_edges += 1;
    const auto d = mesh.degree(mesh.target(h));
    if (d == 2) c.border_ears += 1;
    if (d >= 4) c.border_fans += 1;
  }
  for (Mesh::Face_index f : mesh.faces()) {
    std::size_t degree = 0, border = 0;
    for (Mesh::Halfedge_index h :
         CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      ++degree;
      if (mesh.is_border(mesh.opposite(h))) ++border;
    }
    if (degree != 3) c.non_triangles += 1;
    c.degree_excess += static_cast<double>(degree) - 3;
    if (border >= 2) c.multi_border_faces += 1;
  }
  return c;
}

/// Counts after Polygon_mesh_processing::triangulate_faces: an n-gon becomes
/// n - 2 triangles joined by n - 3 new edges; vertices and border unchanged.
Counts triangulated(Counts c) {
  c.edges += c.degree_excess;
  c.faces += c.degree_excess;
  c.non_triangles = 0;
  c.degree_excess = 0;
  return c;  // border degrees and multi-border faces: not needed by loop/sqrt3
}

/// True when step `global_step` (0-based, counted from the control mesh) of
/// sqrt3 refines the border: CGAL's Sqrt3 does it on the odd steps of one
/// call (i % 2 == 1); counting from the control mesh makes k calls of one
/// level equal one call of k levels.
bool sqrt3_refines_border(int global_step) { return global_step % 2 == 1; }

/// Exact counts after one step. B border edges, S = sum of face degrees.
Counts next_counts(const std::string& scheme, const Counts& c,
                   int global_step) {
  Counts n;
  const double V = c.vertices, E = c.edges, F = c.faces, B = c.border_edges;
  if (scheme == "catmull-clark") {
    // Vertex, edge and face points; each corner becomes a quad.
    n.vertices = V + E + F;
    n.edges = 2 * E + c.degree_sum();
    n.faces = c.degree_sum();
    n.border_edges = 2 * B;
    n.border_ears = c.border_ears;  // old border vertices keep their degree,
    n.border_fans = c.border_fans;  // border edge points have degree 3
  } else if (scheme == "loop") {
    n.vertices = V + E;
    n.edges = 2 * E + 3 * F;
    n.faces = 4 * F;
    n.border_edges = 2 * B;
    n.border_ears = c.border_ears;
    n.border_fans = c.border_fans + B;  // border edge points have degree 4
  } else if (scheme == "doo-sabin") {
    // See dqq_border_3.h for the border construction.
    n.vertices = c.degree_sum() + c.border_ears;
    n.edges = 4 * E - 3 * B + c.border_ears + c.border_fans;
    n.faces = F + (E - B) + (V - B) + c.border_fans;
    n.border_edges = 2 * B;
    n.border_ears = 2 * c.border_ears;
    n.border_fans = 2 * c.border_fans;
    n.non_triangles = n.faces;  // not exact, unused by doo-sabin
  } else if (scheme == "quad-triangle") {
    // quad_triangle_3.h: edge points, a face point per non-triangle; a
    // triangle gives 4 triangles, a k-gon k quads.
    const double T = F - c.non_triangles, S = c.degree_sum() - 3 * T;
    n.vertices = V + E + c.non_triangles;
    n.edges = 2 * E + 3 * T + S;
    n.faces = 4 * T + S;
    n.border_edges = 2 * B;
    n.border_ears = c.border_ears;
    n.border_fans = c.border_fans;
    n.non_triangles = S;
    n.degree_excess = S;
  } else if (scheme == "sqrt3") {
    // A face point per face, old edges flipped: F' = 3F. On a border step
    // each border edge also gets two points and its face splits into 3.
    const double b = sqrt3_refines_border(global_step) ? B : 0;
    n.vertices = V + F + b;
    n.edges = E + 3 * F + b;
    n.faces = 3 * F;
    n.border_edges = B + 2 * b;
  }
  if (scheme == "catmull-clark") {
    n.non_triangles = n.faces;
    n.degree_excess = n.faces;  // all quads
  }
  return n;
}

// ---------------------------------------------------------------------------
// Memory model. A step's peak is simulated from the allocations its host
// makes, in the order it makes them; the figures were checked against a
// counting operator new (tests/core/test_subdivide.cpp, SubdivideMemory,
// which asserts measured <= model <= 1.5 x measured on every host).
//
// Bytes per element of a CGAL::Surface_mesh<Point_3> with double
// coordinates (indices are 32-bit on every target):
//   vertex   4 (halfedge) + 24 (point) + 1/8 (removed flag)
//   halfedge 16 (face, vertex, next, prev)
//   edge     1/8 (removed flag)
//   face     4 (halfedge) + 1/8 (removed flag)
// The mesh arrays are std::vectors: the model tracks their capacities, which
// CGAL's hosts set with reserve() -- more than they keep: PQQ reserves 8E
// edges for 2E + S, sqrt3 about twice its edges, PTQ too few faces (the face
// arrays then double) -- and which persist into the next step (nothing
// shrinks them but collect_garbage, run only when a host left removed
// elements: CGAL's DQQ). Reallocating an array holds old and new blocks
// together. Host temporaries: the descriptor backups (4 bytes per element),
// point buffers (24 per point), PQQ/PTQ's std::unordered_map of vertices
// (40 per vertex: a 32-byte node as malloc hands it out + an 8-byte bucket)
// and sqrt3's std::list of new positions (64 per entry). Sizes are native
// 64-bit ones, which bound wasm32's (its list/map nodes hold 4-byte
// pointers). The input buffers live through the whole call and are added.

constexpr double kVertexBytes = 28.125, kHalfedgeBytes = 16, kEdgeBytes = 0.125,
                 kFaceBytes = 4.125;
constexpr double kMapEntryBytes = 40, kListNodeBytes = 64;
constexpr double kPointBytes = 24, kDescriptorBytes = 4;
/// Allocator slack and small fixed allocations. Under WebAssembly,
/// dlmalloc's high-water mark (mallinfo().arena) exceeded the native live
/// bytes by up to 9.5% (sqrt3, whose std::list nodes sit between the mesh
/// arrays; 0-4% for the other hosts), measured on 10k-1M-face meshes at
/// 1-5 levels; natively the model is then 1.15-1.3x the measured peak.
constexpr double kSlackFactor = 1.15, kSlackBytes = 64 * 1024;

/// Element capacities of the mesh arrays (halfedges counted separately).
struct Caps {
  double v = 0, h = 0, e = 0, f = 0;
  static Caps exact(const Counts& c) {
    return {c.vertices, 2 * c.edges, c.edges, c.faces};
  }
};

double caps_bytes(const Caps& c) {
  return c.v * kVertexBytes + c.h * kHalfedgeBytes + c.e * kEdgeBytes +
         c.f * kFaceBytes;
}

/// Live and peak bytes of a simulated heap, with the mesh arrays in it.
class Heap_model {
 public:
  Heap_model(double live, const Caps& caps)
      : live_(live), peak_(live), caps_(caps) {}
  void alloc(double bytes) {
    live_ += bytes;
    peak_ = std::max(peak_, live_);
  }
  void release(double bytes) { live_ -= bytes; }
  /// Surface_mesh::reserve(nv, ne, nf): each array reallocated if smaller.
  void reserve(double nv, double ne, double nf) {
    reserve_one(caps_.v, nv, kVertexBytes);
    reserve_one(caps_.h, 2 * ne, kHalfedgeBytes);
    reserve_one(caps_.e, ne, kEdgeBytes);
    reserve_one(caps_.f, nf, kFaceBytes);
  }
  /// Elements added one by one up to these slot counts: arrays double.
  void fill(double nv, double ne, double nf) {
    grow(caps_.v, nv, kVertexBytes);
    grow(caps_.h, 2 * ne, kHalfedgeBytes);
    grow(caps_.e, ne, kEdgeBytes);
    grow(caps_.f, nf, kFaceBytes);
  }
  /// Surface_mesh::collect_garbage: three index maps at capacity, then the
  /// arrays shrunk to `n` (a copy each).
  void collect_garbage(const Counts& n) {
    const double maps = 4 * (caps_.v + caps_.h + caps_.f);
    alloc(maps);
    release(maps);
    const Caps exact = Caps::exact(n);
    shrink(caps_.v, exact.v, kVertexBytes);
    shrink(caps_.h, exact.h, kHalfedgeBytes);
    shrink(caps_.e, exact.e, kEdgeBytes);
    shrink(caps_.f, exact.f, kFaceBytes);
  }
  /// Frees the mesh arrays (Surface_mesh::clear...).
  void clear_mesh() {
    release(caps_bytes(caps_));
    caps_ = Caps{};
  }
  double peak() const { return peak_; }
  const Caps& caps() const { return caps_; }

 private:
  void reserve_one(double& cap, double n, double bytes) {
    if (n <= cap) return;
    alloc(n * bytes);
    release(cap * bytes);
    cap = n;
  }
  void grow(double& cap, double n, double bytes) {
    while (cap < n) reserve_one(cap, std::max(2 * cap, 1.0), bytes);
  }
  void shrink(double& cap, double n, double bytes) {
    alloc(n * bytes);
    release(cap * bytes);
    cap = n;
  }
  double live_, peak_;
  Caps caps_;
};

/// Simulates one step from counts `c` (mesh arrays at `caps`) to `n`, on top
/// of `base` bytes; returns the peak and leaves the caps after the step.
double simulate_step(const std::string& scheme, const Counts& c,
                     const Counts& n, Caps& caps, double base,
                     int global_step) {
  const double V = c.vertices, E = c.edges, F = c.faces, B = c.border_edges;
  Heap_model heap(base + caps_bytes(caps), caps);
  const double backups = kDescriptorBytes * (V + E + F);  // p_vertices ...
  double temps = backups;
  heap.alloc(backups);
  if (scheme == "catmull-clark") {
    // PQQ_1step: reserve(V+E+F, 8E, 2E), a point buffer, a vertex map.
    heap.reserve(V + E + F, 8 * E, 2 * E);
    const double more = kPointBytes * (V + E + F) + kMapEntryBytes * V;
    heap.alloc(more);
    temps += more;
    heap.fill(n.vertices, n.edges, n.faces);
  } else if (scheme == "loop") {
    // PTQ_1step: reserve(V+E, 4E, 2E) for 4F faces.
    heap.reserve(V + E, 4 * E, 2 * E);
    const double more = kPointBytes * (V + E) + kMapEntryBytes * V;
    heap.alloc(more);
    temps += more;
    heap.fill(n.vertices, n.edges, n.faces);
  } else if (scheme == "sqrt3") {
    // Sqrt3_1step: P new points, reserve(V+P, 2(E+2F+P), 3F), a halfedge per
    // face, a list of new positions (interior vertices + border faces).
    const double P = n.vertices - V;
    const double border_step = sqrt3_refines_border(global_step) ? B : 0;
    heap.alloc(kPointBytes * P);
    temps += kPointBytes * P;
    heap.reserve(V + P, 2 * (E + 2 * F + P), 3 * F);
    const double more =
        kDescriptorBytes * F + kListNodeBytes * (V + border_step);
    heap.alloc(more);
    temps += more;
    heap.fill(n.vertices, n.edges, n.faces);
  } else if (scheme == "quad-triangle") {
    // PQT_1step (quad_triangle_3.h): edge and face points, an exact reserve,
    // then a point and a descriptor per refined vertex for the averaging.
    const double points = kPointBytes * (E + F);
    heap.alloc(points);
    temps += points;
    heap.reserve(n.vertices, n.edges, n.faces);
    const double averaging = (kPointBytes + kDescriptorBytes) * n.vertices;
    heap.alloc(averaging);
    temps += averaging;
  } else if (scheme == "doo-sabin" && B > 0) {
    // DQQ_border_1step: two halfedge tables, the new points and faces as
    // flat arrays; the old mesh freed; the new one reserved exactly.
    const double tables = 2 * 4 * caps.h;
    const double arrays =
        kPointBytes * n.vertices + 4 * n.faces +
        4 * (c.degree_sum() + c.border_ears + 4 * (E - B) + 2 * E);
    heap.alloc(tables + arrays);
    heap.release(tables);
    heap.clear_mesh();
    heap.reserve(n.vertices, n.edges, n.faces);
    temps += arrays;
  } else if (scheme == "doo-sabin") {
    // CGAL's DQQ_1step: 2E corner points, reserve(V+E+F, 2E, 8E); old and
    // new elements coexist (V + 2E vertices, 6E edges, F + 3E faces in
    // slots) until the old ones are removed; then collect_garbage.
    heap.alloc(kPointBytes * 2 * E);
    temps += kPointBytes * 2 * E;
    heap.reserve(V + E + F, 2 * E, 8 * E);
    heap.fill(V + 2 * E, 6 * E + 1, F + 3 * E);
    heap.release(temps);
    temps = 0;
    heap.collect_garbage(n);
  }
  heap.release(temps);
  caps = heap.caps();
  return heap.peak();
}

/// Control edges (control_edges.h) alive around a step with `marks` marked
/// edges: the marks (8 bytes a pair), their children (twice as many) and,
/// after the last step, the output pairs.
double control_edge_bytes(double marks) { return 8 * 3 * marks; }

double buffers_bytes(double vertices, double faces, double corners) {
  return vertices * 3 * 8 + faces * 4 + corners * 4;
}

/// to_buffers on a mesh at `caps`: a vertex numbering, positions and face
/// sizes reserved exactly, face indices reserved at H/2 + F then doubling.
double to_buffers_peak(const Counts& n, const Caps& caps, double base) {
  const double corners = n.degree_sum();
  double indices = n.edges + n.faces;
  while (indices < corners) indices *= 2;
  return base + caps_bytes(caps) + 4 * caps.v +
         buffers_bytes(n.vertices, n.faces, 0) + 4 * (indices + indices / 2);
}

/// The fast primal hosts (refine/): the schemes whose size model is
/// catmull-clark (PQQ) or loop (PTQ) run there. Their peak: the parent and
/// child levels' tables and the step's per-vertex sums; on the first step
/// the Surface_mesh the level came from (freed before the step); after the
/// last, the child level with the output's face sizes and control edges
/// (positions and face vertices move out). The child of the last step has
/// only its face vertices, and its halfedge targets when edges are marked.
bool runs_on_fast_host(const Subdivide_options& o) {
  const std::string model = size_model(o);
  return !o.cgal_hosts && (model == "catmull-clark" || model == "loop");
}

double fast_step_peak(const std::string& scheme, const Counts& c,
                      const Counts& n, const Caps& caps, bool first, bool last,
                      double marks, double base) {
  const bool marked = marks > 0;
  const double parent =
      refine::level_bytes(c.vertices, c.edges, c.degree_sum(), marked, false) +
      (first ? 4 * (c.faces + 1) : 0);
  const double child =
      refine::level_bytes(n.vertices, n.edges, n.degree_sum(), marked, last);
  double peak = base + parent + child +
                refine::primal_scratch_bytes(
                    c.vertices, scheme == "catmull-clark", c.border_edges > 0);
  // Level 0 comes from the buffers (check_buffers' temporaries: 32 bytes
  // a corner, 8 a vertex, 4 a face; then the level beside the corners'
  // halfedges and a vertex numbering) or, when it had to be triangulated,
  // from CGAL's mesh (beside it). Control edges given as pairs are found
  // through the halfedges around each vertex and held as pairs (8 bytes,
  // as initial_control_edges grew them) until marked; the output's pairs
  // come after the last step.
  if (first) {
    const double S = c.degree_sum(), V = c.vertices;
    const double from_buffers =
        std::max(32 * S + 8 * V + 4 * c.faces, 4 * S + 4 * V + parent);
    const double from_mesh = caps_bytes(caps) + parent;
    const double finding = marks > 0 ? 8 * V + 8 * c.edges : 0;
    peak = std::max(peak, base + std::max(from_buffers, from_mesh) + finding +
                              control_edge_bytes(marks));
  }
  if (last) peak = std::max(peak, base + child + 4 * n.faces + 8 * 2 * marks);
  return peak;
}

// ---------------------------------------------------------------------------
// Messages.

std::string format_bytes(double bytes) {
  char buf[64];
  const double gb = 1024.0 * 1024.0 * 1024.0, mb = 1024.0 * 1024.0;
  if (bytes >= gb)
    std::snprintf(buf, sizeof buf, "%.1f GB", bytes / gb);
  else if (bytes >= 100 * mb)
    std::snprintf(buf, sizeof buf, "%.0f MB", bytes / mb);
  else if (bytes >= mb)
    std::snprintf(buf, sizeof buf, "%.1f MB", bytes / mb);
  else
    std::snprintf(buf, sizeof buf, "%.0f kB", std::ceil(bytes / 1024.0));
  return buf;
}

std::string format_count(double n) {
  char buf[64];
  if (n >= 1e9)
    std::snprintf(buf, sizeof buf, "%.3g G", n / 1e9);
  else if (n >= 1e6)
    std::snprintf(buf, sizeof buf, "%.3g M", n / 1e6);
  else
    std::snprintf(buf, sizeof buf, "%.0f", n);
  return buf;
}

/// Surface_mesh numbers halfedges with 32-bit indices.
constexpr double kMaxHalfedges = 4294967294.0;

std::uint64_t to_size(double x) {
  if (!(x < static_cast<double>(std::numeric_limits<std::uint64_t>::max())))
    return std::numeric_limits<std::uint64_t>::max();
  return static_cast<std::uint64_t>(x);
}

/// Memory one step needs, everything included.
struct Step_need {
  Counts after;
  Caps caps_after;
  double peak_bytes = 0;
};

/// The step from `c` (mesh arrays at `caps`) with the input buffers
/// (`input_bytes`) and `marks` control edges alive; `first` is the first
/// step of the call, `last` its last (which adds the output buffers).
Step_need step_need(const Subdivide_options& options, const Counts& c,
                    const Caps& caps, int global_step, bool first, bool last,
                    double marks, double input_bytes) {
  const std::string scheme = size_model(options);
  Step_need need;
  need.after = next_counts(scheme, c, global_step);
  need.caps_after = caps;
  if (runs_on_fast_host(options)) {
    need.peak_bytes = fast_step_peak(scheme, c, need.after, caps, first, last,
                                     marks, input_bytes) *
                          kSlackFactor +
                      kSlackBytes;
    return need;
  }
  input_bytes += control_edge_bytes(marks);
  double peak = simulate_step(scheme, c, need.after, need.caps_after,
                              input_bytes, global_step);
  if (last)
    peak = std::max(peak,
                    to_buffers_peak(need.after, need.caps_after, input_bytes));
  need.peak_bytes = peak * kSlackFactor + kSlackBytes;
  return need;
}

Status too_large(const std::string& scheme, int level, const Step_need& need,
                 double limit, const char* why) {
  std::string m = "level " + std::to_string(level) + " of " + scheme +
                  " would need about " + format_bytes(need.peak_bytes) +
                  " (predicted " + format_count(need.after.vertices) +
                  " vertices, " + format_count(need.after.faces) + " faces), ";
  if (why != nullptr)
    m += why;
  else
    m += "more than the " + format_bytes(limit) + " available";
  return Status::error(Status_code::too_large, m);
}

/// Fails with too_large when the step would not fit.
Status check_step(const std::string& scheme, const Step_need& need,
                  int global_step, std::size_t limit) {
  if (2 * need.after.edges > kMaxHalfedges)
    return too_large(scheme, global_step + 1, need, 0,
                     "more elements than a mesh can index (2^32)");
  if (limit != 0 && need.peak_bytes > static_cast<double>(limit))
    return too_large(scheme, global_step + 1, need, static_cast<double>(limit),
                     nullptr);
  return Status::success();
}

/// Counts after the last step of a run and its largest peak, predicted from
/// the counts `c` of the mesh the run starts from.
struct Run_prediction {
  Counts after;
  double peak_bytes = 0;
};

/// Predicts every step of a run. With `refuse`, the first step that would not
/// fit (options.memory_limit_bytes, or 2^32 halfedges) ends it with too_large,
/// so a run is refused before its first step, not after the levels that fit.
Status predict_run(const Subdivide_options& options, Counts c, double input,
                   double marks, bool refuse, Run_prediction& out) {
  Caps caps = Caps::exact(c);
  double peak = to_buffers_peak(c, caps, input) * kSlackFactor + kSlackBytes;
  for (int i = 0; i < options.levels; ++i) {
    const int global_step = options.start_level + i;
    const Step_need need = step_need(options, c, caps, global_step, i == 0,
                                     i + 1 == options.levels, marks, input);
    if (refuse) {
      const Status s = check_step(options.scheme, need, global_step,
                                  options.memory_limit_bytes);
      if (!s.ok()) return s;
    }
    marks *= 2;
    peak = std::max(peak, need.peak_bytes);
    c = need.after;
    caps = need.caps_after;
    if (!(c.faces < 1e300)) break;  // hopeless anyway; keep it finite
  }
  out.after = c;
  out.peak_bytes = peak;
  return Status::success();
}

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
/// it is no polygon mesh (it cannot be read back). PQQ handles it.
Status check_two_valent_vertices(const Mesh& mesh,
                                 const Subdivide_options& options) {
  const std::string model = size_model(options);
  // quad-triangle splits triangles as PTQ does, quads as PQQ: only a vertex
  // between two triangles repeats an edge.
  const bool two_triangles_only = options.scheme == "quad-triangle";
  if (model != "loop" && model != "sqrt3" && model != "doo-sabin" &&
      !two_triangles_only)
    return Status::success();
  for (Mesh::Vertex_index v : mesh.vertices()) {
    if (mesh.degree(v) != 2 || mesh.is_border(v)) continue;
    if (two_triangles_only) {
      const Mesh::Halfedge_index h = mesh.halfedge(v);
      if (mesh.degree(mesh.face(h)) != 3 ||
          mesh.degree(mesh.face(mesh.opposite(mesh.next(h)))) != 3)
        continue;
    }
    return Status::error(
        Status_code::invalid_mesh,
        options.scheme + " cannot refine vertex " + std::to_string(v.idx()) +
            ": it has only 2 edges, so its two faces share two edges and "
            "the result would repeat edges (catmull-clark can refine it)");
  }
  return Status::success();
}

/// Triangulates every polygon as triangulate_faces does (CGAL's
/// triangulate_face, face by face), naming the first it refuses: one whose
/// normal is zero (degenerate), or past 4 vertices one whose projection is
/// not a simple polygon. Faces are numbered as in the input buffers.
Status triangulate_all(Mesh& mesh, const std::string& scheme) {
  std::vector<Mesh::Face_index> polygons;
  for (Mesh::Face_index f : mesh.faces())
    if (mesh.degree(f) > 3) polygons.push_back(f);
  for (Mesh::Face_index f : polygons) {
    const std::size_t degree = mesh.degree(f);
    if (CGAL::Polygon_mesh_processing::triangulate_face(f, mesh)) continue;
    return Status::error(
        Status_code::invalid_mesh,
        "face " + std::to_string(f.idx()) + " (" + std::to_string(degree) +
            " vertices) could not be triangulated: it is degenerate (no "
            "area) or self-intersecting; " +
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

Status sqrt3_step(Mesh& mesh, int global_step) {
  if (!sqrt3_refines_border(global_step) || CGAL::is_closed(mesh)) {
    SM3::Sqrt3_subdivision(mesh, CGAL::parameters::number_of_iterations(1));
    return Status::success();
  }
  // A border step. Its host assumes at most one border edge per face, which
  // holds for the output of a non-border step but not for arbitrary input.
  const Counts c = counts_of(mesh);
  if (c.multi_border_faces > 0)
    return Status::error(
        Status_code::invalid_argument,
        "start_level " + std::to_string(global_step) +
            " of sqrt3 refines the border, which needs a mesh from an even "
            "level of sqrt3, but " +
            format_count(c.multi_border_faces) +
            " faces have more than one border edge; start from level 0");
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

/// Counts of a level (border degrees from its valences).
Counts counts_of(const refine::Level& l) {
  Counts c;
  c.vertices = l.vertex_count;
  c.edges = l.edge_count;
  c.faces = l.face_count;
  c.border_edges = l.border_edge_count;
  std::vector<std::uint32_t> valence(l.vertex_count, 0);
  std::vector<bool> border(l.vertex_count, false);
  const std::uint32_t* t = l.halfedge_target.data();
  for (std::uint32_t h = 0; h < 2 * l.edge_count; ++h) {
    ++valence[t[h]];
    if (l.halfedge_corner[h] == refine::kNone) border[t[h]] = true;
  }
  for (std::uint32_t v = 0; v < l.vertex_count; ++v) {
    if (!border[v]) continue;
    c.border_ears += valence[v] == 2;
    c.border_fans += valence[v] >= 4;
  }
  for (std::uint32_t f = 0; f < l.face_count; ++f) {
    const std::uint32_t begin = l.face_begin(f), end = l.face_end(f);
    c.non_triangles += end - begin != 3;
    c.degree_excess += static_cast<double>(end - begin) - 3;
    std::uint32_t on_border = 0;
    for (std::uint32_t i = begin; i < end; ++i)
      on_border += l.halfedge_corner[l.face_halfedges[i] ^ 1] == refine::kNone;
    c.multi_border_faces += on_border >= 2;
  }
  return c;
}

/// check_two_valent_vertices on a level (the PTQ schemes refuse an interior
/// vertex of valence 2).
Status check_two_valent_vertices(const refine::Level& l,
                                 const Subdivide_options& options) {
  if (size_model(options) != "loop") return Status::success();
  std::vector<std::uint32_t> valence(l.vertex_count, 0);
  std::vector<bool> border(l.vertex_count, false);
  const std::uint32_t* t = l.halfedge_target.data();
  for (std::uint32_t h = 0; h < 2 * l.edge_count; ++h) {
    ++valence[t[h]];
    if (l.halfedge_corner[h] == refine::kNone) border[t[h]] = true;
  }
  for (std::uint32_t v = 0; v < l.vertex_count; ++v) {
    if (valence[v] != 2 || border[v]) continue;
    return Status::error(
        Status_code::invalid_mesh,
        options.scheme + " cannot refine vertex " + std::to_string(v) +
            ": it has only 2 edges, so its two faces share two edges and "
            "the result would repeat edges (catmull-clark can refine it)");
  }
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
    all_edges_are_face_edges = false;
  } else {
    s = check_two_valent_vertices(level, options);
    if (!s.ok()) return s;
  }
  marks = 0;
  if (!scheme_keeps_control_edges(options)) return Status::success();
  if (in.control_edges.empty() && all_edges_are_face_edges) {
    if (options.start_level == 0) level.edge_marks.assign(level.edge_count, 1);
    marks = options.start_level == 0 ? level.edge_count : 0;
    return Status::success();
  }
  const refine::Vertex_halfedges around = refine::vertex_halfedges(level);
  const auto edge_of = [&](std::uint32_t a, std::uint32_t b) {
    return around.edge(level, a, b);
  };
  const Result<Control_edges> control =
      initial_control_edges(in, level.edge_count, edge_of, options.start_level);
  if (!control.ok()) return control.status;
  level.edge_marks.assign(level.edge_count, 0);
  for (const auto& [a, b] : control.value) level.edge_marks[edge_of(a, b)] = 1;
  marks = static_cast<double>(control.value.size());
  return Status::success();
}

/// Runs the steps of `options` on the fast primal hosts (refine/, `mask`
/// from refine::primal_mask) from `parent` (level 0 from prepare_level,
/// with `counts` and `marks` control edges). Each step is checked against
/// the memory limit first, as the CGAL steps are. `level` follows the step
/// for messages.
Status run_primal_steps(refine::Level& parent, Counts counts, double marks,
                        const refine::Primal_mask& mask,
                        const Subdivide_options& options,
                        const Mesh_buffers& in, double input, Mesh_buffers& out,
                        int& level) {
  const Caps mesh_caps = Caps::exact(counts);
  refine::Level child;
  refine::Primal_scratch scratch;
  for (int i = 0; i < options.levels; ++i) {
    level = options.start_level + i + 1;
    const bool last = i + 1 == options.levels;
    const Step_need need =
        step_need(options, counts, mesh_caps, options.start_level + i, i == 0,
                  last, marks, input);
    Status s = check_step(options.scheme, need, options.start_level + i,
                          options.memory_limit_bytes);
    if (!s.ok()) return s;
    const std::uint32_t uncovered =
        refine::primal_uncovered_valence(parent, mask, scratch);
    if (uncovered != 0)
      return custom_rules_valence_refusal(options.custom, uncovered);
    if (mask.pqq)
      refine::refine_pqq_topology(parent, child, last);
    else
      refine::refine_ptq_topology(parent, child, last);
    refine::refine_primal_points(parent, mask, scratch, child);
    for (double x : child.positions)
      if (!std::isfinite(x)) return overflow(in, options.scheme, level);
    std::swap(parent, child);
    counts = need.after;
    marks *= 2;
  }
  child = refine::Level();
  scratch = refine::Primal_scratch();
  out = refine::level_to_buffers(std::move(parent));
  return Status::success();
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
    s = sqrt3_step(mesh, global_step);
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
      s = Status::error(
          Status_code::invalid_argument,
          "start_level " + std::to_string(global_step) +
              " of custom (sqrt3 host) refines the border, which needs a mesh "
              "from an even level, but some faces have more than one border "
              "edge; start from level 0");
    if (s.ok()) custom_subdivision_step(mesh, options.custom, global_step);
  } else {
    return Status::error(
        Status_code::invalid_argument,
        "unknown scheme \"" + scheme + "\"; known schemes: " + scheme_list());
  }
  collect_removed(mesh);
  return s;
}

Result<Size_prediction> predict_size(const Mesh_buffers& in,
                                     const Subdivide_options& options) {
  Result<Size_prediction> result;
  try {
    Counts c;
    {
      Mesh mesh;
      Status s = check_options(options);
      if (s.ok()) s = build_mesh(in, mesh);
      if (s.ok()) s = check_two_valent_vertices(mesh, options);
      if (!s.ok()) {
        result.status = s;
        return result;
      }
      c = counts_of(mesh);
    }
    // Marks the primal schemes carry (before any triangulation).
    double marks = 0;
    if (scheme_keeps_control_edges(options))
      marks = !in.control_edges.empty()
                  ? static_cast<double>(in.control_edges.size() / 2)
              : options.start_level == 0 ? c.edges
                                         : 0;
    if (needs_triangles(options) && c.non_triangles > 0) {
      if (!options.triangulate) {
        result.status = not_triangles(options.scheme, c);
        return result;
      }
      c = triangulated(c);
    }
    const double input =
        buffers_bytes(static_cast<double>(in.vertex_count()),
                      static_cast<double>(in.face_count()),
                      static_cast<double>(in.face_indices.size()));
    Run_prediction run;
    predict_run(options, c, input, marks, false, run);
    c = run.after;
    result.value.vertices = to_size(c.vertices);
    result.value.edges = to_size(c.edges);
    result.value.faces = to_size(c.faces);
    result.value.peak_bytes = to_size(run.peak_bytes);
  } catch (const std::exception& e) {
    result.status = Status::error(Status_code::internal_error,
                                  std::string("internal error: ") + e.what());
  } catch (...) {
    result.status = Status::error(Status_code::internal_error,
                                  "internal error: unknown exception");
  }
  return result;
}

Result<Mesh_buffers> subdivide_mesh(const Mesh_buffers& in,
                                    const Subdivide_options& options) {
  Result<Mesh_buffers> result;
  int level = options.start_level;  // for messages
  try {
    const refine::Primal_mask_lookup fast =
        refine::primal_mask(options.scheme, options.custom);
    const double input =
        buffers_bytes(static_cast<double>(in.vertex_count()),
                      static_cast<double>(in.face_count()),
                      static_cast<double>(in.face_indices.size()));
    if (fast.ok && runs_on_fast_host(options) && options.levels > 0) {
      refine::Level level0;
      Counts counts;
      double marks = 0;
      Status s = prepare_level(in, options, level0, counts, marks);
      // Refuse at once a run whose later level would not fit.
      Run_prediction run;
      if (s.ok()) s = predict_run(options, counts, input, marks, true, run);
      if (s.ok())
        s = run_primal_steps(level0, counts, marks, fast.mask, options, in,
                             input, result.value, level);
      if (!s.ok()) result = Result<Mesh_buffers>{s, {}};
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

std::vector<std::string> scheme_names() {
  std::vector<std::string> names;
  for (const Scheme_entry& s : scheme_table()) names.push_back(s.name);
  return names;
}

}  // namespace subdivlab
