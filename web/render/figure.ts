/**
 * The view as a vector figure, described once for every format (SVG, PDF,
 * EPS): drawn as a painter would, the polygons that face the camera sorted
 * back to front by their centroid's depth, each filled with a flat Lambert
 * shade and stroked with its edges, then the control-mesh overlay, the
 * control-edge curves, the creases and the corners (coloured by sharpness).
 * A line or corner that lies on no camera-facing polygon of its mesh is
 * drawn before the faces, so that the surface covers it where it passes
 * behind, as the depth-tested view does; the others go on top. Polygons
 * stay polygons (three's SVGRenderer draws triangles, so the projection is
 * done here). The writers (svg-export.ts, figure-pdf.ts, figure-eps.ts)
 * only spell the layers out.
 */
import { Color, type PerspectiveCamera, Vector3 } from 'three';
import type { MeshTags } from '../core/mesh';
import { sharpnessColor } from './level-graphics';
import { DEFAULT_LINE_WIDTH, type LineKind, lineWidthPx } from './line-style';
import { lightShare } from './surface-materials';
import { VIEW_COLORS } from './view-colors';

/** Positions (xyz) and vertex index pairs of line segments. */
export interface LineSet {
  positions: ArrayLike<number>;
  edges: ArrayLike<number>;
  /**
   * The polygons the lines lie on (indices into `positions`). Without them
   * every line is drawn over the faces.
   */
  faces?: { faceSizes: ArrayLike<number>; faceIndices: ArrayLike<number> };
}

/** Polygons: positions (xyz) and each face's vertex indices, face after face. */
export interface PolygonSet {
  positions: ArrayLike<number>;
  faceSizes: Uint32Array;
  faceIndices: Uint32Array;
}

/**
 * What the surface looks like in the figure: shaded polygons with their
 * edges (the app's figures, `subdiv figure --mode edges`), without edges
 * (flat), or only the edges, every one of them (wireframe).
 */
export type FigureStyle = 'edges' | 'flat' | 'wireframe';

export interface FigureInput {
  /** The level shown. */
  mesh: PolygonSet;
  camera: PerspectiveCamera;
  /** Size of the view in CSS pixels (the figure's page). */
  width: number;
  height: number;
  /** Level-0 positions and polygon edges, when the control-mesh overlay is shown. */
  control?: LineSet | null;
  /** The shown level's marked control edges, when the control-edge curves are shown. */
  curves?: LineSet | null;
  /** The shown level's sharp edges, a set per colour (their sharpness's), when the creases are shown. */
  creases?: { lines: LineSet; color: string }[];
  /** The shown level's sharp vertices (`lines.edges` holds one vertex each), a set per colour. */
  corners?: { points: LineSet; color: string }[];
  /** Fill the background (false: transparent). */
  background: boolean;
  /** The line-width setting (CSS pixels; line-style.ts), default 1. */
  lineWidth?: number;
  /** The polygon edges' opacity as the view draws them (line-style.ts, edgeOpacity), default 1. */
  edgeOpacity?: number;
  /** The control mesh's opacity, by the same rule from its own edges, default 1. */
  controlOpacity?: number;
  /** Default 'edges'. */
  style?: FigureStyle;
}

/** How a line is drawn: colour (#rrggbb), width in figure units (CSS pixels), opacity 0..1. */
export interface FigureStroke {
  color: string;
  width: number;
  opacity: number;
}

/** A filled polygon: x y pairs in figure units from the top left, and its fill (#rrggbb). */
export interface FigurePolygon {
  points: number[];
  fill: string;
}

/** One group of the figure, drawn in order; `id` names it in the SVG. */
export type FigureLayer =
  | { kind: 'polygons'; id: string; polygons: FigurePolygon[]; stroke: FigureStroke | null }
  /** Line segments, x0 y0 x1 y1 each, round caps. */
  | { kind: 'lines'; id: string; stroke: FigureStroke; segments: number[] }
  /** Filled dots, x y each. */
  | { kind: 'dots'; id: string; color: string; radius: number; centres: number[] };

/** A figure in any format: its page (figure units: CSS pixels, a point in PDF and EPS), background and layers. */
export interface Figure {
  width: number;
  height: number;
  /** The page's colour (#rrggbb), or null for none (transparent). */
  background: string | null;
  layers: FigureLayer[];
}

/** The vector formats a figure is written in. */
export type FigureFormat = 'svg' | 'pdf' | 'eps';

/** The radius of a corner dot (CSS pixels), as the view draws them. */
const DOT_RADIUS = 5;

/** True when the camera sees the front of a face with normal `normal` and centroid `centroid`. */
export function facesCamera(camera: PerspectiveCamera, centroid: Vector3, normal: Vector3): boolean {
  return new Vector3().subVectors(camera.position, centroid).dot(normal) > 0;
}

/** The figure of `input`'s view: see the file's comment for what is drawn in which order. */
export function buildFigure(input: FigureInput): Figure {
  const { camera, width, height } = input;
  const style = input.style ?? 'edges';
  camera.updateMatrixWorld();
  const project = projector(camera, width, height);
  const lineWidth = input.lineWidth ?? DEFAULT_LINE_WIDTH;
  const w = (kind: LineKind) => lineWidthPx(kind, lineWidth, 1);
  const edgeStroke = { color: VIEW_COLORS.edges, width: w('edges'), opacity: input.edgeOpacity ?? 1 };

  const overlays = [
    { lines: input.curves, id: 'control-curves', color: VIEW_COLORS.curves, width: w('curves'), opacity: 1 },
    {
      lines: input.control,
      id: 'control-mesh',
      color: VIEW_COLORS.control,
      width: w('control'),
      opacity: input.controlOpacity ?? 1,
    },
    ...(input.creases ?? []).map(({ lines, color }, i) => ({
      lines,
      id: `creases-${i}`,
      color,
      width: w('creases'),
      opacity: 1,
    })),
  ].flatMap(({ lines, ...o }) => (lines ? [{ ...splitByFacing(lines, camera), ...o }] : []));
  const dots = (input.corners ?? []).map(({ points, color }, i) => ({
    ...splitPointsByFacing(points, camera),
    id: `corners-${i}`,
    color,
  }));
  const lineLayer = (lines: LineSet, id: string, color: string, width: number, opacity = 1): FigureLayer => ({
    kind: 'lines',
    id,
    stroke: { color, width, opacity },
    segments: segmentsOf(lines, project),
  });
  const dotLayer = (points: LineSet, id: string, color: string): FigureLayer => ({
    kind: 'dots',
    id,
    color,
    radius: DOT_RADIUS,
    centres: Array.from(points.edges).flatMap((i) => project(points.positions, i)),
  });

  const layers: FigureLayer[] = [];
  // Lines behind the surface first (ids ending in -back), the faces over them, then the lines in front.
  for (const o of overlays) layers.push(lineLayer(o.back, `${o.id}-back`, o.color, o.width, o.opacity));
  for (const o of dots) layers.push(dotLayer(o.back, `${o.id}-back`, o.color));
  if (style === 'wireframe') {
    const edges = { positions: input.mesh.positions, edges: polygonEdges(input.mesh) };
    layers.push(lineLayer(edges, 'edges', edgeStroke.color, edgeStroke.width, edgeStroke.opacity));
  } else {
    const polygons = facingPolygons(input.mesh, camera, project);
    layers.push({ kind: 'polygons', id: 'faces', polygons, stroke: style === 'edges' ? edgeStroke : null });
  }
  for (const o of overlays) layers.push(lineLayer(o.front, o.id, o.color, o.width, o.opacity));
  for (const o of dots) layers.push(dotLayer(o.front, o.id, o.color));
  return { width, height, background: input.background ? VIEW_COLORS.background : null, layers };
}

/**
 * A level's sharp edges and corners (its OpenSubdiv tags) as the figure's
 * creases and corners, a set per colour of their sharpness (as the view
 * colours them, level-graphics.ts), lying on `faces`.
 */
export function tagOverlays(
  tags: Pick<MeshTags, 'creaseEdges' | 'creaseSharpness' | 'cornerVertices' | 'cornerSharpness'>,
  positions: ArrayLike<number>,
  faces: NonNullable<LineSet['faces']>,
): Required<Pick<FigureInput, 'creases' | 'corners'>> {
  const groups = (vertices: Uint32Array, sharpness: Float32Array, per: 1 | 2) => {
    const byColor = new Map<string, number[]>();
    for (let i = 0; i < sharpness.length; ++i) {
      const color = `#${sharpnessColor(sharpness[i]).getHexString()}`;
      const group = byColor.get(color) ?? [];
      group.push(...vertices.subarray(per * i, per * i + per));
      byColor.set(color, group);
    }
    return [...byColor];
  };
  return {
    creases: groups(tags.creaseEdges, tags.creaseSharpness, 2).map(([color, edges]) => ({
      lines: { positions, edges, faces },
      color,
    })),
    corners: groups(tags.cornerVertices, tags.cornerSharpness, 1).map(([color, vertices]) => ({
      points: { positions, edges: vertices, faces },
      color,
    })),
  };
}

/** Where vertex `i` of `positions` is drawn, x y from the top left. */
type Project = (positions: ArrayLike<number>, i: number) => [number, number];

function projector(camera: PerspectiveCamera, width: number, height: number): Project {
  const v = new Vector3();
  return (positions, i) => {
    v.set(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]).project(camera);
    return [((v.x + 1) / 2) * width, ((1 - v.y) / 2) * height];
  };
}

/**
 * The camera-facing polygons of `mesh`, back to front, flat-shaded; a
 * polygon with a corner behind the camera's near plane is left out.
 */
function facingPolygons(mesh: PolygonSet, camera: PerspectiveCamera, project: Project): FigurePolygon[] {
  const positions = mesh.positions;
  const vertexCount = positions.length / 3;
  const behind = new Uint8Array(vertexCount);
  const v = new Vector3();
  for (let i = 0; i < vertexCount; i++) {
    v.set(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]).applyMatrix4(camera.matrixWorldInverse);
    behind[i] = v.z > -camera.near ? 1 : 0;
  }
  const base = new Color(VIEW_COLORS.surface);
  const viewDir = camera.getWorldDirection(new Vector3());
  const faces: (FigurePolygon & { depth: number })[] = [];
  const normal = new Vector3();
  const centroid = new Vector3();
  const shaded = new Color();
  let offset = 0;
  for (const size of mesh.faceSizes) {
    const corners = mesh.faceIndices.subarray(offset, offset + size);
    offset += size;
    polygonNormalAndCentroid(positions, corners, 0, size, normal, centroid);
    const clipped = corners.some((c) => behind[c] === 1);
    if (clipped || normal.lengthSq() === 0 || !facesCamera(camera, centroid, normal)) continue;
    normal.normalize();
    const shade = lightShare(normal, camera.quaternion);
    shaded.copy(base).multiplyScalar(Math.min(shade, 1));
    const points: number[] = [];
    for (const c of corners) points.push(...project(positions, c));
    const depth = new Vector3().subVectors(centroid, camera.position).dot(viewDir);
    faces.push({ depth, points, fill: `#${shaded.getHexString()}` });
  }
  faces.sort((a, b) => b.depth - a.depth);
  return faces.map(({ points, fill }) => ({ points, fill }));
}

/** Each polygon edge of `mesh` once, as vertex pairs. */
function polygonEdges(mesh: PolygonSet): number[] {
  const vertexCount = mesh.positions.length / 3;
  const seen = new Set<number>();
  const edges: number[] = [];
  let offset = 0;
  for (const size of mesh.faceSizes) {
    for (let k = 0; k < size; k++) {
      const a = mesh.faceIndices[offset + k];
      const b = mesh.faceIndices[offset + ((k + 1) % size)];
      const key = Math.min(a, b) * vertexCount + Math.max(a, b);
      if (!seen.has(key)) edges.push(a, b);
      seen.add(key);
    }
    offset += size;
  }
  return edges;
}

/** The segments of `lines` on the page, x0 y0 x1 y1 each. */
function segmentsOf(lines: LineSet, project: Project): number[] {
  const out: number[] = [];
  for (let e = 0; e + 1 < lines.edges.length; e += 2) {
    out.push(...project(lines.positions, lines.edges[e]), ...project(lines.positions, lines.edges[e + 1]));
  }
  return out;
}

/**
 * Newell's normal of the polygon indices[offset .. offset + size) (exact for
 * planar polygons, a good average otherwise; not normalised) and its vertex
 * centroid.
 */
function polygonNormalAndCentroid(
  positions: ArrayLike<number>,
  indices: ArrayLike<number>,
  offset: number,
  size: number,
  normal: Vector3,
  centroid: Vector3,
): void {
  normal.set(0, 0, 0);
  centroid.set(0, 0, 0);
  for (let k = 0; k < size; k++) {
    const a = indices[offset + k];
    const b = indices[offset + ((k + 1) % size)];
    const [ax, ay, az] = [positions[3 * a], positions[3 * a + 1], positions[3 * a + 2]];
    const [bx, by, bz] = [positions[3 * b], positions[3 * b + 1], positions[3 * b + 2]];
    normal.x += (ay - by) * (az + bz);
    normal.y += (az - bz) * (ax + bx);
    normal.z += (ax - bx) * (ay + by);
    centroid.x += ax;
    centroid.y += ay;
    centroid.z += az;
  }
  centroid.divideScalar(size);
}

/** Calls `visit` with the vertices of each polygon of `faces` that faces the camera. */
function forFacingPolygons(
  positions: ArrayLike<number>,
  faces: NonNullable<LineSet['faces']>,
  camera: PerspectiveCamera,
  visit: (corner: (k: number) => number, size: number) => void,
): void {
  const normal = new Vector3();
  const centroid = new Vector3();
  let offset = 0;
  for (const size of Array.from(faces.faceSizes)) {
    polygonNormalAndCentroid(positions, faces.faceIndices, offset, size, normal, centroid);
    const start = offset;
    if (normal.lengthSq() > 0 && facesCamera(camera, centroid, normal))
      visit((k) => faces.faceIndices[start + (k % size)], size);
    offset += size;
  }
}

/**
 * Splits `lines` into those on a camera-facing polygon of `lines.faces`
 * (front) and the rest (back). Without faces every line is in front.
 */
function splitByFacing(lines: LineSet, camera: PerspectiveCamera): { front: LineSet; back: LineSet } {
  const { positions, edges, faces } = lines;
  if (!faces) return { front: lines, back: { positions, edges: [] } };
  const vertexCount = positions.length / 3;
  const key = (a: number, b: number) => Math.min(a, b) * vertexCount + Math.max(a, b);
  const onFront = new Set<number>();
  forFacingPolygons(positions, faces, camera, (corner, size) => {
    for (let k = 0; k < size; k++) onFront.add(key(corner(k), corner(k + 1)));
  });
  const front: number[] = [];
  const back: number[] = [];
  for (let e = 0; e + 1 < edges.length; e += 2) {
    (onFront.has(key(edges[e], edges[e + 1])) ? front : back).push(edges[e], edges[e + 1]);
  }
  return { front: { positions, edges: front }, back: { positions, edges: back } };
}

/** As {@link splitByFacing}, for points (`points.edges`: one vertex each): in front when on a camera-facing polygon. */
function splitPointsByFacing(points: LineSet, camera: PerspectiveCamera): { front: LineSet; back: LineSet } {
  const { positions, edges: vertices, faces } = points;
  if (!faces) return { front: points, back: { positions, edges: [] } };
  const onFront = new Set<number>();
  forFacingPolygons(positions, faces, camera, (corner, size) => {
    for (let k = 0; k < size; k++) onFront.add(corner(k));
  });
  const front: number[] = [];
  const back: number[] = [];
  for (const v of Array.from(vertices)) (onFront.has(v) ? front : back).push(v);
  return { front: { positions, edges: front }, back: { positions, edges: back } };
}

/** `color` (any CSS colour three reads) as sRGB r g b in 0..1. */
export function rgbOf(color: string): [number, number, number] {
  const hex = new Color(color).getHexString();
  return [0, 2, 4].map((i) => Number.parseInt(hex.slice(i, i + 2), 16) / 255) as [number, number, number];
}

/** Two decimals: sub-pixel at any export size (and short files). */
export function figureNumber(x: number): string {
  const s = (Math.round(x * 100) / 100).toString();
  return s === '-0' ? '0' : s;
}
