/** init({ wasmUrl }): the module fetched over HTTP; a failed load can be retried. */
import { readFileSync } from 'node:fs';
import { createServer, type Server } from 'node:http';
import type { AddressInfo } from 'node:net';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { init, isReady, schemeNames } from '../../web/core/subdiv-core';
import { SubdivError } from '../../web/core/subdiv-error';

// The module vitest loads (its test build: vitest.config.ts), whose glue subdiv-core.ts has here.
const WASM =
  process.env.SUBDIVLAB_WASM ??
  join(dirname(fileURLToPath(import.meta.url)), '..', '..', 'web', 'core', 'generated', 'subdivlab.wasm');
let server: Server;
let base = '';
let requests = 0;

beforeAll(async () => {
  const bytes = readFileSync(WASM);
  server = createServer((req, res) => {
    requests++;
    if (req.url === '/subdivlab.wasm') {
      res.writeHead(200, { 'content-type': 'application/wasm' });
      res.end(bytes);
    } else {
      res.writeHead(404);
      res.end();
    }
  });
  await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
  base = `http://127.0.0.1:${(server.address() as AddressInfo).port}`;
});

afterAll(() => {
  server.close();
});

describe('init from a URL', () => {
  it('fails with a SubdivError on a missing file, then loads from a good URL', async () => {
    await expect(init({ wasmUrl: `${base}/missing.wasm` })).rejects.toThrowError(SubdivError);
    await expect(init({ wasmUrl: `${base}/missing.wasm` })).rejects.toThrowError(/HTTP 404/);
    expect(isReady()).toBe(false);
    await init({ wasmUrl: `${base}/subdivlab.wasm` });
    expect(isReady()).toBe(true);
    expect(schemeNames()).toContain('catmull-clark');
    const before = requests;
    await init({ wasmUrl: `${base}/subdivlab.wasm` });
    expect(requests).toBe(before);
  });
});
