/**
 * Crease editing on a viewer's control mesh: a click picks a control edge
 * (Alt+click: its edge loop) or vertex, a sharpness (0 smooth .. 10
 * infinitely sharp) goes into level 0's tags, and the viewer computes its
 * levels again up to the one shown. Every edit can be undone and redone.
 * The editor owns the selection and the history; panels show its state.
 */
import type { MeshTags } from '../core/mesh';
import type { ViewClick } from '../render/scene-view';
import { schemeInfo } from '../viewer/scheme-info';
import type { SubdivViewer } from '../viewer/subdiv-viewer';
import { ControlTopology } from './control-topology';
import { hasTags, sharpnessOf, TagHistory, type TagTarget, withSharpness } from './tag-edits';

/** What the crease panel shows. */
export interface CreaseEditorState {
  /** A model is loaded. */
  available: boolean;
  /** Clicks on the view pick control edges and vertices. */
  editing: boolean;
  /** The scheme applies tags (Catmull-Clark, Loop); else the panel says that it ignores them. */
  schemeApplies: boolean;
  schemeLabel: string;
  /** What is selected ("Edge 1–5", "Edge loop: 4 edges", "Vertex 2"), its sharpness, and whether its edges differ. */
  selection: { label: string; sharpness: number; mixed: boolean } | null;
  canUndo: boolean;
  canRedo: boolean;
}

export class CreaseEditor {
  private editing = false;
  private target: TagTarget | null = null;
  private readonly history = new TagHistory();
  /** The control mesh's connectivity (built at the first click on a model). */
  private topology: ControlTopology | null = null;
  /**
   * The face list of the model the topology, selection and history are of:
   * tag edits keep it, a new model comes with another.
   */
  private faces: Uint32Array | null = null;
  private readonly listeners = new Set<(state: CreaseEditorState) => void>();
  /** The last edit asked for (each waits for the one before). */
  private edits: Promise<unknown> = Promise.resolve();

  /** `onError` hears of an edit the viewer could not compute (the previous levels stay). */
  constructor(
    private readonly viewer: SubdivViewer,
    private readonly onError: (error: unknown) => void,
  ) {
    viewer.onChange(() => {
      this.forgetIfNewModel();
      this.emit();
    });
  }

  get state(): CreaseEditorState {
    const viewer = this.viewer.state;
    const info = schemeInfo(viewer.scheme);
    const tags = this.viewer.controlMesh?.tags;
    return {
      available: viewer.levelCount > 0,
      editing: this.editing,
      schemeApplies: info.creases,
      schemeLabel: info.label,
      selection: this.target ? { label: labelOf(this.target), ...sharpnessOf(tags, this.target) } : null,
      canUndo: this.history.canUndo,
      canRedo: this.history.canRedo,
    };
  }

  onChange(listener: (state: CreaseEditorState) => void): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }

  /** Turns picking on the view on or off; on, the control mesh is drawn so that its edges can be seen. */
  setEditing(on: boolean): void {
    if (on === this.editing) return;
    this.editing = on;
    if (on) this.viewer.setOverlay('control', true);
    else this.select(null);
    this.emit();
  }

  /** Picks what is under a click: a vertex, an edge, or (Alt) the edge's loop; nothing clears the selection. */
  click(click: ViewClick): void {
    if (!this.editing) return;
    const pick = this.viewer.view.pickControl(click.x, click.y);
    const topology = this.currentTopology();
    if (!pick || !topology) this.select(null);
    else if (pick.kind === 'vertex') this.select({ kind: 'vertex', vertex: pick.vertex });
    else this.select({ kind: 'edges', edges: click.altKey ? topology.edgeLoop(pick.a, pick.b) : [[pick.a, pick.b]] });
  }

  /** Selects `target` (control edges or a vertex; null: nothing), as a click would. */
  select(target: TagTarget | null): void {
    this.target = target;
    if (target) this.faces = this.viewer.controlMesh?.faceIndices ?? null;
    this.showSelection();
    this.emit();
  }

  /**
   * Sets the selection's sharpness (0 smooth, 10 and more infinitely
   * sharp) and computes the levels again. Edits run one after another, each
   * on the tags the one before left, so that quick edits all count.
   * Resolves false when nothing is selected or nothing changes.
   */
  setSharpness(sharpness: number): Promise<boolean> {
    const target = this.target;
    return this.queued(async () => {
      const mesh = this.viewer.controlMesh;
      if (!target || !mesh) return false;
      const now = sharpnessOf(mesh.tags, target);
      const next = withSharpness(mesh.tags, target, sharpness);
      if (!now.mixed && sharpnessOf(next, target).sharpness === now.sharpness) return false;
      if (await this.apply(next)) this.history.push(mesh.tags);
      return true;
    });
  }

  /** Goes back one edit; false when there is none. */
  undo(): boolean {
    return this.travel('undo');
  }

  /** Makes an undone edit again; false when there is none. */
  redo(): boolean {
    return this.travel('redo');
  }

  private travel(kind: 'undo' | 'redo'): boolean {
    if (!(kind === 'undo' ? this.history.canUndo : this.history.canRedo)) return false;
    void this.queued(async () => {
      const mesh = this.viewer.controlMesh;
      const step = kind === 'undo' ? this.history.undoTarget() : this.history.redoTarget();
      if (!mesh || !step || !(await this.apply(step.tags))) return;
      if (kind === 'undo') this.history.undone(mesh.tags);
      else this.history.redone(mesh.tags);
      this.emit();
    });
    return true;
  }

  /** Runs `edit` after the edits asked for before it. */
  private queued<T>(edit: () => Promise<T>): Promise<T> {
    const run = this.edits.then(edit);
    this.edits = run.catch(() => undefined);
    return run;
  }

  /** Hands `tags` to the viewer (dropped when they hold nothing); false when that failed. */
  private async apply(tags: MeshTags | undefined): Promise<boolean> {
    try {
      await this.viewer.setControlTags(tags && hasTags(tags) ? tags : undefined);
      return true;
    } catch (error) {
      this.onError(error);
      return false;
    } finally {
      this.showSelection();
      this.emit();
    }
  }

  private currentTopology(): ControlTopology | null {
    const mesh = this.viewer.controlMesh;
    if (!mesh) return null;
    this.topology ??= new ControlTopology(mesh);
    this.faces = mesh.faceIndices;
    return this.topology;
  }

  /** A new model (other faces than the ones edited): the topology, selection and history go. */
  private forgetIfNewModel(): void {
    const faces = this.viewer.controlMesh?.faceIndices ?? null;
    if (this.faces === faces || this.faces === null) return;
    this.faces = null;
    this.topology = null;
    this.target = null;
    this.history.clear();
    this.showSelection();
  }

  /** Marks the selected edges or vertex on the view, at the control mesh's points. */
  private showSelection(): void {
    const positions = this.viewer.controlMesh?.positions;
    const target = positions ? this.target : null;
    const segments: number[] = [];
    const points: number[] = [];
    if (positions && target?.kind === 'edges') {
      for (const [a, b] of target.edges)
        segments.push(...positions.subarray(3 * a, 3 * a + 3), ...positions.subarray(3 * b, 3 * b + 3));
    } else if (positions && target?.kind === 'vertex') {
      points.push(...positions.subarray(3 * target.vertex, 3 * target.vertex + 3));
    }
    this.viewer.view.setSelection(Float32Array.from(segments), Float32Array.from(points));
  }

  private emit(): void {
    const state = this.state;
    for (const listener of this.listeners) listener(state);
  }
}

function labelOf(target: TagTarget): string {
  if (target.kind === 'vertex') return `Vertex ${target.vertex}`;
  const [a, b] = target.edges[0];
  if (target.edges.length === 1) return `Edge ${a}–${b}`;
  return `Edge loop: ${target.edges.length} edges`;
}
