/** What `<subdiv-viewer>`'s events carry (the iframe route posts the same to its parent). */
import type { MeshFacts, SchemeName } from '../core/mesh';
import { SubdivError } from '../core/subdiv-error';
import { LoadError } from '../viewer/mesh-source';

/** `detail` of `load`. */
export interface LoadDetail {
  modelName: string;
  facts: MeshFacts;
}

/** `detail` of `level-change`: the shown level and its facts. */
export interface LevelChangeDetail {
  level: number;
  /** Levels computed so far (0..levelCount−1). */
  levelCount: number;
  scheme: SchemeName;
  modelName: string | null;
  facts: MeshFacts;
}

/** `detail` of `error`. */
export interface ErrorDetail {
  /** SubdivError's code, `load_error` (download, file), or `invalid_attribute`. */
  code: string;
  message: string;
  /** 1-based line in the mesh file, 0 when it does not apply. */
  line: number;
  /** What failed: the URL, file name or attribute. */
  source: string;
}

/** `detail` of `progress`: busy starts and ends (`compute`: a teaching tool's request). */
export interface ProgressDetail {
  busy: boolean;
  kind: 'load' | 'subdivide' | 'compute' | 'export' | null;
  label: string;
}

/** `detail` of `stencil` (tool="stencils"): vertex `vertex` of level `level` as its parents at level − 1 make it. */
export interface StencilDetail {
  level: number;
  vertex: number;
  /** "vertex point", "edge point", "face point", "border vertex", … */
  kind: string;
  parents: { vertex: number; weight: number }[];
}

/** `detail` of `basis` (tool="basis"): control vertex `vertex`'s basis function on level `level`. */
export interface BasisDetail {
  vertex: number;
  level: number;
  /** Vertices of the level it reaches (a weight other than 0), of `count`. */
  reached: number;
  count: number;
  /** Its largest weight. */
  max: number;
}

/** `detail` of `distance` (attribute beside): the symmetric Hausdorff distance between the first two panes' surfaces. */
export interface DistanceDetail {
  distance: number;
  /** `distance` as a share of `diagonal`, the bounding-box diagonal of both surfaces. */
  relative: number;
  diagonal: number;
  /** The distance is within this of the true one (CGAL's bounded-error algorithm). */
  errorBound: number;
  schemes: [string, string];
  levels: [number, number];
}

/** A bad attribute value. */
export class AttributeError extends Error {}

/** The `error` event's detail for a failure about `source`. */
export function errorDetail(source: string, error: unknown): ErrorDetail {
  const message = error instanceof Error ? error.message : String(error);
  const code =
    error instanceof SubdivError
      ? error.code
      : error instanceof LoadError
        ? 'load_error'
        : error instanceof AttributeError
          ? 'invalid_attribute'
          : 'error';
  return {
    code,
    message,
    line: error instanceof SubdivError ? error.line : 0,
    source: error instanceof LoadError ? error.source : source,
  };
}
