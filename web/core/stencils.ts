/**
 * The stencils of a step as the core gives them (wasm/src/core/stencils.h):
 * each refined vertex as a weighted sum of the vertices of the level
 * before, with its origin (kind, element, valence or degree) and the
 * scheme's formula for that kind; and weights written as exact fractions
 * where they are rational with a small denominator (3/8, 1/64).
 */

/** A step's stencil table, typed arrays as the core fills them. */
export interface StencilTable {
  parentVertices: number;
  /** Refined vertex v's parents and weights are [offsets[v], offsets[v + 1]). */
  offsets: Uint32Array;
  parents: Uint32Array;
  weights: Float64Array;
  /** Per refined vertex: an index into kindNames. */
  kinds: Uint8Array;
  /** The vertex, edge or face it comes from (0xffffffff: not named by the host). */
  elements: Uint32Array;
  /** That vertex's valence, or that face's degree; 2 for an edge. */
  sizes: Uint32Array;
  /** An edge point's edge ends, two per refined vertex (0xffffffff: none). */
  ends: Uint32Array;
  kindNames: string[];
  /** The scheme's formula for each kind that occurs, by kind name. */
  formulas: Record<string, string>;
}

export const NO_ELEMENT = 0xffffffff;

/** One refined vertex's stencil. */
export interface VertexStencil {
  vertex: number;
  /** "vertex point", "edge point", "face point", "border vertex", "corner point", "relaxed vertex", ... */
  kind: string;
  /** The vertex, edge or face it comes from; null where the host does not name it. */
  element: number | null;
  /** Valence (vertex kinds) or degree (face and corner kinds). */
  size: number;
  /** An edge point's edge, as its two ends. */
  edge: [number, number] | null;
  formula: string;
  parents: { vertex: number; weight: number }[];
}

export function vertexStencil(table: StencilTable, vertex: number): VertexStencil {
  if (!Number.isInteger(vertex) || vertex < 0 || vertex >= table.kinds.length) {
    throw new RangeError(`vertex ${vertex} is not a vertex of the level (0 to ${table.kinds.length - 1})`);
  }
  const kind = table.kindNames[table.kinds[vertex]];
  const parents: { vertex: number; weight: number }[] = [];
  for (let i = table.offsets[vertex]; i < table.offsets[vertex + 1]; ++i)
    parents.push({ vertex: table.parents[i], weight: table.weights[i] });
  const [a, b] = [table.ends[2 * vertex], table.ends[2 * vertex + 1]];
  return {
    vertex,
    kind,
    element: table.elements[vertex] === NO_ELEMENT ? null : table.elements[vertex],
    size: table.sizes[vertex],
    edge: a === NO_ELEMENT ? null : [a, b],
    formula: table.formulas[kind] ?? '',
    parents,
  };
}

/**
 * `weight` as "p/q" when it is p/q to the last bits with q ≤ 4096 (continued
 * fractions), else null: 0.375 → "3/8", Loop's β(5) → null.
 */
export function fraction(weight: number): string | null {
  if (!Number.isFinite(weight)) return null;
  const tolerance = 4 * Number.EPSILON * Math.max(1, Math.abs(weight));
  // Convergents h/k of the continued fraction of weight.
  let [h0, h1, k0, k1] = [0, 1, 1, 0];
  let x = weight;
  for (let i = 0; i < 40; ++i) {
    const a = Math.floor(x);
    [h0, h1] = [h1, a * h1 + h0];
    [k0, k1] = [k1, a * k1 + k0];
    if (k1 > 4096) return null;
    if (Math.abs(weight - h1 / k1) <= tolerance) return k1 === 1 ? String(h1) : `${h1}/${k1}`;
    const rest = x - a;
    if (rest === 0) return null;
    x = 1 / rest;
  }
  return null;
}
