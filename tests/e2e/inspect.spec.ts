/**
 * Inspect: the stella octangula (two tetrahedra through each other) has 12
 * pairs of crossing faces, drawn in red and listed, a pair framed by a
 * click; Catmull-Clark's level 2 of the cube gets the figures `subdiv
 * inspect` prints (sphere, hull, width, and its shrinking from level 0),
 * each drawn, kept per level.
 */
import { spawnSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { figure } from '../../web/ui/inspect-panel';
import { expect, test } from './fixtures';
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
  const plain = await app.canvasPixels();
  await app.byTestId('inspect.run').click();
  await expect(app.byTestId('inspect.width')).toContainText(`${figure(cli.width.width)}, between the planes`);
  await expect(app.byTestId('inspect.volume')).toHaveText(
    `${figure(cli.measures.volume)} (×${figure(cli.change.volume)} of level 0)`,
  );
  await expect(app.byTestId('inspect.area')).toHaveText(
    `${figure(cli.measures.area)} (×${figure(cli.change.area)} of level 0)`,
  );
  await expect(app.byTestId('inspect.sphere')).toHaveText(
    new RegExp(`^radius ${figure(cli.sphere.radius)}, centre \\(0, 0, 0\\) · [\\d.,]+ ms$`),
  );
  await expect(app.byTestId('inspect.hull')).toHaveText(
    new RegExp(
      `^98 vertices, 288 edges, 192 triangles; area ${figure(cli.hull.area)}, volume ${figure(cli.hull.volume)} · `,
    ),
  );
  await expect(app.byTestId('inspect.self-intersections')).toHaveText(/^none · /);
  const drawn = await app.canvasPixels();
  expect(drawn.equals(plain)).toBe(false);
  await app.snapshot('inspect-cube-level2');

  await test.step('each drawing goes with its box', async () => {
    let last = drawn;
    for (const id of ['sphere', 'hull', 'width']) {
      await app.byTestId(`inspect.choice.${id}`).uncheck();
      await expect.poll(async () => (await app.canvasPixels()).equals(last)).toBe(false);
      last = await app.canvasPixels();
    }
    // Nothing drawn is left: the plain picture again.
    await expect.poll(async () => (await app.canvasPixels()).equals(plain)).toBe(true);
    for (const id of ['sphere', 'hull', 'width']) await app.byTestId(`inspect.choice.${id}`).check();
  });

  await test.step('level 1 is inspected as it is shown; level 2 comes back at once', async () => {
    await app.scrubTo(1);
    await expect(app.byTestId('inspect.hull')).toHaveText(/^26 vertices, 72 edges, 48 triangles;/);
    await app.scrubTo(2);
    // Kept: shown without computing again.
    await expect(app.byTestId('inspect.hull')).toHaveText(/^98 vertices/, { timeout: 500 });
  });
});
