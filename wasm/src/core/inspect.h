// CGAL's geometry around a mesh, as the tutorial this project comes from
// ends with it: self-intersections (box intersection as a filter, then
// exact triangle tests), the smallest enclosing sphere, the convex hull,
// the minimum width, and the mesh's own area, volume and bounding box;
// each timed. Owner: inspect.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "mesh_types.h"

namespace subdivlab {

struct Inspect_options {
  bool self_intersections = false;
  bool sphere = false;
  bool hull = false;
  bool width = false;
  /// Face pairs listed (all are counted).
  std::size_t max_pairs = 100;
  /// Hull vertices above which the exact width is not attempted (its
  /// algorithm is quadratic in them); `Width_result::skipped` says so.
  std::size_t max_width_vertices = 4000;
};

/// Area, volume and bounding box of the mesh itself.
struct Mesh_measures {
  double area = 0;
  /// The enclosed volume of a closed mesh (0 when open: see `closed`).
  double volume = 0;
  bool closed = false;
  std::array<double, 3> bbox_min{}, bbox_max{};
  double diagonal = 0;
  double ms = 0;
};

struct Self_intersections {
  /// Pairs of faces that intersect (faces that share an edge or a vertex
  /// count only when they truly cross), by the exact predicates of
  /// Exact_predicates_inexact_constructions_kernel.
  std::size_t pairs = 0;
  /// The first max_pairs pairs, two face numbers (the input's) each, and
  /// every face in some pair (sorted).
  std::vector<std::uint32_t> first_pairs, faces;
  double ms = 0;
};

struct Enclosing_sphere {
  std::array<double, 3> center{};
  double radius = 0;
  double ms = 0;
};

struct Hull_result {
  /// Counts of the hull as convex_hull_3 builds it: a triangulated surface
  /// (a polygon, with zero volume, when the points are coplanar).
  std::size_t vertices = 0, edges = 0, faces = 0;
  double area = 0, volume = 0;
  /// Its vertices (x, y, z each) and triangles, to draw it.
  std::vector<double> positions;
  std::vector<std::uint32_t> triangles;
  double ms = 0;
};

struct Width_result {
  /// The distance between the two closest parallel planes that hold the
  /// points between them; exact (Width_3 on homogeneous integer
  /// coordinates), then rounded.
  double width = 0;
  /// The planes' unit normal n and offsets: n·x = offsets[0] and
  /// n·x = offsets[1].
  std::array<double, 3> normal{};
  std::array<double, 2> offsets{};
  /// Not computed: the hull has more than max_width_vertices vertices.
  bool skipped = false;
  double ms = 0;
};

struct Inspection {
  Mesh_measures measures;
  bool has_self_intersections = false, has_sphere = false, has_hull = false,
       has_width = false;
  Self_intersections self_intersections;
  Enclosing_sphere sphere;
  Hull_result hull;
  Width_result width;
};

/// The measures of `mesh` (a valid mesh: build_mesh's checks) and the
/// computations `options` asks for.
Result<Inspection> inspect_mesh(const Mesh_buffers& mesh,
                                const Inspect_options& options);

}  // namespace subdivlab
