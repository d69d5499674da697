// Checking a mesh against a reference ("check my result", issue 9): a
// student's level of a scheme against the core's. Vertices are matched in
// order when the counts agree and that order fits, else each to its
// nearest reference vertex (CGAL's kd-tree); then the faces are compared
// as cycles through that matching, and the distances give the errors.
// Owner: compare.cpp.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "mesh_types.h"

namespace subdivlab {

/// One candidate vertex far from where the reference has it.
struct Vertex_error {
  std::uint32_t vertex = 0;     ///< in the candidate's numbering
  std::uint32_t reference = 0;  ///< the reference vertex it was matched to
  double error = 0;             ///< their distance
};

struct Mesh_comparison {
  /// Same vertex, edge and face counts, same faces through the matching,
  /// every vertex within the tolerance.
  bool match = false;
  /// What failed, one sentence each ("3 of 98 vertices are farther than
  /// the tolerance ...").
  std::vector<std::string> reasons;
  std::uint64_t vertices[2] = {0, 0},
                faces[2] = {0, 0};  ///< reference, candidate
  /// "order" (vertex i is reference vertex i) or "nearest".
  std::string matching;
  /// The matching is one-to-one and the faces are the same cycles through
  /// it (false when it is not, or the counts differ).
  bool same_faces = false;
  /// The absolute tolerance used: the relative one times the reference's
  /// bounding-box diagonal.
  double tolerance = 0, diagonal = 0;
  double max_error = 0, mean_error = 0;
  /// The worst vertices, at most `worst` of them, largest error first.
  std::vector<Vertex_error> worst;
  /// Per candidate vertex: the reference vertex it was matched to, and
  /// their distance (for colouring a result by its errors).
  std::vector<std::uint32_t> matched;
  std::vector<double> errors;
};

/// Compares `candidate` with `reference`; `relative_tolerance` is a share
/// of the reference's bounding-box diagonal.
Mesh_comparison compare_meshes(const Mesh_buffers& reference,
                               const Mesh_buffers& candidate,
                               double relative_tolerance,
                               std::size_t worst = 5);

}  // namespace subdivlab
