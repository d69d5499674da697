/**
 * The halfedge explorer's picture: every halfedge of a level as an arrow
 * inside the face it bounds (moved toward the face's centre, shortened at
 * both ends, its head at the target), border halfedges in their own colour
 * outside the boundary, as the tutorials draw them; over them the picked
 * halfedge, its target vertex and its face, the halfedges a circulation
 * met, and split_face's second halfedge. Fat lines (LineSegments2), lifted
 * a little off the faces so the surface does not hide them. The caller
 * shows the group (SceneView.setExtras) and disposes it.
 */
import {
  BufferGeometry,
  Color,
  DoubleSide,
  Float32BufferAttribute,
  Group,
  Mesh,
  MeshBasicMaterial,
  type PerspectiveCamera,
  Points,
  PointsMaterial,
  Vector3,
} from 'three';
import { LineMaterial } from 'three/addons/lines/LineMaterial.js';
import { LineSegments2 } from 'three/addons/lines/LineSegments2.js';
import { LineSegmentsGeometry } from 'three/addons/lines/LineSegmentsGeometry.js';
import type { HalfedgeTable } from '../core/halfedges';

export const HALFEDGE_COLORS = {
  arrow: '#0f172a',
  border: '#ea580c',
  picked: '#dc2626',
  visited: '#059669',
  second: '#7c3aed',
  face: '#facc15',
} as const;

/** How near the pointer (CSS pixels) an arrow must be drawn to be picked. */
export const ARROW_PICK_RADIUS = 10;

/** Share of the way from an edge to its face's centre the arrow is drawn at. */
const INSET = 0.22;
/** Share of the arrow cut off at each end, so arrows meeting at a corner stay apart. */
const TRIM = 0.14;

/** What is marked over the arrows. */
export interface ArrowMarks {
  picked: number | null;
  /** A circulation's halfedges so far (the picked one excluded). */
  visited: readonly number[];
  /** split_face's second halfedge. */
  second: number | null;
}

export class HalfedgeArrows {
  readonly group = new Group();
  /** Per halfedge: the shaft's ends, and the normal of the face it is drawn on. */
  private readonly tail: Float32Array;
  private readonly tip: Float32Array;
  private readonly normal: Float32Array;
  private readonly heads: Float32Array;
  private readonly centre: Float32Array;
  private readonly lift: number;
  private readonly marks: LineSegments2;
  private readonly vertexMark: Points<BufferGeometry, PointsMaterial>;
  private readonly faceMark: Mesh<BufferGeometry, MeshBasicMaterial>;
  private readonly arrows: LineSegments2;

  /** `positions`: the level's vertices (x y z each), numbered as `table`'s targets. */
  constructor(
    private readonly positions: ArrayLike<number>,
    private readonly table: HalfedgeTable,
  ) {
    const count = table.next.length;
    const faces = table.face.reduce((m, f) => Math.max(m, f + 1), 0);
    this.centre = new Float32Array(3 * faces);
    const faceNormal = new Float32Array(3 * faces);
    const corners = new Uint32Array(faces);
    let edgeLength = 0;
    const p = new Vector3();
    const q = new Vector3();
    for (let h = 0; h < count; ++h) {
      p.fromArray(positions, 3 * table.target[table.opposite[h]]);
      q.fromArray(positions, 3 * table.target[h]);
      edgeLength += p.distanceTo(q);
      const f = table.face[h];
      if (f < 0) continue;
      for (let i = 0; i < 3; ++i) this.centre[3 * f + i] += q.getComponent(i);
      corners[f]++;
      // Newell's normal: sums over the face's edges, outward for faces turned counter-clockwise.
      faceNormal[3 * f] += (p.y - q.y) * (p.z + q.z);
      faceNormal[3 * f + 1] += (p.z - q.z) * (p.x + q.x);
      faceNormal[3 * f + 2] += (p.x - q.x) * (p.y + q.y);
    }
    for (let f = 0; f < faces; ++f) {
      for (let i = 0; i < 3; ++i) this.centre[3 * f + i] /= Math.max(1, corners[f]);
      p.fromArray(faceNormal, 3 * f)
        .normalize()
        .toArray(faceNormal, 3 * f);
    }
    this.lift = count > 0 ? (0.02 * edgeLength) / count : 0;

    this.tail = new Float32Array(3 * count);
    this.tip = new Float32Array(3 * count);
    this.normal = new Float32Array(3 * count);
    this.heads = new Float32Array(12 * count);
    const colours = new Float32Array(18 * count);
    const inner = new Color(HALFEDGE_COLORS.arrow);
    const outer = new Color(HALFEDGE_COLORS.border);
    const c = new Vector3();
    const n = new Vector3();
    const a = new Vector3();
    const b = new Vector3();
    const side = new Vector3();
    for (let h = 0; h < count; ++h) {
      const border = table.face[h] < 0;
      // A border halfedge is drawn on the far side of its opposite's face: outside the boundary.
      const f = border ? table.face[table.opposite[h]] : table.face[h];
      c.fromArray(this.centre, 3 * f);
      n.fromArray(faceNormal, 3 * f);
      const k = border ? -INSET : INSET;
      p.fromArray(positions, 3 * table.target[table.opposite[h]]);
      q.fromArray(positions, 3 * table.target[h]);
      a.copy(p).lerp(c, k).addScaledVector(n, this.lift);
      b.copy(q).lerp(c, k).addScaledVector(n, this.lift);
      const shaft = b.clone().sub(a);
      a.addScaledVector(shaft, TRIM);
      b.addScaledVector(shaft, -TRIM);
      a.toArray(this.tail, 3 * h);
      b.toArray(this.tip, 3 * h);
      n.toArray(this.normal, 3 * h);
      // The head: two short strokes back from the tip, in the face's plane.
      const length = b.distanceTo(a);
      const back = shaft.normalize().multiplyScalar(-0.2 * length);
      side.crossVectors(n, back).setLength(0.09 * length);
      p.copy(b)
        .add(back)
        .add(side)
        .toArray(this.heads, 12 * h);
      p.copy(b)
        .add(back)
        .sub(side)
        .toArray(this.heads, 12 * h + 6);
      b.toArray(this.heads, 12 * h + 3);
      b.toArray(this.heads, 12 * h + 9);
      const colour = border ? outer : inner;
      for (let i = 0; i < 6; ++i) colour.toArray(colours, 18 * h + 3 * i);
    }
    this.arrows = new LineSegments2(
      new LineSegmentsGeometry()
        .setPositions(this.segments(Array.from({ length: count }, (_, h) => h)))
        .setColors(colours),
      new LineMaterial({ vertexColors: true, linewidth: 2.5 * devicePixelRatio }),
    );
    this.marks = new LineSegments2(
      new LineSegmentsGeometry(),
      new LineMaterial({ vertexColors: true, linewidth: 5 * devicePixelRatio }),
    );
    // CSS pixels: the view scales them to a picture's pixels (SceneView, as its own lines).
    this.arrows.userData.cssLineWidth = 2.5;
    this.marks.userData.cssLineWidth = 5;
    this.vertexMark = new Points(
      new BufferGeometry(),
      new PointsMaterial({ color: HALFEDGE_COLORS.picked, size: 14, sizeAttenuation: false, depthTest: false }),
    );
    this.faceMark = new Mesh(
      new BufferGeometry(),
      new MeshBasicMaterial({
        color: HALFEDGE_COLORS.face,
        transparent: true,
        opacity: 0.55,
        depthWrite: false,
        side: DoubleSide,
      }),
    );
    this.faceMark.renderOrder = 1;
    this.marks.renderOrder = 2;
    this.vertexMark.renderOrder = 3;
    this.group.add(this.arrows, this.faceMark, this.marks, this.vertexMark);
    this.setMarks({ picked: null, visited: [], second: null });
  }

  /** Marks the picked halfedge (red, with its target and its face), a circulation's (green) and a second pick (violet). */
  setMarks(marks: ArrowMarks): void {
    const shown: number[] = [];
    const colours: number[] = [];
    const add = (h: number, hex: string) => {
      shown.push(h);
      const rgb = new Color(hex).toArray();
      for (let i = 0; i < 6; ++i) colours.push(...rgb);
    };
    for (const h of marks.visited) add(h, HALFEDGE_COLORS.visited);
    if (marks.second !== null) add(marks.second, HALFEDGE_COLORS.second);
    if (marks.picked !== null) add(marks.picked, HALFEDGE_COLORS.picked);
    this.marks.geometry.dispose();
    this.marks.geometry = new LineSegmentsGeometry().setPositions(this.segments(shown)).setColors(colours);
    this.marks.visible = shown.length > 0;

    const h = marks.picked;
    this.vertexMark.geometry.dispose();
    this.vertexMark.geometry = new BufferGeometry();
    this.faceMark.geometry.dispose();
    this.faceMark.geometry = new BufferGeometry();
    this.vertexMark.visible = h !== null;
    this.faceMark.visible = h !== null && this.table.face[h] >= 0;
    if (h === null) return;
    const target = Array.from({ length: 3 }, (_, i) => this.positions[3 * this.table.target[h] + i]);
    this.vertexMark.geometry.setAttribute('position', new Float32BufferAttribute(target, 3));
    if (this.table.face[h] >= 0) this.faceMark.geometry.setAttribute('position', this.faceFan(h));
  }

  /** The halfedge whose arrow is drawn nearest (x, y) (CSS pixels), on a face turned to the camera, or null. */
  pick(camera: PerspectiveCamera, x: number, y: number, width: number, height: number): number | null {
    let best: number | null = null;
    let nearest = ARROW_PICK_RADIUS;
    const a = new Vector3();
    const b = new Vector3();
    const n = new Vector3();
    for (let h = 0; h < this.table.next.length; ++h) {
      a.fromArray(this.tail, 3 * h);
      b.fromArray(this.tip, 3 * h);
      // Arrows on faces turned away are behind the surface (on a closed, outward-turned mesh).
      const mid = a.clone().lerp(b, 0.5);
      if (n.fromArray(this.normal, 3 * h).dot(camera.position.clone().sub(mid)) <= 0) continue;
      const s = project(a, camera, width, height);
      const t = project(b, camera, width, height);
      if (!s || !t) continue;
      const dx = t.x - s.x;
      const dy = t.y - s.y;
      const l2 = dx * dx + dy * dy;
      const u = l2 > 0 ? Math.min(1, Math.max(0, ((x - s.x) * dx + (y - s.y) * dy) / l2)) : 0;
      const d = Math.hypot(s.x + u * dx - x, s.y + u * dy - y);
      if (d < nearest) {
        nearest = d;
        best = h;
      }
    }
    return best;
  }

  /** Where the middle of `h`'s arrow is drawn (CSS pixels from the view's top left), or null behind the camera. */
  arrowOnScreen(h: number, camera: PerspectiveCamera, width: number, height: number): { x: number; y: number } | null {
    if (h < 0 || h >= this.table.next.length) return null;
    const mid = new Vector3().fromArray(this.tail, 3 * h).lerp(new Vector3().fromArray(this.tip, 3 * h), 0.5);
    return project(mid, camera, width, height);
  }

  dispose(): void {
    for (const object of [this.arrows, this.marks]) {
      object.geometry.dispose();
      object.material.dispose();
    }
    for (const object of [this.vertexMark, this.faceMark]) {
      object.geometry.dispose();
      object.material.dispose();
    }
  }

  /** Shaft and head strokes of each of `halfedges`, six numbers a segment. */
  private segments(halfedges: readonly number[]): Float32Array {
    const out = new Float32Array(18 * halfedges.length);
    halfedges.forEach((h, i) => {
      out.set(this.tail.subarray(3 * h, 3 * h + 3), 18 * i);
      out.set(this.tip.subarray(3 * h, 3 * h + 3), 18 * i + 3);
      out.set(this.heads.subarray(12 * h, 12 * h + 12), 18 * i + 6);
    });
    return out;
  }

  /** The face of `h` as a fan of triangles from its centre, lifted as the arrows are (half as much). */
  private faceFan(h: number): Float32BufferAttribute {
    const f = this.table.face[h];
    const c = new Vector3().fromArray(this.centre, 3 * f);
    const n = new Vector3().fromArray(this.normal, 3 * h).multiplyScalar(this.lift / 2);
    const out: number[] = [];
    let g = h;
    do {
      const from = this.table.target[this.table.opposite[g]];
      const to = this.table.target[g];
      for (const point of [
        c,
        new Vector3().fromArray(this.positions, 3 * from),
        new Vector3().fromArray(this.positions, 3 * to),
      ])
        out.push(...point.clone().add(n).toArray());
      g = this.table.next[g];
    } while (g !== h && out.length < 9 * this.table.next.length);
    return new Float32BufferAttribute(out, 3);
  }
}

function project(
  point: Vector3,
  camera: PerspectiveCamera,
  width: number,
  height: number,
): { x: number; y: number } | null {
  const v = point.clone().project(camera);
  if (v.z > 1) return null;
  return { x: ((v.x + 1) / 2) * width, y: ((1 - v.y) / 2) * height };
}
