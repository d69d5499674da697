/**
 * Figures from the Export menu: the view as SVG, PDF and EPS. The PDF is
 * rendered by poppler (pdftoppm), the EPS by ghostscript and the SVG by
 * Chromium itself, each at the view's size (a CSS pixel, a point). Any
 * two of the three pictures agree on ≥ 98% of pixels within 16 levels of
 * 255 (what differs is antialiasing along the lines: ghostscript's 4×4
 * samples against poppler's and Skia's exact coverage; measured 98.6% to
 * 99.4%), and the area each draws off the background is within 1% of the
 * others'.
 */
import { execFileSync } from 'node:child_process';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { readFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { drawnPixels, type Raster, rasterEps, rasterPdf, shareWithin } from '../unit/figure-raster';
import { viewerPage } from './embed-page';
import { expect, test } from './fixtures';
import { readPng } from './helpers';

const CUBE = await readFile('public/meshes/cube.off', 'utf8');
/** The view's background, VIEW_COLORS.background. */
const BACKGROUND: [number, number, number] = [0xf3, 0xf4, 0xf6];

/** A PNG screenshot as an RGB raster. */
function pngRaster(png: Buffer): Raster {
  const info = readPng(png);
  const rgb = new Uint8Array(3 * info.width * info.height);
  for (let y = 0; y < info.height; y++) {
    for (let x = 0; x < info.width; x++) rgb.set(info.pixel(x, y).slice(0, 3), 3 * (y * info.width + x));
  }
  return { width: info.width, height: info.height, rgb };
}

test('PDF and EPS exports render as the SVG export does', async ({ app }) => {
  await app.open();
  await app.load('cube.off', CUBE);
  await app.subdivide();
  await app.byTestId('controls.overlay-control').check();
  const dir = mkdtempSync(join(tmpdir(), 'figures-e2e-'));
  const files = new Map<string, string>();
  for (const format of ['svg', 'pdf', 'eps']) {
    await test.step(`Export → ${format.toUpperCase()}`, async () => {
      await app.byTestId('export-panel').locator('summary').click();
      const download = await app.download(`export.${format}`);
      expect(download.suggestedFilename()).toBe(`cube-catmull-clark-L1.${format}`);
      const path = join(dir, download.suggestedFilename());
      await download.saveAs(path);
      files.set(format, path);
    });
  }
  const [width, height] = await app.byTestId('viewer').evaluate((e) => [e.clientWidth, e.clientHeight]);
  const svg = await readFile(files.get('svg') as string, 'utf8');
  const pdf = await readFile(files.get('pdf') as string, 'latin1');
  const eps = await readFile(files.get('eps') as string, 'latin1');

  await test.step('page sizes and polygons: the same in the three files', async () => {
    expect(execFileSync('pdfinfo', [files.get('pdf') as string], { encoding: 'utf8' })).toMatch(
      new RegExp(`Page size:\\s+${width} x ${height} pts`),
    );
    expect(eps).toContain(`\n%%BoundingBox: 0 0 ${width} ${height}\n`);
    const polygons = (svg.match(/<polygon /g) ?? []).length;
    expect(polygons).toBeGreaterThan(4);
    expect(pdf.split('\n').filter((l) => / h B$/.test(l))).toHaveLength(polygons);
    expect(eps.split('\n').filter((l) => / P$/.test(l))).toHaveLength(polygons);
    // The cage: in front of the surface and behind it, in all three.
    for (const id of ['control-mesh', 'control-mesh-back']) {
      expect(svg).toContain(`id="${id}"`);
      expect(pdf).toContain(`% ${id}\n`);
      expect(eps).toContain(`% ${id}\n`);
    }
  });

  await test.step('rendered: poppler and ghostscript against Chromium drawing the SVG', async () => {
    const page = await app.page.context().newPage();
    await page.setViewportSize({ width, height });
    await page.setContent(`<body style="margin:0">${svg}</body>`);
    const shot = await page.screenshot({ clip: { x: 0, y: 0, width, height } });
    await page.close();
    writeFileSync('test-results/screenshots/figures-svg-chromium.png', shot);
    const fromSvg = pngRaster(shot);
    const fromPdf = rasterPdf(files.get('pdf') as string, join(dir, 'pdf'));
    const fromEps = rasterEps(files.get('eps') as string, join(dir, 'eps'));
    execFileSync('pdftoppm', [
      '-r',
      '72',
      '-png',
      '-singlefile',
      files.get('pdf') as string,
      'test-results/screenshots/figures-pdf-poppler',
    ]);
    for (const r of [fromPdf, fromEps]) expect([r.width, r.height]).toEqual([width, height]);
    const shares = {
      pdfSvg: shareWithin(fromPdf, fromSvg, 16),
      epsSvg: shareWithin(fromEps, fromSvg, 16),
      pdfEps: shareWithin(fromPdf, fromEps, 16),
    };
    test.info().annotations.push({ type: 'shares within 16 levels', description: JSON.stringify(shares) });
    for (const share of Object.values(shares)) expect(share).toBeGreaterThanOrEqual(0.98);
    const [svgArea, pdfArea, epsArea] = [fromSvg, fromPdf, fromEps].map((r) => drawnPixels(r, BACKGROUND));
    expect(svgArea).toBeGreaterThan(0.1 * width * height);
    for (const area of [pdfArea, epsArea]) expect(Math.abs(area / svgArea - 1)).toBeLessThan(0.01);
  });

  await test.step('transparent: no background in the PDF and EPS', async () => {
    await app.byTestId('export-panel').locator('summary').click();
    await app.byTestId('export.transparent').check();
    for (const format of ['pdf', 'eps']) {
      // A download closes the menu; the first one is still open.
      if (format === 'eps') await app.byTestId('export-panel').locator('summary').click();
      const text = await readFile(await (await app.download(`export.${format}`)).path(), 'latin1');
      expect(text).not.toMatch(/ re f\n| rectfill\n/);
      expect(text).toContain('% faces\n');
    }
  });
});

test('<subdiv-viewer>: exportPdf and exportEps give the figure of exportSvg', async ({ embed, page }) => {
  await embed.serve(
    'e2e/figures.html',
    viewerPage(
      'Figures',
      'subdiv-viewer{width:480px;height:360px}',
      '<subdiv-viewer id="f" src="../meshes/cube.off" levels="1"></subdiv-viewer>',
    ),
  );
  await page.goto('./e2e/figures.html');
  await embed.waitForLevel('f', 1);
  const files = await page.locator('#f').evaluate((e) => {
    const viewer = e as HTMLElementTagNameMap['subdiv-viewer'];
    return { svg: viewer.exportSvg(), pdf: Array.from(viewer.exportPdf(true)), eps: viewer.exportEps() };
  });
  const pdf = Buffer.from(files.pdf).toString('latin1');
  const polygons = (files.svg.match(/<polygon /g) ?? []).length;
  expect(polygons).toBeGreaterThan(4);
  expect(pdf.startsWith('%PDF-1.4\n')).toBe(true);
  // The page is the view's (the element's canvas, below its caption), as the SVG's.
  const [, width, height] = /<svg [^>]*width="(\d+)" height="(\d+)"/.exec(files.svg) ?? [];
  expect(Number(width)).toBe(480);
  expect(pdf).toContain(`/MediaBox [0 0 ${width} ${height}]`);
  expect(pdf).not.toContain(' re f\n');
  expect(pdf.split('\n').filter((l) => / h B$/.test(l))).toHaveLength(polygons);
  expect(files.eps).toContain(`\n%%BoundingBox: 0 0 ${width} ${height}\n`);
  expect(files.eps.split('\n').filter((l) => / P$/.test(l))).toHaveLength(polygons);
});
