/**
 * Switching scheme keeps the level: the levels are computed again with the
 * new scheme up to the level shown, with progress and Cancel; a switch that
 * cannot be made leaves the previous scheme and levels, and its message goes
 * once it is resolved.
 */
import { readFileSync } from 'node:fs';
import { expect, test } from './fixtures';
import { quadGridOff } from './helpers';

const CUBE = readFileSync('public/meshes/cube.off', 'utf8');

test('a scheme picked at level 2 computes its own level 2, and back', async ({ app }) => {
  await app.open();
  await app.load('cube.off', CUBE);
  await app.subdivide();
  await app.subdivide();
  // Catmull-Clark: 6 · 4² quads.
  expect(await app.facts()).toMatchObject({ vertices: 98, edges: 192, faces: 96 });
  const state = await app.chooseScheme('doo-sabin');
  expect(state).toMatchObject({ scheme: 'doo-sabin', level: 2, levelCount: 3, lastError: null });
  // Doo-Sabin: level 1 has a face per vertex, edge and face of the cube (8 + 12 + 6 = 26: 24
  // corners, 48 edges); level 2 a face per vertex, edge and face of level 1 (24 + 48 + 26 = 98)
  // and a vertex per corner of level 1 (8 · 3 + 18 · 4 = 96).
  expect(await app.facts()).toMatchObject({ vertices: 96, edges: 192, faces: 98, genus: 0 });
  await expect(app.byTestId('controls.level-status')).toHaveText('Level 2: 8 triangles, 90 quads, genus 0');
  await test.step('every level below is the new scheme too', async () => {
    await app.scrubTo(1);
    expect(await app.facts()).toMatchObject({ vertices: 24, edges: 48, faces: 26 });
  });
  await test.step('back to Catmull-Clark at level 1', async () => {
    expect(await app.chooseScheme('catmull-clark')).toMatchObject({ level: 1, levelCount: 2 });
    expect(await app.facts()).toMatchObject({ vertices: 26, edges: 48, faces: 24 });
  });
  await test.step('at level 0 a switch only drops the levels above', async () => {
    await app.scrubTo(0);
    expect(await app.chooseScheme('linear')).toMatchObject({ level: 0, levelCount: 1 });
  });
});

test('a switch that needs triangles leaves the previous levels and offers to triangulate; the message goes once resolved', async ({
  app,
}) => {
  await app.open();
  await app.load('cube.off', CUBE);
  await app.subdivide();
  await app.byTestId('controls.scheme').selectOption('loop');
  await expect(app.errorBanner).toBeVisible();
  await expect(app.byTestId('error.message')).toContainText('triangles');
  const state = await app.idle();
  expect(state).toMatchObject({ scheme: 'catmull-clark', level: 1, levelCount: 2 });
  await expect(app.byTestId('controls.scheme')).toHaveValue('catmull-clark');
  expect((await app.facts()).faces).toBe(24);
  await test.step('Triangulate and switch: Loop at level 1 of the triangulated cube', async () => {
    await app.byTestId('error.action').click();
    await expect.poll(async () => (await app.state()).scheme).toBe('loop');
    expect(await app.idle()).toMatchObject({ level: 1, triangulate: true, lastError: null });
    // 12 triangles, each split in 4.
    expect(await app.facts()).toMatchObject({ vertices: 26, edges: 72, faces: 48 });
    await expect(app.errorBanner).toBeHidden();
  });
});

test('a step error goes once what caused it is resolved', async ({ app }) => {
  await app.open();
  await app.load('cube.off', CUBE);
  await app.chooseScheme('loop');
  await app.byTestId('controls.subdivide').click();
  await expect(app.byTestId('error.message')).toContainText('triangles');
  expect(await app.idle()).toMatchObject({ level: 0, levelCount: 1 });
  // Ticking Triangulate first resolves it: the message goes before the next step.
  await app.byTestId('controls.triangulate').check();
  await expect(app.errorBanner).toBeHidden();
  await app.subdivide();
  expect((await app.facts()).faces).toBe(48);
});

test('a long switch shows its progress and can be cancelled: the previous scheme and levels stay', async ({ app }) => {
  test.setTimeout(120_000);
  await app.open();
  // 250 000 quads: Catmull-Clark level 2 (4 M quads); Doo-Sabin's levels 1 and 2 take seconds.
  await app.load('grid-500.off', quadGridOff(500));
  await app.subdivide();
  await app.subdivide();
  expect((await app.facts()).faces).toBe(4_000_000);
  // What the progress box and the menu said meanwhile, recorded in the page, and Cancel pressed
  // the moment the box shows (the switch takes about a second: a click from outside can miss it).
  await app.page.evaluate(() => {
    const seen: string[] = [];
    (window as unknown as { seen: string[] }).seen = seen;
    const box = document.querySelector<HTMLElement>('[data-testid="progress"]');
    const label = document.querySelector('[data-testid="progress.label"]');
    const cancel = document.querySelector<HTMLButtonElement>('[data-testid="progress.cancel"]');
    const menu = document.querySelector<HTMLSelectElement>('[data-testid="controls.scheme"]');
    if (!box || !label || !cancel || !menu) throw new Error('no progress box or scheme menu');
    const observer = new MutationObserver(() => {
      if (box.hidden) return;
      seen.push(`${label.textContent} (menu: ${menu.value})`);
      observer.disconnect();
      cancel.click();
    });
    observer.observe(box, { attributes: true, attributeFilter: ['hidden'] });
  });
  await app.byTestId('controls.scheme').selectOption('doo-sabin');
  await expect.poll(() => app.page.evaluate(() => (window as unknown as { seen: string[] }).seen.length)).toBe(1);
  await expect(app.byTestId('progress')).toBeHidden();
  const seen = await app.page.evaluate(() => (window as unknown as { seen: string[] }).seen);
  expect(seen[0]).toMatch(/^Doo-Sabin: level [12] of 2… \(menu: doo-sabin\)$/);
  expect(await app.idle()).toMatchObject({ scheme: 'catmull-clark', level: 2, levelCount: 3, lastError: null });
  await expect(app.byTestId('controls.scheme')).toHaveValue('catmull-clark');
  expect((await app.facts()).faces).toBe(4_000_000);
  await test.step('the levels kept are still there', async () => {
    await app.scrubTo(1);
    expect((await app.facts()).faces).toBe(1_000_000);
  });
});

test('the teaching samples, and the counts of every level in a table with thousands separators', async ({ app }) => {
  await app.open();
  await app.openSample('triacontahedron', 'triacontahedron.off');
  expect(await app.facts()).toMatchObject({ vertices: 32, edges: 60, faces: 30, faceTypes: '30 quads' });
  for (let k = 0; k < 3; k++) await app.subdivide();
  // 30 · 4³ quads; V = F + 2 on a closed genus-0 quad mesh (E = 2F).
  await expect(app.byTestId('facts.faces')).toHaveText('1,920');
  await expect(app.byTestId('facts.vertices')).toHaveText('1,922');
  const rows = app.byTestId('levels.table').locator('tbody tr');
  await expect(rows).toHaveText([
    /^0\s*32\s*60\s*30\s*–$/,
    /^1\s*122\s*240\s*120\s*×4$/,
    /^2\s*482\s*960\s*480\s*×4$/,
    /^3\s*1,922\s*3,840\s*1,920\s*×4$/,
  ]);
  await expect(app.byTestId('levels.row.3')).toHaveAttribute('aria-current', 'true');
  await app.snapshot('scheme-switch-level-table');
  await app.scrubTo(1);
  await expect(app.byTestId('levels.row.1')).toHaveAttribute('aria-current', 'true');
  await expect(app.byTestId('levels.row.3')).not.toHaveAttribute('aria-current', 'true');
  await test.step('the pentagonal tower and the saddle', async () => {
    await app.openSample('pentagonal-tower', 'pentagonal-tower.off');
    expect(await app.facts()).toMatchObject({ faces: 11, faceTypes: '5 triangles, 5 quads, 1 other polygon' });
    await expect(app.byTestId('facts.face-types')).toHaveAttribute('title', /by their number of sides/);
    await app.openSample('saddle', 'saddle.off');
    expect(await app.facts()).toMatchObject({ vertices: 25, faces: 16, boundaries: 1 });
  });
});
