/**
 * CGAL's geometry around a mesh (wasm/src/core/inspect.h), as inspectMesh
 * (subdiv-core.ts) gives it: the measures always, each computation when
 * asked, with the milliseconds it took.
 */
export type Xyz = [number, number, number];

/** What to compute besides the measures. */
export interface InspectOptions {
  selfIntersections?: boolean;
  sphere?: boolean;
  hull?: boolean;
  width?: boolean;
  /** Face pairs listed (all are counted); default 100. */
  maxPairs?: number;
}

export interface MeshMeasures {
  area: number;
  /** The enclosed volume when `closed`, else 0. */
  volume: number;
  closed: boolean;
  bboxMin: Xyz;
  bboxMax: Xyz;
  diagonal: number;
  ms: number;
}

export interface SelfIntersections {
  /** Pairs of faces that cross (sharing an edge or a vertex counts only when they truly cross). */
  pairs: number;
  /** The first pairs, two face numbers each. */
  firstPairs: Uint32Array;
  /** Every face in some pair, sorted. */
  faces: Uint32Array;
  ms: number;
}

export interface EnclosingSphere {
  center: Xyz;
  radius: number;
  ms: number;
}

export interface ConvexHull {
  /** Counts of the triangulated hull convex_hull_3 builds. */
  vertices: number;
  edges: number;
  faces: number;
  area: number;
  /** 0 when the points are coplanar. */
  volume: number;
  positions: Float64Array;
  triangles: Uint32Array;
  ms: number;
}

export interface MinimumWidth {
  /** Not computed: the hull has too many vertices for the exact algorithm. */
  skipped: boolean;
  width: number;
  /** The two planes n·x = offsets[0] and n·x = offsets[1]. */
  normal: Xyz;
  offsets: [number, number];
  ms: number;
}

export interface Inspection {
  measures: MeshMeasures;
  selfIntersections?: SelfIntersections;
  sphere?: EnclosingSphere;
  hull?: ConvexHull;
  width?: MinimumWidth;
}

/** The buffers of an inspection, to transfer from a worker. */
export function inspectionBuffers(i: Inspection): ArrayBuffer[] {
  const arrays = [i.selfIntersections?.firstPairs, i.selfIntersections?.faces, i.hull?.positions, i.hull?.triangles];
  return arrays.flatMap((a) => (a ? [a.buffer as ArrayBuffer] : []));
}
