/**
 * The halfedges of a control mesh, as far as crease editing needs them: is
 * a vertex pair an edge, and which edges continue an edge across its ends
 * (an edge loop, as modellers pick them with Alt+click). Level-0 meshes are
 * small and this runs on the main thread, so a map of halfedges serves;
 * the core's halfedge structures live in the worker.
 */
import type { Mesh } from '../core/mesh';

/** An edge as its two vertices, the lower first. */
export type Edge = readonly [number, number];

export function edgeOf(a: number, b: number): Edge {
  return a < b ? [a, b] : [b, a];
}

export class ControlTopology {
  /** Halfedge a→b (key a * V + b) to the vertex that follows b in its face. */
  private readonly next = new Map<number, number>();
  private readonly vertexCount: number;

  constructor(mesh: Pick<Mesh, 'positions' | 'faceSizes' | 'faceIndices'>) {
    this.vertexCount = mesh.positions.length / 3;
    let o = 0;
    for (const size of mesh.faceSizes) {
      for (let j = 0; j < size; ++j) {
        const a = mesh.faceIndices[o + j];
        const b = mesh.faceIndices[o + ((j + 1) % size)];
        const c = mesh.faceIndices[o + ((j + 2) % size)];
        this.next.set(this.key(a, b), c);
      }
      o += size;
    }
  }

  /** Whether a and b are the ends of an edge. */
  isEdge(a: number, b: number): boolean {
    return this.next.has(this.key(a, b)) || this.next.has(this.key(b, a));
  }

  /**
   * The vertices joined to `v`, in order around it (against the faces'
   * turning direction), starting at `from`; null when `v` is on the border (its fan
   * is not closed) or not next to `from`.
   */
  ringAround(v: number, from: number): number[] | null {
    const ring: number[] = [];
    let u = from;
    for (let guard = 0; guard <= this.vertexCount; ++guard) {
      ring.push(u);
      // The face of halfedge u→v goes on v→w: w is v's next neighbour, and
      // the face of w→v (across edge v–w) gives the one after.
      const w = this.next.get(this.key(u, v));
      if (w === undefined) return null;
      if (w === from) return ring;
      u = w;
    }
    return null;
  }

  /**
   * The edge loop through edge a–b: from each end, the edge straight across
   * a vertex of even valence inside the mesh (the n/2-th neighbour from the
   * incoming one), until a border, an odd valence or the start again.
   */
  edgeLoop(a: number, b: number): Edge[] {
    const edges: Edge[] = [edgeOf(a, b)];
    const seen = new Set<number>([this.edgeKey(a, b)]);
    const walk = (from: number, at: number, push: (e: Edge) => void) => {
      for (let guard = 0; guard <= this.next.size; ++guard) {
        const ring = this.ringAround(at, from);
        if (!ring || ring.length % 2 !== 0) return;
        const to = ring[ring.length / 2];
        const key = this.edgeKey(at, to);
        if (seen.has(key)) return;
        seen.add(key);
        push(edgeOf(at, to));
        from = at;
        at = to;
      }
    };
    walk(a, b, (e) => edges.push(e));
    walk(b, a, (e) => edges.unshift(e));
    return edges;
  }

  private key(a: number, b: number): number {
    return a * this.vertexCount + b;
  }

  private edgeKey(a: number, b: number): number {
    return a < b ? this.key(a, b) : this.key(b, a);
  }
}
