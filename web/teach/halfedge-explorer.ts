/**
 * The halfedge explorer: every halfedge of the shown level drawn as an
 * arrow (render/halfedge-arrows.ts), one picked on the view or by its
 * number, and walked with next, prev, opposite, next around the target
 * vertex and next around the face (halfedge-moves.ts), the expression that
 * reached it spelled as CGAL spells it. Circulating a vertex or a face
 * steps around it on the view and reports its degree. The table comes from
 * the core (the worker), numbered as CGAL's Surface_mesh numbers the level.
 */
import type { HalfedgeTable } from '../core/halfedges';
import { HalfedgeArrows } from '../render/halfedge-arrows';
import type { ViewClick } from '../render/scene-view';
import type { SubdivViewer } from '../viewer/subdiv-viewer';
import {
  type CirculationKind,
  cgalExpressions,
  circulate,
  circulationReport,
  extendWalk,
  type HalfedgeMove,
  moveHalfedge,
  sourceOf,
} from './halfedge-moves';

/** The largest level the explorer draws: beyond, arrows are too many to read (and to draw). */
export const MAX_EXPLORED_HALFEDGES = 5000;

/** Milliseconds between two steps of a circulation. */
const CIRCULATION_STEP_MS = 350;

/** The picked halfedge and its neighbours' numbers. */
export interface PickedHalfedge {
  h: number;
  source: number;
  target: number;
  /** −1: a border halfedge. */
  face: number;
  next: number;
  prev: number;
  opposite: number;
}

export interface ExplorerState {
  /** A model is loaded. */
  available: boolean;
  exploring: boolean;
  level: number;
  /** Halfedges of the shown level (0 while its table is on its way or refused). */
  halfedgeCount: number;
  /** Why the shown level is not drawn (too large, or the core refused it); '' otherwise. */
  refusal: string;
  picked: PickedHalfedge | null;
  /** The halfedge the expressions start from, and the expressions that reach the picked one. */
  from: number | null;
  surfaceMesh: string;
  polyhedron: string;
  /** A circulation under way or done: its halfedges so far and, once done, its report. */
  circulation: { kind: CirculationKind; visited: number[]; done: boolean; report: string } | null;
  /** The next pick is split_face's second halfedge. */
  choosingSecond: boolean;
  second: number | null;
  /** What to do next. */
  hint: string;
}

/**
 * Why a level of `count` halfedges is not drawn, naming the computed levels
 * that are small enough (`levelCounts`: each level's halfedges).
 */
export function sizeRefusal(count: number, levelCounts: readonly number[]): string {
  const small = levelCounts.flatMap((n, k) => (n <= MAX_EXPLORED_HALFEDGES ? [String(k)] : []));
  const pick =
    small.length === 0
      ? 'Load a smaller mesh.'
      : `Pick level ${small.length === 1 ? small[0] : `${small.slice(0, -1).join(', ')} or ${small.at(-1)}`}.`;
  const n = (x: number) => x.toLocaleString('en-US');
  return `The halfedge explorer shows meshes up to ${n(MAX_EXPLORED_HALFEDGES)} halfedges; this level has ${n(count)}. ${pick}`;
}

export class HalfedgeExplorer {
  private exploring = false;
  private table: HalfedgeTable | null = null;
  private arrows: HalfedgeArrows | null = null;
  private refusal = '';
  private shownLevel = 0;
  private picked: number | null = null;
  private walk: { from: number; path: HalfedgeMove[] } | null = null;
  private circulation: ExplorerState['circulation'] = null;
  private timer: ReturnType<typeof setTimeout> | null = null;
  private choosingSecond = false;
  private second: number | null = null;
  /** The halfedge to pick once the next level's table is in (an Euler operator's result). */
  private pending: number | null = null;
  private asked = 0;
  private readonly listeners = new Set<(state: ExplorerState) => void>();

  constructor(
    private readonly viewer: SubdivViewer,
    private readonly onError: (error: unknown) => void,
  ) {
    viewer.onChange(() => {
      if (viewer.levelId() !== this.shownLevel) {
        this.shownLevel = viewer.levelId();
        if (this.exploring) void this.loadTable();
      }
      this.emit();
    });
  }

  get state(): ExplorerState {
    const table = this.table;
    const h = this.picked;
    const expressions = cgalExpressions(this.walk?.path ?? []);
    return {
      available: this.viewer.state.levelCount > 0,
      exploring: this.exploring,
      level: this.viewer.state.level,
      halfedgeCount: table?.next.length ?? 0,
      refusal: this.refusal,
      picked:
        table && h !== null
          ? {
              h,
              source: sourceOf(table, h),
              target: table.target[h],
              face: table.face[h],
              next: table.next[h],
              prev: table.prev[h],
              opposite: table.opposite[h],
            }
          : null,
      from: this.walk?.from ?? null,
      surfaceMesh: expressions.surfaceMesh,
      polyhedron: expressions.polyhedron,
      circulation: this.circulation,
      choosingSecond: this.choosingSecond,
      second: this.second,
      hint: this.hint(),
    };
  }

  /** The shown level's table (null when not exploring or refused). */
  get halfedges(): HalfedgeTable | null {
    return this.table;
  }

  onChange(listener: (state: ExplorerState) => void): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }

  setExploring(on: boolean): void {
    if (on === this.exploring) return;
    this.exploring = on;
    if (on) void this.loadTable();
    else this.drop();
    this.emit();
  }

  /** Picks the halfedge under a click of the view (split_face's second while choosing it). */
  click(click: ViewClick): void {
    if (!this.exploring || !this.arrows) return;
    const { width, height } = this.viewer.view.size;
    const h = this.arrows.pick(this.viewer.view.camera, click.x, click.y, width, height);
    if (h !== null) this.select(h);
  }

  /** Picks halfedge `h` (a number out of range is ignored); while choosing split_face's second, that one. */
  select(h: number): void {
    if (!this.table || !Number.isInteger(h) || h < 0 || h >= this.table.next.length) return;
    this.stopCirculation();
    if (this.choosingSecond) {
      this.second = h;
      this.choosingSecond = false;
    } else {
      this.picked = h;
      this.walk = { from: h, path: [] };
      this.second = null;
    }
    this.redraw();
  }

  /** Follows `move` from the picked halfedge. */
  move(move: HalfedgeMove): void {
    if (!this.table || this.picked === null || !this.walk) return;
    this.stopCirculation();
    this.picked = moveHalfedge(this.table, this.picked, move);
    this.walk = extendWalk(this.table, this.walk, move);
    this.redraw();
  }

  /** Steps around the picked halfedge's target vertex or its face on the view, then reports the degree. */
  circulate(kind: CirculationKind): void {
    const table = this.table;
    const h = this.picked;
    if (!table || h === null) return;
    this.stopCirculation();
    const all = circulate(table, h, kind);
    this.circulation = { kind, visited: [], done: false, report: '' };
    const step = (i: number) => {
      if (!this.circulation) return;
      const done = i >= all.length;
      this.circulation = {
        kind,
        visited: all.slice(1, Math.min(i, all.length)),
        done,
        report: done ? circulationReport(table, h, kind, all.length) : '',
      };
      this.redraw();
      this.timer = done ? null : setTimeout(() => step(i + 1), CIRCULATION_STEP_MS);
    };
    step(1);
  }

  /** The next pick is split_face's second halfedge (on the picked one's face). */
  chooseSecond(on: boolean): void {
    this.choosingSecond = on && this.picked !== null;
    if (on) this.second = null;
    this.redraw();
  }

  /** Picks `h` once the next level's table is in (the halfedge an Euler operator returned). */
  pickAfterLoad(h: number): void {
    this.pending = h;
  }

  /** Where the middle of `h`'s arrow is drawn, CSS pixels from the view's top left (for tests). */
  arrowOnScreen(h: number): { x: number; y: number } | null {
    const { width, height } = this.viewer.view.size;
    return this.arrows?.arrowOnScreen(h, this.viewer.view.camera, width, height) ?? null;
  }

  private async loadTable(): Promise<void> {
    const asked = ++this.asked;
    const pending = this.pending;
    this.pending = null;
    this.clearTable();
    const facts = this.viewer.state.facts;
    if (!facts) return this.emit();
    const count = 2 * facts.edges;
    if (count > MAX_EXPLORED_HALFEDGES) {
      this.refusal = sizeRefusal(
        count,
        this.viewer.state.levelFacts.map((f) => 2 * f.edges),
      );
      return this.emit();
    }
    try {
      const [table, mesh] = await Promise.all([this.viewer.halfedges(), this.viewer.meshOf()]);
      if (asked !== this.asked || !this.exploring || !table || !mesh) return;
      this.table = table;
      this.arrows = new HalfedgeArrows(mesh.positions, table);
      this.viewer.view.setExtras(this.arrows.group);
      if (pending !== null && pending < table.next.length) this.select(pending);
      else this.redraw();
    } catch (error) {
      if (asked !== this.asked) return;
      this.refusal = error instanceof Error ? error.message : String(error);
      this.onError(error);
      this.emit();
    }
  }

  private clearTable(): void {
    this.stopCirculation();
    this.table = null;
    this.refusal = '';
    this.picked = null;
    this.walk = null;
    this.second = null;
    this.choosingSecond = false;
    if (this.arrows) {
      this.viewer.view.setExtras(null);
      this.arrows.dispose();
      this.arrows = null;
    }
  }

  private drop(): void {
    this.asked++;
    this.clearTable();
  }

  private stopCirculation(): void {
    if (this.timer !== null) clearTimeout(this.timer);
    this.timer = null;
    this.circulation = null;
  }

  private redraw(): void {
    this.arrows?.setMarks({
      picked: this.picked,
      visited: this.circulation?.visited ?? [],
      second: this.second,
    });
    this.viewer.view.requestRender();
    this.emit();
  }

  private hint(): string {
    if (!this.exploring) return 'Walk the halfedge structure: next, prev, opposite, around a vertex or a face.';
    if (this.refusal) return '';
    if (!this.table) return 'Working out the halfedges…';
    if (this.choosingSecond) return 'Click a second halfedge of the same face (or type its number).';
    if (this.picked === null) return 'Click an arrow (a halfedge), or type its number.';
    return '';
  }

  private emit(): void {
    const state = this.state;
    for (const listener of this.listeners) listener(state);
  }
}
