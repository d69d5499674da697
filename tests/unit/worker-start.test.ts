/**
 * A core whose worker cannot start (web/core/worker-client.ts): a worker
 * that fails before answering, one whose core fails to load, and a `.wasm`
 * that cannot be fetched are failed starts, not crashes. Every request then
 * rejects with one CoreStartError saying the core could not be started and
 * why; no crash is reported and no new worker is tried. Fake workers stand
 * in for the browser's, so each case is exact.
 */
import { describe, expect, it } from 'vitest';
import type { Mesh } from '../../web/core/mesh';
import { CoreCrashedError, CoreStartError, WorkerClient } from '../../web/core/worker-client';
import type { WorkerRequestMessage, WorkerResponseMessage } from '../../web/core/worker-protocol';

/** A Worker as WorkerClient uses it: `answer` decides what each request gets. */
class FakeWorker {
  onmessage: ((event: MessageEvent<WorkerResponseMessage>) => void) | null = null;
  onerror: ((event: Event) => void) | null = null;
  readonly received: WorkerRequestMessage[] = [];
  terminated = false;

  constructor(private readonly answer: (worker: FakeWorker, message: WorkerRequestMessage) => void) {}

  postMessage(message: WorkerRequestMessage): void {
    this.received.push(message);
    queueMicrotask(() => this.answer(this, message));
  }

  terminate(): void {
    this.terminated = true;
  }

  reply(response: WorkerResponseMessage): void {
    this.onmessage?.({ data: response } as MessageEvent<WorkerResponseMessage>);
  }

  /** A load failure: a plain `error` Event, no message (what Chromium fires for a script it cannot load). */
  failToLoad(): void {
    this.onerror?.(new Event('error'));
  }
}

function clientWith(answer: (worker: FakeWorker, message: WorkerRequestMessage) => void): {
  client: WorkerClient;
  workers: FakeWorker[];
  crashes: CoreCrashedError[];
} {
  const workers: FakeWorker[] = [];
  const client = new WorkerClient(() => {
    const worker = new FakeWorker(answer);
    workers.push(worker);
    return worker as unknown as Worker;
  }, null);
  const crashes: CoreCrashedError[] = [];
  client.onCrash((error) => crashes.push(error));
  return { client, workers, crashes };
}

const MESH: Mesh = {
  positions: new Float64Array(9),
  faceSizes: new Uint32Array([3]),
  faceIndices: new Uint32Array([0, 1, 2]),
  controlEdges: new Uint32Array(0),
};

describe('a core that cannot start', () => {
  it('a worker that fails to load: init and every later request reject with one CoreStartError, no crash, no new worker', async () => {
    const { client, workers, crashes } = clientWith((worker) => worker.failToLoad());
    const session = client.session();
    const queued = session.prepare(MESH);
    const ready = client.ready();
    await expect(ready).rejects.toBeInstanceOf(CoreStartError);
    const error = (await ready.catch((e: unknown) => e)) as CoreStartError;
    expect(error.message).toBe(
      'The SubdivLab core could not be started: its worker script did not load. Check that the files beside ' +
        'subdiv-viewer.js (assets/) are served, and that a Content-Security-Policy allows the worker (worker-src).',
    );
    expect(error.code).toBe('internal_error');
    expect(error.message).not.toMatch(/stopped unexpectedly|levels already shown/);
    // The request queued behind init, and one made afterwards, get the same error.
    await expect(queued).rejects.toBe(error);
    await expect(session.parse('OFF\n', 'off')).rejects.toBe(error);
    expect(workers).toHaveLength(1);
    expect(workers[0].terminated).toBe(true);
    expect(workers[0].received.map((m) => m.kind)).toEqual(['init']);
    expect(crashes).toEqual([]);
  });

  it("an error thrown while the worker loads names the browser's message", async () => {
    const { client, crashes } = clientWith((worker) =>
      worker.onerror?.(
        Object.assign(new Event('error'), { message: "Uncaught NetworkError: Failed to execute 'importScripts'" }),
      ),
    );
    await expect(client.ready()).rejects.toThrow(
      "The SubdivLab core could not be started: Uncaught NetworkError: Failed to execute 'importScripts'. Check",
    );
    expect(crashes).toEqual([]);
  });

  it('a fatal answer to init (the core failed to load in the worker) is a failed start too', async () => {
    const { client, workers, crashes } = clientWith((worker, message) =>
      worker.reply({
        id: message.id,
        ok: false,
        error: { code: 'internal_error', message: 'RuntimeError: Aborted(OOM)', line: 0 },
        fatal: true,
      }),
    );
    await expect(client.ready()).rejects.toThrow('The SubdivLab core could not be started: RuntimeError: Aborted(OOM)');
    await expect(client.session().prepare(MESH)).rejects.toBeInstanceOf(CoreStartError);
    expect(workers).toHaveLength(1);
    expect(crashes).toEqual([]);
  });

  it('a .wasm that cannot be fetched fails the start before any worker is made', async () => {
    const workers: FakeWorker[] = [];
    const client = new WorkerClient(() => {
      const worker = new FakeWorker(() => undefined);
      workers.push(worker);
      return worker as unknown as Worker;
    }, 'http://127.0.0.1:9/subdivlab.wasm');
    await expect(client.ready()).rejects.toThrow(/^The SubdivLab core could not be started: /);
    await expect(client.session().prepare(MESH)).rejects.toBeInstanceOf(CoreStartError);
    expect(workers).toHaveLength(0);
  });

  it('a worker that answered and then fails is a crash, as before: a new worker, the request rejected with CoreCrashedError', async () => {
    let made = 0;
    const { client, workers, crashes } = clientWith((worker, message) => {
      if (message.kind === 'init') worker.reply({ id: message.id, ok: true, value: ['loop'] });
      else if (made++ === 0)
        worker.onerror?.(Object.assign(new Event('error'), { message: 'RuntimeError: unreachable' }));
      else worker.reply({ id: message.id, ok: true, value: null });
    });
    expect(await client.ready()).toEqual(['loop']);
    const failed = await client
      .session()
      .prepare(MESH)
      .catch((e: unknown) => e);
    expect(failed).toBeInstanceOf(CoreCrashedError);
    expect((failed as Error).message).toMatch(
      /stopped unexpectedly while preparing a mesh \(RuntimeError: unreachable\)/,
    );
    expect(crashes).toHaveLength(1);
    expect(await client.ready()).toEqual(['loop']);
    expect(workers).toHaveLength(2);
  });
});
