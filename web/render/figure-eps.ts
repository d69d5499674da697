/**
 * The view's figure (figure.ts) as Encapsulated PostScript, for latex +
 * dvips: its BoundingBox the figure's size (a CSS pixel is a point), the
 * background a filled rectangle (none when transparent: EPS leaves the
 * page unpainted), each polygon one line (`fill-rgb stroke-rgb x y M x y L
 * … P`: filled, then stroked), each group of lines one stroked path, each
 * corner dot an arc.
 *
 * PostScript has no transparency, so everything is drawn opaque: a line
 * drawn at opacity a takes a·colour + (1 − a)·what lies under it, the
 * polygon's own fill for the polygon edges (their fading, line-style.ts),
 * the background (white when transparent) for other lines.
 */
import { type Figure, figureNumber as n, rgbOf } from './figure';

type Rgb = [number, number, number];

function rgbText(c: Rgb): string {
  return c.map((x) => (Math.round(x * 1000) / 1000).toString()).join(' ');
}

/** `color` at `alpha` over `under`, as one opaque colour. */
function mix(color: string, alpha: number, under: Rgb): Rgb {
  const c = rgbOf(color);
  return [0, 1, 2].map((i) => alpha * c[i] + (1 - alpha) * under[i]) as Rgb;
}

/** Procedures the body uses (short names keep a level with thousands of faces small). */
const PROLOG = [
  '/M { moveto } bind def',
  '/L { lineto } bind def',
  '% fill-r g b stroke-r g b path P: fill the path, then stroke it',
  '/P { closepath 6 3 roll gsave setrgbcolor fill grestore setrgbcolor stroke } bind def',
  '% r g b path F: fill the path',
  '/F { closepath setrgbcolor fill } bind def',
  '% x y r D: a dot',
  '/D { 0 360 arc closepath fill } bind def',
];

/** `figure` as an EPS file (EPSF-3.0, one page), titled `title`. */
export function figureEps(figure: Figure, title = 'SubdivLab figure'): string {
  const { width, height } = figure;
  const under: Rgb = figure.background ? rgbOf(figure.background) : [1, 1, 1];
  const body: string[] = [];
  if (figure.background) {
    body.push(`${rgbText(rgbOf(figure.background))} setrgbcolor 0 0 ${n(width)} ${n(height)} rectfill`);
  }
  for (const layer of figure.layers) {
    body.push(`% ${layer.id}`);
    if (layer.kind === 'polygons') {
      const s = layer.stroke;
      if (s) body.push(`${n(s.width)} setlinewidth 1 setlinejoin`);
      for (const p of layer.polygons) {
        const path: string[] = [];
        for (let i = 0; i + 1 < p.points.length; i += 2) {
          path.push(`${n(p.points[i])} ${n(p.points[i + 1])} ${i === 0 ? 'M' : 'L'}`);
        }
        const fill = rgbText(rgbOf(p.fill));
        body.push(
          s
            ? `${fill} ${rgbText(mix(s.color, s.opacity, rgbOf(p.fill)))} ${path.join(' ')} P`
            : `${fill} ${path.join(' ')} F`,
        );
      }
    } else if (layer.kind === 'lines') {
      const s = layer.stroke;
      const q = layer.segments;
      if (q.length === 0) continue;
      body.push(`${rgbText(mix(s.color, s.opacity, under))} setrgbcolor ${n(s.width)} setlinewidth 1 setlinecap`);
      body.push('newpath');
      for (let i = 0; i + 3 < q.length; i += 4) {
        body.push(`${n(q[i])} ${n(q[i + 1])} M ${n(q[i + 2])} ${n(q[i + 3])} L`);
      }
      body.push('stroke');
    } else {
      body.push(`${rgbText(rgbOf(layer.color))} setrgbcolor`);
      const c = layer.centres;
      for (let i = 0; i + 1 < c.length; i += 2) body.push(`newpath ${n(c[i])} ${n(c[i + 1])} ${layer.radius} D`);
    }
  }
  const lines = [
    '%!PS-Adobe-3.0 EPSF-3.0',
    `%%BoundingBox: 0 0 ${Math.ceil(width)} ${Math.ceil(height)}`,
    `%%HiResBoundingBox: 0 0 ${n(width)} ${n(height)}`,
    `%%Title: ${title.replace(/[^\x20-\x7e]/g, '')}`,
    '%%Creator: SubdivLab',
    '%%LanguageLevel: 2',
    '%%Pages: 1',
    '%%EndComments',
    '%%BeginProlog',
    ...PROLOG,
    '%%EndProlog',
    '%%Page: 1 1',
    'gsave',
    // y down, as the figure's coordinates.
    `0 ${n(height)} translate 1 -1 scale`,
    ...body,
    'grestore',
    'showpage',
    '%%EOF',
  ];
  return `${lines.join('\n')}\n`;
}
