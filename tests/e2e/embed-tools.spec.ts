/**
 * The teaching tools in <subdiv-viewer> and the iframe route, as a teacher's
 * page switches them on with attributes: `tool="stencils"` (vertex 7 of the
 * cube's level 1: Catmull-Clark's corner mask), `tool="basis"` (the torus:
 * one control vertex reaches 13 × 13 vertices at level 2) and `tool="split"`
 * (level 1 from its split to its smoothed points). Weights and counts are
 * checked against the published rules and the cube's geometry, not against
 * the app's code.
 */
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { viewerPage } from './embed-page';
import { expect, test } from './fixtures';
import { isViridisPurple, pixelsWhere } from './pixels';

/** The sample cube's 8 corners as its file lists them (level 0). */
const CORNERS = readFileSync('public/meshes/cube.off', 'utf8')
  .split('\n')
  .filter((line) => line.trim() !== '' && !line.startsWith('#'))
  .slice(2, 10)
  .map((line) => line.trim().split(/\s+/).map(Number));

/** A camera looking at the cube's corner (1, 1, 1), fixed so that two pictures can be compared. */
const VIEW = '4.2,3.4,5.6,0,0,0,0,1,0';

type Viewer = HTMLElementTagNameMap['subdiv-viewer'];

/** The polygon corners of an SVG export of the view, in CSS pixels from its top left, and its size. */
function svgPixels(svg: string): { width: number; height: number; points: [number, number][] } {
  const width = Number(/width="([\d.]+)"/.exec(svg)?.[1]);
  const height = Number(/height="([\d.]+)"/.exec(svg)?.[1]);
  const points: [number, number][] = [];
  for (const [, list] of svg.matchAll(/<polygon points="([^"]+)"/g))
    for (const p of list.split(' ')) points.push(p.split(',').map(Number) as [number, number]);
  return { width, height, points };
}

/** The same corners in units of the picture's height from its centre: the same for any size of the view. */
function svgCorners(svg: string): [number, number][] {
  const { width, height, points } = svgPixels(svg);
  return points.map(([x, y]) => [(2 * x - width) / height, (height - 2 * y) / height]);
}

function near(points: [number, number][], p: [number, number]): boolean {
  return points.some((q) => Math.hypot(q[0] - p[0], q[1] - p[1]) < 0.005);
}

test('tool="stencils": vertex 7 of the cube is 5/12 of its corner, 1/6 of each edge neighbour, 1/36 of each diagonal one', async ({
  embed,
  page,
}) => {
  await embed.serve(
    'e2e/stencils.html',
    viewerPage(
      'Stencils',
      'body{margin:0 16px} subdiv-viewer{width:640px;margin:0 0 16px}',
      '<subdiv-viewer id="st" src="../meshes/cube.off" scheme="catmull-clark" levels="1" tool="stencils" vertex="7"></subdiv-viewer>',
    ),
  );
  await page.goto('./e2e/stencils.html');
  await embed.waitForLevel('st', 1);
  const viewer = page.locator('#st');

  await test.step('the stencil event: the parents of level 0 and their weights', async () => {
    await expect.poll(async () => (await embed.events('stencil', 'st')).length).toBeGreaterThan(0);
    const [event] = await embed.events('stencil', 'st');
    expect(event.detail).toMatchObject({ level: 1, vertex: 7, kind: 'vertex point' });
    const parents = event.detail.parents as { vertex: number; weight: number }[];
    expect(parents).toHaveLength(7);
    // Catmull-Clark at valence n = 3: 1 - 7/(4n) = 5/12 itself, 3/(2n^2) = 1/6 each edge neighbour
    // (one coordinate apart on the cube), 1/(4n^2) = 1/36 each diagonal one (two apart).
    const byDistance = [5 / 12, 1 / 6, 1 / 36];
    for (const { vertex, weight } of parents) {
      const apart = CORNERS[vertex].filter((x, i) => x !== CORNERS[7][i]).length;
      expect(apart).toBeLessThan(3);
      expect(weight).toBeCloseTo(byDistance[apart], 12);
    }
    expect(new Set(parents.map((p) => p.vertex)).size).toBe(7);
  });

  await test.step('the caption says the same, with the formula; the weights are labelled on the view', async () => {
    const caption = await embed.caption('st');
    expect(caption).toContain('Level 1, vertex 7: vertex point of vertex 7 (valence 3) = ');
    expect(caption).toContain('(Q + 2R + (n - 3) S) / n');
    // Grouped by weight: 5/12·v7 + 1/6·(three edge neighbours) + 1/36·(three diagonal ones).
    const sum = caption.split('\n')[0].split(' = ')[1] ?? '';
    const terms = [...sum.matchAll(/(\d+\/\d+)·(?:v(\d+)|\(([^)]*)\))/g)].map(([, w, one, many]) => ({
      weight: w,
      vertices: (one ?? many)
        .split(' + ')
        .map((v) => Number(v.replace('v', '')))
        .sort(),
    }));
    const apart = (v: number) => CORNERS[v].filter((x, i) => x !== CORNERS[7][i]).length;
    expect(terms.map((t) => t.weight)).toEqual(['5/12', '1/6', '1/36']);
    expect(terms[0].vertices).toEqual([7]);
    expect(terms[1].vertices.map(apart)).toEqual([1, 1, 1]);
    expect(terms[2].vertices.map(apart)).toEqual([2, 2, 2]);
    // The labels come with the next frame after the caption: polled.
    await expect
      .poll(async () => (await viewer.getByTestId('view.stencil-label').allTextContents()).sort())
      .toEqual(['1/36', '1/36', '1/36', '1/6', '1/6', '1/6', '5/12'].sort());
    await viewer.screenshot({ path: 'test-results/screenshots/embed-tools-stencil-cube.png' });
    // A narrow viewer (a phone, a sidebar): the caption wraps, the picture keeps most of the height.
    await viewer.evaluate((e) => {
      (e as HTMLElement).style.width = '340px';
    });
    await viewer.screenshot({ path: 'test-results/screenshots/embed-tools-stencil-narrow.png' });
    const stage = await viewer.locator('[part="stage"]').boundingBox();
    expect(stage?.height).toBeGreaterThan(160);
    await viewer.evaluate((e) => {
      (e as HTMLElement).style.width = '';
    });
    // The view follows the width a frame later (a resize observer): the next step aims at its picture.
    await expect.poll(async () => Math.round((await viewer.locator('canvas').boundingBox())?.width ?? 0)).toBe(640);
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  });

  await test.step('a click on the view picks another vertex, written into the vertex attribute', async () => {
    const box = await viewer.locator('canvas').boundingBox();
    if (!box) throw new Error('no canvas');
    // A vertex drawn left of the corner facing the camera (vertex 7, near the middle): another vertex of level 1.
    const { width, height, points } = svgPixels(await viewer.evaluate((e) => (e as Viewer).exportSvg()));
    const aim = [width / 2 - 60, height / 2];
    const [x, y] = points
      .filter(([px, py]) => Math.hypot(px - width / 2, py - height / 2) > 30)
      .sort((p, q) => Math.hypot(p[0] - aim[0], p[1] - aim[1]) - Math.hypot(q[0] - aim[0], q[1] - aim[1]))[0];
    await page.mouse.click(box.x + x, box.y + y);
    await expect(viewer).not.toHaveAttribute('vertex', '7');
    const picked = Number(await viewer.getAttribute('vertex'));
    expect(Number.isInteger(picked)).toBe(true);
    await expect.poll(async () => (await embed.events('stencil', 'st')).at(-1)?.detail.vertex).toBe(picked);
    await expect.poll(() => embed.caption('st')).toContain(`Level 1, vertex ${picked}: `);
    expect(await page.evaluate(() => (document.getElementById('st') as Viewer).vertex)).toBe(picked);
  });

  await test.step('a number out of range: a message in the caption, no marks, no crash', async () => {
    await viewer.evaluate((e) => e.setAttribute('vertex', '99'));
    await expect.poll(() => embed.caption('st')).toBe('Level 1 has vertices 0 to 25.');
    await expect(viewer.getByTestId('view.stencil-label')).toHaveCount(0);
    await viewer.evaluate((e) => e.setAttribute('vertex', '7'));
    await expect(viewer.getByTestId('view.stencil-label')).toHaveCount(7);
  });

  await test.step('at level 0 the caption says to go up a level; back at level 1 vertex 7 again', async () => {
    await viewer.evaluate((e) => e.setAttribute('levels', '0'));
    await expect.poll(() => embed.caption('st')).toContain('Level 0 is the control mesh');
    await expect(viewer.getByTestId('view.stencil-label')).toHaveCount(0);
    await viewer.evaluate((e) => e.setAttribute('levels', '1'));
    await expect.poll(() => embed.caption('st')).toContain('Level 1, vertex 7: ');
  });

  await test.step('removing the tool attribute turns the inspector off: no caption, no labels', async () => {
    await viewer.evaluate((e) => e.removeAttribute('tool'));
    await expect(viewer.locator('[part="tool"]')).toBeHidden();
    await expect(viewer.getByTestId('view.stencil-label')).toHaveCount(0);
  });
});

test('tool="basis": control vertex 0 of the torus reaches 169 of the 768 vertices of level 2, coloured', async ({
  embed,
  page,
}) => {
  await embed.serve(
    'e2e/basis.html',
    viewerPage(
      'Basis',
      'body{margin:0 16px} subdiv-viewer{width:480px;margin:0 0 16px}',
      `<subdiv-viewer id="b" src="../meshes/torus.off" scheme="catmull-clark" levels="2" tool="basis" vertex="0"></subdiv-viewer>
<subdiv-viewer id="plain" src="../meshes/torus.off" scheme="catmull-clark" levels="2"></subdiv-viewer>`,
    ),
  );
  await page.goto('./e2e/basis.html');
  await embed.waitForLevel('b', 2);
  await embed.waitForLevel('plain', 2);
  const viewer = page.locator('#b');
  // Every torus vertex has valence 4: after two steps a vertex reaches 1.5 control rings, 13 x 13 vertices.
  await expect
    .poll(async () => (await embed.events('basis', 'b')).at(-1)?.detail)
    .toMatchObject({
      vertex: 0,
      level: 2,
      reached: 169,
      count: 768,
    });
  const max = (await embed.events('basis', 'b')).at(-1)?.detail.max as number;
  expect(max).toBeGreaterThan(0);
  expect(max).toBeLessThan(1);
  await expect
    .poll(() => embed.caption('b'))
    .toContain('Basis function of control vertex 0: reaches 169 of 768 vertices');
  expect(await embed.caption('b')).toContain(max.toFixed(4));
  await expect(viewer.locator('[part="tool"] .tool-bar')).toBeVisible();
  // The surface in the colour bar's colours; the same torus without the tool has none of them.
  expect(await pixelsWhere(viewer.locator('canvas'), isViridisPurple)).toBeGreaterThan(2000);
  expect(await pixelsWhere(page.locator('#plain canvas'), isViridisPurple)).toBe(0);
  // The control mesh stays as the attributes have it (off).
  expect(await viewer.evaluate((e) => (e as Viewer).state?.overlays.control)).toBe(false);
  await viewer.screenshot({ path: 'test-results/screenshots/embed-tools-basis-torus.png' });

  await test.step('level 1 is coloured again: 25 vertices', async () => {
    await viewer.evaluate((e) => e.setAttribute('levels', '1'));
    await expect
      .poll(async () => (await embed.events('basis', 'b')).at(-1)?.detail)
      .toMatchObject({ vertex: 0, level: 1, reached: 25, count: 192 });
  });

  await test.step('a vertex the control mesh does not have: a message', async () => {
    await viewer.evaluate((e) => e.setAttribute('vertex', '48'));
    await expect.poll(() => embed.caption('b')).toBe('The control mesh has vertices 0 to 47.');
  });

  await test.step('tool removed: the colours go', async () => {
    await viewer.evaluate((e) => e.removeAttribute('tool'));
    await expect(viewer.locator('[part="tool"]')).toBeHidden();
    await expect.poll(() => pixelsWhere(viewer.locator('canvas'), isViridisPurple)).toBe(0);
  });
});

test('tool="split": split="0" draws level 1 on the cube (old corners at their level-0 places), split="1" smoothed', async ({
  embed,
  page,
}) => {
  await embed.serve(
    'e2e/split.html',
    viewerPage(
      'Split',
      'body{margin:0 16px} subdiv-viewer{width:560px;margin:0 0 16px}',
      `<subdiv-viewer id="sp" src="../meshes/cube.off" levels="1" tool="split" split="0" view="${VIEW}"></subdiv-viewer>`,
    ),
  );
  await page.goto('./e2e/split.html');
  await embed.waitForLevel('sp', 1);
  const viewer = page.locator('#sp');
  await expect.poll(() => embed.caption('sp')).toBe('Split → smoothed: 0.00');
  const svg = () => viewer.evaluate((e) => (e as Viewer).exportSvg());
  const splitSvg = await svg();
  const splitPixels = await viewer.locator('canvas').screenshot();
  await viewer.screenshot({ path: 'test-results/screenshots/embed-tools-split-0.png' });

  await test.step('split="1": the smoothed level, other pixels', async () => {
    await viewer.evaluate((e) => e.setAttribute('split', '1'));
    await expect.poll(() => embed.caption('sp')).toBe('Split → smoothed: 1.00');
    await expect.poll(async () => (await viewer.locator('canvas').screenshot()).equals(splitPixels)).toBe(false);
  });
  const smoothSvg = await svg();

  await test.step("at split 0 the cube's corners are where level 0 has them; smoothed, they moved in", async () => {
    await viewer.evaluate((e) => e.setAttribute('levels', '0'));
    await embed.waitForLevel('sp', 0);
    const corners = svgCorners(await svg());
    const split = svgCorners(splitSvg);
    const smooth = svgCorners(smoothSvg);
    // Three faces of the cube face the camera: 7 of its corners are drawn.
    const unique = corners.filter((p, i) => !near(corners.slice(0, i), p));
    expect(unique).toHaveLength(7);
    for (const p of unique) expect(near(split, p)).toBe(true);
    expect(unique.filter((p) => near(smooth, p)).length).toBeLessThan(2);
  });

  await test.step('the slider and Play in the control bar; Play ends at 1 and says so in the attribute', async () => {
    await viewer.evaluate((e) => {
      e.setAttribute('levels', '1');
      e.setAttribute('split', '0.5');
    });
    await embed.waitForLevel('sp', 1);
    await expect.poll(() => embed.caption('sp')).toBe('Split → smoothed: 0.50');
    await expect(viewer.locator('[part="split"]')).toHaveValue('0.5');
    await viewer.screenshot({ path: 'test-results/screenshots/embed-tools-split-half.png' });
    await viewer.locator('[part="play"]').click();
    await expect(viewer).toHaveAttribute('split', '1');
    await expect.poll(() => embed.caption('sp')).toBe('Split → smoothed: 1.00');
    await viewer.locator('[part="split"]').fill('0.25');
    await expect(viewer).toHaveAttribute('split', '0.25');
    await expect.poll(() => embed.caption('sp')).toBe('Split → smoothed: 0.25');
  });
});

test('a bad tool value fires error invalid_attribute; the viewer goes on without a tool', async ({ embed, page }) => {
  await embed.serve(
    'e2e/bad-tool.html',
    viewerPage(
      'Bad tool',
      'subdiv-viewer{width:400px}',
      '<subdiv-viewer id="bad" src="../meshes/cube.off" levels="1" tool="stencil" vertex="7"></subdiv-viewer>',
    ),
  );
  await page.goto('./e2e/bad-tool.html');
  await embed.waitForLevel('bad', 1);
  await expect.poll(async () => (await embed.events('error', 'bad')).length).toBe(1);
  const [error] = await embed.events('error', 'bad');
  expect(error.detail).toMatchObject({
    code: 'invalid_attribute',
    source: 'tool',
    message: 'tool must be none, stencils, basis, split or halfedges, not "stencil".',
  });
  await expect(page.locator('#bad').locator('.message')).toContainText('tool must be none');
  expect(await page.evaluate(() => (document.getElementById('bad') as Viewer).tool)).toBe('none');
  await expect(page.locator('#bad').locator('[part="tool"]')).toBeHidden();
  // Put right: the message goes and the inspector shows vertex 7.
  await page.locator('#bad').evaluate((e) => e.setAttribute('tool', 'stencils'));
  await expect(page.locator('#bad').locator('.message')).toBeHidden();
  await expect.poll(async () => (await embed.events('stencil', 'bad')).at(-1)?.detail.vertex).toBe(7);
});

test('the iframe route: ?tool=stencils&vertex=7&levels=1 shows the caption; set-tool and set-split by postMessage', async ({
  embed,
  page,
}) => {
  await embed.serve(
    'e2e/tool-frame.html',
    viewerPage(
      'Tools in an iframe',
      'iframe{width:560px;height:320px;border:0}',
      '<iframe id="frame" title="Stencils of the cube" src="../embed.html?src=meshes/cube.off&amp;tool=stencils&amp;vertex=7&amp;levels=1"></iframe>',
    ),
  );
  await page.goto('./e2e/tool-frame.html');
  const frame = page.frameLocator('#frame');
  const caption = frame.locator('subdiv-viewer').locator('[part="tool"]');
  await expect(caption).toContainText('Level 1, vertex 7: vertex point of vertex 7 (valence 3) = 5/12·v7 + 1/6·(');
  await expect
    .poll(async () => (await embed.events('message:stencil')).at(-1)?.detail)
    .toMatchObject({ level: 1, vertex: 7, kind: 'vertex point' });
  await expect(frame.getByTestId('view.stencil-label')).toHaveCount(7);
  await page.locator('#frame').screenshot({ path: 'test-results/screenshots/embed-tools-iframe-stencil.png' });

  const post = (message: object) =>
    page.evaluate((m) => {
      const target = (document.getElementById('frame') as HTMLIFrameElement).contentWindow as Window;
      target.postMessage(m, '*');
    }, message);
  await post({ subdivlab: 'set-tool', tool: 'split' });
  await post({ subdivlab: 'set-split', t: 0.5 });
  await expect(caption).toHaveText('Split → smoothed: 0.50');
  await expect(frame.getByTestId('view.stencil-label')).toHaveCount(0);
  await post({ subdivlab: 'set-tool', tool: 'basis', vertex: 0 });
  // One step from the cube: corner 0 weighs in the points of its 3 faces, of their 9 edges, and of
  // the 7 corners that share a face with it (itself, 3 edge neighbours, 3 diagonal ones): 19 of 26.
  await expect
    .poll(async () => (await embed.events('message:basis')).at(-1)?.detail)
    .toMatchObject({ vertex: 0, level: 1, reached: 19, count: 26 });
  await expect(caption).toContainText('Basis function of control vertex 0: reaches 19 of 26 vertices');
});

test('tool="halfedges": the cube’s 24 arrows; a click picks one, numbered as subdiv halfedges numbers it', async ({
  embed,
  page,
}) => {
  await embed.serve(
    'e2e/halfedges.html',
    viewerPage(
      'Halfedges',
      'subdiv-viewer{width:560px}',
      `<subdiv-viewer id="he" src="../meshes/cube.off" tool="halfedges" view="${VIEW}"></subdiv-viewer>`,
    ),
  );
  await page.goto('./e2e/halfedges.html');
  await embed.waitForLevel('he', 0);
  await expect.poll(() => embed.caption('he')).toBe('Level 0: 24 halfedges. Click an arrow to pick one.');
  // The middle of the picture is on the cube; the arrow nearest the click is picked.
  const stage = page.locator('#he').locator('[part="stage"]');
  const box = await stage.boundingBox();
  if (!box) throw new Error('no stage');
  await page.mouse.click(box.x + box.width / 2, box.y + box.height / 2);
  await expect.poll(() => embed.caption('he')).toMatch(/^Halfedge \d+: /);
  const line = (await embed.caption('he')).split('\n')[0];
  const m = /^Halfedge (\d+): vertex (\d+) → vertex (\d+), face (\d+); next (\d+), prev (\d+), opposite (\d+)$/.exec(
    line,
  );
  expect(m, line).not.toBeNull();
  const [h, source, target, face, next, prev, opposite] = (m ?? []).slice(1).map(Number);
  // The same row in the table the CLI prints from the same file.
  const table = JSON.parse(
    execFileSync(process.execPath, ['bin/subdiv.mjs', 'halfedges', 'public/meshes/cube.off'], { encoding: 'utf8' }),
  ).table as { h: number; next: number; prev: number; opposite: number; vertex: number; face: number | null }[];
  expect(table[h]).toEqual({ h, next, prev, opposite, vertex: target, face });
  expect(table[opposite].vertex).toBe(source);
  await page.locator('#he').screenshot({ path: 'test-results/screenshots/embed-tools-halfedges.png' });
});
