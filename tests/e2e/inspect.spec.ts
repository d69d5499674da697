/**
 * Inspect: the stella octangula (two tetrahedra through each other) has 12
 * pairs of crossing faces, drawn in red and listed, a pair framed by a
 * click; CGAL's mannequin crosses itself in 1,643 pairs, which Inspect
 * frames and shows alone at first; Catmull-Clark's level 2 of the cube gets
 * the figures `subdiv inspect` prints (sphere, hull, width, and its
 * shrinking from level 0), each computed and drawn on one click, kept per
 * level.
 */
import { spawnSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { figure } from '../../web/ui/inspect-panel';
import { expect, test } from './fixtures';
import { readPng } from './helpers';
import { isInspectRed, pixelsWhere } from './pixels';

const STELLA = readFileSync('tests/fixtures/stella-octangula.off', 'utf8');
const CUBE = readFileSync('tests/fixtures/cube.off', 'utf8');

test('the stella octangula: 12 crossing pairs of faces, red on the view, listed, one framed', async ({ app }) => {
  await app.open();
  await app.load('stella-octangula.off', STELLA);
  expect(await pixelsWhere(app.canvas, isInspectRed)).toBe(0);
  await app.byTestId('inspect.run').click();
  await expect(app.byTestId('inspect.self-intersections')).toHaveText(/^12 pairs of faces \(8 faces\) · [\d.,]+ ms$/);
  expect(await pixelsWhere(app.canvas, isInspectRed)).toBeGreaterThan(2000);
  // The self-intersections alone: the sphere, hull and planes would cover the red faces.
  for (const id of ['sphere', 'hull', 'width']) {
    await expect(app.byTestId(`inspect.choice.${id}`)).not.toBeChecked();
    await expect(app.byTestId(`inspect.${id}`)).toHaveCount(0);
  }
  // The first pairs, by face number: each face of one tetrahedron crosses three of the other.
  const pairs = app.byTestId('inspect.pair');
  await expect(pairs).toHaveCount(12);
  await expect(pairs.first()).toHaveText('0 × 5');
  const before = (await app.state()).view;
  await pairs.first().click();
  await expect(pairs.first()).toHaveAttribute('aria-pressed', 'true');
  expect((await app.state()).view.position).not.toEqual(before.position);
  await app.snapshot('inspect-stella-octangula');
});

test('Catmull-Clark level 2 of the cube: the figures of subdiv inspect, drawn, kept per level', async ({ app }) => {
  await app.open();
  await app.load('cube.off', CUBE);
  await app.subdivide();
  await app.subdivide();
  const cli = JSON.parse(
    spawnSync(process.execPath, ['bin/subdiv.mjs', 'inspect', 'tests/fixtures/cube.off', '--levels', '2'], {
      encoding: 'utf8',
    }).stdout,
  );
  await app.byTestId('inspect.run').click();
  await expect(app.byTestId('inspect.self-intersections')).toHaveText(/^none · /);
  await expect(app.byTestId('inspect.volume')).toHaveText(
    `${figure(cli.measures.volume)} (×${figure(cli.change.volume)} of level 0)`,
  );
  await expect(app.byTestId('inspect.area')).toHaveText(
    `${figure(cli.measures.area)} (×${figure(cli.change.area)} of level 0)`,
  );
  // Nothing crosses: nothing is drawn and the level stays framed.
  const plain = await app.canvasPixels();

  await test.step('each figure on one click: computed, drawn, framed with the level', async () => {
    let last = plain;
    const rows: Record<string, RegExp> = {
      sphere: new RegExp(`^radius ${figure(cli.sphere.radius)}, centre \\(0, 0, 0\\) · [\\d.,]+ ms$`),
      hull: new RegExp(
        `^98 vertices, 288 edges, 192 triangles; area ${figure(cli.hull.area)}, volume ${figure(cli.hull.volume)} · `,
      ),
      width: new RegExp(`^${figure(cli.width.width)}, between the planes`),
    };
    for (const id of ['sphere', 'hull', 'width']) {
      const before = (await app.state()).view;
      await app.byTestId(`inspect.choice.${id}`).check();
      await expect(app.byTestId(`inspect.${id}`)).toHaveText(rows[id]);
      await expect.poll(async () => (await app.canvasPixels()).equals(last)).toBe(false);
      last = await app.canvasPixels();
      // The sphere reaches beyond the level: the camera backs off to show it; the hull lies within the
      // sphere, framed already; the planes (squares a box diagonal wide) reach farther still.
      const after = (await app.state()).view;
      const distance = (v: typeof after) => Math.hypot(...v.position.map((x, i) => x - v.target[i]));
      if (id === 'sphere') expect(distance(after)).toBeGreaterThan(1.05 * distance(before));
      if (id === 'hull') expect(distance(after)).toBeCloseTo(distance(before), 6);
      if (id === 'width') expect(distance(after)).toBeGreaterThan(distance(before));
    }
    await app.snapshot('inspect-cube-level2');
    for (const id of ['sphere', 'hull', 'width']) {
      await app.byTestId(`inspect.choice.${id}`).uncheck();
      await expect.poll(async () => (await app.canvasPixels()).equals(last)).toBe(false);
      last = await app.canvasPixels();
      await expect(app.byTestId(`inspect.${id}`)).toHaveText(rows[id]);
    }
    // Nothing drawn is left, the level framed again: the picture right after Inspect.
    await expect.poll(async () => (await app.canvasPixels()).equals(plain)).toBe(true);
    await app.byTestId('inspect.choice.hull').check();
  });

  await test.step('level 1 is inspected as it is shown; level 2 comes back at once', async () => {
    await app.scrubTo(1);
    await expect(app.byTestId('inspect.hull')).toHaveText(/^26 vertices, 72 edges, 48 triangles;/);
    await app.scrubTo(2);
    // Kept: shown without computing again.
    await expect(app.byTestId('inspect.hull')).toHaveText(/^98 vertices/, { timeout: 500 });
  });
});

test('the mannequin crosses itself: Inspect shows the crossing faces alone, framed', async ({ app }) => {
  await app.open();
  await app.openSample('mannequin', 'mannequin-devil.off');
  const { viewOffset, canvas, view: whole } = await app.state();
  await app.byTestId('inspect.run').click();
  await expect(app.byTestId('inspect.self-intersections')).toHaveText(
    /^1,643 pairs of faces \(984 faces\) · [\d.,]+ ms$/,
  );
  await app.snapshot('inspect-mannequin');
  // The red faces' box, in the part of the view the facts panel leaves free (Fit's offset: x0 = offset x).
  const redBox = async () => {
    await app.page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    const png = readPng(await app.canvas.screenshot());
    let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
    for (let y = 0; y < png.height; ++y)
      for (let x = 0; x < png.width; ++x) {
        const [r, g, b] = png.pixel(x, y);
        // Red, or red seen through the surface (blended with its blue-grey; the warm light on it is less red).
        if (r < g + 55 || r < b + 20) continue;
        [x0, y0, x1, y1] = [Math.min(x0, x), Math.min(y0, y), Math.max(x1, x + 1), Math.max(y1, y + 1)];
      }
    return { x0, y0, x1, y1 };
  };
  const free = { x0: viewOffset[0] * canvas.width, x1: canvas.width, y0: 0, y1: canvas.height };
  const framed = await redBox();
  expect(framed.x0).toBeGreaterThanOrEqual(free.x0 - 2);
  expect(framed.x1).toBeLessThanOrEqual(free.x1 + 2);
  expect(framed.y0).toBeGreaterThanOrEqual(free.y0 - 2);
  expect(framed.y1).toBeLessThanOrEqual(free.y1 + 2);
  // Closer than the whole model's fit: the faces fill most of the free part across or down (Fit fills 90 % with
  // their corners; some are slivers that draw no pixel).
  const distance = (v: { position: number[]; target: number[] }) =>
    Math.hypot(...v.position.map((x, i) => x - v.target[i]));
  expect(distance((await app.state()).view)).toBeLessThan(0.6 * distance(whole));
  const fill = Math.max((framed.x1 - framed.x0) / (free.x1 - free.x0), (framed.y1 - framed.y0) / (free.y1 - free.y0));
  expect(fill).toBeGreaterThan(0.6);

  await test.step('the sphere on one click: computed, and framed with the faces', async () => {
    await app.byTestId('inspect.choice.sphere').check();
    await expect(app.byTestId('inspect.sphere')).toHaveText(/^radius [\d.]+, centre /);
    await expect
      .poll(async () => {
        const box = await redBox();
        return box.x1 - box.x0;
      })
      .toBeLessThan(0.9 * (framed.x1 - framed.x0));
  });
});
