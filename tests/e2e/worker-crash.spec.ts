/**
 * The core's worker crashes (forced through the test hook, crashForTest):
 * the app says what happened, starts a new worker, keeps the levels it
 * shows, and the next action works.
 */
import { readFileSync } from 'node:fs';
import { expect, test } from './fixtures';

const CUBE = readFileSync('public/meshes/cube.off', 'utf8');

test('a WebAssembly trap during a step: the app says so, keeps levels 0–2, and the next step makes level 3', async ({
  app,
}) => {
  await app.open();
  await app.load('cube.off', CUBE);
  await app.subdivide();
  await app.subdivide();
  const level2 = await app.positions();
  expect(level2.length).toBe(3 * 98);
  expect((await app.page.evaluate(() => window.__subdivlab?.coreMemory()))?.keptLevels).toBe(3);

  await app.page.evaluate(() => window.__subdivlab?.crashCore('trap', 'subdivide'));
  await app.byTestId('controls.subdivide').click();
  await expect(app.errorBanner).toContainText(
    'SubdivLab core: stopped unexpectedly while subdividing (RuntimeError: unreachable). ' +
      'A new one was started; the levels already shown are kept.',
  );
  expect(await app.idle()).toMatchObject({ busy: false, level: 2, levelCount: 3 });
  expect((await app.facts()).faces).toBe(96);
  // A new worker: it keeps none of the old one's levels until one is used.
  expect((await app.page.evaluate(() => window.__subdivlab?.coreMemory()))?.keptLevels).toBe(0);

  await test.step('the shown level reads back as it was (made again in the new worker)', async () => {
    expect(await app.positions()).toEqual(level2);
  });
  await test.step('the next step works, and the message goes', async () => {
    await app.subdivide();
    expect((await app.facts()).faces).toBe(384);
    await expect(app.errorBanner).toBeHidden();
    // Levels 0–2 made again one step at a time, and level 3.
    expect((await app.page.evaluate(() => window.__subdivlab?.coreMemory()))?.keptLevels).toBe(4);
  });
  await test.step('scrubbing back shows level 1 as before', async () => {
    await app.scrubTo(1);
    expect((await app.facts()).faces).toBe(24);
  });
});

test('an uncaught error in the idle worker: said once, and export and steps go on from the shown level', async ({
  app,
}) => {
  await app.open();
  await app.load('cube.off', CUBE);
  await app.subdivide();
  await app.page.evaluate(() => window.__subdivlab?.crashCore('uncaught'));
  await expect(app.errorBanner).toContainText(
    'SubdivLab core: stopped unexpectedly while running a crash test (Uncaught Error: uncaught error raised by crashForTest).',
  );
  expect(await app.idle()).toMatchObject({ busy: false, level: 1, levelCount: 2 });
  await test.step('the level exports from the new worker', async () => {
    await app.byTestId('export-panel').locator('summary').click();
    const off = readFileSync(await (await app.download('export.off')).path(), 'utf8');
    expect(off.split('\n', 3)[2]).toBe('26 24 0');
  });
  await test.step('and the next step starts from it', async () => {
    await app.subdivide();
    expect((await app.facts()).faces).toBe(96);
  });
});
