/**
 * Side by side: two to four panes on one control mesh, each with its own
 * scheme, so that a student compares Loop with √3 or Catmull-Clark with
 * quad-triangle on the same input. The first pane is the page's own
 * viewer; the others follow its model. Cameras are linked; levels are
 * stepped together (every pane shows the first pane's level) or apart
 * (each its own). The symmetric Hausdorff distance between two panes'
 * shown surfaces (CGAL's bounded-error algorithm, in the worker) is given
 * relative to the bounding-box diagonal, and both surfaces are coloured by
 * each vertex's distance to the other one.
 */
import type { Mesh, SchemeName } from '../core/mesh';
import type { HausdorffDistance } from '../core/subdiv-core';
import { CancelledError } from '../core/worker-client';
import type { CanonicalView } from '../render/fit';
import { influenceColors } from '../render/level-graphics';
import type { ViewState } from '../render/view-state';
import { messageOf } from '../viewer/error-message';
import { PANE_SCHEMES, schemeInfo } from '../viewer/scheme-info';
import type { SubdivViewer, ViewerState } from '../viewer/subdiv-viewer';
import { MAX_PANES } from '../viewer/viewer-params';

/** What a new pane shows beside a scheme: its classic comparison first, then the others in order. */
const COMPANIONS: Partial<Record<SchemeName, SchemeName[]>> = {
  'catmull-clark': ['loop', 'quad-triangle', 'doo-sabin'],
  loop: ['sqrt3', 'catmull-clark', 'quad-triangle'],
  sqrt3: ['loop', 'catmull-clark'],
  'doo-sabin': ['catmull-clark', 'loop'],
  'quad-triangle': ['catmull-clark', 'loop'],
};

/** A distance as the tools write it: four significant digits. */
export function distanceText(d: number): string {
  return d === 0 ? '0' : d.toPrecision(4);
}

/**
 * A measured Hausdorff distance as the tools write it: CGAL's estimate is
 * within its error bound of the true distance, so an estimate no larger
 * than the bound says the surfaces agree to within it (quad-triangle and
 * Catmull-Clark on quads), not that they differ by it.
 */
export function hausdorffText(d: { distance: number; errorBound: number }): string {
  return d.distance <= d.errorBound ? `0 (to within ${distanceText(d.errorBound)})` : distanceText(d.distance);
}

/** The place of the extra panes in the page: a viewer in pane `index` (1 or more), and its removal. */
export interface PaneHost {
  addPane(index: number): SubdivViewer;
  removePane(index: number): void;
}

export interface PaneState {
  scheme: SchemeName;
  /** The pane triangulated the control mesh first (its scheme needs triangles, the mesh has other faces). */
  triangulated: boolean;
  /** The model has creases or corners that this pane's scheme does not apply. */
  ignoresTags: boolean;
  viewer: ViewerState;
  /** Why the pane does not show the level asked for (a step failed). */
  message: string;
}

export interface MeasuredDistance extends HausdorffDistance {
  /** The two panes measured, and the schemes and levels they showed. */
  panes: [number, number];
  schemes: [SchemeName, SchemeName];
  levels: [number, number];
  /** `distance` as a share of the diagonal. */
  relative: number;
}

export interface SideBySideState {
  /** 1: side by side is off. */
  count: number;
  together: boolean;
  panes: PaneState[];
  /** The two panes whose distance is measured (indices into panes). */
  pair: [number, number];
  colours: boolean;
  distance: MeasuredDistance | null;
  measuring: boolean;
  message: string;
}

interface ExtraPane {
  viewer: SubdivViewer;
  scheme: SchemeName;
  /** The level this pane aims at (levels apart), and why it could not get there. */
  target: number;
  message: string;
  /** A model is being loaded into the pane: its own fit of the camera is not passed on. */
  loading: boolean;
  /** A pass bringing it to its target runs. */
  reaching: Promise<void> | null;
  again: boolean;
  /** Its model loaded and its level reached (or failed), since it was added. */
  shown: Promise<void>;
  unsubscribe: (() => void)[];
}

export class SideBySide {
  private readonly extra: ExtraPane[] = [];
  private together = true;
  private pair: [number, number] = [0, 1];
  private colours = true;
  private distance: MeasuredDistance | null = null;
  private measuring = false;
  private message = '';
  /** The control mesh the panes show (the first pane's). */
  private model: Mesh | null = null;
  /** Whether {@link model} has faces other than triangles (worked out once a model: state is read on every change). */
  private polygons = false;
  /** A camera change is being passed on: the panes it reaches do not pass it back. */
  private linking = false;
  /** Counts measurements, so that a late one for levels no longer shown is dropped. */
  private asked = 0;
  /** The level ids (viewer.levelId) the distance and colours are of. */
  private measuredIds = '';
  /** Panes (index, level) coloured by the distance. */
  private coloured: { pane: number; level: number }[] = [];
  private readonly listeners = new Set<(state: SideBySideState) => void>();

  /** `onError` hears of failures outside a pane's steps (a distance the core could not measure). */
  constructor(
    private readonly main: SubdivViewer,
    private readonly host: PaneHost,
    private readonly onError: (error: unknown) => void,
  ) {
    main.onChange(() => this.mainChanged());
    main.onViewChange((view) => this.passView(main, view));
  }

  get state(): SideBySideState {
    const main = this.main.state;
    const tags = this.model?.tags;
    const tagged = (tags?.creaseSharpness.length ?? 0) + (tags?.cornerSharpness.length ?? 0) > 0;
    const polygons = this.polygons;
    const pane = (scheme: SchemeName, viewer: ViewerState, message: string): PaneState => ({
      scheme,
      triangulated: polygons && schemeInfo(scheme).needsTriangles,
      ignoresTags: tagged && !schemeInfo(scheme).creases,
      viewer,
      message,
    });
    return {
      count: 1 + this.extra.length,
      together: this.together,
      panes: [pane(main.scheme, main, ''), ...this.extra.map((p) => pane(p.scheme, p.viewer.state, p.message))],
      pair: [...this.pair],
      colours: this.colours,
      distance: this.distance,
      measuring: this.measuring,
      message: this.message,
    };
  }

  onChange(listener: (state: SideBySideState) => void): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }

  /** The viewer of pane `index` (0: the page's own). */
  viewer(index: number): SubdivViewer | null {
    return index === 0 ? this.main : (this.extra[index - 1]?.viewer ?? null);
  }

  /** Shows `count` panes (1 turns side by side off); new ones get a scheme the others do not show. */
  setCount(count: number): void {
    const n = Math.min(Math.max(Math.round(count), 1), MAX_PANES);
    const before = this.extra.length;
    while (1 + this.extra.length > n) this.removeLast();
    while (1 + this.extra.length < n) this.addPane();
    if (this.extra.length !== before) this.refitWhenShown();
    this.keepPair();
    this.remeasure();
    this.emit();
  }

  /** Shows `schemes` in the panes beside the first, in order (none: side by side off). */
  setBeside(schemes: readonly SchemeName[]): void {
    const wanted = schemes.slice(0, MAX_PANES - 1);
    const before = this.extra.length;
    while (this.extra.length > wanted.length) this.removeLast();
    wanted.forEach((scheme, i) => {
      if (i < this.extra.length) this.setScheme(i + 1, scheme);
      else this.addPane(scheme);
    });
    if (this.extra.length !== before) this.refitWhenShown();
    this.keepPair();
    this.remeasure();
    this.emit();
  }

  /**
   * Frames what every pane shows with the linked camera (from `view` as
   * SubdivViewer.fitView takes it): the first pane fits around its own level
   * and the others' levels, and passes the camera on.
   */
  fit(view?: CanonicalView | 'current'): void {
    this.main.fitView(
      view,
      this.extra.map((p) => p.viewer),
    );
  }

  /**
   * The panes changed size (one was added or removed): frames them all again
   * once the new panes show their levels, so that none is cut off (a
   * camera fitted to a wide view is too close for a narrow one).
   */
  private refitWhenShown(): void {
    const shown = this.extra.map((p) => p.shown);
    // A frame first: the views take their new sizes from a resize observer.
    void Promise.allSettled(shown).then(() => requestAnimationFrame(() => this.fit('current')));
  }

  /** The schemes of the panes beside the first. */
  beside(): SchemeName[] {
    return this.extra.map((p) => p.scheme);
  }

  /** Pane `index` (1 or more) shows `scheme`: its levels are computed again up to the level it showed. */
  setScheme(index: number, scheme: SchemeName): void {
    const pane = this.extra[index - 1];
    if (!pane || pane.scheme === scheme) return;
    pane.scheme = scheme;
    pane.message = '';
    pane.viewer.setScheme(scheme);
    pane.viewer.setTriangulate(schemeInfo(scheme).needsTriangles);
    void this.reach(pane);
    this.emit();
  }

  /** Levels stepped together (every pane at the first pane's level) or apart. */
  setTogether(together: boolean): void {
    this.together = together;
    if (together) for (const pane of this.extra) void this.reach(pane);
    this.emit();
  }

  /** Stops the other panes' steps (the levels they reached stay; Cancel in the page stops the first pane's). */
  cancel(): void {
    for (const pane of this.extra) {
      pane.again = false;
      pane.viewer.cancel();
    }
  }

  /** Pane `index` (levels apart; 0 is the page's own) one level up or down; up computes it when needed. */
  step(index: number, delta: number): void {
    const pane = this.extra[index - 1];
    if (!pane) return;
    pane.target = Math.max(0, pane.viewer.state.level + delta);
    void this.reach(pane);
  }

  /** Measures the distance between panes `a` and `b`. */
  setPair(a: number, b: number): void {
    const count = 1 + this.extra.length;
    // Two menus: one pane in both keeps the pair it had (the panel shows it again).
    if (a !== b && a >= 0 && b >= 0 && a < count && b < count) this.pair = [a, b];
    this.remeasure();
    this.emit();
  }

  /** Colours the measured panes by each vertex's distance to the other surface, or not. */
  setColours(on: boolean): void {
    this.colours = on;
    if (on) {
      this.remeasure();
    } else {
      this.clearColours();
      this.measuredIds = '';
    }
    this.emit();
  }

  /** The measured pair stays two different panes that exist. */
  private keepPair(): void {
    const n = 1 + this.extra.length;
    this.pair = [Math.min(this.pair[0], n - 1), Math.min(this.pair[1], n - 1)];
    if (this.pair[0] === this.pair[1]) this.pair = [0, n > 1 ? 1 : 0];
  }

  /** A pane beside the others, showing `scheme` (default: one the others do not show, the classic comparison first). */
  private addPane(chosen?: SchemeName): void {
    const index = 1 + this.extra.length;
    const used = new Set([this.main.state.scheme, ...this.extra.map((p) => p.scheme)]);
    const preferred = COMPANIONS[this.main.state.scheme] ?? [];
    const scheme = chosen ?? [...preferred, ...PANE_SCHEMES].find((s) => !used.has(s)) ?? 'loop';
    const viewer = this.host.addPane(index);
    viewer.setScheme(scheme);
    viewer.setTriangulate(schemeInfo(scheme).needsTriangles);
    viewer.setRenderMode(this.main.state.renderMode);
    for (const [name, on] of Object.entries(this.main.state.overlays) as [keyof ViewerState['overlays'], boolean][])
      viewer.setOverlay(name, on);
    const pane: ExtraPane = {
      viewer,
      scheme,
      target: this.main.state.level,
      message: '',
      loading: false,
      reaching: null,
      again: false,
      shown: Promise.resolve(),
      unsubscribe: [],
    };
    pane.unsubscribe.push(
      viewer.onChange(() => {
        this.remeasure();
        this.emit();
      }),
      viewer.onViewChange((view) => {
        if (!pane.loading) this.passView(viewer, view);
      }),
    );
    this.extra.push(pane);
    if (this.model) pane.shown = this.loadInto(pane, this.model);
  }

  private removeLast(): void {
    const pane = this.extra.pop();
    if (!pane) return;
    for (const stop of pane.unsubscribe) stop();
    this.coloured = this.coloured.filter((c) => c.pane !== this.extra.length + 1);
    pane.viewer.dispose();
    this.host.removePane(this.extra.length + 1);
  }

  private mainChanged(): void {
    const main = this.main.state;
    const model = this.main.controlMesh;
    if (model !== this.model) {
      this.model = model;
      this.polygons = model !== null && !allTriangles(model.faceSizes);
      this.distance = null;
      this.coloured = [];
      if (model) for (const pane of this.extra) void this.loadInto(pane, model);
    } else if (this.together && !main.busy) {
      for (const pane of this.extra) if (pane.viewer.state.level !== main.level) void this.reach(pane);
    }
    // The display follows the first pane: render mode and overlays.
    for (const pane of this.extra) {
      const state = pane.viewer.state;
      if (state.renderMode !== main.renderMode) pane.viewer.setRenderMode(main.renderMode);
      for (const [name, on] of Object.entries(main.overlays) as [keyof typeof main.overlays, boolean][])
        if (state.overlays[name] !== on) pane.viewer.setOverlay(name, on);
    }
    this.remeasure();
    this.emit();
  }

  /** Shows `model` (the first pane's control mesh) in `pane`, then its level; the camera stays the first pane's. */
  private async loadInto(pane: ExtraPane, model: Mesh): Promise<void> {
    pane.loading = true;
    pane.message = '';
    try {
      await pane.viewer.load(model, this.main.state.modelName ?? 'mesh');
    } catch (error) {
      if (!(error instanceof CancelledError)) pane.message = `Could not show the model: ${messageOf(error)}`;
      this.emit();
      return;
    } finally {
      pane.loading = false;
    }
    if (this.model !== model) return;
    this.linkCamera(pane.viewer);
    await this.reach(pane);
  }

  /** Brings `pane` to its level (the first pane's when together), one step at a time; a step that fails is named in the pane. */
  private reach(pane: ExtraPane): Promise<void> {
    if (pane.reaching) {
      pane.again = true;
      return pane.reaching;
    }
    const run = async () => {
      do {
        pane.again = false;
        const viewer = pane.viewer;
        const target = this.together ? this.main.state.level : pane.target;
        if (viewer.state.levelCount === 0) return;
        while (viewer.state.levelCount <= target && !pane.again) {
          try {
            if (viewer.state.busy) {
              // A measurement (or a load) runs in this pane: step once it is done.
              await idle(viewer);
              continue;
            }
            if (!(await viewer.subdivide())) {
              pane.message = `Level ${viewer.state.levelCount} was not computed: it is larger than this tab should hold.`;
              break;
            }
          } catch (error) {
            if (!(error instanceof CancelledError)) pane.message = messageOf(error);
            pane.target = viewer.state.level;
            this.emit();
            return;
          }
        }
        if (pane.again) continue;
        viewer.setLevel(Math.min(target, viewer.state.levelCount - 1));
        pane.target = viewer.state.level;
        if (viewer.state.level === target) pane.message = '';
      } while (pane.again);
    };
    // Cleared in a callback, which runs after the assignment even when run() ends without waiting.
    pane.reaching = run().finally(() => {
      pane.reaching = null;
      this.emit();
    });
    return pane.reaching;
  }

  /** Passes the camera of `from` on to every other pane. */
  private passView(from: SubdivViewer, view: ViewState): void {
    if (this.linking || this.extra.length === 0) return;
    this.linking = true;
    try {
      for (const viewer of this.viewers()) if (viewer !== from) viewer.setView(view);
    } finally {
      this.linking = false;
    }
  }

  private linkCamera(viewer: SubdivViewer): void {
    this.linking = true;
    try {
      viewer.setView(this.main.getView());
    } finally {
      this.linking = false;
    }
  }

  /** Every pane's viewer, the page's own first. */
  viewers(): SubdivViewer[] {
    return [this.main, ...this.extra.map((p) => p.viewer)];
  }

  /** Measures the pair again when the levels they show changed and neither is busy. */
  private remeasure(): void {
    if (this.extra.length === 0) {
      if (this.distance || this.coloured.length > 0) {
        this.clearColours();
        this.distance = null;
        this.measuredIds = '';
      }
      return;
    }
    const [a, b] = this.pair.map((i) => this.viewer(i));
    if (!a || !b) return;
    const ids = `${this.pair.join(',')}:${a.levelId()},${b.levelId()}`;
    if (ids === this.measuredIds) return;
    if (a.state.busy || b.state.busy || a.levelId() === 0 || b.levelId() === 0) return;
    if (this.measuring) {
      // Asked again once the running measurement ends.
      this.measuredIds = '';
      return;
    }
    this.measuredIds = ids;
    void this.measure(a, b);
  }

  private async measure(a: SubdivViewer, b: SubdivViewer): Promise<void> {
    const asked = ++this.asked;
    const pair: [number, number] = [...this.pair];
    const levels: [number, number] = [a.state.level, b.state.level];
    const schemes: [SchemeName, SchemeName] = [a.state.scheme, b.state.scheme];
    const ids = [a.levelId(), b.levelId()];
    this.measuring = true;
    this.emit();
    try {
      const h = await a.distanceTo(b);
      if (asked !== this.asked || !h || a.levelId() !== ids[0] || b.levelId() !== ids[1]) return;
      this.distance = { ...h, panes: pair, schemes, levels, relative: h.diagonal > 0 ? h.distance / h.diagonal : 0 };
      this.message = '';
      this.clearColours();
      if (this.colours && h.aToB && h.bToA) {
        // One scale for both: dark on the other surface, yellow at the Hausdorff distance.
        const top = Math.max(h.distance, 1e-300);
        a.setLevelColors(levels[0], influenceColors(h.aToB, 0, top), 'distance');
        b.setLevelColors(levels[1], influenceColors(h.bToA, 0, top), 'distance');
        this.coloured = [
          { pane: pair[0], level: levels[0] },
          { pane: pair[1], level: levels[1] },
        ];
      }
    } catch (error) {
      if (asked !== this.asked || error instanceof CancelledError) return;
      this.message = `The distance could not be measured: ${messageOf(error)}`;
      this.onError(error);
    } finally {
      if (asked === this.asked) this.measuring = false;
      this.emit();
      if (asked === this.asked) this.remeasure();
    }
  }

  private clearColours(): void {
    for (const { pane, level } of this.coloured) this.viewer(pane)?.setLevelColors(level, null, 'distance');
    this.coloured = [];
  }

  private emit(): void {
    const state = this.state;
    for (const listener of this.listeners) listener(state);
  }
}

/** Resolves once `viewer` is no longer busy. */
function idle(viewer: SubdivViewer): Promise<void> {
  return new Promise((resolve) => {
    if (!viewer.state.busy) return resolve();
    const stop = viewer.onChange((state) => {
      if (state.busy) return;
      stop();
      resolve();
    });
  });
}

/** Whether every face has three corners (a loop, not some(): a million faces are read within a frame). */
function allTriangles(faceSizes: ArrayLike<number>): boolean {
  for (let f = 0; f < faceSizes.length; ++f) if (faceSizes[f] !== 3) return false;
  return true;
}
