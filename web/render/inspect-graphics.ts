/**
 * What Inspect draws over a level: the self-intersecting faces in red (a
 * framed pair darker; seen through the surface, fainter), the smallest enclosing sphere as a translucent ball,
 * the convex hull as a wireframe, and the minimum width's two parallel
 * planes as translucent squares. Built from the inspection and the level's
 * render buffers; the caller shows the group (SceneView.setExtras) and
 * disposes it, and frames its points (SceneView.fitPoints).
 */
import {
  BufferGeometry,
  Color,
  DoubleSide,
  Float32BufferAttribute,
  Group,
  LineBasicMaterial,
  LineSegments,
  type Material,
  Mesh,
  MeshBasicMaterial,
  MeshLambertMaterial,
  PlaneGeometry,
  Quaternion,
  SphereGeometry,
  Vector3,
} from 'three';
import type { Inspection } from '../core/inspect';
import type { RenderBuffers } from '../core/mesh';

export const INSPECT_COLORS = {
  intersecting: '#d7263d',
  framed: '#7a0010',
  sphere: '#f0a202',
  hull: '#0b6e4f',
  planes: '#2563eb',
} as const;

/** Which of an inspection's results to draw. */
export interface InspectLayers {
  intersections: boolean;
  sphere: boolean;
  hull: boolean;
  width: boolean;
}

export class InspectGraphics {
  readonly group = new Group();
  /**
   * Points (xyz each) that hold what is drawn, for framing it: the crossing
   * faces' corners, the sphere's box, the hull's vertices, the planes'
   * corners. Empty when nothing is drawn.
   */
  readonly points: Float32Array;

  /** `framed`: a pair of faces drawn darker (the one the panel framed), or null. */
  constructor(inspection: Inspection, buffers: RenderBuffers, layers: InspectLayers, framed: [number, number] | null) {
    const points: ArrayLike<number>[] = [];
    const pairs = inspection.selfIntersections;
    if (layers.intersections && pairs && pairs.faces.length > 0) {
      const faces = facesMesh(buffers, new Set(pairs.faces), INSPECT_COLORS.intersecting, 1);
      // Faces that cross mostly lie inside the surface (the part that went through it): drawn through
      // the surface too, fainter, so that a student sees where they are.
      const hidden = new Mesh(
        faces.geometry,
        new MeshBasicMaterial({
          color: INSPECT_COLORS.intersecting,
          side: DoubleSide,
          transparent: true,
          opacity: 0.45,
          depthTest: false,
          depthWrite: false,
        }),
      );
      hidden.renderOrder = 1.5;
      this.group.add(faces, hidden);
      const corners = faces.geometry.index?.array ?? [];
      const xyz = new Float32Array(3 * corners.length);
      for (let k = 0; k < corners.length; ++k)
        xyz.set(buffers.positions.subarray(3 * corners[k], 3 * corners[k] + 3), 3 * k);
      points.push(xyz);
      if (framed) this.group.add(facesMesh(buffers, new Set(framed), INSPECT_COLORS.framed, 2));
    }
    const sphere = inspection.sphere;
    if (layers.sphere && sphere) {
      const ball = new Mesh(
        new SphereGeometry(sphere.radius, 48, 24),
        new MeshLambertMaterial({ color: INSPECT_COLORS.sphere, transparent: true, opacity: 0.22, depthWrite: false }),
      );
      ball.position.fromArray(sphere.center);
      ball.renderOrder = 5;
      this.group.add(ball);
      // The eight corners of the sphere's box.
      const [x, y, z] = sphere.center;
      const r = sphere.radius;
      for (const sx of [-r, r])
        for (const sy of [-r, r]) for (const sz of [-r, r]) points.push([x + sx, y + sy, z + sz]);
    }
    const hull = inspection.hull;
    if (layers.hull && hull) {
      const segments: number[] = [];
      const seen = new Set<string>();
      for (let t = 0; t < hull.triangles.length; t += 3) {
        for (let k = 0; k < 3; ++k) {
          const a = hull.triangles[t + k];
          const b = hull.triangles[t + ((k + 1) % 3)];
          const key = a < b ? `${a},${b}` : `${b},${a}`;
          if (seen.has(key)) continue;
          seen.add(key);
          segments.push(...hull.positions.subarray(3 * a, 3 * a + 3), ...hull.positions.subarray(3 * b, 3 * b + 3));
        }
      }
      const geometry = new BufferGeometry();
      geometry.setAttribute('position', new Float32BufferAttribute(segments, 3));
      const lines = new LineSegments(geometry, new LineBasicMaterial({ color: INSPECT_COLORS.hull }));
      lines.renderOrder = 4;
      this.group.add(lines);
      points.push(hull.positions);
    }
    const width = inspection.width;
    if (layers.width && width && !width.skipped) {
      const normal = new Vector3().fromArray(width.normal);
      // Squares as large as the mesh's box, centred on the box's centre projected onto each plane.
      const { bboxMin, bboxMax, diagonal } = inspection.measures;
      const centre = new Vector3().fromArray(bboxMin).add(new Vector3().fromArray(bboxMax)).multiplyScalar(0.5);
      const turn = new Quaternion().setFromUnitVectors(new Vector3(0, 0, 1), normal);
      for (const offset of width.offsets) {
        const plane = new Mesh(
          new PlaneGeometry(diagonal, diagonal),
          new MeshBasicMaterial({
            color: INSPECT_COLORS.planes,
            transparent: true,
            opacity: 0.18,
            side: DoubleSide,
            depthWrite: false,
          }),
        );
        plane.quaternion.copy(turn);
        plane.position.copy(centre).addScaledVector(normal, offset - centre.dot(normal));
        plane.renderOrder = 6;
        this.group.add(plane);
        plane.updateMatrixWorld();
        const corners = plane.geometry.getAttribute('position');
        for (let k = 0; k < corners.count; ++k) {
          points.push(new Vector3().fromBufferAttribute(corners, k).applyMatrix4(plane.matrixWorld).toArray());
        }
      }
    }
    for (const child of this.group.children) child.frustumCulled = false;
    this.points = new Float32Array(points.reduce((n, p) => n + p.length, 0));
    let at = 0;
    for (const p of points) {
      this.points.set(p, at);
      at += p.length;
    }
  }

  dispose(): void {
    this.group.traverse((object) => {
      const drawn = object as Partial<Mesh>;
      drawn.geometry?.dispose();
      const material = drawn.material as Material | Material[] | undefined;
      for (const m of Array.isArray(material) ? material : material ? [material] : []) m.dispose();
    });
    this.group.clear();
  }
}

/** The level's triangles of `faces`, in `color`, drawn in front of the surface (`order` above it). */
function facesMesh(buffers: RenderBuffers, faces: Set<number>, color: string, order: number): Mesh {
  const index: number[] = [];
  for (let t = 0; t < buffers.triangleFace.length; ++t) {
    if (faces.has(buffers.triangleFace[t]))
      index.push(buffers.triangles[3 * t], buffers.triangles[3 * t + 1], buffers.triangles[3 * t + 2]);
  }
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new Float32BufferAttribute(buffers.positions, 3));
  geometry.setIndex(index);
  const mesh = new Mesh(
    geometry,
    new MeshBasicMaterial({
      color: new Color(color),
      side: DoubleSide,
      // In front of the surface at the same depth, behind nothing else.
      polygonOffset: true,
      polygonOffsetFactor: -1 - order,
      polygonOffsetUnits: -1 - order,
    }),
  );
  mesh.renderOrder = order;
  return mesh;
}
