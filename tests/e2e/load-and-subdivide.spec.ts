/**
 * Loading meshes, choosing schemes, subdividing to level 2 and scrubbing,
 * and load errors: what a user does first.
 */
import { readFileSync } from 'node:fs';
import { expect, test } from './fixtures';
import { type Counts, expectedClosedCounts, triangulatedQuads } from './helpers';

const CUBE = readFileSync('public/meshes/cube.off', 'utf8');
const TETRAHEDRON = readFileSync('public/meshes/tetrahedron.off', 'utf8');
const CUBE_COUNTS: Counts = { vertices: 8, edges: 12, faces: 6 };
const TETRA_COUNTS: Counts = { vertices: 4, edges: 6, faces: 4 };

test('empty page, drop a cube, facts of level 0', async ({ app }) => {
  await app.open();
  await expect(app.byTestId('viewer.empty')).toBeVisible();
  await app.snapshot('01-empty');
  await app.load('cube.off', CUBE);
  await expect(app.byTestId('viewer.empty')).toBeHidden();
  await expect(app.byTestId('app.model-name')).toHaveText('cube.off');
  expect(await app.facts()).toEqual({
    vertices: 8,
    edges: 12,
    faces: 6,
    components: 1,
    boundaries: 0,
    genus: 0,
    faceTypes: '6 quads',
  });
  await app.snapshot('02-loaded');
});

for (const scheme of ['catmull-clark', 'doo-sabin', 'loop', 'sqrt3']) {
  const needsTriangles = scheme === 'loop' || scheme === 'sqrt3';
  test(`${scheme}: cube to level 2, exact counts, scrub back and forth`, async ({ app }) => {
    await app.open();
    await app.load('cube.off', CUBE);
    await app.chooseScheme(scheme);
    await expect(app.byTestId('controls.scheme-description')).toContainText(
      needsTriangles ? 'Needs triangles' : 'Any polygons',
    );
    if (needsTriangles) {
      await test.step('the scheme says it needs triangles and offers to triangulate', async () => {
        await expect(app.byTestId('controls.triangle-note')).toHaveText(/needs triangles; this mesh has 6 other faces/);
        await app.byTestId('controls.triangulate').check();
      });
    }
    const start = needsTriangles ? triangulatedQuads(CUBE_COUNTS) : CUBE_COUNTS;
    for (const level of [1, 2]) {
      await test.step(`level ${level}`, async () => {
        const state = await app.subdivide();
        const expected = expectedClosedCounts(scheme, start, level);
        const shown = await app.facts();
        expect({ vertices: shown.vertices, edges: shown.edges, faces: shown.faces }).toEqual(expected);
        expect(shown.genus).toBe(0);
        expect(shown.components).toBe(1);
        expect(shown.boundaries).toBe(0);
        expect(state.facts?.faces).toBe(expected.faces);
        await expect(app.byTestId('facts.time')).toHaveText(/^\d+(\.\d)? ms$/);
      });
    }
    await test.step('scrub: levels switch at once, counts follow', async () => {
      // The view draws the level shown, after the steps' draws (the benchmark's "on screen").
      await expect.poll(async () => (await app.state()).drawn?.level).toBe(2);
      const drawnAt = (await app.state()).drawn?.at ?? Number.POSITIVE_INFINITY;
      await app.scrubTo(0);
      expect((await app.facts()).faces).toBe(6);
      await expect(app.byTestId('facts.time')).toHaveText('–');
      await expect.poll(async () => (await app.state()).drawn?.level).toBe(0);
      expect((await app.state()).drawn?.at).toBeGreaterThan(drawnAt);
      await app.scrubTo(1);
      expect((await app.facts()).faces).toBe(expectedClosedCounts(scheme, start, 1).faces);
      await app.scrubTo(2);
      expect((await app.facts()).faces).toBe(expectedClosedCounts(scheme, start, 2).faces);
      await expect(app.byTestId('controls.level-label')).toHaveText('2 / 2');
    });
    if (scheme === 'catmull-clark') {
      // The issue's own figures: cube, Catmull-Clark, level 2.
      expect(await app.facts()).toMatchObject({ vertices: 98, edges: 192, faces: 96, faceTypes: '96 quads' });
    }
  });
}

test('loop and √3 on a triangle mesh need no triangulation', async ({ app }) => {
  await app.open();
  await app.load('tetrahedron.off', TETRAHEDRON);
  for (const scheme of ['loop', 'sqrt3']) {
    await test.step(scheme, async () => {
      // Loop is stepped to level 2; √3, picked there, computes its own levels 1 and 2 at once.
      await app.chooseScheme(scheme);
      await expect(app.byTestId('controls.triangle-note')).toBeHidden();
      if (scheme === 'loop') {
        expect((await app.state()).levelCount).toBe(1);
        await app.subdivide();
        await app.subdivide();
      }
      expect(await app.state()).toMatchObject({ level: 2, levelCount: 3 });
      const shown = await app.facts();
      expect({ vertices: shown.vertices, edges: shown.edges, faces: shown.faces }).toEqual(
        expectedClosedCounts(scheme, TETRA_COUNTS, 2),
      );
    });
  }
});

test('a scheme that needs triangles fails clearly on quads and offers to triangulate', async ({ app }) => {
  await app.open();
  await app.load('cube.off', CUBE);
  await app.chooseScheme('loop');
  await app.byTestId('controls.subdivide').click();
  await expect(app.errorBanner).toBeVisible();
  await expect(app.errorBanner).toHaveAttribute('role', 'alert');
  await expect(app.byTestId('error.message')).toContainText('triangle');
  await expect(app.byTestId('error.source')).toHaveText('cube.off: ');
  expect((await app.state()).level).toBe(0);
  await app.byTestId('error.action').click();
  await expect.poll(async () => (await app.state()).level).toBe(1);
  await expect(app.errorBanner).toBeHidden();
  expect((await app.facts()).faces).toBe(48);
  expect((await app.state()).triangulate).toBe(true);
});

test('reset drops computed levels and their GPU geometry; a new scheme replaces the levels it computes again', async ({
  app,
}) => {
  await app.open();
  await app.load('cube.off', CUBE);
  // Level 0 draws a surface and its edge lines once rendered: that is the baseline.
  await app.byTestId('controls.render-mode').selectOption('edges');
  await app.canvasPixels();
  const baseline = (await app.state()).gpuGeometries;
  await app.subdivide();
  await app.subdivide();
  await app.scrubTo(1);
  await app.canvasPixels();
  expect((await app.state()).gpuGeometries).toBeGreaterThan(baseline);
  await app.byTestId('controls.reset').click();
  await expect.poll(async () => (await app.state()).levelCount).toBe(1);
  expect((await app.facts()).faces).toBe(6);
  await app.canvasPixels();
  expect((await app.state()).gpuGeometries).toBe(baseline);
  await app.subdivide();
  await app.canvasPixels();
  const oneLevel = (await app.state()).gpuGeometries;
  await app.chooseScheme('doo-sabin');
  expect(await app.state()).toMatchObject({ level: 1, levelCount: 2 });
  // Doo-Sabin's level 1 drawn in place of Catmull-Clark's: as many geometries as before.
  await app.canvasPixels();
  expect((await app.state()).gpuGeometries).toBe(oneLevel);
  await test.step('loading another model frees the old one', async () => {
    await app.load('tetrahedron.off', TETRAHEDRON);
    await app.canvasPixels();
    expect((await app.state()).gpuGeometries).toBe(baseline);
  });
});

test('an invalid file shows a message naming it; the previous mesh and levels stay', async ({ app }) => {
  await app.open();
  await app.load('cube.off', CUBE);
  await app.subdivide();
  const before = await app.state();
  await test.step('index out of range', async () => {
    await app.dropFile('broken.off', 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n');
    await expect(app.errorBanner).toBeVisible();
    await expect(app.byTestId('error.source')).toHaveText('broken.off: ');
    await expect(app.byTestId('error.message')).toHaveText(/line 6.*out of range/);
  });
  const after = await app.idle();
  expect(after.modelName).toBe('cube.off');
  expect(after.level).toBe(before.level);
  expect(after.levelCount).toBe(before.levelCount);
  expect(after.facts).toEqual(before.facts);
  expect(after.lastError).toMatchObject({ source: 'broken.off', code: 'invalid_mesh' });
  await expect(app.byTestId('facts.model')).toHaveText('cube.off');
  await app.snapshot('04-error');

  await test.step('a file name with markup is shown as text', async () => {
    const name = '<img src=x onerror="window.__pwned=1">.off';
    await app.dropFile(name, 'OFF\nnot numbers\n');
    await expect(app.byTestId('error.source')).toHaveText(`${name}: `);
    expect(await app.errorBanner.locator('img').count()).toBe(0);
    expect(await app.page.evaluate(() => (window as unknown as { __pwned?: number }).__pwned)).toBeUndefined();
  });

  await test.step('a file that is no mesh format', async () => {
    await app.dropFile('notes.txt', 'just some words\n');
    await expect(app.byTestId('error.message')).toContainText(
      'This is not a mesh file: no OFF, OBJ, PLY or STL header or statement at its start.',
    );
  });

  await test.step('loading a good file clears the message', async () => {
    await app.load('tetrahedron.off', TETRAHEDRON);
    await expect(app.errorBanner).toBeHidden();
    expect((await app.facts()).faces).toBe(4);
  });
});

test('OBJ files load too (quads and n-gons stay polygons)', async ({ app }) => {
  await app.open();
  const obj = readFileSync('tests/fixtures/cube.obj', 'utf8');
  await app.load('cube.obj', obj);
  expect(await app.facts()).toMatchObject({ vertices: 8, edges: 12, faces: 6, faceTypes: '6 quads' });
});
