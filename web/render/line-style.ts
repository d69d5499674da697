/**
 * How wide and how dark the view's lines are drawn, shared by the WebGL view
 * and the SVG export: one line-width setting (CSS pixels), each kind of line
 * a multiple of it, every width multiplied by the pixels per CSS pixel of
 * the picture (the screen's devicePixelRatio, a PNG's ×2 or ×4), and the
 * polygon edges faded as they crowd together on screen.
 *
 * WebGL draws its own lines one pixel wide whatever width is asked, so every
 * line is a three.js fat line (LineSegments2: two triangles a segment).
 */
import type { BufferAttribute, BufferGeometry, InterleavedBuffer, PerspectiveCamera } from 'three';
import { LineSegmentsGeometry } from 'three/addons/lines/LineSegmentsGeometry.js';
import { changesOf } from './parted-attribute';

/** The line-width setting's default and its choices (CSS pixels). */
export const DEFAULT_LINE_WIDTH = 1;
export const LINE_WIDTHS: readonly number[] = [0.5, 1, 1.5, 2, 3, 4];
export const MIN_LINE_WIDTH = 0.25;
export const MAX_LINE_WIDTH = 8;

/** Each kind of line as a multiple of the setting: the cage and the curves stand out from the edges. */
export const LINE_FACTORS = {
  edges: 1,
  control: 1.5,
  curves: 2,
  creases: 4,
  parents: 1,
  /** Border edges, drawn over the polygon edges. */
  border: 3,
} as const;

export type LineKind = keyof typeof LINE_FACTORS;

/** Width in picture pixels of a line of `kind` for the setting `width` at `pixelsPerCss`. */
export function lineWidthPx(kind: LineKind, width: number, pixelsPerCss: number): number {
  return LINE_FACTORS[kind] * width * pixelsPerCss;
}

/** `value` as a line width the setting takes, or null (a number from {@link MIN_LINE_WIDTH} to {@link MAX_LINE_WIDTH}). */
export function parseLineWidth(value: string | number): number | null {
  const n = typeof value === 'number' ? value : Number(value.trim() === '' ? Number.NaN : value);
  return Number.isFinite(n) && n >= MIN_LINE_WIDTH && n <= MAX_LINE_WIDTH ? n : null;
}

/**
 * Edges spaced this many line widths apart on screen (or more) are drawn at
 * full strength; closer ones fade.
 */
export const FADE_SPACING = 60;
/** The faintest edges: still there, never a dark mass. */
export const MIN_EDGE_OPACITY = 0.2;

/**
 * The opacity of the polygon edges when their mean length on screen is
 * `meanEdgePx` CSS pixels and the line width is `width` CSS pixels:
 * sqrt(meanEdgePx / (FADE_SPACING × width)), between MIN_EDGE_OPACITY and 1.
 * Ink covers about width / spacing of a grid's area, so edges 60 widths
 * apart (a cube at level 1 on a laptop screen) are drawn at full strength,
 * 15 widths apart (a cube at level 4) at one half and 6 widths apart at
 * about a third; the square root keeps a dense level readable instead of
 * fading it out. The rule
 * depends on the ratio only, so a ×4 PNG (widths and lengths ×4) fades as
 * the screen does.
 */
export function edgeOpacity(meanEdgePx: number, width: number): number {
  if (!(meanEdgePx > 0) || !(width > 0)) return 1;
  return Math.min(1, Math.max(MIN_EDGE_OPACITY, Math.sqrt(meanEdgePx / (FADE_SPACING * width))));
}

/**
 * Mean length of the segments `index` (vertex pairs into `positions`, x y z
 * each), from at most `samples` of them spread evenly: enough for a mean,
 * cheap on a million edges.
 */
export function meanSegmentLength(positions: ArrayLike<number>, index: ArrayLike<number>, samples = 4096): number {
  const segments = Math.floor(index.length / 2);
  if (segments === 0) return 0;
  const step = Math.max(1, Math.floor(segments / samples));
  let sum = 0;
  let count = 0;
  for (let s = 0; s < segments; s += step) {
    const a = 3 * index[2 * s];
    const b = 3 * index[2 * s + 1];
    sum += Math.hypot(
      positions[a] - positions[b],
      positions[a + 1] - positions[b + 1],
      positions[a + 2] - positions[b + 2],
    );
    count++;
  }
  return sum / count;
}

/**
 * A length `length` in the model, seen at `distance` from `camera` in a view
 * `heightPx` CSS pixels tall, in CSS pixels: how long the mean edge is drawn
 * at the depth of the camera's target.
 */
export function projectedLength(length: number, distance: number, camera: PerspectiveCamera, heightPx: number): number {
  const visible = 2 * distance * Math.tan(((camera.fov / 2) * Math.PI) / 180);
  return visible > 0 ? (length / visible) * heightPx : 0;
}

/** Fat-line geometries made from a level's indexed lines (and the changes of the points they copy: changesOf), kept until that geometry is disposed. */
const fatLines = new WeakMap<BufferGeometry, { fat: LineSegmentsGeometry; version: number }>();

/** Copies the ends of each segment of `lines` into `segments` (x y z of both ends, six numbers a segment). */
function fillSegments(lines: BufferGeometry, segments: Float32Array): void {
  const xyz = lines.getAttribute('position').array as ArrayLike<number>;
  const pairs = lines.index?.array as ArrayLike<number>;
  for (let i = 0; i < pairs.length; ++i) {
    const v = 3 * pairs[i];
    segments[3 * i] = xyz[v];
    segments[3 * i + 1] = xyz[v + 1];
    segments[3 * i + 2] = xyz[v + 2];
  }
}

/**
 * `lines` (an indexed line geometry: a level's edges or marked curves) as a
 * fat-line geometry, made on first use, refilled when the level's points
 * moved (Split's blend) and disposed with `lines`.
 */
export function fatLinesOf(lines: BufferGeometry): LineSegmentsGeometry {
  const position = lines.getAttribute('position') as BufferAttribute;
  const known = fatLines.get(lines);
  if (known) {
    if (known.version !== changesOf(position)) {
      const buffer = (known.fat.getAttribute('instanceStart') as unknown as { data: InterleavedBuffer }).data;
      fillSegments(lines, buffer.array as Float32Array);
      buffer.needsUpdate = true;
      known.version = changesOf(position);
    }
    return known.fat;
  }
  const segments = new Float32Array(3 * (lines.index?.count ?? 0));
  fillSegments(lines, segments);
  const fat = new LineSegmentsGeometry().setPositions(segments);
  // The level's sphere: three would otherwise walk every segment.
  if (lines.boundingSphere) fat.boundingSphere = lines.boundingSphere.clone();
  fatLines.set(lines, { fat, version: changesOf(position) });
  const dispose = () => {
    fat.dispose();
    fatLines.delete(lines);
    lines.removeEventListener('dispose', dispose);
  };
  lines.addEventListener('dispose', dispose);
  return fat;
}
