/**
 * Discrete curvature at the vertices of a mesh, as the core works it out
 * (wasm/src/core/curvature.h): Gaussian by the angle defect, mean by the
 * cotangent Laplacian, each over the mixed (Voronoi) area of Meyer et al.
 * 2003; polygons fanned from their first corner as they are drawn.
 */

/** Per-vertex curvature; NaN at a border vertex (and where a vertex has no area around it). */
export interface VertexCurvature {
  /** Angle defect / mixed area. */
  gaussian: Float64Array;
  /** Mean curvature, positive where the surface bends away from its normal (a sphere turned outward: 1/r). */
  mean: Float64Array;
  /** 2π − the angles at the vertex. */
  angleDefect: Float64Array;
  /** The mixed area around the vertex. */
  area: Float64Array;
  /** How many vertices lie on the border. */
  borderVertices: number;
}

/** The kinds of curvature the viewer colours by. */
export type CurvatureKind = 'gaussian' | 'mean';

/** The typed arrays of a VertexCurvature, for a transfer list. */
export function curvatureBuffers(c: VertexCurvature): ArrayBuffer[] {
  return [c.gaussian, c.mean, c.angleDefect, c.area].map((a) => a.buffer as ArrayBuffer);
}
