/**
 * The web app's mesh sources (web/viewer/mesh-source.ts): format detection and
 * the ?src= download rules (http/https only, size limit enforced while
 * reading, even when the server sends no Content-Length). A real HTTP server
 * on a loopback port serves the bodies.
 */
import { createServer, type Server } from 'node:http';
import type { AddressInfo } from 'node:net';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { CancelledError } from '../../web/core/worker-client';
import { detectFormat, fetchMesh, LoadError } from '../../web/viewer/mesh-source';

const CUBE = 'OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n';

let server: Server;
let base: string;

beforeAll(async () => {
  server = createServer((request, response) => {
    const url = new URL(request.url ?? '/', 'http://localhost');
    if (url.pathname === '/cube.off') {
      response.writeHead(200, { 'content-type': 'text/plain' });
      response.end(CUBE);
    } else if (url.pathname === '/declared-big.off') {
      response.writeHead(200, { 'content-length': String(5000) });
      response.end('x'.repeat(5000));
    } else if (url.pathname === '/chunked-big.off') {
      // No Content-Length: the limit must hold while reading.
      response.writeHead(200, { 'transfer-encoding': 'chunked' });
      for (let i = 0; i < 10; i++) response.write('y'.repeat(1000));
      response.end();
    } else if (url.pathname === '/spa/cube.off') {
      // A single-page-app host answers every path with its index page.
      response.writeHead(200, { 'content-type': 'text/html; charset=utf-8' });
      response.end('<!doctype html><title>App</title>');
    } else if (url.pathname === '/slow.off') {
      // Headers at once, the body never: only an abort ends the download.
      response.writeHead(200, { 'content-type': 'text/plain' });
      response.write('OFF\n');
    } else if (url.pathname === '/mesh') {
      response.writeHead(200);
      response.end('# no extension\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n');
    } else {
      response.writeHead(404, 'Not Found');
      response.end();
    }
  });
  await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
  base = `http://127.0.0.1:${(server.address() as AddressInfo).port}/`;
});

afterAll(() => new Promise<void>((resolve) => server.close(() => resolve())));

describe('detectFormat', () => {
  it('uses the extension, in any case', () => {
    expect(detectFormat('Model.OFF')).toBe('off');
    expect(detectFormat('model.obj')).toBe('obj');
    expect(detectFormat('scan.PLY')).toBe('ply');
    expect(detectFormat('part.stl ')).toBe('stl');
  });
  it("leaves the rest to the core's look at the bytes ('auto')", () => {
    expect(detectFormat('mesh')).toBe('auto');
    expect(detectFormat('photo.png')).toBe('auto');
  });
});

describe('fetchMesh', () => {
  it('loads a relative http URL and names it by its last path segment', async () => {
    const mesh = await fetchMesh('cube.off', base);
    expect(mesh).toEqual({ name: 'cube.off', text: new TextEncoder().encode(CUBE), format: 'off' });
  });

  it("leaves the format of a URL without extension to the core ('auto')", async () => {
    expect((await fetchMesh(`${base}mesh`, base)).format).toBe('auto');
  });

  it.each(['file:///etc/passwd', 'javascript:alert(1)', 'data:text/plain,OFF', 'ftp://example.com/a.off'])(
    'refuses %s',
    async (src) => {
      await expect(fetchMesh(src, base)).rejects.toThrow(/^Only http and https URLs can be loaded, not [a-z]+:$/);
    },
  );

  it('refuses a body whose declared length is over the limit, before reading it', async () => {
    const error = await fetchMesh('declared-big.off', base, 1000).catch((e: unknown) => e);
    expect(error).toBeInstanceOf(LoadError);
    expect((error as LoadError).source).toBe('declared-big.off');
    expect((error as LoadError).message).toMatch(/limit for URLs/);
  });

  it('stops reading a chunked body as soon as it passes the limit', async () => {
    await expect(fetchMesh('chunked-big.off', base, 2500)).rejects.toThrow(/larger than the limit for URLs/);
  });

  it('refuses a web page sent in place of the mesh', async () => {
    await expect(fetchMesh('spa/cube.off', base)).rejects.toThrow(
      'The server sent a web page, not a mesh: is the URL right?',
    );
  });

  it('stops a download when its signal aborts, with CancelledError', async () => {
    const controller = new AbortController();
    const download = fetchMesh('slow.off', base, undefined, controller.signal);
    setTimeout(() => controller.abort(), 50);
    await expect(download).rejects.toBeInstanceOf(CancelledError);
  });

  it('reports the server status', async () => {
    await expect(fetchMesh('missing.off', base)).rejects.toThrow('The server answered 404 Not Found');
  });
});
