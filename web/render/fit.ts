/**
 * Fit and the canonical views: where the camera goes so that every point
 * shown (the level, the control mesh when it is drawn, a tool's markers)
 * projects inside the part of the canvas that no panel covers.
 *
 * Worked out in closed form rather than with a bounding sphere: a sphere
 * around a cube's cage leaves its corners inside but frames the model
 * loosely, and one around the level alone can leave the cage's corners out
 * (Doo-Sabin and Catmull-Clark shrink a cube, so its cage lies outside).
 */
import { type PerspectiveCamera, Vector3 } from 'three';

/** A rectangle in fractions of the canvas: x from the left, y from the top, 0..1. */
export interface FreeRect {
  x0: number;
  y0: number;
  x1: number;
  y1: number;
}

export const WHOLE_CANVAS: FreeRect = { x0: 0, y0: 0, x1: 1, y1: 1 };

/** Fraction of the free rectangle's half-size the model may fill: a small margin on each side. */
export const FIT_FILL = 0.9;

export interface FitInput {
  /** Point sets (x y z each), e.g. the level's and the cage's positions. */
  points: readonly ArrayLike<number>[];
  /** Unit vector from the model towards the camera. */
  direction: Vector3;
  /** The camera's up (not necessarily orthogonal to `direction`). */
  up: Vector3;
  /** Vertical field of view in degrees and width / height of the canvas. */
  fov: number;
  aspect: number;
  /** Where on the canvas the model should go (default: all of it). */
  free?: FreeRect;
}

export interface FitResult {
  position: Vector3;
  target: Vector3;
  up: Vector3;
  /**
   * Where the target is drawn, in NDC (x right, y up; 0 0: the canvas's
   * centre): the free rectangle's centre. The view shifts its projection
   * there (PerspectiveCamera.setViewOffset, see {@link viewOffsetPixels}),
   * so the trackball still turns about the model's centre.
   */
  offset: [number, number];
  /** Half the diagonal of the points' box. */
  radius: number;
}

/**
 * The camera looking along −`direction` at the centre of the points' box
 * that shows every point inside the free rectangle (shrunk by
 * {@link FIT_FILL}), as close as that allows, and the projection's shift
 * that centres the box there.
 *
 * With the box centre C, the camera's right r, up u and back axis d, the
 * camera at C + D·d and the projection shifted by o (NDC), a point p with
 * x = r·(p − C), y = u·(p − C), z = d·(p − C) lands at NDC
 * o_x + x/((D − z)·t_x) (t_x the tangent of half the horizontal field).
 * Keeping it within the half-width h_x of the free rectangle gives
 * D ≥ z + |x| / (h_x·t_x), and the same for y: the largest bound over all
 * points is the distance.
 */
export function fitCamera(input: FitInput): FitResult | null {
  const d = input.direction.clone().normalize();
  const right = new Vector3().crossVectors(input.up, d);
  if (right.lengthSq() < 1e-12) right.crossVectors(new Vector3(0, 0, 1), d);
  if (right.lengthSq() < 1e-12) right.crossVectors(new Vector3(1, 0, 0), d);
  right.normalize();
  const up = new Vector3().crossVectors(d, right).normalize();

  const free = input.free ?? WHOLE_CANVAS;
  const ty = Math.tan(((input.fov / 2) * Math.PI) / 180);
  const tx = ty * input.aspect;
  // The free rectangle in NDC (y up): its centre and half-sizes.
  const ox = free.x0 + free.x1 - 1;
  const oy = 1 - (free.y0 + free.y1);
  const kx = 1 / (Math.max((free.x1 - free.x0) * FIT_FILL, 1e-3) * tx);
  const ky = 1 / (Math.max((free.y1 - free.y0) * FIT_FILL, 1e-3) * ty);

  // One pass over the points, in plain numbers (a level of a million points is framed within a frame): the box,
  // and the largest of z ± kx·x and of z ± ky·y (x, y, z along right, up and d). These are linear, so measured
  // from the box's centre C each is the same less its value at C.
  let [x0, y0, z0, x1, y1, z1] = [Infinity, Infinity, Infinity, -Infinity, -Infinity, -Infinity];
  let [left, rightmost, bottom, top] = [-Infinity, -Infinity, -Infinity, -Infinity];
  const [rx, ry, rz, ux, uy, uz, dx, dy, dz] = [right.x, right.y, right.z, up.x, up.y, up.z, d.x, d.y, d.z];
  for (const set of input.points) {
    for (let i = 0; i + 2 < set.length; i += 3) {
      const px = set[i];
      const py = set[i + 1];
      const pz = set[i + 2];
      if (!Number.isFinite(px + py + pz)) continue;
      if (px < x0) x0 = px;
      if (px > x1) x1 = px;
      if (py < y0) y0 = py;
      if (py > y1) y1 = py;
      if (pz < z0) z0 = pz;
      if (pz > z1) z1 = pz;
      const x = kx * (px * rx + py * ry + pz * rz);
      const y = ky * (px * ux + py * uy + pz * uz);
      const z = px * dx + py * dy + pz * dz;
      if (z - x > left) left = z - x;
      if (z + x > rightmost) rightmost = z + x;
      if (z - y > bottom) bottom = z - y;
      if (z + y > top) top = z + y;
    }
  }
  if (x0 > x1) return null;
  const min = new Vector3(x0, y0, z0);
  const max = new Vector3(x1, y1, z1);
  const center = min.clone().add(max).multiplyScalar(0.5);
  const size = Math.max(x1 - x0, y1 - y0, z1 - z0, 1e-9);
  const xc = kx * center.dot(right);
  const yc = ky * center.dot(up);
  const zc = center.dot(d);
  const distance = Math.max(0, left - (zc - xc), rightmost - (zc + xc), bottom - (zc - yc), top - (zc + yc));
  const radius = max.distanceTo(min) / 2;
  return {
    // Never inside the model, however flat it is seen.
    position: center.clone().addScaledVector(d, Math.max(distance, size * 0.05)),
    target: center,
    up,
    offset: [ox, oy],
    radius,
  };
}

/**
 * The x and y of PerspectiveCamera.setViewOffset (full size and window both
 * `width` × `height`) that move the picture by `offset` (NDC): what the
 * camera looks at is drawn at `offset` instead of the centre.
 */
export function viewOffsetPixels(offset: readonly [number, number], width: number, height: number): [number, number] {
  return [(-offset[0] * width) / 2, (offset[1] * height) / 2];
}

/**
 * How far from its centre the camera shows a sphere of `radius` whole, by
 * the narrower of the two fields of view: a view taller than wide (a
 * side-by-side pane, a phone held upright) sees less across than up and down.
 */
export function fitDistance(radius: number, fov: number, aspect: number): number {
  const vertical = ((fov / 2) * Math.PI) / 180;
  const horizontal = Math.atan(Math.tan(vertical) * aspect);
  return (radius / Math.sin(Math.min(vertical, horizontal))) * 1.2;
}

/** Direction the camera looks from (towards the model) when fitting: shows three sides of a box. */
export const DEFAULT_VIEW_DIRECTION = new Vector3(0.55, 0.45, 1).normalize();

export type CanonicalView = 'front' | 'top' | 'side' | 'iso';

/** The canonical views in menu order: the direction from the model to the camera, and the camera's up. */
export const CANONICAL_VIEWS: readonly {
  name: CanonicalView;
  label: string;
  direction: [number, number, number];
  up: [number, number, number];
}[] = [
  { name: 'front', label: 'Front', direction: [0, 0, 1], up: [0, 1, 0] },
  { name: 'top', label: 'Top', direction: [0, 1, 0], up: [0, 0, -1] },
  { name: 'side', label: 'Side', direction: [1, 0, 0], up: [0, 1, 0] },
  { name: 'iso', label: 'Iso', direction: [1, 1, 1], up: [0, 1, 0] },
];

/** The canonical view after `view` (the first after none), as the V key steps through them. */
export function nextCanonicalView(view: CanonicalView | null): CanonicalView {
  const i = CANONICAL_VIEWS.findIndex((v) => v.name === view);
  return CANONICAL_VIEWS[(i + 1) % CANONICAL_VIEWS.length].name;
}

/**
 * The part of a view's canvas that panels laid over it leave free: each
 * `covers` rectangle (CSS pixels, relative to the canvas) takes a strip off
 * the side it touches, the strip across the shorter way (a panel in the top
 * left corner, wider than tall, takes the top).
 */
export function freeRect(
  width: number,
  height: number,
  covers: readonly { left: number; top: number; right: number; bottom: number }[],
): FreeRect {
  let [x0, y0, x1, y1] = [0, 0, width, height];
  for (const c of covers) {
    if (c.right <= x0 || c.left >= x1 || c.bottom <= y0 || c.top >= y1) continue;
    // The area each cut would leave; the larger wins.
    const cuts = [
      { area: (x1 - Math.max(x0, c.right)) * (y1 - y0), apply: () => (x0 = Math.max(x0, c.right)) },
      { area: (Math.min(x1, c.left) - x0) * (y1 - y0), apply: () => (x1 = Math.min(x1, c.left)) },
      { area: (x1 - x0) * (y1 - Math.max(y0, c.bottom)), apply: () => (y0 = Math.max(y0, c.bottom)) },
      { area: (x1 - x0) * (Math.min(y1, c.top) - y0), apply: () => (y1 = Math.min(y1, c.top)) },
    ];
    cuts.sort((a, b) => b.area - a.area);
    // A panel that would leave less than half the canvas is ignored (it folds or hides itself there).
    if (cuts[0].area >= 0.5 * width * height) cuts[0].apply();
  }
  return { x0: x0 / width, y0: y0 / height, x1: x1 / width, y1: y1 / height };
}

/** Points (x y z each) as `camera` projects them on a `width` × `height` canvas: CSS pixels from its top left, not clipped. */
export function projectPoints(
  points: ArrayLike<number>,
  camera: PerspectiveCamera,
  width: number,
  height: number,
): { x: number; y: number }[] {
  camera.updateMatrixWorld();
  const out: { x: number; y: number }[] = [];
  const p = new Vector3();
  for (let i = 0; i + 2 < points.length; i += 3) {
    p.set(points[i], points[i + 1], points[i + 2]).project(camera);
    out.push({ x: ((p.x + 1) / 2) * width, y: ((1 - p.y) / 2) * height });
  }
  return out;
}
