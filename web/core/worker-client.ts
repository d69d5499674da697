/**
 * Typed, promise-based access to the core running in a Web Worker.
 * Cancelling terminates the worker (a WASM call cannot be interrupted) and
 * starts a fresh one; callers keep whatever results they already have.
 */
import type { Mesh, MeshFormat, SizePrediction, SubdivideOptions } from './mesh';
import type { RuleSet } from './rule-set';
import { SubdivError } from './subdiv-error';
import type {
  LevelData,
  WorkerRequestKind,
  WorkerRequestMessage,
  WorkerRequests,
  WorkerResponseMessage,
} from './worker-protocol';

export type { LevelData } from './worker-protocol';

/** Rejection of requests that were running or queued when {@link WorkerClient.cancel} was called. */
export class CancelledError extends Error {
  constructor() {
    super('Cancelled.');
    this.name = 'CancelledError';
  }
}

interface Pending {
  resolve: (value: unknown) => void;
  reject: (error: Error) => void;
}

/** Makes the worker; the default one is bundled by Vite from subdiv-worker.ts. */
export type WorkerFactory = () => Worker;

const defaultFactory: WorkerFactory = () =>
  new Worker(new URL('./subdiv-worker.ts', import.meta.url), { type: 'module', name: 'subdivlab-core' });

/** One worker running the core. Several viewers may share one client. */
export class WorkerClient {
  private worker: Worker;
  private readonly pending = new Map<number, Pending>();
  private nextId = 1;
  private schemes: Promise<string[]>;

  constructor(private readonly factory: WorkerFactory = defaultFactory) {
    this.worker = this.start();
    this.schemes = this.startInit();
  }

  /** Resolves with the core's scheme names once the WASM module is loaded. */
  ready(): Promise<string[]> {
    return this.schemes;
  }

  /** Parses OFF/OBJ text; the result is level 0 with its facts and render buffers. */
  parse(text: string, format: MeshFormat): Promise<LevelData> {
    return this.request('parse', { text, format });
  }

  /** Facts and render buffers of a mesh built elsewhere. */
  prepare(mesh: Mesh): Promise<LevelData> {
    return this.request('prepare', { mesh });
  }

  /** Subdivides in the worker; `ms` of the result is the core's time for the step. */
  subdivide(mesh: Mesh, options: SubdivideOptions): Promise<LevelData> {
    return this.request('subdivide', { mesh, options });
  }

  /** Predicted counts and peak bytes of `subdivide(mesh, options)`. */
  predictSize(mesh: Mesh, options: SubdivideOptions): Promise<SizePrediction> {
    return this.request('predict', { mesh, options });
  }

  /** OFF or OBJ text of `mesh`. */
  exportMesh(mesh: Mesh, format: MeshFormat): Promise<string> {
    return this.request('export', { mesh, format });
  }

  /** Resolves when the core accepts `rules`; rejects with its SubdivError (invalid_argument) otherwise. */
  checkRules(rules: RuleSet): Promise<null> {
    return this.request('checkRules', { rules });
  }

  /** True while a request is running or queued. */
  get busy(): boolean {
    return this.pending.size > 0;
  }

  /** Stops whatever runs now: every pending request rejects with CancelledError; a fresh worker takes over. */
  cancel(): void {
    this.worker.terminate();
    const pending = [...this.pending.values()];
    this.pending.clear();
    for (const p of pending) p.reject(new CancelledError());
    this.worker = this.start();
    this.schemes = this.startInit();
  }

  /** Terminates the worker; the client cannot be used afterwards. */
  dispose(): void {
    this.worker.terminate();
    for (const p of this.pending.values()) p.reject(new CancelledError());
    this.pending.clear();
  }

  private startInit(): Promise<string[]> {
    const schemes = this.request('init', {});
    // Cancelling may reject it before anyone awaits it: that is not an error.
    schemes.catch(() => undefined);
    return schemes;
  }

  private start(): Worker {
    const worker = this.factory();
    worker.onmessage = (event: MessageEvent<WorkerResponseMessage>) => this.settle(event.data);
    worker.onerror = (event: ErrorEvent) => {
      // A worker that fails to load or crashes answers nothing more: fail everything pending.
      event.preventDefault();
      const message = event.message || 'The SubdivLab core worker failed to start.';
      for (const p of this.pending.values()) p.reject(new SubdivError('internal_error', message));
      this.pending.clear();
    };
    return worker;
  }

  private settle(response: WorkerResponseMessage): void {
    const pending = this.pending.get(response.id);
    if (!pending) return;
    this.pending.delete(response.id);
    if (response.ok) pending.resolve(response.value);
    else pending.reject(new SubdivError(response.error.code, response.error.message, response.error.line));
  }

  private request<K extends WorkerRequestKind>(
    kind: K,
    args: WorkerRequests[K]['args'],
  ): Promise<WorkerRequests[K]['result']> {
    const id = this.nextId++;
    const message: WorkerRequestMessage<K> = { id, kind, args };
    return new Promise((resolve, reject) => {
      this.pending.set(id, { resolve: resolve as (value: unknown) => void, reject });
      this.worker.postMessage(message);
    });
  }
}
