// User-defined subdivision rules as data: a refinement host of CGAL's
// Subdivision_method_3 (PQQ, PTQ, DQQ, Sqrt3) and the weights of its mask,
// as tables indexed by vertex valence or face degree. Nothing is compiled at
// run time; table_masks_3.h turns the tables into CGAL masks.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "mesh_types.h"

namespace subdivlab {

/// Weights of an interior vertex rule at one valence n:
///   v' = self v + neighbour sum(edge neighbours) + face sum(face points).
/// The face points are the centroids of the incident faces (PQQ only; on
/// the PTQ and Sqrt3 hosts `face` must be 0). Sum: self + n (neighbour + face).
struct Vertex_weights {
  double self = 1.0;
  double neighbour = 0.0;
  double face = 0.0;
};

/// A rule set for `custom`. Which members a host reads:
///   pqq:   vertex, edge_end/edge_wing (wings = the two face centroids),
///          border_vertex, border_edge; face points are centroids.
///   ptq:   vertex (face = 0), edge_end/edge_wing (wings = the two vertices
///          opposite the edge), border_vertex, border_edge.
///   dqq:   corner, border_corner.
///   sqrt3: vertex (face = 0), border_vertex, border_edge (on the steps that
///          refine the border); face points are centroids.
/// Border weights run along the border in the direction in which the border
/// halfedges are chained (clockwise seen from the front of the surface).
struct Custom_rules {
  std::string host;  ///< "pqq", "ptq", "dqq" or "sqrt3"

  int first_valence = 3;               ///< valence of vertex[0]
  std::vector<Vertex_weights> vertex;  ///< vertex[n - first_valence]

  /// Interior edge point: edge_end per endpoint, edge_wing per wing point.
  double edge_end = 0.5, edge_wing = 0.0;

  int first_degree = 3;  ///< degree of corner[0]
  /// DQQ: the new point of corner c of a k-gon is sum_j corner[k -
  /// first_degree][j] p_j, where p_0 is c's vertex and p_j follows p_{j-1}
  /// around the face.
  std::vector<std::vector<double>> corner;

  /// Border vertex {previous, self, next} (PQQ, PTQ, Sqrt3).
  std::array<double, 3> border_vertex{0.125, 0.75, 0.125};
  /// Border edge point {before a, a, b, after b} for the border edge a -> b
  /// (PQQ, PTQ). Sqrt3: the new point nearer a; the one nearer b is mirrored.
  std::array<double, 4> border_edge{0.0, 0.5, 0.5, 0.0};
  /// DQQ: a corner point on a border edge is border_corner[0] times its own
  /// vertex plus border_corner[1] times the edge's other end (Chaikin's
  /// 3/4, 1/4 for Doo-Sabin, see dqq_border_3.h).
  std::array<double, 2> border_corner{0.75, 0.25};
};

/// Checks a rule set on its own: a known host; every weight the host reads
/// finite; every stencil summing to 1 within 1e-9; tables not empty. Fails
/// with Status_code::invalid_argument and a message naming the rule and the
/// valence or degree, e.g. "custom rules: the vertex rule at valence 5 sums
/// to 0.95, not 1".
Status check_custom_rules(const Custom_rules& rules);

/// Checks that the tables cover `mesh`: every interior vertex valence (pqq,
/// ptq, sqrt3) and every face degree (dqq). Precondition: check_custom_rules
/// succeeded.
Status check_custom_rules_cover(const Custom_rules& rules, const Mesh& mesh);

/// The refusal of check_custom_rules_cover for an interior vertex of
/// valence n that the vertex table does not cover.
Status custom_rules_valence_refusal(const Custom_rules& rules, std::size_t n);

/// The refusal of check_custom_rules_cover (dqq) for a face of degree k
/// that the corner table does not cover.
Status custom_rules_degree_refusal(const Custom_rules& rules, std::size_t k);

/// The built-in rule sets, as tables for valences / degrees 3..max_valence:
/// "catmull-clark" (pqq), "loop" (ptq), "doo-sabin" (dqq), "sqrt3" (sqrt3),
/// "improved-loop" (ptq; CGAL's Customized_subdivision example: Warren's
/// 3/(8n), Loop at valence 6, its own rule at valence 3), "linear" (pqq).
/// An unknown name gives rules with an empty host.
Custom_rules custom_rules_preset(const std::string& name, int max_valence = 64);

/// One step of the rules' host on `mesh`. `level_index` is the level of the
/// mesh before the step (Sqrt3 refines the border when it is odd).
/// Preconditions: check_custom_rules and check_custom_rules_cover succeeded;
/// triangles for ptq and sqrt3.
void custom_subdivision_step(Mesh& mesh, const Custom_rules& rules,
                             int level_index);

}  // namespace subdivlab
