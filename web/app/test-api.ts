/**
 * The typed test API on `window.__subdivlab`: Playwright reads state here
 * (level, counts, last error, render mode, camera) instead of pixels.
 */
import type { MeshFacts } from '../core/mesh';
import type { RuleSet } from '../core/rule-set';
import type { WorkerMemory } from '../core/worker-client';
import type { CrashKind, WorkerRequestKind } from '../core/worker-protocol';
import type { OverlayName, RenderMode } from '../render/render-mode';
import type { ViewState } from '../render/view-state';
import type { EulerState } from '../teach/euler-steps';
import type { ExplorerState } from '../teach/halfedge-explorer';
import type { DrawnLevel } from '../viewer/subdiv-viewer';
import type { ModelSource } from './share-actions';

export interface TestError {
  source: string;
  message: string;
  /** SubdivError code, 'load_error' for LoadError, 'error' otherwise. */
  code: string;
}

export interface SubdivLabTestState {
  /** The core answered its scheme names. */
  ready: boolean;
  schemes: string[];
  modelName: string | null;
  scheme: string;
  triangulate: boolean;
  level: number;
  levelCount: number;
  facts: MeshFacts | null;
  renderMode: RenderMode;
  overlays: Record<OverlayName, boolean>;
  busy: boolean;
  lastError: TestError | null;
  view: ViewState;
  /** Vertical field of view in degrees and aspect ratio of the camera. */
  fov: number;
  aspect: number;
  /** Geometries alive on the GPU: levels that were dropped must not stay. */
  gpuGeometries: number;
  /** Segments of the polygon-edge lines of the shown level. */
  edgeSegments: number;
  /** The polygon edges were last drawn as WebGL's one-pixel lines (a dense level), not fat lines. */
  thinEdges: boolean;
  /** Rules the custom scheme steps with (the rules panel's last Apply, preset or file); null before any. */
  customRules: RuleSet | null;
  /** Rules the shown levels were computed with: customRules once its recomputation is done. */
  levelRules: RuleSet | null;
  /** quad-triangle's border option (false: "Fixed boundary" is checked). */
  smoothBoundary: boolean;
  /** Where the shown model came from: a URL as given (sample, ?src=, link) or a local file. */
  modelSource: ModelSource | null;
  /** The non-blocking notice shown (e.g. ignored link values), null when hidden. */
  notice: string | null;
  /** The line-width setting (CSS pixels) and the opacity the polygon edges are drawn with now (render/line-style.ts). */
  lineWidth: number;
  edgeOpacity: number;
  /** Names of the saved views, oldest first. */
  savedViews: string[];
  /** Where the camera's target is drawn, in NDC (x right, y up): Fit shifts it to clear the panels over the view. */
  viewOffset: [number, number];
  /** Size of the view's canvas in CSS pixels. */
  canvas: { width: number; height: number };
  /** The level the view last drew and performance.now() when that picture was in its canvas (null before a model). */
  drawn: DrawnLevel | null;
}

/** The side-by-side panes as a test reads them. */
export interface SideBySideTestState {
  count: number;
  together: boolean;
  panes: {
    scheme: string;
    level: number;
    levelCount: number;
    faces: number | null;
    busy: boolean;
    message: string;
    view: ViewState;
  }[];
  /** The last distance measured: the panes and levels, the figures. */
  distance: {
    panes: [number, number];
    schemes: [string, string];
    levels: [number, number];
    distance: number;
    relative: number;
    diagonal: number;
    errorBound: number;
    /** The largest vertex distance of each pane to the other surface. */
    farthest: [number, number];
  } | null;
  measuring: boolean;
}

export interface SubdivLabTestApi {
  state(): SubdivLabTestState;
  /** Lowers the budget over which a step asks first (to test the question with small meshes). */
  setMemoryBudget(bytes: number): void;
  /** Vertex positions of the shown level, x0 y0 z0 x1 ... (empty before a load). */
  positions(): Promise<number[]>;
  /** The shown level's points as drawn (float32; between split and smoothed while Split, then smooth is used). */
  drawnPositions(): number[];
  /** The link Share would copy; null when there is none (a local file, no model). */
  shareLink(): string | null;
  /**
   * Where vertex `v` of the control mesh (with `shown`, of the shown level) is drawn, in page (client)
   * pixels, so a test can click it or an edge; null: not in view.
   */
  vertexOnScreen(v: number, shown?: boolean): { x: number; y: number } | null;
  /** The side-by-side panes, their levels and the distance measured. */
  sideBySide(): SideBySideTestState;
  /** The halfedge explorer (picked halfedge, expressions, circulation) and its Euler operators (outcome, √3 walk). */
  halfedges(): {
    explorer: ExplorerState;
    euler: EulerState;
    /** The shown level's halfedge table while the explorer draws it. */
    table: { next: number[]; target: number[]; face: number[] } | null;
  };
  /** Where the middle of halfedge `h`'s arrow is drawn, in page (client) pixels; null: not drawn or behind the camera. */
  arrowOnScreen(h: number): { x: number; y: number } | null;
  /**
   * Every vertex of computed level `level` (0: the control mesh) projected through the camera, in CSS
   * pixels from the canvas's top left, not clipped (a point off the canvas has x or y outside it); in
   * side-by-side pane `pane` (0, the first, by default).
   */
  projected(level: number, pane?: number): { x: number; y: number }[];
  /**
   * Crashes the core's worker (worker-protocol.ts, crashForTest): now (resolves once a new one is asked
   * to start) or, with `during`, at the start of its next request of that kind (a step: 'subdivide').
   */
  crashCore(how: CrashKind, during?: WorkerRequestKind): Promise<void>;
  /** The core's memory and the levels its worker keeps. */
  coreMemory(): Promise<WorkerMemory>;
}

declare global {
  interface Window {
    __subdivlab?: SubdivLabTestApi;
  }
}
