/**
 * The stencil inspector as a student uses it: click a vertex of a refined
 * level and read its kind, formula and parents with their weights, the
 * parents marked on the surface with labels; or type a vertex's number.
 * Weights are checked against the published masks, not the app's code.
 */

import { expect, test } from './fixtures';
import type { SubdivLabPage } from './subdivlab-page';

/** Where vertex `v` of the shown level is drawn, in page pixels. */
async function shownVertex(app: SubdivLabPage, v: number): Promise<{ x: number; y: number }> {
  const at = await app.page.evaluate((i) => window.__subdivlab?.vertexOnScreen(i, true) ?? null, v);
  if (!at) throw new Error(`vertex ${v} is not in view`);
  return at;
}

test('Catmull-Clark on the cube: a clicked vertex point shows 5/12, 1/6 and 1/36 with labels on its parents', async ({
  app,
}) => {
  await app.open();
  await app.openSample('cube', 'cube.off');
  await app.subdivide();
  await expect(app.byTestId('stencils.vertex')).toBeHidden();
  await app.page.keyboard.press('w');
  await expect(app.byTestId('stencils.inspect')).toHaveAttribute('aria-pressed', 'true');
  await expect(app.byTestId('stencils.vertex')).toBeVisible();
  // Vertex 7 of level 1 is the cube's corner (1, 1, 1), facing the camera: valence 3.
  const corner = await shownVertex(app, 7);
  await app.page.mouse.click(corner.x, corner.y);
  await expect(app.byTestId('stencils.title')).toHaveText('Vertex 7 of level 1');
  await expect(app.byTestId('stencils.kind')).toHaveText('vertex point of vertex 7, valence 3');
  await expect(app.byTestId('stencils.formula')).toContainText('(Q + 2R + (n - 3) S) / n');
  // Catmull-Clark at valence n = 3: 1 - 7/(4n) = 5/12 itself, 3/(2n^2) = 1/6 each neighbour, 1/(4n^2) = 1/36 each diagonal.
  const weights = await app.byTestId('stencils.parents').locator('tbody td:nth-child(2)').allTextContents();
  expect(weights.sort()).toEqual(['1/36', '1/36', '1/36', '1/6', '1/6', '1/6', '5/12'].sort());
  await expect(app.byTestId('stencils.sum')).toHaveText('Σ w = 1');
  const labels = await app.page.getByTestId('view.stencil-label').allTextContents();
  expect(labels.sort()).toEqual(weights.sort());
  await app.snapshot('stencil-cube-corner');

  await test.step('an edge point by its number, from the keyboard', async () => {
    await app.byTestId('stencils.vertex').fill('8');
    await app.byTestId('stencils.vertex').press('Enter');
    await expect(app.byTestId('stencils.title')).toHaveText('Vertex 8 of level 1');
    await expect(app.byTestId('stencils.kind')).toHaveText(/^edge point of edge \d–\d$/);
    const edge = await app.byTestId('stencils.parents').locator('tbody td:nth-child(2)').allTextContents();
    expect(edge.sort()).toEqual(['1/16', '1/16', '1/16', '1/16', '3/8', '3/8']);
  });

  await test.step('another level drops the inspected vertex; level 0 has no stencils', async () => {
    await app.scrubTo(0);
    await expect(app.byTestId('stencils.details')).toBeHidden();
    await expect(app.page.getByTestId('view.stencil-label')).toHaveCount(0);
    await expect(app.byTestId('stencils.message')).toContainText('Subdivide');
  });
});

test('Loop on the icosahedron: the edge mask 3/8, 1/8 and beta(5) in decimals; M and W take turns', async ({ app }) => {
  await app.open();
  await app.openSample('icosahedron', 'icosahedron.off');
  await app.chooseScheme('loop');
  await app.subdivide();
  await app.byTestId('stencils.inspect').click();
  await app.byTestId('stencils.vertex').fill('0');
  await app.byTestId('stencils.vertex').press('Enter');
  await expect(app.byTestId('stencils.kind')).toHaveText('vertex point of vertex 0, valence 5');
  const beta = (5 / 8 - (3 / 8 + Math.cos((2 * Math.PI) / 5) / 4) ** 2) / 5;
  const weights = await app.byTestId('stencils.parents').locator('tbody td:nth-child(2)').allTextContents();
  expect(weights.sort()).toEqual([(1 - 5 * beta).toFixed(4), ...Array(5).fill(beta.toFixed(4))].sort());
  await app.byTestId('stencils.vertex').fill('12');
  await app.byTestId('stencils.vertex').press('Enter');
  await expect(app.byTestId('stencils.kind')).toHaveText(/^edge point/);
  const edge = await app.byTestId('stencils.parents').locator('tbody td:nth-child(2)').allTextContents();
  expect(edge.sort()).toEqual(['1/8', '1/8', '3/8', '3/8']);
  await app.snapshot('stencil-loop-edge');
  // Crease editing and the inspector share the click: one at a time.
  await app.page.locator('body').click({ position: { x: 5, y: 5 } });
  await app.page.keyboard.press('m');
  await expect(app.byTestId('creases.edit')).toHaveAttribute('aria-pressed', 'true');
  await expect(app.byTestId('stencils.inspect')).toHaveAttribute('aria-pressed', 'false');
  await expect(app.page.getByTestId('view.stencil-label')).toHaveCount(0);
  await app.page.keyboard.press('w');
  await expect(app.byTestId('creases.edit')).toHaveAttribute('aria-pressed', 'false');
  await expect(app.byTestId('stencils.inspect')).toHaveAttribute('aria-pressed', 'true');
});
