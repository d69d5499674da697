/**
 * Side by side in <subdiv-viewer> and the iframe route, as a teacher's page
 * asks for it: `beside="loop"` next to Catmull-Clark on the cube, levels
 * and cameras together, the Hausdorff distance in a caption and a
 * `distance` event equal to what `subdiv compare` prints for the same two
 * levels, the surfaces coloured unless `distance="0"`; a bad `beside` is
 * named; removing it leaves one view.
 */
import { cliDistance } from './cli-distance';
import { viewerPage } from './embed-page';
import { expect, test } from './fixtures';
import { isViridisPurple, pixelsWhere } from './pixels';

const CUBE = 'public/meshes/cube.off';

test('beside="loop": two panes, levels together, the distance of subdiv compare in caption and event, colours', async ({
  embed,
  page,
}) => {
  await embed.serve(
    'e2e/beside.html',
    viewerPage(
      'Side by side',
      'body{margin:0 16px} subdiv-viewer{width:720px;height:360px;margin:0 0 16px}',
      `<subdiv-viewer id="sb" src="../meshes/cube.off" scheme="catmull-clark" levels="2" beside="loop" controls="full"></subdiv-viewer>
       <subdiv-viewer id="plain" src="../meshes/cube.off" scheme="catmull-clark" levels="2" beside="loop" distance="0"></subdiv-viewer>`,
    ),
  );
  await page.goto('./e2e/beside.html');
  await embed.waitForLevel('sb', 2);
  const viewer = page.locator('#sb');

  await test.step('the panes: Catmull-Clark and Loop at level 2, labelled', async () => {
    await expect(viewer.locator('canvas')).toHaveCount(2);
    await expect(viewer.locator('[part="pane-label"]')).toHaveText(['Catmull-Clark · level 2', 'Loop · level 2']);
  });

  await test.step('the distance: caption and event, as subdiv compare gives it', async () => {
    await expect.poll(async () => (await embed.events('distance', 'sb')).length).toBeGreaterThan(0);
    const [event] = await embed.events('distance', 'sb');
    const d = event.detail as {
      distance: number;
      relative: number;
      errorBound: number;
      schemes: string[];
      levels: number[];
    };
    expect(d.schemes).toEqual(['catmull-clark', 'loop']);
    expect(d.levels).toEqual([2, 2]);
    const cli = cliDistance(CUBE, ['catmull-clark', 2], ['loop', 2]);
    expect(Math.abs(d.distance - cli.distance)).toBeLessThanOrEqual(d.errorBound + cli.errorBound);
    expect(await embed.caption('sb', 'distance')).toBe(
      `Hausdorff distance, Catmull-Clark 2 to Loop 2: ${d.distance.toPrecision(4)} (${(100 * d.relative).toPrecision(3)} % of the diagonal)\n0\n${d.distance.toPrecision(4)}`,
    );
    await embed.snapshot('embed-beside-cc-loop');
  });

  await test.step('coloured by the distance; distance="0" shows neither colours nor caption', async () => {
    expect(await pixelsWhere(viewer.locator('.stage'), isViridisPurple)).toBeGreaterThan(1000);
    await embed.waitForLevel('plain', 2);
    const plain = page.locator('#plain');
    await expect(plain.locator('canvas')).toHaveCount(2);
    expect(await pixelsWhere(plain.locator('.stage'), isViridisPurple)).toBe(0);
    expect(await embed.caption('plain', 'distance')).toBe('');
    expect(await embed.events('distance', 'plain')).toEqual([]);
  });

  await test.step('levels together: level 3 in both panes, measured again', async () => {
    await viewer.evaluate((e) => (e as HTMLElementTagNameMap['subdiv-viewer']).setLevel(3));
    await expect(viewer.locator('[part="pane-label"]')).toHaveText(['Catmull-Clark · level 3', 'Loop · level 3']);
    await expect.poll(async () => (await embed.events('distance', 'sb')).at(-1)?.detail.levels).toEqual([3, 3]);
  });

  await test.step('a bad beside is named; removing beside leaves one view', async () => {
    await viewer.evaluate((e) => e.setAttribute('beside', 'loop custom'));
    await expect
      .poll(async () => (await embed.events('error', 'sb')).map((e) => e.detail.code))
      .toContain('invalid_attribute');
    const error = (await embed.events('error', 'sb')).at(-1);
    expect(String(error?.detail.message)).toContain('not "custom"');
    await expect(viewer.locator('canvas')).toHaveCount(1);
    await viewer.evaluate((e) => e.setAttribute('beside', 'sqrt3'));
    await expect(viewer.locator('[part="pane-label"]')).toHaveText([
      'Catmull-Clark · level 3',
      '√3 (Kobbelt) · level 3',
    ]);
    await viewer.evaluate((e) => e.removeAttribute('beside'));
    await expect(viewer.locator('canvas')).toHaveCount(1);
    expect(await embed.caption('sb', 'distance')).toBe('');
    expect(await pixelsWhere(viewer.locator('.stage'), isViridisPurple)).toBe(0);
  });
});

test('the iframe route: beside in the query, the distance posted to the page', async ({ embed, page }) => {
  await embed.serve(
    'e2e/beside-frame.html',
    `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Frame</title></head><body>
<iframe src="../embed.html?src=meshes/cube.off&scheme=loop&triangulate=1&levels=1&beside=sqrt3" width="640" height="360" title="Loop beside sqrt 3"></iframe>
</body></html>`,
  );
  await page.goto('./e2e/beside-frame.html');
  await expect
    .poll(async () => (await embed.events('message:distance')).length, { timeout: 30_000 })
    .toBeGreaterThan(0);
  const [message] = await embed.events('message:distance');
  expect(message.detail).toMatchObject({ schemes: ['loop', 'sqrt3'], levels: [1, 1] });
  const cli = cliDistance(CUBE, ['loop', 1], ['sqrt3', 1]);
  const d = message.detail as unknown as { distance: number; errorBound: number };
  expect(Math.abs(d.distance - cli.distance)).toBeLessThanOrEqual(d.errorBound + cli.errorBound);
});
