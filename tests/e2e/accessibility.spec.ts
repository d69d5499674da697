/**
 * axe-core (Deque's accessibility engine, the rules of WCAG 2.1 A and AA
 * and its best practices) finds no violation in the app's main states: empty,
 * a model with levels, the zebra and curvature modes with the colour bar,
 * saved views, the custom rules, open menus, an error, side by side with
 * Inspect's results, the halfedge explorer with its Euler operators and
 * √3 by hand, and a phone.
 */
import { readFileSync } from 'node:fs';
import AxeBuilder from '@axe-core/playwright';
import type { Page } from '@playwright/test';
import { expect, test } from './fixtures';

const CUBE = readFileSync('public/meshes/cube.off', 'utf8');

/** Runs axe on the page and fails with each violation's rule, impact and first elements. */
async function expectNoViolations(page: Page, state: string): Promise<void> {
  const results = await new AxeBuilder({ page })
    .withTags(['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa', 'best-practice'])
    .analyze();
  const found = results.violations.map(
    (v) =>
      `${v.id} (${v.impact}): ${v.help} — ${v.nodes
        .slice(0, 3)
        .map((n) => n.target.join(' '))
        .join('; ')}`,
  );
  expect(found, `axe violations with ${state}`).toEqual([]);
  // Rules that ran: a check that axe looked at the page at all.
  expect(results.passes.length, state).toBeGreaterThan(20);
}

test('no axe violations: empty, a model with levels, the rules, open menus, an error', async ({ app }) => {
  test.setTimeout(120_000);
  await app.open();
  await expectNoViolations(app.page, 'the empty app');
  await app.load('cube.off', CUBE);
  await app.subdivide();
  await app.subdivide();
  await expectNoViolations(app.page, 'the cube at level 2');
  for (const mode of ['zebra', 'mean-curvature']) {
    await app.byTestId('controls.render-mode').selectOption(mode);
    await expectNoViolations(app.page, `the ${mode} mode`);
  }
  await expect(app.page.getByText(/^Mean curvature H/)).toBeVisible();
  await app.byTestId('view.top').click();
  await app.byTestId('view.save').click();
  await app.byTestId('view.save').click();
  await expect(app.byTestId('view.saved').locator('option')).toHaveCount(2);
  await expectNoViolations(app.page, 'two saved views');
  await app.chooseScheme('custom');
  await expectNoViolations(app.page, 'the custom rules');
  await app.byTestId('gallery').locator('summary').click();
  await expectNoViolations(app.page, 'the samples menu open');
  await app.page.keyboard.press('Escape');
  await app.dropFile('broken.off', 'OFF\n3 1 0\n0 0 0\n1 0 0\n');
  await expect(app.errorBanner).toBeVisible();
  await expectNoViolations(app.page, 'an error shown');
});

test('no axe violations: side by side with distances, the results of Inspect, a phone', async ({ app }) => {
  test.setTimeout(120_000);
  await app.open();
  await app.load('cube.off', CUBE);
  await app.subdivide();
  await app.byTestId('inspect.run').click();
  await expect(app.byTestId('inspect.self-intersections')).toHaveText(/^none · /);
  await app.idle();
  await expectNoViolations(app.page, 'Inspect’s results');
  await app.byTestId('side.count').selectOption('2');
  await expect.poll(async () => app.page.getByTestId('pane.1.scheme').count()).toBe(1);
  await app.idle();
  await expectNoViolations(app.page, 'two panes side by side');
  await app.page.setViewportSize({ width: 390, height: 844 });
  await expectNoViolations(app.page, 'a phone');
});

test('no axe violations: the halfedge explorer, a split face, √3 by hand, the size refusal', async ({ app }) => {
  test.setTimeout(120_000);
  await app.open();
  await app.openSample('tetrahedron', 'tetrahedron.off');
  await app.byTestId('halfedges.explore').click();
  await app.byTestId('halfedges.number').fill('0');
  await app.byTestId('halfedges.number').press('Enter');
  await app.byTestId('halfedges.circulate-vertex').click();
  await expect(app.byTestId('halfedges.report')).toHaveText(/3 halfedges around it$/);
  await expectNoViolations(app.page, 'the explorer with a circulated vertex');
  await app.byTestId('euler.split_edge').click();
  await expect(app.byTestId('euler.outcome')).toContainText('split_edge: V 5');
  await app.byTestId('euler.flip_edge').click();
  await expect(app.byTestId('euler.problem')).toBeVisible();
  await expectNoViolations(app.page, 'an Euler operator done and one refused');
  await app.byTestId('euler.undo').click();
  await app.byTestId('sqrt3.step').click();
  await expect(app.byTestId('sqrt3.progress')).toHaveText(/^1 \/ 14 operators/);
  await expectNoViolations(app.page, 'the √3 walk-through under way');
  await app.byTestId('euler.undo').click();
  await expect.poll(async () => (await app.facts()).faces).toBe(4);
  // Catmull-Clark's level 5 of the tetrahedron: 12,288 quads.
  for (let i = 0; i < 5; ++i) await app.subdivide();
  await expect(app.byTestId('halfedges.message')).toContainText('shows meshes up to 5,000 halfedges');
  await expectNoViolations(app.page, 'the explorer refusing a large level');
});
