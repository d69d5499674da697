/**
 * The basis function view: a control vertex picked on the view colours the
 * surface by its influence, with a colour bar and its reach; another level
 * is coloured again as it is shown; turning it off brings the plain surface
 * back.
 */
import { expect, test } from './fixtures';

test('Catmull-Clark on the torus: a control vertex reaches 13 x 13 vertices at level 2, coloured on the surface', async ({
  app,
}) => {
  await app.open();
  await app.openSample('torus', 'torus.off');
  await app.subdivide();
  await app.subdivide();
  const plain = await app.canvasPixels();
  await app.byTestId('basis.toggle').click();
  await expect(app.byTestId('basis.toggle')).toHaveAttribute('aria-pressed', 'true');
  await expect(app.byTestId('controls.overlay-control')).toBeChecked();
  const at = await app.page.evaluate(() => window.__subdivlab?.vertexOnScreen(0) ?? null);
  if (!at) throw new Error('control vertex 0 is not in view');
  await app.page.mouse.click(at.x, at.y);
  // Every torus vertex has valence 4: after two steps a vertex reaches 1.5 control rings,
  // 6 quarter-steps each way.
  await expect(app.byTestId('basis.reach')).toHaveText(
    /^Control vertex 0 reaches 169 of the 768 vertices of level 2 \(largest weight 0\.\d{4}\)\.$/,
  );
  await expect(app.byTestId('basis.legend')).toBeVisible();
  await expect.poll(async () => (await app.canvasPixels()).equals(plain)).toBe(false);
  await app.snapshot('basis-torus-level2');

  await test.step('level 1 is coloured again: 25 vertices', async () => {
    await app.scrubTo(1);
    await expect(app.byTestId('basis.reach')).toHaveText(/reaches 25 of the 192 vertices of level 1/);
  });

  await test.step('by number from the keyboard, and off again', async () => {
    await app.byTestId('basis.vertex').fill('7');
    await app.byTestId('basis.vertex').press('Enter');
    await expect(app.byTestId('basis.reach')).toHaveText(/^Control vertex 7 reaches 25 /);
    await app.byTestId('basis.toggle').click();
    await expect(app.byTestId('basis.legend')).toBeHidden();
    await app.scrubTo(2);
    // The plain surface again (the control-mesh overlay stays on: turn it off to compare).
    await app.page.keyboard.press('c');
    await expect.poll(async () => (await app.canvasPixels()).equals(plain)).toBe(true);
  });
});
