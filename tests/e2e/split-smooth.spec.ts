/**
 * Split, then smooth: the slider draws the shown level between its split
 * alone (midpoints and centroids of the level before) and its smoothed
 * points; Play runs the step; another level is drawn at its own points.
 */
import { readFileSync } from 'node:fs';
import { expect, test } from './fixtures';

const CUBE = readFileSync('tests/fixtures/cube.off', 'utf8');

/** The cube's 8 vertices as the fixture lists them (level 0): the lines after "OFF" and the counts. */
const CONTROL = CUBE.split('\n')
  .filter((line) => line.trim() !== '' && !line.startsWith('#'))
  .slice(2, 10)
  .map((line) => line.trim().split(/\s+/).map(Number));

test('Catmull-Clark on the cube: level 1 from its split (old corners, face centroids) to its smoothed points', async ({
  app,
}) => {
  await app.open();
  await app.load('cube.off', CUBE);
  await expect(app.byTestId('split.t')).toBeDisabled();
  await expect(app.byTestId('split.message')).toContainText('Subdivide');
  await app.subdivide();
  const smoothed = await app.page.evaluate(() => window.__subdivlab?.drawnPositions() ?? []);
  const drawnPixels = await app.canvasPixels();
  await app.byTestId('split.t').fill('0');
  await expect(app.byTestId('split.value')).toHaveText('0.00');
  await expect
    .poll(async () => (await app.page.evaluate(() => window.__subdivlab?.drawnPositions() ?? [])).slice(0, 3))
    .toEqual(CONTROL[0]);
  const split = await app.page.evaluate(() => window.__subdivlab?.drawnPositions() ?? []);
  // The split keeps the 8 corners where they were; the 6 face points (20..25) are the centroids of the
  // faces of [-1, 1]^3: 0 in two coordinates, ±1 in the third.
  for (let v = 0; v < 8; ++v) expect(split.slice(3 * v, 3 * v + 3)).toEqual(CONTROL[v]);
  for (let f = 20; f < 26; ++f) {
    const p = split.slice(3 * f, 3 * f + 3);
    expect(p.filter((x) => x === 0)).toHaveLength(2);
    expect(p.filter((x) => Math.abs(x) === 1)).toHaveLength(1);
  }
  await expect.poll(async () => (await app.canvasPixels()).equals(drawnPixels)).toBe(false);
  await app.snapshot('split-cube-0');
  await app.byTestId('split.t').fill('0.5');
  await expect(app.byTestId('split.value')).toHaveText('0.50');
  const half = await app.page.evaluate(() => window.__subdivlab?.drawnPositions() ?? []);
  for (let i = 0; i < half.length; ++i) expect(half[i]).toBeCloseTo((split[i] + smoothed[i]) / 2, 6);
  await app.snapshot('split-cube-half');

  await test.step('Play ends at the smoothed level; another level is drawn at its own points', async () => {
    await app.byTestId('split.play').click();
    await expect(app.byTestId('split.value')).toHaveText('1.00');
    expect(await app.page.evaluate(() => window.__subdivlab?.drawnPositions() ?? [])).toEqual(smoothed);
    await app.byTestId('split.t').fill('0');
    await expect(app.byTestId('split.value')).toHaveText('0.00');
    await app.scrubTo(0);
    await app.scrubTo(1);
    await expect(app.byTestId('split.value')).toHaveText('1.00');
    expect(await app.page.evaluate(() => window.__subdivlab?.drawnPositions() ?? [])).toEqual(smoothed);
  });
});
