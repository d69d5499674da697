/**
 * The basis function view: a control vertex picked on the view (or by its
 * number) colours the shown level's surface by that vertex's influence, its
 * weight in every refined vertex through all steps (core/basis.ts, run in
 * the worker), from none (dark) to the largest (yellow). Students see the
 * support and smoothness of the scheme's basis function, and how it changes
 * at an extraordinary vertex or on a border. Another level is coloured
 * again as it is shown.
 */
import { influenceColors } from '../render/level-graphics';
import type { ViewClick } from '../render/scene-view';
import type { SubdivViewer } from '../viewer/subdiv-viewer';

/** Weights at or below this count as no influence (rounding of exact zeros). */
const NONE = 1e-12;

export interface BasisState {
  available: boolean;
  /** Clicks on the view pick a control vertex. */
  picking: boolean;
  /** The control vertex shown, with its values' largest, how many vertices it reaches, of how many. */
  shown: { vertex: number; level: number; max: number; min: number; reached: number; count: number } | null;
  controlVertices: number;
  message: string;
  /** Why the last vertex asked for is not shown (a number out of range); '' when none. */
  problem: string;
}

export class BasisView {
  private picking = false;
  private vertex: number | null = null;
  private shown: BasisState['shown'] = null;
  private message = '';
  /** The level shown coloured (its index, and its viewer.levelId). */
  private colouredLevel = -1;
  private colouredId = 0;
  private faces: Uint32Array | null = null;
  private asked = 0;
  private readonly listeners = new Set<(state: BasisState) => void>();

  constructor(
    private readonly viewer: SubdivViewer,
    private readonly onError: (error: unknown) => void,
  ) {
    viewer.onChange((state) => {
      const faces = viewer.controlMesh?.faceIndices ?? null;
      if (faces !== this.faces) {
        // Another model: its vertex numbers mean other vertices.
        const marked = this.vertex !== null;
        this.faces = faces;
        this.asked++;
        this.vertex = null;
        this.shown = null;
        this.colouredLevel = -1;
        this.colouredId = 0;
        if (marked) viewer.view.setSelection(new Float32Array(0), new Float32Array(0));
      } else if (this.vertex !== null && viewer.levelId() !== this.colouredId && !state.busy) {
        // Another level, or this one computed again (a crease edit): coloured anew.
        this.colouredId = viewer.levelId();
        void this.colour(this.vertex);
      }
      this.emit();
    });
  }

  get state(): BasisState {
    const viewer = this.viewer.state;
    return {
      available: viewer.levelCount > 0,
      picking: this.picking,
      shown: this.shown,
      controlVertices: (this.viewer.controlMesh?.positions.length ?? 0) / 3,
      message:
        this.message || (this.picking && !this.shown ? 'Click a vertex of the control mesh, or type its number.' : ''),
      problem: this.message,
    };
  }

  onChange(listener: (state: BasisState) => void): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }

  /** Turns picking on (the control mesh drawn, so that its vertices show) or off (the colours go). */
  setPicking(on: boolean): void {
    if (on === this.picking) return;
    this.picking = on;
    if (on) {
      this.viewer.setOverlay('control', true);
    } else {
      this.asked++;
      this.vertex = null;
      this.shown = null;
      this.message = '';
      this.viewer.setLevelColors(this.colouredLevel, null, 'basis');
      this.colouredLevel = -1;
      this.viewer.view.setSelection(new Float32Array(0), new Float32Array(0));
    }
    this.emit();
  }

  click(click: ViewClick): void {
    if (!this.picking) return;
    const vertex = this.pick(click);
    if (vertex !== null) void this.select(vertex);
  }

  /** The control vertex under a click of the view, or null. */
  pick(click: ViewClick): number | null {
    const pick = this.viewer.view.pickControl(click.x, click.y);
    return pick?.kind === 'vertex' ? pick.vertex : null;
  }

  /** Colours the shown level by control vertex `vertex`'s basis function. */
  async select(vertex: number): Promise<void> {
    const count = (this.viewer.controlMesh?.positions.length ?? 0) / 3;
    if (!Number.isInteger(vertex) || vertex < 0 || vertex >= count) {
      this.message = `The control mesh has vertices 0 to ${count - 1}.`;
      this.emit();
      return;
    }
    this.vertex = vertex;
    this.message = '';
    await this.colour(vertex);
  }

  private async colour(vertex: number): Promise<void> {
    const asked = ++this.asked;
    const level = this.viewer.state.level;
    const id = this.viewer.levelId();
    this.colouredId = id;
    try {
      const values = await this.viewer.basis(vertex, level);
      if (asked !== this.asked || !values || this.viewer.levelId() !== id) return;
      let max = 0;
      let min = 0;
      let reached = 0;
      for (const x of values) {
        max = Math.max(max, x);
        min = Math.min(min, x);
        if (Math.abs(x) > NONE) reached++;
      }
      const rgb = influenceColors(values, min, max);
      if (this.colouredLevel !== level) this.viewer.setLevelColors(this.colouredLevel, null, 'basis');
      this.viewer.setLevelColors(level, rgb, 'basis');
      this.colouredLevel = level;
      this.colouredId = id;
      this.shown = { vertex, level, max, min, reached, count: values.length };
      const control = this.viewer.controlMesh?.positions;
      if (control)
        this.viewer.view.setSelection(
          new Float32Array(0),
          Float32Array.from(control.subarray(3 * vertex, 3 * vertex + 3)),
        );
      this.emit();
    } catch (error) {
      if (asked === this.asked) this.onError(error);
    }
  }

  private emit(): void {
    const state = this.state;
    for (const listener of this.listeners) listener(state);
  }
}
