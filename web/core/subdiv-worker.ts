/**
 * The Web Worker that runs the WASM core off the main thread, so the page
 * stays responsive during a long step. It imports the core's TS API only
 * (never ./generated/), answers one request at a time and transfers results.
 */
import {
  checkRules,
  exportMeshChunks,
  init,
  parseMesh,
  predictSize,
  schemeNames,
  subdivideForView,
  viewMesh,
} from './subdiv-core';
import { SubdivError } from './subdiv-error';
import type {
  LevelData,
  WorkerRequestKind,
  WorkerRequestMessage,
  WorkerRequests,
  WorkerResponseMessage,
} from './worker-protocol';

/** The part of DedicatedWorkerGlobalScope this file uses (tsconfig has DOM types, not WebWorker). */
interface WorkerScope {
  onmessage: ((event: MessageEvent<WorkerRequestMessage>) => void) | null;
  postMessage(message: WorkerResponseMessage, options?: { transfer?: Transferable[] }): void;
}
const scope = self as unknown as WorkerScope;

/** Each distinct ArrayBuffer under a LevelData, for the transfer list. */
function buffersOf(level: LevelData): Transferable[] {
  const arrays = [
    level.mesh.positions,
    level.mesh.faceSizes,
    level.mesh.faceIndices,
    level.mesh.controlEdges,
    level.buffers.positions,
    level.buffers.normals,
    level.buffers.triangles,
    level.buffers.edges,
    level.buffers.triangleFace,
  ];
  return [...new Set(arrays.map((a) => a.buffer as ArrayBuffer))];
}

type Handlers = {
  [K in WorkerRequestKind]: (args: WorkerRequests[K]['args']) => Promise<WorkerRequests[K]['result']>;
};

const handlers: Handlers = {
  async init({ module }) {
    await init(module ? { wasmModule: module } : {});
    return schemeNames();
  },
  async parse({ text, format }) {
    await init();
    return { ...viewMesh(parseMesh(text, format)), ms: 0 };
  },
  async prepare({ mesh }) {
    await init();
    return { ...viewMesh(mesh), ms: 0 };
  },
  async subdivide({ mesh, options, parent }) {
    await init();
    const start = performance.now();
    const level = subdivideForView(mesh, options, parent);
    return { ...level, ms: performance.now() - start };
  },
  async predict({ mesh, options }) {
    await init();
    return predictSize(mesh, options);
  },
  async export({ mesh, format }) {
    await init();
    return exportMeshChunks(mesh, format);
  },
  async checkRules({ rules }) {
    await init();
    checkRules(rules);
    return null;
  },
};

scope.onmessage = async (event) => {
  const { id, kind, args } = event.data;
  try {
    const handler = handlers[kind] as (a: typeof args) => Promise<unknown>;
    const value = await handler(args);
    const transfer = isLevelData(value) ? buffersOf(value) : isChunkList(value) ? value.map((c) => c.buffer) : [];
    scope.postMessage({ id, ok: true, value }, { transfer });
  } catch (error) {
    const data =
      error instanceof SubdivError
        ? { code: error.code, message: error.message, line: error.line }
        : { code: 'internal_error' as const, message: error instanceof Error ? error.message : String(error), line: 0 };
    scope.postMessage({ id, ok: false, error: data });
  }
};

/** An export's pieces: each owns its buffer (copied out of the heap), so all can be transferred. */
function isChunkList(value: unknown): value is Uint8Array[] {
  return Array.isArray(value) && value.every((chunk) => chunk instanceof Uint8Array);
}

function isLevelData(value: unknown): value is LevelData {
  return typeof value === 'object' && value !== null && 'buffers' in value && 'mesh' in value;
}
