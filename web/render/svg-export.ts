/**
 * The view's figure (figure.ts) as SVG: a <polygon> per camera-facing face
 * in the group `faces`, a <path> per group of lines (ids `control-mesh`,
 * `control-curves`, `creases-i`, and `…-back` for those behind the
 * surface), a <g> of <circle>s per colour of corners.
 */
import { buildFigure, type Figure, type FigureInput, figureNumber as n } from './figure';

export type { FigureInput as SvgExportInput, LineSet, PolygonSet } from './figure';
export { facesCamera } from './figure';

/** SVG of the view described by `input`. */
export function exportSvg(input: FigureInput): string {
  return figureSvg(buildFigure(input));
}

/** `figure` as an SVG document, one element per polygon and one path per group of lines. */
export function figureSvg(figure: Figure): string {
  const { width, height } = figure;
  const out: string[] = [
    `<svg xmlns="http://www.w3.org/2000/svg" width="${width}" height="${height}" viewBox="0 0 ${width} ${height}">`,
  ];
  if (figure.background) out.push(`<rect width="${width}" height="${height}" fill="${figure.background}"/>`);
  for (const layer of figure.layers) {
    if (layer.kind === 'polygons') {
      const s = layer.stroke;
      const stroke = s
        ? ` stroke="${s.color}" stroke-width="${n(s.width)}" stroke-opacity="${n(s.opacity)}" stroke-linejoin="round"`
        : '';
      out.push(`<g id="${layer.id}"${stroke}>`);
      for (const p of layer.polygons) out.push(`<polygon points="${pointList(p.points)}" fill="${p.fill}"/>`);
      out.push('</g>');
    } else if (layer.kind === 'lines') {
      const s = layer.stroke;
      const d: string[] = [];
      const q = layer.segments;
      for (let i = 0; i + 3 < q.length; i += 4) d.push(`M${n(q[i])} ${n(q[i + 1])}L${n(q[i + 2])} ${n(q[i + 3])}`);
      const opacity = s.opacity < 1 ? ` stroke-opacity="${n(s.opacity)}"` : '';
      out.push(
        `<path id="${layer.id}" fill="none" stroke="${s.color}" stroke-width="${n(s.width)}"${opacity} stroke-linecap="round" d="${d.join('')}"/>`,
      );
    } else {
      const dots: string[] = [];
      const c = layer.centres;
      for (let i = 0; i + 1 < c.length; i += 2)
        dots.push(`<circle cx="${n(c[i])}" cy="${n(c[i + 1])}" r="${layer.radius}"/>`);
      out.push(`<g id="${layer.id}" fill="${layer.color}">${dots.join('')}</g>`);
    }
  }
  out.push('</svg>');
  return `${out.join('\n')}\n`;
}

/** x y pairs as an SVG points list: "x,y x,y …". */
function pointList(points: readonly number[]): string {
  const out: string[] = [];
  for (let i = 0; i + 1 < points.length; i += 2) out.push(`${n(points[i])},${n(points[i + 1])}`);
  return out.join(' ');
}
