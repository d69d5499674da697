/**
 * The figure writers on a tiny figure: the exact SVG, the PDF's content
 * stream operators and cross-reference table, the EPS's lines, and the
 * PDF and EPS drawn by poppler and ghostscript.
 */
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { inflateSync } from 'node:zlib';
import { describe, expect, it } from 'vitest';
import type { Figure } from '../../web/render/figure';
import { figureEps } from '../../web/render/figure-eps';
import { figureContentStream, figurePdf, PLAIN_STREAM_BYTES } from '../../web/render/figure-pdf';
import { figureSvg } from '../../web/render/svg-export';
import { pixel, rasterEps, rasterPdf } from './figure-raster';

/** A red triangle stroked black at half opacity, a blue line across, a green dot: 100 × 50 on white. */
const TINY: Figure = {
  width: 100,
  height: 50,
  background: '#ffffff',
  layers: [
    {
      kind: 'polygons',
      id: 'faces',
      polygons: [{ points: [10, 10, 90, 10, 50, 40], fill: '#ff0000' }],
      stroke: { color: '#000000', width: 2, opacity: 0.5 },
    },
    {
      kind: 'lines',
      id: 'control-mesh',
      stroke: { color: '#0000ff', width: 1.5, opacity: 1 },
      segments: [0, 0, 100, 50],
    },
    { kind: 'dots', id: 'corners-0', color: '#00ff00', radius: 5, centres: [50, 25] },
  ],
};

describe('figure writers', () => {
  it('SVG: one polygon, one path, one circle, as the SVG export writes them', () => {
    expect(figureSvg(TINY).split('\n')).toEqual([
      '<svg xmlns="http://www.w3.org/2000/svg" width="100" height="50" viewBox="0 0 100 50">',
      '<rect width="100" height="50" fill="#ffffff"/>',
      '<g id="faces" stroke="#000000" stroke-width="2" stroke-opacity="0.5" stroke-linejoin="round">',
      '<polygon points="10,10 90,10 50,40" fill="#ff0000"/>',
      '</g>',
      '<path id="control-mesh" fill="none" stroke="#0000ff" stroke-width="1.5" stroke-linecap="round" d="M0 0L100 50"/>',
      '<g id="corners-0" fill="#00ff00"><circle cx="50" cy="25" r="5"/></g>',
      '</svg>',
      '',
    ]);
  });

  it('PDF: the content stream, operator by operator', () => {
    const states: number[] = [];
    const stream = figureContentStream(TINY, (a) => {
      states.push(a);
      return 'GS0';
    });
    expect(states).toEqual([0.5]);
    expect(stream.split('\n')).toEqual([
      '1 0 0 -1 0 50 cm',
      '1 1 1 rg 0 0 100 50 re f',
      '% faces',
      'q',
      '/GS0 gs 0 0 0 RG 2 w 1 j',
      '1 0 0 rg 10 10 m 90 10 l 50 40 l h B',
      'Q',
      '% control-mesh',
      'q',
      '0 0 1 RG 1.5 w 1 J 1 j',
      '0 0 m 100 50 l',
      'S',
      'Q',
      '% corners-0',
      'q',
      '0 1 0 rg',
      '55 25 m 55 27.76 52.76 30 50 30 c 47.24 30 45 27.76 45 25 c 45 22.24 47.24 20 50 20 c 52.76 20 55 22.24 55 25 c h f',
      'Q',
      '',
    ]);
  });

  it('PDF: header, objects where the cross-reference table says, trailer, a transparent page without the rectangle', () => {
    const bytes = figurePdf({ ...TINY, background: null }, 'tiny (test)');
    const text = Buffer.from(bytes).toString('latin1');
    expect(text.startsWith('%PDF-1.4\n')).toBe(true);
    expect(text.endsWith('%%EOF\n')).toBe(true);
    const startxref = Number(/startxref\n(\d+)\n%%EOF\n$/.exec(text)?.[1]);
    expect(text.slice(startxref, startxref + 5)).toBe('xref\n');
    const rows = text.slice(startxref).split('\n').slice(3, 8);
    rows.forEach((row, i) => {
      expect(row).toMatch(/^\d{10} 00000 n $/);
      expect(text.slice(Number(row.slice(0, 10))).startsWith(`${i + 1} 0 obj\n`)).toBe(true);
    });
    expect(text).toContain('/MediaBox [0 0 100 50]');
    expect(text).toContain('/GS0 << /Type /ExtGState /CA 0.5 >>');
    expect(text).toContain('/Title (tiny \\(test\\))');
    expect(text).not.toContain(' re f');
    const length = Number(/\/Length (\d+) >>\nstream\n/.exec(text)?.[1]);
    const start = text.indexOf('stream\n') + 7;
    expect(text.slice(start + length)).toMatch(/^endstream\n/);
  });

  it('PDF: a long content stream is deflated, inflates to the same operators and renders', () => {
    // A checkerboard of 160 × 120 squares, each a polygon: about 1 MB of operators.
    const polygons = [];
    for (let y = 0; y < 120; y++) {
      for (let x = 0; x < 160; x++) {
        const [a, b] = [5 * x, 5 * y];
        polygons.push({
          points: [a, b, a + 5, b, a + 5, b + 5, a, b + 5],
          fill: (x + y) % 2 ? '#000000' : '#ffff00',
        });
      }
    }
    const board: Figure = {
      width: 800,
      height: 600,
      background: null,
      layers: [{ kind: 'polygons', id: 'faces', polygons, stroke: null }],
    };
    const plain = figureContentStream(board, () => 'GS0');
    expect(plain.length).toBeGreaterThan(PLAIN_STREAM_BYTES);
    const bytes = figurePdf(board);
    const text = Buffer.from(bytes).toString('latin1');
    const header = /<< \/Length (\d+) \/Filter \/FlateDecode >>\nstream\n/.exec(text);
    expect(header).not.toBeNull();
    const start = (header?.index ?? 0) + (header?.[0].length ?? 0);
    const stream = bytes.subarray(start, start + Number(header?.[1]));
    expect(inflateSync(stream).toString('latin1')).toBe(plain);
    expect(bytes.length).toBeLessThan(plain.length / 4);
    const dir = mkdtempSync(join(tmpdir(), 'figure-board-'));
    writeFileSync(join(dir, 'board.pdf'), bytes);
    const r = rasterPdf(join(dir, 'board.pdf'), join(dir, 'board'));
    expect(pixel(r, 2, 2)).toEqual([255, 255, 0]);
    expect(pixel(r, 7, 2)).toEqual([0, 0, 0]);
    expect(pixel(r, 797, 597)).toEqual([255, 255, 0]);
  });

  it('EPS: header, BoundingBox, one line per polygon with the faded stroke mixed into its fill', () => {
    const lines = figureEps(TINY).split('\n');
    expect(lines.slice(0, 3)).toEqual([
      '%!PS-Adobe-3.0 EPSF-3.0',
      '%%BoundingBox: 0 0 100 50',
      '%%HiResBoundingBox: 0 0 100 50',
    ]);
    const body = lines.slice(lines.indexOf('0 50 translate 1 -1 scale') + 1);
    expect(body).toEqual([
      '1 1 1 setrgbcolor 0 0 100 50 rectfill',
      '% faces',
      '2 setlinewidth 1 setlinejoin',
      // Black at half opacity over red: dark red, opaque.
      '1 0 0 0.5 0 0 10 10 M 90 10 L 50 40 L P',
      '% control-mesh',
      '0 0 1 setrgbcolor 1.5 setlinewidth 1 setlinecap',
      'newpath',
      '0 0 M 100 50 L',
      'stroke',
      '% corners-0',
      '0 1 0 setrgbcolor',
      'newpath 50 25 5 D',
      'grestore',
      'showpage',
      '%%EOF',
      '',
    ]);
  });

  it('poppler and ghostscript draw both files alike: background, fill, stroke, line and dot where they belong', () => {
    const dir = mkdtempSync(join(tmpdir(), 'figure-writers-'));
    writeFileSync(join(dir, 'tiny.pdf'), figurePdf(TINY));
    writeFileSync(join(dir, 'tiny.eps'), figureEps(TINY));
    const rasters = [
      rasterPdf(join(dir, 'tiny.pdf'), join(dir, 'pdf')),
      rasterEps(join(dir, 'tiny.eps'), join(dir, 'eps')),
    ];
    for (const r of rasters) {
      expect([r.width, r.height]).toEqual([100, 50]);
      expect(pixel(r, 95, 45)).toEqual([255, 255, 255]);
      expect(pixel(r, 50, 36)).toEqual([255, 0, 0]);
      expect(pixel(r, 50, 25)).toEqual([0, 255, 0]);
      // The line from the top left corner, clear of the triangle.
      expect(pixel(r, 4, 2)).toEqual([0, 0, 255]);
      // The triangle's top edge: black at half opacity over red (0.5·255 = 127.5), within antialiasing.
      const [red, green, blue] = pixel(r, 30, 10);
      expect(Math.abs(red - 128)).toBeLessThanOrEqual(20);
      expect([green, blue]).toEqual([0, 0]);
    }
  });
});
