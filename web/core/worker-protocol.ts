/**
 * Messages between the page (worker-client.ts) and the core's Web Worker
 * (subdiv-worker.ts). The worker keeps every level's mesh; the page holds
 * a handle to it with what the page needs to show it (facts, render
 * buffers, control edges), transferred, not copied. A step sends a handle
 * and gets the new level back.
 */
import type { StepOptions } from './basis';
import type { MeshComparison } from './compare';
import type { VertexCurvature } from './curvature';
import type { EulerOperator, EulerResult, HalfedgeTable, Sqrt3Walk } from './halfedges';
import type { Inspection, InspectOptions } from './inspect';
import type {
  Mesh,
  MeshFacts,
  MeshFormat,
  MeshTags,
  ReadFormat,
  ReadOptions,
  RenderBuffers,
  SizePrediction,
  SubdivideOptions,
} from './mesh';
import type { RuleSet } from './rule-set';
import type { StencilTable } from './stencils';
import type { CoreMemory, HausdorffDistance } from './subdiv-core';
import type { SubdivErrorCode } from './subdiv-error';

/**
 * A mesh kept by the worker. `epoch` counts the workers the client has
 * started: a handle of an earlier one names nothing (the worker restarted
 * after a cancel or a crash, and its levels went with it).
 */
export interface LevelHandle {
  epoch: number;
  id: number;
}

/** One level as the page keeps it: its handle in the worker, its facts and what the GPU draws. */
export interface LevelData {
  handle: LevelHandle;
  facts: MeshFacts;
  buffers: RenderBuffers;
  /** The level's marked control edges (vertex index pairs; may be empty). */
  controlEdges: Uint32Array;
  /** The level's creases, corners and holes (OpenSubdiv's tags, a copy), or null when it has none. */
  tags: MeshTags | null;
  /** Milliseconds the core spent on the step, its facts and render buffers included (0 for a loaded mesh). */
  ms: number;
  /**
   * Which way the faces of a closed, one-piece level turn (+1 outward, −1 inward; 0: open, several
   * pieces or flat). The view then draws only the faces turned to the camera.
   */
  orientation: -1 | 0 | 1;
}

/** A √3 walk-through's state, with the check against the scheme once every operator is done. */
export interface Sqrt3Check extends Sqrt3Walk {
  comparison: MeshComparison | null;
}

/** Requests the worker understands, by kind. */
export interface WorkerRequests {
  /** Loads the WASM core (from the page's compiled module when given); answers the scheme names. */
  init: { args: { module?: WebAssembly.Module | null; epoch: number }; result: string[] };
  /** Parses an OFF/OBJ/PLY/STL file (text or bytes) into a kept level 0; answers it with its mesh (the page keeps level 0 to restore it). */
  parse: {
    args: { text: string | Uint8Array; format: ReadFormat; options?: ReadOptions };
    result: { level: LevelData; mesh: Mesh };
  };
  /** Keeps a mesh the page already has as a level 0, with its facts and render buffers. */
  prepare: { args: { mesh: Mesh }; result: LevelData };
  /** Keeps a mesh again whose facts the page has (after the worker restarted); answers its handle. */
  keep: { args: { mesh: Mesh; facts: MeshFacts }; result: LevelHandle };
  /** One or more steps of a scheme from a kept level; keeps the result. */
  subdivide: { args: { handle: LevelHandle; options: SubdivideOptions }; result: LevelData };
  /** The stencils of a step from a kept level (its result's vertices from the level's), without keeping the result. */
  stencils: { args: { handle: LevelHandle; options: SubdivideOptions }; result: StencilTable };
  /** A control vertex's basis function at level `levels` (basis.ts), from a kept level 0. */
  basis: { args: { handle: LevelHandle; vertex: number; levels: number; options: StepOptions }; result: Float64Array };
  /** The points of a step from a kept level (float32, as drawn), without keeping the result. */
  points: { args: { handle: LevelHandle; options: SubdivideOptions }; result: Float32Array };
  /** Parses a result (OFF/OBJ text) and checks it against a kept level (compare.ts). */
  compare: {
    args: { handle: LevelHandle; text: string | Uint8Array; format: ReadFormat; tolerance: number };
    result: MeshComparison;
  };
  /** The symmetric Hausdorff distance between two kept levels, with each vertex's distance to the other surface. */
  hausdorff: { args: { a: LevelHandle; b: LevelHandle }; result: HausdorffDistance };
  /** CGAL's geometry around a kept level (inspect.ts): its measures and what `options` asks for. */
  inspect: { args: { handle: LevelHandle; options: InspectOptions }; result: Inspection };
  /** The discrete curvature at each vertex of a kept level (curvature.ts). */
  curvature: { args: { handle: LevelHandle }; result: VertexCurvature };
  /** Predicted counts and peak bytes of a step from a kept level, without subdividing. */
  predict: { args: { handle: LevelHandle; options: SubdivideOptions }; result: SizePrediction };
  /** The file of a kept level (OFF/OBJ/PLY text, binary STL) with `comment` in it, as the pieces of writeMesh (transferred; a file may exceed one string's limit). */
  export: { args: { handle: LevelHandle; format: MeshFormat; comment?: string }; result: Uint8Array[] };
  /** A copy of a kept level's mesh. */
  mesh: { args: { handle: LevelHandle }; result: Mesh };
  /** The halfedge table of a kept level, numbered as CGAL's Surface_mesh numbers it (halfedges.ts). */
  halfedges: { args: { handle: LevelHandle }; result: HalfedgeTable };
  /** CGAL's Euler operator `op` on halfedge `h` (and `h2` for split_face) of `mesh`: the edited mesh, not kept. */
  euler: { args: { mesh: Mesh; op: EulerOperator; h: number; h2: number }; result: EulerResult };
  /**
   * One √3 step of `mesh` by Euler operators stopped after `steps` of them; once all are done, the
   * comparison (compare.ts, 1e-12) of the result with the √3 scheme's level 1 of `mesh`, else null.
   */
  sqrt3ByHand: { args: { mesh: Mesh; steps: number }; result: Sqrt3Check };
  /** Forgets kept levels (handles of an earlier worker are ignored). */
  release: { args: { handles: LevelHandle[] }; result: null };
  /** The core's verdict on a custom rule set, without a mesh: answers null or fails with its SubdivError. */
  checkRules: { args: { rules: RuleSet }; result: null };
  /** The core's memory and the number of levels the worker keeps (for the long-session tests and the curious). */
  memory: { args: Record<string, never>; result: WorkerMemory };
  /**
   * Test hook: crashes the worker as a WebAssembly trap does (`trap`: a real `unreachable`, thrown out
   * of the request) or as a bug outside any request does (`uncaught`: the worker's error event, no
   * answer). The page must replace the worker and keep its levels (worker-client.ts). With `during`,
   * answers null at once and crashes at the start of the next request of that kind instead.
   */
  crashForTest: { args: { how: CrashKind; during?: WorkerRequestKind }; result: null };
}

/** How crashForTest crashes the worker. */
export type CrashKind = 'trap' | 'uncaught';

/** What a `memory` request answers. */
export interface WorkerMemory extends CoreMemory {
  keptLevels: number;
}

export type WorkerRequestKind = keyof WorkerRequests;

export interface WorkerRequestMessage<K extends WorkerRequestKind = WorkerRequestKind> {
  id: number;
  kind: K;
  args: WorkerRequests[K]['args'];
}

/** The error as data: SubdivError fields, or a plain Error's message with code internal_error. */
export interface WorkerErrorData {
  code: SubdivErrorCode;
  message: string;
  line: number;
}

/** `fatal`: the worker crashed while answering (worker-client.ts replaces it). */
export type WorkerResponseMessage =
  | { id: number; ok: true; value: unknown }
  | { id: number; ok: false; error: WorkerErrorData; fatal?: true };
