// Discrete curvature at the vertices of a mesh (the viewer's curvature
// colours): Gaussian curvature by the angle defect and mean curvature by
// the cotangent Laplacian, each over the mixed (Voronoi) area of Meyer,
// Desbrun, Schröder and Barr, "Discrete Differential-Geometry Operators
// for Triangulated 2-Manifolds" (2003). Owner: curvature.cpp.
//
// Written here rather than taken from CGAL: CGAL 5.5 has no curvature of
// a mesh (Polygon_mesh_processing's interpolated corrected curvatures
// arrive in 5.6), and its Jet_fitting_3 fits a polynomial to a point
// neighbourhood (needs Eigen, which the build does not have, a chosen
// neighbourhood size, and at least six points: a cube's corner has four),
// which gives neither the exact angle defect at a corner nor Gauss-Bonnet.
#pragma once

#include <cstddef>
#include <vector>

#include "mesh_types.h"

namespace subdivlab {

/// Per-vertex curvature. Polygons are fanned from their first corner, as
/// the render buffers draw them (so the angles at a vertex sum over the
/// triangles drawn, and the defects of a closed mesh sum to 2π χ exactly
/// but for rounding). A vertex on the border (an edge of one face), or
/// with no area around it, has NaN in every array: the angle defect there
/// measures the border's turning, not the surface's bending, so the viewer
/// leaves it uncoloured and out of the colour range.
struct Vertex_curvature {
  /// 2π − the sum of the angles of the triangles at the vertex.
  std::vector<double> angle_defect;
  /// The mixed area: the Voronoi region's part of each non-obtuse triangle,
  /// of an obtuse one half its area at the obtuse corner, a quarter at the
  /// others (Meyer et al., fig. 4).
  std::vector<double> area;
  /// angle_defect / area.
  std::vector<double> gaussian;
  /// Mean curvature H: the cotangent Laplacian Σ (cot α + cot β)(x_i − x_j)
  /// / (2 area), which is 2H n, dotted with the unit vertex normal (the
  /// area-weighted sum of the triangle normals) and halved. Positive where
  /// the surface bends away from its normal (a sphere whose faces turn
  /// outward: 1/r), negative in a saddle's concave direction or a dent.
  std::vector<double> mean;
  /// Vertices on the border (NaN everywhere above).
  std::size_t border_vertices = 0;
};

/// The curvature of every vertex of `mesh` (a valid polygon mesh, as
/// build_mesh checks it: consistently oriented, every edge in at most two
/// faces). Fails with invalid_argument when a face names a vertex the mesh
/// does not have.
Result<Vertex_curvature> vertex_curvature(const Mesh_buffers& mesh);

}  // namespace subdivlab
