/**
 * Messages between the page (worker-client.ts) and the core's Web Worker
 * (subdiv-worker.ts). Meshes cross as flat typed arrays; results are
 * transferred, not copied.
 */
import type { LevelView, Mesh, MeshFacts, MeshFormat, SizePrediction, SubdivideOptions } from './mesh';
import type { RuleSet } from './rule-set';
import type { SubdivErrorCode } from './subdiv-error';

/** One level as the viewer keeps it: the mesh, its facts and what the GPU draws. */
export interface LevelData extends LevelView {
  /** Milliseconds the core spent on the step, its facts and render buffers included (0 for a loaded mesh). */
  ms: number;
}

/** Requests the worker understands, by kind. */
export interface WorkerRequests {
  /** Loads the WASM core (from the page's compiled module when given); answers the scheme names. */
  init: { args: { module?: WebAssembly.Module | null }; result: string[] };
  /** Parses OFF/OBJ text into a level-0 LevelData. */
  parse: { args: { text: string; format: MeshFormat }; result: LevelData };
  /** Facts and render buffers of a mesh the page already has. */
  prepare: { args: { mesh: Mesh }; result: LevelData };
  /** One or more steps of a scheme from a mesh whose facts are `parent`. */
  subdivide: { args: { mesh: Mesh; options: SubdivideOptions; parent: MeshFacts }; result: LevelData };
  /** Predicted counts and peak bytes of a step, without subdividing. */
  predict: { args: { mesh: Mesh; options: SubdivideOptions }; result: SizePrediction };
  /** OFF/OBJ text of a mesh, as the pieces of writeMesh (transferred; a text may exceed one string's limit). */
  export: { args: { mesh: Mesh; format: MeshFormat }; result: Uint8Array[] };
  /** The core's verdict on a custom rule set, without a mesh: answers null or fails with its SubdivError. */
  checkRules: { args: { rules: RuleSet }; result: null };
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

export type WorkerResponseMessage =
  | { id: number; ok: true; value: unknown }
  | { id: number; ok: false; error: WorkerErrorData };
