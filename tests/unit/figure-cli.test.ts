/**
 * `subdiv figure` as a user runs it (node bin/subdiv.mjs, the bundle built
 * by `npx vite build --config vite.cli.config.ts`): the cube at
 * Catmull-Clark level 1 as SVG, PDF and EPS, the files' structure, the
 * polygons drawn counted against the faces that face the camera, and the
 * PDF and EPS rendered by poppler and ghostscript compared with each
 * other and with the SVG's polygons.
 *
 * Tolerances: the PDF and EPS rasters agree on ≥ 98% of pixels within 16
 * levels of 255 (antialiasing along the lines differs: ghostscript's 4×4
 * samples against poppler's exact coverage; measured 99.4%), on ≥ 99%
 * within 8 levels without the edges (flat, measured 99.7%); the silhouette each draws (pixels off
 * the background) is within 1% of the area of the SVG's polygons (the cube
 * is convex, so its facing polygons tile the silhouette); at the centre of
 * each SVG polygon both rasters show its fill within 2 levels.
 */
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';
import { initNode } from '../../web/core/init-node';
import { parseMesh, subdivide } from '../../web/core/subdiv-core';
import { drawnPixels, pixel, rasterEps, rasterPdf, shareWithin } from './figure-raster';
import { FIXTURES_DIR } from './test-helpers';

const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const BIN = join(ROOT, 'bin', 'subdiv.mjs');
const CUBE = join(FIXTURES_DIR, 'cube.off');
const CREASED = join(FIXTURES_DIR, 'cube-creased.obj');
const BACKGROUND: [number, number, number] = [0xf3, 0xf4, 0xf6];

function subdiv(args: string[]) {
  const r = spawnSync(process.execPath, [BIN, ...args], { cwd: ROOT, encoding: 'utf8' });
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

let work = '';
beforeAll(() => {
  work = mkdtempSync(join(tmpdir(), 'subdiv-figure-'));
  // The level the figures show, as a mesh file: the faces to count against.
  expect(subdiv([CUBE, '--levels', '1', '-o', join(work, 'cube1.off')]).status).toBe(0);
});

/** `subdiv figure` of the cube at level 1 into `name` with `extra` options; its JSON report. */
function figure(name: string, extra: string[] = []) {
  const r = subdiv(['figure', CUBE, '--levels', '1', ...extra, '-o', join(work, name)]);
  expect(r.stderr).toBe('');
  expect(r.status).toBe(0);
  return JSON.parse(r.stdout) as { polygons: number; view: string; width: number; height: number; edgeOpacity: number };
}

/** Faces of an OFF whose front the eye sees: (eye − centroid) · Newell normal > 0. */
function facingFaces(offText: string, eye: number[]): number {
  const lines = offText.split('\n').filter((l) => l.trim() !== '' && !l.startsWith('#'));
  const [nv, nf] = lines[1].trim().split(/\s+/).map(Number);
  const p = lines.slice(2, 2 + nv).map((l) => l.trim().split(/\s+/).map(Number));
  let count = 0;
  for (const line of lines.slice(2 + nv, 2 + nv + nf)) {
    const f = line.trim().split(/\s+/).map(Number).slice(1);
    const n = [0, 0, 0];
    const c = [0, 0, 0];
    f.forEach((a, k) => {
      const [A, B] = [p[a], p[f[(k + 1) % f.length]]];
      n[0] += (A[1] - B[1]) * (A[2] + B[2]);
      n[1] += (A[2] - B[2]) * (A[0] + B[0]);
      n[2] += (A[0] - B[0]) * (A[1] + B[1]);
      for (let i = 0; i < 3; i++) c[i] += A[i] / f.length;
    });
    if ((eye[0] - c[0]) * n[0] + (eye[1] - c[1]) * n[1] + (eye[2] - c[2]) * n[2] > 0) count++;
  }
  return count;
}

/** The SVG's polygons: points and fill. */
function svgPolygons(svg: string): { xy: number[][]; fill: number[] }[] {
  return [...svg.matchAll(/<polygon points="([^"]*)" fill="#(\w{6})"\/>/g)].map((m) => ({
    xy: m[1].split(' ').map((pair) => pair.split(',').map(Number)),
    fill: [0, 2, 4].map((i) => Number.parseInt(m[2].slice(i, i + 2), 16)),
  }));
}

function area(xy: number[][]): number {
  let twice = 0;
  xy.forEach(([x0, y0], k) => {
    const [x1, y1] = xy[(k + 1) % xy.length];
    twice += x0 * y1 - x1 * y0;
  });
  return Math.abs(twice) / 2;
}

describe('subdiv figure', () => {
  it('the cube at level 1 as SVG, PDF and EPS: 800×600, the facing faces drawn once each, alike when rendered', () => {
    const reports = ['cube.svg', 'cube.pdf', 'cube.eps'].map((name) => figure(name));
    // The same camera (the app's first view, framed by Fit) for all three.
    expect(new Set(reports.map((r) => r.view)).size).toBe(1);
    const eye = reports[0].view.split(',').map(Number).slice(0, 3);
    const facing = facingFaces(readFileSync(join(work, 'cube1.off'), 'utf8'), eye);
    expect(facing).toBeGreaterThan(4);
    expect(facing).toBeLessThan(24);

    const svg = readFileSync(join(work, 'cube.svg'), 'utf8');
    const pdf = readFileSync(join(work, 'cube.pdf'), 'latin1');
    const eps = readFileSync(join(work, 'cube.eps'), 'latin1');
    expect(svg).toMatch(/^<svg [^>]*width="800" height="600" viewBox="0 0 800 600">/);
    const info = spawnSync('pdfinfo', [join(work, 'cube.pdf')], { encoding: 'utf8' });
    expect(info.status).toBe(0);
    // poppler says nothing about the file's structure (a bad xref or length is a "Syntax Error" here).
    expect(info.stderr).toBe('');
    expect(info.stdout).toMatch(/Pages:\s+1\n/);
    expect(info.stdout).toMatch(/Page size:\s+800 x 600 pts/);
    expect(info.stdout).toMatch(/Title:\s+cube\.off, Catmull-Clark, level 1/);
    expect(eps.split('\n').slice(0, 2)).toEqual(['%!PS-Adobe-3.0 EPSF-3.0', '%%BoundingBox: 0 0 800 600']);
    // One polygon each per facing face: <polygon> in SVG, a line ending "B" (fill, stroke) in PDF, "P" in EPS.
    expect(svgPolygons(svg)).toHaveLength(facing);
    expect(pdf.split('\n').filter((l) => / h B$/.test(l))).toHaveLength(facing);
    expect(eps.split('\n').filter((l) => / P$/.test(l))).toHaveLength(facing);
    for (const r of reports) expect(r.polygons).toBe(facing);

    const fromPdf = rasterPdf(join(work, 'cube.pdf'), join(work, 'cube-pdf'));
    const fromEps = rasterEps(join(work, 'cube.eps'), join(work, 'cube-eps'));
    expect([fromPdf.width, fromPdf.height, fromEps.width, fromEps.height]).toEqual([800, 600, 800, 600]);
    expect(shareWithin(fromPdf, fromEps, 16)).toBeGreaterThanOrEqual(0.98);
    expect(pixel(fromPdf, 3, 3)).toEqual(BACKGROUND);
    expect(pixel(fromEps, 3, 3)).toEqual(BACKGROUND);
  });

  it('flat: the PDF and EPS silhouettes within 1% of the SVG polygons’ area, each polygon’s fill at its centre', () => {
    figure('flat.svg', ['--mode', 'flat']);
    figure('flat.pdf', ['--mode', 'flat']);
    figure('flat.eps', ['--mode', 'flat']);
    const polygons = svgPolygons(readFileSync(join(work, 'flat.svg'), 'utf8'));
    const svgArea = polygons.reduce((sum, p) => sum + area(p.xy), 0);
    expect(svgArea).toBeGreaterThan(0.2 * 800 * 600);
    const rasters = [
      rasterPdf(join(work, 'flat.pdf'), join(work, 'flat-pdf')),
      rasterEps(join(work, 'flat.eps'), join(work, 'flat-eps')),
    ];
    expect(shareWithin(rasters[0], rasters[1], 8)).toBeGreaterThanOrEqual(0.99);
    for (const r of rasters) {
      expect(Math.abs(drawnPixels(r, BACKGROUND) / svgArea - 1)).toBeLessThan(0.01);
      for (const p of polygons) {
        // The vertex mean lies inside a convex polygon.
        const [x, y] = [0, 1].map((i) => p.xy.reduce((s, q) => s + q[i], 0) / p.xy.length);
        const got = pixel(r, Math.floor(x), Math.floor(y));
        for (let c = 0; c < 3; c++) expect(Math.abs(got[c] - p.fill[c])).toBeLessThanOrEqual(2);
      }
    }
  });

  it('--view front and a camera string; wireframe draws every edge; --transparent has no background', () => {
    const front = figure('front.svg', ['--view', 'front', '--size', '400x300']);
    const [px, py, pz, tx, ty, tz] = front.view.split(',').map(Number);
    expect([px, py, tx, ty, tz]).toEqual([0, 0, 0, 0, 0]);
    expect(pz).toBeGreaterThan(2);
    expect(readFileSync(join(work, 'front.svg'), 'utf8')).toMatch(/width="400" height="300"/);
    const camera = '0,0,5,0,0,0,0,1,0';
    const given = figure('given.pdf', ['--view', camera]);
    expect(given.view).toBe(camera);
    expect(given.polygons).toBe(facingFaces(readFileSync(join(work, 'cube1.off'), 'utf8'), [0, 0, 5]));
    figure('wire.eps', ['--mode', 'wireframe']);
    const wire = readFileSync(join(work, 'wire.eps'), 'utf8').split('\n');
    // Catmull-Clark level 1 of the cube: 48 edges, none hidden.
    expect(wire.filter((l) => / M .* L$/.test(l))).toHaveLength(48);
    expect(wire.filter((l) => / P$/.test(l))).toHaveLength(0);
    const wideReport = figure('wide.pdf', ['--line-width', '2', '--control-mesh']);
    const wide = readFileSync(join(work, 'wide.pdf'), 'latin1');
    // The edges at the setting, the cage at 1.5 times it (line-style.ts); edges 2 px wide crowd
    // sooner, so they fade a little, through the stroking alpha of /GS0.
    expect(wideReport.edgeOpacity).toBeLessThan(1);
    expect(wide).toContain(`/GS0 << /Type /ExtGState /CA ${Math.round(wideReport.edgeOpacity * 100) / 100} >>`);
    expect(wide).toContain('% faces\nq\n/GS0 gs 0.122 0.176 0.239 RG 2 w 1 j\n');
    expect(wide).toContain('% control-mesh\nq\n0.91 0.349 0.047 RG 3 w 1 J 1 j\n');
    figure('clear.pdf', ['--transparent', '--control-mesh']);
    const clear = readFileSync(join(work, 'clear.pdf'), 'latin1');
    expect(clear).not.toContain(' re f');
    expect(clear).toContain('% control-mesh-back');
  });

  it("a tagged file's creases and corners as the app shows them, and --curves: every one drawn, in front or behind", async () => {
    await initNode();
    const level = subdivide(parseMesh(readFileSync(CREASED), 'obj'), { scheme: 'catmull-clark', levels: 2 });
    const tags = level.tags;
    expect(tags?.creaseSharpness.length).toBeGreaterThan(0);
    const r = subdiv(['figure', CREASED, '--levels', '2', '--curves', '-o', join(work, 'creased.svg')]);
    expect(r.status).toBe(0);
    const svg = readFileSync(join(work, 'creased.svg'), 'utf8');
    const segments = (prefix: string) =>
      [...svg.matchAll(/<path id="([^"]+)"[^>]* d="([^"]*)"\/>/g)]
        .filter((m) => m[1].startsWith(prefix))
        .reduce((sum, m) => sum + (m[2].match(/M/g) ?? []).length, 0);
    expect(segments('creases-')).toBe(tags?.creaseSharpness.length);
    expect(segments('control-curves')).toBe(level.controlEdges.length / 2);
    expect((svg.match(/<circle /g) ?? []).length).toBe(tags?.cornerSharpness.length);
  });

  it('a dense cage fades as the app draws it, by its own edges; the cube’s stays solid', () => {
    // A 60 × 60 quad grid: its cage's edges are a few pixels long in 800 × 600.
    const n = 60;
    const vertices: string[] = [];
    const faces: string[] = [];
    for (let j = 0; j <= n; j++) for (let i = 0; i <= n; i++) vertices.push(`${i / n} ${j / n} 0`);
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n; i++) {
        const a = j * (n + 1) + i;
        faces.push(`4 ${a} ${a + 1} ${a + n + 2} ${a + n + 1}`);
      }
    }
    const grid = join(work, 'grid60.off');
    writeFileSync(grid, `OFF\n${vertices.length} ${faces.length} 0\n${vertices.join('\n')}\n${faces.join('\n')}\n`);
    const r = subdiv(['figure', grid, '--levels', '1', '--control-mesh', '-o', join(work, 'grid.svg')]);
    expect(r.status).toBe(0);
    const svg = readFileSync(join(work, 'grid.svg'), 'utf8');
    const cageOpacity = (text: string) =>
      Number(/<path id="control-mesh" [^>]*?stroke-opacity="([\d.]+)"/.exec(text)?.[1] ?? 1);
    const edges = Number(/<g id="faces" [^>]*stroke-opacity="([\d.]+)"/.exec(svg)?.[1]);
    // The cage's edges are twice its level's: fainter than solid, less faint than the level's.
    expect(cageOpacity(svg)).toBeLessThan(0.9);
    expect(cageOpacity(svg)).toBeGreaterThan(edges);
    expect(cageOpacity(svg)).toBeCloseTo(Math.min(1, edges * Math.SQRT2), 1);
    figure('cube-cage.svg', ['--control-mesh']);
    expect(readFileSync(join(work, 'cube-cage.svg'), 'utf8')).toMatch(
      /<path id="control-mesh" (?![^>]*stroke-opacity)/,
    );
  });

  it('bad usage: unknown view or mode, another extension, no -o: exit 2 with the reason', () => {
    const cases: [string[], RegExp][] = [
      [['--view', 'under', '-o', 'x.svg'], /--view must be front, top, side, iso or a camera/],
      [['--mode', 'zebra', '-o', 'x.svg'], /--mode must be edges, flat, smooth, wireframe/],
      [['-o', 'x.png'], /figure file x.png must end in .svg, .pdf or .eps/],
      [[], /subdiv figure needs -o OUT.svg/],
      [['--size', '800', '-o', 'x.svg'], /--size must be WIDTHxHEIGHT/],
      [['--stats', '-o', 'x.svg'], /subdiv figure takes no --stats/],
    ];
    for (const [args, message] of cases) {
      const r = subdiv(['figure', CUBE, ...args]);
      expect(r.status).toBe(2);
      expect(r.stderr).toMatch(message);
    }
    expect(subdiv([CUBE, '--view', 'front']).stderr).toMatch(/--view belongs to another command/);
  });
});
