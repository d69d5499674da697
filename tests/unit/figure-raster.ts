/**
 * Rasters of the figure files for the tests: PDF through poppler's
 * pdftoppm, EPS through ghostscript, both at 72 dpi (a point a pixel, so a
 * W × H figure gives W × H pixels), antialiased, read back as RGB.
 */
import { spawnSync } from 'node:child_process';
import { readFileSync } from 'node:fs';

/** An RGB raster, 3 bytes a pixel, rows from the top. */
export interface Raster {
  width: number;
  height: number;
  rgb: Uint8Array;
}

/** A binary PPM (P6, maxval 255) as a raster. */
export function readPpm(bytes: Uint8Array): Raster {
  const header: string[] = [];
  let at = 0;
  while (header.length < 4) {
    while (/\s/.test(String.fromCharCode(bytes[at]))) at++;
    if (bytes[at] === 0x23) {
      while (bytes[at] !== 0x0a) at++;
      continue;
    }
    let token = '';
    while (!/\s/.test(String.fromCharCode(bytes[at]))) token += String.fromCharCode(bytes[at++]);
    header.push(token);
  }
  if (header[0] !== 'P6' || header[3] !== '255') throw new Error(`not an 8-bit P6 PPM: ${header.join(' ')}`);
  const [width, height] = [Number(header[1]), Number(header[2])];
  return { width, height, rgb: bytes.subarray(at + 1, at + 1 + 3 * width * height) };
}

function run(cmd: string, args: string[]): void {
  const r = spawnSync(cmd, args, { encoding: 'utf8' });
  if (r.status !== 0) throw new Error(`${cmd} ${args.join(' ')}: ${r.stderr || r.error}`);
}

/** Page 1 of a PDF, by pdftoppm at 72 dpi. */
export function rasterPdf(pdf: string, out: string): Raster {
  run('pdftoppm', ['-r', '72', '-singlefile', pdf, out]);
  return readPpm(readFileSync(`${out}.ppm`));
}

/** An EPS cropped to its BoundingBox, by ghostscript at 72 dpi, antialiased as pdftoppm does. */
export function rasterEps(eps: string, out: string): Raster {
  run('gs', [
    '-q',
    '-dSAFER',
    '-dBATCH',
    '-dNOPAUSE',
    '-dEPSCrop',
    '-r72',
    '-dGraphicsAlphaBits=4',
    '-dTextAlphaBits=4',
    '-sDEVICE=ppmraw',
    `-sOutputFile=${out}.ppm`,
    eps,
  ]);
  return readPpm(readFileSync(`${out}.ppm`));
}

/** The pixel at x, y. */
export function pixel(r: Raster, x: number, y: number): [number, number, number] {
  const i = 3 * (y * r.width + x);
  return [r.rgb[i], r.rgb[i + 1], r.rgb[i + 2]];
}

/** The share of pixels whose channels all differ by at most `levels` between two rasters of one size. */
export function shareWithin(a: Raster, b: Raster, levels: number): number {
  if (a.width !== b.width || a.height !== b.height) throw new Error('rasters of different sizes');
  let close = 0;
  for (let i = 0; i < a.rgb.length; i += 3) {
    const d = Math.max(
      Math.abs(a.rgb[i] - b.rgb[i]),
      Math.abs(a.rgb[i + 1] - b.rgb[i + 1]),
      Math.abs(a.rgb[i + 2] - b.rgb[i + 2]),
    );
    if (d <= levels) close++;
  }
  return close / (a.width * a.height);
}

/** How many pixels differ from `background` by more than `levels` in some channel: the drawn area. */
export function drawnPixels(r: Raster, background: [number, number, number], levels = 24): number {
  let count = 0;
  for (let i = 0; i < r.rgb.length; i += 3) {
    if ([0, 1, 2].some((c) => Math.abs(r.rgb[i + c] - background[c]) > levels)) count++;
  }
  return count;
}
