/**
 * The one module that owns the WebAssembly instance of the C++ core.
 * `init()` once (idempotent), then call the typed, stateless API: meshes go in
 * and come out as flat typed arrays owned by JS, so nothing needs freeing.
 * Every failure is thrown as a {@link SubdivError} carrying the core's code,
 * message and line. Nothing else in the project imports the module's glue
 * in ./generated/ (scheme-table.ts reads the table set-up writes beside it).
 */

import type { MeshComparison } from './compare';
import type { VertexCurvature } from './curvature';
import createSubdivModule from './generated/subdivlab.mjs';
import type { EulerOperator, EulerResult, HalfedgeTable, Sqrt3Walk } from './halfedges';
import type { Inspection, InspectOptions } from './inspect';
import type {
  LevelView,
  Mesh,
  MeshFacts,
  MeshFormat,
  ReadFormat,
  ReadOptions,
  RenderBuffers,
  SizePrediction,
  SubdivideOptions,
} from './mesh';
import { type CompiledRules, type CompileLimits, compileLimitsFor, compileRuleSet, type RuleSet } from './rule-set';
import type { StencilTable } from './stencils';
import { SubdivError, type SubdivErrorCode } from './subdiv-error';

/** Where the `.wasm` comes from. Without either field the browser fetches the file next to the glue. */
export interface InitSource {
  /** The module's bytes (Node: read from disk; see init-node.ts). */
  wasmBinary?: ArrayBuffer | Uint8Array;
  /** URL of subdivlab.wasm, when it is served from somewhere else (browser or Node). */
  wasmUrl?: string;
  /** The module already compiled (a page compiles it once and hands it to each worker it starts). */
  wasmModule?: WebAssembly.Module;
}

type RawFailure = { ok: false; code: SubdivErrorCode; message: string; line: number };
/** Options as bindings.cpp reads them: custom rules already evaluated into tables. */
type CoreOptions = Omit<SubdivideOptions, 'rules'> & { rules?: CompiledRules };
type RawResult<T> = ({ ok: true } & T) | RawFailure;

/** What bindings.cpp registers; every call returns a result object, never throws. */
interface CoreModule {
  /** A string or its UTF-8 bytes: bindings.cpp has the engine write them into the heap (encodeInto, set). */
  read_mesh(text: string | Uint8Array, format: string, options: ReadOptions): RawResult<{ mesh: Mesh }>;
  write_mesh(
    mesh: Mesh,
    format: string,
    maxChunkBytes: number,
    onChunk: (chunk: Uint8Array) => boolean,
    comment: string,
  ): RawResult<object>;
  subdivide(mesh: Mesh, options: CoreOptions): RawResult<{ mesh: Mesh }>;
  predict_size(mesh: Mesh, options: CoreOptions): RawResult<{ prediction: SizePrediction }>;
  predict_size_of_counts(counts: ClosedMeshCounts, options: CoreOptions): RawResult<{ prediction: SizePrediction }>;
  step_stencils(mesh: Mesh, options: CoreOptions): RawResult<StencilTable>;
  compare_meshes(reference: Mesh, result: Mesh, relativeTolerance: number): RawResult<MeshComparison>;
  inspect_mesh(
    mesh: Mesh,
    selfIntersections: boolean,
    sphere: boolean,
    hull: boolean,
    width: boolean,
    maxPairs: number,
  ): RawResult<Inspection>;
  hausdorff_distance(a: Mesh, b: Mesh, vertexDistances: boolean): RawResult<HausdorffDistance>;
  halfedge_table(mesh: Mesh): RawResult<HalfedgeTable>;
  euler_op(mesh: Mesh, op: string, h: number, h2: number): RawResult<EulerResult>;
  sqrt3_by_hand(mesh: Mesh, steps: number): RawResult<Sqrt3Walk>;
  vertex_curvature(mesh: Mesh): RawResult<VertexCurvature>;
  facts(mesh: Mesh): RawResult<{ facts: MeshFacts }>;
  view_mesh(mesh: Mesh): RawResult<{ facts: MeshFacts; buffers: RenderBuffers }>;
  read_view(text: string | Uint8Array, format: string, options: ReadOptions): RawResult<LevelView>;
  subdivide_view(mesh: Mesh, options: CoreOptions, parent: MeshFacts): RawResult<LevelView>;
  scheme_names(): RawResult<{ names: string[] }>;
  scheme_info(): RawResult<CoreSchemeInfo>;
  check_rules(rules: CompiledRules): RawResult<object>;
  heap_in_use(): number;
  /** The module's memory as bytes (Emscripten replaces the view when the memory grows). */
  HEAP8: Int8Array;
  /** Test hook: only in the test build of the module (wasm target subdivlab_test). */
  throw_for_test?(kind: string): RawFailure;
}

let core: CoreModule | null = null;
let loading: Promise<void> | null = null;

/**
 * Instantiates the WebAssembly core. Safe to call many times: later calls
 * wait for the first. A failed load may be retried.
 */
export function init(source: InitSource = {}): Promise<void> {
  if (core) return Promise.resolve();
  if (!loading) {
    loading = load(source).catch((error: unknown) => {
      loading = null;
      throw error;
    });
  }
  return loading;
}

async function load(source: InitSource): Promise<void> {
  const moduleArgs: Record<string, unknown> = {
    print: () => {},
    printErr: (text: string) => console.warn(`[subdivlab] ${text}`),
  };
  if (source.wasmModule) {
    const compiled = source.wasmModule;
    // The glue never fetches the .wasm here; without locateFile it still resolves its URL
    // against the script's, which in a classic worker started from a blob: (another host,
    // a sandboxed frame) is the blob: URL, no base for a relative URL (TypeError).
    moduleArgs.locateFile = (path: string) => path;
    // Emscripten's hook for instantiating a module it did not fetch; a failure
    // here would leave the glue waiting, so it rejects the load instead.
    let fail: (error: unknown) => void = () => undefined;
    const failed = new Promise<never>((_, reject) => {
      fail = reject;
    });
    moduleArgs.instantiateWasm = (
      imports: WebAssembly.Imports,
      receive: (instance: WebAssembly.Instance, module: WebAssembly.Module) => void,
    ) => {
      WebAssembly.instantiate(compiled, imports).then((instance) => receive(instance, compiled), fail);
      return {};
    };
    core = (await Promise.race([createSubdivModule(moduleArgs), failed])) as CoreModule;
    return;
  }
  if (source.wasmBinary) {
    moduleArgs.wasmBinary = source.wasmBinary;
  } else if (source.wasmUrl) {
    // Fetched here rather than by the glue, whose loader only works in browsers.
    const response = await fetch(source.wasmUrl);
    if (!response.ok) {
      throw new SubdivError('internal_error', `Cannot load ${source.wasmUrl}: HTTP ${response.status}.`);
    }
    moduleArgs.wasmBinary = await response.arrayBuffer();
  }
  // Otherwise the glue resolves `new URL('subdivlab.wasm', import.meta.url)`,
  // which Vite rewrites to the emitted asset in dev, builds and workers alike.
  core = (await createSubdivModule(moduleArgs)) as CoreModule;
}

/** True once {@link init} has finished. */
export function isReady(): boolean {
  return core !== null;
}

function module(): CoreModule {
  if (!core) throw new SubdivError('internal_error', 'The SubdivLab core is not loaded yet: await init() first.');
  return core;
}

function unwrap<T>(result: RawResult<T>): T {
  if (!result.ok) throw new SubdivError(result.code, result.message, result.line);
  return result;
}

/**
 * Parses an OFF, OBJ, PLY or STL file (text or bytes; `'auto'`: the format
 * from the content) into a checked mesh (a valid oriented 2-manifold
 * polygon mesh). OpenSubdiv's tag lines (OBJ `t ...`, OFF `# t ...` after
 * the faces) come back as `mesh.tags`, absent when the file has none; a
 * malformed tag is a `parse_error` on its line. A file of another kind
 * (PNG, PDF, ZIP ...) is a `parse_error` saying what it is.
 */
export function parseMesh(text: string | Uint8Array, format: ReadFormat, options: ReadOptions = {}): Mesh {
  return unwrap(module().read_mesh(text, format, options)).mesh;
}

/**
 * {@link parseMesh} and, in the same call, the mesh's facts and render
 * buffers ({@link viewMesh}): what a viewer shows of a loaded file, with the
 * mesh checked once.
 */
export function parseForView(text: string | Uint8Array, format: ReadFormat, options: ReadOptions = {}): LevelView {
  const { mesh, facts, buffers } = unwrap(module().read_view(text, format, options));
  return { mesh, facts, buffers };
}

/** Default bound of the pieces {@link writeMesh} hands out: 1 MiB. */
export const DEFAULT_CHUNK_BYTES = 1 << 20;
/** Bounds of `chunkBytes` (the largest piece stays far below a JS string's 512 M characters). */
export const MIN_CHUNK_BYTES = 64;
export const MAX_CHUNK_BYTES = 1 << 28;

/**
 * Writes `mesh` as OFF, OBJ or PLY text or binary STL in consecutive pieces of at most
 * `chunkBytes` bytes, each handed to `onChunk` as soon as it is written
 * (ASCII bytes, a copy the caller owns; a piece may end inside a line). The
 * pieces joined are {@link exportMesh}'s text, so a text too large for one
 * string can go to a Blob or a file. Coordinates round-trip exactly (STL:
 * as floats, polygons as fans). An error thrown by `onChunk` stops the
 * writing and is rethrown. A `comment` (e.g. `SubdivLab: cube.off, Loop,
 * level 2`) goes in as the format's comment: `# ...` in OFF (after its
 * first line) and OBJ, `comment ...` in PLY, STL's 80-byte header.
 */
export function writeMesh(
  mesh: Mesh,
  format: MeshFormat,
  onChunk: (chunk: Uint8Array) => void,
  chunkBytes: number = DEFAULT_CHUNK_BYTES,
  comment = '',
): void {
  if (!Number.isInteger(chunkBytes) || chunkBytes < MIN_CHUNK_BYTES || chunkBytes > MAX_CHUNK_BYTES) {
    throw new SubdivError(
      'invalid_argument',
      `chunkBytes must be a whole number from ${MIN_CHUNK_BYTES} to ${MAX_CHUNK_BYTES}, not ${chunkBytes}.`,
    );
  }
  let stopped: { error: unknown } | null = null;
  const result = module().write_mesh(
    mesh,
    format,
    chunkBytes,
    (chunk) => {
      try {
        onChunk(chunk);
        return true;
      } catch (error) {
        stopped = { error };
        return false;
      }
    },
    comment,
  );
  unwrap(result);
  if (stopped) throw (stopped as { error: unknown }).error;
}

/** The pieces of {@link writeMesh}, collected: what an export saves as a Blob. */
export function exportMeshChunks(mesh: Mesh, format: MeshFormat, chunkBytes?: number, comment = ''): Uint8Array[] {
  const chunks: Uint8Array[] = [];
  writeMesh(mesh, format, (chunk) => chunks.push(chunk), chunkBytes, comment);
  return chunks;
}

/**
 * OFF or OBJ text of `mesh` as one string; coordinates and tags round-trip
 * exactly (tags after the faces; in OFF as `# t ...` comments).
 * A text beyond JavaScript's string limit (about 512 M characters) cannot be
 * one string: use {@link writeMesh} or {@link exportMeshChunks} for those.
 */
export function exportMesh(mesh: Mesh, format: MeshFormat): string {
  const decoder = new TextDecoder();
  return exportMeshChunks(mesh, format)
    .map((chunk) => decoder.decode(chunk))
    .join('');
}

/**
 * A new mesh, `options.levels` steps of `options.scheme` from `mesh` (which is
 * not changed). Fails with `not_triangles`, `too_large`, `invalid_mesh`, ...
 * Without `memoryLimitBytes` the limit is what the WebAssembly heap can still take.
 */
export function subdivide(mesh: Mesh, options: SubdivideOptions): Mesh {
  return unwrap(module().subdivide(mesh, coreOptions(mesh, options))).mesh;
}

/**
 * {@link subdivide} and, in the same call, the result's facts and render
 * buffers: what a viewer shows. `parent` is the facts of `mesh`: the
 * result's components and boundary loops are carried from them (every
 * scheme keeps them) and the rest is counted, so no mesh structure is built
 * for the facts; facts that disagree with the counts are computed afresh.
 */
export function subdivideForView(mesh: Mesh, options: SubdivideOptions, parent: MeshFacts): LevelView {
  const { mesh: result, facts, buffers } = unwrap(module().subdivide_view(mesh, coreOptions(mesh, options), parent));
  return { mesh: result, facts, buffers };
}

/**
 * The options as the core takes them: `rules` evaluated into tables large
 * enough for `mesh` (valences and degrees 3..max(64, what the mesh has)).
 */
function coreOptions(mesh: Mesh, options: SubdivideOptions): CoreOptions {
  const { rules, ...rest } = options;
  if (options.scheme === 'custom' && rules === undefined) {
    throw new SubdivError('invalid_argument', 'scheme custom needs a rule set (option rules)');
  }
  if (rules === undefined || options.scheme !== 'custom') return rest;
  const limits = compileLimitsFor(mesh.faceSizes, mesh.faceIndices, Math.floor(mesh.positions.length / 3));
  return { ...rest, rules: compileRuleSet(rules, limits) };
}

/**
 * The stencils of the last step of `subdivide(mesh, options)`: its result's
 * vertices (numbered as that result) as weighted sums of the vertices of
 * the level before (numbered as `subdivide` with one level fewer), from the
 * step's own point pass (stencils.ts).
 */
export function stepStencils(mesh: Mesh, options: SubdivideOptions): StencilTable {
  const { ok: _ok, ...table } = unwrap(module().step_stencils(mesh, coreOptions(mesh, options))) as StencilTable & {
    ok: true;
  };
  return table;
}

/**
 * Checks `result` (a student's level, say) against `reference` (the core's):
 * counts, the faces through a vertex matching (in order where it fits,
 * else nearest points), and each vertex's distance; `relativeTolerance` is
 * a share of the reference's bounding-box diagonal.
 */
export function compareMeshes(reference: Mesh, result: Mesh, relativeTolerance: number): MeshComparison {
  const { ok: _ok, ...comparison } = unwrap(
    module().compare_meshes(reference, result, relativeTolerance),
  ) as MeshComparison & {
    ok: true;
  };
  return comparison;
}

/** The symmetric Hausdorff distance between two surfaces. */
export interface HausdorffDistance {
  distance: number;
  /** The bounding-box diagonal of both together. */
  diagonal: number;
  /** `distance` is within this of the true distance (1e-4 of the diagonal). */
  errorBound: number;
  /** With `vertexDistances`: each vertex of `a` its distance to the surface of `b`, and of `b` to `a`. */
  aToB?: Float64Array;
  bToA?: Float64Array;
}

/**
 * The symmetric Hausdorff distance between `a` and `b` (CGAL's bounded-error
 * algorithm on both triangulated): how far apart two schemes' surfaces are;
 * with `vertexDistances`, also how far each vertex is from the other surface.
 */
export function hausdorffDistance(a: Mesh, b: Mesh, vertexDistances = false): HausdorffDistance {
  const { ok: _ok, ...h } = unwrap(module().hausdorff_distance(a, b, vertexDistances)) as HausdorffDistance & {
    ok: true;
  };
  return h;
}

/** The discrete curvature at every vertex of `mesh` (curvature.ts); NaN at border vertices. */
export function vertexCurvature(mesh: Mesh): VertexCurvature {
  const { ok: _ok, ...c } = unwrap(module().vertex_curvature(mesh)) as VertexCurvature & { ok: true };
  return c;
}

/**
 * CGAL's geometry around `mesh` (inspect.ts): its area, volume and box,
 * and the self-intersections, smallest enclosing sphere, convex hull and
 * minimum width that `options` asks for.
 */
/**
 * The halfedge structure of `mesh` as CGAL's Surface_mesh numbers it
 * (wasm/src/core/halfedges.h): per halfedge its next, prev, opposite,
 * target vertex and face (−1 on the border); opposite(h) is h ^ 1.
 * Throws SubdivError (invalid_mesh) on a mesh that is not valid.
 */
export function halfedgeTable(mesh: Mesh): HalfedgeTable {
  const { ok: _ok, ...table } = unwrap(module().halfedge_table(mesh)) as HalfedgeTable & { ok: true };
  return table;
}

/**
 * Applies CGAL's Euler operator `op` to halfedge `h` of `mesh` (numbered as
 * halfedgeTable numbers them; split_face also takes `h2`, the other corner's
 * halfedge). Throws SubdivError: invalid_argument naming the broken
 * precondition, invalid_mesh for a mesh that is not valid.
 */
export function eulerOperator(mesh: Mesh, op: EulerOperator, h: number, h2 = 0): EulerResult {
  const { ok: _ok, ...result } = unwrap(module().euler_op(mesh, op, h, h2)) as EulerResult & { ok: true };
  return result;
}

/**
 * One √3 step of a closed triangle mesh written with Euler operators (a
 * centre vertex per face, a flip per old edge, the old vertices smoothed),
 * stopped after `steps` operators (Infinity: all; then it equals the √3
 * scheme's level 1).
 */
export function sqrt3ByHand(mesh: Mesh, steps = Number.POSITIVE_INFINITY): Sqrt3Walk {
  const raw = module().sqrt3_by_hand(mesh, Number.isFinite(steps) ? steps : 1e15);
  const { ok: _ok, ...walk } = unwrap(raw) as Sqrt3Walk & { ok: true };
  return walk;
}

export function inspectMesh(mesh: Mesh, options: InspectOptions = {}): Inspection {
  const o = options;
  const raw = module().inspect_mesh(
    mesh,
    o.selfIntersections ?? false,
    o.sphere ?? false,
    o.hull ?? false,
    o.width ?? false,
    o.maxPairs ?? 100,
  );
  const { ok: _ok, ...inspection } = unwrap(raw) as Inspection & { ok: true };
  return inspection;
}

/** Counts and peak heap bytes predicted for `subdivide(mesh, options)`, without subdividing. */
export function predictSize(mesh: Mesh, options: SubdivideOptions): SizePrediction {
  return unwrap(module().predict_size(mesh, coreOptions(mesh, options))).prediction;
}

/** What the core's predict_size_of_counts reads (subdivide.h's Closed_mesh_counts). */
interface ClosedMeshCounts {
  vertices: number;
  edges: number;
  faces: number;
  triangles: number;
  controlEdges: number;
}

/**
 * predictSize for a level that a step with the same options made, whose
 * facts are `facts`: a closed level without tags is predicted from its
 * counts, without copying its arrays into the core and checking them again
 * (its run checked its parent); the same figures. Others go through
 * predictSize, as does one the options would triangulate first.
 */
export function predictSizeOfLevel(mesh: Mesh, facts: MeshFacts, options: SubdivideOptions): SizePrediction {
  const fromFaces = !facts.closed || mesh.tags !== undefined || (options.triangulate && facts.triangles < facts.faces);
  if (fromFaces) return predictSize(mesh, options);
  const counts: ClosedMeshCounts = {
    vertices: facts.vertices,
    edges: facts.edges,
    faces: facts.faces,
    triangles: facts.triangles,
    controlEdges: facts.controlEdges,
  };
  return unwrap(module().predict_size_of_counts(counts, coreOptions(mesh, options))).prediction;
}

/** Vertices, edges, faces, components, boundaries, genus, face kinds, bounding box. */
export function meshFacts(mesh: Mesh): MeshFacts {
  return unwrap(module().facts(mesh)).facts;
}

/** A loaded mesh as a viewer shows it: its facts ({@link meshFacts}) and render buffers. */
export function viewMesh(mesh: Mesh): LevelView {
  const { facts, buffers } = unwrap(module().view_mesh(mesh));
  return { mesh, facts, buffers };
}

/**
 * Checks a rule set as the core will when subdividing, without a mesh: its
 * formulas parse, and, evaluated for valences and degrees 3..64 (or
 * `limits`), every weight is finite and every stencil sums to 1. Throws the
 * same SubdivError as subdivide would ('invalid_argument', naming the rule
 * and the valence or degree).
 */
export function checkRules(rules: RuleSet, limits?: CompileLimits): void {
  unwrap(module().check_rules(compileRuleSet(rules, limits)));
}

/** Scheme names the core knows, in display order. */
export function schemeNames(): string[] {
  return unwrap(module().scheme_names()).names;
}

/** A refinement host, as the core's one table of hosts describes it. */
export interface HostInfo {
  /** 'pqq', 'ptq', 'dqq', 'sqrt3' or 'pqt' (quad-triangle's). */
  name: string;
  /** 'PQQ', 'PTQ', 'DQQ', '√3', 'PQT'. */
  label: string;
  /** Refuses faces other than triangles (the core's not_triangles). */
  needsTriangles: boolean;
  /** Primal: results carry the control mesh's edges. */
  keepsControlEdges: boolean;
  /** Runs on the core's fast refinement hosts. */
  fast: boolean;
  /** The scheme whose counts and memory model a step follows. */
  sizeModel: string;
}

/** What the core knows of its schemes: each scheme's label, host (null for custom: its rule set's) and description. */
export interface CoreSchemeInfo {
  hosts: HostInfo[];
  /** `creases`: the scheme applies a mesh's tags (creases, corners, holes, border modes). */
  schemes: { name: string; label: string; host: string | null; description: string; creases: boolean }[];
}

/** The core's scheme and host table (wasm/src/core/scheme_table.cpp), in display order. */
export function coreSchemeInfo(): CoreSchemeInfo {
  const { hosts, schemes } = unwrap(module().scheme_info());
  return { hosts, schemes };
}

/** The host a step of `scheme` runs on (custom: the rule set's), or undefined for an unknown scheme. */
export function hostOf(scheme: string, rules?: RuleSet | null): HostInfo | undefined {
  const { hosts, schemes } = coreSchemeInfo();
  const name = scheme === 'custom' ? rules?.host : schemes.find((s) => s.name === scheme)?.host;
  return hosts.find((h) => h.name === name);
}

/** Bytes allocated in the WebAssembly heap right now (for leak checks). */
export function heapBytesInUse(): number {
  return module().heap_in_use();
}

/** The core's memory: bytes allocated in its heap, and the WebAssembly memory's size (it only grows). */
export interface CoreMemory {
  heapInUse: number;
  memoryBytes: number;
}

export function coreMemory(): CoreMemory {
  return { heapInUse: module().heap_in_use(), memoryBytes: module().HEAP8.length };
}

/**
 * Test hook: throws, inside the core's guard, a CGAL precondition failure
 * (`'cgal'`), a std::exception (`'std'`), a failed allocation (`'alloc'`) or
 * something else (`'other'`), and throws the SubdivError it comes back as.
 */
export function throwForTesting(kind: 'cgal' | 'std' | 'alloc' | 'other'): never {
  unwrap(testHook('throw_for_test')(kind));
  throw new Error('throw_for_test returned without an error');
}

/** A test hook of the module, which only its test build has (the one vitest loads). */
function testHook<K extends 'throw_for_test'>(name: K): NonNullable<CoreModule[K]> {
  const hook = module()[name];
  if (!hook) throw new Error(`${name} is a test hook: load the test build of the core (build/wasm/test-module/)`);
  return hook.bind(module()) as NonNullable<CoreModule[K]>;
}

/** `'off'`, `'obj'`, `'ply'` or `'stl'` from a file name's extension (any case), otherwise null. */
export function formatFromFileName(name: string): MeshFormat | null {
  const match = /\.(off|obj|ply|stl)$/i.exec(name.trim());
  return match ? (match[1].toLowerCase() as MeshFormat) : null;
}
