/**
 * The Web Worker that runs the WASM core off the main thread, so the page
 * stays responsive during a long step. It keeps the mesh of every level the
 * page shows (the page holds handles), imports the core's TS API only
 * (never ./generated/), answers one request at a time and transfers results.
 */
import { basisFunction } from './basis';
import { curvatureBuffers } from './curvature';
import { inspectionBuffers } from './inspect';
import type { Mesh, MeshFacts, MeshTags, RenderBuffers } from './mesh';
import { orientation } from './orientation';
import {
  checkRules,
  compareMeshes,
  coreMemory,
  eulerOperator,
  exportMeshChunks,
  halfedgeTable,
  hausdorffDistance,
  init,
  inspectMesh,
  parseForView,
  parseMesh,
  predictSize,
  predictSizeOfLevel,
  schemeNames,
  sqrt3ByHand,
  stepStencils,
  subdivide,
  subdivideForView,
  vertexCurvature,
  viewMesh,
} from './subdiv-core';
import { SubdivError } from './subdiv-error';
import { vertexSources } from './vertex-lines';
import type {
  CrashKind,
  LevelData,
  LevelHandle,
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

/** The levels kept for the page, by handle id; `epoch` is this worker's, from init. */
/** The √3 walk-through's check: a share of the bounding-box diagonal, as the native tests use. */
const SQRT3_TOLERANCE = 1e-12;

const kept = new Map<number, KeptLevel>();
let epoch = -1;
let nextId = 1;

interface KeptLevel {
  mesh: Mesh;
  facts: MeshFacts;
  /** Worked out once for level 0: every scheme keeps the way faces turn. */
  orientation: -1 | 0 | 1;
  /** Made by a step here (its next step is predicted from its facts when it can be: predictSizeOfLevel). */
  stepped?: boolean;
}

function keep(level: KeptLevel): LevelHandle {
  const id = nextId++;
  kept.set(id, level);
  return { epoch, id };
}

function keptLevel(handle: LevelHandle): KeptLevel {
  const level = handle.epoch === epoch ? kept.get(handle.id) : undefined;
  if (!level) throw new SubdivError('internal_error', `Level ${handle.epoch}/${handle.id} is not kept by the core.`);
  return level;
}

/** Keeps the mesh; the page gets the rest, its control edges as a copy (the kept mesh keeps its own). */
function levelData(level: KeptLevel, buffers: RenderBuffers, ms: number): LevelData {
  const { mesh, facts } = level;
  return {
    handle: keep(level),
    facts,
    buffers,
    controlEdges: mesh.controlEdges.slice(),
    tags: mesh.tags ? copyOfTags(mesh.tags) : null,
    ms,
    orientation: level.orientation,
  };
}

/** Each distinct ArrayBuffer under a LevelData, for the transfer list. */
function buffersOf(level: LevelData): Transferable[] {
  const { positions, boundingSphere, normals, triangles, edges, triangleFace, borderEdges } = level.buffers;
  const arrays: ArrayBufferView[] = [positions, boundingSphere, normals, triangles, edges, triangleFace, borderEdges];
  arrays.push(level.controlEdges, ...tagArrays(level.tags));
  return [...new Set(arrays.map((a) => a.buffer as ArrayBuffer))];
}

function meshBuffers(mesh: Mesh): Transferable[] {
  const arrays: ArrayBufferView[] = [mesh.positions, mesh.faceSizes, mesh.faceIndices, mesh.controlEdges];
  arrays.push(...tagArrays(mesh.tags ?? null));
  return [...new Set(arrays.map((a) => a.buffer as ArrayBuffer))];
}

/** The typed arrays of a mesh's tags (none without tags). */
function tagArrays(tags: MeshTags | null): ArrayBufferView[] {
  if (!tags) return [];
  return [tags.creaseEdges, tags.creaseSharpness, tags.cornerVertices, tags.cornerSharpness, tags.holes];
}

function copyOfTags(tags: MeshTags): MeshTags {
  return {
    ...tags,
    creaseEdges: tags.creaseEdges.slice(),
    creaseSharpness: tags.creaseSharpness.slice(),
    cornerVertices: tags.cornerVertices.slice(),
    cornerSharpness: tags.cornerSharpness.slice(),
    holes: tags.holes.slice(),
    notes: [...tags.notes],
  };
}

function copyOf(mesh: Mesh): Mesh {
  const copy: Mesh = {
    positions: mesh.positions.slice(),
    faceSizes: mesh.faceSizes.slice(),
    faceIndices: mesh.faceIndices.slice(),
    controlEdges: mesh.controlEdges.slice(),
  };
  if (mesh.tags) copy.tags = copyOfTags(mesh.tags);
  return copy;
}

type Handlers = {
  [K in WorkerRequestKind]: (
    args: WorkerRequests[K]['args'],
  ) => Promise<{ value: WorkerRequests[K]['result']; transfer: Transferable[] }>;
};

const handlers: Handlers = {
  async init({ module, epoch: given }) {
    await init(module ? { wasmModule: module } : {});
    epoch = given;
    return { value: schemeNames(), transfer: [] };
  },
  async parse({ text, format, options }) {
    await init();
    const { mesh, facts, buffers } = parseForView(text, format, options);
    const level = levelData({ mesh, facts, orientation: orientation(mesh, facts) }, buffers, 0);
    const copy = copyOf(mesh);
    return { value: { level, mesh: copy }, transfer: [...buffersOf(level), ...meshBuffers(copy)] };
  },
  async prepare({ mesh }) {
    await init();
    const { facts, buffers } = viewMesh(mesh);
    const level = levelData({ mesh, facts, orientation: orientation(mesh, facts) }, buffers, 0);
    return { value: level, transfer: buffersOf(level) };
  },
  async keep({ mesh, facts }) {
    return { value: keep({ mesh, facts, orientation: orientation(mesh, facts) }), transfer: [] };
  },
  async subdivide({ handle, options }) {
    await init();
    const parent = keptLevel(handle);
    const start = performance.now();
    const { mesh, facts, buffers } = subdivideForView(parent.mesh, options, parent.facts);
    const level = levelData(
      { mesh, facts, orientation: parent.orientation, stepped: true },
      buffers,
      performance.now() - start,
    );
    return { value: level, transfer: buffersOf(level) };
  },
  async stencils({ handle, options }) {
    await init();
    const table = stepStencils(keptLevel(handle).mesh, options);
    const arrays = [table.offsets, table.parents, table.weights, table.kinds, table.elements, table.sizes, table.ends];
    return { value: table, transfer: arrays.map((a) => a.buffer) };
  },
  async basis({ handle, vertex, levels, options }) {
    await init();
    const values = basisFunction(keptLevel(handle).mesh, vertex, levels, options);
    return { value: values, transfer: [values.buffer] };
  },
  async points({ handle, options }) {
    await init();
    const points = Float32Array.from(subdivide(keptLevel(handle).mesh, options).positions);
    return { value: points, transfer: [points.buffer] };
  },
  async compare({ handle, text, format, tolerance }) {
    await init();
    const result = parseMesh(text, format);
    const comparison = compareMeshes(keptLevel(handle).mesh, result, tolerance);
    // The worst vertices as the file has them: their lines and numbers there.
    const sources = vertexSources(text, format);
    if (sources && sources.vertices.length === result.positions.length / 3) {
      comparison.fileFormat = sources.format;
      for (const w of comparison.worst) Object.assign(w, sources.vertices[w.vertex]);
    }
    return { value: comparison, transfer: [comparison.matched.buffer, comparison.errors.buffer] };
  },
  async hausdorff({ a, b }) {
    await init();
    const h = hausdorffDistance(keptLevel(a).mesh, keptLevel(b).mesh, true);
    return { value: h, transfer: [h.aToB, h.bToA].flatMap((d) => (d ? [d.buffer] : [])) };
  },
  async inspect({ handle, options }) {
    await init();
    const inspection = inspectMesh(keptLevel(handle).mesh, options);
    return { value: inspection, transfer: inspectionBuffers(inspection) };
  },
  async curvature({ handle }) {
    await init();
    const curvature = vertexCurvature(keptLevel(handle).mesh);
    return { value: curvature, transfer: curvatureBuffers(curvature) };
  },
  async predict({ handle, options }) {
    await init();
    const level = keptLevel(handle);
    const prediction = level.stepped
      ? predictSizeOfLevel(level.mesh, level.facts, options)
      : predictSize(level.mesh, options);
    return { value: prediction, transfer: [] };
  },
  async export({ handle, format, comment }) {
    await init();
    // Each piece owns its buffer (copied out of the heap), so all can be transferred.
    const chunks = exportMeshChunks(keptLevel(handle).mesh, format, undefined, comment);
    return { value: chunks, transfer: chunks.map((c) => c.buffer) };
  },
  async mesh({ handle }) {
    const copy = copyOf(keptLevel(handle).mesh);
    return { value: copy, transfer: meshBuffers(copy) };
  },
  async halfedges({ handle }) {
    await init();
    const table = halfedgeTable(keptLevel(handle).mesh);
    const arrays = [table.next, table.prev, table.opposite, table.target, table.face];
    return { value: table, transfer: arrays.map((a) => a.buffer as ArrayBuffer) };
  },
  async euler({ mesh, op, h, h2 }) {
    await init();
    const result = eulerOperator(mesh, op, h, h2);
    return { value: result, transfer: meshBuffers(result.mesh) };
  },
  async sqrt3ByHand({ mesh, steps }) {
    await init();
    const walk = sqrt3ByHand(mesh, steps);
    const comparison =
      walk.done === walk.total
        ? compareMeshes(subdivide(mesh, { scheme: 'sqrt3', levels: 1 }), walk.mesh, SQRT3_TOLERANCE)
        : null;
    const transfer = [
      ...meshBuffers(walk.mesh),
      ...(comparison ? [comparison.matched.buffer, comparison.errors.buffer] : []),
    ];
    return { value: { ...walk, comparison }, transfer };
  },
  async release({ handles }) {
    for (const h of handles) if (h.epoch === epoch) kept.delete(h.id);
    return { value: null, transfer: [] };
  },
  async checkRules({ rules }) {
    await init();
    checkRules(rules);
    return { value: null, transfer: [] };
  },
  async memory() {
    await init();
    return { value: { ...coreMemory(), keptLevels: kept.size }, transfer: [] };
  },
  async crashForTest({ how, during }) {
    if (during) {
      crashDuring = { how, kind: during };
      return { value: null, transfer: [] };
    }
    return crash(how);
  },
};

/** The request kind crashForTest armed, and how it crashes. */
let crashDuring: { how: CrashKind; kind: WorkerRequestKind } | null = null;

function crash(how: CrashKind): Promise<never> {
  if (how === 'uncaught') {
    // Thrown outside any request, as a bug in the worker's own code would be: the page gets the
    // worker's error event, and the request no answer.
    setTimeout(() => {
      throw new Error('uncaught error raised by crashForTest');
    });
    return new Promise<never>(() => {});
  }
  // A real WebAssembly trap (an `unreachable` instruction), as the core's own traps arrive.
  trap();
}

/** Module bytes of `(func (export "trap") unreachable)`. */
const TRAP_MODULE = new Uint8Array([
  0x00, 0x61, 0x73, 0x6d, 0x01, 0x00, 0x00, 0x00, 0x01, 0x04, 0x01, 0x60, 0x00, 0x00, 0x03, 0x02, 0x01, 0x00, 0x07,
  0x08, 0x01, 0x04, 0x74, 0x72, 0x61, 0x70, 0x00, 0x00, 0x0a, 0x05, 0x01, 0x03, 0x00, 0x00, 0x0b,
]);

function trap(): never {
  const instance = new WebAssembly.Instance(new WebAssembly.Module(TRAP_MODULE));
  (instance.exports.trap as () => void)();
  throw new Error('the trap did not trap');
}

scope.onmessage = async (event) => {
  const { id, kind, args } = event.data;
  try {
    if (crashDuring?.kind === kind) {
      const { how } = crashDuring;
      crashDuring = null;
      await crash(how);
    }
    const handler = handlers[kind] as (a: typeof args) => Promise<{ value: unknown; transfer: Transferable[] }>;
    const { value, transfer } = await handler(args);
    scope.postMessage({ id, ok: true, value }, { transfer });
  } catch (error) {
    if (error instanceof SubdivError) {
      scope.postMessage({ id, ok: false, error: { code: error.code, message: error.message, line: error.line } });
      return;
    }
    // Anything else is a crash: a WebAssembly trap or abort (the core's instance may be broken), memory
    // the worker could not get, a bug. The page replaces this worker (worker-client.ts).
    const message = error instanceof Error ? `${error.name}: ${error.message}` : String(error);
    scope.postMessage({ id, ok: false, error: { code: 'internal_error', message, line: 0 }, fatal: true });
  }
};
