/**
 * Issue 4 in the app: quad-triangle (and its fixed boundary) from the
 * gallery, and the rules panel of the custom scheme — presets equal the
 * built-in schemes, edited weights change the surface and not the counts,
 * invalid weights are refused with the core's message, rules are saved and
 * loaded as JSON files.
 */
import { readFileSync } from 'node:fs';
import { expect, test } from './fixtures';
import { expectedClosedCounts } from './helpers';
import type { SubdivLabPage } from './subdivlab-page';

const LOOP_PRESET = JSON.parse(readFileSync('public/rules/loop.json', 'utf8'));
const ICOSAHEDRON = { vertices: 12, edges: 30, faces: 20 };

/** Largest coordinate difference of two position arrays of the same length. */
function maxDifference(a: readonly number[], b: readonly number[]): number {
  expect(a.length).toBe(b.length);
  let max = 0;
  for (let i = 0; i < a.length; i++) max = Math.max(max, Math.abs(a[i] - b[i]));
  return max;
}

/** Subdivides until `level` is shown. */
async function subdivideTo(app: SubdivLabPage, level: number): Promise<void> {
  while ((await app.state()).level < level) await app.subdivide();
}

async function countsShown(app: SubdivLabPage) {
  const f = await app.facts();
  return { vertices: f.vertices, edges: f.edges, faces: f.faces };
}

test('quad-triangle on the rhombicuboctahedron; Fixed boundary on an open grid', async ({ app }) => {
  await app.open();
  await test.step('rhombicuboctahedron from the gallery, level 1', async () => {
    await app.openSample('rhombicuboctahedron', 'rhombicuboctahedron.off');
    await expect(app.byTestId('controls.fixed-boundary')).toBeHidden();
    await app.chooseScheme('quad-triangle');
    await expect(app.byTestId('controls.fixed-boundary')).toBeVisible();
    await app.subdivide();
    // 8 triangles and 18 quads, 24 vertices, 48 edges: triangles split 1→4 at edge midpoints,
    // quads 1→4 around a centre, so V = 24 + 48 + 18, 4·8 triangles, 4·18 quads, E = (3·32 + 4·72)/2.
    expect(await app.facts()).toMatchObject({
      vertices: 90,
      edges: 192,
      faces: 104,
      genus: 0,
      boundaries: 0,
      faceTypes: '32 triangles, 72 quads',
    });
  });
  await test.step('open grid: the corner is cut by the border rule, or stays with Fixed boundary', async () => {
    await app.openSample('open-grid', 'open-grid.off');
    await app.subdivide();
    expect(await app.facts()).toMatchObject({ vertices: 49, faces: 36, boundaries: 1 });
    // Vertex 0 is the corner (0, 0, 0); the border rule [1/8, 3/4, 1/8] along the border
    // takes it to (1/8)(0, 1, 0) + (3/4)(0, 0, 0) + (1/8)(1, 0, 0).
    expect((await app.positions()).slice(0, 3)).toEqual([0.125, 0.125, 0]);
    expect((await app.state()).smoothBoundary).toBe(true);
    await app.byTestId('controls.fixed-boundary').check();
    // The level is computed again at once with the border kept.
    await expect.poll(async () => (await app.positions()).slice(0, 3)).toEqual([0, 0, 0]);
    const state = await app.idle();
    expect(state.level).toBe(1);
    expect(state.smoothBoundary).toBe(false);
    expect(await app.facts()).toMatchObject({ vertices: 49, faces: 36, boundaries: 1 });
  });
});

test('rules panel: Loop preset equals loop; an edited weight changes the surface, not the counts', async ({ app }) => {
  await app.open();
  await app.openSample('icosahedron', 'icosahedron.off');
  let builtIn: number[] = [];
  await test.step('built-in loop to level 2', async () => {
    await app.chooseScheme('loop');
    await subdivideTo(app, 2);
    expect(await countsShown(app)).toEqual(expectedClosedCounts('loop', ICOSAHEDRON, 2));
    builtIn = await app.positions();
  });
  await test.step('custom shows the rules panel with its first preset', async () => {
    await expect(app.byTestId('rules')).toBeHidden();
    await app.chooseScheme('custom');
    await expect(app.byTestId('rules')).toBeVisible();
    await expect(app.byTestId('rules.preset')).toHaveValue('catmull-clark');
    await expect(app.byTestId('rules.host')).toContainText('PQQ');
    await expect(app.weight('vertex.self')).toHaveValue('(n - 2)/n');
    await expect.poll(async () => (await app.state()).customRules?.name).toBe('Catmull-Clark');
  });
  let loop: number[] = [];
  await test.step('Loop preset: counts and positions of the built-in loop', async () => {
    await app.chooseRulePreset('loop', 'Loop');
    await expect(app.byTestId('rules.host')).toContainText('PTQ');
    await expect(app.weight('edge.end')).toHaveValue('3/8');
    await expect(app.weight('vertex.self.6')).toHaveValue('10/16');
    await expect(app.weight('vertex.neighbour.default')).toHaveValue('(5/8 - (3 + 2*cos(2*pi/n))^2/64)/n');
    expect((await app.state()).customRules).toEqual(LOOP_PRESET);
    await subdivideTo(app, 2);
    expect(await countsShown(app)).toEqual(expectedClosedCounts('loop', ICOSAHEDRON, 2));
    loop = await app.positions();
    expect(maxDifference(loop, builtIn)).toBeLessThan(1e-12);
    await app.snapshot('rules-01-loop-preset');
    await app.panelSnapshot('rules', 'rules-panel-open');
  });
  await test.step('edge rule 3/8, 1/8 → 0.4, 0.1: Apply recomputes level 2', async () => {
    const before = await app.state();
    const pixels = await app.canvasPixels();
    await app.weight('edge.end').fill('0.4');
    await app.weight('edge.wing').fill('0.1');
    await expect(app.byTestId('rules.status')).toHaveText('Every stencil sums to 1. Press Apply to use these weights.');
    const after = await app.applyRules();
    expect(after.level).toBe(2);
    expect(after.customRules?.edge).toEqual({ end: 0.4, wing: 0.1 });
    expect(await countsShown(app)).toEqual(expectedClosedCounts('loop', ICOSAHEDRON, 2));
    expect(maxDifference(await app.positions(), loop)).toBeGreaterThan(1e-3);
    expect(after.facts?.bboxMax).not.toEqual(before.facts?.bboxMax);
    expect((await app.canvasPixels()).equals(pixels)).toBe(false);
  });
});

for (const { preset, ruleName, scheme, sample, host, field, value } of [
  {
    preset: 'doo-sabin',
    ruleName: 'Doo-Sabin',
    scheme: 'doo-sabin',
    sample: 'cube',
    host: 'DQQ',
    field: 'corner.other',
    value: '(3 + 2*cos(2*pi*j/k))/(4*k)',
  },
  {
    preset: 'sqrt3',
    ruleName: 'Sqrt(3)',
    scheme: 'sqrt3',
    sample: 'octahedron',
    host: '√3',
    field: 'vertex.neighbour',
    value: '(4 - 2*cos(2*pi/n))/(9*n)',
  },
  {
    preset: 'catmull-clark',
    ruleName: 'Catmull-Clark',
    scheme: 'catmull-clark',
    sample: 'rhombicuboctahedron',
    host: 'PQQ',
    field: 'vertex.face',
    value: '1/n^2',
  },
]) {
  test(`rules panel: the ${preset} preset equals ${scheme} on the ${sample}`, async ({ app }) => {
    await app.open();
    await app.openSample(sample, `${sample}.off`);
    await app.chooseScheme(scheme);
    await subdivideTo(app, 2);
    const counts = await countsShown(app);
    const builtIn = await app.positions();
    await app.chooseScheme('custom');
    if (preset !== 'catmull-clark') await app.chooseRulePreset(preset, ruleName);
    else await expect.poll(async () => (await app.state()).customRules?.name).toBe(ruleName);
    await expect(app.byTestId('rules.host')).toContainText(host);
    await expect(app.weight(field)).toHaveValue(value);
    await subdivideTo(app, 2);
    expect(await countsShown(app)).toEqual(counts);
    expect(maxDifference(await app.positions(), builtIn)).toBeLessThan(1e-12);
  });
}

test('rules panel: a PTQ rule set on quads says it needs triangles and offers to triangulate', async ({ app }) => {
  await app.open();
  await app.openSample('cube', 'cube.off');
  await app.chooseScheme('custom');
  await expect.poll(async () => (await app.state()).customRules?.host).toBe('pqq');
  await expect(app.byTestId('controls.triangle-note')).toBeHidden();
  await app.chooseRulePreset('loop', 'Loop');
  await expect(app.byTestId('controls.triangle-note')).toHaveText(
    'The PTQ host needs triangles; this mesh has 6 other faces.',
  );
  await app.byTestId('controls.subdivide').click();
  await expect(app.byTestId('error.message')).toContainText('needs a triangle mesh');
  await app.byTestId('error.action').click();
  await expect.poll(async () => (await app.state()).level).toBe(1);
  // The cube triangulated (12 triangles, 18 edges), then Loop: 8 + 18 vertices, 48 triangles.
  expect(await countsShown(app)).toEqual({ vertices: 26, edges: 72, faces: 48 });
});

test('rules panel refuses invalid weights with a message; Apply stays off', async ({ app }) => {
  await app.open();
  await app.openSample('tetrahedron', 'tetrahedron.off');
  await app.chooseScheme('custom');
  await app.chooseRulePreset('loop', 'Loop');
  await app.subdivide();
  const applied = (await app.state()).customRules;
  const positions = await app.positions();
  const error = app.byTestId('rules.error');
  const apply = app.byTestId('rules.apply');
  await expect(error).toBeHidden();

  const refused = async (message: string | RegExp) => {
    await expect(error).toBeVisible();
    await expect(error).toHaveAttribute('role', 'alert');
    await expect(error).toHaveText(message);
    await expect(apply).toBeDisabled();
    await expect(app.byTestId('rules.save')).toBeDisabled();
  };
  await test.step('a formula that does not parse, named with its field', async () => {
    await app.weight('edge.end').fill('3/');
    await refused('Edge rule: each end: expression "3/": expected a number, a name or "(" but found at the end');
    await expect(app.weight('edge.end')).toHaveAttribute('aria-invalid', 'true');
  });
  await test.step('a name the rule may not use', async () => {
    await app.weight('edge.end').fill('3/(8*n)');
    await refused(/^Edge rule: each end: expression "3\/\(8\*n\)": unknown name "n" at column 6/);
  });
  await test.step('a weight that is not finite: the core says so', async () => {
    await app.weight('edge.end').fill('1/0');
    await refused('custom rules: the edge rule has a weight that is not finite (inf)');
    await expect(app.weight('edge.end')).toHaveAttribute('aria-invalid', 'false');
    await app.snapshot('rules-02-error');
    await app.panelSnapshot('rules', 'rules-panel-error');
  });
  await test.step('a stencil that does not sum to 1: the core says so; Enter does not apply', async () => {
    await app.weight('edge.end').fill('0.45');
    await refused('custom rules: the edge rule sums to 1.15, not 1');
    await app.weight('vertex.self.6').fill('0.6');
    await app.weight('edge.end').fill('3/8');
    await refused('custom rules: the vertex rule at valence 6 sums to 0.975, not 1');
    await app.weight('vertex.self.6').press('Enter');
    await expect(apply).toBeDisabled();
  });
  await test.step('the level and the applied rules did not change', async () => {
    const state = await app.state();
    expect(state.customRules).toEqual(applied);
    expect(state.level).toBe(1);
    expect(maxDifference(await app.positions(), positions)).toBe(0);
  });
  await test.step('fixing the weight clears the message; Enter applies from the keyboard', async () => {
    await expect(app.byTestId('rules.preset').locator('option:checked')).toHaveText('Loop (edited)');
    await app.weight('vertex.self.6').fill('0.625');
    await expect(error).toBeHidden();
    await app.weight('vertex.self.6').press('Enter');
    await expect
      .poll(async () => (await app.state()).customRules?.vertex?.self)
      .toEqual({
        '6': 0.625,
        default: LOOP_PRESET.vertex.self.default,
      });
    await app.rulesApplied(1);
    // 0.625 is 10/16 exactly: the same surface.
    expect(maxDifference(await app.positions(), positions)).toBe(0);
  });
});

test('save rules downloads the edited rule set; loading it applies it; a bad file is refused', async ({ app }) => {
  await app.open();
  await app.openSample('octahedron', 'octahedron.off');
  await app.chooseScheme('custom');
  await app.chooseRulePreset('loop', 'Loop');
  await app.subdivide();
  let saved = '';
  let edited: number[] = [];
  await test.step('edit, apply, save', async () => {
    await app.byTestId('rules.name').fill('Loop, flatter');
    await app.weight('edge.end').fill('0.4');
    await app.weight('edge.wing').fill('1/10');
    await app.weight('vertex.neighbour.default').fill('3/(8*n)');
    await app.weight('vertex.self.default').fill('5/8');
    await app.applyRules();
    edited = await app.positions();
    const download = await app.download('rules.save');
    expect(download.suggestedFilename()).toBe('loop-flatter.json');
    saved = readFileSync((await download.path()) ?? '', 'utf8');
    const json = JSON.parse(saved);
    expect(json).toEqual({
      ...LOOP_PRESET,
      name: 'Loop, flatter',
      vertex: {
        self: { '6': '10/16', default: '5/8' },
        neighbour: { '6': '1/16', default: '3/(8*n)' },
      },
      edge: { end: 0.4, wing: '1/10' },
    });
    expect((await app.state()).customRules).toEqual(json);
  });
  await test.step('back to the Loop preset, then load the saved file', async () => {
    await app.chooseRulePreset('loop', 'Loop');
    expect(maxDifference(await app.positions(), edited)).toBeGreaterThan(1e-3);
    await app.byTestId('rules.load.input').setInputFiles({
      name: 'loop-flatter.json',
      mimeType: 'application/json',
      buffer: Buffer.from(saved),
    });
    await expect.poll(async () => (await app.state()).customRules?.name).toBe('Loop, flatter');
    await app.rulesApplied(1);
    await expect(app.weight('edge.end')).toHaveValue('0.4');
    await expect(app.byTestId('rules.preset').locator('option:checked')).toHaveText('From file: loop-flatter.json');
    expect(maxDifference(await app.positions(), edited)).toBeLessThan(1e-15);
  });
  await test.step('Load rules… opens a file picker', async () => {
    const [chooser] = await Promise.all([app.page.waitForEvent('filechooser'), app.byTestId('rules.load').click()]);
    expect(chooser.isMultiple()).toBe(false);
    await chooser.setFiles([]);
  });
  for (const [name, text, message] of [
    ['hex.json', '{ "host": "hex" }', 'hex.json: rule set: host: expected one of pqq, ptq, dqq, sqrt3, got "hex"'],
    ['broken.json', '{ "host": ', /^broken\.json: rule set: file: not valid JSON/],
    [
      'sum.json',
      JSON.stringify({ ...LOOP_PRESET, edge: { end: 0.5, wing: 0.1 } }),
      'sum.json: custom rules: the edge rule sums to 1.2, not 1',
    ],
  ] as const) {
    await test.step(`${name} is refused with its name and the problem; the rules stay`, async () => {
      await app.byTestId('rules.load.input').setInputFiles({
        name,
        mimeType: 'application/json',
        buffer: Buffer.from(text),
      });
      await expect(app.byTestId('rules.error')).toBeVisible();
      await expect(app.byTestId('rules.error')).toHaveAttribute('role', 'alert');
      await expect(app.byTestId('rules.error')).toHaveText(message);
      const state = await app.state();
      expect(state.customRules?.name).toBe('Loop, flatter');
      expect(state.level).toBe(1);
      await expect(app.weight('edge.end')).toHaveValue('0.4');
      expect(maxDifference(await app.positions(), edited)).toBe(0);
    });
  }
});

for (const viewport of [
  { width: 1024, height: 768 },
  { width: 768, height: 1024 },
]) {
  test(`rules panel at ${viewport.width}×${viewport.height}: fits, collapses, keyboard reachable`, async ({ app }) => {
    await app.page.setViewportSize(viewport);
    await app.open();
    await app.openSample('icosahedron', 'icosahedron.off');
    await app.chooseScheme('custom');
    await app.chooseRulePreset('improved-loop', 'Improved Loop');
    const panel = app.byTestId('rules');
    await test.step('every field is inside the window once scrolled to, with an accessible name', async () => {
      const fields = panel.locator('input[type="text"]');
      const count = await fields.count();
      // name + vertex.self {3, 6, default} + vertex.neighbour {3, 6, default} + edge 2 + border 3 + 4.
      expect(count).toBe(1 + 6 + 2 + 3 + 4);
      for (let i = 0; i < count; i++) {
        const field = fields.nth(i);
        await field.scrollIntoViewIfNeeded();
        const box = await field.boundingBox();
        expect(box).not.toBeNull();
        if (!box) continue;
        expect(box.x).toBeGreaterThanOrEqual(0);
        expect(box.x + box.width).toBeLessThanOrEqual(viewport.width);
        expect(box.width).toBeGreaterThan(60);
      }
      await expect(app.weight('vertex.self.3')).toHaveAccessibleName('Vertex rule (valence n): the vertex (n = 3)');
      await expect(app.weight('border.edge.3')).toHaveAccessibleName('Border edge rule: after b');
      await expect(app.byTestId('rules.preset')).toHaveAccessibleName('Preset');
    });
    await test.step('Tab walks from the preset menu through the fields to Apply', async () => {
      await app.byTestId('rules.preset').focus();
      await app.page.keyboard.press('Tab');
      await expect(app.byTestId('rules.name')).toBeFocused();
      await app.page.keyboard.press('Tab');
      const about = app.byTestId('rules').getByText('About this rule set');
      await expect(about).toBeFocused();
      await app.page.keyboard.press('Enter');
      await expect(app.byTestId('rules.description')).toContainText('Warren');
      await app.page.keyboard.press('Tab');
      await expect(app.weight('vertex.self.3')).toBeFocused();
      await app.weight('border.edge.3').focus();
      await app.page.keyboard.press('Tab');
      await expect(app.byTestId('rules.apply')).toBeFocused();
      await app.page.keyboard.press('Tab');
      await expect(app.byTestId('rules.save')).toBeFocused();
      await app.page.keyboard.press('Tab');
      await expect(app.byTestId('rules.load')).toBeFocused();
    });
    await test.step('the panel collapses and opens again', async () => {
      await app.byTestId('rules.toggle').click();
      await expect(app.byTestId('rules.apply')).toBeHidden();
      await app.byTestId('rules.toggle').press('Enter');
      await expect(app.byTestId('rules.apply')).toBeVisible();
    });
    await app.panelSnapshot('rules', `rules-panel-${viewport.width}x${viewport.height}`);
    await app.snapshot(`rules-03-${viewport.width}x${viewport.height}`);
  });
}
