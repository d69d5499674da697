/**
 * A result checked against the reference (wasm/src/core/compare.h), as
 * compareMeshes (subdiv-core.ts) gives it.
 */
export interface MeshComparison {
  /** Same counts, the same faces through the vertex matching, every vertex within the tolerance. */
  match: boolean;
  /** What failed, one sentence each. */
  reasons: string[];
  referenceVertices: number;
  resultVertices: number;
  referenceFaces: number;
  resultFaces: number;
  /** 'order': vertex i is the reference's vertex i; 'nearest': each the reference vertex nearest it. */
  matching: 'order' | 'nearest';
  sameFaces: boolean;
  /** The absolute tolerance: the relative one times the reference's bounding-box diagonal. */
  tolerance: number;
  diagonal: number;
  maxError: number;
  meanError: number;
  /**
   * The worst vertices (the result's numbers), largest error first, with the reference vertex each was matched
   * to; for OFF and OBJ also the line each is on and its number in the file (vertex-lines.ts).
   */
  worst: { vertex: number; reference: number; error: number; line?: number; fileVertex?: number }[];
  /** How the result's file numbers its vertices (OFF from 0, OBJ from 1); absent for PLY and STL. */
  fileFormat?: 'off' | 'obj';
  /** Per result vertex: the reference vertex it was matched to, and their distance. */
  matched: Uint32Array;
  errors: Float64Array;
}
