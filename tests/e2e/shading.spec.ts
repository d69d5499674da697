/**
 * Shading that shows what schemes differ in (issue 11): the default light,
 * reflection lines (zebra), curvature colours with their colour bar, border
 * edges, back faces in their own colour, the control mesh drawn flat. Each
 * mode is checked by pixels of the canvas and looked at in a 1280×800
 * screenshot (test-results/screenshots/shading-*.png).
 */
import { expect, type Locator } from '@playwright/test';
import { test } from './fixtures';
import { readPng } from './helpers';
import { pixelsWhere } from './pixels';
import type { SubdivLabPage } from './subdivlab-page';

test.use({ viewport: { width: 1280, height: 800 } });

/** Grey, white or black (the background, the facts panel over the view and its text): no hue. */
const isGrey = (r: number, g: number, b: number) => Math.max(r, g, b) - Math.min(r, g, b) < 10;
/** A zebra stripe's dark band. */
const isStripeDark = (r: number, g: number, b: number) => r < 60 && g < 60 && b < 60;
/** The red half of the diverging map (positive curvature). */
const isRed = (r: number, g: number, b: number) => r > g + 40 && r > b + 40;
/** The surface's blue front. */
const isFrontBlue = (r: number, _g: number, b: number) => b > r + 30;
/** The back's dull orange. */
const isBackOrange = (r: number, g: number, b: number) => r > b + 30 && g > b;

/**
 * Opens `hash` (without `mode` or without `view`) and waits until the level
 * it names is shown, the core is idle and the app has written its whole
 * state back (mode and view: the link is applied, so a mode chosen now stays).
 */
async function openAt(app: SubdivLabPage, hash: string, level: number): Promise<void> {
  await app.open(`#${hash}`);
  await expect.poll(async () => (await app.state()).level, { timeout: 60_000 }).toBe(level);
  await app.idle();
  await expect
    .poll(async () => {
      const params = await app.hashParams();
      return params.has('mode') && params.has('view');
    })
    .toBe(true);
}

async function chooseMode(app: SubdivLabPage, mode: string): Promise<void> {
  await app.byTestId('controls.render-mode').selectOption(mode);
  await expect.poll(async () => (await app.state()).renderMode).toBe(mode);
}

/**
 * Distinct colours of the model's pixels (greys left out: background and
 * panel; the colour bar masked in grey), with their pixel counts.
 */
async function modelColours(view: Locator): Promise<Map<string, number>> {
  await view.page().evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  const mask = [view.page().getByTestId('view.colour-bar')];
  const png = readPng(await view.screenshot({ mask, maskColor: '#f3f4f6' }));
  const colours = new Map<string, number>();
  for (let y = 0; y < png.height; ++y)
    for (let x = 0; x < png.width; ++x) {
      const [r, g, b] = png.pixel(x, y);
      if (isGrey(r, g, b)) continue;
      const key = `${r},${g},${b}`;
      colours.set(key, (colours.get(key) ?? 0) + 1);
    }
  return colours;
}

test('zebra stripes replace the shading; on the cube they run on at level 3 of Catmull-Clark and break on linear', async ({
  app,
}) => {
  await openAt(app, 'src=meshes/cube.off&scheme=catmull-clark&levels=3', 3);
  const shadedDark = await pixelsWhere(app.canvas, isStripeDark);
  await app.snapshot('shading-cube-cc3-shaded');
  await chooseMode(app, 'zebra');
  await app.waitForHash('mode', 'zebra');
  const zebraDark = await pixelsWhere(app.canvas, isStripeDark);
  await app.snapshot('shading-cube-cc3-zebra');
  // The shaded cube has no near-black pixels (those counted are the facts panel's text); its stripes cover many thousands.
  expect(shadedDark).toBeLessThan(500);
  expect(zebraDark - shadedDark).toBeGreaterThan(20_000);

  await test.step('linear level 3: flat faces, each one band, with kinks at the edges', async () => {
    await openAt(app, 'src=meshes/cube.off&scheme=linear&levels=3&mode=zebra', 3);
    await app.snapshot('shading-cube-linear3-zebra');
  });
});

test('curvature colours: a colour bar with its range, red all over a sphere-like mesh, gone with the mode', async ({
  app,
}) => {
  await openAt(app, 'src=meshes/icosahedron.off&scheme=loop&levels=3', 3);
  const bar = app.byTestId('view.colour-bar');
  await expect(bar).toBeHidden();
  const shadedRed = await pixelsWhere(app.canvas, isRed);
  await chooseMode(app, 'mean-curvature');
  await expect(bar).toBeVisible();
  await expect(app.byTestId('view.colour-bar.title')).toHaveText('Mean curvature H (1/length), level 3');
  await expect(app.byTestId('view.colour-bar.middle')).toHaveText('0');
  const high = (await app.byTestId('view.colour-bar.high').textContent()) ?? '';
  expect(high).toMatch(/^\+\d/);
  await expect(app.byTestId('view.colour-bar.low')).toHaveText(high.replace('+', '−'));
  await expect(app.byTestId('view.colour-bar.note')).toContainText(
    'the larger magnitude of the 2nd and 98th percentiles',
  );
  // Positive everywhere, within a few percent of the range's end: the model is red, nearly uniformly.
  const colours = await modelColours(app.canvas);
  let model = 0;
  let red = 0;
  for (const [key, n] of colours) {
    const [r, g, b] = key.split(',').map(Number);
    model += n;
    if (isRed(r, g, b)) red += n;
  }
  expect(shadedRed).toBe(0);
  expect(model).toBeGreaterThan(50_000);
  expect(red / model).toBeGreaterThan(0.97);
  await app.snapshot('shading-icosahedron-loop3-mean');

  await chooseMode(app, 'gaussian-curvature');
  await expect(app.byTestId('view.colour-bar.title')).toHaveText('Gaussian curvature K (1/length²), level 3');
  await chooseMode(app, 'smooth');
  await expect(bar).toBeHidden();
  expect(await pixelsWhere(app.canvas, isRed)).toBe(0);
});

test('an open grid shows its back in the back colour and its border edges in green', async ({ app }) => {
  // The grid lies in z = 0 with its faces turned to +z: seen from +z, then from −z.
  await openAt(app, 'src=meshes/open-grid.off&scheme=catmull-clark&levels=1&view=1.5,1.5,7,1.5,1.5,0,0,1,0', 1);
  const frontBlue = await pixelsWhere(app.canvas, isFrontBlue);
  expect(frontBlue).toBeGreaterThan(30_000);
  expect(await pixelsWhere(app.canvas, isBackOrange)).toBe(0);
  await openAt(app, 'src=meshes/open-grid.off&scheme=catmull-clark&levels=1&view=1.5,1.5,-7,1.5,1.5,0,0,1,0', 1);
  const backOrange = await pixelsWhere(app.canvas, isBackOrange);
  expect(backOrange).toBeGreaterThan(30_000);
  expect(await pixelsWhere(app.canvas, isFrontBlue)).toBe(0);
  await app.snapshot('shading-open-grid-back');
  await chooseMode(app, 'edges');
  const green = (r: number, g: number, b: number) => g > r + 60 && g > b + 40;
  // 24 border edges 3 px wide around a square of about 400 px a side.
  expect(await pixelsWhere(app.canvas, green)).toBeGreaterThan(2_000);
  await app.snapshot('shading-open-grid-border');
});

test('the control mesh is drawn flat: each visible face of the cube is one colour', async ({ app }) => {
  await openAt(app, 'src=meshes/cube.off&scheme=catmull-clark&levels=0', 0);
  const colours = await modelColours(app.canvas);
  const total = [...colours.values()].reduce((s, n) => s + n, 0);
  const big = [...colours.entries()].filter(([, n]) => n > total * 0.05).map(([key]) => key.split(',').map(Number));
  // Three faces show (the default view looks at a corner), each in one colour, all three different.
  expect(big).toHaveLength(3);
  // Nearly every pixel of the model is one of the three within 2 levels: no gradient across a face, as the
  // smooth vertex normals (the corners' diagonals) would give. (SwiftShader brightens a small patch at
  // the top face's far corner by up to 8 levels; under 4% of the pixels.)
  let near = 0;
  for (const [key, n] of colours) {
    const c = key.split(',').map(Number);
    if (big.some((b) => b.every((x, i) => Math.abs(x - c[i]) <= 2))) near += n;
  }
  expect(near / total).toBeGreaterThan(0.95);
  await app.snapshot('shading-cube-level0');
});

test('screenshots of the modes on real models', async ({ app }) => {
  await openAt(app, 'src=meshes/cgal/elephant.off&scheme=loop&levels=1', 1);
  await app.snapshot('shading-elephant-shaded');
  await chooseMode(app, 'zebra');
  await app.snapshot('shading-elephant-zebra');
  await chooseMode(app, 'mean-curvature');
  await expect(app.byTestId('view.colour-bar')).toBeVisible();
  await app.snapshot('shading-elephant-mean');
  await openAt(app, 'src=meshes/cgal/bunny00.off&scheme=loop&levels=1', 1);
  await app.snapshot('shading-bunny-shaded');
  await chooseMode(app, 'zebra');
  await app.snapshot('shading-bunny-zebra');
  await chooseMode(app, 'gaussian-curvature');
  await expect(app.byTestId('view.colour-bar')).toBeVisible();
  await app.snapshot('shading-bunny-gaussian');
  for (const level of [0, 1, 2]) {
    await openAt(app, `src=meshes/cube.off&scheme=catmull-clark&levels=${level}`, level);
    await app.snapshot(`shading-cube-cc${level}`);
  }
  await openAt(app, 'src=meshes/cgal/holes.off&scheme=loop&levels=1&mode=edges', 1);
  await app.snapshot('shading-holes-edges');
});

test('the iframe route takes the new modes from its query: curvature with its colour bar, zebra', async ({ page }) => {
  await page.goto('./embed.html?src=meshes/icosahedron.off&scheme=loop&levels=2&mode=gaussian-curvature');
  const bar = page.getByTestId('view.colour-bar');
  await expect(bar).toBeVisible({ timeout: 30_000 });
  await expect(page.getByTestId('view.colour-bar.title')).toHaveText('Gaussian curvature K (1/length²), level 2');
  await page.screenshot({ path: 'test-results/screenshots/shading-embed-gaussian.png' });
  await page.goto('./embed.html?src=meshes/icosahedron.off&scheme=loop&levels=2&mode=zebra');
  const canvas = page.locator('canvas.subdiv-canvas');
  await expect.poll(() => pixelsWhere(canvas, isStripeDark), { timeout: 30_000 }).toBeGreaterThan(5_000);
  await expect(bar).toBeHidden();
});
