/**
 * Which vertex or edge of a level is under a point of the view: the one
 * whose picture is nearest the pointer (vertices within a few pixels
 * first, then edges), among those the level's own faces do not hide.
 * Screen-space distances, so a thin edge is as easy to hit when the model
 * is far away as when it is close. The crease editor picks on the control
 * mesh, the stencil inspector a vertex of the level shown.
 */
import { DoubleSide, Mesh, MeshBasicMaterial, type PerspectiveCamera, Raycaster, Vector3 } from 'three';
import type { LevelGraphics } from './level-graphics';

export type Pick = { kind: 'vertex'; vertex: number } | { kind: 'edge'; a: number; b: number };

/** How near the pointer (CSS pixels) a vertex or an edge must be drawn to be picked. */
export const PICK_RADIUS = { vertex: 9, edge: 7 } as const;

/** The nearest candidates tried (each a ray against the level's faces): a dense level has many within reach. */
const MAX_TRIED = 12;

const HIT_MATERIAL = new MeshBasicMaterial({ side: DoubleSide });

/**
 * The vertex or (with `edges`) edge of `level` drawn nearest (x, y) (CSS
 * pixels from the view's top left in a view of `width` × `height`), or
 * null when none is within {@link PICK_RADIUS}.
 */
export function pickElement(
  level: LevelGraphics,
  camera: PerspectiveCamera,
  x: number,
  y: number,
  width: number,
  height: number,
  edges: boolean,
): Pick | null {
  const positions = level.points;
  const segments = edges ? (level.edges.index?.array ?? new Uint32Array(0)) : new Uint32Array(0);
  const count = positions.length / 3;
  // Each vertex on screen (NaN behind the camera).
  const screen = new Float64Array(2 * count);
  const p = new Vector3();
  for (let v = 0; v < count; ++v) {
    const at = onScreen(p.fromArray(positions, 3 * v), camera, width, height);
    screen[2 * v] = at?.x ?? Number.NaN;
    screen[2 * v + 1] = at?.y ?? Number.NaN;
  }
  const hidden = occlusion(level, camera);

  const vertices: { d: number; v: number }[] = [];
  for (let v = 0; v < count; ++v) {
    const d = Math.hypot(screen[2 * v] - x, screen[2 * v + 1] - y);
    if (d <= PICK_RADIUS.vertex) vertices.push({ d, v });
  }
  vertices.sort((m, n) => m.d - n.d);
  for (const { v } of vertices.slice(0, MAX_TRIED))
    if (!hidden(p.fromArray(positions, 3 * v))) return { kind: 'vertex', vertex: v };

  const candidates: { d: number; a: number; b: number; t: number }[] = [];
  for (let i = 0; i + 1 < segments.length; i += 2) {
    const a = segments[i];
    const b = segments[i + 1];
    const ax = screen[2 * a];
    const ay = screen[2 * a + 1];
    const dx = screen[2 * b] - ax;
    const dy = screen[2 * b + 1] - ay;
    const length2 = dx * dx + dy * dy;
    const t = length2 > 0 ? Math.min(1, Math.max(0, ((x - ax) * dx + (y - ay) * dy) / length2)) : 0;
    const d = Math.hypot(ax + t * dx - x, ay + t * dy - y);
    if (d <= PICK_RADIUS.edge) candidates.push({ d, a, b, t });
  }
  candidates.sort((m, n) => m.d - n.d);
  const q = new Vector3();
  for (const { a, b, t } of candidates.slice(0, MAX_TRIED)) {
    // The edge's point under the pointer (t along its picture: near enough for a visibility test).
    p.fromArray(positions, 3 * a).lerp(q.fromArray(positions, 3 * b), t);
    if (!hidden(p)) return { kind: 'edge', a: Math.min(a, b), b: Math.max(a, b) };
  }
  return null;
}

/** A test of whether the level's faces hide a point (on or off the mesh) from `camera`. */
function occlusion(level: LevelGraphics, camera: PerspectiveCamera): (point: Vector3) => boolean {
  const mesh = new Mesh(level.surface, HIT_MATERIAL);
  mesh.updateMatrixWorld();
  const raycaster = new Raycaster();
  const origin = camera.getWorldPosition(new Vector3());
  const direction = new Vector3();
  const radius = level.boundingSphere.radius;
  return (point) => {
    const distance = direction.subVectors(point, origin).length();
    if (distance === 0) return false;
    raycaster.set(origin, direction.divideScalar(distance));
    raycaster.far = distance;
    // A point on the mesh meets its own faces at its distance: only what is clearly nearer hides it.
    const slack = 1e-3 * radius + 1e-4 * distance;
    const hits = raycaster.intersectObject(mesh, false);
    return hits.some((hit) => hit.distance < distance - slack);
  };
}

/** Where vertex `v` of a level is drawn, in CSS pixels from the view's top left (null: behind the camera). */
export function screenPointOf(
  level: LevelGraphics,
  camera: PerspectiveCamera,
  v: number,
  width: number,
  height: number,
): { x: number; y: number } | null {
  const positions = level.points;
  return onScreen(new Vector3().fromArray(positions, 3 * v), camera, width, height);
}

/** Where `point` is drawn in a view of `width` × `height` CSS pixels (null: outside the depth range); changes `point`. */
function onScreen(point: Vector3, camera: PerspectiveCamera, width: number, height: number) {
  point.project(camera);
  if (point.z < -1 || point.z > 1) return null;
  return { x: ((point.x + 1) / 2) * width, y: ((1 - point.y) / 2) * height };
}
