/**
 * Typed, promise-based access to the core running in a Web Worker, shared
 * by every viewer of a page: one worker, one WebAssembly instance, the
 * `.wasm` fetched and compiled once on the page and handed to each worker
 * it starts. Each viewer talks through its own {@link CoreSession}; the
 * client sends one request at a time, so cancelling a session drops its
 * queued requests and, only when its request is the one running, restarts
 * the worker (a WASM call cannot be interrupted) and goes on with the other
 * sessions' requests.
 */
import type { StepOptions } from './basis';
import type { MeshComparison } from './compare';
import type { VertexCurvature } from './curvature';
import type { EulerOperator, EulerResult, HalfedgeTable } from './halfedges';
import type { Inspection, InspectOptions } from './inspect';
import type { Mesh, MeshFacts, MeshFormat, ReadFormat, ReadOptions, SizePrediction, SubdivideOptions } from './mesh';
import type { RuleSet } from './rule-set';
import type { StencilTable } from './stencils';
import type { HausdorffDistance } from './subdiv-core';
import { SubdivError } from './subdiv-error';
import workerUrl from './subdiv-worker.ts?worker&url';
import type {
  CrashKind,
  LevelData,
  LevelHandle,
  Sqrt3Check,
  WorkerMemory,
  WorkerRequestKind,
  WorkerRequestMessage,
  WorkerRequests,
  WorkerResponseMessage,
} from './worker-protocol';

export type { LevelData, LevelHandle, WorkerMemory } from './worker-protocol';

/** Rejection of requests that were running or queued when their session was cancelled. */
export class CancelledError extends Error {
  constructor() {
    super('Cancelled.');
    this.name = 'CancelledError';
  }
}

/**
 * Rejection of a request about a level the worker no longer keeps: it
 * restarted (a cancel or a crash) since the level was made. The caller keeps
 * it again (level 0) or recomputes it, then asks again.
 */
export class StaleLevelError extends Error {
  constructor() {
    super('The core restarted since this level was made.');
    this.name = 'StaleLevelError';
  }
}

/**
 * Rejection of the request that was running when the worker crashed (a
 * WebAssembly trap or abort, memory it could not get, its error event). The
 * client has already started a new worker; the levels the page shows are
 * kept and made again in it when used (StaleLevelError).
 */
export class CoreCrashedError extends SubdivError {
  constructor(
    /** The request that was running (null: none). */
    readonly request: WorkerRequestKind | null,
    /** What the worker said, or the error event's message. */
    readonly reason: string,
  ) {
    super('internal_error', `The SubdivLab core ${crashSummary(request, reason)}`);
    this.name = 'CoreCrashedError';
  }

  /** The message without its subject, "The SubdivLab core", for a banner that names it. */
  get summary(): string {
    return crashSummary(this.request, this.reason);
  }
}

/**
 * Rejection of every request when the core could not be started: its worker
 * failed before answering anything (a script that did not load, a policy
 * that refuses workers), or loading the core in it failed (the `.wasm` not
 * fetched). Not a crash: nothing ran in it and no level was lost. The client
 * does not try again, as it would fail the same way; the page says once why.
 */
export class CoreStartError extends SubdivError {
  constructor(
    /** Why, as the browser or the worker said it, with what the page or its host can do. */
    readonly reason: string,
  ) {
    super('internal_error', `The SubdivLab core could not be started: ${reason}`);
    this.name = 'CoreStartError';
  }
}

/**
 * Why a worker that answered nothing failed: the error event's message when
 * there is one (a worker that threw while loading), otherwise its script did
 * not load; in a sandboxed frame (an opaque origin) what such a frame needs.
 */
function startFailureReason(message: string): string {
  const why = message || 'its worker script did not load';
  const where =
    globalThis.origin === 'null'
      ? ' This page is in a sandboxed frame (an opaque origin): the frame needs sandbox="allow-scripts" and, under a Content-Security-Policy, worker-src blob: and script-src for the SubdivLab host.'
      : ' Check that the files beside subdiv-viewer.js (assets/) are served, and that a Content-Security-Policy allows the worker (worker-src).';
  return `${why}.${where}`;
}

function crashSummary(request: WorkerRequestKind | null, reason: string): string {
  const doing = request ? ` while ${DOING[request] ?? `answering a ${request} request`}` : '';
  return `stopped unexpectedly${doing} (${reason}). A new one was started; the levels already shown are kept.`;
}

/** What the worker was doing, by request, for the crash message. */
const DOING: Partial<Record<WorkerRequestKind, string>> = {
  init: 'loading',
  parse: 'reading a file',
  prepare: 'preparing a mesh',
  keep: 'keeping a level again',
  subdivide: 'subdividing',
  stencils: 'working out stencils',
  basis: 'computing a basis function',
  points: 'computing points',
  compare: 'checking a result',
  hausdorff: 'measuring a distance',
  inspect: 'inspecting the mesh',
  curvature: 'computing curvature',
  predict: "predicting the next step's size",
  export: 'writing a file',
  mesh: 'copying a level',
  halfedges: 'listing halfedges',
  euler: 'applying an Euler operator',
  sqrt3ByHand: 'running √3 by hand',
  crashForTest: 'running a crash test',
};

/** Makes the worker; the default one is bundled by Vite from subdiv-worker.ts. */
export type WorkerFactory = () => Worker;

/**
 * The bundled worker: a classic script in builds (`worker.format: 'iife'` in
 * both Vite configs); Vite's dev server serves it as a module whatever the
 * format.
 */
const defaultFactory: WorkerFactory = () =>
  startWorker(new URL(workerUrl, import.meta.url), import.meta.env.DEV ? 'module' : 'classic');

/**
 * Starts the worker script at `url`. Browsers start workers only from the
 * page's own origin: from another host (a course page pointing at wherever
 * SubdivLab is hosted, or a sandboxed frame, whose origin is opaque) a
 * same-origin `blob:` worker runs `importScripts(url)`, which needs no CORS.
 * A classic shim, not a module one: Chromium refuses a module worker from a
 * `blob:` URL in an opaque origin (`sandbox="allow-scripts"`), and an import
 * would need CORS.
 */
export function startWorker(url: URL, type: WorkerType = 'classic'): Worker {
  const options: WorkerOptions = { name: 'subdivlab-core', type };
  // The document's origin, not its URL's: a sandboxed frame's is opaque ('null') whatever its URL.
  if (url.origin === self.origin) return new Worker(url, options);
  const load =
    type === 'module' ? `import ${JSON.stringify(url.href)};` : `importScripts(${JSON.stringify(url.href)});`;
  return new Worker(URL.createObjectURL(new Blob([load], { type: 'text/javascript' })), options);
}

/** Where the page fetches the core's `.wasm` (Vite rewrites the URL to the emitted asset). */
const WASM_URL = new URL('./generated/subdivlab.wasm', import.meta.url).href;

/**
 * Fetches and compiles the core once. Streaming compilation needs the
 * server to send `application/wasm`; a static host that does not gets the
 * slower path instead of a failure.
 */
async function compileCore(url: string): Promise<WebAssembly.Module> {
  const response = await fetch(url, { credentials: 'same-origin' });
  if (!response.ok) throw new SubdivError('internal_error', `Cannot load the core (${url}): HTTP ${response.status}.`);
  if (response.headers.get('content-type')?.startsWith('application/wasm')) {
    return WebAssembly.compileStreaming(response);
  }
  return WebAssembly.compile(await response.arrayBuffer());
}

interface Queued {
  id: number;
  session: CoreSession;
  kind: WorkerRequestKind;
  args: unknown;
  resolve: (value: unknown) => void;
  reject: (error: Error) => void;
}

/** The page's core: one worker, shared by the sessions it hands out. */
export class WorkerClient {
  private worker: Worker | null = null;
  private readonly queue: Queued[] = [];
  private running: Queued | null = null;
  private nextId = 1;
  private readonly module: Promise<WebAssembly.Module | null>;
  private schemes: Promise<string[]>;
  private disposed = false;
  private workerEpoch = 0;
  private readonly crashListeners = new Set<(error: CoreCrashedError) => void>();
  /** Set once the core could not be started: every request rejects with it. */
  private startFailure: CoreStartError | null = null;

  /**
   * @param factory makes a worker (tests pass their own).
   * @param wasmUrl where the `.wasm` is; null lets each worker fetch it itself.
   */
  constructor(
    private readonly factory: WorkerFactory = defaultFactory,
    wasmUrl: string | null = WASM_URL,
  ) {
    this.module = wasmUrl ? compileCore(wasmUrl) : Promise.resolve(null);
    // A failed compile is reported by the first request (init), not as an unhandled rejection.
    this.module.catch(() => undefined);
    this.schemes = this.startInit();
  }

  /** A new session: its own requests and its own cancel. */
  session(): CoreSession {
    return new CoreSession(this);
  }

  /** Resolves with the core's scheme names once the WASM module is loaded. */
  ready(): Promise<string[]> {
    return this.schemes;
  }

  /**
   * Counts the workers dropped (cancelled or crashed): the levels a worker
   * kept are gone with it, so a handle of another epoch names nothing.
   */
  get epoch(): number {
    return this.workerEpoch;
  }

  /**
   * Calls `listener` with each crash of the worker (after the new one is
   * asked to start), whichever session's request was running; answers a
   * function that stops the calls.
   */
  onCrash(listener: (error: CoreCrashedError) => void): () => void {
    this.crashListeners.add(listener);
    return () => this.crashListeners.delete(listener);
  }

  /** The core's memory and the number of levels the worker keeps. */
  memory(): Promise<WorkerMemory> {
    return this.request(this.internal, 'memory', {});
  }

  /**
   * Test hook: crashes the worker (worker-protocol.ts) and resolves once it
   * has been replaced; with `during`, resolves at once and the worker
   * crashes at the start of its next request of that kind.
   */
  async crashForTest(how: CrashKind, during?: WorkerRequestKind): Promise<void> {
    try {
      await this.request(this.internal, 'crashForTest', { how, during });
    } catch (error) {
      if (error instanceof CoreCrashedError && !during) return;
      throw error;
    }
    if (!during) throw new Error('the worker did not crash');
  }

  /** Terminates the worker; every pending request rejects with CancelledError. */
  dispose(): void {
    this.disposed = true;
    this.worker?.terminate();
    this.worker = null;
    const all = [...(this.running ? [this.running] : []), ...this.queue.splice(0)];
    this.running = null;
    for (const r of all) r.reject(new CancelledError());
  }

  /** @internal Queues a request of `session`. */
  request<K extends WorkerRequestKind>(
    session: CoreSession,
    kind: K,
    args: WorkerRequests[K]['args'],
  ): Promise<WorkerRequests[K]['result']> {
    return new Promise((resolve, reject) => {
      if (this.disposed || this.startFailure) {
        reject(this.startFailure ?? new CancelledError());
        return;
      }
      this.queue.push({ id: this.nextId++, session, kind, args, resolve: resolve as (v: unknown) => void, reject });
      this.pump();
    });
  }

  /** @internal Queues a release of kept levels as the client's own request. */
  release(handles: LevelHandle[]): void {
    if (handles.length === 0 || this.disposed) return;
    this.request(this.internal, 'release', { handles }).catch(() => undefined);
  }

  /** @internal Drops `session`'s requests; restarts the worker only if one of them is running. */
  cancel(session: CoreSession): void {
    const dropped = this.queue.filter((r) => r.session === session);
    for (const r of dropped) this.queue.splice(this.queue.indexOf(r), 1);
    const running = this.running;
    if (running?.session === session) {
      this.worker?.terminate();
      this.worker = null;
      this.workerEpoch++;
      this.running = null;
      dropped.unshift(running);
      // The new worker loads the core again before the next request.
      this.schemes = this.startInit();
    }
    for (const r of dropped) r.reject(new CancelledError());
    this.pump();
  }

  private startInit(): Promise<string[]> {
    // The epoch is filled in when the request is sent.
    const schemes = this.request(this.internal, 'init', { epoch: -1 });
    // Cancelling may reject it before anyone awaits it: that is not an error.
    schemes.catch(() => undefined);
    return schemes;
  }

  /** The client's own session, for init requests (never cancelled by a viewer). */
  private readonly internal = new CoreSession(this);

  private pump(): void {
    if (this.running || this.disposed) return;
    // An init request goes first: the next request needs the core.
    const initAt = this.queue.findIndex((r) => r.kind === 'init');
    const next = initAt >= 0 ? this.queue.splice(initAt, 1)[0] : this.queue.shift();
    if (!next) return;
    this.running = next;
    void this.send(next);
  }

  private async send(request: Queued): Promise<void> {
    let args = request.args;
    if (request.kind === 'init') {
      try {
        args = { module: await this.module, epoch: this.workerEpoch };
      } catch (error) {
        if (this.running === request) this.failStart(errorData(error).message);
        return;
      }
      if (this.running !== request) return;
    }
    const handle = (args as { handle?: LevelHandle }).handle;
    if (handle && handle.epoch !== this.workerEpoch) {
      this.running = null;
      request.reject(new StaleLevelError());
      this.pump();
      return;
    }
    const message: WorkerRequestMessage = { id: request.id, kind: request.kind, args: args as never };
    let worker: Worker;
    try {
      worker = this.ensureWorker();
    } catch (error) {
      // A worker the page may not start (a Content-Security-Policy, a URL it refuses).
      this.failStart(startFailureReason(errorData(error).message));
      return;
    }
    try {
      worker.postMessage(message);
    } catch (error) {
      // Arguments that cannot be sent.
      this.settle(request, { id: request.id, ok: false, error: errorData(error) });
    }
  }

  private ensureWorker(): Worker {
    if (this.worker) return this.worker;
    const worker = this.factory();
    /** Whether this worker has answered once: an error before that is a failed start, not a crash. */
    let answered = false;
    worker.onmessage = (event: MessageEvent<WorkerResponseMessage>) => {
      answered = true;
      const response = event.data;
      if (!this.running || response.id !== this.running.id) return;
      if (!response.ok && response.fatal) this.crashed(worker, response.error.message);
      else this.settle(this.running, response);
    };
    // A load failure fires a plain Event; an error thrown in the worker an ErrorEvent with its message.
    worker.onerror = (event: Event) => {
      event.preventDefault();
      const message = (event as Partial<ErrorEvent>).message ?? '';
      if (answered) this.crashed(worker, message || 'The SubdivLab core worker failed.');
      else if (this.worker === worker) this.failStart(startFailureReason(message));
    };
    this.worker = worker;
    return worker;
  }

  /**
   * The core could not be started: the running and queued requests, and
   * every later one, reject with one CoreStartError.
   */
  private failStart(reason: string): void {
    const error = new CoreStartError(reason);
    this.startFailure = error;
    this.worker?.terminate();
    this.worker = null;
    const all = [...(this.running ? [this.running] : []), ...this.queue.splice(0)];
    this.running = null;
    for (const r of all) r.reject(error);
  }

  /**
   * Replaces `worker`, which crashed: its levels are gone (the epoch moves
   * on), the next one loads the core first, and the running request fails
   * with CoreCrashedError, which the listeners hear of. A worker that fails
   * while loading the core is not started again (it would fail the same
   * way): that is a failed start (CoreStartError).
   */
  private crashed(worker: Worker, reason: string): void {
    worker.terminate();
    if (this.worker !== worker) return;
    this.worker = null;
    this.workerEpoch++;
    const running = this.running;
    if (running?.kind === 'init') {
      this.failStart(reason);
      return;
    }
    // The next worker loads the core first (from the page's compiled module), as after a cancel.
    this.schemes = this.startInit();
    const error = new CoreCrashedError(running?.kind ?? null, reason);
    if (running) {
      this.running = null;
      running.reject(error);
    }
    for (const listener of this.crashListeners) listener(error);
    this.pump();
  }

  private settle(request: Queued, response: WorkerResponseMessage): void {
    if (this.running !== request) return;
    if (request.kind === 'init' && !response.ok) {
      this.failStart(response.error.message);
      return;
    }
    this.running = null;
    if (response.ok) request.resolve(response.value);
    else request.reject(new SubdivError(response.error.code, response.error.message, response.error.line));
    this.pump();
  }
}

function errorData(error: unknown): { code: 'internal_error'; message: string; line: number } {
  return { code: 'internal_error', message: error instanceof Error ? error.message : String(error), line: 0 };
}

/**
 * One viewer's access to the page's core. Requests run in order with the
 * other sessions'; {@link cancel} stops only this session's.
 */
export class CoreSession {
  constructor(readonly client: WorkerClient) {}

  /** Resolves with the core's scheme names once the WASM module is loaded. */
  ready(): Promise<string[]> {
    return this.client.ready();
  }

  /** Parses an OFF/OBJ/PLY/STL file (text or bytes) into a level 0 kept by the worker; answers it and its mesh. */
  parse(
    text: string | Uint8Array,
    format: ReadFormat,
    options: ReadOptions = {},
  ): Promise<{ level: LevelData; mesh: Mesh }> {
    return this.client.request(this, 'parse', { text, format, options });
  }

  /** Keeps a mesh built elsewhere as a level 0: its handle, facts and render buffers. */
  prepare(mesh: Mesh): Promise<LevelData> {
    return this.client.request(this, 'prepare', { mesh });
  }

  /** Keeps `mesh`, whose facts are `facts`, again (after a restart); answers its handle. */
  keep(mesh: Mesh, facts: MeshFacts): Promise<LevelHandle> {
    return this.client.request(this, 'keep', { mesh, facts });
  }

  /**
   * Subdivides a kept level in the worker, which keeps the result; it comes
   * with its facts and render buffers. Its `ms` is the core's time.
   * Rejects with StaleLevelError when the worker restarted since `handle`.
   */
  subdivide(handle: LevelHandle, options: SubdivideOptions): Promise<LevelData> {
    return this.client.request(this, 'subdivide', { handle, options });
  }

  /** The stencils of `subdivide(handle, options)`'s last step (stencils.ts). */
  stencils(handle: LevelHandle, options: SubdivideOptions): Promise<StencilTable> {
    return this.client.request(this, 'stencils', { handle, options });
  }

  /** Control vertex `vertex`'s basis function at level `levels` of the kept level 0 `handle` (basis.ts). */
  basis(handle: LevelHandle, vertex: number, levels: number, options: StepOptions): Promise<Float64Array> {
    return this.client.request(this, 'basis', { handle, vertex, levels, options });
  }

  /** The points of `subdivide(handle, options)` as float32, without keeping the result. */
  points(handle: LevelHandle, options: SubdivideOptions): Promise<Float32Array> {
    return this.client.request(this, 'points', { handle, options });
  }

  /** Parses `text` (a result from elsewhere) and checks it against the kept level `handle`. */
  /** The symmetric Hausdorff distance between kept levels `a` and `b` (either session's), with vertex distances. */
  hausdorff(a: LevelHandle, b: LevelHandle): Promise<HausdorffDistance> {
    return this.client.request(this, 'hausdorff', { a, b });
  }

  /** The discrete curvature at each vertex of kept level `handle` (NaN on its border). */
  curvature(handle: LevelHandle): Promise<VertexCurvature> {
    return this.client.request(this, 'curvature', { handle });
  }

  /** CGAL's geometry around kept level `handle`: its measures and what `options` asks for. */
  inspect(handle: LevelHandle, options: InspectOptions): Promise<Inspection> {
    return this.client.request(this, 'inspect', { handle, options });
  }

  compare(
    handle: LevelHandle,
    text: string | Uint8Array,
    format: ReadFormat,
    tolerance: number,
  ): Promise<MeshComparison> {
    return this.client.request(this, 'compare', { handle, text, format, tolerance });
  }

  /** Predicted counts and peak bytes of `subdivide(handle, options)`. */
  predictSize(handle: LevelHandle, options: SubdivideOptions): Promise<SizePrediction> {
    return this.client.request(this, 'predict', { handle, options });
  }

  /** The file of a kept level (OFF/OBJ/PLY text, binary STL; `comment` in it), in pieces (see writeMesh) to join into a Blob or a file. */
  exportMesh(handle: LevelHandle, format: MeshFormat, comment = ''): Promise<Uint8Array[]> {
    return this.client.request(this, 'export', { handle, format, comment });
  }

  /** A copy of a kept level's mesh. */
  mesh(handle: LevelHandle): Promise<Mesh> {
    return this.client.request(this, 'mesh', { handle });
  }

  /** The halfedge table of kept level `handle` (CGAL's Surface_mesh numbering). */
  halfedges(handle: LevelHandle): Promise<HalfedgeTable> {
    return this.client.request(this, 'halfedges', { handle });
  }

  /** CGAL's Euler operator `op` on halfedge `h` (`h2`: split_face's other corner) of `mesh`. */
  euler(mesh: Mesh, op: EulerOperator, h: number, h2 = 0): Promise<EulerResult> {
    return this.client.request(this, 'euler', { mesh, op, h, h2 });
  }

  /** √3 by hand on `mesh` stopped after `steps` operators, checked against the scheme once complete. */
  sqrt3ByHand(mesh: Mesh, steps: number): Promise<Sqrt3Check> {
    return this.client.request(this, 'sqrt3ByHand', { mesh, steps });
  }

  /**
   * Lets the worker forget kept levels. Not this session's request: a
   * cancel of the session does not drop it (handles of an earlier worker
   * are ignored).
   */
  release(handles: LevelHandle[]): void {
    this.client.release(handles);
  }

  /** Resolves when the core accepts `rules`; rejects with its SubdivError (invalid_argument) otherwise. */
  checkRules(rules: RuleSet): Promise<null> {
    return this.client.request(this, 'checkRules', { rules });
  }

  /** Stops this session's running or queued requests (they reject with CancelledError); others go on. */
  cancel(): void {
    this.client.cancel(this);
  }
}

let page: WorkerClient | null = null;

/** The page's one core (made on first use): every viewer on a page shares it. */
export function pageCore(): WorkerClient {
  page ??= new WorkerClient();
  return page;
}
