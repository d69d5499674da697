/**
 * `<subdiv-viewer>`: a SubdivViewer as a standard custom element, for
 * teaching pages. Attributes describe the state it should show (model,
 * scheme, level, display, camera) and are applied live; methods mirror the
 * viewer; events (bubbling, composed CustomEvents) report `load`,
 * `level-change`, `error` and `progress`, and the teaching tools'
 * `stencil` and `basis` (embed-tools.ts). Every viewer of a page shares one
 * worker and one WebGL renderer; a viewer starts when it nears the
 * viewport and gives its GPU memory back when it is far from it.
 */
import type { MeshFacts, SchemeName } from '../core/mesh';
import { SubdivError } from '../core/subdiv-error';
import { CancelledError } from '../core/worker-client';
import { nextRenderMode, OVERLAY_NAMES } from '../render/render-mode';
import { VIEW_COLORS } from '../render/scene-view';
import { checkedView, parseViewString, type ViewState } from '../render/view-state';
import { faceTypes } from '../ui/facts-panel';
import { installShortcuts } from '../ui/shortcuts';
import { handleViewKey } from '../ui/view-keys';
import { messageOf } from '../viewer/error-message';
import { formatBytes } from '../viewer/memory-budget';
import { meshText, readFile } from '../viewer/mesh-source';
import { schemeInfo } from '../viewer/scheme-info';
import { SubdivViewer, type ViewerState } from '../viewer/subdiv-viewer';
import { MAX_PARAM_LEVELS, OVERLAY_KEYS } from '../viewer/viewer-params';
import { EmbedCaption } from './embed-caption';
import { EmbedChrome } from './embed-chrome';
import { EmbedControls } from './embed-controls';
import { whenFar, whenNear } from './embed-distance';
import { errorDetail, type LevelChangeDetail, type LoadDetail, type ProgressDetail } from './embed-events';
import { EmbedPanes } from './embed-panes';
import { EmbedSync } from './embed-sync';
import { EmbedTools } from './embed-tools';
import { OBSERVED_ATTRIBUTES, ViewerAttributes } from './viewer-attributes';

/** Attributes applied without touching the model or its levels. */
const DISPLAY_ATTRIBUTES = new Set([
  'render-mode',
  'control-mesh',
  'control-edges',
  'bbox',
  'view',
  'controls',
  'alt',
  'background',
  'tool',
  'vertex',
  'split',
  'beside',
  'distance',
  'line-width',
]);

export class SubdivViewerElement extends ViewerAttributes {
  static readonly observedAttributes = OBSERVED_ATTRIBUTES;

  private viewer: SubdivViewer | null = null;
  private tools: EmbedTools | null = null;
  private readonly controlBar: EmbedControls;
  private readonly caption = new EmbedCaption();
  private readonly distanceCaption = new EmbedCaption(
    'distance',
    'colour bar: on the other surface (dark) to the Hausdorff distance (yellow)',
  );
  private panes: EmbedPanes | null = null;
  private readonly chrome: EmbedChrome;
  /** Stop watching the distance to the viewport (start, release). */
  private unwatch: (() => void)[] = [];
  private readonly darkQuery = window.matchMedia('(prefers-color-scheme: dark)');
  private readonly sync = new EmbedSync({
    viewer: () => this.viewer,
    readState: () => this.readState(),
    fail: (source, error) => this.fail(source, error),
    loaded: () => {
      const viewer = this.viewer;
      if (!viewer) return;
      this.chrome.setPlaceholder(null);
      this.applyDisplay(true);
      this.dispatch('load', { modelName: viewer.state.modelName, facts: viewer.state.facts } as LoadDetail);
    },
    downloadChanged: () => {
      if (this.viewer) this.onState(this.viewer.state);
    },
    allWell: () => this.chrome.hideMessage(),
    settled: () => this.tools?.refresh(),
  });
  private last: { level: number; facts: MeshFacts | null; busy: boolean; scheme: SchemeName } | null = null;
  private gpuReleasedFlag = false;

  constructor() {
    super();
    this.controlBar = new EmbedControls({
      stepLevel: (delta) => void this.stepLevel(delta),
      scheme: (scheme) => {
        this.scheme = scheme;
      },
      renderMode: (mode) => {
        this.renderMode = mode;
      },
      overlay: (name, on) => this.setFlag(OVERLAY_KEYS[name], on),
      fit: () => this.viewer?.fitView(),
      split: (t) => this.setAttribute('split', String(t)),
      play: () => this.tools?.play(),
    });
    const root = this.attachShadow({ mode: 'open' });
    this.chrome = new EmbedChrome(root, this.controlBar, [this.caption, this.distanceCaption], () => this.cancel());
    this.installKeys();
    this.darkQuery.addEventListener('change', () => this.applyDisplay());
  }

  connectedCallback(): void {
    this.upgradeProperties();
    if (!this.hasAttribute('tabindex')) this.tabIndex = 0;
    this.applyDisplay();
    if (this.viewer) return;
    this.unwatch.push(whenNear(this, () => this.start()));
  }

  disconnectedCallback(): void {
    this.teardownIfOut();
  }

  /** Moving the element in the page disconnects and connects it in one task: tear down only if it stays out. */
  private teardownIfOut(): void {
    queueMicrotask(() => {
      if (this.isConnected || !this.viewer) return;
      for (const stop of this.unwatch.splice(0)) stop();
      this.sync.reset();
      this.panes?.dispose();
      this.panes = null;
      this.viewer.dispose();
      this.viewer = null;
      this.tools = null;
      // A page's spinner waits for the end of what was under way.
      if (this.last?.busy) this.dispatch('progress', { busy: false, kind: null, label: '' } as ProgressDetail);
      this.last = null;
      this.gpuReleasedFlag = false;
    });
  }

  attributeChangedCallback(name: string, oldValue: string | null, value: string | null): void {
    if (oldValue === value) return;
    if (DISPLAY_ATTRIBUTES.has(name)) {
      this.applyDisplay(name === 'view');
      return;
    }
    if (name === 'src' || name === 'rules') this.sync.sourceChanged();
    // A model of the old src still being read is not wanted any more.
    if (name === 'src' && this.viewer?.state.busy?.kind === 'load') this.viewer.cancel();
    // A change that makes the running step useless stops it; the levels computed so far stay.
    const running = this.sync.runningLevels;
    const stepping = this.viewer?.state.busy?.kind === 'subdivide';
    if (running !== null && stepping && (name !== 'levels' || this.readState().levels < running)) this.viewer?.cancel();
    void this.sync.request();
  }

  /** The shown level (−1 before a model is loaded). */
  get level(): number {
    const state = this.viewer?.state;
    return state && state.levelCount > 0 ? state.level : -1;
  }

  /** Facts of the shown level (null before a model is loaded). */
  get facts(): MeshFacts | null {
    return this.viewer?.state.facts ?? null;
  }

  /** The viewer's state (null before the element started). */
  get state(): ViewerState | null {
    return this.viewer?.state ?? null;
  }

  /** True while the element holds no GPU memory (far out of view). */
  get gpuReleased(): boolean {
    return this.gpuReleasedFlag;
  }

  // --- Methods ------------------------------------------------------------------------------

  /** Computes one more level and shows it (up to level 8); resolves with the level shown. */
  async subdivide(): Promise<number> {
    const level = this.level;
    return level < 0 ? level : this.setLevel(level + 1);
  }

  /**
   * Shows level `n` (0–8), computing the levels up to it as needed; resolves
   * with the level shown, lower than `n` when a step failed or was cancelled.
   */
  async setLevel(n: number): Promise<number> {
    if (typeof n !== 'number' || !Number.isFinite(n)) throw new TypeError(`setLevel needs a number, not ${n}.`);
    this.levels = Math.max(0, Math.min(MAX_PARAM_LEVELS, Math.round(n)));
    // The attribute's change started a pass if it changed; otherwise start one (a level that failed before).
    await this.sync.current();
    return this.level;
  }

  /**
   * Shows a mesh from a File, or from OFF/OBJ text named `name`, in place of
   * `src`'s; the last call wins. Resolves once it is shown, or when it was
   * superseded (another load(), cancel(), removal); rejects with the reason
   * it could not be read.
   */
  load(input: File | string, name = 'mesh.off'): Promise<void> {
    this.start();
    const read = input instanceof File ? () => readFile(input) : async () => meshText(name, input);
    return this.sync.load(read, input instanceof File ? input.name : name, this.src);
  }

  /** Loads `src` again (after load(), or when the file behind the URL changed). */
  reload(): Promise<void> {
    this.sync.forgetSrc();
    this.start();
    return this.sync.request();
  }

  /** PNG of the view at `scale` × its size. */
  exportPng(scale = 1, transparent = false): Promise<Blob> {
    return this.start().exportPng(scale, transparent);
  }

  /** SVG of the view (camera-facing polygons back to front, overlays when shown). */
  exportSvg(transparent = false): string {
    return this.start().exportSvg(transparent);
  }

  /** The same figure as {@link exportSvg}, as a one-page PDF (bytes). */
  exportPdf(transparent = false): Uint8Array {
    return this.start().exportPdf(transparent);
  }

  /** The same figure as {@link exportSvg}, as EPS (opaque). */
  exportEps(transparent = false): string {
    return this.start().exportEps(transparent);
  }

  getView(): ViewState | null {
    return this.viewer?.getView() ?? null;
  }

  /** Sets the camera: a ViewState, or the nine-number string of the `view` attribute. */
  setView(view: ViewState | string): void {
    const checked = typeof view === 'string' ? parseViewString(view) : checkedView(view);
    if (!checked) {
      throw new TypeError('setView needs { position, target, up } (finite, the eye off the target) or nine numbers.');
    }
    this.start().setView(checked);
  }

  /** Stops this viewer's running step and the steps it was to run next (other viewers' work goes on). */
  cancel(): void {
    this.sync.cancel();
    this.viewer?.cancel();
    this.panes?.cancel();
    if (this.level < 0) this.chrome.setPlaceholder('Loading stopped.');
  }

  // --- Inside ------------------------------------------------------------------------------

  private start(): SubdivViewer {
    if (this.viewer) return this.viewer;
    // Started outside the page (a method called on a removed element): torn down again unless it is put back.
    if (!this.isConnected) this.teardownIfOut();
    const initial = this.readState();
    const viewer = new SubdivViewer(this.chrome.stage, {
      scheme: initial.scheme,
      renderMode: initial.renderMode,
      // No dialog in a page: a step over the budget is refused, and says so.
      confirmLargeStep: async (info) => {
        const faces = info.prediction.faces.toLocaleString('en');
        const message =
          `Level ${info.level} would have ${faces} faces and need about ${formatBytes(info.estimatedBytes)}; ` +
          `this page should not use more than ${formatBytes(info.budgetBytes)}.`;
        this.fail(viewer.state.modelName ?? 'mesh', new SubdivError('too_large', message));
        return false;
      },
    });
    this.viewer = viewer;
    viewer.onChange((state) => this.onState(state));
    this.tools = new EmbedTools(
      viewer,
      {
        readState: () => this.readState(),
        settling: () => this.sync.running,
        setVertex: (vertex) => this.setAttribute('vertex', String(vertex)),
        setSplit: (t) => this.setAttribute('split', String(t)),
        fail: (error) => this.fail(viewer.state.modelName ?? 'mesh', error),
        dispatch: (type: string, detail: unknown) => this.dispatch(type, detail),
      },
      this.caption,
      this.controlBar,
    );
    this.panes = new EmbedPanes(
      viewer,
      {
        readState: () => this.readState(),
        fail: (error) => this.fail(viewer.state.modelName ?? 'mesh', error),
        dispatch: (type, detail) => this.dispatch(type, detail),
      },
      this.chrome,
      this.distanceCaption,
    );
    this.controlBar.update(viewer.state);
    this.unwatch.push(
      whenFar(
        this,
        () => {
          viewer.releaseGpu();
          this.panes?.releaseGpu(true);
          this.gpuReleasedFlag = true;
        },
        () => {
          this.gpuReleasedFlag = false;
          viewer.view.requestRender();
          this.panes?.releaseGpu(false);
        },
      ),
    );
    this.applyDisplay();
    void this.sync.request();
    return viewer;
  }

  private async stepLevel(delta: number): Promise<void> {
    const level = this.level;
    const next = level + delta;
    if (level < 0 || next < 0 || next > MAX_PARAM_LEVELS) return;
    await this.setLevel(next);
  }

  /** Applies what changes nothing in the levels: display, overlays, camera, controls, labels, colours. */
  private applyDisplay(applyView = false): void {
    const want = this.readState();
    this.controlBar.setMode(want.controls);
    const viewer = this.viewer;
    const label = want.alt || this.describe();
    this.chrome.setLabel(label);
    if (!viewer) return;
    // A bad display attribute put right: a pass clears its message if nothing else is wrong.
    if (this.sync.reportProblems(want.problems)) void this.sync.run();
    if (!want.src && viewer.state.levelCount === 0) this.chrome.setPlaceholder('No model: set the src attribute.');
    if (viewer.state.renderMode !== want.renderMode) viewer.setRenderMode(want.renderMode);
    if (viewer.state.lineWidth !== want.lineWidth) viewer.setLineWidth(want.lineWidth);
    for (const name of OVERLAY_NAMES) {
      if (viewer.state.overlays[name] !== want.overlays[name]) viewer.setOverlay(name, want.overlays[name]);
    }
    const dark = this.darkQuery.matches;
    const background = want.background ?? (dark ? VIEW_COLORS.backgroundDark : VIEW_COLORS.background);
    viewer.view.setBackground(background === 'transparent' ? null : background, dark);
    this.panes?.apply(background === 'transparent' ? null : background, dark);
    if (applyView && want.view && viewer.state.levelCount > 0) viewer.setView(want.view);
    this.tools?.apply();
  }

  private describe(): string {
    const state = this.viewer?.state;
    if (!state || state.levelCount === 0) return 'Subdivision surface viewer';
    const f = state.facts;
    const what = f ? `, ${faceTypes(f)}` : '';
    return `${state.modelName ?? 'Mesh'}, ${schemeInfo(state.scheme).label} level ${state.level}${what}`;
  }

  private onState(state: ViewerState): void {
    this.controlBar.update(state);
    if (state.levelCount > 0) this.chrome.setPlaceholder(null);
    const downloading = this.sync.downloading;
    const busy = state.busy !== null || downloading !== null;
    const kind = state.busy?.kind ?? (downloading ? 'load' : null);
    const label = state.busy?.label ?? (downloading ? `Downloading ${downloading}…` : '');
    this.chrome.setBusy(busy ? label : null);
    if (!this.getAttribute('alt')) this.chrome.setLabel(this.describe());
    const prev = this.last;
    this.last = { level: state.level, facts: state.facts, busy, scheme: state.scheme };
    if (!prev || prev.busy !== busy) {
      this.dispatch('progress', { busy, kind, label } as ProgressDetail);
    }
    const changed = !prev || prev.level !== state.level || prev.facts !== state.facts || prev.scheme !== state.scheme;
    if (state.facts && changed) {
      this.chrome.announce(`Level ${state.level}: ${faceTypes(state.facts)}, genus ${state.facts.genus}`);
      this.dispatch('level-change', {
        level: state.level,
        levelCount: state.levelCount,
        scheme: state.scheme,
        modelName: state.modelName,
        facts: state.facts,
      } as LevelChangeDetail);
    }
  }

  /** Camera keys, then the app's shortcuts (ui/shortcuts.ts), on this element only. */
  private installKeys(): void {
    this.addEventListener('keydown', (event) => {
      const target = event.composedPath()[0];
      if (this.viewer && !(target instanceof HTMLSelectElement) && handleViewKey(this.viewer.view, event)) return;
    });
    installShortcuts(
      this,
      {
        subdivide: () => void this.stepLevel(1),
        stepLevel: (delta) => void this.stepLevel(delta),
        cycleRenderMode: () => {
          this.renderMode = nextRenderMode(this.renderMode);
        },
        toggleOverlay: (name) => this.setFlag(OVERLAY_KEYS[name], !this.readState().overlays[name]),
        fit: () => this.viewer?.fitView(),
        cancel: () => this.cancel(),
        copyImage: () => void this.copyImage(),
      },
      () => !this.viewer,
    );
  }

  private async copyImage(): Promise<void> {
    if (this.level < 0) return;
    try {
      await navigator.clipboard.write([new ClipboardItem({ 'image/png': this.exportPng(1) })]);
    } catch (error) {
      this.fail('Clipboard', error);
    }
  }

  private fail(source: string, error: unknown): void {
    if (error instanceof CancelledError) return;
    this.sync.noteFailure();
    const detail = errorDetail(source, error);
    this.chrome.showMessage(`${detail.source}: ${messageOf(error)}`);
    this.dispatch('error', detail);
  }

  private dispatch(type: string, detail: unknown): void {
    this.dispatchEvent(new CustomEvent(type, { detail, bubbles: true, composed: true }));
  }
}
