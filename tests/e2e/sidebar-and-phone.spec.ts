/**
 * What a new student meets first: the display controls near the top of the
 * sidebar (few Tab stops away), the teaching tools in one group, skip links
 * as the first Tab stops, and on a phone a tool's panel on screen with the view.
 */
import { mkdirSync } from 'node:fs';
import type { Page } from '@playwright/test';
import { expect, test } from './fixtures';
import type { SubdivLabPage } from './subdivlab-page';

const SHOTS = '/tmp/shots/sight2';
mkdirSync(SHOTS, { recursive: true });

/** What has keyboard focus: its test id, else its tag and text. */
function focused(page: Page): Promise<string> {
  return page.evaluate(() => {
    const e = document.activeElement as HTMLElement | null;
    if (!e || e === document.body) return 'body';
    return e.dataset.testid ?? `${e.tagName.toLowerCase()}:${(e.textContent ?? '').trim().slice(0, 30)}`;
  });
}

/** The first `count` Tab stops from the top of the page, in order. */
async function tabStops(page: Page, count: number): Promise<string[]> {
  await page.evaluate(() => (document.activeElement as HTMLElement | null)?.blur());
  const stops: string[] = [];
  for (let i = 0; i < count; ++i) {
    await page.keyboard.press('Tab');
    stops.push(await focused(page));
  }
  return stops;
}

/** The box of `testId`'s element in CSS pixels of the page. */
async function box(app: SubdivLabPage, testId: string) {
  const b = await app.byTestId(testId).first().boundingBox();
  if (!b) throw new Error(`${testId} has no box`);
  return b;
}

test('first visit: the render mode is Tab stop 14 (was 28), after the skip links, the header, the scheme and levels', async ({
  app,
}) => {
  await app.openFirstVisit();
  const stops = await tabStops(app.page, 40);
  const mode = stops.indexOf('controls.render-mode') + 1;
  test.info().annotations.push({ type: 'tab stops', description: stops.join(', ') });
  // Before: the 28th stop, after every teaching tool's first control.
  expect(mode, stops.join(', ')).toBe(14);
  expect(stops.slice(0, 2)).toEqual(['skip.view', 'skip.controls']);
  // Then the overlays and Fit, before any teaching tool.
  const fit = stops.indexOf('view.fit') + 1;
  const firstTool =
    stops.findIndex((s) => /^(side|creases|stencils|basis|halfedges|split|check|inspect)\./.test(s)) + 1;
  expect(fit).toBeGreaterThan(mode);
  expect(firstTool === 0 || firstTool > fit).toBe(true);
});

test('the sidebar: scheme, levels, display, then the teaching tools under one heading', async ({ app }) => {
  await app.openFirstVisit();
  const order = await app.page.evaluate(() =>
    [...document.querySelectorAll<HTMLElement>('.sidebar > *')].map((e) => e.dataset.testid ?? e.className),
  );
  expect(order.slice(0, 4)).toEqual(['scheme-panel', 'level-panel', 'display-panel', 'tools']);
  const tools = app.byTestId('tools');
  await expect(tools.getByRole('heading', { level: 2 }).first()).toHaveText('Teaching tools');
  const inside = await tools.evaluate((e) =>
    [...e.querySelectorAll<HTMLElement>(':scope > [data-testid]')].map((s) => s.dataset.testid),
  );
  expect(inside.sort()).toEqual(
    [
      'basis-panel',
      'check-panel',
      'crease-panel',
      'halfedge-panel',
      'inspect-panel',
      'rules',
      'side-panel',
      'split-panel',
      'stencil-panel',
    ].sort(),
  );
  // The whole sidebar in one picture: a window as tall as it.
  const sidebar = app.page.locator('.sidebar');
  const height = await sidebar.evaluate((e) => e.scrollHeight);
  await app.page.setViewportSize({ width: 1024, height: height + 60 });
  await sidebar.screenshot({ path: `${SHOTS}/sidebar-1024-whole.png` });
});

test('skip links: the first Tab stop shows "Skip to the view"; Enter puts the keyboard in the view, where arrows turn it', async ({
  app,
}) => {
  await app.openFirstVisit();
  const skipView = app.byTestId('skip.view');
  const skipControls = app.byTestId('skip.controls');
  await test.step('hidden until focused', async () => {
    for (const link of [skipView, skipControls]) {
      const b = await link.boundingBox();
      // Off screen or one pixel: nothing a mouse user sees.
      expect(!b || b.width <= 1 || b.y + b.height <= 0 || b.x + b.width <= 0).toBe(true);
    }
  });
  const hash = await app.page.evaluate(() => window.location.hash);
  await app.page.keyboard.press('Tab');
  await expect(skipView).toBeFocused();
  await expect(skipView).toHaveText('Skip to the view');
  const shown = await skipView.boundingBox();
  expect(shown?.width).toBeGreaterThan(80);
  expect(shown?.x).toBeGreaterThanOrEqual(0);
  expect(shown?.y).toBeGreaterThanOrEqual(0);
  await app.page.screenshot({ path: `${SHOTS}/skip-link-focused.png` });
  await app.page.keyboard.press('Enter');
  await expect(app.byTestId('viewer')).toBeFocused();
  // The link moved focus; it did not write its target into the hash (which holds the app's state).
  expect(await app.page.evaluate(() => window.location.hash)).toBe(hash);
  const before = (await app.state()).view.position;
  await app.page.keyboard.press('ArrowLeft');
  await expect.poll(async () => (await app.state()).view.position).not.toEqual(before);

  await test.step('"Skip to the controls": the next Tab is the scheme menu', async () => {
    // The next Tab stop after "Skip to the view".
    await skipView.focus();
    await app.page.keyboard.press('Tab');
    await expect(skipControls).toBeFocused();
    await expect(skipControls).toHaveText('Skip to the controls');
    await app.page.keyboard.press('Enter');
    expect(await focused(app.page)).toBe('controls');
    await app.page.keyboard.press('Tab');
    await expect(app.byTestId('controls.scheme')).toBeFocused();
  });
});

type Box = { x: number; y: number; width: number; height: number };

/** Taps vertex 7 of level 1 of the cube (its corner (1, 1, 1), facing the camera) on the view; returns the panel's title. */
async function tapVertex(app: SubdivLabPage, canvas: Box) {
  const at = await app.page.evaluate(() => window.__subdivlab?.vertexOnScreen(7, true) ?? null);
  if (!at) throw new Error('vertex 7 is not in view');
  expect(at.y).toBeGreaterThan(canvas.y);
  expect(at.y).toBeLessThan(canvas.y + canvas.height);
  await app.page.touchscreen.tap(at.x, at.y);
  await expect(app.byTestId('stencils.title')).toHaveText('Vertex 7 of level 1');
  return app.byTestId('stencils.title');
}

/** Taps the arrows of level 1's halfedges until one facing the camera is picked; returns the panel's line about it. */
async function tapArrow(app: SubdivLabPage, canvas: Box) {
  for (let h = 0; h < 96; ++h) {
    const at = await app.page.evaluate((i) => window.__subdivlab?.arrowOnScreen(i) ?? null, h);
    if (!at || at.y < canvas.y || at.y > canvas.y + canvas.height) continue;
    await app.page.touchscreen.tap(at.x, at.y);
    const picked = await app.page.evaluate(() => window.__subdivlab?.halfedges().explorer.picked?.h);
    if (picked === h) {
      await expect(app.byTestId('halfedges.picked')).toContainText(`Halfedge ${h}:`);
      return app.byTestId('halfedges.picked');
    }
  }
  throw new Error('no arrow of the cube could be tapped');
}

test.describe('a phone (390×844, touch)', () => {
  test.use({ viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true });

  for (const tool of [
    { button: 'stencils.inspect', panel: 'stencil-panel', shot: 'phone-stencils', pick: tapVertex },
    { button: 'halfedges.explore', panel: 'halfedge-panel', shot: 'phone-halfedges', pick: tapArrow },
  ]) {
    test(`${tool.panel}: the tool's panel and the view are on screen together, and a tap on the view picks`, async ({
      app,
    }) => {
      await app.open();
      await app.openSample('cube', 'cube.off');
      await app.subdivide();
      await app.byTestId(tool.button).tap();
      await expect(app.byTestId(tool.button)).toHaveAttribute('aria-pressed', 'true');
      const canvas = await box(app, 'viewer');
      const panel = await box(app, tool.panel);
      test.info().annotations.push({ type: 'boxes', description: JSON.stringify({ canvas, panel }) });
      // The view: whole, on screen, the width of the phone and a good part of its height.
      expect(canvas.y).toBeGreaterThanOrEqual(0);
      expect(canvas.y + canvas.height).toBeLessThanOrEqual(844);
      expect(canvas.width).toBe(390);
      expect(canvas.height).toBeGreaterThanOrEqual(300);
      // The panel: below the view (not under it), its top 150 px or more on screen.
      expect(panel.y).toBeGreaterThanOrEqual(canvas.y + canvas.height - 1);
      expect(panel.y).toBeLessThanOrEqual(844 - 150);
      // A tap on the view picks what the tool shows in its panel.
      const shown = await tool.pick(app, canvas);
      await expect(shown).toBeInViewport();
      await app.page.screenshot({ path: `${SHOTS}/${tool.shot}-390x844.png` });
    });
  }
});

test('a tool on a laptop-sized window (1024×700): the view beside the sidebar, the panel in view', async ({ app }) => {
  await app.open();
  await app.openSample('cube', 'cube.off');
  await app.subdivide();
  await app.byTestId('stencils.inspect').click();
  const at = await app.page.evaluate(() => window.__subdivlab?.vertexOnScreen(7, true) ?? null);
  if (!at) throw new Error('vertex 7 is not in view');
  await app.page.mouse.click(at.x, at.y);
  await expect(app.byTestId('stencils.title')).toHaveText('Vertex 7 of level 1');
  await expect(app.byTestId('stencils.title')).toBeInViewport();
  const canvas = await box(app, 'viewer');
  expect(canvas.width).toBeGreaterThan(600);
  expect(canvas.height).toBeGreaterThan(550);
  await app.page.screenshot({ path: `${SHOTS}/laptop-stencils-1024x700.png` });
});

test('a tool turned on with its key (W, M): its panel scrolls into view in the sidebar', async ({ app }) => {
  await app.open();
  await app.openSample('cube', 'cube.off');
  await app.subdivide();
  // Below Display, out of a 700 px window's sidebar.
  await expect(app.byTestId('stencil-panel')).not.toBeInViewport();
  await app.page.locator('body').click({ position: { x: 5, y: 5 } });
  await app.page.keyboard.press('w');
  await expect(app.byTestId('stencils.inspect')).toHaveAttribute('aria-pressed', 'true');
  await expect(app.byTestId('stencil-panel')).toBeInViewport({ ratio: 1 });
  await app.byTestId('controls').evaluate((e) => e.scrollTo({ top: 0 }));
  await expect(app.byTestId('crease-panel')).not.toBeInViewport();
  await app.page.keyboard.press('m');
  await expect(app.byTestId('creases.edit')).toHaveAttribute('aria-pressed', 'true');
  await expect(app.byTestId('crease-panel')).toBeInViewport({ ratio: 1 });
});
