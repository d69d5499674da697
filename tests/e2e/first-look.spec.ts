/**
 * The first visit's polygon edges and cage are a default, not a choice: a
 * model opened after it gets the look that suits its size (web/app/first-look.ts),
 * until the user picks a render mode or the cage; a link's display is kept.
 */
import { mkdirSync, readFileSync } from 'node:fs';
import { expect, test } from './fixtures';
import type { SubdivLabPage } from './subdivlab-page';

const SHOTS = '/tmp/shots/sight2';
mkdirSync(SHOTS, { recursive: true });

/** CGAL's elephant: 5,558 triangles, a scanned-size model. */
const ELEPHANT = readFileSync('public/meshes/cgal/elephant.off', 'utf8');
const CUBE = readFileSync('public/meshes/cube.off', 'utf8');

/** The render mode and the cage as the state, the menu and the checkbox show them. */
async function look(app: SubdivLabPage): Promise<{ mode: string; cage: boolean }> {
  const state = await app.state();
  await expect(app.byTestId('controls.render-mode')).toHaveValue(state.renderMode);
  if (state.overlays.control) await expect(app.byTestId('controls.overlay-control')).toBeChecked();
  else await expect(app.byTestId('controls.overlay-control')).not.toBeChecked();
  return { mode: state.renderMode, cage: state.overlays.control };
}

test('first visit, then a dropped scan: smooth shading, no cage; then a cube: its edges and cage again', async ({
  app,
}) => {
  test.setTimeout(90_000);
  await app.openFirstVisit();
  expect(await look(app)).toEqual({ mode: 'edges', cage: true });
  const dropped = await app.load('elephant.off', ELEPHANT);
  expect(dropped.facts?.faces).toBe(5558);
  expect(await look(app)).toEqual({ mode: 'smooth', cage: false });
  await expect(app.byTestId('viewer.first-visit')).toBeHidden();
  // The hash says what is shown: the look is written as any display change is.
  await app.waitForHash('mode', 'smooth');
  expect((await app.hashParams()).has('control-mesh')).toBe(false);
  await app.snapshot('first-look-elephant');
  await app.page.screenshot({ path: `${SHOTS}/dropped-scan-first-look.png` });

  await test.step('a small model next: polygon edges and cage, as the first visit showed', async () => {
    await app.load('cube.off', CUBE);
    expect(await look(app)).toEqual({ mode: 'edges', cage: true });
  });
});

test('first visit: a cage or a render mode the user chose stays on the scan and on the next model', async ({ app }) => {
  test.setTimeout(90_000);
  await app.openFirstVisit();
  await app.load('elephant.off', ELEPHANT);
  expect(await look(app)).toEqual({ mode: 'smooth', cage: false });
  await test.step('the user turns the cage on (the C key): the next scan keeps it, its mode still follows the model', async () => {
    await app.page.locator('body').click({ position: { x: 5, y: 5 } });
    await app.page.keyboard.press('c');
    await expect.poll(async () => (await app.state()).overlays.control).toBe(true);
    await app.load('cube.off', CUBE);
    expect(await look(app)).toEqual({ mode: 'edges', cage: true });
    await app.load('elephant-again.off', ELEPHANT);
    expect(await look(app)).toEqual({ mode: 'smooth', cage: true });
  });
  await test.step('the user picks flat shading: the cube keeps it', async () => {
    await app.byTestId('controls.render-mode').selectOption('flat');
    await app.load('cube.off', CUBE);
    expect(await look(app)).toEqual({ mode: 'flat', cage: true });
  });
});

test('first visit: the cage switched off and on again by the user stays on the scan', async ({ app }) => {
  test.setTimeout(90_000);
  await app.openFirstVisit();
  const cage = app.byTestId('controls.overlay-control');
  await cage.uncheck();
  await cage.check();
  await app.load('elephant.off', ELEPHANT);
  expect(await look(app)).toEqual({ mode: 'smooth', cage: true });
});

test('a link asked for edges and the cage: a dropped scan keeps them', async ({ app }) => {
  test.setTimeout(90_000);
  await app.open('#src=meshes/rhombicuboctahedron.off&scheme=catmull-clark&levels=2&mode=edges&control-mesh=1');
  await expect.poll(async () => (await app.state()).level).toBe(2);
  await app.idle();
  expect(await look(app)).toEqual({ mode: 'edges', cage: true });
  await app.load('elephant.off', ELEPHANT);
  expect(await look(app)).toEqual({ mode: 'edges', cage: true });
});
