/**
 * Walking a halfedge table (core/halfedges.ts) as CGAL's tutorials do, and
 * the expression that reached a halfedge in CGAL's own spelling: for
 * Surface_mesh the free functions of the BGL interface (`next(h, m)`), for
 * Polyhedron_3 the handle's members (`h->next()`).
 *
 * "Next around the target vertex" is `opposite(next(h, m), m)`: it keeps
 * the target and turns around it, as CGAL's Halfedge_around_target_circulator
 * steps. "Next around the face" is `next(h, m)`, as
 * Halfedge_around_face_circulator steps.
 */
import type { HalfedgeTable } from '../core/halfedges';

export type HalfedgeMove = 'next' | 'prev' | 'opposite' | 'around-vertex' | 'around-face';

export const HALFEDGE_MOVES: readonly HalfedgeMove[] = ['next', 'prev', 'opposite', 'around-vertex', 'around-face'];

/** The halfedge `move` leads to from `h`. */
export function moveHalfedge(table: HalfedgeTable, h: number, move: HalfedgeMove): number {
  switch (move) {
    case 'next':
    case 'around-face':
      return table.next[h];
    case 'prev':
      return table.prev[h];
    case 'opposite':
      return table.opposite[h];
    case 'around-vertex':
      return table.opposite[table.next[h]];
  }
}

/** The vertex `h` starts from (CGAL's source: the target of its opposite). */
export function sourceOf(table: HalfedgeTable, h: number): number {
  return table.target[table.opposite[h]];
}

/** Surface_mesh's spelling of `move` applied to the expression `e`. */
function surfaceMeshStep(e: string, move: HalfedgeMove): string {
  switch (move) {
    case 'next':
    case 'around-face':
      return `next(${e}, m)`;
    case 'prev':
      return `prev(${e}, m)`;
    case 'opposite':
      return `opposite(${e}, m)`;
    case 'around-vertex':
      return `opposite(next(${e}, m), m)`;
  }
}

/** Polyhedron_3's spelling of `move` after the expression `e`. */
function polyhedronStep(e: string, move: HalfedgeMove): string {
  switch (move) {
    case 'next':
    case 'around-face':
      return `${e}->next()`;
    case 'prev':
      return `${e}->prev()`;
    case 'opposite':
      return `${e}->opposite()`;
    case 'around-vertex':
      return `${e}->next()->opposite()`;
  }
}

/**
 * The expression that follows `path` from a halfedge `h` in CGAL's
 * spelling: `['opposite', 'next']` is `next(opposite(h, m), m)` for
 * Surface_mesh (m: the mesh) and `h->opposite()->next()` for Polyhedron_3.
 */
export function cgalExpressions(path: readonly HalfedgeMove[]): { surfaceMesh: string; polyhedron: string } {
  return {
    surfaceMesh: path.reduce(surfaceMeshStep, 'h'),
    polyhedron: path.reduce(polyhedronStep, 'h'),
  };
}

/** The longest path an expression shows; older moves are folded into its start halfedge. */
export const MAX_PATH = 6;

/**
 * A walk from halfedge `from` along `path`, one move longer: past
 * {@link MAX_PATH} moves its first move is taken and its start moves on, so
 * the expression stays readable and still reaches the same halfedge.
 */
export function extendWalk(
  table: HalfedgeTable,
  walk: { from: number; path: readonly HalfedgeMove[] },
  move: HalfedgeMove,
): { from: number; path: HalfedgeMove[] } {
  let { from } = walk;
  const path = [...walk.path, move];
  while (path.length > MAX_PATH) from = moveHalfedge(table, from, path.shift() as HalfedgeMove);
  return { from, path };
}

/** What a circulation turns around: the target vertex of a halfedge, or its face (a border loop on the border). */
export type CirculationKind = 'vertex' | 'face';

/**
 * The halfedges met circulating from `h` until it comes back: around its
 * target (`opposite(next(h))`, each pointing to the vertex) or around its
 * face (`next(h)`). Their number is the vertex's degree or the face's.
 */
export function circulate(table: HalfedgeTable, h: number, kind: CirculationKind): number[] {
  const move: HalfedgeMove = kind === 'vertex' ? 'around-vertex' : 'around-face';
  const visited = [h];
  // A valid table comes back; the bound only guards against a broken one.
  for (
    let g = moveHalfedge(table, h, move);
    g !== h && visited.length <= table.next.length;
    g = moveHalfedge(table, g, move)
  )
    visited.push(g);
  return visited;
}

/** The circulation's report: "vertex 3: 3 halfedges around it", "face 2: …", "border loop: …". */
export function circulationReport(table: HalfedgeTable, h: number, kind: CirculationKind, count: number): string {
  const face = table.face[h];
  const what = kind === 'vertex' ? `vertex ${table.target[h]}` : face >= 0 ? `face ${face}` : 'border loop';
  return `${what}: ${count} halfedge${count === 1 ? '' : 's'} around it`;
}
