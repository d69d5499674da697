/**
 * <subdiv-viewer> and the iframe route as a teacher's page uses them: the
 * shipped teaching example, and a test page with twelve elements and an
 * iframe. Counts are checked against the schemes' refinement rules
 * (helpers.ts), never against the app's own code.
 */
import { expect, test } from './fixtures';
import { expectedClosedCounts } from './helpers';

const OCTAHEDRON = { vertices: 6, edges: 12, faces: 8 };

test('the teaching example: four schemes on the octahedron, counts in the table from level-change events', async ({
  embed,
  page,
}) => {
  await page.setViewportSize({ width: 1100, height: 900 });
  await page.goto('./examples/');
  const viewers = { cc: 'catmull-clark', loop: 'loop', ds: 'doo-sabin', sqrt3: 'sqrt3' } as const;
  for (const [id, scheme] of Object.entries(viewers)) {
    await test.step(`${scheme} reaches level 2 with its exact counts`, async () => {
      await page.locator(`#${id}`).scrollIntoViewIfNeeded();
      const reading = await embed.waitForLevel(id, 2);
      const want = expectedClosedCounts(scheme, OCTAHEDRON, 2);
      expect(reading.facts).toMatchObject({ ...want, genus: 0, closed: true });
      const event = await embed.lastLevelChange(id);
      expect(event?.detail).toMatchObject({ level: 2, scheme, facts: want });
      const cells = await page.locator(`#counts tr[data-viewer="${id}"] td`).allTextContents();
      expect(cells.slice(1).map(Number)).toEqual([2, want.vertices, want.edges, want.faces, 0]);
    });
  }
  await test.step('the iframe shows the torus at level 1', async () => {
    const frame = page.frameLocator('#torus-frame');
    await page.locator('#torus-frame').scrollIntoViewIfNeeded();
    await expect(frame.locator('subdiv-viewer')).toHaveAttribute('levels', '1');
    await expect
      .poll(() =>
        page
          .frame({ url: /embed\.html/ })
          ?.evaluate(() => (document.querySelector('subdiv-viewer') as HTMLElementTagNameMap['subdiv-viewer']).level),
      )
      .toBe(1);
  });
  await page.evaluate(() => window.scrollTo(0, 0));
  await embed.snapshot('embed-example-page');
  await embed.snapshot('embed-example-page-full', true);
});
