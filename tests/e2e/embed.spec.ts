/**
 * <subdiv-viewer> and the iframe route as a teacher's page uses them: the
 * shipped teaching example, and a test page with twelve elements and an
 * iframe. Counts are checked against the schemes' refinement rules
 * (helpers.ts), never against the app's own code.
 */
import { createServer } from 'node:http';
import type { AddressInfo } from 'node:net';
import type { Locator } from '@playwright/test';
import { viewerPage } from './embed-page';
import { expect, test } from './fixtures';
import { expectedClosedCounts, quadGridOff, readPng, triangulatedQuads } from './helpers';

const OCTAHEDRON = { vertices: 6, edges: 12, faces: 8 };
/** A tetrahedron as a page would hand it to load(). */
const TETRA = 'OFF\n4 4 0\n1 1 1\n-1 -1 1\n-1 1 -1\n1 -1 -1\n3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n';

test('the teaching example: four schemes on the octahedron, counts in the table from level-change events', async ({
  embed,
  page,
}) => {
  await page.setViewportSize({ width: 1100, height: 900 });
  await page.goto('./examples/');
  const viewers = { cc: 'catmull-clark', loop: 'loop', ds: 'doo-sabin', sqrt3: 'sqrt3' } as const;
  for (const [id, scheme] of Object.entries(viewers)) {
    await test.step(`${scheme} reaches level 2 with its exact counts`, async () => {
      await page.locator(`#${id}`).scrollIntoViewIfNeeded();
      const reading = await embed.waitForLevel(id, 2);
      const want = expectedClosedCounts(scheme, OCTAHEDRON, 2);
      expect(reading.facts).toMatchObject({ ...want, genus: 0, closed: true });
      const event = await embed.lastLevelChange(id);
      expect(event?.detail).toMatchObject({ level: 2, scheme, facts: want });
      const cells = await page.locator(`#counts tr[data-viewer="${id}"] td`).allTextContents();
      expect(cells.slice(1).map(Number)).toEqual([2, want.vertices, want.edges, want.faces, 0]);
    });
  }
  await test.step('the iframe shows the torus at level 1', async () => {
    const frame = page.frameLocator('#torus-frame');
    await page.locator('#torus-frame').scrollIntoViewIfNeeded();
    await expect(frame.locator('subdiv-viewer')).toHaveAttribute('levels', '1');
    await expect
      .poll(() =>
        page
          .frame({ url: /embed\.html/ })
          ?.evaluate(() => (document.querySelector('subdiv-viewer') as HTMLElementTagNameMap['subdiv-viewer']).level),
      )
      .toBe(1);
  });
  await page.evaluate(() => window.scrollTo(0, 0));
  await embed.snapshot('embed-example-page');
  await embed.snapshot('embed-example-page-full', true);
});

const MESHES = {
  cube: { vertices: 8, edges: 12, faces: 6 },
  tetrahedron: { vertices: 4, edges: 6, faces: 4 },
  octahedron: OCTAHEDRON,
  icosahedron: { vertices: 12, edges: 30, faces: 20 },
  torus: { vertices: 48, edges: 96, faces: 48 },
} as const;

/** The twelve viewers of the test page: mesh, scheme, levels (v10's src does not exist). */
const TWELVE: { mesh: keyof typeof MESHES; scheme: string; levels: number }[] = [
  { mesh: 'cube', scheme: 'catmull-clark', levels: 1 },
  { mesh: 'tetrahedron', scheme: 'loop', levels: 2 },
  { mesh: 'octahedron', scheme: 'sqrt3', levels: 1 },
  { mesh: 'icosahedron', scheme: 'loop', levels: 1 },
  { mesh: 'torus', scheme: 'catmull-clark', levels: 1 },
  { mesh: 'cube', scheme: 'doo-sabin', levels: 2 },
  { mesh: 'tetrahedron', scheme: 'sqrt3', levels: 2 },
  { mesh: 'octahedron', scheme: 'catmull-clark', levels: 2 },
  { mesh: 'icosahedron', scheme: 'doo-sabin', levels: 1 },
  { mesh: 'torus', scheme: 'doo-sabin', levels: 1 },
  { mesh: 'cube', scheme: 'catmull-clark', levels: 1 },
  { mesh: 'octahedron', scheme: 'loop', levels: 3 },
];
const BAD = 10;

function twelveViewerPage(): string {
  const viewers = TWELVE.map(({ mesh, scheme, levels }, i) => {
    const src = i === BAD ? '../meshes/missing.off' : `../meshes/${mesh}.off`;
    return `<subdiv-viewer id="v${i}" src="${src}" scheme="${scheme}" levels="${levels}" controls="full"></subdiv-viewer>`;
  });
  return viewerPage(
    'Twelve viewers',
    `body{margin:0 20px} subdiv-viewer{width:600px;height:300px;margin:0 0 60px}`,
    `<label>Notes <input id="field"></label>
${viewers.join('\n')}
<iframe id="frame" title="Loop on a tetrahedron" style="width:500px;height:300px;border:0"
  src="../embed.html?src=meshes/tetrahedron.off&amp;scheme=loop&amp;levels=1&amp;controls=none"></iframe>`,
  );
}

test.describe('a page with twelve viewers and an iframe', () => {
  test.use({ allowedConsoleErrors: [/404/] });

  test('one core, lazy start, exact counts by events, GPU released and restored, live attributes, one bad src', async ({
    embed,
    page,
  }) => {
    const wasmRequests: string[] = [];
    page.on('request', (request) => {
      if (request.url().endsWith('.wasm') && request.frame() === page.mainFrame()) wasmRequests.push(request.url());
    });
    const warnings: string[] = [];
    page.on('console', (message) => {
      if (message.type() === 'warning') warnings.push(message.text());
    });
    await embed.serve('e2e/twelve.html', twelveViewerPage());
    // A static host's 404 (vite preview would answer with the app's index.html).
    await page.route('**/missing.off', (route) => route.fulfill({ status: 404, body: 'Not found' }));
    await page.goto('./e2e/twelve.html');

    await test.step('the viewers near the viewport start; the far ones wait', async () => {
      await embed.waitForLevel('v0', 1);
      await embed.waitForLevel('v1', 2);
      expect((await embed.reading('v9')).started).toBe(false);
      expect(await embed.events('load', 'v9')).toEqual([]);
    });

    for (const [i, { mesh, scheme, levels }] of TWELVE.entries()) {
      await test.step(`v${i}: ${scheme} on the ${mesh}, level ${levels}`, async () => {
        await page.locator(`#v${i}`).scrollIntoViewIfNeeded();
        if (i === BAD) {
          await expect.poll(async () => (await embed.events('error', `v${i}`)).length).toBe(1);
          const [error] = await embed.events('error', `v${i}`);
          expect(error.detail).toMatchObject({ code: 'load_error', line: 0 });
          expect(String(error.detail.message)).toContain('404');
          expect(String(error.detail.source)).toContain('missing.off');
          await expect(page.locator(`#v${i}`).locator('.message')).toContainText('404');
          expect((await embed.reading(`v${i}`)).level).toBe(-1);
          return;
        }
        const reading = await embed.waitForLevel(`v${i}`, levels);
        const want = expectedClosedCounts(scheme, MESHES[mesh], levels);
        expect(reading.facts).toMatchObject({ ...want });
        expect((await embed.lastLevelChange(`v${i}`))?.detail).toMatchObject({ level: levels, scheme, facts: want });
        expect(await embed.events('load', `v${i}`)).toHaveLength(1);
      });
    }

    await test.step('far above, the first viewers give back their GPU memory; back in view they draw the same level', async () => {
      await page.locator('#frame').scrollIntoViewIfNeeded();
      await expect.poll(async () => (await embed.reading('v0')).gpuReleased).toBe(true);
      expect((await embed.reading('v11')).gpuReleased).toBe(false);
      await page.evaluate(() => window.scrollTo(0, 0));
      await expect.poll(async () => (await embed.reading('v0')).gpuReleased).toBe(false);
      const v0 = await embed.reading('v0');
      expect(v0.level).toBe(1);
      expect(v0.facts).toMatchObject({ ...expectedClosedCounts('catmull-clark', MESHES.cube, 1) });
      const pixels = await page.locator('#v0').screenshot();
      await page.locator('#v0').evaluate((e) => e.setAttribute('render-mode', 'wireframe'));
      await expect.poll(async () => (await page.locator('#v0').screenshot()).equals(pixels)).toBe(false);
    });

    await test.step('levels="3" recomputes to level 3, with progress events around each step', async () => {
      const progressBefore = (await embed.events('progress', 'v0')).length;
      await page.locator('#v0').evaluate((e) => e.setAttribute('levels', '3'));
      const reading = await embed.waitForLevel('v0', 3);
      const progress = (await embed.events('progress', 'v0')).slice(progressBefore).map((e) => e.detail);
      expect(progress).toEqual([
        { busy: true, kind: 'subdivide', label: 'Subdividing to level 2…' },
        { busy: false, kind: null, label: '' },
        { busy: true, kind: 'subdivide', label: 'Subdividing to level 3…' },
        { busy: false, kind: null, label: '' },
      ]);
      expect(reading.facts).toMatchObject({ ...expectedClosedCounts('catmull-clark', MESHES.cube, 3) });
      expect((await embed.lastLevelChange('v0'))?.detail).toMatchObject({ level: 3 });
    });

    await test.step("keys typed in the page's text field never reach a viewer; on a focused viewer they act on it alone", async () => {
      await page.locator('#field').click();
      await page.keyboard.type('s[]r');
      await expect(page.locator('#field')).toHaveValue('s[]r');
      expect((await embed.reading('v0')).level).toBe(3);
      expect((await embed.reading('v1')).level).toBe(2);
      await page.locator('#v1').focus();
      await page.keyboard.press('s');
      expect((await embed.waitForLevel('v1', 3)).facts).toMatchObject({
        ...expectedClosedCounts('loop', MESHES.tetrahedron, 3),
      });
      await page.keyboard.press('[');
      await embed.waitForLevel('v1', 2);
      expect((await embed.reading('v0')).level).toBe(3);
      await expect(page.locator('#field')).toHaveValue('s[]r');
    });

    await test.step('the whole page fetched the .wasm once, and no WebGL context was lost', async () => {
      expect(wasmRequests).toHaveLength(1);
      expect(warnings.filter((w) => /WebGL/i.test(w))).toEqual([]);
    });
    await page.evaluate(() => window.scrollTo(0, 0));
    await embed.snapshot('embed-twelve-viewers');
  });

  test('the iframe route: ready and level-change reach the parent; set-level by postMessage; malformed messages ignored', async ({
    embed,
    page,
  }) => {
    await embed.serve('e2e/twelve.html', twelveViewerPage());
    await page.goto('./e2e/twelve.html');
    await page.locator('#frame').scrollIntoViewIfNeeded();
    await expect.poll(async () => (await embed.events('message:ready')).length).toBe(1);
    const loop1 = expectedClosedCounts('loop', MESHES.tetrahedron, 1);
    await expect
      .poll(async () => (await embed.events('message:level-change')).at(-1)?.detail)
      .toMatchObject({ level: 1, scheme: 'loop', facts: loop1 });
    expect((await embed.events('message:load')).at(-1)?.detail).toMatchObject({ modelName: 'tetrahedron.off' });

    const frameWarnings: string[] = [];
    page.on('console', (message) => {
      if (message.type() === 'warning' && message.text().includes('[subdivlab]')) frameWarnings.push(message.text());
    });
    await page.evaluate(() => {
      const frame = document.getElementById('frame') as HTMLIFrameElement;
      const target = frame.contentWindow as Window;
      target.postMessage('set-level 3', '*');
      target.postMessage({ subdivlab: 'set-level', level: '3' }, '*');
      target.postMessage({ subdivlab: 'eval', code: 'alert(1)' }, '*');
      target.postMessage({ subdivlab: 'set-level', level: 2 }, '*');
    });
    await page.evaluate(() => {
      const frame = document.getElementById('frame') as HTMLIFrameElement;
      (frame.contentWindow as Window).postMessage({ subdivlab: 'set-render-mode', mode: 'wireframe' }, '*');
      (frame.contentWindow as Window).postMessage({ subdivlab: 'set-overlay', overlay: 'control-mesh', on: true }, '*');
    });
    const inner = page.frames().find((f) => f.url().includes('embed.html'));
    await expect
      .poll(() =>
        inner?.evaluate(() => {
          const v = document.querySelector('subdiv-viewer') as HTMLElementTagNameMap['subdiv-viewer'];
          return [v.renderMode, v.controlMesh];
        }),
      )
      .toEqual(['wireframe', true]);
    const loop2 = expectedClosedCounts('loop', MESHES.tetrahedron, 2);
    await expect
      .poll(async () => (await embed.events('message:level-change')).at(-1)?.detail)
      .toMatchObject({ level: 2, facts: loop2 });
    expect(frameWarnings).toHaveLength(3);
    expect(frameWarnings[2]).toContain('unknown command "eval"');
    // Levels 1 → 2 only: the malformed set-level never ran.
    const levels = (await embed.events('message:level-change')).map((e) => e.detail.level);
    expect(levels).not.toContain(3);

    await page.evaluate(() => {
      const frame = document.getElementById('frame') as HTMLIFrameElement;
      (frame.contentWindow as Window).postMessage({ subdivlab: 'set-scheme', scheme: 'sqrt3' }, '*');
    });
    await expect
      .poll(async () => (await embed.events('message:level-change')).at(-1)?.detail)
      .toMatchObject({ level: 2, scheme: 'sqrt3', facts: expectedClosedCounts('sqrt3', MESHES.tetrahedron, 2) });
  });
});

test("cancelling one viewer stops only its step; the next viewer's queued step completes", async ({ embed, page }) => {
  await embed.serve(
    'e2e/cancel.html',
    viewerPage(
      'Cancel',
      `subdiv-viewer{width:400px;height:240px}`,
      `<subdiv-viewer id="big" src="../meshes/cgal/bunny00.off" scheme="loop" levels="0"></subdiv-viewer>
<subdiv-viewer id="small" src="../meshes/cube.off" scheme="catmull-clark" levels="0"></subdiv-viewer>`,
    ),
  );
  await page.goto('./e2e/cancel.html');
  await embed.waitForLevel('big', 0);
  await embed.waitForLevel('small', 0);
  const result = await page.evaluate(async () => {
    const big = document.getElementById('big') as HTMLElementTagNameMap['subdiv-viewer'];
    const small = document.getElementById('small') as HTMLElementTagNameMap['subdiv-viewer'];
    const bigDone = big.setLevel(2);
    const smallDone = small.setLevel(2);
    big.cancel();
    const [bigLevel, smallLevel] = await Promise.all([bigDone, smallDone]);
    return { bigLevel, smallLevel, smallFacts: small.facts };
  });
  expect(result.bigLevel).toBe(0);
  expect(result.smallLevel).toBe(2);
  expect(result.smallFacts).toMatchObject({ ...expectedClosedCounts('catmull-clark', MESHES.cube, 2) });
  expect(await embed.events('error', 'big')).toEqual([]);
  // The cancelled viewer works on afterwards.
  expect(
    await page.evaluate(() => (document.getElementById('big') as HTMLElementTagNameMap['subdiv-viewer']).setLevel(1)),
  ).toBe(1);
  expect((await embed.reading('big')).facts?.faces).toBe(4 * 75408);
});

test('a viewer with nothing to send draws while another waits for the GPU to take its upload', async ({
  embed,
  page,
}) => {
  test.setTimeout(120_000);
  type Viewer = HTMLElementTagNameMap['subdiv-viewer'];
  await embed.serve(
    'e2e/two.html',
    viewerPage(
      'Two',
      `subdiv-viewer{width:320px;height:240px;display:inline-block}`,
      `<subdiv-viewer id="big"></subdiv-viewer>
<subdiv-viewer id="small" src="../meshes/cube.off"></subdiv-viewer>`,
    ),
  );
  await page.goto('./e2e/two.html');
  await embed.waitForLevel('small', 0);
  // 300 × 300 quads: level 2 has 1,442,401 points (17 MB of positions, as many of normals), sent in parts.
  await page.locator('#big').evaluate((e, text) => (e as Viewer).load(text, 'grid.off'), quadGridOff(300));
  await embed.waitForLevel('big', 0);
  // A GPU that never passes a fence (its transfer space full): the big level's parts stop after the first frame's.
  await page.evaluate(() => {
    const w = window as unknown as { fences: number; restoreSync: () => void };
    const proto = WebGL2RenderingContext.prototype;
    const { fenceSync, getSyncParameter } = proto;
    w.fences = 0;
    proto.fenceSync = function (this: WebGL2RenderingContext, condition: GLenum, flags: GLbitfield) {
      w.fences++;
      return fenceSync.call(this, condition, flags);
    };
    proto.getSyncParameter = function (this: WebGL2RenderingContext, sync: WebGLSync, pname: GLenum) {
      return pname === this.SYNC_STATUS ? this.UNSIGNALED : getSyncParameter.call(this, sync, pname);
    };
    w.restoreSync = () => {
      proto.fenceSync = fenceSync;
      proto.getSyncParameter = getSyncParameter;
    };
  });
  await page.locator('#big').evaluate((e) => {
    void (e as Viewer).setLevel(2);
  });
  await embed.waitForLevel('big', 2);
  await expect.poll(() => page.evaluate(() => (window as unknown as { fences: number }).fences)).toBeGreaterThan(0);
  const before = await page.locator('#small').screenshot();
  await page.locator('#small').evaluate((e) => (e as Viewer).setView('5,1,2,0,0,0,0,1,0'));
  // Drawn within frames, not once the view gives up on the fence (5 s).
  await expect
    .poll(async () => (await page.locator('#small').screenshot()).equals(before), { timeout: 2500 })
    .toBe(false);
  await page.evaluate(() => (window as unknown as { restoreSync: () => void }).restoreSync());
  expect((await embed.reading('big')).facts?.vertices).toBe(1_442_401);
  expect(await embed.events('error', 'big')).toEqual([]);
});

test.describe('styled by the page', () => {
  test.use({ colorScheme: 'dark' });

  test('sized by page CSS, parts styled with ::part(), dark background under prefers-color-scheme: dark', async ({
    embed,
    page,
  }) => {
    await embed.serve(
      'e2e/styled.html',
      viewerPage(
        'Styled',
        `
  #a { width: 420px; height: 260px; }
  subdiv-viewer::part(level-up) { background-color: rgb(200, 0, 0); }
`,
        `<subdiv-viewer id="a" src="../meshes/cube.off" levels="1" controls="minimal"></subdiv-viewer>
<subdiv-viewer id="b" src="../meshes/cube.off" levels="1" controls="none" background="#ffffff" style="width:300px;height:200px"></subdiv-viewer>`,
      ),
    );
    await page.goto('./e2e/styled.html');
    await embed.waitForLevel('a', 1);
    await embed.waitForLevel('b', 1);
    expect(await page.locator('#a').boundingBox()).toMatchObject({ width: 420, height: 260 });
    const upColour = await page
      .locator('#a')
      .evaluate((e) => getComputedStyle(e.shadowRoot?.querySelector('[part="level-up"]') as Element).backgroundColor);
    expect(upColour).toBe('rgb(200, 0, 0)');
    expect(
      await page.locator('#b').evaluate((e) => e.shadowRoot?.querySelector<HTMLElement>('[part="controls"]')?.hidden),
    ).toBe(true);
    // A corner pixel of each picture (the view's own 2D canvas): the background, away from the model.
    const corner = (id: string) =>
      page.locator(`#${id}`).evaluate((e) => {
        const canvas = e.shadowRoot?.querySelector('canvas') as HTMLCanvasElement;
        return Array.from((canvas.getContext('2d') as CanvasRenderingContext2D).getImageData(1, 1, 1, 1).data);
      });
    expect(await corner('a')).toEqual([0x1f, 0x23, 0x28, 255]);
    expect(await corner('b')).toEqual([255, 255, 255, 255]);
  });
});

test('a lost WebGL context comes back: a viewer drawn meanwhile draws its level again by itself', async ({
  embed,
  page,
}) => {
  // Keep a handle on the page's one WebGL context (the shared renderer's) to lose it on purpose.
  await page.addInitScript(() => {
    const getContext = HTMLCanvasElement.prototype.getContext;
    HTMLCanvasElement.prototype.getContext = function (this: HTMLCanvasElement, type: string, ...rest: unknown[]) {
      const context = (getContext as (...a: unknown[]) => RenderingContext | null).call(this, type, ...rest);
      if (type.startsWith('webgl'))
        (window as unknown as { __gl: WebGLRenderingContext }).__gl = context as WebGLRenderingContext;
      return context;
    } as typeof getContext;
  });
  await embed.serve(
    'e2e/lost.html',
    viewerPage(
      'Lost context',
      `subdiv-viewer{width:300px;height:220px;display:inline-block}`,
      `<subdiv-viewer id="a" src="../meshes/cube.off" levels="1" controls="none"></subdiv-viewer>
<subdiv-viewer id="b" src="../meshes/icosahedron.off" scheme="loop" levels="1" controls="none"></subdiv-viewer>`,
    ),
  );
  await page.goto('./e2e/lost.html');
  await embed.waitForLevel('a', 1);
  await embed.waitForLevel('b', 1);
  const centre = (id: string) =>
    page.locator(`#${id}`).evaluate((e) => {
      const canvas = e.shadowRoot?.querySelector('canvas') as HTMLCanvasElement;
      const context = canvas.getContext('2d') as CanvasRenderingContext2D;
      return Array.from(context.getImageData(canvas.width >> 1, canvas.height >> 1, 1, 1).data);
    });
  const background = [0xf3, 0xf4, 0xf6, 255];
  await expect.poll(() => centre('a')).not.toEqual(background);
  const before = { a: await centre('a'), b: await centre('b') };
  const context = (call: 'loseContext' | 'restoreContext') =>
    page.evaluate((name) => {
      // A lost context answers no getExtension: keep the extension from before.
      const w = window as unknown as { __gl: WebGLRenderingContext; __lose?: WEBGL_lose_context };
      w.__lose ??= w.__gl.getExtension('WEBGL_lose_context') as WEBGL_lose_context;
      w.__lose[name]();
    }, call);
  const redraw = async (id: string) => {
    // A render-mode round trip makes the view draw again, showing the same picture.
    await page.locator(`#${id}`).evaluate((e) => e.setAttribute('render-mode', 'flat'));
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    await page.locator(`#${id}`).evaluate((e) => e.setAttribute('render-mode', 'smooth'));
  };
  await context('loseContext');
  // Drawn while the context is lost: nothing can be drawn, the picture is empty for now.
  await redraw('b');
  await expect.poll(() => centre('b')).not.toEqual(before.b);
  await context('restoreContext');
  // b draws again by itself once the context is back; a draws when asked.
  await redraw('a');
  await expect.poll(() => centre('a')).toEqual(before.a);
  await expect.poll(() => centre('b')).toEqual(before.b);
});

test('a page on another origin uses the hosted element: module, worker (through a blob: shim) and .wasm load across origins', async ({
  embed,
  page,
  baseURL,
}) => {
  const host = new URL(baseURL ?? 'http://127.0.0.1:4179/').origin;
  // A course page served by a second server on this machine: another origin to the browser.
  const lesson = `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Lesson</title>
<script type="module" src="${host}/embed/subdiv-viewer.js"></script></head><body>
<subdiv-viewer id="x" src="${host}/meshes/tetrahedron.off" scheme="loop" levels="2" style="width:320px;height:240px"></subdiv-viewer>
</body></html>`;
  const server = createServer((_request, response) => {
    response.writeHead(200, { 'content-type': 'text/html; charset=utf-8' });
    response.end(lesson);
  });
  await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
  try {
    const origin = `http://127.0.0.1:${(server.address() as AddressInfo).port}`;
    expect(origin).not.toBe(host);
    const workers: string[] = [];
    page.on('worker', (worker) => workers.push(worker.url()));
    await page.goto(`${origin}/course/lesson.html`);
    const reading = await embed.waitForLevel('x', 2);
    expect(reading.facts).toMatchObject({ ...expectedClosedCounts('loop', MESHES.tetrahedron, 2) });
    expect(workers).toHaveLength(1);
    expect(workers[0]).toMatch(new RegExp(`^blob:${origin}/`));
  } finally {
    await new Promise<void>((resolve) => server.close(() => resolve()));
  }
});

test.describe('what pages do to an element', () => {
  test.use({ allowedConsoleErrors: [] });

  test('properties set before the module loads, a level the scheme cannot reach yet, the top level, setView', async ({
    embed,
    page,
  }) => {
    await embed.serve(
      'e2e/early.html',
      `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Early</title></head><body>
<subdiv-viewer id="p" src="../meshes/cube.off" style="width:320px;height:220px"></subdiv-viewer>
<subdiv-viewer id="q" src="../meshes/cube.off" scheme="loop" levels="2" style="width:320px;height:220px"></subdiv-viewer>
<subdiv-viewer id="r" src="../meshes/tetrahedron.off" scheme="linear-tri" levels="7" style="width:320px;height:220px"></subdiv-viewer>
<script>
  // A classic script before the module: plain properties on a not-yet-defined element.
  const p = document.getElementById('p');
  p.levels = 2;
  p.renderMode = 'edges';
</script>
<script type="module" src="../embed/subdiv-viewer.js"></script>
</body></html>`,
    );
    await page.goto('./e2e/early.html');
    await test.step('properties set early apply once the element is defined', async () => {
      const p = await embed.waitForLevel('p', 2);
      expect(p.facts).toMatchObject({ ...expectedClosedCounts('catmull-clark', MESHES.cube, 2) });
      expect(await page.locator('#p').evaluate((e) => e.getAttribute('render-mode'))).toBe('edges');
    });
    await test.step('a level Loop cannot reach on quads keeps levels="2"; triangulate then reaches it', async () => {
      await expect.poll(async () => (await embed.events('error', 'q')).length).toBe(1);
      expect((await embed.events('error', 'q'))[0].detail).toMatchObject({ code: 'not_triangles' });
      const q = await embed.reading('q');
      expect(q).toMatchObject({ level: 0, levelsAttribute: '2' });
      await expect(page.locator('#q').locator('.message')).toBeVisible();
      await page.locator('#q').evaluate((e) => {
        (e as HTMLElementTagNameMap['subdiv-viewer']).triangulate = true;
      });
      const reached = await embed.waitForLevel('q', 2);
      expect(reached.facts).toMatchObject({ ...expectedClosedCounts('loop', triangulatedQuads(MESHES.cube), 2) });
      await expect(page.locator('#q').locator('.message')).toBeHidden();
      expect(await embed.events('error', 'q')).toHaveLength(1);
    });
    await test.step('level 8 is the top: + is off there and subdivide() stays', async () => {
      await embed.waitForLevel('r', 7);
      expect(await page.locator('#r').evaluate((e) => (e as HTMLElementTagNameMap['subdiv-viewer']).subdivide())).toBe(
        8,
      );
      await expect(page.locator('#r').locator('[part="level-up"]')).toBeDisabled();
      expect(await page.locator('#r').evaluate((e) => (e as HTMLElementTagNameMap['subdiv-viewer']).subdivide())).toBe(
        8,
      );
      expect(await page.locator('#r').evaluate((e) => (e as HTMLElementTagNameMap['subdiv-viewer']).setLevel(20))).toBe(
        8,
      );
      expect((await embed.reading('r')).facts?.faces).toBe(4 * 4 ** 8);
      expect(await embed.events('error', 'r')).toEqual([]);
    });
    await test.step('setView takes the view string and refuses what no camera can take', async () => {
      const view = await page.locator('#p').evaluate((e) => {
        const v = e as HTMLElementTagNameMap['subdiv-viewer'];
        v.setView('0,0,6,0,0,0,0,1,0');
        return v.getView();
      });
      expect(view).toEqual({ position: [0, 0, 6], target: [0, 0, 0], up: [0, 1, 0] });
      const refused = await page.locator('#p').evaluate((e) => {
        const v = e as HTMLElementTagNameMap['subdiv-viewer'];
        const errors: string[] = [];
        for (const bad of ['1,2', { position: [0, 0, 0], target: [0, 0, 0], up: [0, 1, 0] }]) {
          try {
            v.setView(bad as string);
          } catch (error) {
            errors.push((error as Error).name);
          }
        }
        return errors;
      });
      expect(refused).toEqual(['TypeError', 'TypeError']);
    });
  });

  test('a lower level stops the running step; load() wins over a src still downloading; removal stops the pass', async ({
    embed,
    page,
  }) => {
    const CUBE =
      'OFF\n8 6 0\n-1 -1 -1\n1 -1 -1\n1 1 -1\n-1 1 -1\n-1 -1 1\n1 -1 1\n1 1 1\n-1 1 1\n4 3 2 1 0\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n';
    await page.route('**/slow/*.off', async (route) => {
      await new Promise((r) => setTimeout(r, 1500));
      await route.fulfill({ body: CUBE, contentType: 'text/plain' });
    });
    await embed.serve(
      'e2e/races.html',
      viewerPage(
        'Races',
        `subdiv-viewer{width:320px;height:220px;display:inline-block}`,
        `<subdiv-viewer id="big" src="../meshes/cgal/bunny00.off" scheme="loop"></subdiv-viewer>
<subdiv-viewer id="slow"></subdiv-viewer>
<subdiv-viewer id="gone" levels="2"></subdiv-viewer>`,
      ),
    );
    await page.goto('./e2e/races.html');
    await test.step('levels back to 0 during the first Loop step of the bunny stops it', async () => {
      await embed.waitForLevel('big', 0);
      const result = await page.locator('#big').evaluate(async (e) => {
        const v = e as HTMLElementTagNameMap['subdiv-viewer'];
        const started = performance.now();
        // Back to 0 as soon as the first step is under way (a fixed wait lost the race on a fast machine).
        const stepping = (window.__stepUnderWay as (element: HTMLElement) => Promise<string>)(v);
        const done = v.setLevel(2);
        const label = await stepping;
        v.levels = 0;
        const level = await done;
        return { level, label, ms: performance.now() - started };
      });
      expect(result.level).toBe(0);
      expect(result.label).toMatch(/level 1/);
      const levels = (await embed.events('level-change', 'big')).map((e) => e.detail.level);
      expect(levels).toEqual([0]);
      expect(await embed.events('error', 'big')).toEqual([]);
    });
    await test.step('load() while src is still downloading: the loaded text stays', async () => {
      await page.locator('#slow').evaluate(async (e, text) => {
        const v = e as HTMLElementTagNameMap['subdiv-viewer'];
        v.src = '../slow/cube.off';
        await v.load(text, 'tetra.off');
      }, TETRA);
      await page.waitForTimeout(2000);
      expect((await embed.reading('slow')).facts).toMatchObject(MESHES.tetrahedron);
      expect((await embed.events('load', 'slow')).map((e) => e.detail.modelName)).toEqual(['tetra.off']);
    });
    await test.step('cancel() stops a download: progress says so, nothing is loaded', async () => {
      await page.locator('#gone').evaluate(async (e) => {
        e.setAttribute('src', '../slow/third.off');
        await new Promise((r) => setTimeout(r, 200));
        (e as HTMLElementTagNameMap['subdiv-viewer']).cancel();
      });
      await page.waitForTimeout(1800);
      expect((await embed.events('progress', 'gone')).map((e) => e.detail)).toEqual([
        { busy: true, kind: 'load', label: 'Downloading third.off…' },
        { busy: false, kind: null, label: '' },
      ]);
      expect(await embed.events('load', 'gone')).toEqual([]);
      expect(await embed.events('error', 'gone')).toEqual([]);
    });
    await test.step('an element removed while its src downloads does nothing more', async () => {
      await page.locator('#gone').evaluate(async (e) => {
        e.setAttribute('src', '../slow/other.off');
        await new Promise((r) => setTimeout(r, 200));
        e.remove();
      });
      await page.waitForTimeout(2000);
      expect(await embed.events('load', 'gone')).toEqual([]);
      expect(await embed.events('level-change', 'gone')).toEqual([]);
    });
  });
});

test.describe('what pages do to an element, continued', () => {
  test.use({ allowedConsoleErrors: [/404/] });

  test('load() then a scheme change; a failed src stays failed; a display attribute put right; cancel holds; removal; setLevel(NaN)', async ({
    embed,
    page,
  }) => {
    await page.route('**/missing.off', (route) => route.fulfill({ status: 404, body: 'Not found' }));
    await embed.serve(
      'e2e/more.html',
      viewerPage(
        'More',
        `subdiv-viewer{width:300px;height:200px;display:inline-block}`,
        `<subdiv-viewer id="a" src="../meshes/cube.off"></subdiv-viewer>
<subdiv-viewer id="b" src="../meshes/cube.off"></subdiv-viewer>
<subdiv-viewer id="c" src="../meshes/cgal/bunny00.off" scheme="loop"></subdiv-viewer>`,
      ),
    );
    await page.goto('./e2e/more.html');
    await embed.waitForLevel('a', 0);
    await embed.waitForLevel('b', 0);
    type Viewer = HTMLElementTagNameMap['subdiv-viewer'];
    const on = (id: string) => page.locator(`#${id}`);
    const message = (id: string) => on(id).locator('.message');

    await test.step('load() followed at once by a scheme change: the loaded mesh, in the new scheme', async () => {
      await on('a').evaluate(async (e, text) => {
        const v = e as Viewer;
        const shown = v.load(text, 'tetra.off');
        v.scheme = 'sqrt3';
        v.levels = 1;
        await shown;
      }, TETRA);
      const reading = await embed.waitForLevel('a', 1);
      expect(reading.facts).toMatchObject({ ...expectedClosedCounts('sqrt3', MESHES.tetrahedron, 1) });
      expect((await embed.events('load', 'a')).map((e) => e.detail.modelName)).toEqual(['cube.off', 'tetra.off']);
    });

    await test.step('a src that failed stays failed: its message stays through other changes', async () => {
      await on('b').evaluate((e) => e.setAttribute('src', '../meshes/missing.off'));
      await expect(message('b')).toContainText('404');
      await on('b').evaluate((e) => {
        (e as Viewer).scheme = 'doo-sabin';
        (e as Viewer).levels = 1;
      });
      await page.waitForTimeout(500);
      await expect(message('b')).toContainText('404');
      expect((await embed.reading('b')).level).toBe(0);
      expect(await embed.events('error', 'b')).toHaveLength(1);
      await on('b').evaluate((e) => e.setAttribute('src', '../meshes/octahedron.off'));
      const reading = await embed.waitForLevel('b', 1);
      expect(reading.facts).toMatchObject({ ...expectedClosedCounts('doo-sabin', MESHES.octahedron, 1) });
      await expect(message('b')).toBeHidden();
    });

    await test.step('a bad display attribute put right clears its message', async () => {
      await on('b').evaluate((e) => e.setAttribute('render-mode', 'glossy'));
      await expect(message('b')).toContainText('Unknown render mode "glossy"');
      await on('b').evaluate((e) => e.setAttribute('render-mode', 'edges'));
      await expect(message('b')).toBeHidden();
    });

    await test.step('cancel() holds over a level asked just before it', async () => {
      await embed.waitForLevel('c', 0);
      const shown = await on('c').evaluate(async (e) => {
        const v = e as Viewer;
        // Level 2 is asked, and cancel() called, while the first step is under way: on its progress
        // event, not after a fixed wait (the fast core's step on the bunny can end within 30 ms).
        const stepping = (window.__stepUnderWay as (element: HTMLElement) => Promise<string>)(v);
        v.levels = 1;
        const label = await stepping;
        v.levels = 2;
        v.cancel();
        await new Promise((r) => setTimeout(r, 1500));
        return { level: v.level, label };
      });
      expect(shown).toEqual({ level: 0, label: expect.stringMatching(/level 1/) });
      expect((await embed.events('level-change', 'c')).map((e) => e.detail.level)).toEqual([0]);
    });

    await test.step('setLevel(NaN) is refused; a removed element does not come back', async () => {
      const refused = await on('a').evaluate((e) =>
        (e as Viewer).setLevel(Number.NaN).then(
          () => 'ok',
          (error: Error) => error.name,
        ),
      );
      expect(refused).toBe('TypeError');
      const loadsBefore = (await embed.events('load', 'a')).length;
      await on('a').evaluate(async (e) => {
        e.remove();
        await new Promise((r) => setTimeout(r, 50));
        await (e as Viewer).reload();
      });
      await page.waitForTimeout(1000);
      expect(await embed.events('load', 'a')).toHaveLength(loadsBefore);
    });
  });
});

test('a tagged file in <subdiv-viewer> and in the iframe route: creases drawn in their colours unless creases="0"', async ({
  embed,
  page,
}) => {
  await embed.serve(
    'e2e/creased.html',
    viewerPage(
      'Creased',
      'subdiv-viewer, iframe { width: 360px; height: 260px; border: 0; }',
      `<subdiv-viewer id="on" src="../meshes/cube-creased.obj" levels="1" controls="none"></subdiv-viewer>
<subdiv-viewer id="off" src="../meshes/cube-creased.obj" levels="1" controls="none" creases="0"></subdiv-viewer>
<iframe id="frame" title="Creased cube" src="../embed.html?src=meshes/cube-creased.obj&amp;levels=1&amp;controls=none"></iframe>`,
    ),
  );
  await page.goto('./e2e/creased.html');
  await embed.waitForLevel('on', 1);
  await embed.waitForLevel('off', 1);
  // The front loop is infinitely sharp: its colour, dark red, where the thick lines are drawn.
  const infinite = [0x6b, 0x0f, 0x1a];
  const darkRed = async (view: Locator) => {
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    const png = readPng(await view.screenshot({ omitBackground: true }));
    let count = 0;
    for (let y = 0; y < png.height; ++y)
      for (let x = 0; x < png.width; ++x) {
        const p = png.pixel(x, y);
        if (infinite.every((c, i) => Math.abs(p[i] - c) <= 12)) count++;
      }
    return count;
  };
  expect(await darkRed(page.locator('#on'))).toBeGreaterThan(200);
  expect(await darkRed(page.locator('#off'))).toBe(0);
  // Level 1 of the creased cube has 24 quads, as the app's.
  expect((await embed.reading('on')).facts?.faces).toBe(24);
  const frameCanvas = page.frameLocator('#frame').locator('canvas');
  await expect.poll(() => darkRed(frameCanvas), { timeout: 20_000 }).toBeGreaterThan(200);
  await embed.snapshot('embed-creased');
});
