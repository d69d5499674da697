/**
 * Exported pictures are framed on the model: the view shifts its
 * projection so that the model clears the facts panel over it, but the
 * panel is not in a PNG or an SVG, so they are drawn without that shift
 * and the model is in their middle (it was 19 % of the width to the right).
 */
import { readFileSync } from 'node:fs';
import { readFile } from 'node:fs/promises';
import { expect, test } from './fixtures';
import { type PngInfo, readPng } from './helpers';

const CUBE = readFileSync('public/meshes/cube.off', 'utf8');

/** The box of the pixels whose colour is not the background's (the corner's), as fractions of the picture. */
function modelBox(png: PngInfo): { x0: number; y0: number; x1: number; y1: number } {
  const bg = png.pixel(0, 0);
  let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
  for (let y = 0; y < png.height; ++y)
    for (let x = 0; x < png.width; ++x) {
      const p = png.pixel(x, y);
      if (Math.abs(p[0] - bg[0]) + Math.abs(p[1] - bg[1]) + Math.abs(p[2] - bg[2]) <= 24) continue;
      x0 = Math.min(x0, x);
      y0 = Math.min(y0, y);
      x1 = Math.max(x1, x + 1);
      y1 = Math.max(y1, y + 1);
    }
  return { x0: x0 / png.width, y0: y0 / png.height, x1: x1 / png.width, y1: y1 / png.height };
}

test('PNG (×1, ×2) and SVG exports have the model in their middle, not where the facts panel leaves room', async ({
  app,
}) => {
  await app.open();
  await app.load('cube.off', CUBE);
  await app.subdivide();
  await app.subdivide();
  // On screen the model is shifted right of the facts panel.
  const { viewOffset } = await app.state();
  expect(viewOffset[0]).toBeGreaterThan(0.2);
  const size = await app.byTestId('viewer').evaluate((e) => [e.clientWidth, e.clientHeight]);

  for (const scale of ['1', '2']) {
    await test.step(`PNG ×${scale}`, async () => {
      await app.byTestId('export-panel').locator('summary').click();
      await app.byTestId('export.scale').selectOption(scale);
      const png = readPng(await readFile(await (await app.download('export.png')).path()));
      expect([png.width, png.height]).toEqual(size.map((s) => Number(scale) * s));
      const box = modelBox(png);
      // The model is there, and not the whole picture.
      expect(box.x1 - box.x0).toBeGreaterThan(0.2);
      expect(box.x1 - box.x0).toBeLessThan(0.9);
      expect(Math.abs((box.x0 + box.x1) / 2 - 0.5)).toBeLessThan(0.05);
      expect(Math.abs((box.y0 + box.y1) / 2 - 0.5)).toBeLessThan(0.05);
    });
  }

  await test.step('SVG: the box of its polygons', async () => {
    await app.byTestId('export-panel').locator('summary').click();
    const svg = await readFile(await (await app.download('export.svg')).path(), 'utf8');
    const [, , width, height] = (/viewBox="([^"]+)"/.exec(svg)?.[1] ?? '').split(' ').map(Number);
    expect([width, height]).toEqual(size);
    const xy = [...svg.matchAll(/<polygon points="([^"]+)"/g)].flatMap((m) =>
      m[1].split(' ').map((pair) => pair.split(',').map(Number)),
    );
    // About half of level 2's 96 quads face the camera, four corners each.
    expect(xy.length).toBeGreaterThan(100);
    const xs = xy.map((p) => p[0]);
    const ys = xy.map((p) => p[1]);
    const cx = (Math.min(...xs) + Math.max(...xs)) / 2 / width;
    const cy = (Math.min(...ys) + Math.max(...ys)) / 2 / height;
    expect(Math.abs(cx - 0.5)).toBeLessThan(0.05);
    expect(Math.abs(cy - 0.5)).toBeLessThan(0.05);
  });
});
