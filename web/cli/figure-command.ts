/**
 * `subdiv figure`: the app's vector figure of a level (render/figure.ts),
 * drawn in Node without a browser. The camera is a three.js
 * PerspectiveCamera as the app's (35° vertical field), framed by the app's
 * Fit rule (render/fit.ts) from a canonical view or the app's first
 * direction, or placed where a link's `view=` string puts it; the line
 * widths and the edges' fading are the view's (render/line-style.ts).
 */
import { PerspectiveCamera, Vector3 } from 'three';
import type { LevelView } from '../core/mesh';
import { fanPolygons } from '../render/fan-polygons';
import { buildFigure, type Figure, type FigureFormat, type FigureStyle, tagOverlays } from '../render/figure';
import { figureEps } from '../render/figure-eps';
import { figurePdf } from '../render/figure-pdf';
import { CANONICAL_VIEWS, type CanonicalView, DEFAULT_VIEW_DIRECTION, fitCamera } from '../render/fit';
import { edgeOpacity, meanSegmentLength, projectedLength } from '../render/line-style';
import { figureSvg } from '../render/svg-export';
import { formatViewString, parseViewString, type ViewState } from '../render/view-state';

/** The view's vertical field of view (scene-view.ts). */
const FOV = 35;

/** `--mode` values a vector figure can draw; smooth is drawn flat-shaded (polygons are flat in SVG, PDF and EPS). */
export const FIGURE_MODES = ['edges', 'flat', 'smooth', 'wireframe'] as const;
export type FigureMode = (typeof FIGURE_MODES)[number];

/** `subdiv figure`'s options, checked (cli-args.ts). */
export interface FigureOptions {
  /** A canonical view, a camera (the link's `view=` value) or null for the app's first view. */
  view: CanonicalView | ViewState | null;
  mode: FigureMode;
  controlMesh: boolean;
  /** The control-edge curves (primal schemes: the level's edges on the cage's edges). */
  curves: boolean;
  width: number;
  height: number;
  /** The line-width setting (CSS pixels, line-style.ts). */
  lineWidth: number;
  transparent: boolean;
  format: FigureFormat;
}

/** `--view` as a canonical view or a camera; null when it is neither. */
export function parseFigureView(text: string): CanonicalView | ViewState | null {
  return CANONICAL_VIEWS.find((v) => v.name === text)?.name ?? parseViewString(text);
}

/** What `subdiv figure` made: the file's contents and what it shows. */
export interface FigureResult {
  contents: string | Uint8Array;
  /** The camera-facing polygons drawn (0 in wireframe). */
  polygons: number;
  /** The camera as the app's link writes it (`view=`). */
  camera: string;
  edgeOpacity: number;
}

/**
 * The figure of `level` (with `control`, level 0, as the cage when asked)
 * as `options` say, in `options.format`, titled `title`.
 */
export function renderFigure(
  level: LevelView,
  control: LevelView,
  options: FigureOptions,
  title: string,
): FigureResult {
  const { width, height } = options;
  const buffers = level.buffers;
  const mesh = { positions: buffers.positions, ...fanPolygons(buffers) };
  const cage = control.buffers;
  const controlLines = options.controlMesh
    ? { positions: cage.positions, edges: cage.edges, faces: fanPolygons(cage) }
    : null;
  const camera = placeCamera(options, width / height, [buffers.positions, ...(controlLines ? [cage.positions] : [])]);
  const distance = camera.position.distanceTo(camera.userData.target as Vector3);
  const opacityOf = (lines: { positions: Float32Array; edges: Uint32Array }) =>
    edgeOpacity(
      projectedLength(meanSegmentLength(lines.positions, lines.edges), distance, camera, height),
      options.lineWidth,
    );
  const opacity = opacityOf(buffers);
  const { controlEdges, tags } = level.mesh;
  const figure = buildFigure({
    mesh,
    camera,
    width,
    height,
    control: controlLines,
    curves: options.curves ? { positions: buffers.positions, edges: controlEdges, faces: mesh } : null,
    // The file's creases and corners, as the app shows them unless switched off.
    ...(tags ? tagOverlays(tags, buffers.positions, mesh) : {}),
    background: !options.transparent,
    lineWidth: options.lineWidth,
    edgeOpacity: opacity,
    controlOpacity: controlLines ? opacityOf(cage) : 1,
    style: figureStyle(options.mode),
  });
  const view: ViewState = {
    position: camera.position.toArray(),
    target: (camera.userData.target as Vector3).toArray(),
    up: camera.up.toArray(),
  };
  return {
    contents: writeFigure(figure, options.format, title),
    polygons: figure.layers.reduce((sum, l) => sum + (l.kind === 'polygons' ? l.polygons.length : 0), 0),
    camera: formatViewString(view),
    edgeOpacity: opacity,
  };
}

/** `figure` in `format`. */
export function writeFigure(figure: Figure, format: FigureFormat, title: string): string | Uint8Array {
  if (format === 'pdf') return figurePdf(figure, title);
  if (format === 'eps') return figureEps(figure, title);
  return figureSvg(figure);
}

function figureStyle(mode: FigureMode): FigureStyle {
  return mode === 'edges' || mode === 'wireframe' ? mode : 'flat';
}

/**
 * The camera of the figure: at the given view, or framed around `points`
 * by Fit from a canonical view's direction (the app's first direction
 * without one), its near and far planes as the view sets them. Its target
 * is kept in `userData.target`.
 */
function placeCamera(options: FigureOptions, aspect: number, points: readonly ArrayLike<number>[]): PerspectiveCamera {
  const camera = new PerspectiveCamera(FOV, aspect, 0.01, 100);
  const fitted = fitCamera({
    points,
    direction: directionOf(options.view),
    up: new Vector3().fromArray(upOf(options.view)),
    fov: FOV,
    aspect,
  });
  if (!fitted) throw new Error('the mesh has no finite points to frame');
  const view: ViewState =
    options.view !== null && typeof options.view === 'object'
      ? options.view
      : { position: fitted.position.toArray(), target: fitted.target.toArray(), up: fitted.up.toArray() };
  const target = new Vector3().fromArray(view.target);
  camera.position.fromArray(view.position);
  camera.up.fromArray(view.up);
  camera.lookAt(target);
  camera.userData.target = target;
  // The view's clipping planes (scene-view.ts, updateClipping).
  const distance = camera.position.distanceTo(target);
  camera.near = Math.max(distance * 0.005, fitted.radius * 1e-4);
  camera.far = 2 * distance + 4 * fitted.radius;
  camera.updateProjectionMatrix();
  camera.updateMatrixWorld();
  return camera;
}

function directionOf(view: FigureOptions['view']): Vector3 {
  const canonical = typeof view === 'string' ? CANONICAL_VIEWS.find((v) => v.name === view) : undefined;
  return canonical ? new Vector3().fromArray(canonical.direction) : DEFAULT_VIEW_DIRECTION.clone();
}

function upOf(view: FigureOptions['view']): [number, number, number] {
  return (typeof view === 'string' ? CANONICAL_VIEWS.find((v) => v.name === view)?.up : undefined) ?? [0, 1, 0];
}
