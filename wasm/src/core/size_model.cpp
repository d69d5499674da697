#include "size_model.h"

#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "refine/crease.h"
#include "refine/dual_hosts.h"
#include "refine/level_convert.h"
#include "refine/primal_points.h"
#include "refine/sqrt3_host.h"
#include "render_buffers.h"
#include "scheme_table.h"

namespace subdivlab::detail {

// ---------------------------------------------------------------------------
// Counts. Everything a step's result size depends on, kept in doubles so that
// predictions far beyond 2^32 (and beyond size_t under wasm32) stay finite
// and comparable.

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
  c.from_triangulated_mesh = true;
  return c;  // border degrees and multi-border faces: not needed by loop/sqrt3
}

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

/// Peak of a step on the fast primal hosts (refine/): the parent and
/// child levels' tables and the step's per-vertex scratch (the last step
/// of a primal run frees some before its child's corners); on the first step
/// the Surface_mesh the level came from (freed before the step); after the
/// last, the child level with the output's face sizes (positions, face
/// vertices and control edges move out). The child of the last step has
/// only its face vertices and its marked edges' ends (4 per parent mark).
double fast_step_peak(const std::string& scheme, bool face_sums,
                      const Counts& c, const Counts& n, const Caps& caps,
                      bool first, bool last, double marks, double base) {
  const bool marked = marks > 0;
  // DQQ levels keep their face offsets (mixed degrees) and, but for the
  // last, their vertices' halfedges; PQT levels keep theirs when they mix
  // triangles and other faces.
  const bool dual = scheme == "doo-sabin", pqt = scheme == "quad-triangle";
  const auto mixed = [&](const Counts& k) {
    return dual || (pqt && k.non_triangles > 0 && k.non_triangles < k.faces);
  };
  const double parent =
      refine::level_bytes(c.vertices, c.edges, c.degree_sum(), marked, false) +
      (first || mixed(c) ? 4 * (c.faces + 1) : 0) + (dual ? 4 * c.vertices : 0);
  const double child =
      refine::level_bytes(n.vertices, n.edges, n.degree_sum(), marked, last) +
      (mixed(n) ? 4 * (n.faces + 1) : 0) +
      (dual && !last ? 4 * n.vertices : 0) + (last ? 16 * marks : 0);
  // sqrt3: the primal points' scratch, and on a border step a code per face
  // (counted whenever there is a border). PQT: the primal points' sums, and
  // with faces other than triangles their counts at vertices and edges.
  const bool border = c.border_edges > 0;
  double scratch = 0;
  // The DQQ step frees its parent's halfedge targets and, closed, their
  // corners first (run_dual_steps).
  double freed = 0;
  if (dual) {
    scratch =
        refine::dual_scratch_bytes(c.vertices, c.edges, n.vertices, border);
    freed = 8 * c.edges + (border ? 0 : 8 * c.edges);
  } else if (pqt) {
    scratch = refine::pqt_scratch_bytes(c.vertices, c.edges,
                                        c.non_triangles > 0, border);
  } else {
    scratch =
        refine::primal_scratch_bytes(c.vertices, face_sums, border) +
        (scheme == "sqrt3" ? refine::sqrt3_scratch_bytes(c.faces, border) : 0);
  }
  if (c.creased) {
    // The crease tables of both levels, apply_crease_rules' vertex runs or
    // Chaikin's sums, and the last level's halfedge targets.
    scratch += refine::crease_level_bytes(c.vertices, c.edges, c.faces) +
               refine::crease_level_bytes(n.vertices, n.edges, n.faces) +
               refine::crease_scratch_bytes(c.vertices, c.edges) +
               (last ? 8 * n.edges : 0);
  }
  double peak = base + parent - freed + child + scratch;
  if (last && !c.creased && !dual && scheme != "sqrt3") {
    // The last step of a PQQ, PTQ or PQT run (release_before_last_topology):
    // its points beside the parent and the scratch; then, the scratch and
    // the parent's positions and halfedge corners freed, the marked edges'
    // ends beside its halfedge targets; then, those and its marks freed,
    // the child's corners.
    const double points = 24 * n.vertices, ends = 16 * marks;
    const double kept = parent - 24 * c.vertices - 8 * c.edges;
    peak =
        base + std::max({parent + points + scratch, kept + points + ends,
                         kept - 8 * c.edges - (marked ? c.edges : 0) + child});
  }
  // Level 0 comes from the buffers (check_buffers' temporaries: 32 bytes
  // a corner, 8 a vertex, 4 a face; then the level beside the corners'
  // halfedges and a vertex numbering) or, when it had to be triangulated,
  // from CGAL's mesh (beside it). Control edges given as pairs are found
  // through the halfedges around each vertex and held as pairs (8 bytes,
  // as initial_control_edges grew them) until marked; the output's pairs
  // come after the last step.
  if (first) {
    const double S = c.degree_sum(), V = c.vertices;
    double level0 =
        std::max(32 * S + 8 * V + 4 * c.faces, 4 * S + 4 * V + parent);
    if (c.from_triangulated_mesh)
      level0 = std::max(level0, caps_bytes(caps) + parent);
    const double finding =
        marks > 0 && (c.control_edge_pairs || c.from_triangulated_mesh)
            ? 8 * V + 8 * c.edges + control_edge_bytes(marks)
            : 0;
    peak = std::max(peak, base + level0 + finding);
  }
  if (last) peak = std::max(peak, base + child + 4 * n.faces);
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

/// The step from `c` (mesh arrays at `caps`) with the input buffers
/// (`input_bytes`) and `marks` control edges alive; `first` is the first
/// step of the call, `last` its last (which adds the output buffers).
Step_need step_need(const Subdivide_options& options, const Counts& c,
                    const Caps& caps, int global_step, bool first, bool last,
                    double marks, double input_bytes) {
  const std::string scheme = size_model(options);
  Step_need need;
  need.after = next_counts(scheme, c, global_step);
  need.after.creased = c.creased;
  need.caps_after = caps;
  double peak = 0;
  if (runs_on_fast_host(options)) {
    const bool face_sums = refine::primal_mask(options.scheme, options.custom)
                               .mask.separate_face_sums();
    peak = fast_step_peak(scheme, face_sums, c, need.after, caps, first, last,
                          marks, input_bytes);
  } else {
    const double base = input_bytes + control_edge_bytes(marks);
    peak = simulate_step(scheme, c, need.after, need.caps_after, base,
                         global_step);
    if (last)
      peak = std::max(peak, to_buffers_peak(need.after, need.caps_after, base));
  }
  if (last && options.render_buffers) {
    // The result's buffers and the input beside the render arrays.
    const Counts& n = need.after;
    const double corners = n.degree_sum();
    peak = std::max(peak,
                    input_bytes + buffers_bytes(n.vertices, n.faces, corners) +
                        16 * marks +  // the result's control edges, 2 per mark
                        render_peak_bytes(n.vertices, n.edges, corners,
                                          corners - 2 * n.faces) +
                        // A creased level may have holes: the faces drawn
                        // are copied apart (render_buffers.cpp).
                        (n.creased ? 8 * n.faces + 4 * corners : 0));
  }
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

/// Counts of a level (border degrees from its valences).
Counts counts_of(const refine::Level& l) {
  Counts c;
  c.vertices = l.vertex_count;
  c.edges = l.edge_count;
  c.faces = l.face_count;
  c.border_edges = l.border_edge_count;
  if (l.border_edge_count == 0 && l.uniform_degree != 0) {
    // Closed, of one degree: nothing to count on the border, and the
    // degrees are known (a level of millions of faces read twice less).
    const double excess = static_cast<double>(l.uniform_degree) - 3;
    c.non_triangles = excess != 0 ? c.faces : 0;
    c.degree_excess = excess * c.faces;
    return c;
  }
  std::vector<std::uint32_t> valence;
  std::vector<bool> border;
  refine::vertex_valences(l, valence, border);
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

}  // namespace subdivlab::detail
