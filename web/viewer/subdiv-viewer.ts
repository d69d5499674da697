/**
 * SubdivViewer: a self-contained, embeddable viewer. It owns one SceneView
 * (camera, controls, its picture) inside a container element and the history
 * of levels 0..N of one model under one scheme. The core runs in a Web
 * Worker shared by every viewer of the page (a WorkerClient; each viewer has
 * its own CoreSession, so cancelling one viewer stops only its requests).
 * The worker keeps each level's mesh; the viewer holds its handle, facts and
 * render buffers, and level 0's mesh, from which it recomputes a level the
 * worker lost when it restarted (a cancel, a crash). Methods reject
 * with SubdivError / CancelledError / Error; the viewer never touches the
 * DOM outside its container, so an app shell or an embed adds the panels.
 */

import type { MeshComparison } from '../core/compare';
import type { VertexCurvature } from '../core/curvature';
import type { HalfedgeTable } from '../core/halfedges';
import type { Inspection, InspectOptions } from '../core/inspect';
import type {
  BoundaryInterpolation,
  CreaseMethod,
  Mesh,
  MeshFacts,
  MeshFormat,
  MeshTags,
  ReadFormat,
  ReadOptions,
  RenderBuffers,
  SchemeName,
  SizePrediction,
  SubdivideOptions,
} from '../core/mesh';
import type { RuleHost } from '../core/rule-set';
import type { StencilTable } from '../core/stencils';
import type { HausdorffDistance } from '../core/subdiv-core';
import {
  CancelledError,
  type CoreSession,
  type LevelData,
  type LevelHandle,
  pageCore,
  StaleLevelError,
  type WorkerClient,
} from '../core/worker-client';
import { fanPolygons } from '../render/fan-polygons';
import { buildFigure, type Figure, tagOverlays } from '../render/figure';
import { figureEps } from '../render/figure-eps';
import { figurePdf } from '../render/figure-pdf';
import { CANONICAL_VIEWS, type CanonicalView } from '../render/fit';
import { LevelGraphics } from '../render/level-graphics';
import type { OverlayName, RenderMode } from '../render/render-mode';
import { SceneView } from '../render/scene-view';
import { figureSvg } from '../render/svg-export';
import type { ViewState } from '../render/view-state';
import { CurvatureShading } from './curvature-shading';
import { defaultMemoryBudget, stepBytes } from './memory-budget';
import { linearTwin, schemeInfo } from './scheme-info';

/**
 * Options of a step other than the scheme, the level and triangulation:
 * e.g. issue 4's `rules` (custom scheme) and `smoothBoundary`.
 */
export type SchemeOptions = Omit<SubdivideOptions, 'scheme' | 'levels' | 'startLevel' | 'triangulate'>;

/** What every step is computed with besides the level it starts from. */
export interface StepSettings {
  scheme: SchemeName;
  triangulate: boolean;
  options: SchemeOptions;
}

/** What a large-step confirmation is told. */
export interface LargeStepInfo {
  level: number;
  prediction: SizePrediction;
  estimatedBytes: number;
  budgetBytes: number;
}

export interface SubdivViewerOptions {
  /** The core. Default: the page's one worker ({@link pageCore}), shared with every other viewer. */
  client?: WorkerClient;
  scheme?: SchemeName;
  renderMode?: RenderMode;
  /** Asked before a step whose estimate exceeds the budget; resolve true to go on. Default: refuse. */
  confirmLargeStep?: (info: LargeStepInfo) => Promise<boolean>;
  /** Bytes a step may take before asking. Default: {@link defaultMemoryBudget}. */
  memoryBudgetBytes?: number;
}

/** What the viewer is doing right now. */
export interface BusyState {
  /** 'compute': a teaching tool's request (stencils, a basis function). */
  kind: 'load' | 'subdivide' | 'export' | 'compute';
  label: string;
  /** The level a step computes ('subdivide'). */
  level?: number;
  /** performance.now() when it started. */
  since: number;
}

/** The level whose picture the view last put in its canvas, and performance.now() when it did. */
export interface DrawnLevel {
  level: number;
  at: number;
}

/** A level's tags as the facts panel lists them. */
export interface TagSummary {
  creases: number;
  corners: number;
  holes: number;
  boundary: BoundaryInterpolation;
  creaseMethod: CreaseMethod;
  /** The file's tags the core read but does not apply (level 0 only). */
  notes: string[];
}

function tagSummary(tags: MeshTags | null): TagSummary | null {
  if (!tags) return null;
  return {
    creases: tags.creaseSharpness.length,
    corners: tags.cornerSharpness.length,
    holes: tags.holes.length,
    boundary: tags.boundary,
    creaseMethod: tags.creaseMethod,
    notes: tags.notes,
  };
}

/** A snapshot of the viewer, for panels and tests. */
export interface ViewerState {
  modelName: string | null;
  scheme: SchemeName;
  triangulate: boolean;
  level: number;
  /** Number of computed levels (levels 0..levelCount−1 exist). */
  levelCount: number;
  facts: MeshFacts | null;
  /** The facts of every computed level, 0..levelCount−1. */
  levelFacts: readonly MeshFacts[];
  /** The shown level's OpenSubdiv tags, counted (null: it has none). */
  tags: TagSummary | null;
  /** Milliseconds of the step that produced the shown level (null at level 0). */
  stepMs: number | null;
  renderMode: RenderMode;
  overlays: Record<OverlayName, boolean>;
  /** The line-width setting, CSS pixels (render/line-style.ts). */
  lineWidth: number;
  busy: BusyState | null;
}

interface Level {
  /** Unique to this level object: a recomputed level (a tag edit, a new model) has another. */
  id: number;
  data: LevelData;
  graphics: LevelGraphics | null;
  /** Its stencils, once asked for (stencils()). */
  stencils?: Promise<StencilTable>;
  /** Its vertices' curvature, once asked for (curvature()). */
  curvature?: Promise<VertexCurvature>;
  /** The tools' colours of its vertices (setLevelColors). */
  colours?: { owner: ColourOwner; rgb: Float32Array }[];
}

/** Who colours a level's vertices: the basis view, a result's check, side by side's distances, a curvature render mode. */
export type ColourOwner = 'basis' | 'check' | 'distance' | 'curvature';

/**
 * Which colours show when several colour a level: a curvature render mode
 * (chosen for the whole view; leaving it gives the tools' colours back),
 * then what the user picked last in the panels, then the panes' distances.
 */
const COLOUR_PRIORITY: Record<ColourOwner, number> = { curvature: 3, basis: 2, check: 2, distance: 1 };

export class SubdivViewer {
  readonly view: SceneView;
  /** The id of the last level made (newLevel). */
  private lastLevelId = 0;
  /** A level drawn between its split and its own points (setSplitBlend), with its own points. */
  private blend: { level: Level; own: Float32Array; normals: Float32Array } | null = null;
  /** This viewer's requests to the page's core. */
  readonly core: CoreSession;
  private levels: Level[] = [];
  /** Level 0's mesh (the worker keeps one too). */
  private source: Mesh | null = null;
  private current = 0;
  private name: string | null = null;
  private scheme: SchemeName;
  private triangulate = false;
  private schemeOptions: SchemeOptions = {};
  private busyState: BusyState | null = null;
  private readonly listeners = new Set<(state: ViewerState) => void>();
  private readonly viewListeners = new Set<(view: ViewState) => void>();
  private memoryBudget: number;
  private readonly confirmLargeStep: (info: LargeStepInfo) => Promise<boolean>;
  /** Bumped by load/reset/scheme changes so a step that finishes late is dropped. */
  private generation = 0;
  /** A step is between its prediction and its result (possibly waiting for a confirmation). */
  private stepping = false;
  private disposed = false;
  private drawn: DrawnLevel | null = null;
  /**
   * The size of the next step from the last level, asked for once that
   * level is drawn (a prediction copies the level's mesh into the core:
   * tens of milliseconds on a million faces, otherwise spent after the
   * click); `key` names the generation and the level it was asked from.
   */
  private ahead: { key: string; prediction: Promise<SizePrediction> } | null = null;
  /** The curvature render modes' colours and colour bar. */
  private readonly curvatureShading: CurvatureShading;

  constructor(container: HTMLElement, options: SubdivViewerOptions = {}) {
    this.core = (options.client ?? pageCore()).session();
    this.scheme = options.scheme ?? 'catmull-clark';
    this.memoryBudget = options.memoryBudgetBytes ?? defaultMemoryBudget();
    this.confirmLargeStep = options.confirmLargeStep ?? (async () => false);
    this.view = new SceneView(container);
    if (options.renderMode) this.view.setRenderMode(options.renderMode);
    const viewer = this;
    this.curvatureShading = new CurvatureShading(container, {
      get renderMode() {
        return viewer.view.renderMode;
      },
      get shownLevel() {
        return viewer.levels[viewer.current] ? { k: viewer.current, id: viewer.levelId() } : null;
      },
      get levelCount() {
        return viewer.levels.length;
      },
      curvature: (k) => this.curvature(k),
      setCurvatureColours: (k, rgb) => this.setLevelColors(k, rgb, 'curvature'),
    });
    this.view.onDraw = () => {
      if (this.levels.length === 0) return;
      this.drawn = { level: this.current, at: performance.now() };
      // Asked once the frame is on screen (two animation frames later: the
      // browser holds them back while the GPU draws), so that the core's
      // work does not compete with the drawing of a large level.
      requestAnimationFrame(() => requestAnimationFrame(() => this.predictAheadIfIdle()));
    };
    this.view.onViewChange = () => {
      if (this.viewListeners.size === 0) return;
      const view = this.view.getView();
      for (const listener of this.viewListeners) listener(view);
    };
  }

  /** Scheme names the core offers (resolves once the WASM core is loaded). */
  schemes(): Promise<string[]> {
    return this.core.ready();
  }

  get state(): ViewerState {
    const level = this.levels[this.current];
    return {
      modelName: this.name,
      scheme: this.scheme,
      triangulate: this.triangulate,
      level: this.current,
      levelCount: this.levels.length,
      facts: level?.data.facts ?? null,
      levelFacts: this.levels.map((l) => l.data.facts),
      tags: tagSummary(level?.data.tags ?? null),
      stepMs: level && this.current > 0 ? level.data.ms : null,
      renderMode: this.view.renderMode,
      overlays: {
        control: this.view.overlay('control'),
        bbox: this.view.overlay('bbox'),
        curves: this.view.overlay('curves'),
        creases: this.view.overlay('creases'),
      },
      lineWidth: this.view.lineWidthSetting,
      busy: this.busyState,
    };
  }

  /**
   * The last picture drawn (null before a model): its level and when it was
   * in the canvas, the GPU's work read back included. A level is on screen
   * from then on; the benchmark times a step to it.
   */
  get lastDraw(): DrawnLevel | null {
    return this.drawn;
  }

  /**
   * Calls `listener` after the camera moved (pointer, keys, fit, setView);
   * returns the unsubscribe function. Not part of {@link onChange}: it fires
   * on every frame of a drag.
   */
  onViewChange(listener: (view: ViewState) => void): () => void {
    this.viewListeners.add(listener);
    return () => this.viewListeners.delete(listener);
  }

  /** Calls `listener` after every change; returns the unsubscribe function. */
  onChange(listener: (state: ViewerState) => void): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }

  /** Shows `mesh` as level 0 of model `name`; earlier levels are dropped only once it succeeded. */
  async load(mesh: Mesh, name: string): Promise<void> {
    await this.replaceWith(name, async () => ({ data: await this.core.prepare(mesh), mesh }));
  }

  /** Parses an OFF/OBJ/PLY/STL file (text or bytes) in the worker and shows it. On failure the previous model stays. */
  async loadText(
    text: string | Uint8Array,
    format: ReadFormat,
    name: string,
    options: ReadOptions = {},
  ): Promise<void> {
    await this.replaceWith(name, async () => {
      const { level, mesh } = await this.core.parse(text, format, options);
      return { data: level, mesh };
    });
  }

  /**
   * Computes level N+1 from the last level N and shows it. Before the step
   * the core predicts its size; over the budget, `confirmLargeStep` decides.
   * Resolves false when declined or when nothing is loaded.
   */
  async subdivide(): Promise<boolean> {
    if (this.disposed || this.levels.length === 0 || this.busyState || this.stepping) return false;
    this.stepping = true;
    const generation = this.generation;
    const from = this.levels.length - 1;
    const options = this.stepOptions(from, 1);
    this.setBusy({
      kind: 'subdivide',
      label: `Subdividing to level ${from + 1}…`,
      level: from + 1,
      since: performance.now(),
    });
    try {
      const prediction = await this.predictionFrom(from, options);
      const estimatedBytes = stepBytes(prediction);
      if (estimatedBytes > this.memoryBudget) {
        this.setBusy(null);
        const info = { level: from + 1, prediction, estimatedBytes, budgetBytes: this.memoryBudget };
        if (!(await this.confirmLargeStep(info))) return false;
        if (generation !== this.generation) return false;
        this.setBusy({
          kind: 'subdivide',
          label: `Subdividing to level ${from + 1}…`,
          level: from + 1,
          since: performance.now(),
        });
      }
      const data = await this.withHandle(from, (h) => this.core.subdivide(h, options));
      if (generation !== this.generation) {
        this.core.release([data.handle]);
        return false;
      }
      this.levels.push(this.newLevel(data));
      this.current = this.levels.length - 1;
      this.show();
      return true;
    } finally {
      this.stepping = false;
      if (generation === this.generation) this.setBusy(null);
    }
  }

  /**
   * Gives the control mesh `tags` (undefined: none) and computes its levels
   * again up to the one shown, one step at a time, so every level can still
   * be scrubbed. The previous levels stay shown until the new ones are all
   * there, and stay if it fails or a load or reset comes first.
   */
  async setControlTags(tags: MeshTags | undefined): Promise<void> {
    const source = this.source;
    if (this.disposed || !source) return;
    this.cancel();
    const generation = ++this.generation;
    const target = this.current;
    const { tags: _old, ...untagged } = source;
    const mesh: Mesh = tags ? { ...untagged, tags } : untagged;
    const made = await this.computeLevels('Applying the tags', generation, target, this.steps(), () =>
      this.core.prepare(mesh),
    );
    this.source = mesh;
    this.replaceLevels(made, 0, target);
  }

  /**
   * Changes what every step is computed with (scheme, triangulation,
   * options) and computes the levels again up to the one shown, one step at
   * a time, as a tag edit does: the previous levels stay shown until the new
   * ones are all there. If the change cannot reach that level (a step fails,
   * is declined or cancelled, or a load comes first) it rejects, and the
   * previous scheme, options and levels stay. From level 0 it only drops the
   * levels above.
   */
  async changeSteps(change: Partial<StepSettings>): Promise<void> {
    if (this.disposed) return;
    const settings = { ...this.steps(), ...change };
    if (JSON.stringify(settings) === JSON.stringify(this.steps())) return;
    const target = this.current;
    if (target === 0 || !this.source) {
      this.cancel();
      this.setSteps(settings);
      this.truncate();
      return;
    }
    this.cancel();
    const generation = ++this.generation;
    const over = await this.withHandle(0, (h) => this.core.predictSize(h, this.stepOptions(0, target, settings)));
    const estimatedBytes = stepBytes(over);
    if (estimatedBytes > this.memoryBudget) {
      const info = { level: target, prediction: over, estimatedBytes, budgetBytes: this.memoryBudget };
      if (!(await this.confirmLargeStep(info)) || generation !== this.generation) throw new CancelledError();
    }
    const made = await this.computeLevels(schemeInfo(settings.scheme).label, generation, target, settings);
    this.setSteps(settings);
    this.replaceLevels(made, 1, target);
  }

  /** The settings every step of the shown levels was computed with. */
  steps(): StepSettings {
    return { scheme: this.scheme, triangulate: this.triangulate, options: this.schemeOptions };
  }

  private setSteps(settings: StepSettings): void {
    this.scheme = settings.scheme;
    this.triangulate = settings.triangulate;
    this.schemeOptions = { ...settings.options };
  }

  /**
   * Levels 0..target computed with `settings`, one step at a time, from a
   * new level 0 (`prepare`) or the shown one; busy meanwhile, the label
   * (`what`) followed by the level in progress. Rejects, with
   * what it made released, if a step fails or `generation` moves on.
   */
  private async computeLevels(
    what: string,
    generation: number,
    target: number,
    settings: StepSettings,
    prepare?: () => Promise<LevelData>,
  ): Promise<LevelData[]> {
    const since = performance.now();
    this.setBusy({ kind: 'subdivide', label: what, since });
    const made: LevelData[] = [];
    try {
      made.push(prepare ? await prepare() : this.levels[0].data);
      for (let k = 1; k <= target && generation === this.generation; ++k) {
        const options = this.stepOptions(k - 1, 1, settings);
        this.setBusy({ kind: 'subdivide', label: `${what}: level ${k} of ${target}…`, since });
        made.push(
          await (k === 1 && !prepare
            ? this.withHandle(0, (h) => this.core.subdivide(h, options))
            : this.core.subdivide(made[k - 1].handle, options)),
        );
      }
      if (generation !== this.generation) throw new CancelledError();
      return made;
    } catch (error) {
      this.core.release((prepare ? made : made.slice(1)).map((level) => level.handle));
      throw error;
    } finally {
      if (generation === this.generation) this.setBusy(null);
    }
  }

  /** Puts `made` in place of levels `from`.. and shows level `current`. */
  private replaceLevels(made: LevelData[], from: number, current: number): void {
    for (const level of this.levels.slice(from)) level.graphics?.dispose();
    this.core.release(this.levels.slice(from).map((l) => l.data.handle));
    this.levels = [...this.levels.slice(0, from), ...made.slice(from).map((data) => this.newLevel(data))];
    this.current = current;
    this.show();
  }

  /** Shows computed level `k` (clamped to 0..N) at once. */
  setLevel(k: number): void {
    if (this.levels.length === 0) return;
    const level = Math.max(0, Math.min(this.levels.length - 1, Math.round(k)));
    if (level === this.current) return;
    this.current = level;
    this.show();
  }

  /** Drops every level above 0 and shows the control mesh. */
  reset(): void {
    this.cancel();
    this.truncate();
  }

  /** Changes the scheme; levels computed with the previous one are dropped. */
  setScheme(scheme: SchemeName): void {
    if (scheme === this.scheme) return;
    this.cancel();
    this.scheme = scheme;
    this.truncate();
  }

  /** Triangulate before the first step of a scheme that needs triangles; drops computed levels. */
  setTriangulate(triangulate: boolean): void {
    if (triangulate === this.triangulate) return;
    this.cancel();
    this.triangulate = triangulate;
    this.truncate();
  }

  /**
   * Further options for every step (a rules panel sets `rules` here). Levels
   * computed with other options are dropped, as for a scheme change.
   */
  setSchemeOptions(options: SchemeOptions): void {
    this.cancel();
    this.schemeOptions = { ...options };
    this.truncate();
  }

  setRenderMode(mode: RenderMode): void {
    this.view.setRenderMode(mode);
    void this.curvatureShading.update();
    this.emit();
  }

  /**
   * The discrete curvature at level `k`'s vertices (default: the shown
   * one), asked of the core once a level; null before a load.
   */
  async curvature(k = this.current): Promise<VertexCurvature | null> {
    const level = this.levels[k];
    if (!level) return null;
    level.curvature ??= this.withHandle(k, (h) => this.core.curvature(h));
    try {
      return await level.curvature;
    } catch (error) {
      level.curvature = undefined;
      throw error;
    }
  }

  /** Resolves once the colours of a curvature render mode show on the shown level (at once in other modes). */
  curvatureShown(): Promise<void> {
    return this.curvatureShading.update();
  }

  setOverlay(name: OverlayName, visible: boolean): void {
    this.view.setOverlay(name, visible);
    this.emit();
  }

  /** Stops a running load or step (the worker restarts); the levels computed so far stay. */
  cancel(): void {
    if (!this.busyState) return;
    this.generation++;
    this.core.cancel();
    this.setBusy(null);
  }

  /**
   * Frames what is shown (the level, the cage when drawn, a tool's
   * objects) and the levels `also` show (panes side by side with a linked
   * camera): from a canonical view, from where the camera looks now
   * ('current'), or from the default direction.
   */
  fitView(view?: CanonicalView | 'current', also: readonly SubdivViewer[] = []): void {
    const level = this.levels[this.current];
    if (!level?.graphics) return;
    const others = also.flatMap((v) => {
      const graphics = v.levels[v.current]?.graphics;
      return graphics ? [graphics.points] : [];
    });
    this.view.fit(
      view === 'current' ? this.view.lookDirection() : CANONICAL_VIEWS.find((v) => v.name === view),
      others,
    );
  }

  /** Sets the width of the drawn lines (CSS pixels; render/line-style.ts). */
  setLineWidth(width: number): void {
    this.view.setLineWidth(width);
    this.emit();
  }

  getView(): ViewState {
    return this.view.getView();
  }

  setView(view: ViewState): void {
    this.view.setView(view);
  }

  /** PNG of the view at `scale` × its size. */
  exportPng(scale: number, transparent: boolean): Promise<Blob> {
    return this.view.exportPng(scale, transparent);
  }

  /** SVG of the view: camera-facing polygons back to front, and the overlays shown. */
  exportSvg(transparent = false): string {
    return figureSvg(this.figure(transparent));
  }

  /** The same figure as {@link exportSvg}, as a one-page PDF titled `title`. */
  exportPdf(transparent = false, title?: string): Uint8Array {
    return figurePdf(this.figure(transparent), title);
  }

  /** The same figure as {@link exportSvg}, as EPS (opaque: fading lines mixed with what lies under them). */
  exportEps(transparent = false, title?: string): string {
    return figureEps(this.figure(transparent), title);
  }

  /** The view as a vector figure (render/figure.ts), in any format. */
  private figure(transparent: boolean): Figure {
    const { buffers, controlEdges, tags } = this.requireLevel().data;
    const base = this.levels[0].data.buffers;
    // The polygons as the core fanned them: the shown level's, in float32.
    const mesh = { positions: buffers.positions, ...fanPolygons(buffers) };
    const control = this.view.overlay('control')
      ? { positions: base.positions, edges: base.edges, faces: fanPolygons(base) }
      : null;
    const curves =
      this.view.overlay('curves') && controlEdges.length > 0
        ? { positions: buffers.positions, edges: controlEdges, faces: mesh }
        : null;
    // The sharp edges and vertices, one set per colour.
    const tagged = this.view.overlay('creases') && tags ? tagOverlays(tags, buffers.positions, mesh) : {};
    return buildFigure({
      mesh,
      camera: this.view.pictureCamera(),
      ...this.view.size,
      control,
      curves,
      ...tagged,
      background: !transparent,
      lineWidth: this.view.lineWidthSetting,
      edgeOpacity: this.view.edgeOpacity(),
      controlOpacity: this.view.cageOpacity(),
    });
  }

  /**
   * The shown level as a file (OFF/OBJ/PLY text, binary STL) with `comment`
   * in it, as a Blob: assembled from the core's pieces, so a file beyond a
   * JS string's 512 M characters exports too.
   */
  async exportMesh(format: MeshFormat, comment = ''): Promise<Blob> {
    this.requireLevel();
    const chunks = await this.withHandle(this.current, (h) => this.core.exportMesh(h, format, comment));
    return new Blob(chunks as BlobPart[], { type: format === 'stl' ? 'model/stl' : 'text/plain' });
  }

  /** A copy of the mesh of level `k` (default: the shown one), from the worker; null before a load. */
  async meshOf(k = this.current): Promise<Mesh | null> {
    if (!this.levels[k]) return null;
    if (k === 0) return this.source;
    return this.withHandle(k, (h) => this.core.mesh(h));
  }

  /**
   * The stencils of level `k` (default: the shown one; 1 or more): its
   * vertices as weighted sums of level k − 1's, from the worker, kept with
   * the level. Null at level 0 or before a load.
   */
  async stencils(k = this.current): Promise<StencilTable | null> {
    const level = this.levels[k];
    if (k < 1 || !level) return null;
    level.stencils ??= this.computing(`Working out the stencils of level ${k}…`, () =>
      this.withHandle(k - 1, (h) => this.core.stencils(h, this.stepOptions(k - 1, 1))),
    );
    try {
      return await level.stencils;
    } catch (error) {
      level.stencils = undefined;
      throw error;
    }
  }

  /**
   * Control vertex `vertex`'s basis function at level `k` (default: the
   * shown one): its weight in each of the level's vertices, through every
   * step (basis.ts). Null before a load.
   */
  async basis(vertex: number, k = this.current): Promise<Float64Array | null> {
    if (!this.levels[k]) return null;
    const { levels: _levels, startLevel: _start, ...options } = this.stepOptions(0, 1);
    return this.computing(`Working out the basis function of vertex ${vertex}…`, () =>
      this.withHandle(0, (h) => this.core.basis(h, vertex, k, { ...options, renderBuffers: false })),
    );
  }

  /**
   * Colours level `k`'s surface per vertex (`rgb`: three numbers in 0..1 a
   * vertex) for `owner`, or takes `owner`'s colours away (null). Several
   * tools may colour a level: the one of highest {@link COLOUR_PRIORITY}
   * shows, the latest among equals, and the others' come back when it
   * stops. The view shows a level's colours whenever that level is shown.
   */
  setLevelColors(k: number, rgb: Float32Array | null, owner: ColourOwner): void {
    const level = this.levels[k];
    if (!level) return;
    const layers = (level.colours ?? []).filter((c) => c.owner !== owner);
    if (rgb) layers.push({ owner, rgb });
    level.colours = layers;
    const shown = this.shownColours(level);
    this.graphicsOf(level).setColors(shown);
    if (k === this.current) this.view.setVertexColors(shown !== null);
  }

  /** The colours of `level` that show (setLevelColors), or null. */
  private shownColours(level: Level): Float32Array | null {
    let top: { owner: ColourOwner; rgb: Float32Array } | null = null;
    for (const layer of level.colours ?? [])
      if (!top || COLOUR_PRIORITY[layer.owner] >= COLOUR_PRIORITY[top.owner]) top = layer;
    return top?.rgb ?? null;
  }

  /**
   * The points of the shown level k ≥ 1 as the split alone puts them: the
   * linear scheme on the same host, one step from level k − 1 (the same
   * numbering). Null at level 0 and for schemes without a linear twin
   * (linearTwin).
   */
  async splitPoints(): Promise<Float32Array | null> {
    const k = this.current;
    const twin = linearTwin(this.scheme, this.schemeRulesHost());
    if (k < 1 || !twin || !this.levels[k]) return null;
    const { rules: _rules, ...options } = this.stepOptions(k - 1, 1);
    return this.withHandle(k - 1, (h) => this.core.points(h, { ...options, scheme: twin, renderBuffers: false }));
  }

  /**
   * Draws the shown level's points at `t` of the way from `split` (its
   * split alone, splitPoints) to its own (t = 1); the edges and the
   * surface follow. Another level, or t = 1, draws the level's own points
   * again.
   */
  setSplitBlend(split: Float32Array, t: number): void {
    const level = this.levels[this.current];
    if (!level) return;
    const graphics = this.graphicsOf(level);
    const drawn = graphics.points;
    if (split.length !== drawn.length) return;
    if (this.blend?.level !== level) {
      this.endSplitBlend();
      this.blend = { level, own: Float32Array.from(drawn), normals: Float32Array.from(graphics.normals) };
    }
    const own = this.blend.own;
    for (let i = 0; i < drawn.length; ++i) drawn[i] = split[i] + t * (own[i] - split[i]);
    // Shaded as the blended surface is (the normals of the drawn triangles), not as the smoothed one.
    graphics.pointsMoved(null);
    this.view.requestRender();
    if (t === 1) this.endSplitBlend();
  }

  /** Puts the blended level's own points back. */
  private endSplitBlend(): void {
    if (!this.blend) return;
    const { level, own, normals } = this.blend;
    this.blend = null;
    if (!level.graphics) return;
    level.graphics.points.set(own);
    level.graphics.pointsMoved(normals);
    this.view.requestRender();
  }

  /**
   * Checks a result from elsewhere (OFF/OBJ text) against computed level
   * `k` (compare.ts): `tolerance` is a share of the level's diagonal.
   */
  async checkResult(
    k: number,
    text: string | Uint8Array,
    format: ReadFormat,
    tolerance: number,
  ): Promise<MeshComparison | null> {
    if (!this.levels[k]) return null;
    return this.computing(`Checking the result against level ${k}…`, () =>
      this.withHandle(k, (h) => this.core.compare(h, text, format, tolerance)),
    );
  }

  /**
   * The symmetric Hausdorff distance between this viewer's shown level and
   * `other`'s (both kept by the page's one worker), with each vertex's
   * distance to the other surface. Null when either has no model.
   */
  async distanceTo(other: SubdivViewer): Promise<HausdorffDistance | null> {
    if (!this.levels[this.current] || !other.levels[other.current]) return null;
    const k = other.current;
    // Not a busy state: a step asked for meanwhile waits for it in the worker, not refused.
    return this.withHandle(this.current, (a) => other.withHandle(k, (b) => this.core.hausdorff(a, b)));
  }

  /**
   * CGAL's geometry around level `k` (inspect.ts), in the worker, as the
   * viewer's busy state (Cancel and Esc stop it). Null before a load.
   */
  async inspect(k: number, options: InspectOptions): Promise<Inspection | null> {
    if (!this.levels[k]) return null;
    return this.computing(`Inspecting level ${k}…`, () => this.withHandle(k, (h) => this.core.inspect(h, options)));
  }

  /** The halfedge table of level `k` (CGAL's Surface_mesh numbering), from the worker; null before a load. */
  async halfedges(k = this.current): Promise<HalfedgeTable | null> {
    if (!this.levels[k]) return null;
    return this.withHandle(k, (h) => this.core.halfedges(h));
  }

  /** The render buffers of level `k` (null: not computed), as the view draws them. */
  buffersOf(k: number): RenderBuffers | null {
    return this.levels[k]?.data.buffers ?? null;
  }

  /** The host of the custom scheme's rule set (undefined without one). */
  schemeRulesHost(): RuleHost | undefined {
    return this.schemeOptions.rules?.host;
  }

  /** The control mesh (level 0). */
  get controlMesh(): Mesh | null {
    return this.source;
  }

  /**
   * Frees the GPU copies of every level's geometry (a viewer far out of
   * view); the levels stay, and what is drawn next is uploaded again.
   */
  releaseGpu(): void {
    for (const level of this.levels) level.graphics?.dispose();
  }

  /** Budget over which a step asks first (tests lower it to see the question). */
  setMemoryBudget(bytes: number): void {
    this.memoryBudget = bytes;
  }

  /** Frees the GPU objects and the view, and cancels this viewer's requests (the page's worker stays). */
  dispose(): void {
    this.disposed = true;
    this.generation++;
    for (const level of this.levels) level.graphics?.dispose();
    this.core.cancel();
    this.core.release(this.levels.map((l) => l.data.handle));
    this.levels = [];
    this.source = null;
    this.curvatureShading.dispose();
    this.view.dispose();
    this.listeners.clear();
    this.viewListeners.clear();
  }

  private async replaceWith(name: string, produce: () => Promise<{ data: LevelData; mesh: Mesh }>): Promise<void> {
    if (this.disposed) throw new CancelledError();
    this.cancel();
    const generation = ++this.generation;
    this.setBusy({ kind: 'load', label: `Loading ${name}…`, since: performance.now() });
    try {
      const { data, mesh } = await produce();
      if (generation !== this.generation) {
        this.core.release([data.handle]);
        return;
      }
      for (const level of this.levels) level.graphics?.dispose();
      this.core.release(this.levels.map((l) => l.data.handle));
      this.source = mesh;
      this.levels = [this.newLevel(data)];
      this.current = 0;
      this.name = name;
      this.show();
      this.fitView();
    } finally {
      if (generation === this.generation) this.setBusy(null);
    }
  }

  private truncate(): void {
    this.generation++;
    for (const level of this.levels.slice(1)) level.graphics?.dispose();
    this.core.release(this.levels.slice(1).map((l) => l.data.handle));
    this.levels = this.levels.slice(0, 1);
    this.current = 0;
    if (this.levels.length > 0) this.show();
    else this.emit();
  }

  /** {@link predictAhead} when the last level is shown and no step is under way. */
  private predictAheadIfIdle(): void {
    if (this.disposed || this.levels.length === 0) return;
    if (this.current === this.levels.length - 1 && !this.busyState && !this.stepping) this.predictAhead();
  }

  /** Asks the core for the size of the next step from the last level, unless already asked. */
  private predictAhead(): void {
    const from = this.levels.length - 1;
    const key = `${this.generation}/${from}`;
    if (this.ahead?.key === key) return;
    const { handle } = this.levels[from].data;
    // A level the worker lost (it restarted) is restored only when used, not ahead.
    if (handle.epoch !== this.core.client.epoch) return;
    const prediction = this.core.predictSize(handle, this.stepOptions(from, 1));
    // Unused or failed, it is asked again by the step.
    prediction.catch(() => {});
    this.ahead = { key, prediction };
  }

  /** The size of the step from level `from` with `options`: the one asked ahead, or asked now. */
  private async predictionFrom(from: number, options: SubdivideOptions): Promise<SizePrediction> {
    const ahead = this.ahead?.key === `${this.generation}/${from}` ? this.ahead.prediction : null;
    this.ahead = null;
    if (ahead) {
      try {
        return await ahead;
      } catch {
        // Cancelled or lost with a restarted worker: ask again.
      }
    }
    return this.withHandle(from, (h) => this.core.predictSize(h, options));
  }

  /** Options of `levels` steps from level `from` under the current scheme and options. */
  private stepOptions(from: number, levels: number, settings = this.steps()): SubdivideOptions {
    return {
      ...settings.options,
      scheme: settings.scheme,
      levels,
      startLevel: from,
      triangulate: settings.triangulate,
      renderBuffers: true,
    };
  }

  /**
   * Runs `request` on level `k`'s handle in the worker. A worker that
   * restarted since (a cancel, a crash) no longer keeps the level: it is
   * kept again (level 0, from its mesh) or made again from the level before
   * it, one step at a time as it was made (one call of k levels gives the
   * same mesh numbered otherwise, and the page's buffers, picks and
   * stencils go by the numbers), and `request` runs once more.
   */
  private async withHandle<T>(k: number, request: (handle: LevelHandle) => Promise<T>): Promise<T> {
    for (let attempt = 0; ; attempt++) {
      try {
        return await request(await this.handleOf(k));
      } catch (error) {
        if (!(error instanceof StaleLevelError) || attempt > 0) throw error;
      }
    }
  }

  private async handleOf(k: number): Promise<LevelHandle> {
    const level = this.levels[k];
    if (!level) throw new CancelledError();
    if (level.data.handle.epoch === this.core.client.epoch) return level.data.handle;
    let handle: LevelHandle;
    if (k === 0) {
      if (!this.source) throw new CancelledError();
      handle = await this.core.keep(this.source, level.data.facts);
    } else {
      const before = await this.handleOf(k - 1);
      handle = (await this.core.subdivide(before, this.stepOptions(k - 1, 1))).handle;
    }
    // A load or reset while waiting dropped the level: the worker need not keep it.
    if (this.levels[k] !== level) {
      this.core.release([handle]);
      throw new CancelledError();
    }
    level.data.handle = handle;
    return handle;
  }

  /**
   * Runs a teaching tool's request as the viewer's busy state (the progress
   * box shows after a moment; Cancel and Esc stop it), unless a load or step
   * is already under way.
   */
  private async computing<T>(label: string, request: () => Promise<T>): Promise<T> {
    if (this.busyState) return request();
    const generation = this.generation;
    this.setBusy({ kind: 'compute', label, since: performance.now() });
    try {
      return await request();
    } finally {
      if (generation === this.generation && (this.busyState as BusyState | null)?.kind === 'compute')
        this.setBusy(null);
    }
  }

  private newLevel(data: LevelData): Level {
    return { id: ++this.lastLevelId, data, graphics: null };
  }

  /**
   * The identity of level `k` (default: the shown one): another number
   * once that level is recomputed or dropped (a tag edit, a new model or
   * scheme), so that what was worked out for it can be told apart; 0 when
   * there is none.
   */
  levelId(k = this.current): number {
    return this.levels[k]?.id ?? 0;
  }

  private requireLevel(): Level {
    const level = this.levels[this.current];
    if (!level) throw new Error('No mesh is loaded.');
    return level;
  }

  private graphicsOf(level: Level): LevelGraphics {
    if (!level.graphics) {
      level.graphics = new LevelGraphics(
        level.data.buffers,
        level.data.controlEdges,
        level.data.orientation,
        level.data.tags,
      );
      // Made again after releaseGpu: the tools' colours come back with it.
      const shown = this.shownColours(level);
      if (shown) level.graphics.setColors(shown);
    }
    return level.graphics;
  }

  private show(): void {
    this.endSplitBlend();
    const level = this.levels[this.current];
    const graphics = this.graphicsOf(level);
    this.view.setLevel(graphics, this.current === 0);
    this.view.setVertexColors(graphics.surface.hasAttribute('color'));
    this.view.setControlMesh(this.graphicsOf(this.levels[0]));
    this.view.setBoundingBox(level.data.facts.bboxMin, level.data.facts.bboxMax);
    void this.curvatureShading.update();
    this.emit();
  }

  private setBusy(busy: BusyState | null): void {
    this.busyState = busy;
    this.emit();
  }

  private emit(): void {
    const state = this.state;
    for (const listener of this.listeners) listener(state);
  }
}
