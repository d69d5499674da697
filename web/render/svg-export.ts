/**
 * SVG of the current view, drawn as a painter would: the polygons that face
 * the camera, sorted back to front by their centroid's depth, each filled
 * with a flat Lambert shade and stroked with its edges, then the control-mesh
 * overlay, the control-edge curves, the creases and the corners (coloured
 * by sharpness). A line or corner that lies on no camera-facing polygon of
 * its mesh is drawn before the faces, so that the surface covers it where
 * it passes behind, as the depth-tested view does; the others go on top. Polygons stay polygons (one <polygon> per face). three's
 * SVGRenderer draws triangles, so the projection is done here.
 */
import { Color, type PerspectiveCamera, Vector3 } from 'three';
import { DEFAULT_LINE_WIDTH, type LineKind, lineWidthPx } from './line-style';
import { VIEW_COLORS } from './scene-view';
import { lightShare } from './surface-materials';

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

export interface SvgExportInput {
  /** The level shown. */
  mesh: PolygonSet;
  camera: PerspectiveCamera;
  /** Size of the view in CSS pixels (the SVG's viewBox). */
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
}

/** Number formatting: two decimals are sub-pixel at any export size. */
function n(x: number): string {
  return (Math.round(x * 100) / 100).toString();
}

/** True when the camera sees the front of a face with normal `normal` and centroid `centroid`. */
export function facesCamera(camera: PerspectiveCamera, centroid: Vector3, normal: Vector3): boolean {
  return new Vector3().subVectors(camera.position, centroid).dot(normal) > 0;
}

export function exportSvg(input: SvgExportInput): string {
  const { mesh, camera, width, height } = input;
  camera.updateMatrixWorld();
  const positions = mesh.positions;
  const vertexCount = positions.length / 3;

  // Project every vertex once: screen x, y and view-space depth.
  const screen = new Float64Array(vertexCount * 2);
  const behind = new Uint8Array(vertexCount);
  const v = new Vector3();
  const viewMatrix = camera.matrixWorldInverse;
  for (let i = 0; i < vertexCount; i++) {
    v.set(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
    const viewZ = v.clone().applyMatrix4(viewMatrix).z;
    behind[i] = viewZ > -camera.near ? 1 : 0;
    v.project(camera);
    screen[2 * i] = ((v.x + 1) / 2) * width;
    screen[2 * i + 1] = ((1 - v.y) / 2) * height;
  }

  const base = new Color(VIEW_COLORS.surface);
  const viewDir = new Vector3();
  camera.getWorldDirection(viewDir);

  interface Face {
    depth: number;
    points: string;
    fill: string;
  }
  const faces: Face[] = [];
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
    const points: string[] = [];
    for (const c of corners) points.push(`${n(screen[2 * c])},${n(screen[2 * c + 1])}`);
    const depth = new Vector3().subVectors(centroid, camera.position).dot(viewDir);
    faces.push({ depth, points: points.join(' '), fill: `#${shaded.getHexString()}` });
  }
  faces.sort((a, b) => b.depth - a.depth);

  const out: string[] = [];
  out.push(
    `<svg xmlns="http://www.w3.org/2000/svg" width="${width}" height="${height}" viewBox="0 0 ${width} ${height}">`,
  );
  if (input.background) out.push(`<rect width="${width}" height="${height}" fill="${VIEW_COLORS.background}"/>`);
  // Lines behind the surface first (ids ending in -back), the faces over them, then the lines in front.
  // The view's widths (line-style.ts): the same multiples of the setting.
  const lineWidth = input.lineWidth ?? DEFAULT_LINE_WIDTH;
  const w = (kind: LineKind) => n(lineWidthPx(kind, lineWidth, 1));
  const overlays = [
    { lines: input.curves, id: 'control-curves', color: VIEW_COLORS.curves, width: w('curves') },
    { lines: input.control, id: 'control-mesh', color: VIEW_COLORS.control, width: w('control') },
    ...(input.creases ?? []).map(({ lines, color }, i) => ({ lines, id: `creases-${i}`, color, width: w('creases') })),
  ].flatMap(({ lines, id, color, width: w }) => (lines ? [{ ...splitByFacing(lines, camera), id, color, w }] : []));
  const dots = (input.corners ?? []).map(({ points, color }, i) => ({
    ...splitPointsByFacing(points, camera),
    id: `corners-${i}`,
    color,
  }));
  for (const o of overlays) out.push(linePath(o.back, `${o.id}-back`, o.color, camera, width, height, o.w));
  for (const o of dots) out.push(dotGroup(o.back, `${o.id}-back`, o.color, camera, width, height));
  const edgeOpacity = n(input.edgeOpacity ?? 1);
  out.push(
    `<g id="faces" stroke="${VIEW_COLORS.edges}" stroke-width="${w('edges')}" stroke-opacity="${edgeOpacity}" stroke-linejoin="round">`,
  );
  for (const f of faces) out.push(`<polygon points="${f.points}" fill="${f.fill}"/>`);
  out.push('</g>');
  for (const o of overlays) out.push(linePath(o.front, o.id, o.color, camera, width, height, o.w));
  for (const o of dots) out.push(dotGroup(o.front, o.id, o.color, camera, width, height));
  out.push('</svg>');
  return `${out.join('\n')}\n`;
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

/** Points (`points.edges`: one vertex each) as dots of the view's corner size, in one group (id `id`). */
function dotGroup(
  points: LineSet,
  id: string,
  color: string,
  camera: PerspectiveCamera,
  width: number,
  height: number,
): string {
  const dots: string[] = [];
  for (const i of Array.from(points.edges)) {
    const [x, y] = screenPoint(points.positions, i, camera, width, height);
    dots.push(`<circle cx="${x}" cy="${y}" r="5"/>`);
  }
  return `<g id="${id}" fill="${color}">${dots.join('')}</g>`;
}

/** Line segments as one path (id `id`). */
function linePath(
  lines: LineSet,
  id: string,
  color: string,
  camera: PerspectiveCamera,
  width: number,
  height: number,
  strokeWidth: string,
): string {
  const project = (i: number): string => screenPoint(lines.positions, i, camera, width, height).join(' ');
  const d: string[] = [];
  for (let e = 0; e + 1 < lines.edges.length; e += 2) {
    d.push(`M${project(lines.edges[e])}L${project(lines.edges[e + 1])}`);
  }
  return `<path id="${id}" fill="none" stroke="${color}" stroke-width="${strokeWidth}" stroke-linecap="round" d="${d.join('')}"/>`;
}

/** Where vertex `i` of `positions` is drawn in a view of `width` × `height`, formatted. */
function screenPoint(
  positions: ArrayLike<number>,
  i: number,
  camera: PerspectiveCamera,
  width: number,
  height: number,
): [string, string] {
  const v = new Vector3(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]).project(camera);
  return [n(((v.x + 1) / 2) * width), n(((1 - v.y) / 2) * height)];
}
