/**
 * Inspect: CGAL's geometry around the shown level, computed in the worker
 * (core/inspect.ts) and kept per level, so that scrubbing shows a level's
 * figures at once; once the user inspected, each level shown next is
 * inspected with the same choices. Level 0's measures are kept too, for
 * how much a scheme changes area, volume and size. The results are drawn
 * over the surface (render/inspect-graphics.ts). It starts with the
 * self-intersections alone (the sphere, hull and planes would bury the red
 * faces); a box ticked later computes its figure then. What the user asks
 * for is framed: the crossing faces and the layers shown, or a pair.
 */
import { Sphere, Vector3 } from 'three';
import type { Inspection, InspectOptions, MeshMeasures } from '../core/inspect';
import { CancelledError } from '../core/worker-client';
import { InspectGraphics, type InspectLayers } from '../render/inspect-graphics';
import type { SubdivViewer } from '../viewer/subdiv-viewer';

/** What to compute besides the measures. */
export type InspectChoices = Required<Omit<InspectOptions, 'maxPairs'>>;

export interface InspectorState {
  /** A model is loaded. */
  available: boolean;
  level: number;
  choices: InspectChoices;
  layers: InspectLayers;
  /** The shown level's inspection (null: not yet). */
  result: Inspection | null;
  /** Level 0's measures (null: not yet), to compare the shown level's with. */
  control: MeshMeasures | null;
  busy: boolean;
  framed: [number, number] | null;
  message: string;
}

/** Pairs of crossing faces listed (all are counted). */
const LISTED_PAIRS = 100;

export class MeshInspector {
  private choices: InspectChoices = { selfIntersections: true, sphere: false, hull: false, width: false };
  private layers: InspectLayers = { intersections: true, sphere: false, hull: false, width: false };
  /** Inspections by level object (viewer.levelId): a recomputed level has another. */
  private readonly results = new Map<number, Inspection>();
  private control: { faces: Uint32Array; measures: MeshMeasures } | null = null;
  /** The user inspected: each level shown next is inspected too. */
  private active = false;
  private busy = false;
  private framed: [number, number] | null = null;
  /** The level object the framed pair belongs to. */
  private framedId = 0;
  private message = '';
  private graphics: InspectGraphics | null = null;
  /** What the drawn graphics show (level id, framed pair, layers). */
  private drawnKey = '';
  /** The inspection the drawn graphics show (a figure computed later makes another). */
  private drawnResult: Inspection | null = null;
  private readonly listeners = new Set<(state: InspectorState) => void>();

  constructor(
    private readonly viewer: SubdivViewer,
    private readonly onError: (error: unknown) => void,
  ) {
    viewer.onChange((state) => {
      const faces = viewer.controlMesh?.faceIndices ?? null;
      if (this.control && this.control.faces !== faces) {
        // Another model: nothing kept is about it.
        this.control = null;
        this.results.clear();
        this.framed = null;
      }
      // Levels dropped or computed again (a scheme change, a crease edit): their results go.
      const live = new Set(Array.from({ length: state.levelCount }, (_, k) => viewer.levelId(k)));
      for (const id of this.results.keys()) if (!live.has(id)) this.results.delete(id);
      if (this.framed && this.framedId !== viewer.levelId()) this.framed = null;
      // Scrubbing keeps the camera where the user has it.
      if (this.active && !state.busy && !this.busy && state.levelCount > 0 && !this.results.has(viewer.levelId()))
        void this.inspect(false);
      this.draw();
      this.emit();
    });
  }

  get state(): InspectorState {
    const viewer = this.viewer.state;
    return {
      available: viewer.levelCount > 0,
      level: viewer.level,
      choices: { ...this.choices },
      layers: { ...this.layers },
      result: this.results.get(this.viewer.levelId()) ?? null,
      control: this.control?.measures ?? null,
      busy: this.busy,
      framed: this.framed,
      message: this.message,
    };
  }

  onChange(listener: (state: InspectorState) => void): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }

  /**
   * Shows or hides a figure (`choice`, drawn as `layer`): one the shown
   * level was inspected without is computed now; the view frames what is
   * then drawn.
   */
  async show(choice: keyof InspectChoices, layer: keyof InspectLayers, on: boolean): Promise<void> {
    this.choices = { ...this.choices, [choice]: on };
    this.layers = { ...this.layers, [layer]: on };
    const result = this.results.get(this.viewer.levelId());
    if (on && result && result[choice] === undefined && !this.busy) return this.inspect();
    this.draw();
    if (result) this.frameShown();
    this.emit();
  }

  /**
   * Inspects the shown level for the chosen figures it lacks (the levels
   * shown next follow) and, with `frame`, frames what is drawn.
   */
  async inspect(frame = true): Promise<void> {
    const viewer = this.viewer;
    if (viewer.state.levelCount === 0) return;
    this.active = true;
    const level = viewer.state.level;
    const id = viewer.levelId();
    const faces = viewer.controlMesh?.faceIndices ?? null;
    let again = false;
    this.busy = true;
    this.message = '';
    this.emit();
    try {
      if (!this.control && faces) {
        const measures = (await viewer.inspect(0, {}))?.measures;
        if (measures && viewer.controlMesh?.faceIndices === faces) this.control = { faces, measures };
      }
      const kept = this.results.get(id);
      const wanted = { ...this.choices };
      for (const key of Object.keys(wanted) as (keyof InspectChoices)[]) wanted[key] &&= kept?.[key] === undefined;
      const result = await viewer.inspect(level, { ...wanted, maxPairs: LISTED_PAIRS });
      if (result && viewer.levelId(level) === id) {
        const merged = { ...kept, ...result };
        this.results.set(id, merged);
        // A box ticked meanwhile: its figure next.
        if (Object.entries(this.choices).some(([key, on]) => on && merged[key as keyof InspectChoices] === undefined))
          again = true;
      }
    } catch (error) {
      if (error instanceof CancelledError) {
        this.active = false;
        this.message = 'Inspection cancelled.';
      } else {
        this.message = '';
        this.onError(error);
      }
    } finally {
      this.busy = false;
      this.draw();
      if (frame && viewer.levelId() === id && this.results.has(id)) this.frameShown();
      this.emit();
    }
    if (again) await this.inspect(frame);
  }

  /**
   * Frames what is drawn (the crossing faces, the sphere, the hull, the
   * planes), looking from where the camera looks; the whole level when
   * nothing is.
   */
  private frameShown(): void {
    const points = this.graphics?.points;
    const view = this.viewer.view;
    if (points && points.length > 0) view.fitPoints([points], view.lookDirection());
    else this.viewer.fitView('current');
  }

  /** Frames crossing faces `a` and `b` of the shown level, drawn darker; null: none framed. */
  frame(pair: [number, number] | null): void {
    this.framed = pair;
    this.framedId = this.viewer.levelId();
    const buffers = this.viewer.buffersOf(this.viewer.state.level);
    if (pair && buffers) {
      const box: Vector3[] = [];
      for (let t = 0; t < buffers.triangleFace.length; ++t) {
        if (buffers.triangleFace[t] !== pair[0] && buffers.triangleFace[t] !== pair[1]) continue;
        for (let k = 0; k < 3; ++k)
          box.push(new Vector3().fromArray(buffers.positions, 3 * buffers.triangles[3 * t + k]));
      }
      if (box.length > 0) this.viewer.view.frameSphere(new Sphere().setFromPoints(box));
    }
    this.draw();
    this.emit();
  }

  /** Draws the shown level's results (none when it has none). */
  private draw(): void {
    const result = this.results.get(this.viewer.levelId()) ?? null;
    const buffers = this.viewer.buffersOf(this.viewer.state.level);
    const key = result ? `${this.viewer.levelId()}:${this.framed}:${JSON.stringify(this.layers)}` : '';
    if (key === this.drawnKey && result === this.drawnResult) return;
    this.drawnKey = key;
    this.drawnResult = result;
    this.graphics?.dispose();
    this.graphics = result && buffers ? new InspectGraphics(result, buffers, this.layers, this.framed) : null;
    this.viewer.view.setExtras(this.graphics?.group ?? null);
  }

  private emit(): void {
    const state = this.state;
    for (const listener of this.listeners) listener(state);
  }
}
