/**
 * CGAL's Euler operators, step by step, on the halfedge the explorer
 * picked, and "√3 by hand": one √3 step replayed operator by operator as
 * the tutorial writes it (a centre vertex per face, a flip per old edge,
 * the old vertices smoothed). The core (in the worker) applies them and
 * checks the result; here each result becomes the shown model's level 0
 * (SubdivViewer.load, the camera kept), and Undo loads the exact mesh
 * before it again.
 */
import type { EulerOperator } from '../core/halfedges';
import type { Mesh, MeshFacts } from '../core/mesh';
import { SubdivError } from '../core/subdiv-error';
import type { Sqrt3Check } from '../core/worker-protocol';
import type { SubdivViewer } from '../viewer/subdiv-viewer';
import type { HalfedgeExplorer } from './halfedge-explorer';

/** Milliseconds between two operators while the walk-through plays. */
const PLAY_STEP_MS = 120;

/** What the operator did, or the undo, with the facts and CGAL's validity of the mesh shown after it. */
export interface EditOutcome {
  /** The operator's name (CGAL's), or 'undo'. */
  what: EulerOperator | 'undo';
  facts: MeshFacts;
  /** CGAL's is_valid_polygon_mesh of the result; null: the model as loaded (not checked here). */
  valid: boolean | null;
}

export interface Sqrt3WalkState {
  done: number;
  total: number;
  last: string;
  playing: boolean;
  /** Once every operator is done: the verdict of the comparison with the √3 scheme's level 1. */
  verdict: string;
  equal: boolean | null;
}

export interface EulerState {
  /** A halfedge is picked in the explorer. */
  available: boolean;
  canUndo: boolean;
  /** The shown model's level 0 is an edited mesh. */
  edited: boolean;
  outcome: EditOutcome | null;
  /** The core's refusal of the last operator or walk (its precondition named); '' when none. */
  problem: string;
  walk: Sqrt3WalkState | null;
}

interface Saved {
  mesh: Mesh;
  name: string;
  valid: boolean | null;
}

export class EulerSteps {
  private readonly undoStack: Saved[] = [];
  private outcome: EditOutcome | null = null;
  private problem = '';
  private walk: (Sqrt3WalkState & { source: Mesh; name: string }) | null = null;
  private playing = false;
  private busy = false;
  /** The mesh the last edit, undo or walk step showed: another level 0 (a model loaded) ends the history. */
  private shownMesh: Mesh | null = null;
  private readonly listeners = new Set<(state: EulerState) => void>();

  constructor(
    private readonly viewer: SubdivViewer,
    private readonly explorer: HalfedgeExplorer,
    private readonly onError: (error: unknown) => void,
  ) {
    explorer.onChange(() => this.emit());
    viewer.onChange(() => {
      const mesh = viewer.controlMesh;
      if (this.busy || !this.shownMesh || !mesh || mesh === this.shownMesh) return;
      this.undoStack.length = 0;
      this.shownMesh = null;
      this.outcome = null;
      this.problem = '';
      this.walk = null;
      this.playing = false;
      this.emit();
    });
  }

  get state(): EulerState {
    const walk = this.walk;
    return {
      available: this.explorer.state.picked !== null && !this.busy,
      canUndo: this.undoStack.length > 0 && !this.busy,
      edited: this.undoStack.length > 0,
      outcome: this.outcome,
      problem: this.problem,
      walk: walk
        ? {
            done: walk.done,
            total: walk.total,
            last: walk.last,
            playing: this.playing,
            verdict: walk.verdict,
            equal: walk.equal,
          }
        : null,
    };
  }

  onChange(listener: (state: EulerState) => void): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }

  /** Applies `op` to the picked halfedge (split_face: with the second one) of the shown level. */
  async apply(op: EulerOperator): Promise<void> {
    const picked = this.explorer.state.picked;
    const second = this.explorer.state.second;
    if (!picked || this.busy) return;
    if (op === 'split_face' && second === null) {
      this.problem = 'Split a face: pick a second halfedge of the same face first (Second halfedge…).';
      return this.emit();
    }
    await this.run(async () => {
      const mesh = await this.viewer.meshOf();
      const name = this.viewer.state.modelName ?? 'mesh';
      if (!mesh) return;
      const result = await this.viewer.core.euler(mesh, op, picked.h, second ?? 0);
      this.undoStack.push({ mesh, name, valid: this.outcome?.valid ?? null });
      this.walk = null;
      this.explorer.pickAfterLoad(result.halfedge);
      await this.show(result.mesh, name.endsWith(' (edited)') ? name : `${name} (edited)`);
      this.outcome = { what: op, facts: result.facts, valid: result.valid };
    });
  }

  /** Shows the mesh before the last operator (or before the walk-through) again, exactly as it was. */
  async undo(): Promise<void> {
    const saved = this.undoStack.at(-1);
    if (!saved || this.busy) return;
    this.stop();
    await this.run(async () => {
      await this.show(saved.mesh, saved.name);
      this.undoStack.pop();
      this.walk = null;
      const facts = this.viewer.state.facts;
      this.outcome = facts ? { what: 'undo', facts, valid: saved.valid } : null;
    });
  }

  /** One more operator of the walk-through (its first: from the shown model's level 0). */
  async step(): Promise<void> {
    if (this.busy) return;
    await this.run(async () => {
      if (!this.walk || this.walk.done === this.walk.total) await this.begin();
      const walk = this.walk;
      if (!walk) return;
      const next = await this.viewer.core.sqrt3ByHand(walk.source, walk.done + 1);
      await this.showWalk(next);
    });
  }

  /** Plays the walk-through to its end, an operator at a time (Pause stops it). */
  async play(): Promise<void> {
    if (this.playing) return;
    this.playing = true;
    this.emit();
    while (this.playing) {
      await this.step();
      if (!this.walk || this.problem || this.walk.done === this.walk.total) break;
      await new Promise((resolve) => setTimeout(resolve, PLAY_STEP_MS));
    }
    this.playing = false;
    this.emit();
  }

  /** Pauses the walk-through. */
  stop(): void {
    this.playing = false;
    this.emit();
  }

  private async begin(): Promise<void> {
    const source = this.viewer.controlMesh;
    const name = this.viewer.state.modelName ?? 'mesh';
    if (!source) return;
    // Refused meshes (open, not triangles) come back with the core's message, before anything changes.
    const first = await this.viewer.core.sqrt3ByHand(source, 0);
    this.undoStack.push({ mesh: source, name, valid: this.outcome?.valid ?? null });
    this.walk = { source, name, done: 0, total: first.total, last: '', playing: false, verdict: '', equal: null };
  }

  private async showWalk(next: Sqrt3Check): Promise<void> {
    const walk = this.walk;
    if (!walk) return;
    await this.show(next.mesh, `${walk.name} (√3 by hand)`);
    walk.done = next.done;
    walk.last = next.last;
    const c = next.comparison;
    walk.equal = c ? c.match : null;
    walk.verdict = !c
      ? ''
      : c.match
        ? `Equal to the √3 scheme's level 1: same ${c.referenceVertices} vertices and ${c.referenceFaces} faces, ` +
          `largest distance ${c.maxError.toExponential(1)} (tolerance ${c.tolerance.toExponential(1)}).`
        : `Not the √3 scheme's level 1: ${c.reasons.join(' ')}`;
    this.outcome = null;
  }

  /** Loads `mesh` as the shown model's level 0, keeping the camera where it is. */
  private async show(mesh: Mesh, name: string): Promise<void> {
    const view = this.viewer.getView();
    await this.viewer.load(mesh, name);
    this.shownMesh = mesh;
    this.viewer.setView(view);
  }

  private async run(work: () => Promise<void>): Promise<void> {
    this.busy = true;
    this.problem = '';
    this.emit();
    try {
      await work();
    } catch (error) {
      this.problem = error instanceof Error ? error.message : String(error);
      this.playing = false;
      // The core's refusals (a broken precondition) are the panel's to show; anything else is the app's.
      if (!(error instanceof SubdivError)) this.onError(error);
    } finally {
      this.busy = false;
      this.emit();
    }
  }

  private emit(): void {
    const state = this.state;
    for (const listener of this.listeners) listener(state);
  }
}
