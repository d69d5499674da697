/**
 * The stencil inspector: a vertex of the shown level k ≥ 1, picked on the
 * view or by its number, as the weighted sum of its parents at level k − 1.
 * The weights come from the core (the step's own point pass, stencils.ts);
 * here they are only looked up, shown on the surface (the vertex, its
 * parents, a label with each weight) and handed to the panel with the
 * check Σ w·p = p, computed from the drawn points.
 */
import { fraction, type VertexStencil, vertexStencil } from '../core/stencils';
import type { ViewClick } from '../render/scene-view';
import type { SubdivViewer } from '../viewer/subdiv-viewer';

/** What the stencil panel shows. */
export interface InspectorState {
  /** A model is loaded. */
  available: boolean;
  /** Clicks on the view pick a vertex of the shown level. */
  inspecting: boolean;
  /** The shown level. */
  level: number;
  /** Vertices of the shown level (a number to type is below it). */
  vertexCount: number;
  /** The inspected vertex's stencil, its weights as text (3/8, or 4 decimals), and the sums. */
  stencil: InspectedStencil | null;
  /** Why nothing is shown, or what to do next. */
  message: string;
  /** Why the last vertex asked for is not shown (level 0, a number out of range); '' when none. */
  problem: string;
}

export interface InspectedStencil extends VertexStencil {
  level: number;
  /** Each parent's weight as shown: an exact fraction where there is one. */
  weightTexts: string[];
  /** Σ w. */
  sum: number;
  /** Σ w·p over the parents' drawn points, and the vertex's drawn point. */
  combination: [number, number, number];
  position: [number, number, number];
}

/** A weight as the inspector writes it: "3/8", or four decimals (Loop's β(5) = 0.0663). */
export function weightText(weight: number): string {
  return fraction(weight) ?? weight.toFixed(4);
}

/**
 * Where a vertex comes from, in words: the element (`vertex 7`, `edge 2–5`,
 * `face 3`; '' where the host does not name it) and its valence or degree
 * (`valence 3`, `degree 4`; '' for an edge point).
 */
export function stencilOrigin(s: VertexStencil): { of: string; size: string } {
  const of = s.edge
    ? `edge ${s.edge[0]}–${s.edge[1]}`
    : s.element !== null
      ? `${/face/.test(s.kind) ? 'face' : 'vertex'} ${s.element}`
      : '';
  const size = s.edge ? '' : /face|corner/.test(s.kind) ? `degree ${s.size}` : `valence ${s.size}`;
  return { of, size };
}

/** The vertex's kind and origin in one phrase: "vertex point of vertex 7, valence 3". */
export function stencilKindText(s: VertexStencil): string {
  const { of, size } = stencilOrigin(s);
  return `${s.kind}${of ? ` of ${of}` : ''}${size ? `, ${size}` : ''}`;
}

/**
 * The weighted sum of the parents, equal weights grouped, largest first:
 * "5/12·v7 + 1/6·(v1 + v3 + v6) + 1/36·(v0 + v2 + v5)" (v: a vertex of the
 * level before).
 */
export function stencilSum(s: VertexStencil): string {
  const groups = new Map<string, { weight: number; vertices: number[] }>();
  for (const { vertex, weight } of s.parents) {
    const text = weightText(Math.abs(weight));
    const key = `${weight < 0 ? '-' : ''}${text}`;
    const group = groups.get(key) ?? { weight, vertices: [] };
    group.vertices.push(vertex);
    groups.set(key, group);
  }
  const terms = [...groups.values()].sort((a, b) => b.weight - a.weight);
  return terms
    .map(({ weight, vertices }, i) => {
      const sign = weight < 0 ? (i === 0 ? '−' : ' − ') : i === 0 ? '' : ' + ';
      const points = vertices.map((v) => `v${v}`);
      const sum = points.length === 1 ? points[0] : `(${points.join(' + ')})`;
      return `${sign}${weightText(Math.abs(weight))}·${sum}`;
    })
    .join('');
}

export class StencilInspector {
  private inspecting = false;
  private inspected: InspectedStencil | null = null;
  private message = '';
  /** The level object the inspected vertex belongs to (viewer.levelId): another one drops it. */
  private shownLevel = 0;
  private readonly listeners = new Set<(state: InspectorState) => void>();
  /** Counts selections, so that a slow table for an earlier click is not shown. */
  private asked = 0;

  /** `onError` hears of stencils the core could not make. */
  constructor(
    private readonly viewer: SubdivViewer,
    private readonly onError: (error: unknown) => void,
  ) {
    viewer.onChange(() => {
      // Another level, or this one computed again (a new model, scheme or crease edit).
      if (viewer.levelId() !== this.shownLevel) {
        this.shownLevel = viewer.levelId();
        this.clear();
      }
      this.emit();
    });
  }

  get state(): InspectorState {
    const viewer = this.viewer.state;
    return {
      available: viewer.levelCount > 0,
      inspecting: this.inspecting,
      level: viewer.level,
      vertexCount: viewer.facts?.vertices ?? 0,
      stencil: this.inspected,
      message: this.message || this.hint(),
      problem: this.message,
    };
  }

  onChange(listener: (state: InspectorState) => void): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }

  setInspecting(on: boolean): void {
    if (on === this.inspecting) return;
    this.inspecting = on;
    if (!on) this.clear();
    this.emit();
  }

  /** Inspects the vertex under a click of the view (nothing there: clears). */
  click(click: ViewClick): void {
    if (!this.inspecting) return;
    const vertex = this.pick(click);
    if (vertex === null) this.clear();
    else void this.select(vertex);
  }

  /** The vertex of the shown level under a click of the view, or null. */
  pick(click: ViewClick): number | null {
    return this.viewer.view.pickVertex(click.x, click.y);
  }

  /** Inspects vertex `vertex` of the shown level. */
  async select(vertex: number): Promise<void> {
    const level = this.viewer.state.level;
    const id = this.viewer.levelId();
    const asked = ++this.asked;
    if (level < 1) {
      this.inspected = null;
      this.message = 'Level 0 is the control mesh: subdivide, then pick a vertex of level 1 or higher.';
      this.showMarks();
      this.emit();
      return;
    }
    try {
      const table = await this.viewer.stencils(level);
      if (asked !== this.asked || this.viewer.levelId() !== id || !table) return;
      if (vertex < 0 || vertex >= table.kinds.length) {
        this.message = `Level ${level} has vertices 0 to ${table.kinds.length - 1}.`;
        this.emit();
        return;
      }
      this.inspected = this.withSums(vertexStencil(table, vertex), level);
      this.message = '';
      this.showMarks();
      this.emit();
    } catch (error) {
      if (asked === this.asked) this.onError(error);
    }
  }

  private withSums(stencil: VertexStencil, level: number): InspectedStencil {
    const parents = this.viewer.buffersOf(level - 1)?.positions ?? new Float32Array(0);
    const points = this.viewer.buffersOf(level)?.positions ?? new Float32Array(0);
    const combination: [number, number, number] = [0, 0, 0];
    for (const { vertex, weight } of stencil.parents)
      for (let i = 0; i < 3; ++i) combination[i] += weight * parents[3 * vertex + i];
    const v = stencil.vertex;
    return {
      ...stencil,
      level,
      weightTexts: stencil.parents.map((p) => weightText(p.weight)),
      sum: stencil.parents.reduce((total, p) => total + p.weight, 0),
      combination,
      position: [points[3 * v], points[3 * v + 1], points[3 * v + 2]],
    };
  }

  private clear(): void {
    this.asked++;
    const shown = this.inspected !== null;
    this.inspected = null;
    this.message = '';
    if (shown) this.showMarks();
  }

  private hint(): string {
    if (!this.inspecting) return 'Why a vertex lands where it does: its parents and their weights.';
    if (this.viewer.state.level < 1) return 'Subdivide, then click a vertex of level 1 or higher.';
    return this.inspected ? '' : 'Click a vertex of the surface, or type its number.';
  }

  /** The inspected vertex and its parents (with their weights) on the view. */
  private showMarks(): void {
    const s = this.inspected;
    const view = this.viewer.view;
    if (!s) {
      view.setSelection(new Float32Array(0), new Float32Array(0));
      view.setParents(new Float32Array(0), []);
      return;
    }
    const parents = this.viewer.buffersOf(s.level - 1)?.positions ?? new Float32Array(0);
    const at = new Float32Array(3 * s.parents.length);
    s.parents.forEach((p, i) => {
      at.set(parents.subarray(3 * p.vertex, 3 * p.vertex + 3), 3 * i);
    });
    view.setSelection(new Float32Array(0), Float32Array.from(s.position));
    view.setParents(at, s.weightTexts, s.position);
  }

  private emit(): void {
    const state = this.state;
    for (const listener of this.listeners) listener(state);
  }
}
