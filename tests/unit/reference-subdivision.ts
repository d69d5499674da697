/**
 * Plain, independent implementations of the published rules, to check the
 * core point by point. Nothing here comes from CGAL's code.
 *  - Catmull-Clark (Catmull & Clark 1978): face point = centroid; interior
 *    edge point = (a + b + f0 + f1) / 4; interior vertex = (Q + 2R + (n-3)S) / n
 *    with Q the mean of the face points, R the mean of the edge midpoints.
 *  - Loop (Loop 1987): interior edge point = 3/8 (a + b) + 1/8 (c + d);
 *    interior vertex = (1 - α) S + α/n Σ neighbours, α = 5/8 - (3/8 + cos(2π/n)/4)².
 *  - Borders (both; the cubic B-spline of the border curve): edge point =
 *    midpoint, vertex = (a + 6 S + b) / 8 with a, b its border neighbours.
 */
import type { PlainMesh } from './test-helpers';

type Point = [number, number, number];

const add = (p: Point, q: Point): Point => [p[0] + q[0], p[1] + q[1], p[2] + q[2]];
const scale = (p: Point, s: number): Point => [p[0] * s, p[1] * s, p[2] * s];
const zero = (): Point => [0, 0, 0];

interface EdgeInfo {
  id: number;
  a: number;
  b: number;
  /** Faces on the edge, with the corner opposite the edge for triangles. */
  faces: number[];
  opposite: number[];
}

interface Topology {
  edges: EdgeInfo[];
  edgeOf: (a: number, b: number) => EdgeInfo;
  /** Neighbour vertices of each vertex. */
  neighbours: Set<number>[];
  /** Faces around each vertex. */
  vertexFaces: number[][];
  /** Border neighbours of each border vertex (two of them), empty otherwise. */
  borderNeighbours: number[][];
}

function topology(mesh: PlainMesh): Topology {
  const map = new Map<string, EdgeInfo>();
  const edges: EdgeInfo[] = [];
  const key = (a: number, b: number) => (a < b ? `${a} ${b}` : `${b} ${a}`);
  const n = mesh.points.length;
  const neighbours = Array.from({ length: n }, () => new Set<number>());
  const vertexFaces = Array.from({ length: n }, () => [] as number[]);
  mesh.faces.forEach((face, f) => {
    face.forEach((a, k) => {
      const b = face[(k + 1) % face.length];
      const c = face[(k + 2) % face.length];
      let e = map.get(key(a, b));
      if (!e) {
        e = { id: edges.length, a, b, faces: [], opposite: [] };
        map.set(key(a, b), e);
        edges.push(e);
      }
      e.faces.push(f);
      e.opposite.push(c);
      neighbours[a].add(b);
      neighbours[b].add(a);
      vertexFaces[a].push(f);
    });
  });
  const borderNeighbours = Array.from({ length: n }, () => [] as number[]);
  for (const e of edges) {
    if (e.faces.length === 1) {
      borderNeighbours[e.a].push(e.b);
      borderNeighbours[e.b].push(e.a);
    }
  }
  const edgeOf = (a: number, b: number) => {
    const e = map.get(key(a, b));
    if (!e) throw new Error(`no edge ${a}-${b}`);
    return e;
  };
  return { edges, edgeOf, neighbours, vertexFaces, borderNeighbours };
}

function borderVertex(mesh: PlainMesh, t: Topology, v: number): Point {
  const [a, b] = t.borderNeighbours[v];
  return scale(add(add(mesh.points[a], mesh.points[b]), scale(mesh.points[v], 6)), 1 / 8);
}

/** One Catmull-Clark step: vertices, then edge points, then face points. */
export function catmullClarkStep(mesh: PlainMesh): PlainMesh {
  const t = topology(mesh);
  const { points, faces } = mesh;
  const V = points.length;
  const E = t.edges.length;
  const facePoints = faces.map((face) =>
    scale(
      face.reduce((s, v) => add(s, points[v]), zero()),
      1 / face.length,
    ),
  );
  const edgePoints = t.edges.map((e) => {
    const mid = add(points[e.a], points[e.b]);
    if (e.faces.length === 1) return scale(mid, 1 / 2);
    return scale(add(mid, add(facePoints[e.faces[0]], facePoints[e.faces[1]])), 1 / 4);
  });
  const vertexPoints = points.map((s, v) => {
    if (t.borderNeighbours[v].length > 0) return borderVertex(mesh, t, v);
    const around = [...t.neighbours[v]];
    const n = around.length;
    const r = scale(
      around.reduce((sum, w) => add(sum, scale(add(s, points[w]), 1 / 2)), zero()),
      1 / n,
    );
    const q = scale(
      t.vertexFaces[v].reduce((sum, f) => add(sum, facePoints[f]), zero()),
      1 / t.vertexFaces[v].length,
    );
    return scale(add(add(q, scale(r, 2)), scale(s, n - 3)), 1 / n);
  });
  const newFaces: number[][] = [];
  faces.forEach((face, f) => {
    const k = face.length;
    for (let i = 0; i < k; i++) {
      const prev = face[(i + k - 1) % k];
      const v = face[i];
      const next = face[(i + 1) % k];
      newFaces.push([v, V + t.edgeOf(v, next).id, V + E + f, V + t.edgeOf(prev, v).id]);
    }
  });
  return { points: [...vertexPoints, ...edgePoints, ...facePoints], faces: newFaces };
}

/** Loop's α(n): the total weight of the n neighbours of an interior vertex. */
export function loopAlpha(n: number): number {
  const c = 3 / 8 + Math.cos((2 * Math.PI) / n) / 4;
  return 5 / 8 - c * c;
}

/** One Loop step on a triangle mesh: vertices, then edge points. */
export function loopStep(mesh: PlainMesh): PlainMesh {
  const t = topology(mesh);
  const { points, faces } = mesh;
  const V = points.length;
  const edgePoints = t.edges.map((e) => {
    const mid = add(points[e.a], points[e.b]);
    if (e.faces.length === 1) return scale(mid, 1 / 2);
    return add(scale(mid, 3 / 8), scale(add(points[e.opposite[0]], points[e.opposite[1]]), 1 / 8));
  });
  const vertexPoints = points.map((s, v) => {
    if (t.borderNeighbours[v].length > 0) return borderVertex(mesh, t, v);
    const around = [...t.neighbours[v]];
    const alpha = loopAlpha(around.length);
    const sum = around.reduce((acc, w) => add(acc, points[w]), zero());
    return add(scale(s, 1 - alpha), scale(sum, alpha / around.length));
  });
  const newFaces: number[][] = [];
  for (const [a, b, c] of faces) {
    const ab = V + t.edgeOf(a, b).id;
    const bc = V + t.edgeOf(b, c).id;
    const ca = V + t.edgeOf(c, a).id;
    newFaces.push([a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]);
  }
  return { points: [...vertexPoints, ...edgePoints], faces: newFaces };
}

/** `levels` steps of `step`. */
export function repeat(step: (m: PlainMesh) => PlainMesh, mesh: PlainMesh, levels: number): PlainMesh {
  let out = mesh;
  for (let i = 0; i < levels; i++) out = step(out);
  return out;
}

/**
 * √3 (Kobbelt 2000) on a closed triangle mesh: a centre per face, old vertex
 * = (1 - α) S + α/n Σ neighbours with α = (4 - 2 cos(2π/n)) / 9, then every
 * old edge flipped so that it joins the centres of its two faces.
 */
export function sqrt3ClosedStep(mesh: PlainMesh): PlainMesh {
  const t = topology(mesh);
  const { points, faces } = mesh;
  const V = points.length;
  const centres = faces.map((face) =>
    scale(
      face.reduce((s, v) => add(s, points[v]), zero()),
      1 / face.length,
    ),
  );
  const moved = points.map((s, v) => {
    const around = [...t.neighbours[v]];
    const n = around.length;
    const alpha = (4 - 2 * Math.cos((2 * Math.PI) / n)) / 9;
    const sum = around.reduce((acc, w) => add(acc, points[w]), zero());
    return add(scale(s, 1 - alpha), scale(sum, alpha / n));
  });
  // Triangles (a, b, c1) and (b, a, c2) around the edge a→b of face f1 become
  // (c1, a, c2) and (c2, b, c1) once the edge is flipped.
  const newFaces: number[][] = [];
  faces.forEach((face, f1) => {
    for (let k = 0; k < 3; k++) {
      const a = face[k];
      const b = face[(k + 1) % 3];
      if (a > b) continue; // each edge once, from the face where it runs low → high
      const e = t.edgeOf(a, b);
      const f2 = e.faces[0] === f1 ? e.faces[1] : e.faces[0];
      newFaces.push([V + f1, a, V + f2], [V + f2, b, V + f1]);
    }
  });
  return { points: [...moved, ...centres], faces: newFaces };
}

/**
 * The new points of one Doo-Sabin step (Doo & Sabin 1978): for corner i of
 * an n-gon, Σ_j α_(j-i) p_j with α_0 = (n + 5) / 4n and
 * α_k = (3 + 2 cos(2πk/n)) / 4n. One point per face corner.
 */
export function dooSabinPoints(mesh: PlainMesh): [number, number, number][] {
  const out: [number, number, number][] = [];
  for (const face of mesh.faces) {
    const n = face.length;
    for (let i = 0; i < n; i++) {
      let p = zero();
      for (let j = 0; j < n; j++) {
        const k = (j - i + n) % n;
        const alpha = k === 0 ? (n + 5) / (4 * n) : (3 + 2 * Math.cos((2 * Math.PI * k) / n)) / (4 * n);
        p = add(p, scale(mesh.points[face[j]], alpha));
      }
      out.push(p);
    }
  }
  return out;
}
