/**
 * The viewer on slides (issue 29): reveal.js scales every slide with a CSS
 * transform, other tools and pages use CSS `zoom` or turn a figure. Clicks
 * on the cube's control vertices must pick the same vertices as on a plain
 * page, and a drag must turn the model as far.
 *
 * Where a vertex is on screen is worked out here, not by the viewer: its
 * corner (±1 in each coordinate, as cube.off lists them) projected with the
 * element's camera (getView, a 35° field of view) into the canvas's own
 * pixels, then through the slide's known transform (reveal.js's scale, the
 * zoom, the turn) to the page. The page's numbers come from the browser's
 * layout (bounding rectangles of the canvas), never from the viewer's own
 * mapping.
 */
import { readFileSync } from 'node:fs';
import type { Frame, Page } from '@playwright/test';
import { viewerPage } from './embed-page';
import { expect, test } from './fixtures';

type Viewer = HTMLElementTagNameMap['subdiv-viewer'];
type Vec = [number, number, number];

/** The sample cube's 8 corners as its file lists them (level 0). */
const CORNERS: Vec[] = readFileSync('public/meshes/cube.off', 'utf8')
  .split('\n')
  .filter((line) => line.trim() !== '' && !line.startsWith('#'))
  .slice(2, 10)
  .map((line) => line.trim().split(/\s+/).map(Number) as Vec);

/** Looking at the corner (1, 1, 1) from a little to the right: three faces, seven corners in view. */
const VIEW: { position: Vec; target: Vec; up: Vec } = { position: [4.2, 3.4, 5.6], target: [0, 0, 0], up: [0, 1, 0] };
/** The viewer's camera: a vertical field of view of 35° (SceneView). */
const FOV = 35;

/** The corners on the camera's side of at least one of their three faces (the others are behind the cube). */
const VISIBLE = CORNERS.map((c, v) => ({ c, v }))
  .filter(({ c }) => c.some((x, i) => Math.sign(x) * (VIEW.position[i] - x) > 0))
  .map(({ v }) => v);

const sub = (a: Vec, b: Vec): Vec => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a: Vec, b: Vec) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a: Vec, b: Vec): Vec => [
  a[1] * b[2] - a[2] * b[1],
  a[2] * b[0] - a[0] * b[2],
  a[0] * b[1] - a[1] * b[0],
];
const unit = (a: Vec): Vec => {
  const n = Math.hypot(...a);
  return [a[0] / n, a[1] / n, a[2] / n];
};

/** Where `p` is drawn in a view of `width` × `height` CSS pixels (its own, from its top left): a pinhole camera. */
function project(p: Vec, width: number, height: number): [number, number] {
  const back = unit(sub(VIEW.position, VIEW.target));
  const right = unit(cross(VIEW.up, back));
  const up = cross(back, right);
  const d = sub(p, VIEW.position);
  const t = Math.tan((FOV / 2) * (Math.PI / 180));
  const depth = -dot(d, back);
  const x = dot(d, right) / depth / (t * (width / height));
  const y = dot(d, up) / depth / t;
  return [((x + 1) / 2) * width, ((1 - y) / 2) * height];
}

/** The element as a slide shows it: the basis tool on the cube, the cage drawn, no vertex picked yet. */
const ELEMENT = `<subdiv-viewer id="v" src="../meshes/cube.off" levels="1" tool="basis" control-mesh controls="none"
  view="${[...VIEW.position, ...VIEW.target, ...VIEW.up].join(',')}"></subdiv-viewer>`;

/** The same viewer through the iframe route (embed.html), 800 × 480. */
const IFRAME = `<iframe title="Where one control vertex reaches" width="800" height="480" style="border:0;display:block;margin:0 auto"
  src="../embed.html?src=meshes/cube.off&amp;levels=1&amp;tool=basis&amp;control-mesh=1&amp;controls=none&amp;view=${[
    ...VIEW.position,
    ...VIEW.target,
    ...VIEW.up,
  ].join(',')}"></iframe>`;

/**
 * A reveal.js deck of 1280 × 720 (its own CSS and script, from node_modules) with the element on its
 * first slide (in a box of `zoom`), or the iframe route.
 */
function deck(options: { zoom?: number; iframe?: boolean } = {}): string {
  const style = options.zoom ? ` style="zoom:${options.zoom}"` : '';
  // Zoomed, it is as large on the slide as 800 × 480 unzoomed.
  const size = options.zoom ? '640px;height:384px' : '800px;height:480px';
  return `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Subdivision, a deck</title>
<link rel="stylesheet" href="../reveal/reveal.css"><link rel="stylesheet" href="../reveal/theme/white.css">
<script type="module" src="../embed/subdiv-viewer.js"></script>
<style>.reveal subdiv-viewer{display:block;width:${size};margin:0 auto}</style></head><body>
<div class="reveal"><div class="slides"><section>
<h3>Where does one control vertex reach?</h3><div${style}>${options.iframe ? IFRAME : ELEMENT}</div>
</section><section><h3>The next slide</h3></section></div></div>
<script src="../reveal/reveal.js"></script>
<script>Reveal.initialize({ width: 1280, height: 720, margin: 0.1, transition: 'none', hash: false, controls: false, progress: false });</script>
</body></html>`;
}

/** reveal.js's files, served from node_modules under ../reveal/ (they are not part of the build). */
async function serveReveal(page: Page): Promise<void> {
  await page.route('**/reveal/**', (route) => {
    const file = new URL(route.request().url()).pathname.split('/reveal/')[1];
    return route.fulfill({ path: `node_modules/reveal.js/dist/${file}` });
  });
}

/**
 * The canvas's layout size (its own CSS pixels), its bounding rectangle in its document (the page's,
 * or an iframe's: `frame`) and its bitmap's size.
 */
async function canvasLayout(frame: Frame): Promise<Layout> {
  return frame.evaluate(() => {
    const canvas = document.querySelector('subdiv-viewer')?.shadowRoot?.querySelector('canvas');
    if (!canvas) throw new Error('no canvas');
    const r = canvas.getBoundingClientRect();
    return {
      width: canvas.clientWidth,
      height: canvas.clientHeight,
      left: r.left,
      top: r.top,
      rect: [r.width, r.height],
      bitmap: [canvas.width, canvas.height],
    };
  });
}

interface Layout {
  width: number;
  height: number;
  left: number;
  top: number;
  rect: number[];
  bitmap: number[];
}

/** Waits until the view has followed its canvas's size (a resize observer, a frame later) and drawn. */
async function waitForSize(frame: Frame): Promise<Layout> {
  await expect
    .poll(async () => {
      const c = await canvasLayout(frame);
      return c.bitmap[0] === c.width && c.bitmap[1] === c.height;
    })
    .toBe(true);
  await frame.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  return canvasLayout(frame);
}

/** Waits until the viewer in `frame` shows level 1 from {@link VIEW}, idle, at its size. */
async function waitForView(frame: Frame): Promise<void> {
  await expect
    .poll(() =>
      frame.evaluate(() => {
        const e = document.querySelector('subdiv-viewer') as Viewer;
        return e.level === 1 && !e.state?.busy && e.getView()?.position.join(',');
      }),
    )
    .toBe(VIEW.position.join(','));
  await waitForSize(frame);
}

/**
 * Clicks each visible corner where `toPage` puts its projection (canvas pixels → page pixels, with
 * the canvas's layout `c` in `frame`) and returns the vertex the element picked after each click
 * (its `vertex` attribute; null: none yet). The caption grows with the first pick (its colour bar)
 * and the canvas shrinks: each corner is projected into the canvas as it is when clicked.
 */
async function clickCorners(
  page: Page,
  toPage: (x: number, y: number, c: Layout) => [number, number],
  frame: Frame = page.mainFrame(),
): Promise<(number | null)[]> {
  const picked: (number | null)[] = [];
  for (const v of VISIBLE) {
    const c = await waitForSize(frame);
    const [x, y] = project(CORNERS[v], c.width, c.height);
    await page.mouse.click(...toPage(x, y, c));
    const attribute = await frame.locator('subdiv-viewer').getAttribute('vertex');
    picked.push(attribute === null ? null : Number(attribute));
    // The basis function of that vertex is shown (its caption) before the next click.
    if (attribute === String(v))
      await expect
        .poll(() => frame.locator('subdiv-viewer').locator('[part="tool"]').textContent())
        .toContain(`Basis function of control vertex ${v}: reaches `);
  }
  return picked;
}

const round = (x: number) => Math.round(x * 1000) / 1000 + 0;

/**
 * How far the element's camera turned from {@link VIEW} (radians, to 0.001) and how far off the plane
 * of a turn about VIEW's screen-up axis (the eye's component along that axis, to 0.001).
 */
async function turnedBy(page: Page): Promise<{ angle: number; tilt: number }> {
  const view = await page.evaluate(() => (document.getElementById('v') as Viewer).getView());
  if (!view) return { angle: Number.NaN, tilt: Number.NaN };
  const before = unit(sub(VIEW.position, VIEW.target));
  const screenUp = cross(before, unit(cross(VIEW.up, before)));
  const after = unit(sub(view.position as Vec, view.target as Vec));
  return { angle: round(Math.acos(Math.min(1, dot(before, after)))), tilt: round(dot(after, screenUp)) };
}

test.beforeAll(() => {
  // Seven corners of the cube face the camera; the eighth, (−1, −1, −1), is behind it.
  expect(VISIBLE).toEqual([1, 2, 3, 4, 5, 6, 7]);
});

test('on a plain page the seven visible control vertices are picked where this test projects them', async ({
  embed,
  page,
}) => {
  await embed.serve(
    'e2e/slides-plain.html',
    viewerPage('Plain', 'body{margin:0 16px} #v{width:800px;height:480px}', ELEMENT),
  );
  await page.goto('./e2e/slides-plain.html');
  await waitForView(page.mainFrame());
  const c = await canvasLayout(page.mainFrame());
  // clientHeight is a whole number; the box may be a fraction taller.
  expect(c.rect[0]).toBeCloseTo(c.width, 0);
  expect(c.rect[1]).toBeCloseTo(c.height, 0);
  expect(await clickCorners(page, (x, y, c) => [c.left + x, c.top + y])).toEqual(VISIBLE);
});

test('a reveal.js deck scales its slide by about 0.72 (a CSS transform): the same seven vertices are picked', async ({
  embed,
  page,
}) => {
  await serveReveal(page);
  await embed.serve('e2e/slides-deck.html', deck());
  await page.goto('./e2e/slides-deck.html');
  await waitForView(page.mainFrame());
  // reveal.js fits 1280 × 720 into 90 % of 1024 × 700 (margin 0.1): min(921.6 / 1280, 630 / 720), to 0.01.
  const scale = await page.evaluate(() => (window as unknown as { Reveal: { getScale(): number } }).Reveal.getScale());
  expect(scale).toBe(0.72);
  const c = await canvasLayout(page.mainFrame());
  expect(c.rect[0]).toBeCloseTo(scale * c.width, 3);
  // clientHeight is a whole number; the box may be a fraction taller.
  expect(c.rect[1] / scale).toBeCloseTo(c.height, 0);
  const picked = await clickCorners(page, (x, y, c) => [c.left + scale * x, c.top + scale * y]);
  await page.screenshot({ path: '/tmp/shots/slides/deck-scaled-picked.png' });
  expect(picked).toEqual(VISIBLE);
  await expect.poll(() => embed.caption('v')).toContain('Basis function of control vertex 7');
  // reveal.js centres a slide's text; the caption keeps its own alignment, with its colour bar.
  const align = await page
    .locator('#v')
    .locator('.tool-line')
    .first()
    .evaluate((e) => getComputedStyle(e).textAlign);
  expect(align).toBe('start');
});

test('CSS zoom 1.25 on the slide, inside the scaled deck: the same seven vertices are picked', async ({
  embed,
  page,
}) => {
  await serveReveal(page);
  await embed.serve('e2e/slides-zoom.html', deck({ zoom: 1.25 }));
  await page.goto('./e2e/slides-zoom.html');
  await waitForView(page.mainFrame());
  const scale = await page.evaluate(() => (window as unknown as { Reveal: { getScale(): number } }).Reveal.getScale());
  const total = scale * 1.25;
  const c = await canvasLayout(page.mainFrame());
  expect(c.rect[0]).toBeCloseTo(total * c.width, 3);
  const picked = await clickCorners(page, (x, y, c) => [c.left + total * x, c.top + total * y]);
  await page.screenshot({ path: '/tmp/shots/slides/deck-zoomed-picked.png' });
  expect(picked).toEqual(VISIBLE);
});

test('the iframe route on the scaled slide: the same seven vertices are picked', async ({ embed, page }) => {
  await serveReveal(page);
  await embed.serve('e2e/slides-iframe.html', deck({ iframe: true }));
  await page.goto('./e2e/slides-iframe.html');
  await expect.poll(() => page.frame({ url: /embed\.html/ }) !== null).toBe(true);
  const frame = page.frame({ url: /embed\.html/ });
  if (!frame) throw new Error('no frame');
  await waitForView(frame);
  const scale = await page.evaluate(() => (window as unknown as { Reveal: { getScale(): number } }).Reveal.getScale());
  expect(scale).toBe(0.72);
  const box = await page.evaluate(() => {
    const r = document.querySelector('iframe')?.getBoundingClientRect();
    return r && { left: r.left, top: r.top, width: r.width };
  });
  if (!box) throw new Error('no iframe');
  expect(box.width).toBeCloseTo(scale * 800, 3);
  // The frame's own pixels are the slide's: its page point is its corner + scale × the point in it.
  const picked = await clickCorners(
    page,
    (x, y, c) => [box.left + scale * (c.left + x), box.top + scale * (c.top + y)],
    frame,
  );
  await page.screenshot({ path: '/tmp/shots/slides/deck-iframe-picked.png' });
  expect(picked).toEqual(VISIBLE);
});

test('a figure turned by 8° and scaled by 0.75 (transform-origin 0 0): the same seven vertices are picked', async ({
  embed,
  page,
}) => {
  const turn = (8 * Math.PI) / 180;
  const s = 0.75;
  await embed.serve(
    'e2e/slides-turned.html',
    viewerPage(
      'Turned',
      'body{margin:0} #figure{position:absolute;left:140px;top:40px;transform-origin:0 0} #v{width:800px;height:480px}',
      `<div id="figure">${ELEMENT}</div>`,
    ),
  );
  await page.goto('./e2e/slides-turned.html');
  await waitForView(page.mainFrame());
  // The canvas's place in the figure, measured before the figure turns.
  const flat = await canvasLayout(page.mainFrame());
  await page.evaluate(
    ([t, k]) => {
      (document.getElementById('figure') as HTMLElement).style.transform = `rotate(${t}rad) scale(${k})`;
    },
    [turn, s],
  );
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  // Page point = the figure's corner (140, 40) + R(turn) · s · (the point in the figure).
  const toPage = (x: number, y: number): [number, number] => {
    const fx = flat.left - 140 + x;
    const fy = flat.top - 40 + y;
    return [
      140 + s * (Math.cos(turn) * fx - Math.sin(turn) * fy),
      40 + s * (Math.sin(turn) * fx + Math.cos(turn) * fy),
    ];
  };
  const picked = await clickCorners(page, toPage);
  await page.screenshot({ path: '/tmp/shots/slides/turned-picked.png' });
  expect(picked).toEqual(VISIBLE);

  await test.step('a drag along the canvas’s own x axis turns the model about its screen-up axis, by 3 · 2d / w', async () => {
    const c = await waitForSize(page.mainFrame());
    const from = toPage(c.width / 2 - 50, c.height / 2);
    const to = toPage(c.width / 2 + 50, c.height / 2);
    await page.mouse.move(...from);
    await page.mouse.down();
    await page.mouse.move(...to, { steps: 5 });
    await page.mouse.up();
    await expect.poll(() => turnedBy(page)).toEqual({ angle: round((3 * 2 * 100) / c.width), tilt: 0 });
  });
});

test('a drag on a slide the deck rescaled after the viewer started turns the model as far as on a plain page (3 · 2d / w radians)', async ({
  embed,
  page,
}) => {
  await serveReveal(page);
  await embed.serve('e2e/slides-drag.html', deck());
  await page.goto('./e2e/slides-drag.html');
  await waitForView(page.mainFrame());
  // A presenter's larger window: reveal.js scales the slide up; the viewer's own size does not change.
  await page.setViewportSize({ width: 1280, height: 800 });
  const reveal = () => page.evaluate(() => (window as unknown as { Reveal: { getScale(): number } }).Reveal.getScale());
  // min(0.9 · 1280 / 1280, 0.9 · 800 / 720), up from 0.72.
  await expect.poll(reveal).toBe(0.9);
  const scale = await reveal();
  const c = await canvasLayout(page.mainFrame());
  expect(c.rect[0]).toBeCloseTo(scale * c.width, 3);
  // 100 of the canvas's own pixels to the right along its middle row.
  const [x0, y0] = [c.left + scale * (c.width / 2 - 50), c.top + scale * (c.height / 2)];
  await page.mouse.move(x0, y0);
  await page.mouse.down();
  await page.mouse.move(x0 + scale * 100, y0, { steps: 5 });
  await page.mouse.up();
  // TrackballControls (rotateSpeed 3): a drag of d pixels across a view w wide turns it by 3 · 2d / w radians.
  await expect.poll(() => turnedBy(page)).toEqual({ angle: round((3 * 2 * 100) / c.width), tilt: 0 });
});

test('the app scaled to 0.8 (a transform on its body): the test API puts each vertex where the browser draws it; a click there picks it', async ({
  app,
}) => {
  await app.open();
  await app.openSample('torus', 'torus.off');
  await app.subdivide();
  await app.byTestId('basis.toggle').click();
  await expect(app.byTestId('controls.overlay-control')).toBeChecked();
  await app.page.evaluate(() => {
    document.body.style.transformOrigin = '0 0';
    document.body.style.transform = 'scale(0.8)';
  });
  await app.page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  const seen = await app.page.evaluate(() => {
    const api = window.__subdivlab;
    const canvas = document.querySelector<HTMLCanvasElement>('[data-testid="viewer"] canvas.subdiv-canvas');
    if (!api || !canvas) throw new Error('no app');
    const r = canvas.getBoundingClientRect();
    const projected = api.projected(0);
    return {
      rect: { left: r.left, top: r.top, width: r.width, layoutWidth: canvas.clientWidth },
      projected,
      onScreen: projected.map((_, v) => api.vertexOnScreen(v)),
    };
  });
  expect(seen.rect.width).toBeCloseTo(0.8 * seen.rect.layoutWidth, 3);
  // Each control vertex: the canvas's corner in the page + 0.8 × its place in the canvas (the camera's projection).
  expect(seen.projected.length).toBeGreaterThan(0);
  seen.projected.forEach((p, v) => {
    const at = seen.onScreen[v];
    expect(at?.x).toBeCloseTo(seen.rect.left + 0.8 * p.x, 3);
    expect(at?.y).toBeCloseTo(seen.rect.top + 0.8 * p.y, 3);
  });
  const at = seen.onScreen[0];
  if (!at) throw new Error('control vertex 0 is not in view');
  await app.page.mouse.click(at.x, at.y);
  await expect(app.byTestId('basis.reach')).toHaveText(/^Control vertex 0 reaches 25 of the 192 vertices of level 1 /);
});

test('Fit in the app turned by 4° and scaled by 0.8 keeps the model clear of the facts panel as on the plain page', async ({
  app,
}) => {
  await app.open();
  await app.openSample('torus', 'torus.off');
  // Fit shifts the picture right of the facts panel (data-covers-view) by the panel's width in the canvas's pixels.
  const plain = (await app.state()).viewOffset;
  expect(plain[0]).toBeGreaterThan(0.1);
  await app.page.evaluate(() => {
    document.body.style.transformOrigin = '0 0';
    document.body.style.transform = 'rotate(4deg) scale(0.8)';
  });
  await app.byTestId('view.fit').click();
  const turned = (await app.state()).viewOffset;
  expect(turned[0]).toBeCloseTo(plain[0], 3);
  expect(turned[1]).toBeCloseTo(plain[1], 3);
});
