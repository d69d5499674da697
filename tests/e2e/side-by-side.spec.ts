/**
 * Side by side: Catmull-Clark and Loop on the cube in two panes, levels
 * together, cameras linked; the symmetric Hausdorff distance shown is the
 * one `subdiv compare` prints for the same two levels (written by
 * `subdiv -o`), and both surfaces are coloured by it; levels apart; back to
 * one view, the picture is the plain one again; another model, and the
 * panes follow it.
 */
import { readFile } from 'node:fs/promises';
import type { SideBySideTestState } from '../../web/app/test-api';
import { cliDistance as compareLevels } from './cli-distance';
import { expect, test } from './fixtures';
import { readPng } from './helpers';

/** `subdiv compare` of the sample cube's Catmull-Clark and Loop levels. */
const cliDistance = (levels: [number, number]) =>
  compareLevels('public/meshes/cube.off', ['catmull-clark', levels[0]], ['loop', levels[1]]);

test('Catmull-Clark beside Loop on the cube: linked panes, levels together and apart, the Hausdorff distance of the CLI', async ({
  app,
}) => {
  await app.open();
  await app.openSample('cube', 'cube.off');
  await app.subdivide();
  await app.subdivide();
  // One view as it is drawn before side by side, to compare with after it.
  await app.byTestId('view.save').click();
  const single = await app.canvasPixels();
  const side = () => app.page.evaluate(() => window.__subdivlab?.sideBySide() as SideBySideTestState);
  /** The distance once measured on `levels` of pane 2's `scheme` (Loop unless said). */
  const measured = async (levels: [number, number], scheme = 'loop') => {
    await expect
      .poll(async () => {
        const s = await side();
        return s.measuring || !s.distance ? null : [s.distance.levels, s.distance.schemes[1]];
      })
      .toEqual([levels, scheme]);
    return (await side()).distance as NonNullable<SideBySideTestState['distance']>;
  };

  await test.step('two panes: Loop beside Catmull-Clark, at the same level', async () => {
    await app.byTestId('side.count').selectOption('2');
    await expect(app.byTestId('pane.1.view').locator('canvas')).toBeVisible();
    await expect(app.byTestId('pane.1.scheme')).toHaveValue('loop');
    await expect(app.byTestId('pane.0.level')).toHaveText('level 2 · 98 vertices · 96 quads');
    // The cube's 6 quads split into 12 triangles first, then 4 each per step.
    await expect(app.byTestId('pane.1.level')).toHaveText('level 2 · 98 vertices · 192 triangles · triangulated first');
  });

  await test.step('the distance is the CLI’s, and both surfaces are coloured by it', async () => {
    const d = await measured([2, 2]);
    const cli = cliDistance([2, 2]);
    expect(Math.abs(d.distance - cli.distance)).toBeLessThanOrEqual(d.errorBound + cli.errorBound);
    expect(d.relative).toBeCloseTo(d.distance / d.diagonal, 15);
    // The cube (side 2, centred) and its levels: the diagonal of both is at most 2√3.
    expect(d.diagonal).toBeLessThanOrEqual(2 * Math.sqrt(3) + 1e-12);
    // No vertex is farther from the other surface than the Hausdorff distance.
    for (const far of d.farthest) expect(far).toBeLessThanOrEqual(d.distance + d.errorBound);
    expect(Math.max(...d.farthest)).toBeGreaterThan(0.5 * d.distance);
    const percent = (100 * d.relative).toPrecision(3);
    await expect(app.byTestId('side.distance')).toContainText(
      `Hausdorff distance between Catmull-Clark level 2 and Loop level 2: ${d.distance.toPrecision(4)}, ${percent} % of the diagonal`,
    );
    await expect(app.byTestId('side.legend')).toBeVisible();
    await expect(app.byTestId('side.high')).toHaveText(d.distance.toPrecision(4));
    const coloured = await app.canvasPixels();
    await app.byTestId('side.colours').uncheck();
    await expect.poll(async () => (await app.canvasPixels()).equals(coloured)).toBe(false);
    const plain = await app.canvasPixels();
    await app.byTestId('side.colours').check();
    await expect.poll(async () => (await app.canvasPixels()).equals(plain)).toBe(false);
    await app.snapshot('side-by-side-cc-loop');
  });

  await test.step('the PNG holds both panes, labelled, side by side', async () => {
    const [w, h] = await app.byTestId('viewer').evaluate((e) => [e.clientWidth, e.clientHeight]);
    await app.byTestId('export-panel').locator('summary').click();
    const download = await app.download('export.png');
    expect(download.suggestedFilename()).toBe('cube-catmull-clark-loop-L2.png');
    const png = readPng(await readFile(await download.path()));
    // Two pictures of the first pane's size, 2 px apart.
    expect([png.width, png.height]).toEqual([2 * w + 2, h]);
  });

  await test.step('quad-triangle on the all-quad cube is Catmull-Clark: the surfaces agree', async () => {
    await app.byTestId('pane.1.scheme').selectOption('quad-triangle');
    await expect(app.byTestId('pane.1.level')).toHaveText('level 2 · 98 vertices · 96 quads');
    const d = await measured([2, 2], 'quad-triangle');
    expect(Math.max(...d.farthest)).toBeLessThan(1e-12);
    expect(d.distance).toBeLessThanOrEqual(d.errorBound);
    await expect(app.byTestId('side.distance')).toHaveText(
      `Hausdorff distance between Catmull-Clark level 2 and Quad/Triangle level 2: 0 (to within ${d.errorBound.toPrecision(4)}): the surfaces agree.`,
    );
    await app.byTestId('pane.1.scheme').selectOption('loop');
    await measured([2, 2]);
  });

  await test.step('a basis function shows over the distance colours, which come back when it goes', async () => {
    const distanceColours = await app.canvasPixels();
    await app.byTestId('basis.toggle').click();
    await app.byTestId('basis.vertex').fill('0');
    await app.byTestId('basis.vertex').press('Enter');
    await expect(app.byTestId('basis.reach')).toHaveText(/^Control vertex 0 reaches /);
    await expect.poll(async () => (await app.canvasPixels()).equals(distanceColours)).toBe(false);
    // A change of pane 2 measures again: the basis function stays on top in pane 1.
    const basisColours = await app.canvasPixels();
    await app.byTestId('pane.1.scheme').selectOption('sqrt3');
    await measured([2, 2], 'sqrt3');
    await app.byTestId('pane.1.scheme').selectOption('loop');
    await measured([2, 2]);
    await expect.poll(async () => (await app.canvasPixels()).equals(basisColours)).toBe(true);
    await app.byTestId('basis.toggle').click();
    // The control mesh the basis view showed goes off again by hand (C).
    await app.page.keyboard.press('c');
    await expect.poll(async () => (await app.canvasPixels()).equals(distanceColours)).toBe(true);
  });

  await test.step('the cameras are linked: turning pane 2 turns pane 1', async () => {
    const before = (await side()).panes[0].view;
    const box = await app.byTestId('pane.1.view').boundingBox();
    if (!box) throw new Error('pane 2 has no box');
    await app.page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await app.page.mouse.down();
    await app.page.mouse.move(box.x + box.width / 2 + 80, box.y + box.height / 2 + 20, { steps: 5 });
    await app.page.mouse.up();
    const after = await side();
    expect(after.panes[0].view.position).not.toEqual(before.position);
    for (let i = 0; i < 3; ++i) expect(after.panes[0].view.position[i]).toBeCloseTo(after.panes[1].view.position[i], 9);
  });

  await test.step('levels together: Subdivide steps both panes', async () => {
    await app.subdivide();
    await expect.poll(async () => (await side()).panes[1].level).toBe(3);
    await expect(app.byTestId('pane.1.level')).toHaveText(
      'level 3 · 386 vertices · 768 triangles · triangulated first',
    );
    const d = await measured([3, 3]);
    const cli = cliDistance([3, 3]);
    expect(Math.abs(d.distance - cli.distance)).toBeLessThanOrEqual(d.errorBound + cli.errorBound);
  });

  await test.step('levels apart: pane 2 goes down alone', async () => {
    await app.byTestId('side.together').uncheck();
    await app.byTestId('pane.1.down').click();
    await expect.poll(async () => (await side()).panes.map((p) => p.level)).toEqual([3, 2]);
    const d = await measured([3, 2]);
    const cli = cliDistance([3, 2]);
    expect(Math.abs(d.distance - cli.distance)).toBeLessThanOrEqual(d.errorBound + cli.errorBound);
    // Stepping the first pane leaves the second where it is.
    await app.scrubTo(2);
    await expect.poll(async () => (await side()).panes.map((p) => p.level)).toEqual([2, 2]);
    await app.scrubTo(1);
    expect((await side()).panes[1].level).toBe(2);
  });

  await test.step('back to one view: no pane, no colours', async () => {
    await app.scrubTo(2);
    await app.byTestId('side.count').selectOption('1');
    await expect(app.byTestId('pane.1')).toHaveCount(0);
    expect((await side()).count).toBe(1);
    // From the same viewpoint, the one view is drawn as before: no distance colours are left.
    await app.byTestId('view.restore').click();
    await expect.poll(async () => (await app.canvasPixels()).equals(single)).toBe(true);
  });

  await test.step('another model: the panes follow it, levels together again', async () => {
    await app.byTestId('side.count').selectOption('2');
    await app.byTestId('side.together').check();
    await app.openSample('tetrahedron', 'tetrahedron.off');
    await app.subdivide();
    await expect
      .poll(async () => (await side()).panes.map((p) => [p.level, p.faces]))
      .toEqual([
        [1, 12],
        [1, 16],
      ]);
    await measured([1, 1]);
    await app.subdivide();
    await measured([2, 2]);
  });

  await test.step('the link keeps the panes: beside=loop, and a reload shows them again', async () => {
    await app.waitForHash('beside', 'loop');
    // The hash is written a moment after the last step.
    await app.waitForHash('levels', '2');
    await app.page.reload();
    await expect
      .poll(async () => (await side()).panes.map((p) => [p.scheme, p.level]))
      .toEqual([
        ['catmull-clark', 2],
        ['loop', 2],
      ]);
    await measured([2, 2]);
    await app.byTestId('side.count').selectOption('1');
    await expect.poll(async () => (await app.hashParams()).has('beside')).toBe(false);
  });
});

test('panes opened from a link are framed together: the linear cube beside Catmull-Clark is not cut off', async ({
  app,
}) => {
  // 1280 × 800: there the fit once ran with the camera's aspect of the single view it had been.
  await app.page.setViewportSize({ width: 1280, height: 800 });
  await app.open('#src=meshes%2Fcube.off&scheme=catmull-clark&levels=3&beside=linear');
  const side = () => app.page.evaluate(() => window.__subdivlab?.sideBySide() as SideBySideTestState);
  await expect
    .poll(async () => (await side()).panes.map((p) => `${p.scheme} ${p.level} ${p.busy}`))
    .toEqual(['catmull-clark 3 false', 'linear 3 false']);
  // The fit comes a frame after the last pane shows its level; the linked cameras then agree.
  await expect
    .poll(async () => {
      const { canvas } = await app.state();
      const corners = await app.page.evaluate(() => window.__subdivlab?.projected(3, 1) ?? []);
      const inside = corners.filter((p) => p.x >= 0 && p.x <= canvas.width && p.y >= 0 && p.y <= canvas.height);
      return `${inside.length} of ${corners.length}`;
    })
    .toBe('386 of 386');
  const panes = (await side()).panes;
  expect(panes[1].view).toEqual(panes[0].view);
  await app.snapshot('side-by-side-framed-together');
});
