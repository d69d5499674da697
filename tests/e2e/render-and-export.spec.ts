/**
 * Render modes and overlays change what is drawn; exports (PNG, SVG, OFF,
 * OBJ) are checked by reading the files back.
 */
import { readFileSync } from 'node:fs';
import { readFile } from 'node:fs/promises';
import { PARTED_ATTRIBUTE_BYTES } from '../../web/render/parted-attribute';
import { expect, test } from './fixtures';
import {
  cameraFacingFaces,
  edgeCount,
  PNG_SIGNATURE,
  type PngInfo,
  projectedFacingFaces,
  readOff,
  readPng,
} from './helpers';

const CUBE = readFileSync('public/meshes/cube.off', 'utf8');

test('render modes, the control-mesh overlay and the bounding box change the picture', async ({ app }) => {
  await app.open();
  await app.load('cube.off', CUBE);
  await app.subdivide();
  await app.subdivide();
  const shots = new Map<string, Buffer>();
  for (const mode of ['smooth', 'flat', 'edges', 'wireframe']) {
    await test.step(`mode ${mode}`, async () => {
      await app.byTestId('controls.render-mode').selectOption(mode);
      expect((await app.state()).renderMode).toBe(mode);
      shots.set(mode, await app.canvasPixels());
    });
  }
  await test.step('polygon edges: quads drawn as quads (no fan diagonals)', async () => {
    const state = await app.state();
    expect(state.facts?.faces).toBe(96);
    expect(state.edgeSegments).toBe(192);
  });
  const modes = [...shots.keys()];
  for (let i = 0; i < modes.length; i++) {
    for (let j = i + 1; j < modes.length; j++) {
      expect(shots.get(modes[i])?.equals(shots.get(modes[j]) as Buffer), `${modes[i]} vs ${modes[j]}`).toBe(false);
    }
  }
  await test.step('key r cycles the modes', async () => {
    await app.page.locator('body').click({ position: { x: 5, y: 690 } });
    // From wireframe on through reflection lines and the curvatures, back to the start.
    for (const mode of ['zebra', 'mean-curvature', 'gaussian-curvature', 'smooth']) {
      await app.page.keyboard.press('r');
      expect((await app.state()).renderMode).toBe(mode);
    }
    await app.page.keyboard.press('r');
    expect((await app.state()).renderMode).toBe('flat');
    expect((await app.canvasPixels()).equals(shots.get('flat') as Buffer)).toBe(true);
  });
  await test.step('control-mesh overlay', async () => {
    await app.byTestId('controls.overlay-control').check();
    expect((await app.state()).overlays.control).toBe(true);
    const withOverlay = await app.canvasPixels();
    expect(withOverlay.equals(shots.get('flat') as Buffer)).toBe(false);
    await app.byTestId('controls.render-mode').selectOption('edges');
    await app.snapshot('03-subdivided-overlay');
  });
  await test.step('bounding box', async () => {
    const before = await app.canvasPixels();
    await app.page.keyboard.press('b');
    expect((await app.state()).overlays.bbox).toBe(true);
    expect((await app.canvasPixels()).equals(before)).toBe(false);
  });
});

test('levels whose points and normals go to the GPU in parts are drawn as the level before them', async ({ app }) => {
  test.setTimeout(120_000);
  await app.open();
  // A grid of 300 × 300 quads with one gentle bump: Catmull-Clark keeps its outline and its shading.
  const n = 300;
  const points: string[] = [];
  const quads: string[] = [];
  for (let j = 0; j <= n; j++)
    for (let i = 0; i <= n; i++)
      points.push(`${i / n} ${j / n} ${0.2 * Math.sin((Math.PI * i) / n) * Math.sin((Math.PI * j) / n)}`);
  for (let j = 0; j < n; j++)
    for (let i = 0; i < n; i++)
      quads.push(`4 ${j * (n + 1) + i} ${j * (n + 1) + i + 1} ${(j + 1) * (n + 1) + i + 1} ${(j + 1) * (n + 1) + i}`);
  await app.load('bump.off', `OFF\n${points.length} ${quads.length} 0\n${points.join('\n')}\n${quads.join('\n')}\n`);
  await app.byTestId('controls.overlay-control').uncheck();
  await app.byTestId('controls.render-mode').selectOption('smooth');
  // The facts panel over the view changes with the level: pixels under it are left out.
  const canvas = await app.canvas.boundingBox();
  const panel = await app.byTestId('facts').boundingBox();
  if (!canvas || !panel) throw new Error('no canvas or facts panel');
  const underPanel = (x: number, y: number) =>
    x <= panel.x + panel.width - canvas.x + 20 && y <= panel.y + panel.height - canvas.y + 20;
  const pictureOf = async (level: number) => {
    // The draw follows the level's upload by some frames.
    await expect.poll(async () => (await app.state()).drawn?.level, { timeout: 60_000 }).toBe(level);
    return readPng(await app.canvasPixels());
  };
  const level0 = await pictureOf(0);
  /** Pixels of the surface (not the background) in `png`, and those whose colour differs from `level0`'s. */
  const compare = (png: PngInfo) => {
    let surface = 0;
    let differ = 0;
    for (let y = 0; y < png.height; ++y) {
      for (let x = 0; x < png.width; ++x) {
        if (underPanel(x, y)) continue;
        const [r, g, b] = png.pixel(x, y);
        const [r0, g0, b0] = level0.pixel(x, y);
        if (Math.max(Math.abs(r - 0xf3), Math.abs(g - 0xf4), Math.abs(b - 0xf6)) > 8) surface++;
        if (Math.max(Math.abs(r - r0), Math.abs(g - g0), Math.abs(b - b0)) > 24) differ++;
      }
    }
    return { surface, differ };
  };
  const before = compare(level0);
  // The grid fills much of the view.
  expect(before.surface).toBeGreaterThan((level0.width * level0.height) / 4);
  // 90,601 points at level 0 (1.1 MB), 361,201 at level 1 and 1,442,401 at level 2 (17 MB, five parts).
  for (const [level, vertices] of [
    [1, 361_201],
    [2, 1_442_401],
  ] as const) {
    await test.step(`level ${level}: ${vertices} points`, async () => {
      expect((await app.subdivide()).facts?.vertices).toBe(vertices);
      expect(12 * vertices).toBeGreaterThan(PARTED_ATTRIBUTE_BYTES);
      const { surface, differ } = compare(await pictureOf(level));
      // The same outline and the same shading: a part of the points or normals missing would leave holes or dark patches.
      expect(Math.abs(surface - before.surface)).toBeLessThan(before.surface / 200);
      expect(differ).toBeLessThan(before.surface / 200);
    });
  }
  await test.step('Split dragged on level 1 (parted too): the view draws the blend while it keeps changing', async () => {
    await app.scrubTo(1);
    await app.byTestId('split.t').fill('0');
    await expect(app.byTestId('split.value')).toHaveText('0.00');
    // The slider moved on every frame, as a hand drags it (and as Play moves it), until the view
    // has drawn twice since the first move (the first may still be the 0 set above): points and
    // normals that change every frame, were they sent in parts, would start over at each change
    // and nothing be drawn while they change. Waits on draws, not on how many fit in a time.
    await app.page.evaluate(() => {
      const w = window as unknown as { blendDrawn: string | null };
      w.blendDrawn = null;
      const slider = document.querySelector<HTMLInputElement>('[data-testid="split.t"]');
      const value = document.querySelector('[data-testid="split.value"]');
      if (!slider || !value) throw new Error('no split slider');
      let last = window.__subdivlab?.state().drawn?.at;
      let draws = 0;
      let move = 0;
      const step = () => {
        const at = window.__subdivlab?.state().drawn?.at;
        if (at !== last) {
          last = at;
          draws += 1;
        }
        if (draws >= 2) {
          w.blendDrawn = value.textContent;
          return;
        }
        move += 1;
        slider.value = (0.1 + 0.08 * (move % 10)).toFixed(2);
        slider.dispatchEvent(new Event('input', { bubbles: true }));
        requestAnimationFrame(step);
      };
      requestAnimationFrame(step);
    });
    await expect
      .poll(() => app.page.evaluate(() => (window as unknown as { blendDrawn: string | null }).blendDrawn), {
        timeout: 90_000,
      })
      .toMatch(/^0\.(1|2|3|4|5|6|7|8)\d$/);
  });
});

test('control-edge curves: the marked edges of a refined level, drawn and exported', async ({ app }) => {
  await app.open();
  await app.load('cube.off', CUBE);
  const toggle = app.byTestId('controls.overlay-curves');
  await expect(toggle).toBeDisabled();
  await test.step('E does not switch on curves that are not there', async () => {
    await app.page.keyboard.press('e');
    expect((await app.state()).overlays.curves).toBe(false);
    await expect(toggle).not.toBeChecked();
  });
  for (let i = 0; i < 3; i++) await app.subdivide();
  // Every cube edge is split in two at each step: 12·2³ marked edges at level 3.
  expect((await app.state()).facts?.controlEdges).toBe(96);
  await expect(toggle).toBeEnabled();
  const before = await app.canvasPixels();
  await app.page.keyboard.press('e');
  expect((await app.state()).overlays.curves).toBe(true);
  await expect(toggle).toBeChecked();
  expect((await app.canvasPixels()).equals(before)).toBe(false);
  await app.snapshot('06-control-curves');
  await app.byTestId('export-panel').locator('summary').click();
  const svg = await readFile(await (await app.download('export.svg')).path(), 'utf8');
  const segments = (id: string) =>
    (new RegExp(`<path id="${id}"[^>]* d="([^"]*)"`).exec(svg)?.[1].split('M').length ?? 0) - 1;
  // Curves on the far side go before the faces, which cover them as in the view; the rest on top.
  const [front, back] = [segments('control-curves'), segments('control-curves-back')];
  expect(front + back).toBe(96);
  expect(front).toBeGreaterThan(0);
  expect(back).toBeGreaterThan(0);
  expect(svg.indexOf('id="control-curves-back"')).toBeLessThan(svg.indexOf('<g id="faces"'));
  expect(svg.indexOf('id="control-curves"')).toBeGreaterThan(svg.indexOf('<g id="faces"'));
});

test('PNG export: signature, ×2 doubles the size, transparent background', async ({ app }) => {
  await app.open();
  await app.load('cube.off', CUBE);
  await app.subdivide();
  const size = await app.byTestId('viewer').evaluate((e) => [e.clientWidth, e.clientHeight]);
  await app.byTestId('export-panel').locator('summary').click();
  const one = await app.download('export.png');
  expect(one.suggestedFilename()).toBe('cube-catmull-clark-L1.png');
  const png1 = await readFile(await one.path());
  expect(png1.subarray(0, 8).equals(PNG_SIGNATURE)).toBe(true);
  const info1 = readPng(png1);
  expect([info1.width, info1.height]).toEqual(size);
  expect(info1.pixel(2, 2)[3]).toBe(255);

  await app.byTestId('export-panel').locator('summary').click();
  await app.byTestId('export.scale').selectOption('2');
  await app.byTestId('export.transparent').check();
  const two = await app.download('export.png');
  const info2 = readPng(await readFile(await two.path()));
  expect([info2.width, info2.height]).toEqual([2 * size[0], 2 * size[1]]);
  expect(info2.pixel(2, 2)[3]).toBe(0);
  // The model in the middle stays opaque.
  expect(info2.pixel(size[0], size[1])[3]).toBe(255);
});

test('SVG export: one polygon per camera-facing face, back to front, viewBox set', async ({ app }) => {
  await app.open();
  await app.load('cube.off', CUBE);
  const cube = readOff(CUBE);

  const svgOf = async (testId = 'export.svg') => {
    await app.byTestId('export-panel').locator('summary').click();
    const download = await app.download(testId);
    const text = await readFile(await download.path(), 'utf8');
    // Parse it as the browser does.
    const parsed = await app.page.evaluate((svg) => {
      const doc = new DOMParser().parseFromString(svg, 'image/svg+xml');
      const root = doc.documentElement;
      return {
        rootName: root.nodeName,
        parseError: doc.querySelector('parsererror') !== null,
        viewBox: root.getAttribute('viewBox'),
        polygons: doc.querySelectorAll('polygon').length,
        control: doc.querySelector('#control-mesh')?.getAttribute('d')?.split('M').length ?? 0,
        controlBack: doc.querySelector('#control-mesh-back')?.getAttribute('d')?.split('M').length ?? 0,
        backBeforeFaces:
          (doc.querySelector('#control-mesh-back')?.compareDocumentPosition(doc.querySelector('#faces') as Node) ?? 0) &
          Node.DOCUMENT_POSITION_FOLLOWING,
        // Screen centroid of each polygon, in drawing order.
        centroids: [...doc.querySelectorAll('polygon')].map((p) => {
          const xy = (p.getAttribute('points') ?? '').split(' ').map((pair) => pair.split(',').map(Number));
          return [xy.reduce((s, q) => s + q[0], 0) / xy.length, xy.reduce((s, q) => s + q[1], 0) / xy.length];
        }),
      };
    }, text);
    return { name: download.suggestedFilename(), ...parsed };
  };

  await test.step('default view of the cube: three faces', async () => {
    const state = await app.state();
    const expected = cameraFacingFaces(cube, state.view.position);
    expect(expected).toBe(3);
    const svg = await svgOf();
    expect(svg).toMatchObject({ rootName: 'svg', parseError: false, polygons: expected, control: 0 });
    const size = await app.byTestId('viewer').evaluate((e) => `0 0 ${e.clientWidth} ${e.clientHeight}`);
    expect(svg.viewBox).toBe(size);
    expect(svg.name).toBe('cube-catmull-clark-L0.svg');
  });

  await test.step('front view (saved view restored): one face', async () => {
    await app.page.evaluate(() =>
      localStorage.setItem('subdivlab.view', JSON.stringify({ position: [0, 0, 9], target: [0, 0, 0], up: [0, 1, 0] })),
    );
    await app.page.reload();
    await app.open();
    await app.load('cube.off', CUBE);
    await app.byTestId('view.restore').click();
    await expect.poll(async () => (await app.state()).view.position).toEqual([0, 0, 9]);
    expect(cameraFacingFaces(cube, [0, 0, 9])).toBe(1);
    expect((await svgOf()).polygons).toBe(1);
  });

  await test.step('level 2 with the control mesh: faces counted from the exported OFF', async () => {
    await app.byTestId('view.fit').click();
    await app.subdivide();
    await app.subdivide();
    await app.byTestId('controls.overlay-control').check();
    await app.byTestId('export-panel').locator('summary').click();
    const off = readOff(await readFile(await (await app.download('export.off')).path(), 'utf8'));
    const expected = cameraFacingFaces(off, (await app.state()).view.position);
    const svg = await svgOf();
    expect(svg.polygons).toBe(expected);
    expect(expected).toBeGreaterThan(20);
    expect(expected).toBeLessThan(96);
    // One move-to per control edge (the leading empty split part counts as one more in each path).
    // Edges of a camera-facing cube face are drawn over the surface; the others before it, hidden where it covers them.
    const eye = (await app.state()).view.position;
    const frontEdges = new Set(
      cube.faces
        .filter((f) => cameraFacingFaces({ positions: cube.positions, faces: [f] }, eye) === 1)
        .flatMap((f) => f.map((a, k) => [a, f[(k + 1) % f.length]].sort().join('-'))),
    );
    expect(frontEdges.size).toBe(9);
    expect(svg.control - 1).toBe(frontEdges.size);
    expect(svg.controlBack - 1).toBe(12 - frontEdges.size);
    expect(svg.backBeforeFaces).toBeTruthy();

    // Back to front: match each polygon to its face by screen centroid, then depths must not increase.
    const state = await app.state();
    const size = await app.byTestId('viewer').evaluate((e) => [e.clientWidth, e.clientHeight]);
    const faces = projectedFacingFaces(off, {
      ...state.view,
      fov: state.fov,
      width: size[0],
      height: size[1],
      // The picture is drawn without the view's shift for the facts panel (export-framing.spec.ts).
    });
    expect(faces.length).toBe(expected);
    const depths = svg.centroids.map(([x, y]) => {
      const nearest = faces.reduce((best, f) =>
        Math.hypot(f.x - x, f.y - y) < Math.hypot(best.x - x, best.y - y) ? f : best,
      );
      expect(Math.hypot(nearest.x - x, nearest.y - y)).toBeLessThan(0.05);
      return nearest.depth;
    });
    for (let i = 1; i < depths.length; i++) expect(depths[i]).toBeLessThanOrEqual(depths[i - 1]);
  });
});

test('OFF and OBJ export of the current level; importing the OFF gives the same counts', async ({ app }) => {
  await app.open();
  await app.load('cube.off', CUBE);
  await app.subdivide();
  await app.subdivide();
  const level2 = await app.facts();
  await app.byTestId('export-panel').locator('summary').click();
  const offDownload = await app.download('export.off');
  expect(offDownload.suggestedFilename()).toBe('cube-catmull-clark-L2.off');
  const offText = await readFile(await offDownload.path(), 'utf8');
  const off = readOff(offText);
  expect([off.positions.length, edgeCount(off), off.faces.length]).toEqual([98, 192, 96]);

  await app.byTestId('export-panel').locator('summary').click();
  const objDownload = await app.download('export.obj');
  expect(objDownload.suggestedFilename()).toBe('cube-catmull-clark-L2.obj');
  const objText = await readFile(await objDownload.path(), 'utf8');
  expect(objText.split('\n').filter((l) => l.startsWith('v ')).length).toBe(98);
  expect(objText.split('\n').filter((l) => l.startsWith('f ')).length).toBe(96);

  await test.step('drop the exported OFF: same counts at level 0', async () => {
    await app.load('cube-catmull-clark-L2.off', offText);
    expect(await app.facts()).toEqual(level2);
    expect((await app.state()).level).toBe(0);
  });
});
