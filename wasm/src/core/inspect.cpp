#include "inspect.h"

#include <CGAL/Exact_integer.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Homogeneous.h>
#include <CGAL/Min_sphere_of_spheres_d.h>
#include <CGAL/Min_sphere_of_spheres_d_traits_3.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Width_3.h>
#include <CGAL/Width_default_traits_3.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <utility>

#include "mesh_build.h"
#include "mesh_facts.h"

namespace subdivlab {

namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

// Exact predicates (interval filters, then exact arithmetic from CGAL's own
// number types: no GMP in WebAssembly) for the intersection tests and the
// hull, as the tutorial asks.
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Exact_mesh = CGAL::Surface_mesh<Epick::Point_3>;
using Exact_face = Exact_mesh::Face_index;

double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(
             std::chrono::steady_clock::now() - start)
      .count();
}

std::vector<Epick::Point_3> points_of(const Mesh_buffers& in) {
  std::vector<Epick::Point_3> points;
  points.reserve(in.positions.size() / 3);
  for (std::size_t i = 0; i + 2 < in.positions.size(); i += 3)
    points.emplace_back(in.positions[i], in.positions[i + 1],
                        in.positions[i + 2]);
  return points;
}

/// Which input face each triangle of the triangulated mesh came from.
struct Origin_visitor {
  Exact_mesh::Property_map<Exact_face, std::uint32_t> origin;
  std::uint32_t current = 0;
  void before_subface_creations(Exact_face f) { current = origin[f]; }
  void after_subface_created(Exact_face f) { origin[f] = current; }
  void after_subface_creations() {}
};

Self_intersections self_intersections_of(const Mesh_buffers& in,
                                         std::size_t max_pairs) {
  const auto start = std::chrono::steady_clock::now();
  Exact_mesh mesh;
  for (const Epick::Point_3& p : points_of(in)) mesh.add_vertex(p);
  auto origin =
      mesh.add_property_map<Exact_face, std::uint32_t>("f:origin", 0).first;
  std::vector<Exact_mesh::Vertex_index> polygon;
  std::size_t corner = 0;
  for (std::size_t f = 0; f < in.face_sizes.size(); ++f) {
    polygon.clear();
    for (std::uint32_t k = 0; k < in.face_sizes[f]; ++k)
      polygon.emplace_back(in.face_indices[corner++]);
    const Exact_face face = mesh.add_face(polygon);
    if (face != Exact_mesh::null_face())
      origin[face] = static_cast<std::uint32_t>(f);
  }
  PMP::triangulate_faces(mesh,
                         CGAL::parameters::visitor(Origin_visitor{origin}));
  std::vector<std::pair<Exact_face, Exact_face>> crossing;
  PMP::self_intersections<CGAL::Sequential_tag>(mesh,
                                                std::back_inserter(crossing));
  // Triangles of the same two faces are one pair of faces; a face's own
  // triangles are not a pair.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  pairs.reserve(crossing.size());
  for (const auto& [a, b] : crossing) {
    const std::uint32_t fa = origin[a], fb = origin[b];
    if (fa != fb) pairs.emplace_back(std::min(fa, fb), std::max(fa, fb));
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  Self_intersections out;
  out.pairs = pairs.size();
  for (std::size_t i = 0; i < pairs.size() && i < max_pairs; ++i) {
    out.first_pairs.push_back(pairs[i].first);
    out.first_pairs.push_back(pairs[i].second);
  }
  for (const auto& [a, b] : pairs) {
    out.faces.push_back(a);
    out.faces.push_back(b);
  }
  std::sort(out.faces.begin(), out.faces.end());
  out.faces.erase(std::unique(out.faces.begin(), out.faces.end()),
                  out.faces.end());
  out.ms = ms_since(start);
  return out;
}

Hull_result hull_of(const std::vector<Epick::Point_3>& points,
                    Exact_mesh& hull) {
  const auto start = std::chrono::steady_clock::now();
  CGAL::convex_hull_3(points.begin(), points.end(), hull);
  Hull_result out;
  out.vertices = hull.number_of_vertices();
  out.edges = hull.number_of_edges();
  out.faces = hull.number_of_faces();
  out.area = CGAL::to_double(PMP::area(hull));
  out.volume =
      CGAL::is_closed(hull) ? std::abs(CGAL::to_double(PMP::volume(hull))) : 0;
  std::map<Exact_mesh::Vertex_index, std::uint32_t> index;
  for (Exact_mesh::Vertex_index v : hull.vertices()) {
    index.emplace(v, static_cast<std::uint32_t>(out.positions.size() / 3));
    const Epick::Point_3& p = hull.point(v);
    out.positions.insert(out.positions.end(), {p.x(), p.y(), p.z()});
  }
  for (Exact_face f : hull.faces())
    for (Exact_mesh::Vertex_index v :
         CGAL::vertices_around_face(hull.halfedge(f), hull))
      out.triangles.push_back(index.at(v));
  out.ms = ms_since(start);
  return out;
}

Enclosing_sphere sphere_of(const std::vector<Epick::Point_3>& points) {
  const auto start = std::chrono::steady_clock::now();
  // Square roots allowed: the centre and radius as doubles.
  using Traits =
      CGAL::Min_sphere_of_spheres_d_traits_3<Epick, double, CGAL::Tag_true>;
  std::vector<Traits::Sphere> spheres;
  spheres.reserve(points.size());
  for (const Epick::Point_3& p : points) spheres.emplace_back(p, 0.0);
  CGAL::Min_sphere_of_spheres_d<Traits> min_sphere(spheres.begin(),
                                                   spheres.end());
  Enclosing_sphere out;
  auto c = min_sphere.center_cartesian_begin();
  for (int i = 0; i < 3; ++i, ++c) out.center[i] = *c;
  out.radius = min_sphere.radius();
  out.ms = ms_since(start);
  return out;
}

// Width_3 needs exact arithmetic on homogeneous coordinates: every double
// is an integer times a power of two, so the points are written exactly
// as integers over one common power of two.
using Exact_integer = CGAL::Exact_integer;
using Homogeneous_kernel = CGAL::Homogeneous<Exact_integer>;
using Width = CGAL::Width_3<CGAL::Width_default_traits_3<Homogeneous_kernel>>;

Exact_integer power_of_two(int k) {
  Exact_integer p(1), base(2);
  for (; k > 0; k >>= 1) {
    if (k & 1) p *= base;
    base *= base;
  }
  return p;
}

double ratio(const Exact_integer& num, const Exact_integer& den) {
  return CGAL::to_double(CGAL::Exact_rational(num) / CGAL::Exact_rational(den));
}

Width_result width_of(const std::vector<Epick::Point_3>& points,
                      const Hull_result& hull, std::size_t max_vertices) {
  const auto start = std::chrono::steady_clock::now();
  Width_result out;
  if (hull.vertices > max_vertices) {
    out.skipped = true;
    return out;
  }
  if (hull.volume == 0) {
    // Coplanar points: width 0, the planes both the points' plane.
    const Epick::Vector_3 n =
        CGAL::normal(points[hull.triangles[0]], points[hull.triangles[1]],
                     points[hull.triangles[2]]);
    const double length = std::sqrt(n.squared_length());
    for (int i = 0; i < 3; ++i) out.normal[i] = n[i] / length;
    const Epick::Point_3& p = points[hull.triangles[0]];
    out.offsets[0] = out.offsets[1] =
        out.normal[0] * p.x() + out.normal[1] * p.y() + out.normal[2] * p.z();
    out.ms = ms_since(start);
    return out;
  }
  // Hull vertices only: the width is theirs.
  int shift = 0;
  for (double x : hull.positions) {
    int e = 0;
    if (x != 0) std::frexp(x, &e);
    shift = std::max(shift, 53 - e);
  }
  std::vector<Homogeneous_kernel::Point_3> exact;
  exact.reserve(hull.vertices);
  std::map<int, Exact_integer> powers;
  auto integer = [&](double x) {
    int e = 0;
    const double m = std::frexp(x, &e);  // x = m 2^e, 1/2 <= |m| < 1
    const auto mantissa = static_cast<long long>(std::ldexp(m, 53));
    const int k = e - 53 + shift;  // >= 0 by the choice of shift
    auto it = powers.find(k);
    if (it == powers.end()) it = powers.emplace(k, power_of_two(k)).first;
    return Exact_integer(mantissa) * it->second;
  };
  const Exact_integer w = power_of_two(shift);
  for (std::size_t i = 0; i + 2 < hull.positions.size(); i += 3)
    exact.emplace_back(integer(hull.positions[i]),
                       integer(hull.positions[i + 1]),
                       integer(hull.positions[i + 2]), w);
  Width width(exact.begin(), exact.end());
  Exact_integer num, den;
  width.get_squared_width(num, den);
  out.width = std::sqrt(ratio(num, den));
  // Planes A x + B y + C z + D = 0 and A x + B y + C z + K = 0 (in the
  // points' own coordinates: the common w cancels).
  Exact_integer a, b, c, d, k;
  width.get_width_coefficients(a, b, c, d, k);
  const Exact_integer* largest = &a;
  for (const Exact_integer* q : {&b, &c})
    if (CGAL::abs(*q) > CGAL::abs(*largest)) largest = q;
  const std::array<double, 5> unit = {ratio(a, *largest), ratio(b, *largest),
                                      ratio(c, *largest), ratio(d, *largest),
                                      ratio(k, *largest)};
  const double length =
      std::sqrt(unit[0] * unit[0] + unit[1] * unit[1] + unit[2] * unit[2]);
  for (int i = 0; i < 3; ++i) out.normal[i] = unit[i] / length;
  out.offsets = {-unit[3] / length, -unit[4] / length};
  out.ms = ms_since(start);
  return out;
}

// Area and volume of the faces fanned from their centroids: the same for
// any numbering of a face's corners (a level computed one step at a time
// and in one call number them differently), exact for planar faces; the
// volume by the divergence theorem (closed meshes).
Mesh_measures measures_of(const Mesh_buffers& in, const Mesh& mesh) {
  const auto start = std::chrono::steady_clock::now();
  Mesh_measures out;
  out.closed = CGAL::is_closed(mesh);
  const auto& p = in.positions;
  double twice_area = 0, six_volume = 0;
  std::size_t corner = 0;
  for (std::uint32_t size : in.face_sizes) {
    const std::uint32_t* f = &in.face_indices[corner];
    double a[3] = {0, 0, 0};
    for (std::uint32_t k = 0; k < size; ++k)
      for (int i = 0; i < 3; ++i) a[i] += p[3 * f[k] + i] / size;
    for (std::uint32_t k = 0; k < size; ++k) {
      const double* b = &p[3 * f[k]];
      const double* c = &p[3 * f[(k + 1) % size]];
      const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
      const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
      const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                           u[0] * v[1] - u[1] * v[0]};
      twice_area += std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      six_volume += a[0] * (b[1] * c[2] - b[2] * c[1]) -
                    a[1] * (b[0] * c[2] - b[2] * c[0]) +
                    a[2] * (b[0] * c[1] - b[1] * c[0]);
    }
    corner += size;
  }
  out.area = twice_area / 2;
  if (out.closed) out.volume = std::abs(six_volume) / 6;
  for (int i = 0; i < 3; ++i) {
    out.bbox_min[i] = out.bbox_max[i] = p[i];
  }
  for (std::size_t i = 0; i < p.size(); ++i) {
    out.bbox_min[i % 3] = std::min(out.bbox_min[i % 3], p[i]);
    out.bbox_max[i % 3] = std::max(out.bbox_max[i % 3], p[i]);
  }
  out.diagonal = bbox_diagonal({&in});
  out.ms = ms_since(start);
  return out;
}

}  // namespace

Result<Inspection> inspect_mesh(const Mesh_buffers& in,
                                const Inspect_options& options) {
  Mesh mesh;
  const Status s = build_mesh(in, mesh);
  if (!s.ok()) return {s, {}};
  Inspection out;
  out.measures = measures_of(in, mesh);
  if (options.self_intersections) {
    out.self_intersections = self_intersections_of(in, options.max_pairs);
    out.has_self_intersections = true;
  }
  if (options.sphere || options.hull || options.width) {
    const std::vector<Epick::Point_3> points = points_of(in);
    Exact_mesh hull;
    const Hull_result h = hull_of(points, hull);
    if (options.hull) {
      out.hull = h;
      out.has_hull = true;
    }
    if (options.sphere) {
      out.sphere = sphere_of(points);
      out.has_sphere = true;
    }
    if (options.width) {
      std::vector<Epick::Point_3> hull_points;
      for (std::size_t i = 0; i + 2 < h.positions.size(); i += 3)
        hull_points.emplace_back(h.positions[i], h.positions[i + 1],
                                 h.positions[i + 2]);
      out.width = width_of(hull_points, h, options.max_width_vertices);
      out.has_width = true;
    }
  }
  return {Status::success(), std::move(out)};
}

}  // namespace subdivlab
