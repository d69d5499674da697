/**
 * Pictures for slides (issue 11): Fit frames the cage, the canonical and
 * the saved views, line widths that scale with a PNG's factor and with the
 * line-width setting, edges that fade as levels grow, and what Copy image
 * and Cancel say.
 */
import { readFile } from 'node:fs/promises';
import { expect, test } from './fixtures';
import { type PngInfo, quadGridOff, readPng } from './helpers';
import type { SubdivLabPage } from './subdivlab-page';

const BACKGROUND = [0xf3, 0xf4, 0xf6];
const EDGES = [0x1f, 0x2d, 0x3d];
const luma = (r: number, g: number, b: number) => 0.299 * r + 0.587 * g + 0.114 * b;

/** How much of the edge colour a pixel holds over the background: 0 background, 1 an edge's full colour. */
function darkness(png: PngInfo, x: number, y: number): number {
  const [r, g, b] = png.pixel(x, y);
  const bg = luma(BACKGROUND[0], BACKGROUND[1], BACKGROUND[2]);
  return (bg - luma(r, g, b)) / (bg - luma(EDGES[0], EDGES[1], EDGES[2]));
}

/**
 * Widths (in pixels) of the dark lines that row `y` crosses: each run of
 * pixels darker than a tenth, its width the sum of their darkness (so an
 * anti-aliased line two half-covered pixels wide counts as one pixel).
 */
function lineWidthsOnRow(png: PngInfo, y: number): number[] {
  const widths: number[] = [];
  let run = 0;
  for (let x = 0; x < png.width; ++x) {
    const d = darkness(png, x, y);
    if (d > 0.1) run += Math.min(d, 1);
    else if (run > 0) {
      widths.push(run);
      run = 0;
    }
  }
  return widths;
}

/** The median width of the lines crossing the rows around the middle of the picture (a cube's vertical edges from the front). */
function measuredLineWidth(png: PngInfo): number {
  const widths: number[] = [];
  for (const f of [0.45, 0.5, 0.55]) widths.push(...lineWidthsOnRow(png, Math.round(png.height * f)));
  widths.sort((a, b) => a - b);
  expect(widths.length, 'lines crossing the middle rows').toBeGreaterThanOrEqual(4);
  return widths[Math.floor(widths.length / 2)];
}

async function exportPng(app: SubdivLabPage, scale: number): Promise<PngInfo> {
  await app.byTestId('export-panel').locator('summary').click();
  await app.byTestId('export.scale').selectOption(String(scale));
  const download = await app.download('export.png');
  return readPng(await readFile(await download.path()));
}

/** Direction from the target to the camera, unit length. */
async function lookDirection(app: SubdivLabPage): Promise<number[]> {
  const { position, target } = (await app.state()).view;
  const d = position.map((p, i) => p - target[i]);
  const n = Math.hypot(...d);
  return d.map((x) => x / n);
}

for (const [width, height] of [
  [1280, 800],
  [1024, 700],
  [390, 844],
]) {
  test(`Fit frames the cage outside the surface at ${width}×${height}`, async ({ app }) => {
    await app.page.setViewportSize({ width, height });
    await app.open();
    await app.openSample('cube', 'cube.off');
    for (const scheme of ['doo-sabin', 'catmull-clark']) {
      await test.step(`${scheme} level 2 with its cage, from the side and from the default direction`, async () => {
        await app.chooseScheme(scheme);
        // A fresh load: level 0 whatever a scheme switch keeps.
        await app.openSample('tetrahedron', 'tetrahedron.off');
        await app.openSample('cube', 'cube.off');
        await app.subdivide();
        await app.subdivide();
        await app.byTestId('controls.overlay-control').check();
        for (const view of ['view.side', 'view.fit']) {
          await app.byTestId(view).click();
          const state = await app.state();
          const cage = await app.page.evaluate(() => window.__subdivlab?.projected(0) ?? []);
          expect(cage.length).toBe(8);
          const { width: w, height: h } = state.canvas;
          for (const p of cage) {
            expect(p.x).toBeGreaterThan(0);
            expect(p.x).toBeLessThan(w);
            expect(p.y).toBeGreaterThan(0);
            expect(p.y).toBeLessThan(h);
          }
          // The facts panel (open or folded) covers no corner.
          const panel = await app.byTestId('facts').boundingBox();
          const canvas = await app.canvas.boundingBox();
          if (panel && canvas) {
            const under = cage.filter(
              (p) =>
                p.x + canvas.x > panel.x &&
                p.x + canvas.x < panel.x + panel.width &&
                p.y + canvas.y > panel.y &&
                p.y + canvas.y < panel.y + panel.height,
            );
            expect(under, 'cage corners under the facts panel').toEqual([]);
          }
          // The surface (inside the cage) too.
          const level = await app.page.evaluate(() => window.__subdivlab?.projected(2) ?? []);
          expect(level.length).toBeGreaterThan(8);
          expect(level.every((p) => p.x > 0 && p.x < w && p.y > 0 && p.y < h)).toBe(true);
        }
      });
    }
    await app.byTestId('controls.render-mode').selectOption('edges');
    await app.byTestId('viewer').evaluate((e) => e.scrollIntoView({ block: 'start' }));
    await app.snapshot(`pictures-fit-cage-${width}x${height}`);
  });
}

test('canonical views look along their axes; V steps through them', async ({ app }) => {
  await app.open();
  await app.openSample('cube', 'cube.off');
  const s = 1 / Math.sqrt(3);
  const expected: Record<string, number[]> = { front: [0, 0, 1], top: [0, 1, 0], side: [1, 0, 0], iso: [s, s, s] };
  for (const [name, axis] of Object.entries(expected)) {
    await test.step(name, async () => {
      await app.byTestId(`view.${name}`).click();
      const d = await lookDirection(app);
      for (let i = 0; i < 3; i++) expect(Math.abs(d[i] - axis[i])).toBeLessThan(1e-6);
    });
  }
  await test.step('V: front, then top', async () => {
    await app.page.locator('body').click({ position: { x: 5, y: 690 } });
    await app.page.keyboard.press('v');
    expect(Math.abs((await lookDirection(app))[2] - 1)).toBeLessThan(1e-6);
    await app.page.keyboard.press('v');
    expect(Math.abs((await lookDirection(app))[1] - 1)).toBeLessThan(1e-6);
  });
});

test('saved views: two saved, each restored exactly, kept across a reload, deleted', async ({ app }) => {
  await app.open();
  await app.openSample('cube', 'cube.off');
  await app.byTestId('view.front').click();
  await app.byTestId('view.save').click();
  const front = (await app.state()).view;
  await app.byTestId('view.iso').click();
  await app.byTestId('view.save').click();
  const iso = (await app.state()).view;
  expect((await app.state()).savedViews).toEqual(['View 1', 'View 2']);
  expect(front.position).not.toEqual(iso.position);
  const restore = async (name: string) => {
    await app.byTestId('view.saved').selectOption(name);
    await app.byTestId('view.restore').click();
  };
  await restore('View 1');
  expect((await app.state()).view).toEqual(front);
  await restore('View 2');
  expect((await app.state()).view).toEqual(iso);
  await test.step('after a reload', async () => {
    await app.page.reload();
    await app.open();
    await app.openSample('tetrahedron', 'tetrahedron.off');
    expect((await app.state()).savedViews).toEqual(['View 1', 'View 2']);
    await restore('View 1');
    expect((await app.state()).view).toEqual(front);
    await restore('View 2');
    expect((await app.state()).view).toEqual(iso);
  });
  await test.step('delete', async () => {
    await app.byTestId('view.saved').selectOption('View 1');
    await app.byTestId('view.delete').click();
    expect((await app.state()).savedViews).toEqual(['View 2']);
    const stored = await app.page.evaluate(() => localStorage.getItem('subdivlab.view'));
    expect(JSON.parse(stored ?? 'null')).toEqual(iso);
  });
});

test('PNG ×4 draws lines four times as wide as ×1; the line-width setting widens them', async ({ app }) => {
  test.setTimeout(90_000);
  await app.page.setViewportSize({ width: 640, height: 480 });
  await app.open();
  await app.openSample('cube', 'cube.off');
  await app.byTestId('controls.render-mode').selectOption('wireframe');
  await app.byTestId('view.front').click();
  const one = measuredLineWidth(await exportPng(app, 1));
  const four = measuredLineWidth(await exportPng(app, 4));
  expect(one).toBeGreaterThan(0.6);
  expect(one).toBeLessThan(1.5);
  expect(four / one).toBeGreaterThan(3.3);
  expect(four / one).toBeLessThan(4.7);
  await test.step('line width 3 px: ×1 lines about 3 px wide, in the link', async () => {
    await app.byTestId('controls.line-width').selectOption('3');
    expect((await app.state()).lineWidth).toBe(3);
    await app.waitForHash('lines', '3');
    const three = measuredLineWidth(await exportPng(app, 1));
    expect(three).toBeGreaterThan(2.5);
    expect(three).toBeLessThan(3.5);
  });
  test.info().annotations.push({ type: 'widths', description: `×1 ${one.toFixed(2)}, ×4 ${four.toFixed(2)}` });
});

test('edges fade as levels grow: level 3 lighter than level 1', async ({ app }) => {
  await app.open();
  await app.openSample('cube', 'cube.off');
  await app.byTestId('controls.render-mode').selectOption('wireframe');
  /** Mean darkness of the pixels the edges touch, over the view's screenshot. */
  const meanEdgeDarkness = async () => {
    const png = readPng(await app.canvasPixels());
    let sum = 0;
    let count = 0;
    for (let y = 0; y < png.height; y += 1)
      for (let x = 0; x < png.width; x += 1) {
        const d = darkness(png, x, y);
        if (d > 0.1) {
          sum += d;
          count++;
        }
      }
    return sum / count;
  };
  await app.subdivide();
  const level1 = { opacity: (await app.state()).edgeOpacity, darkness: await meanEdgeDarkness() };
  await app.snapshot('pictures-edges-level1-1024x700');
  await app.subdivide();
  await app.subdivide();
  const level3 = { opacity: (await app.state()).edgeOpacity, darkness: await meanEdgeDarkness() };
  await app.snapshot('pictures-edges-level3-1024x700');
  expect(level1.opacity).toBe(1);
  expect(level3.opacity).toBeLessThan(0.95);
  expect(level3.darkness).toBeLessThan(level1.darkness * 0.95);
  test.info().annotations.push({ type: 'fading', description: JSON.stringify({ level1, level3 }) });
});

test('edges mode at levels 1 to 3 and a ×4 PNG, for people to look at', async ({ app }) => {
  for (const [width, height] of [
    [1280, 800],
    [390, 844],
  ]) {
    await app.page.setViewportSize({ width, height });
    // A new page at this size (the app folds its facts panel on narrow screens when it starts).
    await app.page.goto('about:blank');
    await app.open();
    await app.openSample('cube', 'cube.off');
    await app.byTestId('controls.render-mode').selectOption('edges');
    for (const level of [1, 2, 3]) {
      await app.subdivide();
      expect((await app.state()).level).toBe(level);
      await app.byTestId('viewer').evaluate((e) => e.scrollIntoView({ block: 'start' }));
      await app.snapshot(`pictures-edges-L${level}-${width}x${height}`);
    }
  }
  await app.page.setViewportSize({ width: 640, height: 480 });
  await app.byTestId('controls.overlay-control').check();
  await app.byTestId('view.fit').click();
  await app.byTestId('export-panel').locator('summary').click();
  await app.byTestId('export.scale').selectOption('4');
  const download = await app.download('export.png');
  await download.saveAs('test-results/screenshots/pictures-png-x4.png');
  const png = readPng(await readFile(await download.path()));
  expect([png.width, png.height]).toEqual([
    4 * (await app.state()).canvas.width,
    4 * (await app.state()).canvas.height,
  ]);
});

test('Copy image says what it copied, or why it could not', async ({ app }) => {
  await app.page.context().grantPermissions(['clipboard-read', 'clipboard-write']);
  await app.open();
  await app.openSample('cube', 'cube.off');
  const { width, height } = (await app.state()).canvas;
  await app.byTestId('export-panel').locator('summary').click();
  await app.byTestId('export.copy').click();
  await expect(app.byTestId('notice.message')).toHaveText(`Copied a ${width}×${height} PNG to the clipboard.`);
  const type = await app.page.evaluate(async () => (await navigator.clipboard.read())[0]?.types[0]);
  expect(type).toBe('image/png');
  await test.step('the browser refuses: the message says so', async () => {
    await app.page.evaluate(() => {
      navigator.clipboard.write = () => Promise.reject(new DOMException('Write permission denied.', 'NotAllowedError'));
    });
    await app.page.keyboard.press('Control+c');
    await expect(app.errorBanner).toContainText('did not allow this page to write to the clipboard');
  });
  await test.step('no ClipboardItem: the message says to export instead', async () => {
    await app.page.evaluate(() => {
      (window as { ClipboardItem?: unknown }).ClipboardItem = undefined;
    });
    await app.page.keyboard.press('Control+c');
    await expect(app.errorBanner).toContainText('This browser cannot put images on the clipboard');
  });
});

test('Cancel of a long step says which level was not computed and which is shown', async ({ app }) => {
  test.setTimeout(120_000);
  await app.open();
  // 22 500 quads: levels 1 and 2 are quick, level 3 (1 440 000 quads) takes over a second.
  await app.load('grid-150.off', quadGridOff(150));
  await app.subdivide();
  await app.subdivide();
  const cancelled = await app.cancelWhenProgressShows();
  await app.byTestId('controls.subdivide').click();
  await cancelled();
  await expect(app.byTestId('notice.message')).toHaveText('Cancelled: level 3 was not computed; level 2 is shown.');
  expect(await app.state()).toMatchObject({ busy: false, level: 2, levelCount: 3 });
  await test.step('the next load clears the message', async () => {
    await app.openSample('cube', 'cube.off');
    await expect(app.byTestId('notice')).toBeHidden();
  });
});

test('a large level in wireframe: its fat lines go to the GPU over several frames and are drawn; a denser one as thin lines', async ({
  app,
}) => {
  test.setTimeout(120_000);
  await app.open();
  // 90 000 quads: level 1 has 720 000 edges, 17 MB of fat-line ends (over the 8 MB a frame uploads).
  await app.load('grid-300.off', quadGridOff(300));
  await app.subdivide();
  await app.byTestId('controls.render-mode').selectOption('wireframe');
  const png = readPng(await app.canvasPixels());
  let dark = 0;
  for (let y = 0; y < png.height; y += 2) for (let x = 0; x < png.width; x += 2) if (darkness(png, x, y) > 0.1) dark++;
  // The grid fills much of the view with edges (faded, but there).
  expect(dark).toBeGreaterThan((png.width * png.height) / 4 / 10);
  expect((await app.state()).edgeOpacity).toBeLessThan(0.5);
  expect((await app.state()).thinEdges).toBe(false);
  await test.step('level 2, past a million edges: one-pixel lines over the level’s own index, as dark', async () => {
    await app.subdivide();
    // 1,200 × 1,200 quads: 2 · 1,200 · 1,201 edges.
    expect(await app.state()).toMatchObject({ level: 2, edgeSegments: 2_882_400 });
    // Said by the draw, which follows the level's upload by some frames.
    await expect.poll(async () => (await app.state()).thinEdges).toBe(true);
    const dense = readPng(await app.canvasPixels());
    let shaded = 0;
    for (let y = 0; y < dense.height; y += 2) {
      for (let x = 0; x < dense.width; x += 2) if (darkness(dense, x, y) > 0.1) shaded++;
    }
    expect(shaded).toBeGreaterThan((dense.width * dense.height) / 4 / 10);
    await app.byTestId('controls.render-mode').selectOption('smooth');
    await expect.poll(async () => (await app.state()).thinEdges).toBe(false);
  });
});

test('the iframe route takes lines=3 (the element’s line-width): lines three times as wide', async ({ app }) => {
  const widthAt = async (query: string) => {
    await app.page.goto(`./embed.html?src=meshes/cube.off&mode=wireframe&controls=none&view=0,0,6,0,0,0,0,1,0${query}`);
    const canvas = app.page.locator('canvas.subdiv-canvas');
    // Drawn once the cube is in: its vertical edges cross the middle rows.
    await expect
      .poll(
        async () => {
          const png = readPng(await canvas.screenshot());
          return lineWidthsOnRow(png, Math.round(png.height / 2)).length;
        },
        { timeout: 20_000 },
      )
      .toBeGreaterThanOrEqual(4);
    return measuredLineWidth(readPng(await canvas.screenshot()));
  };
  const one = await widthAt('');
  const three = await widthAt('&lines=3');
  expect(one).toBeGreaterThan(0.6);
  expect(one).toBeLessThan(1.5);
  expect(three / one).toBeGreaterThan(2.5);
  expect(three / one).toBeLessThan(3.5);
  expect(
    await app.page.locator('subdiv-viewer').evaluate((e) => (e as unknown as { lineWidth: number }).lineWidth),
  ).toBe(3);
});
