/**
 * Edits of a control mesh's OpenSubdiv tags, as the crease editor makes
 * them: the sharpness of some edges or of a vertex set, a smooth one
 * dropped (as the reader drops sharpness 0). Tags are values: each edit
 * answers new tags and leaves its input alone, so an undo stack keeps them.
 */
import { INFINITELY_SHARP, type MeshTags } from '../core/mesh';
import { type Edge, edgeOf } from './control-topology';

/** What the editor acts on: control-mesh edges (one, or a loop) or a vertex. */
export type TagTarget = { kind: 'edges'; edges: readonly Edge[] } | { kind: 'vertex'; vertex: number };

/** Tags with nothing in them and the default modes. */
export function noTags(): MeshTags {
  return {
    creaseEdges: new Uint32Array(0),
    creaseSharpness: new Float32Array(0),
    cornerVertices: new Uint32Array(0),
    cornerSharpness: new Float32Array(0),
    holes: new Uint32Array(0),
    boundary: 'edge',
    boundaryGiven: false,
    creaseMethod: 'uniform',
    creaseMethodGiven: false,
    notes: [],
  };
}

/** The sharpness of each edge of `tags`, by {@link edgeKey}. */
function creaseMap(tags: MeshTags): Map<string, number> {
  const map = new Map<string, number>();
  for (let i = 0; i < tags.creaseSharpness.length; ++i)
    map.set(edgeKey(tags.creaseEdges[2 * i], tags.creaseEdges[2 * i + 1]), tags.creaseSharpness[i]);
  return map;
}

function edgeKey(a: number, b: number): string {
  const [lo, hi] = edgeOf(a, b);
  return `${lo} ${hi}`;
}

/**
 * The sharpness `target` has in `tags` (0: smooth, none tagged), and
 * whether all its items share it (a loop may mix sharpnesses: the first's).
 */
export function sharpnessOf(tags: MeshTags | undefined, target: TagTarget): { sharpness: number; mixed: boolean } {
  const values: number[] = [];
  if (target.kind === 'edges') {
    const map = tags ? creaseMap(tags) : new Map<string, number>();
    for (const [a, b] of target.edges) values.push(map.get(edgeKey(a, b)) ?? 0);
  } else {
    const i = tags ? tags.cornerVertices.indexOf(target.vertex) : -1;
    values.push(i >= 0 && tags ? tags.cornerSharpness[i] : 0);
  }
  return { sharpness: values[0] ?? 0, mixed: values.some((s) => s !== values[0]) };
}

/**
 * `tags` (none: {@link noTags}) with `target` at `sharpness` (clamped to
 * 0..{@link INFINITELY_SHARP}; 0 removes it). Edges keep their order; new
 * ones come last. The other tags, modes and notes stay.
 */
export function withSharpness(tags: MeshTags | undefined, target: TagTarget, sharpness: number): MeshTags {
  const base = tags ?? noTags();
  const s = Math.min(Math.max(Number.isFinite(sharpness) ? sharpness : 0, 0), INFINITELY_SHARP);
  if (target.kind === 'vertex') {
    const vertices: number[] = [];
    const values: number[] = [];
    for (let i = 0; i < base.cornerVertices.length; ++i) {
      if (base.cornerVertices[i] === target.vertex) continue;
      vertices.push(base.cornerVertices[i]);
      values.push(base.cornerSharpness[i]);
    }
    if (s > 0) {
      vertices.push(target.vertex);
      values.push(s);
    }
    return { ...base, cornerVertices: Uint32Array.from(vertices), cornerSharpness: Float32Array.from(values) };
  }
  const map = creaseMap(base);
  for (const [a, b] of target.edges) {
    if (s > 0) map.set(edgeKey(a, b), s);
    else map.delete(edgeKey(a, b));
  }
  const edges: number[] = [];
  const values: number[] = [];
  for (const [key, value] of map) {
    const [a, b] = key.split(' ').map(Number);
    edges.push(a, b);
    values.push(value);
  }
  return { ...base, creaseEdges: Uint32Array.from(edges), creaseSharpness: Float32Array.from(values) };
}

/** Whether `tags` hold anything the core applies or writes back (else the mesh goes untagged). */
export function hasTags(tags: MeshTags): boolean {
  return (
    tags.creaseEdges.length + tags.cornerVertices.length + tags.holes.length > 0 ||
    tags.boundaryGiven ||
    tags.creaseMethodGiven
  );
}

/**
 * Undo and redo of tag edits: each entry is the tags before (undo) or
 * after (redo) an edit; undefined stands for an untagged mesh.
 */
export class TagHistory {
  private readonly undos: (MeshTags | undefined)[] = [];
  private redos: (MeshTags | undefined)[] = [];

  /** Records an edit made from `before`; a new edit forgets what was undone. */
  push(before: MeshTags | undefined): void {
    this.undos.push(before);
    this.redos = [];
  }

  get canUndo(): boolean {
    return this.undos.length > 0;
  }

  get canRedo(): boolean {
    return this.redos.length > 0;
  }

  /** The tags an undo goes back to (null: nothing to undo); {@link undone} records it once applied. */
  undoTarget(): { tags: MeshTags | undefined } | null {
    return this.undos.length > 0 ? { tags: this.undos[this.undos.length - 1] } : null;
  }

  /** The undo was applied; `before`: the tags it replaced (a redo goes back to them). */
  undone(before: MeshTags | undefined): void {
    this.undos.pop();
    this.redos.push(before);
  }

  /** The tags a redo makes again (null: nothing to redo); {@link redone} records it once applied. */
  redoTarget(): { tags: MeshTags | undefined } | null {
    return this.redos.length > 0 ? { tags: this.redos[this.redos.length - 1] } : null;
  }

  /** The redo was applied; `before`: the tags it replaced. */
  redone(before: MeshTags | undefined): void {
    this.redos.pop();
    this.undos.push(before);
  }

  clear(): void {
    this.undos.length = 0;
    this.redos = [];
  }
}
