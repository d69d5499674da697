/**
 * A file with OpenSubdiv's tags: its creases and corners drawn in the
 * colours of their sharpness, counted in the facts level by level as the
 * sharpness decays, and the overlay switched off and on with K.
 */
import { readFileSync } from 'node:fs';
import { readFile } from 'node:fs/promises';
import { sharpnessColor } from '../../web/render/level-graphics';
import { expect, test } from './fixtures';

// Creases 4-5 and 5-7 of sharpness 2, 0-1 and 1-3 of 3.5; vertex 6 a corner of 4.25.
const CREASED_CUBE = readFileSync('tests/fixtures/cube-creased.obj', 'utf8');

test('a creased cube: tags in the facts, creases drawn, decaying level by level', async ({ app }) => {
  await app.open();
  await app.load('cube-creased.obj', CREASED_CUBE);
  await expect(app.byTestId('facts.tags')).toHaveText('4 creases, 1 corner');
  await expect(app.byTestId('controls.overlay-creases')).toBeChecked();
  await app.snapshot('creases-0');
  // Each step halves every sharp edge and takes one from its sharpness:
  // level 1 has the eight halves (1 and 2.5), level 2 only the halves of the
  // 2.5 ones (now 1.5), the corner 4.25 - 2.
  await app.subdivide();
  await expect(app.byTestId('facts.tags')).toHaveText('8 creases, 1 corner');
  await app.subdivide();
  await expect(app.byTestId('facts.tags')).toHaveText('8 creases, 1 corner');
  expect((await app.facts()).faces).toBe(96);
  await app.snapshot('creases-2');
  // The SVG has them too: the 8 halves of sharpness 1.5, one colour (red at 5, amber at 0:
  // 30 % of the way), in front of or behind the faces.
  await app.byTestId('export-panel').locator('summary').click();
  const svg = await readFile(await (await app.download('export.svg')).path(), 'utf8');
  const paths = [...svg.matchAll(/<path id="creases-0(-back)?"[^>]* stroke="([^"]+)"[^>]* d="([^"]*)"/g)];
  expect(paths.length).toBe(2);
  expect(paths.reduce((n, p) => n + p[3].split('M').length - 1, 0)).toBe(8);
  expect(svg).not.toContain('id="creases-1"');
  expect(paths[0][2]).toBe(`#${sharpnessColor(1.5).getHexString()}`);
  // And the corner, now of sharpness 4.25 - 2: one dot of its colour.
  const dots = [...svg.matchAll(/<g id="corners-0(-back)?" fill="([^"]+)">(.*?)<\/g>/g)];
  expect(dots.length).toBe(2);
  expect(dots.reduce((n, d) => n + d[3].split('<circle').length - 1, 0)).toBe(1);
  expect(dots[0][2]).toBe(`#${sharpnessColor(2.25).getHexString()}`);
  expect(svg).not.toContain('id="corners-1"');
  const drawn = await app.canvasPixels();
  // K hides them: the picture changes, and comes back with K again.
  await app.page.keyboard.press('k');
  await expect(app.byTestId('controls.overlay-creases')).not.toBeChecked();
  await expect.poll(async () => (await app.canvasPixels()).equals(drawn)).toBe(false);
  await app.snapshot('creases-2-hidden');
  await app.page.keyboard.press('k');
  await expect(app.byTestId('controls.overlay-creases')).toBeChecked();
  // Loop refuses quads, Doo-Sabin has no creasing rules: its levels carry no tags.
  await app.scrubTo(0);
  await app.chooseScheme('doo-sabin');
  await app.subdivide();
  await expect(app.byTestId('facts.tags')).toHaveText('–');
});

test('tags the core does not apply are named with their lines in a notice, gone with the next model', async ({
  app,
}) => {
  await app.open();
  const text = `${CREASED_CUBE}t smoothtriangles 1/0/0 1\nt facevaryingpropagatecorners 1/0/0 1\n`;
  const lines = text.split('\n').length - 1;
  await app.load('cube-notes.obj', text);
  await expect(app.byTestId('notice.message')).toHaveText(
    `cube-notes.obj loaded without some of its tags: line ${lines - 1}: tag 'smoothtriangles' is not applied; ` +
      `line ${lines}: tag 'facevaryingpropagatecorners' is not applied.`,
  );
  // The model and its applied tags are there all the same.
  await expect(app.byTestId('facts.tags')).toHaveText('4 creases, 1 corner');
  await app.load('cube-creased.obj', CREASED_CUBE);
  await expect(app.byTestId('notice')).toBeHidden();
});
