/**
 * The rest of the user's day: samples, ?src=, the large-step question, a
 * long step with progress and Cancel, the camera, saved views, shortcuts,
 * the clipboard, accessibility and the layout on a laptop and a tablet.
 */
import { readFileSync } from 'node:fs';
import { expect, test } from './fixtures';
import { quadGridOff } from './helpers';

const CUBE = readFileSync('public/meshes/cube.off', 'utf8');

test('the gallery opens sample meshes', async ({ app }) => {
  await app.open();
  const pick = async (id: string, name: string) => {
    await app.byTestId('gallery').locator('summary').click();
    await app.byTestId(`gallery.${id}`).click();
    await expect(app.byTestId('facts.model')).toHaveText(name);
    await app.idle();
    return app.facts();
  };
  expect(await pick('rhombicuboctahedron', 'rhombicuboctahedron.off')).toMatchObject({
    vertices: 24,
    edges: 48,
    faces: 26,
    genus: 0,
    faceTypes: '8 triangles, 18 quads',
  });
  expect(await pick('open-grid', 'open-grid.off')).toMatchObject({ vertices: 16, faces: 9, boundaries: 1 });
  expect(await pick('torus', 'torus.off')).toMatchObject({ genus: 1, boundaries: 0, components: 1 });
  expect(await pick('cube-creased', 'cube-creased.obj')).toMatchObject({ vertices: 8, faces: 6 });
  await expect(app.byTestId('facts.tags')).toHaveText('6 creases, 1 corner');
  const grid = await pick('open-grid', 'open-grid.off');
  // Catmull-Clark on the open 3×3 grid: a 6×6 grid, then 12×12.
  await app.subdivide();
  expect(await app.facts()).toMatchObject({ vertices: 49, edges: 84, faces: 36, boundaries: grid.boundaries });
  await app.subdivide();
  expect(await app.facts()).toMatchObject({ vertices: 169, edges: 312, faces: 144, boundaries: 1 });
});

test('quad-triangle on the rhombicuboctahedron from the gallery', async ({ app }) => {
  await app.open();
  await app.byTestId('gallery').locator('summary').click();
  await app.byTestId('gallery.rhombicuboctahedron').click();
  await expect(app.byTestId('facts.model')).toHaveText('rhombicuboctahedron.off');
  // At level 0 every one of the 48 edges is a control edge.
  await expect(app.byTestId('facts.control-edges')).toHaveText('48');
  await app.chooseScheme('quad-triangle');
  await expect(app.byTestId('controls.scheme-description')).toContainText('triangles and quads');
  await app.subdivide();
  // Triangles split 1→4 at edge midpoints, quads 1→4 around a centre: V + E + Q vertices,
  // 2E + 3T + 4Q edges, 4T triangles and 4Q quads.
  expect(await app.facts()).toMatchObject({
    vertices: 24 + 48 + 18,
    edges: 2 * 48 + 3 * 8 + 4 * 18,
    faces: 104,
    genus: 0,
    faceTypes: '32 triangles, 72 quads',
  });
  await expect(app.byTestId('facts.control-edges')).toHaveText('96');
  // Doo-Sabin is dual: no edge of its result lies on a control edge.
  await app.byTestId('controls.reset').click();
  await app.chooseScheme('doo-sabin');
  await app.subdivide();
  expect((await app.facts()).faces).toBe(24 + 48 + 26);
  await expect(app.byTestId('facts.control-edges')).toHaveText('–');
});

test('Open… and the O key open the file picker', async ({ app }) => {
  await app.open();
  const [chooser] = await Promise.all([app.page.waitForEvent('filechooser'), app.byTestId('open.button').click()]);
  await chooser.setFiles({ name: 'cube.off', mimeType: 'text/plain', buffer: Buffer.from(CUBE) });
  await expect(app.byTestId('facts.model')).toHaveText('cube.off');
  expect((await app.facts()).faces).toBe(6);
  const [again] = await Promise.all([app.page.waitForEvent('filechooser'), app.page.keyboard.press('o')]);
  await again.setFiles('public/meshes/icosahedron.off');
  await expect(app.byTestId('facts.model')).toHaveText('icosahedron.off');
  expect(await app.facts()).toMatchObject({ vertices: 12, edges: 30, faces: 20 });
});

test('?src= loads http(s) URLs and refuses other schemes with a message', async ({ app }) => {
  await test.step('relative http URL', async () => {
    await app.open('?src=meshes/octahedron.off');
    await expect(app.byTestId('facts.model')).toHaveText('octahedron.off');
    expect(await app.facts()).toMatchObject({ vertices: 6, edges: 12, faces: 8, faceTypes: '8 triangles' });
  });
  for (const src of ['file:///etc/passwd', 'javascript:alert(1)']) {
    await test.step(src, async () => {
      await app.open(`?src=${encodeURIComponent(src)}`);
      await expect(app.errorBanner).toBeVisible();
      await expect(app.byTestId('error.source')).toHaveText(`${src}: `);
      await expect(app.byTestId('error.message')).toContainText('Only http and https URLs');
      expect((await app.state()).levelCount).toBe(0);
    });
  }
});

test('a step over the memory budget asks first, in the page', async ({ app }) => {
  await app.open();
  await app.load('cube.off', CUBE);
  await app.page.evaluate(() => window.__subdivlab?.setMemoryBudget(1000));
  await app.byTestId('controls.subdivide').click();
  const dialog = app.byTestId('confirm.dialog');
  await expect(dialog).toBeVisible();
  await expect(app.byTestId('confirm.message')).toContainText('level 1 would have 26 vertices and 24 faces');
  await app.byTestId('confirm.cancel').click();
  await expect(dialog).toBeHidden();
  expect(await app.state()).toMatchObject({ level: 0, levelCount: 1 });

  await app.byTestId('controls.subdivide').click();
  await app.byTestId('confirm.ok').click();
  await expect.poll(async () => (await app.state()).level).toBe(1);
  expect((await app.facts()).faces).toBe(24);
});

test('a long step shows progress, keeps the page responsive and can be cancelled', async ({ app }) => {
  test.setTimeout(120_000);
  await app.open();
  // 1 000 000 quads: Catmull-Clark level 1 (4 M quads) and its render buffers take half a second or more in
  // WebAssembly, which may end before a click from Playwright: the page presses Cancel the moment the box shows.
  await app.load('grid-1000.off', quadGridOff(1000));
  const cancelled = await app.cancelWhenProgressShows();
  await app.byTestId('controls.subdivide').click();
  const seen = await cancelled();
  expect(seen.label).toBe('Subdividing to level 1…');
  // The main thread answers while the worker computes (a frame's upload of level 0 may come first).
  expect(seen.busy).toBe(true);
  expect(seen.lateMs).toBeLessThan(250);
  await expect(app.byTestId('progress')).toBeHidden();
  const state = await app.state();
  expect(state).toMatchObject({ busy: false, level: 0, levelCount: 1, modelName: 'grid-1000.off' });
  expect((await app.facts()).faces).toBe(1_000_000);
  await test.step('a fresh worker takes over', async () => {
    await app.load('cube.off', CUBE);
    await app.subdivide();
    expect((await app.facts()).faces).toBe(24);
  });
});

test('after a cancelled step the worker restarts without the levels it kept: they are restored on use', async ({
  app,
}) => {
  test.setTimeout(120_000);
  await app.open();
  // 90 000 quads: level 1 has 360 000, level 2 (cancelled) would have 1 440 000
  // (a step to 640 000 now ends before the progress shows, 200 ms).
  await app.load('grid-300.off', quadGridOff(300));
  await app.subdivide();
  const level1 = await app.positions();
  expect(level1.length).toBe(3 * 601 * 601);
  const cancelled = await app.cancelWhenProgressShows();
  await app.byTestId('controls.subdivide').click();
  await cancelled();
  await expect(app.byTestId('progress')).toBeHidden();
  expect(await app.state()).toMatchObject({ busy: false, level: 1, levelCount: 2 });
  await test.step('the shown level reads back as it was (made again, step by step, in the new worker)', async () => {
    const again = await app.positions();
    expect(again.length).toBe(level1.length);
    expect(again.every((x, i) => x === level1[i])).toBe(true);
  });
  await test.step('it exports', async () => {
    await app.byTestId('export-panel').locator('summary').click();
    const off = readFileSync(await (await app.download('export.off')).path(), 'utf8');
    // Line 2 is the export's comment (model, scheme, level), line 3 the counts.
    expect(off.split('\n', 3)[1]).toMatch(/^# SubdivLab: .*, level 1$/);
    expect(off.split('\n', 3)[2]).toBe(`${601 * 601} 360000 0`);
  });
  await test.step('and the next step starts from it', async () => {
    await app.subdivide();
    expect((await app.facts()).faces).toBe(1_440_000);
  });
});

test('trackball camera, fit, save view and restore view', async ({ app }) => {
  await app.open();
  await app.load('cube.off', CUBE);
  const box = await app.canvas.boundingBox();
  if (!box) throw new Error('no canvas');
  const cx = box.x + box.width / 2;
  const cy = box.y + box.height / 2;
  const fitted = (await app.state()).view;
  const distance = (v: typeof fitted) => Math.hypot(...v.position.map((p, i) => p - v.target[i]));

  await test.step('drag rotates', async () => {
    await app.page.mouse.move(cx, cy);
    await app.page.mouse.down();
    await app.page.mouse.move(cx + 120, cy + 30, { steps: 8 });
    await app.page.mouse.up();
    await expect.poll(async () => (await app.state()).view.position).not.toEqual(fitted.position);
    const rotated = (await app.state()).view;
    expect(rotated.target).toEqual(fitted.target);
    expect(distance(rotated)).toBeCloseTo(distance(fitted), 3);
  });
  await test.step('save the view, load another model, restore', async () => {
    await app.byTestId('view.save').click();
    const saved = (await app.state()).view;
    await app.load('tetrahedron.off', readFileSync('public/meshes/tetrahedron.off', 'utf8'));
    expect((await app.state()).view.position).not.toEqual(saved.position);
    await app.byTestId('view.restore').click();
    const restored = (await app.state()).view;
    for (let i = 0; i < 3; i++) expect(restored.position[i]).toBeCloseTo(saved.position[i], 6);
  });
  await test.step('keyboard camera in the focused view: arrows rotate, + zooms, Shift+arrows pan', async () => {
    await app.byTestId('viewer').focus();
    const before = (await app.state()).view;
    await app.page.keyboard.press('ArrowRight');
    const turned = (await app.state()).view;
    expect(turned.position).not.toEqual(before.position);
    expect(distance(turned)).toBeCloseTo(distance(before), 6);
    await app.page.keyboard.press('+');
    expect(distance((await app.state()).view)).toBeCloseTo(distance(before) / 1.2, 6);
    await app.page.keyboard.press('Shift+ArrowUp');
    expect((await app.state()).view.target).not.toEqual(before.target);
  });
  await test.step('right-drag pans, wheel zooms, F fits', async () => {
    const before = (await app.state()).view;
    await app.page.mouse.move(cx, cy);
    await app.page.mouse.down({ button: 'right' });
    await app.page.mouse.move(cx + 60, cy, { steps: 6 });
    await app.page.mouse.up({ button: 'right' });
    await expect.poll(async () => (await app.state()).view.target).not.toEqual(before.target);
    const panned = (await app.state()).view;
    await app.page.mouse.wheel(0, 400);
    await expect.poll(async () => distance((await app.state()).view)).not.toBeCloseTo(distance(panned), 3);
    await app.page.keyboard.press('f');
    await expect
      .poll(async () => (await app.state()).view.target.map((t) => Math.abs(t) < 1e-9))
      .toEqual([true, true, true]);
  });
});

test('keyboard: shortcuts, every control reachable with Tab and named', async ({ app }) => {
  await app.open();
  await app.load('cube.off', CUBE);
  await test.step('s subdivides, [ and ] scrub, c toggles the control mesh', async () => {
    await app.page.keyboard.press('s');
    await expect.poll(async () => (await app.state()).level).toBe(1);
    await app.page.keyboard.press('s');
    await expect.poll(async () => (await app.state()).level).toBe(2);
    await app.page.keyboard.press('[');
    expect((await app.state()).level).toBe(1);
    await app.page.keyboard.press(']');
    expect((await app.state()).level).toBe(2);
    await app.page.keyboard.press('c');
    expect((await app.state()).overlays.control).toBe(true);
  });
  await test.step('Tab reaches the controls', async () => {
    const reached = new Set<string>();
    await app.page.locator('body').focus();
    // The view comes after the header and the sidebar (its skip link is the first stop).
    for (let i = 0; i < 50; i++) {
      await app.page.keyboard.press('Tab');
      const id = await app.page.evaluate(
        () =>
          (document.activeElement as HTMLElement | null)?.dataset.testid ??
          document.activeElement?.parentElement?.dataset.testid,
      );
      if (id) reached.add(id);
    }
    for (const id of [
      'viewer',
      'open.button',
      'gallery',
      'export-panel',
      'controls.scheme',
      'controls.subdivide',
      'controls.reset',
      'controls.level',
      'controls.render-mode',
      'controls.overlay-control',
      'controls.overlay-bbox',
      'view.fit',
      'view.save',
    ]) {
      expect(reached, id).toContain(id);
    }
  });
  await test.step('every visible control has an accessible name', async () => {
    const controls = app.page.locator('button:visible, select:visible, input:visible, summary:visible');
    const count = await controls.count();
    expect(count).toBeGreaterThan(10);
    for (let i = 0; i < count; i++) await expect(controls.nth(i)).toHaveAccessibleName(/\S/);
  });
});

test('keyboard: a sample chosen from the Samples menu hands focus back to the menu', async ({ app }) => {
  await app.open();
  const menu = app.byTestId('gallery').locator('summary');
  await menu.focus();
  await app.page.keyboard.press('Enter');
  await expect(app.byTestId('gallery.cube')).toBeVisible();
  await app.page.keyboard.press('Tab');
  await expect(app.byTestId('gallery.cube')).toBeFocused();
  await app.page.keyboard.press('Enter');
  await expect(app.byTestId('facts.model')).toHaveText('cube.off');
  await expect(app.byTestId('gallery.cube')).toBeHidden();
  // Not lost on <body>: the next Tab goes on from the menu, Enter opens it again.
  await expect(menu).toBeFocused();
  await app.page.keyboard.press('Enter');
  await expect(app.byTestId('gallery.tetrahedron')).toBeVisible();
  await app.page.keyboard.press('Escape');
  await test.step('the Export menu too', async () => {
    const exportMenu = app.byTestId('export-panel').locator('summary');
    await exportMenu.focus();
    await app.page.keyboard.press('Enter');
    await app.byTestId('export.off').focus();
    const [download] = await Promise.all([app.page.waitForEvent('download'), app.page.keyboard.press('Enter')]);
    expect(download.suggestedFilename()).toBe('cube-catmull-clark-L0.off');
    await expect(exportMenu).toBeFocused();
  });
});

test('Ctrl+C copies the view as a PNG image', async ({ app, context }) => {
  await context.grantPermissions(['clipboard-read', 'clipboard-write']);
  await app.open();
  await app.load('cube.off', CUBE);
  await app.canvas.click();
  await app.page.keyboard.press('Control+c');
  // The copy is asynchronous (encode, then write): wait until the clipboard holds the image.
  const clipboardTypes = () =>
    app.page.evaluate(async () => (await navigator.clipboard.read()).flatMap((item) => [...item.types]));
  await expect.poll(clipboardTypes).toContain('image/png');
  const head = await app.page.evaluate(async () => {
    const items = await navigator.clipboard.read();
    const blob = await items[0].getType('image/png');
    return [...new Uint8Array(await blob.slice(0, 4).arrayBuffer())];
  });
  expect(head).toEqual([0x89, 0x50, 0x4e, 0x47]);
  expect((await app.state()).lastError).toBeNull();
});

for (const [device, viewport] of [
  ['laptop', { width: 1024, height: 768 }],
  ['tablet', { width: 768, height: 1024 }],
] as const) {
  test(`layout on a ${device} (${viewport.width}×${viewport.height})`, async ({ app }) => {
    await app.page.setViewportSize(viewport);
    await app.open();
    await app.load('cube.off', CUBE);
    const canvas = await app.canvas.boundingBox();
    expect(canvas?.width).toBeGreaterThan(500);
    expect(canvas?.height).toBeGreaterThan(400);
    // Nothing sticks out sideways.
    const overflow = await app.page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
    expect(overflow).toBeLessThanOrEqual(0);
    await expect(app.byTestId('controls.subdivide')).toBeInViewport();
    await test.step('the panels sit one below the other without empty gaps', async () => {
      const gaps = await app.page.evaluate(() => {
        const boxes = [...document.querySelectorAll<HTMLElement>('.sidebar > *')]
          .filter((e) => e.offsetParent !== null)
          .map((e) => e.getBoundingClientRect());
        // For each panel, the distance up to the nearest panel above it in the same column.
        return boxes.map((b) => {
          const above = boxes.filter((a) => a.bottom <= b.top && a.left < b.right && b.left < a.right);
          return above.length === 0 ? 0 : b.top - Math.max(...above.map((a) => a.bottom));
        });
      });
      expect(gaps.length).toBeGreaterThanOrEqual(4);
      // The sidebar's gap is 8 px.
      for (const gap of gaps) expect(gap).toBeLessThanOrEqual(9);
    });
    await app.snapshot(`05-layout-${device}`);
  });
}

test('keyboard after a choice with the mouse: S subdivides, the menu keeps its value; a step is said to screen readers', async ({
  app,
}) => {
  await app.open();
  await app.load('cube.off', CUBE);
  const scheme = app.byTestId('controls.scheme');
  await test.step('a scheme picked with the mouse, then S: level 1 of that scheme', async () => {
    // The pointer presses the menu (headless Chromium's own popup would take the keys: the
    // press is dispatched), then an option is chosen.
    await scheme.dispatchEvent('pointerdown');
    await scheme.focus();
    await scheme.selectOption('doo-sabin');
    await expect(scheme).toBeFocused();
    await app.page.keyboard.press('s');
    await expect.poll(async () => (await app.state()).level).toBe(1);
    const state = await app.state();
    expect(state.scheme).toBe('doo-sabin');
    await expect(scheme).toHaveValue('doo-sabin');
    // Doo-Sabin on the cube: a face per vertex, edge and face, 8 + 12 + 6 = 26.
    await expect(app.byTestId('controls.level-status')).toHaveText('Level 1: 8 triangles, 18 quads, genus 0');
  });
  await test.step('the same menu reached with Tab keeps its type-ahead: S is not a shortcut there', async () => {
    await scheme.focus();
    await app.page.keyboard.press('Shift+Tab');
    await app.page.keyboard.press('Tab');
    await expect(scheme).toBeFocused();
    await app.page.keyboard.press('s');
    // Nothing was subdivided (no option's label starts with S, so the value stays too).
    await app.page.waitForTimeout(300);
    expect((await app.state()).levelCount).toBe(2);
  });
});

test('a phone (390 × 844): no sideways scrolling, every sample and export item inside the screen and tappable', async ({
  app,
}) => {
  await app.page.setViewportSize({ width: 390, height: 844 });
  await app.open();
  await app.openSample('cube', 'cube.off');
  expect(await app.page.evaluate(() => document.documentElement.scrollWidth)).toBeLessThanOrEqual(390);
  const inside = async (selector: string) => {
    const boxes = await app.page
      .locator(selector)
      .evaluateAll((els) => els.map((e) => e.getBoundingClientRect()).map((r) => [r.left, r.right, r.width]));
    expect(boxes.length).toBeGreaterThan(0);
    for (const [left, right, width] of boxes) {
      expect(width).toBeGreaterThan(0);
      expect(left).toBeGreaterThanOrEqual(0);
      expect(right).toBeLessThanOrEqual(390);
    }
  };
  await app.byTestId('gallery').locator('summary').click();
  await inside('[data-testid^="gallery."]:not([data-testid="gallery"])');
  await app.page.screenshot({ path: 'test-results/screenshots/phone-samples.png' });
  // The last sample, at the menu's far corner, opens.
  await app.byTestId('gallery.holes').click();
  await expect(app.byTestId('facts.model')).toHaveText('holes.off');
  await app.byTestId('export-panel').locator('summary').click();
  await inside('[data-testid^="export."]');
  expect(await app.page.evaluate(() => document.documentElement.scrollWidth)).toBeLessThanOrEqual(390);
});
