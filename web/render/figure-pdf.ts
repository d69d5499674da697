/**
 * The view's figure (figure.ts) as a one-page PDF of vector paths, for
 * `\includegraphics` in pdfLaTeX: one page of the figure's size (a CSS
 * pixel is a point), the background a filled rectangle (none when
 * transparent), each polygon one line of the content stream (`… rg … m …
 * l h B`: filled, then stroked with the edges), each group of lines one
 * stroked path, each corner dot four Bézier quarters. The edges' opacity
 * goes through an ExtGState's /CA (stroking alpha), as SVG's stroke-opacity.
 *
 * Written here rather than with a library (jsPDF, pdf-lib): a PDF of filled
 * and stroked paths is a catalogue, a page, a content stream and a
 * cross-reference table; written by hand the content stream is exactly the
 * figure's (tests read its operators), the bytes are the same on every run
 * (no dates, no ids) and neither the app nor the CLI carries a PDF library.
 * A content stream up to {@link PLAIN_STREAM_BYTES} is left uncompressed
 * (readable: a level with a thousand faces); a longer one is deflated with
 * the fflate that three.js ships (a bunny of 130 000 faces: 9 MB plain).
 */
import { zlibSync } from 'three/addons/libs/fflate.module.js';
import { type Figure, type FigureStroke, figureNumber as n, rgbOf } from './figure';

/** Content streams longer than this (bytes) are Flate-compressed. */
export const PLAIN_STREAM_BYTES = 256 * 1024;

/** Bézier handle length of a quarter circle, as a share of its radius. */
const KAPPA = 0.5522847498;

/** Colour components as PDF operands: three decimals (1/1000 is finer than a byte's 1/255). */
function rgb(color: string): string {
  return rgbOf(color)
    .map((c) => (Math.round(c * 1000) / 1000).toString())
    .join(' ');
}

/**
 * The figure's content stream: PDF operators drawing it on a page
 * `figure.width` × `figure.height` points with y down (the first `cm`
 * flips the page so the figure's own coordinates are used). `opacity`
 * names the graphics state of each opacity below 1 (/GS0, /GS1, …).
 */
export function figureContentStream(figure: Figure, opacity: (alpha: number) => string): string {
  const out: string[] = [`1 0 0 -1 0 ${n(figure.height)} cm`];
  if (figure.background) out.push(`${rgb(figure.background)} rg 0 0 ${n(figure.width)} ${n(figure.height)} re f`);
  const strokeState = (s: FigureStroke) =>
    `${s.opacity < 1 ? `/${opacity(s.opacity)} gs ` : ''}${rgb(s.color)} RG ${n(s.width)} w`;
  for (const layer of figure.layers) {
    out.push(`% ${layer.id}`, 'q');
    if (layer.kind === 'polygons') {
      if (layer.stroke) out.push(`${strokeState(layer.stroke)} 1 j`);
      const paint = layer.stroke ? 'B' : 'f';
      for (const p of layer.polygons) {
        const path: string[] = [];
        for (let i = 0; i + 1 < p.points.length; i += 2) {
          path.push(`${n(p.points[i])} ${n(p.points[i + 1])} ${i === 0 ? 'm' : 'l'}`);
        }
        out.push(`${rgb(p.fill)} rg ${path.join(' ')} h ${paint}`);
      }
    } else if (layer.kind === 'lines') {
      out.push(`${strokeState(layer.stroke)} 1 J 1 j`);
      const q = layer.segments;
      for (let i = 0; i + 3 < q.length; i += 4) {
        out.push(`${n(q[i])} ${n(q[i + 1])} m ${n(q[i + 2])} ${n(q[i + 3])} l`);
      }
      if (q.length > 0) out.push('S');
    } else {
      out.push(`${rgb(layer.color)} rg`);
      const c = layer.centres;
      for (let i = 0; i + 1 < c.length; i += 2) out.push(`${circlePath(c[i], c[i + 1], layer.radius)} f`);
    }
    out.push('Q');
  }
  return `${out.join('\n')}\n`;
}

/** A circle as four Bézier quarters, counter-clockwise from its rightmost point. */
function circlePath(x: number, y: number, r: number): string {
  const k = KAPPA * r;
  const p = (...v: number[]) => v.map(n).join(' ');
  return [
    `${p(x + r, y)} m`,
    `${p(x + r, y + k, x + k, y + r, x, y + r)} c`,
    `${p(x - k, y + r, x - r, y + k, x - r, y)} c`,
    `${p(x - r, y - k, x - k, y - r, x, y - r)} c`,
    `${p(x + k, y - r, x + r, y - k, x + r, y)} c h`,
  ].join(' ');
}

/** A PDF string literal: backslash, parentheses escaped, anything beyond ASCII dropped. */
function pdfString(text: string): string {
  return `(${text.replace(/[^\x20-\x7e]/g, '').replace(/[\\()]/g, (c) => `\\${c}`)})`;
}

/** `figure` as a PDF file (version 1.4, for its transparency), titled `title`. */
export function figurePdf(figure: Figure, title = 'SubdivLab figure'): Uint8Array {
  const alphas: number[] = [];
  const opacity = (alpha: number) => {
    const a = Number(n(alpha));
    if (!alphas.includes(a)) alphas.push(a);
    return `GS${alphas.indexOf(a)}`;
  };
  const plain = figureContentStream(figure, opacity);
  const deflate = plain.length > PLAIN_STREAM_BYTES;
  // Strings of bytes (one character each) from here on, so that lengths are byte offsets.
  const content = deflate ? byteString(zlibSync(Uint8Array.from(plain, (c) => c.charCodeAt(0)))) : plain;
  const states = alphas.map((a, i) => `/GS${i} << /Type /ExtGState /CA ${a} >>`).join(' ');
  const objects = [
    '<< /Type /Catalog /Pages 2 0 R >>',
    '<< /Type /Pages /Kids [3 0 R] /Count 1 >>',
    `<< /Type /Page /Parent 2 0 R /MediaBox [0 0 ${n(figure.width)} ${n(figure.height)}] /Contents 4 0 R /Resources << /ExtGState << ${states} >> >> >>`,
    `<< /Length ${content.length}${deflate ? ' /Filter /FlateDecode' : ''} >>\nstream\n${content}${deflate ? '\n' : ''}endstream`,
    `<< /Title ${pdfString(title)} /Producer (SubdivLab) >>`,
  ];
  // The second line's bytes above 127 tell file transfers the file is binary (PDF 1.4, 7.5.2).
  let text = '%PDF-1.4\n%\u00e2\u00e3\u00cf\u00d3\n';
  const offsets: number[] = [];
  objects.forEach((body, i) => {
    offsets.push(text.length);
    text += `${i + 1} 0 obj\n${body}\nendobj\n`;
  });
  const xref = text.length;
  text += `xref\n0 ${objects.length + 1}\n0000000000 65535 f \n`;
  for (const offset of offsets) text += `${offset.toString().padStart(10, '0')} 00000 n \n`;
  text += `trailer\n<< /Size ${objects.length + 1} /Root 1 0 R /Info 5 0 R >>\nstartxref\n${xref}\n%%EOF\n`;
  // One byte per character.
  return Uint8Array.from(text, (c) => c.charCodeAt(0));
}

/** Bytes as a string of one character each (0–255), in chunks: a long stream overflows one call's arguments. */
function byteString(bytes: Uint8Array): string {
  let out = '';
  for (let i = 0; i < bytes.length; i += 0x8000) out += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return out;
}
