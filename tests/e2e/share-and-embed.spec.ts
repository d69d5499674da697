/**
 * Shareable state (issue 7): the URL hash keeps model, scheme, level,
 * display and camera; Share copies the link, Embed… gives an element and an
 * iframe snippet; a local file cannot be linked; a first visit opens a sample.
 */
import type { Frame, Page } from '@playwright/test';
import type { SubdivLabTestState } from '../../web/app/test-api';
import { expect, test } from './fixtures';
import { type Counts, expectedClosedCounts } from './helpers';
import { SubdivLabPage } from './subdivlab-page';

const CUBE: Counts = { vertices: 8, edges: 12, faces: 6 };
const RHOMBI: Counts = { vertices: 24, edges: 48, faces: 26 };
const ICOSA: Counts = { vertices: 12, edges: 30, faces: 20 };
const OCTA: Counts = { vertices: 6, edges: 12, faces: 8 };

type View = SubdivLabTestState['view'];

function expectSameView(actual: View, expected: View): void {
  for (const key of ['position', 'target', 'up'] as const) {
    actual[key].forEach((x, i) => {
      expect(Math.abs(x - expected[key][i]), `${key}[${i}]: ${x} vs ${expected[key][i]}`).toBeLessThan(1e-3);
    });
  }
}

function countsOf(state: SubdivLabTestState): Counts {
  return { vertices: state.facts?.vertices ?? -1, edges: state.facts?.edges ?? -1, faces: state.facts?.faces ?? -1 };
}

/** Waits until the app shows `level` with nothing running. */
async function atLevel(app: SubdivLabPage, level: number): Promise<SubdivLabTestState> {
  await app.page.waitForFunction(
    (k) => {
      const s = window.__subdivlab?.state();
      return s?.ready === true && !s.busy && s.level === k && s.levelCount > k;
    },
    level,
    { timeout: 30_000 },
  );
  return app.state();
}

/** Turns the camera with the arrow keys (the 3D view focused), as a user would. */
async function turnCamera(app: SubdivLabPage): Promise<void> {
  await app.byTestId('viewer').focus();
  for (const key of ['ArrowLeft', 'ArrowLeft', 'ArrowUp', '+']) await app.page.keyboard.press(key);
}

/** Console errors of a second page (the fixture watches the first one). */
function watchErrors(page: Page): string[] {
  const errors: string[] = [];
  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(m.text());
  });
  page.on('pageerror', (e) => errors.push(`page error: ${e.message}`));
  return errors;
}

test('first visit: a sample after two Catmull-Clark steps, with a line on opening your own file', async ({ app }) => {
  await app.page.addInitScript(() => {
    (window as unknown as { __historyAtLoad: number }).__historyAtLoad = history.length;
  });
  const state = await app.openFirstVisit();
  expect(state).toMatchObject({
    modelName: 'rhombicuboctahedron.off',
    scheme: 'catmull-clark',
    level: 2,
    levelCount: 3,
    renderMode: 'edges',
    overlays: { control: true, curves: false, bbox: false },
    lastError: null,
    notice: null,
  });
  expect(countsOf(state)).toEqual(expectedClosedCounts('catmull-clark', RHOMBI, 2));
  expect(await app.facts()).toMatchObject({ vertices: 386, edges: 768, faces: 384, faceTypes: '384 quads', genus: 0 });
  const hint = app.byTestId('viewer.first-visit');
  await expect(hint).toHaveText(
    'A sample to start with: drop your own OFF, OBJ, PLY or STL file anywhere (or use Open…).',
  );
  await test.step('the hint is one line at 1024 px', async () => {
    const { height, lineHeight } = await hint.evaluate((e) => ({
      height: e.clientHeight - Number.parseFloat(getComputedStyle(e).paddingTop) * 2,
      lineHeight: Number.parseFloat(getComputedStyle(e).lineHeight) || 20,
    }));
    expect(height).toBeLessThan(1.5 * lineHeight);
  });
  await expect(app.byTestId('viewer.empty')).toBeHidden();
  await expect(app.byTestId('app.examples')).toHaveAttribute('href', 'examples/');
  await test.step('the first visit is written into the hash, replacing the entry (no empty page to go back to)', async () => {
    await app.waitForHash('src', 'meshes/rhombicuboctahedron.off');
    expect(Object.fromEntries(await app.hashParams())).toMatchObject({
      scheme: 'catmull-clark',
      levels: '2',
      mode: 'edges',
      'control-mesh': '1',
    });
    expect(await app.page.evaluate(() => history.length)).toBe(
      await app.page.evaluate(() => (window as unknown as { __historyAtLoad: number }).__historyAtLoad),
    );
  });
  await app.snapshot('share-01-first-visit');
  await test.step('opening your own file hides the line', async () => {
    await app.dropPath('public/meshes/cube.off');
    await expect(app.byTestId('facts.model')).toHaveText('cube.off');
    await expect(app.byTestId('viewer.first-visit')).toBeHidden();
  });
});

test('Share copies a link that reproduces model, scheme, level, counts, display and camera in a new page', async ({
  app,
  context,
}) => {
  await context.grantPermissions(['clipboard-read', 'clipboard-write']);
  await app.open();
  await app.openSample('cube', 'cube.off');
  await app.chooseScheme('doo-sabin');
  await app.subdivide();
  await app.subdivide();
  await app.byTestId('controls.render-mode').selectOption('flat');
  await app.byTestId('controls.overlay-control').check();
  await app.byTestId('controls.overlay-bbox').check();
  await turnCamera(app);
  const before = await app.idle();
  await app.byTestId('share.button').click();
  await expect(app.byTestId('share.status')).toHaveText('Link copied.');
  const link = await app.page.evaluate(() => navigator.clipboard.readText());
  expect(link).toBe(await app.page.evaluate(() => window.__subdivlab?.shareLink()));
  const url = new URL(link);
  expect(`${url.origin}${url.pathname}`).toBe(new URL('./', app.page.url()).href);
  const hash = new URLSearchParams(url.hash.slice(1));
  expect(Object.fromEntries(hash)).toMatchObject({
    src: 'meshes/cube.off',
    scheme: 'doo-sabin',
    levels: '2',
    mode: 'flat',
    'control-mesh': '1',
    bbox: '1',
  });
  expect(hash.has('control-edges')).toBe(false);

  const other = new SubdivLabPage(await context.newPage());
  const errors = watchErrors(other.page);
  await other.page.goto(link);
  const after = await atLevel(other, 2);
  expect(after).toMatchObject({
    modelName: 'cube.off',
    scheme: 'doo-sabin',
    level: 2,
    levelCount: 3,
    renderMode: 'flat',
    overlays: { control: true, bbox: true, curves: false },
    lastError: null,
    notice: null,
  });
  expect(countsOf(after)).toEqual(expectedClosedCounts('doo-sabin', CUBE, 2));
  expect(after.facts).toEqual(before.facts);
  expectSameView(after.view, before.view);
  expect(await other.facts()).toMatchObject({ vertices: 96, edges: 192, faces: 98 });
  expect(errors).toEqual([]);
});

test('reload keeps the state; Back after a level step returns to the previous level, Forward comes back', async ({
  app,
}) => {
  await app.open('#src=meshes/icosahedron.off&scheme=loop&levels=1&mode=edges');
  await atLevel(app, 1);
  await app.waitForHash('levels', '1');
  await app.subdivide();
  await app.waitForHash('levels', '2');
  await turnCamera(app);
  const turned = await app.state();
  await test.step('the hash follows the camera', async () => {
    await expect
      .poll(async () => {
        const view = (await app.hashParams()).get('view')?.split(',').map(Number) ?? [];
        return Math.max(...turned.view.position.map((x, i) => Math.abs(x - view[i])));
      })
      .toBeLessThan(1e-3);
  });

  await test.step('reload', async () => {
    await app.page.reload();
    const state = await atLevel(app, 2);
    expect(state).toMatchObject({ modelName: 'icosahedron.off', scheme: 'loop', renderMode: 'edges', levelCount: 3 });
    expect(countsOf(state)).toEqual(expectedClosedCounts('loop', ICOSA, 2));
    expectSameView(state.view, turned.view);
  });

  await test.step('Back: level 1 again, computed levels reused', async () => {
    await app.page.goBack();
    const state = await atLevel(app, 1);
    expect(state).toMatchObject({ scheme: 'loop', levelCount: 3 });
    expect(countsOf(state)).toEqual(expectedClosedCounts('loop', ICOSA, 1));
    await expect(app.byTestId('controls.level-label')).toHaveText('1 / 2');
    expect((await app.hashParams()).get('levels')).toBe('1');
  });

  await test.step('Forward: level 2 and its camera', async () => {
    await app.page.goForward();
    const state = await atLevel(app, 2);
    expect(countsOf(state)).toEqual(expectedClosedCounts('loop', ICOSA, 2));
    expectSameView(state.view, turned.view);
  });

  await test.step('a scheme change is a history entry too', async () => {
    await app.chooseScheme('sqrt3');
    await app.waitForHash('scheme', 'sqrt3');
    await app.page.goBack();
    const state = await atLevel(app, 2);
    expect(state.scheme).toBe('loop');
    expect(countsOf(state)).toEqual(expectedClosedCounts('loop', ICOSA, 2));
  });
});

test('triangulate travels in the link, and Back to a link without it turns it off', async ({ app }) => {
  await app.open('#src=meshes/cube.off&scheme=catmull-clark&levels=1');
  await atLevel(app, 1);
  await app.page.evaluate(() => {
    window.location.hash = '#src=meshes/cube.off&scheme=loop&levels=1&triangulate=1';
  });
  const loop = await atLevel(app, 1);
  expect(loop).toMatchObject({ scheme: 'loop', triangulate: true });
  expect(countsOf(loop)).toEqual(expectedClosedCounts('loop', { vertices: 8, edges: 18, faces: 12 }, 1));
  await app.page.goBack();
  await expect.poll(async () => (await app.state()).scheme).toBe('catmull-clark');
  const back = await atLevel(app, 1);
  expect(back.triangulate).toBe(false);
  expect(countsOf(back)).toEqual(expectedClosedCounts('catmull-clark', CUBE, 1));
  expect((await app.hashParams()).has('triangulate')).toBe(false);
});

test('a bad value in the hash is named in a notice; the rest of the link applies', async ({ app }) => {
  await app.open('#src=meshes/cube.off&scheme=nonsense&levels=1&mode=sparkly&control-mesh=1&view=1,2,3');
  const state = await atLevel(app, 1);
  await expect(app.byTestId('notice')).toBeVisible();
  await expect(app.byTestId('notice')).toHaveAttribute('role', 'status');
  await expect(app.byTestId('notice.message')).toContainText('Unknown scheme "nonsense"');
  await expect(app.byTestId('notice.message')).toContainText('Unknown render mode "sparkly"');
  await expect(app.byTestId('notice.message')).toContainText('view must be nine numbers');
  await expect(app.errorBanner).toBeHidden();
  expect(state).toMatchObject({
    modelName: 'cube.off',
    scheme: 'catmull-clark',
    renderMode: 'smooth',
    overlays: { control: true },
    lastError: null,
  });
  expect(countsOf(state)).toEqual(expectedClosedCounts('catmull-clark', CUBE, 1));
  await test.step('the page stays usable and the hash drops the bad values', async () => {
    await app.subdivide();
    await app.waitForHash('levels', '2');
    const hash = await app.hashParams();
    expect(hash.get('scheme')).toBe('catmull-clark');
    expect(hash.get('mode')).toBe('smooth');
    await app.byTestId('notice.dismiss').click();
    await expect(app.byTestId('notice')).toBeHidden();
  });
});

/** Attributes of the first element named `tag` in an HTML snippet, parsed by the browser. */
/**
 * The attributes of the snippet's `tags`, parsed in a blank page: the app's
 * policy refuses the iframe snippet's style attribute even in a DOMParser
 * document (the snippet is for the teacher's page, not ours).
 */
async function parseSnippet(app: SubdivLabPage, code: string, tags: string[]): Promise<Record<string, string>[]> {
  const blank = await app.page.context().newPage();
  try {
    return await blank.evaluate(
      ({ code, tags }) => {
        const doc = new DOMParser().parseFromString(code, 'text/html');
        return tags.map((tag) => {
          const e = doc.querySelector(tag);
          return e ? Object.fromEntries([...e.attributes].map((a) => [a.name, a.value])) : {};
        });
      },
      { code, tags },
    );
  } finally {
    await blank.close();
  }
}

test('Embed… gives an element and an iframe snippet with the exact state; Copy, Esc', async ({ app, context }) => {
  await context.grantPermissions(['clipboard-read', 'clipboard-write']);
  await app.open('#src=meshes/octahedron.off&scheme=loop&levels=2&mode=edges&control-mesh=1&control-edges=1');
  await atLevel(app, 2);
  await turnCamera(app);
  const state = await app.idle();
  const base = new URL('./', app.page.url()).href;
  await app.byTestId('embed.button').click();
  const dialog = app.byTestId('embed.dialog');
  await expect(dialog).toBeVisible();
  await expect(app.byTestId('embed.element.copy')).toBeFocused();

  await test.step('element snippet', async () => {
    const code = await app.byTestId('embed.element.code').inputValue();
    const [script, viewer] = await parseSnippet(app, code, ['script', 'subdiv-viewer']);
    expect(script).toEqual({ defer: '', src: `${base}embed/subdiv-viewer.js` });
    const { view, alt, ...rest } = viewer;
    expect(rest).toEqual({
      src: `${base}meshes/octahedron.off`,
      scheme: 'loop',
      levels: '2',
      'render-mode': 'edges',
      'control-mesh': '',
      'control-edges': '',
      controls: 'minimal',
    });
    const n = view.split(',').map(Number);
    expectSameView({ position: [n[0], n[1], n[2]], target: [n[3], n[4], n[5]], up: [n[6], n[7], n[8]] }, state.view);
    const faces = expectedClosedCounts('loop', OCTA, 2).faces;
    expect(alt).toBe(
      `octahedron.off after 2 Loop subdivision steps (${faces} faces), shaded with polygon edges, ` +
        'with the control mesh and the control-edge curves.',
    );
  });

  await test.step('iframe snippet', async () => {
    const code = await app.byTestId('embed.iframe.code').inputValue();
    const [frame] = await parseSnippet(app, code, ['iframe']);
    const { src, title, ...rest } = frame;
    expect(rest).toEqual({ width: '640', height: '420', loading: 'lazy', style: 'border:0' });
    expect(title).toContain('octahedron.off after 2 Loop subdivision steps');
    const url = new URL(src);
    expect(`${url.origin}${url.pathname}`).toBe(`${base}embed.html`);
    const { view, ...query } = Object.fromEntries(url.searchParams);
    expect(query).toEqual({
      src: `${base}meshes/octahedron.off`,
      scheme: 'loop',
      levels: '2',
      mode: 'edges',
      'control-mesh': '1',
      'control-edges': '1',
      controls: 'minimal',
    });
    const n = view.split(',').map(Number);
    expectSameView({ position: [n[0], n[1], n[2]], target: [n[3], n[4], n[5]], up: [n[6], n[7], n[8]] }, state.view);
  });

  await test.step('both snippets, pasted into a page, show the same state', async () => {
    const element = await app.byTestId('embed.element.code').inputValue();
    const frame = await app.byTestId('embed.iframe.code').inputValue();
    const page = await context.newPage();
    await page.route('**/e2e/pasted.html', (route) =>
      route.fulfill({
        contentType: 'text/html',
        body: `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Pasted</title></head><body>
${element}
${frame}
</body></html>`,
      }),
    );
    await page.goto(new URL('e2e/pasted.html', base).href);
    const want = { ...expectedClosedCounts('loop', OCTA, 2) };
    const read = (target: Page | Frame) =>
      target.evaluate(() => {
        const e = document.querySelector('subdiv-viewer') as HTMLElementTagNameMap['subdiv-viewer'];
        const s = e.state;
        return s && s.busy === null && s.levelCount > 0
          ? { level: s.level, facts: s.facts, mode: s.renderMode, overlays: s.overlays, view: e.getView() }
          : null;
      });
    await expect.poll(async () => (await read(page))?.level).toBe(2);
    const shown = await read(page);
    expect(shown?.facts).toMatchObject(want);
    expect(shown).toMatchObject({ mode: 'edges', overlays: { control: true, curves: true, bbox: false } });
    expectSameView(shown?.view as View, state.view);
    const inner = page.frames().find((f) => f.url().includes('embed.html'));
    if (!inner) throw new Error('the pasted iframe did not load embed.html');
    await expect.poll(async () => (await read(inner))?.level).toBe(2);
    const framed = await read(inner);
    expect(framed?.facts).toMatchObject(want);
    expectSameView(framed?.view as View, state.view);
    await page.close();
  });

  await test.step('Copy puts the snippet on the clipboard', async () => {
    await app.byTestId('embed.iframe.copy').click();
    await expect(app.byTestId('embed.iframe.status')).toHaveText('Copied');
    expect(await app.page.evaluate(() => navigator.clipboard.readText())).toBe(
      await app.byTestId('embed.iframe.code').inputValue(),
    );
  });
  await app.page.setViewportSize({ width: 1024, height: 760 });
  await app.snapshot('share-02-embed-dialog');
  await test.step('Esc closes the dialog and gives focus back to Embed…', async () => {
    await app.page.keyboard.press('Escape');
    await expect(dialog).toBeHidden();
    await expect(app.byTestId('embed.button')).toBeFocused();
  });
});

test('a model opened from the computer cannot be linked: Share and Embed say so', async ({ app, context }) => {
  await context.grantPermissions(['clipboard-read', 'clipboard-write']);
  await app.open();
  await app.page.evaluate(() => navigator.clipboard.writeText('untouched'));
  await app.dropPath('public/meshes/cube.off');
  await expect(app.byTestId('facts.model')).toHaveText('cube.off');
  await app.idle();
  const sentence =
    'cube.off was opened from your computer, so a link cannot load it; pick a sample or load it from a URL with ?src=.';
  await app.byTestId('share.button').click();
  await expect(app.byTestId('share.status')).toHaveText(sentence);
  expect(await app.page.evaluate(() => navigator.clipboard.readText())).toBe('untouched');
  expect(await app.page.evaluate(() => window.__subdivlab?.shareLink())).toBeNull();
  await app.byTestId('embed.button').click();
  await expect(app.byTestId('embed.refusal')).toHaveText(sentence);
  await expect(app.byTestId('embed.dialog').locator('textarea')).toHaveCount(0);
  await app.byTestId('embed.close').click();
  await expect(app.byTestId('embed.dialog')).toBeHidden();
  await test.step('the hash keeps the rest of the state, without a src', async () => {
    await app.subdivide();
    await app.waitForHash('levels', '1');
    expect((await app.hashParams()).has('src')).toBe(false);
  });
});

test('a refused clipboard shows the link in a selected field; custom rules are said not to travel', async ({ app }) => {
  await app.page.addInitScript(() => {
    navigator.clipboard.writeText = () => Promise.reject(new DOMException('refused', 'NotAllowedError'));
  });
  await app.open('#src=meshes/cube.off&levels=1');
  await atLevel(app, 1);
  await app.byTestId('share.button').click();
  await expect(app.byTestId('share.status')).toHaveText('The clipboard was refused: copy the link from this field.');
  const field = app.byTestId('share.link');
  await expect(field).toBeVisible();
  await expect(field).toBeFocused();
  const link = await app.page.evaluate(() => window.__subdivlab?.shareLink());
  await expect(field).toHaveValue(link ?? 'no link');
  expect(await field.evaluate((e: HTMLInputElement) => e.value.slice(e.selectionStart ?? 0, e.selectionEnd ?? 0))).toBe(
    link,
  );
  await test.step('custom scheme: the dialog says the rules are not carried', async () => {
    await app.chooseScheme('custom');
    await app.byTestId('embed.button').click();
    await expect(app.byTestId('embed.note')).toContainText('Custom rules are not carried by links');
    const code = await app.byTestId('embed.element.code').inputValue();
    expect(code).toContain('scheme="custom"');
  });
});
