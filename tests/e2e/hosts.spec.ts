/**
 * Where teachers put the element (issue 29): a sandboxed frame (an opaque
 * origin), a host that sends no CORS headers, a page with both an element
 * and an iframe of embed.html, and a worker that cannot start. The course
 * pages and the other hosts are node servers on loopback ports, so each is
 * another origin to the browser; the hosts serve the built site's folder.
 */
import { createHash } from 'node:crypto';
import { readFile } from 'node:fs/promises';
import { createServer } from 'node:http';
import type { AddressInfo } from 'node:net';
import { extname, join, normalize, resolve } from 'node:path';
import type { Frame, Page } from '@playwright/test';
import { type EmbedPage, viewerPage } from './embed-page';
import { expect, test } from './fixtures';
import { expectedClosedCounts } from './helpers';

const TETRAHEDRON = { vertices: 4, edges: 6, faces: 4 };
const SHOTS = '/tmp/shots/hosts';
/** The built site, as playwright.config.ts builds and serves it. */
const DIST = resolve(process.env.SUBDIVLAB_E2E_DIST ?? 'dist');
/** A string only three.js's code holds (its renderer's warnings): a response carrying three.js. */
const THREE_MARKER = 'THREE.WebGLRenderer';

const TYPES: Record<string, string> = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript',
  '.wasm': 'application/wasm',
  '.off': 'text/plain',
  '.css': 'text/css',
};

interface Served {
  path: string;
  status: number;
  /** The body holds three.js. */
  three: boolean;
}

interface Host {
  origin: string;
  served: Served[];
  close(): Promise<void>;
}

/**
 * A static host of the built site on its own port, with `pages` (path →
 * HTML) beside it. `cors`: sends `Access-Control-Allow-Origin: *`, as public
 * hosts do, or no Access-Control-* header at all. Caching as a static host
 * does it: hashed files under assets/ for a year, the rest revalidated by
 * ETag (a 304 carries no body).
 */
async function startHost(options: { cors: boolean; pages?: Record<string, string> }): Promise<Host> {
  const served: Served[] = [];
  const server = createServer(async (request, response) => {
    const path = decodeURIComponent(new URL(request.url ?? '/', 'http://host').pathname);
    const page = options.pages?.[path];
    const headers: Record<string, string> = options.cors ? { 'access-control-allow-origin': '*' } : {};
    if (path === '/favicon.ico') {
      // Asked by every page; no icon, no 404 in the console.
      response.writeHead(204, headers);
      response.end();
      return;
    }
    let body: Buffer;
    try {
      if (page !== undefined) body = Buffer.from(page);
      else {
        const file = normalize(join(DIST, path));
        if (!file.startsWith(DIST)) throw new Error('outside');
        body = await readFile(file);
      }
    } catch {
      served.push({ path, status: 404, three: false });
      response.writeHead(404, headers);
      response.end('not found');
      return;
    }
    const etag = `"${createHash('sha1').update(body).digest('hex')}"`;
    const hashed = /\/assets\/[^/]+-[\w-]{8}\.\w+$/.test(path);
    headers['content-type'] = TYPES[extname(path)] ?? 'application/octet-stream';
    headers['cache-control'] = hashed ? 'public, max-age=31536000, immutable' : 'no-cache';
    headers.etag = etag;
    if (request.headers['if-none-match'] === etag) {
      served.push({ path, status: 304, three: false });
      response.writeHead(304, headers);
      response.end();
      return;
    }
    served.push({ path, status: 200, three: body.includes(THREE_MARKER) });
    response.writeHead(200, headers);
    response.end(body);
  });
  await new Promise<void>((done) => server.listen(0, '127.0.0.1', done));
  return {
    origin: `http://127.0.0.1:${(server.address() as AddressInfo).port}`,
    served,
    close: () => new Promise<void>((done) => server.close(() => done())),
  };
}

/** What a test reads of an element in `frame`. */
async function readingIn(frame: Frame | Page, id: string) {
  return frame.evaluate((elementId) => {
    const e = document.getElementById(elementId) as HTMLElementTagNameMap['subdiv-viewer'];
    return { level: e.level, facts: e.facts, busy: Boolean(e.state?.busy) };
  }, id);
}

async function waitForLevelIn(frame: Frame | Page, id: string, level: number) {
  await expect
    .poll(async () => {
      const r = await readingIn(frame, id).catch(() => null);
      return r !== null && r.level === level && !r.busy;
    })
    .toBe(true);
  return readingIn(frame, id);
}

test.describe('a sandboxed frame', () => {
  test('sandbox="allow-scripts" (origin null): the element from the hosted copy reaches level 2; its worker is a classic blob: shim', async ({
    embed,
    baseURL,
  }) => {
    // Through the embed fixture: a console error fails the test (fixtures.ts).
    const page = embed.page;
    const host = new URL(baseURL ?? 'http://127.0.0.1:4179/').origin;
    const inside = `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Frame</title>
<script defer src="${host}/embed/subdiv-viewer.js"></script></head><body style="margin:0">
<subdiv-viewer id="x" src="${host}/meshes/tetrahedron.off" scheme="loop" levels="2" render-mode="edges" style="width:380px;height:260px"></subdiv-viewer>
</body></html>`;
    const escaped = inside.replace(/&/g, '&amp;').replace(/"/g, '&quot;');
    const course = await startHost({
      cors: false,
      pages: {
        '/lesson.html': `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Lesson</title></head><body>
<h1>Loop on a tetrahedron</h1>
<iframe id="box" title="viewer" sandbox="allow-scripts" width="400" height="280" srcdoc="${escaped}"></iframe>
</body></html>`,
      },
    });
    try {
      const workers: string[] = [];
      page.on('worker', (worker) => workers.push(worker.url()));
      await page.goto(`${course.origin}/lesson.html`);
      const frame = page.frames().find((f) => f !== page.mainFrame());
      if (!frame) throw new Error('no frame');
      expect(await frame.evaluate(() => self.origin)).toBe('null');
      const reading = await waitForLevelIn(frame, 'x', 2);
      expect(reading.facts).toMatchObject({ ...expectedClosedCounts('loop', TETRAHEDRON, 2), genus: 0, closed: true });
      // No message in the element: nothing failed on the way.
      expect(await frame.locator('#x').locator('[part="message"]').isHidden()).toBe(true);
      expect(workers).toHaveLength(1);
      expect(workers[0]).toMatch(/^blob:null\//);
      await page.locator('#box').screenshot({ path: `${SHOTS}/sandboxed-frame.png` });
    } finally {
      await course.close();
    }
  });
});

test.describe('the iframe route in a sandboxed frame', () => {
  test('<iframe sandbox="allow-scripts" src=".../embed.html?..."> (origin null) posts level 2 with the right counts', async ({
    embed,
    baseURL,
  }) => {
    // Through the embed fixture: a console error fails the test (fixtures.ts).
    const page = embed.page;
    const host = new URL(baseURL ?? 'http://127.0.0.1:4179/').origin;
    const course = await startHost({
      cors: false,
      pages: {
        '/lesson.html': `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Lesson</title></head><body>
<iframe id="route" title="viewer" sandbox="allow-scripts" width="400" height="280"
  src="${host}/embed.html?src=meshes/tetrahedron.off&amp;scheme=loop&amp;levels=2&amp;mode=edges"></iframe>
<script>
  window.__changes = [];
  window.addEventListener('message', (e) => {
    if (e.data && e.data.subdivlab === 'level-change') window.__changes.push(e.data);
    if (e.data && e.data.subdivlab === 'error') window.__changes.push(e.data);
  });
</script>
</body></html>`,
      },
    });
    try {
      await page.goto(`${course.origin}/lesson.html`);
      const frame = page.frame({ url: /embed\.html/ });
      if (!frame) throw new Error('no frame');
      expect(await frame.evaluate(() => self.origin)).toBe('null');
      await expect
        .poll(() =>
          page.evaluate(() => (window as unknown as { __changes: { level?: number }[] }).__changes.at(-1) ?? null),
        )
        .toMatchObject({ subdivlab: 'level-change', level: 2 });
      const last = await page.evaluate(
        () => (window as unknown as { __changes: { facts: Record<string, number> }[] }).__changes.at(-1)?.facts,
      );
      expect(last).toMatchObject({ ...expectedClosedCounts('loop', TETRAHEDRON, 2) });
      await page.locator('#route').screenshot({ path: `${SHOTS}/sandboxed-iframe-route.png` });
    } finally {
      await course.close();
    }
  });
});

test.describe('a host without CORS headers', () => {
  // The browser says in the console that it refused the module; the page says it in the box.
  // One pattern: test.use reads a second array item as the option's settings.
  test.use({ allowedConsoleErrors: [/blocked by CORS policy|^Failed to load resource: net::ERR_FAILED$/] });

  test('each element shows a box naming Access-Control-Allow-Origin and the iframe route, which works there', async ({
    embed,
  }) => {
    const page = embed.page;
    const files = await startHost({ cors: false });
    const body = `<h1>Lesson</h1><p>Loop, two steps.</p>
<subdiv-viewer id="a" src="${files.origin}/meshes/tetrahedron.off" scheme="loop" levels="2" render-mode="edges" style="width:420px;height:300px"></subdiv-viewer>
<subdiv-viewer id="b" src="cube.off" beside="loop sqrt3" rules="rules/mine.json" style="width:420px;height:200px"></subdiv-viewer>
<script>
  window.__errors = [];
  document.addEventListener('error', (e) => {
    if (e.target.localName === 'subdiv-viewer') window.__errors.push({ id: e.target.id, detail: e.detail });
  });
</script>`;
    const course = await startHost({
      cors: false,
      pages: {
        '/lesson.html': `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Lesson</title>
<script defer src="${files.origin}/embed/subdiv-viewer.js"></script></head><body>${body}</body></html>`,
      },
    });
    try {
      await page.goto(`${course.origin}/lesson.html`);
      const box = page.locator('#a').locator('[part="message"]');
      await test.step('the box, visible where the viewer would be, says what the host must send', async () => {
        await expect(box).toBeVisible();
        await expect(box).toContainText('does not send CORS headers');
        await expect(box).toContainText(`Access-Control-Allow-Origin: * (or ${course.origin})`);
        await expect(box).toContainText(
          'Or use the iframe route, which needs no CORS: embed.html?src=http://127.0.0.1:',
        );
        const rect = await page.locator('#a').boundingBox();
        expect(rect).not.toBeNull();
        expect(rect?.width).toBe(420);
        expect(rect?.height).toBe(300);
        const inView = await page.locator('#a').evaluate((e) => {
          const r = e.getBoundingClientRect();
          return r.top >= 0 && r.left >= 0 && r.bottom <= innerHeight && r.right <= innerWidth;
        });
        expect(inView).toBe(true);
        await expect(page.locator('#b').locator('[part="message"]')).toBeVisible();
        await page.screenshot({ path: `${SHOTS}/no-cors-box.png` });
      });
      await test.step('each element fires error with the reason', async () => {
        const errors = await page.evaluate(
          () => (window as unknown as { __errors: { id: string; detail: Record<string, unknown> }[] }).__errors,
        );
        expect(errors.map((e) => e.id).sort()).toEqual(['a', 'b']);
        expect(errors[0].detail).toMatchObject({ code: 'load_error', line: 0 });
        expect(errors[0].detail.message).toMatch(/sends no CORS headers \(Access-Control-Allow-Origin\)/);
        expect(errors[0].detail.source).toMatch(
          new RegExp(`^${files.origin}/embed/assets/subdiv-viewer-[\\w-]{8}\\.js$`),
        );
      });
      let route = '';
      await test.step("the box's iframe route carries the element's settings", async () => {
        route = (await box.locator('a').getAttribute('href')) ?? '';
        const url = new URL(route);
        expect(`${url.origin}${url.pathname}`).toBe(`${files.origin}/embed.html`);
        expect(Object.fromEntries(url.searchParams)).toEqual({
          src: `${files.origin}/meshes/tetrahedron.off`,
          scheme: 'loop',
          levels: '2',
          mode: 'edges',
        });
        const other = new URL((await page.locator('#b').locator('[part="message"] a').getAttribute('href')) ?? '');
        // Both URLs relative to the lesson, as the element would read them, not to embed.html.
        expect(Object.fromEntries(other.searchParams)).toEqual({
          src: `${course.origin}/cube.off`,
          beside: 'loop,sqrt3',
          rules: `${course.origin}/rules/mine.json`,
        });
      });
      await test.step('"Show it here" puts the iframe route in the box\'s place: level 2 with the right counts', async () => {
        await page.locator('#a').locator('[part="show-iframe"]').click();
        await expect(page.locator('#a').locator('[part="message"]')).toHaveCount(0);
        // The frame is attached on the click and navigates after it.
        await expect.poll(() => page.frames().some((f) => f.url() === route)).toBe(true);
        const frame = page.frames().find((f) => f.url() === route);
        if (!frame) throw new Error('no iframe of the route');
        const reading = await readingInRoute(frame);
        expect(reading.facts).toMatchObject({ ...expectedClosedCounts('loop', TETRAHEDRON, 2) });
        await expect(frame.locator('subdiv-viewer').locator('[part="message"]')).toBeHidden();
        const rect = await page.locator('#a').locator('[part="iframe"]').boundingBox();
        expect(rect).toMatchObject({ width: 420, height: 300 });
        await page.screenshot({ path: `${SHOTS}/no-cors-iframe-route.png` });
      });
    } finally {
      await files.close();
      await course.close();
    }
  });
});

test.describe('the iframe route in a sandboxed frame on a host without CORS', () => {
  test.use({ allowedConsoleErrors: [/blocked by CORS policy|^Failed to load resource: net::ERR_FAILED$/] });

  test('the frame shows the box (CORS, or allow-same-origin) and posts the error to the page', async ({ embed }) => {
    const page = embed.page;
    const files = await startHost({ cors: false });
    const course = await startHost({
      cors: false,
      pages: {
        '/lesson.html': `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Lesson</title></head><body>
<iframe id="route" title="viewer" sandbox="allow-scripts" width="480" height="300"
  src="${files.origin}/embed.html?src=meshes/tetrahedron.off&amp;scheme=loop&amp;levels=2"></iframe>
<script>
  window.__messages = [];
  window.addEventListener('message', (e) => { if (e.data && e.data.subdivlab) window.__messages.push(e.data); });
</script>
</body></html>`,
      },
    });
    try {
      await page.goto(`${course.origin}/lesson.html`);
      const frame = page.frame({ url: /embed\.html/ });
      if (!frame) throw new Error('no frame');
      const box = frame.locator('subdiv-viewer').locator('[part="message"]');
      await expect(box).toBeVisible();
      await expect(box).toContainText(`${files.origin} does not send CORS headers`);
      await expect(box).toContainText('Access-Control-Allow-Origin: * (or this sandboxed frame (origin null))');
      await expect(box).toContainText('Adding allow-same-origin to the frame');
      // Inside the route there is no route to offer.
      await expect(box.locator('[part="show-iframe"]')).toHaveCount(0);
      // The box fills the frame.
      expect(await frame.locator('subdiv-viewer').boundingBox()).toMatchObject({ width: 480, height: 300 });
      await expect
        .poll(() => page.evaluate(() => (window as unknown as { __messages: unknown[] }).__messages))
        .toEqual([
          {
            subdivlab: 'error',
            code: 'load_error',
            line: 0,
            source: `${files.origin}/embed/iframe-route.js`,
            message: expect.stringMatching(/sends no CORS headers \(Access-Control-Allow-Origin\)/),
          },
        ]);
      await page.locator('#route').screenshot({ path: `${SHOTS}/sandboxed-route-no-cors.png` });
    } finally {
      await files.close();
      await course.close();
    }
  });
});

/** The iframe route's element (it has no id): waits for level 2 and reads it. */
async function readingInRoute(page: Frame) {
  await expect
    .poll(() =>
      page.evaluate(() => {
        const e = document.querySelector('subdiv-viewer');
        return e && e.level === 2 && !e.state?.busy;
      }),
    )
    .toBe(true);
  return page.evaluate(() => {
    const e = document.querySelector('subdiv-viewer') as HTMLElementTagNameMap['subdiv-viewer'];
    return { level: e.level, facts: e.facts, busy: false };
  });
}

test.describe('a copy of embed/ without its assets', () => {
  test.use({ allowedConsoleErrors: [/^Failed to load resource: the server responded with a status of 404/] });

  /** A page with one element (#x) whose files matching `missing` answer 404: its box. */
  async function boxWithout(embed: EmbedPage, page: Page, missing: RegExp, name: string) {
    await page.route(missing, (route) => route.fulfill({ status: 404, body: '' }));
    await embed.serve(
      `e2e/${name}.html`,
      viewerPage(
        name,
        'subdiv-viewer{width:420px;height:240px}',
        '<subdiv-viewer id="x" src="../meshes/tetrahedron.off"></subdiv-viewer>',
      ).replace('<script type="module" src=', '<script defer src='),
    );
    await page.goto(`./e2e/${name}.html`);
    const box = page.locator('#x').locator('[part="message"]');
    await expect(box).toBeVisible();
    await expect(box).not.toContainText('CORS headers');
    return box;
  }

  test('the box says the module is not there (HTTP 404) and to copy the whole folder', async ({ embed, page }) => {
    const box = await boxWithout(embed, page, /\/embed\/assets\/subdiv-viewer-[\w-]{8}\.js$/, 'no-assets');
    await expect(box).toContainText(
      /The SubdivLab module http:\/\/127\.0\.0\.1:\d+\/embed\/assets\/subdiv-viewer-[\w-]{8}\.js is not there \(HTTP 404\)\./,
    );
    await expect(box).toContainText(
      'Copy the whole embed/ folder of the build (subdiv-viewer.js and assets/) next to the page.',
    );
    const errors = await embed.events('error', 'x');
    expect(errors).toHaveLength(1);
    expect(errors[0].detail).toMatchObject({ code: 'load_error', line: 0 });
    expect(errors[0].detail.message).toMatch(/could not be loaded: HTTP 404\.$/);
    await page.emulateMedia({ colorScheme: 'dark' });
    await page.locator('#x').screenshot({ path: `${SHOTS}/box-404-dark.png` });
  });

  test('the module there but the chunk it imports missing: the box names the files it imports, not only a policy', async ({
    embed,
    page,
  }) => {
    const box = await boxWithout(embed, page, /\/embed\/assets\/subdiv-viewer-element-[\w-]{8}\.js$/, 'no-chunk');
    await expect(box).toContainText(/did not run on this page: the browser did not load it\./);
    await expect(box).toContainText(
      /Check that the files it imports are there too \(http:\/\/127\.0\.0\.1:\d+\/embed\/assets\/: copy the whole embed\/ folder\)/,
    );
  });
});

test('an element and an iframe of embed.html on one page fetch three.js once', async ({ embed }) => {
  const page = embed.page;
  // A host with CORS, as a public one; HTTP caching on (page.route would turn the browser's cache off).
  const host = await startHost({ cors: true });
  const course = await startHost({
    cors: false,
    pages: {
      '/lesson.html': `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Lesson</title>
<script defer src="${host.origin}/embed/subdiv-viewer.js"></script></head><body>
<subdiv-viewer id="x" src="${host.origin}/meshes/tetrahedron.off" scheme="loop" levels="2" style="width:320px;height:220px"></subdiv-viewer>
<iframe title="viewer" src="${host.origin}/embed.html?src=meshes/tetrahedron.off&amp;scheme=loop&amp;levels=1" width="320" height="220" style="border:0"></iframe>
</body></html>`,
    },
  });
  try {
    await page.goto(`${course.origin}/lesson.html`);
    // The loader's module script holds the load event: the element is defined when goto returns.
    expect(
      await page.locator('#x').evaluate((e) => typeof (e as HTMLElementTagNameMap['subdiv-viewer']).setLevel),
    ).toBe('function');
    const reading = await waitForLevelIn(page, 'x', 2);
    expect(reading.facts).toMatchObject({ ...expectedClosedCounts('loop', TETRAHEDRON, 2) });
    const frame = page.frame({ url: /embed\.html/ });
    if (!frame) throw new Error('no frame');
    await expect.poll(() => frame.evaluate(() => document.querySelector('subdiv-viewer')?.level ?? -1)).toBe(1);
    const three = host.served.filter((s) => s.three);
    // One body with three.js, the shared chunk: the second use came from the browser's cache.
    expect(three).toHaveLength(1);
    expect(three[0].path).toMatch(/^\/embed\/assets\/subdiv-viewer-element-[\w-]{8}\.js$/);
    expect(host.served.filter((s) => s.path === three[0].path)).toHaveLength(1);
    // Both ran: the element's module and the frame's route script came from this host.
    const paths = host.served.map((s) => s.path);
    expect(paths).toContain('/embed.html');
    expect(paths).toContain('/embed/iframe-route.js');
    expect(paths.filter((p) => /^\/embed\/assets\/subdiv-viewer-[\w-]{8}\.js$/.test(p))).toHaveLength(1);
  } finally {
    await host.close();
    await course.close();
  }
});

test.describe('a worker that cannot start', () => {
  test.use({
    allowedConsoleErrors: [/^Creating a worker from .* violates the following Content Security Policy directive/],
  });

  test('a policy refusing workers: the element says the core could not be started and why, not that it stopped unexpectedly', async ({
    embed,
    page,
  }) => {
    await embed.serve(
      'e2e/no-workers.html',
      viewerPage(
        'No workers',
        'subdiv-viewer{width:420px;height:260px}',
        `<subdiv-viewer id="x" src="../meshes/tetrahedron.off" scheme="loop" levels="2"></subdiv-viewer>`,
      ).replace('<head>', `<head><meta http-equiv="Content-Security-Policy" content="worker-src 'none'">`),
    );
    await page.goto('./e2e/no-workers.html');
    const message = page.locator('#x').locator('[part="message"]');
    await expect(message).toBeVisible();
    await expect(message).toContainText('The SubdivLab core could not be started');
    await expect(message).not.toContainText('stopped unexpectedly');
    await expect(message).not.toContainText('levels already shown');
    const errors = await embed.events('error', 'x');
    expect(errors).toHaveLength(1);
    expect(errors[0].detail.message).toMatch(/^The SubdivLab core could not be started: /);
    expect((await embed.reading('x')).level).toBe(-1);
    await page.locator('#x').screenshot({ path: `${SHOTS}/worker-start.png` });
  });
});
