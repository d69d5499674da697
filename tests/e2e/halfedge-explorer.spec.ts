/**
 * The halfedge explorer as a student uses it: on the cube, a halfedge
 * clicked on the view, walked with the keys (next four times and opposite
 * twice come back to it, the expression spelled as CGAL spells it), a
 * corner circulated; a face split along its diagonal and undone (the exact
 * mesh back); √3 by hand played to its end on the icosahedron, equal to
 * the scheme's level 1; a level too large refused.
 */
import { readFileSync } from 'node:fs';
import { readFile } from 'node:fs/promises';
import { expect, test } from './fixtures';
import { readPng } from './helpers';
import type { SubdivLabPage } from './subdivlab-page';

type Halfedges = ReturnType<NonNullable<Window['__subdivlab']>['halfedges']>;

async function halfedges(app: SubdivLabPage): Promise<Halfedges> {
  const state = await app.page.evaluate(() => window.__subdivlab?.halfedges() ?? null);
  if (!state) throw new Error('no test API');
  return state;
}

/** Switches the explorer on and waits for the shown level's `count` halfedges. */
async function explore(app: SubdivLabPage, count: number): Promise<void> {
  await app.byTestId('halfedges.explore').click();
  await expect(app.byTestId('halfedges.explore')).toHaveAttribute('aria-pressed', 'true');
  await expect.poll(async () => (await halfedges(app)).explorer.halfedgeCount).toBe(count);
}

/** Clicks the arrows of the cube's halfedges until one on a face turned to the camera is picked; returns it. */
async function clickAnArrow(app: SubdivLabPage): Promise<number> {
  for (let h = 0; h < 24; ++h) {
    const at = await app.page.evaluate((i) => window.__subdivlab?.arrowOnScreen(i) ?? null, h);
    if (!at) continue;
    await app.page.mouse.click(at.x, at.y);
    if ((await halfedges(app)).explorer.picked?.h === h) return h;
  }
  throw new Error('no arrow of the cube could be clicked');
}

async function picked(app: SubdivLabPage): Promise<number | undefined> {
  return (await halfedges(app)).explorer.picked?.h;
}

test('the cube: next four times and opposite twice come back, a corner has 3 halfedges, a split face is undone exactly', async ({
  app,
}) => {
  await app.open();
  await app.openSample('cube', 'cube.off');
  await explore(app, 24);
  await expect(app.byTestId('halfedges.message')).toHaveText('Click an arrow (a halfedge), or type its number.');
  const h = await clickAnArrow(app);
  await expect(app.byTestId('halfedges.surface-mesh')).toHaveText('h');
  const { table } = await halfedges(app);
  if (!table) throw new Error('no table');

  await test.step('next four times (the N key) goes round the quad and back', async () => {
    const seen = [h];
    for (let i = 0; i < 4; ++i) {
      await app.page.keyboard.press('n');
      await expect.poll(() => picked(app)).toBe(table.next[seen[i]]);
      seen.push(table.next[seen[i]]);
    }
    expect(new Set(seen.slice(0, 4)).size).toBe(4);
    expect(seen[4]).toBe(h);
    await expect(app.byTestId('halfedges.surface-mesh')).toHaveText('next(next(next(next(h, m), m), m), m)');
    await expect(app.byTestId('halfedges.polyhedron')).toHaveText('h->next()->next()->next()->next()');
    await expect(app.byTestId('halfedges.start')).toHaveText(`h is halfedge ${h}; m is the mesh.`);
  });

  await test.step('opposite twice (the button) comes back too', async () => {
    await app.byTestId('halfedges.opposite').click();
    await expect.poll(() => picked(app)).toBe(h ^ 1);
    expect((await halfedges(app)).explorer.picked?.face).toBe(table.face[h ^ 1]);
    await app.byTestId('halfedges.opposite').click();
    await expect.poll(() => picked(app)).toBe(h);
    await expect(app.byTestId('halfedges.polyhedron')).toHaveText(
      'h->next()->next()->next()->next()->opposite()->opposite()',
    );
    await expect(app.byTestId('halfedges.surface-mesh')).toHaveText(
      'opposite(opposite(next(next(next(next(h, m), m), m), m), m), m)',
    );
  });

  await test.step('circulating a corner visits 3 halfedges', async () => {
    await app.byTestId('halfedges.circulate-vertex').click();
    await expect(app.byTestId('halfedges.report')).toHaveText(`vertex ${table.target[h]}: 3 halfedges around it`);
    // The corner (1, 1, 1) facing the camera, from face 5 (z = 1): its three halfedges in view.
    const g = table.next.findIndex((_, i) => table.face[i] === 5 && table.target[i] === 7);
    await app.byTestId('halfedges.number').fill(String(g));
    await app.byTestId('halfedges.number').press('Enter');
    await app.byTestId('halfedges.circulate-vertex').click();
    await expect(app.byTestId('halfedges.report')).toHaveText('vertex 7: 3 halfedges around it');
    const { circulation } = (await halfedges(app)).explorer;
    expect(circulation?.visited).toHaveLength(2);
    for (const v of circulation?.visited ?? []) expect(table.target[v]).toBe(7);
    expect(new Set([g, ...(circulation?.visited ?? [])].map((v) => table.face[v]))).toEqual(new Set([2, 4, 5]));
    await app.byTestId('halfedge-panel').scrollIntoViewIfNeeded();
    await app.snapshot('halfedge-explorer-cube');
    await app.byTestId('halfedges.number').fill(String(h));
    await app.byTestId('halfedges.number').press('Enter');
  });

  const before = { positions: await app.positions(), table };
  await test.step('a face split along its diagonal: 7 faces, χ = 2, valid', async () => {
    await app.byTestId('euler.second').click();
    await expect(app.byTestId('halfedges.message')).toContainText('second halfedge');
    await app.byTestId('halfedges.number').fill(String(table.next[table.next[h]]));
    await app.byTestId('halfedges.number').press('Enter');
    await expect(app.byTestId('euler.second')).toHaveText(`Second halfedge: ${table.next[table.next[h]]}`);
    await app.byTestId('euler.split_face').click();
    await expect(app.byTestId('euler.outcome')).toHaveText(
      "split_face: V 8, E 13, F 7, χ = 2; CGAL's is_valid_polygon_mesh: valid.",
    );
    expect((await app.facts()).faces).toBe(7);
    const state = await app.state();
    expect(state.modelName).toBe('cube.off (edited)');
    expect(state.facts?.eulerCharacteristic).toBe(2);
    // The explorer follows the edit: 26 halfedges, CGAL's returned halfedge picked.
    await expect.poll(async () => (await halfedges(app)).explorer.halfedgeCount).toBe(26);
    expect((await halfedges(app)).explorer.picked).not.toBeNull();
  });

  await test.step('undo shows the cube again, the same mesh', async () => {
    await app.byTestId('euler.undo').click();
    await expect(app.byTestId('euler.outcome')).toHaveText(/^Undone: V 8, E 12, F 6, χ = 2/);
    expect((await app.facts()).faces).toBe(6);
    expect((await app.state()).modelName).toBe('cube.off');
    await expect.poll(async () => (await halfedges(app)).explorer.halfedgeCount).toBe(24);
    expect(await app.positions()).toEqual(before.positions);
    expect((await halfedges(app)).table).toEqual(before.table);
    await expect(app.byTestId('euler.undo')).toBeDisabled();
  });

  await test.step('a broken precondition is named and the mesh stays', async () => {
    await app.byTestId('halfedges.number').fill('0');
    await app.byTestId('halfedges.number').press('Enter');
    await app.byTestId('euler.flip_edge').click();
    await expect(app.byTestId('euler.problem')).toBeVisible();
    await expect(app.byTestId('euler.problem')).toContainText('triangle');
    expect((await app.facts()).faces).toBe(6);
    await expect(app.errorBanner).toBeHidden();
  });
});

test('√3 by hand on the icosahedron: 62 operators, then the scheme’s level 1; the cube is refused', async ({ app }) => {
  test.setTimeout(90_000);
  await app.open();
  await app.openSample('cube', 'cube.off');
  await explore(app, 24);
  await app.byTestId('sqrt3.step').click();
  await expect(app.byTestId('euler.problem')).toHaveText(
    'the walk-through follows the tutorial on triangle meshes: face 0 has 4 corners',
  );
  expect((await app.facts()).faces).toBe(6);

  await app.openSample('icosahedron', 'icosahedron.off');
  await expect.poll(async () => (await halfedges(app)).explorer.halfedgeCount).toBe(60);
  await app.byTestId('sqrt3.step').click();
  await expect(app.byTestId('sqrt3.progress')).toHaveText('1 / 62 operators; last: add_center_vertex (face 0)');
  expect((await app.facts()).faces).toBe(22);
  await app.byTestId('sqrt3.play').click();
  await expect(app.byTestId('sqrt3.play')).toHaveText('Pause');
  await expect(app.byTestId('sqrt3.progress')).toHaveText(/^62 \/ 62 operators; last: /, { timeout: 60_000 });
  await expect(app.byTestId('sqrt3.verdict')).toHaveText(
    /^Equal to the √3 scheme's level 1: same 32 vertices and 60 faces, largest distance/,
  );
  const { euler } = await halfedges(app);
  expect(euler.walk?.equal).toBe(true);
  const facts = await app.facts();
  expect([facts.vertices, facts.faces]).toEqual([32, 60]);
  await expect.poll(async () => (await halfedges(app)).explorer.halfedgeCount).toBe(180);
  await app.byTestId('sqrt3.verdict').scrollIntoViewIfNeeded();
  await app.snapshot('sqrt3-by-hand-icosahedron');
  // Undo goes back to the icosahedron before the walk.
  await app.byTestId('euler.undo').click();
  await expect.poll(async () => (await app.facts()).faces).toBe(20);
  await expect(app.byTestId('euler.undo')).toBeDisabled();
  // Another model ends the history: nothing to undo, no walk.
  await app.byTestId('sqrt3.step').click();
  await expect(app.byTestId('sqrt3.progress')).toHaveText(/^1 \/ 62 /);
  await expect(app.byTestId('euler.undo')).toBeEnabled();
  await app.openSample('octahedron', 'octahedron.off');
  await expect(app.byTestId('euler.undo')).toBeDisabled();
  await expect(app.byTestId('sqrt3.progress')).toHaveText('');
});

test('a level above the size limit is refused, naming the levels that fit', async ({ app }) => {
  await app.open();
  await app.openSample('cube', 'cube.off');
  for (let i = 0; i < 4; ++i) await app.subdivide();
  await app.byTestId('halfedges.explore').click();
  await expect(app.byTestId('halfedges.message')).toHaveText(
    'The halfedge explorer shows meshes up to 5,000 halfedges; this level has 6,144. Pick level 0, 1, 2 or 3.',
  );
  await expect(app.byTestId('halfedges.body')).toBeHidden();
  await app.scrubTo(1);
  await expect.poll(async () => (await halfedges(app)).explorer.halfedgeCount).toBe(96);
  await expect(app.byTestId('halfedges.message')).toHaveText('Click an arrow (a halfedge), or type its number.');
});

test('the open grid: border halfedges outside the boundary, one border loop of 12', async ({ app }) => {
  await app.open();
  await app.openSample('open-grid', 'open-grid.off');
  await explore(app, 48);
  const { table } = await halfedges(app);
  if (!table) throw new Error('no table');
  const border = table.face.flatMap((f, h) => (f < 0 ? [h] : []));
  expect(border).toHaveLength(12);
  await app.byTestId('halfedges.number').fill(String(border[0]));
  await app.byTestId('halfedges.number').press('Enter');
  await expect(app.byTestId('halfedges.picked')).toContainText(`Halfedge ${border[0]}: `);
  await expect(app.byTestId('halfedges.picked')).toContainText(', border; ');
  await app.byTestId('halfedges.circulate-face').click();
  await expect(app.byTestId('halfedges.report')).toHaveText('border loop: 12 halfedges around it', { timeout: 10_000 });
  // Opposite leads inside: a halfedge of a face.
  await app.page.keyboard.press('o');
  await expect.poll(async () => (await halfedges(app)).explorer.picked?.face).toBe(table.face[border[0] ^ 1]);
  expect(table.face[border[0] ^ 1]).toBeGreaterThanOrEqual(0);
  await app.snapshot('halfedge-explorer-open-grid');
});

test('a ×4 PNG draws the arrows four times as wide: their dark pixels grow sixteenfold, not fourfold', async ({
  app,
}) => {
  await app.open();
  await app.load('cube.off', readFileSync('public/meshes/cube.off', 'utf8'));
  await explore(app, 24);
  // Near-black: the arrows (the cube's darkest side is far lighter).
  const darkPixels = async (scale: number) => {
    await app.byTestId('export-panel').locator('summary').click();
    await app.byTestId('export.scale').selectOption(String(scale));
    const download = await app.download('export.png');
    const png = readPng(await readFile(await download.path()));
    let dark = 0;
    for (let y = 0; y < png.height; y++)
      for (let x = 0; x < png.width; x++) {
        const [r, g, b] = png.pixel(x, y);
        if (0.299 * r + 0.587 * g + 0.114 * b < 60) dark++;
      }
    return dark;
  };
  const one = await darkPixels(1);
  const four = await darkPixels(4);
  expect(one).toBeGreaterThan(500);
  // Width and length both × 4 (× 4 alone, had the width stayed, would give about × 4).
  expect(four / one).toBeGreaterThan(12);
  expect(four / one).toBeLessThan(20);
});
