/**
 * Crease editing as a user does it: pick a control edge on the view, give
 * it a sharpness with a key, the slider or the buttons, subdivide, undo and
 * redo. The moved vertex is read against OpenSubdiv's value
 * (tests/fixtures/crease-edit.osd.txt, checked against Far by osd_tests).
 */
import { readFileSync } from 'node:fs';
import { readFile } from 'node:fs/promises';
import { expect, test } from './fixtures';
import type { SubdivLabPage } from './subdivlab-page';

/** The level-2 points of the Creased cube sample's level-0 vertices with edge 1-5 of sharpness 2, by OpenSubdiv. */
const OSD_LEVEL_2 = new Map(
  readFileSync('tests/fixtures/crease-edit.osd.txt', 'utf8')
    .split('\n')
    .filter((line) => line.trim() !== '' && !line.startsWith('#'))
    .map((line) => {
      const [v, x, y, z] = line.trim().split(/\s+/).map(Number);
      return [v, [x, y, z]] as const;
    }),
);

/** Where control vertex `v` is drawn, in page pixels. */
async function vertexOnScreen(app: SubdivLabPage, v: number): Promise<{ x: number; y: number }> {
  const at = await app.page.evaluate((i) => window.__subdivlab?.vertexOnScreen(i) ?? null, v);
  if (!at) throw new Error(`control vertex ${v} is not in view`);
  return at;
}

/** Clicks the middle of control edge a–b as drawn (a point on its picture), with Alt for its loop. */
async function clickEdge(app: SubdivLabPage, a: number, b: number, alt = false): Promise<void> {
  const [p, q] = [await vertexOnScreen(app, a), await vertexOnScreen(app, b)];
  if (alt) await app.page.keyboard.down('Alt');
  await app.page.mouse.click((p.x + q.x) / 2, (p.y + q.y) / 2);
  if (alt) await app.page.keyboard.up('Alt');
}

async function pointOf(app: SubdivLabPage, v: number): Promise<number[]> {
  return (await app.positions()).slice(3 * v, 3 * v + 3);
}

test('set an edge of the creased cube to sharpness 2: OpenSubdiv’s points at level 2; undo and redo', async ({
  app,
}) => {
  await app.open();
  await app.openSample('cube-creased', 'cube-creased.obj');
  await expect(app.byTestId('facts.tags')).toHaveText('6 creases, 1 corner');
  // The untagged-edge result first, to compare undo with.
  await app.subdivide();
  await app.subdivide();
  const untouched = await pointOf(app, 1);
  await app.byTestId('controls.reset').click();
  await expect.poll(async () => (await app.state()).levelCount).toBe(1);

  await test.step('pick edge 1–5 on the view, set 2 with the keyboard', async () => {
    await app.page.keyboard.press('m');
    await expect(app.byTestId('creases.edit')).toHaveAttribute('aria-pressed', 'true');
    await expect(app.byTestId('controls.overlay-control')).toBeChecked();
    await clickEdge(app, 1, 5);
    await expect(app.byTestId('creases.selection')).toHaveText('Edge 1–5: smooth');
    await app.snapshot('crease-edit-selected');
    await app.page.keyboard.press('2');
    await expect(app.byTestId('facts.tags')).toHaveText('7 creases, 1 corner');
    await expect(app.byTestId('creases.selection')).toHaveText('Edge 1–5: 2');
    expect((await app.idle()).level).toBe(0);
  });

  await test.step('two steps: vertex 1 where OpenSubdiv puts it', async () => {
    await app.subdivide();
    await app.snapshot('crease-edit-1');
    await app.subdivide();
    await app.snapshot('crease-edit-2');
    const moved = await pointOf(app, 1);
    const want = OSD_LEVEL_2.get(1) ?? [];
    for (let i = 0; i < 3; ++i) expect(moved[i]).toBeCloseTo(want[i], 12);
    // Far from the untouched point: the edge made vertex 1 a crease vertex.
    expect(Math.hypot(...moved.map((c, i) => c - untouched[i]))).toBeGreaterThan(0.01);
    // Every level-0 vertex's point agrees, not only the one that moved most.
    const points = await app.positions();
    for (const [v, p] of OSD_LEVEL_2) for (let i = 0; i < 3; ++i) expect(points[3 * v + i]).toBeCloseTo(p[i], 12);
  });

  await test.step('undo (Ctrl+Z) computes level 2 again without the edit; Redo brings it back', async () => {
    await app.page.keyboard.press('Control+z');
    await expect(app.byTestId('creases.selection')).toHaveText('Edge 1–5: smooth');
    const state = await app.idle();
    expect(state.level).toBe(2);
    expect(state.levelCount).toBe(3);
    expect(await pointOf(app, 1)).toEqual(untouched);
    await expect(app.byTestId('creases.redo')).toBeEnabled();
    await app.byTestId('creases.redo').click();
    await expect(app.byTestId('creases.selection')).toHaveText('Edge 1–5: 2');
    await app.idle();
    const redone = await pointOf(app, 1);
    for (let i = 0; i < 3; ++i) expect(redone[i]).toBeCloseTo(OSD_LEVEL_2.get(1)?.[i] ?? Number.NaN, 12);
  });

  await test.step('a level-3 picture, and the slider and buttons on a vertex', async () => {
    await app.subdivide();
    await app.snapshot('crease-edit-3');
    await app.scrubTo(0);
    await app.snapshot('crease-edit-0');
    const corner = await vertexOnScreen(app, 2);
    await app.page.mouse.click(corner.x, corner.y);
    await expect(app.byTestId('creases.selection')).toHaveText('Vertex 2: 3');
    await app.byTestId('creases.sharpness').fill('0');
    await expect(app.byTestId('facts.tags')).toHaveText('7 creases');
    await app.byTestId('creases.sharp').click();
    await expect(app.byTestId('creases.selection')).toHaveText('Vertex 2: ∞');
    await expect(app.byTestId('facts.tags')).toHaveText('7 creases, 1 corner');
    // Levels above the shown one were dropped by the edit and computed no further.
    expect((await app.idle()).levelCount).toBe(1);
  });

  await test.step('OBJ export of level 0 saves the edits as tags', async () => {
    await app.byTestId('export-panel').locator('summary').click();
    const obj = await readFile(await (await app.download('export.obj')).path(), 'utf8');
    const tags = obj.split('\n').filter((line) => line.startsWith('t '));
    expect(tags).toContain('t corner 1/1/0 2 10');
    expect(tags.join('\n')).toMatch(/^t crease 2\/1\/0 1 5 2$/m);
  });
});

test('Alt+click picks an edge loop; a new model forgets the selection and the edits', async ({ app }) => {
  await app.open();
  await app.openSample('torus', 'torus.off');
  await app.byTestId('creases.edit').click();
  // The torus is 8 × 6 quads, vertex 6i + j at ring i, position j around the tube:
  // edge 0–1 runs around the tube, a loop of 6 edges (0–6 goes around the hole: 8).
  await clickEdge(app, 0, 1, true);
  await expect(app.byTestId('creases.selection')).toHaveText('Edge loop: 6 edges: smooth');
  await app.page.keyboard.press('i');
  await expect(app.byTestId('facts.tags')).toHaveText('6 creases');
  await app.subdivide();
  await app.snapshot('crease-edit-torus-loop');
  await expect(app.byTestId('creases.undo')).toBeEnabled();
  await app.openSample('cube', 'cube.off');
  await expect(app.byTestId('creases.undo')).toBeDisabled();
  await expect(app.byTestId('creases.selection')).toHaveText('Nothing selected');
  await expect(app.byTestId('facts.tags')).toHaveText('–');
});
