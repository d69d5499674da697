// OpenSubdiv's Far uniform refinement of a SubdivLab mesh, and the map from
// SubdivLab's numbering of each refined level to OpenSubdiv's: shared by
// osd_tests (the native comparison) and osd_reference (OpenSubdiv's points
// in SubdivLab's numbering, for the Node tests of the WASM core).
//
// Numbering differs (SubdivLab numbers as CGAL does), so each level's
// vertices are matched through their origin: a vertex's child keeps its
// index on both sides; an edge's point is, on SubdivLab's side, the one
// child vertex next to both ends, and on OpenSubdiv's its
// GetEdgeChildVertex; a face's point (Catmull-Clark) is V + E + f on
// SubdivLab's side.
#pragma once

#include <opensubdiv/far/topologyRefiner.h>

#include <memory>
#include <set>
#include <string>
#include <vector>

#include "core/mesh_types.h"

namespace subdivlab::osd {

struct Point {
  double x = 0, y = 0, z = 0;
  void Clear() { x = y = z = 0; }
  void AddWithWeight(const Point& p, double w) {
    x += w * p.x;
    y += w * p.y;
    z += w * p.z;
  }
};

/// OpenSubdiv's uniform refinement of `mesh` (its tags included) to
/// `levels`, with every level's points.
struct Run {
  std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> refiner;
  std::vector<std::vector<Point>> points;  // per level
};

Run refine(const Mesh_buffers& mesh, bool loop, int levels);

/// SubdivLab's one step of `in` (Catmull-Clark or Loop); `error` set when
/// the core refused.
Mesh_buffers step(const Mesh_buffers& in, bool loop, std::string& error);

/// The edges of a mesh as (lower, higher) vertex pairs.
std::set<std::pair<std::uint32_t, std::uint32_t>> edges_of(
    const Mesh_buffers& m);

/// A face as the cycle of its vertices, starting at the smallest.
std::vector<int> cycle(std::vector<int> face);

/// OpenSubdiv's index of each vertex of `child` (SubdivLab's step of
/// `parent`), given `map`, OpenSubdiv's index of each vertex of `parent`
/// (at `parent_level` of `run`). Empty, with `error` set, when a vertex has
/// no origin on one side.
std::vector<int> child_origins(const Run& run, int parent_level,
                               const Mesh_buffers& parent,
                               const Mesh_buffers& child,
                               const std::vector<int>& map, bool loop,
                               std::string& error);

}  // namespace subdivlab::osd
