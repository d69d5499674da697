/**
 * `<subdiv-viewer>`: a SubdivViewer as a standard custom element, for
 * teaching pages. Attributes describe the state it should show (model,
 * scheme, level, display, camera) and are applied live; methods mirror the
 * viewer; events (bubbling, composed CustomEvents) report `load`,
 * `level-change`, `error` and `progress`. Every viewer of a page shares one
 * worker and one WebGL renderer; a viewer starts when it nears the
 * viewport and gives its GPU memory back when it is far from it.
 */
import type { MeshFacts, SchemeName } from '../core/mesh';
import { SubdivError } from '../core/subdiv-error';
import { CancelledError } from '../core/worker-client';
import { nextRenderMode, type OverlayName } from '../render/render-mode';
import { checkedView, parseViewString, type ViewState } from '../render/view-state';
import { el } from '../ui/dom';
import { faceTypes } from '../ui/facts-panel';
import { installShortcuts } from '../ui/shortcuts';
import { handleViewKey } from '../ui/view-keys';
import { formatBytes } from '../viewer/memory-budget';
import { fetchMesh, meshText, readFile } from '../viewer/mesh-source';
import { fetchRuleSet } from '../viewer/rules-source';
import { schemeInfo } from '../viewer/scheme-info';
import { SubdivViewer, type ViewerState } from '../viewer/subdiv-viewer';
import { MAX_PARAM_LEVELS } from '../viewer/viewer-params';
import { EmbedControls } from './embed-controls';
import {
  AttributeError,
  errorDetail,
  type LevelChangeDetail,
  type LoadDetail,
  type ProgressDetail,
} from './embed-events';
import type { EmbedState } from './embed-state';
import { EMBED_CSS } from './embed-styles';
import { ViewerAttributes } from './viewer-attributes';

export const OBSERVED_ATTRIBUTES = [
  'src',
  'scheme',
  'levels',
  'render-mode',
  'control-mesh',
  'control-edges',
  'bbox',
  'triangulate',
  'rules',
  'view',
  'controls',
  'alt',
  'background',
] as const;

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
]);

/** Margins of the viewport within which a viewer starts, and beyond which it frees its GPU memory. */
const START_MARGIN = '200px 0px';
const RELEASE_MARGIN = '150% 0px';

export class SubdivViewerElement extends ViewerAttributes {
  static readonly observedAttributes = OBSERVED_ATTRIBUTES;

  private viewer: SubdivViewer | null = null;
  private readonly stage: HTMLElement;
  private readonly controlBar: EmbedControls;
  private readonly message: HTMLElement;
  private readonly status: HTMLElement;
  private readonly busyBox: HTMLElement;
  private readonly busyLabel: HTMLElement;
  private readonly placeholder: HTMLElement;
  private startObserver: IntersectionObserver | null = null;
  private releaseObserver: IntersectionObserver | null = null;
  private readonly darkQuery = window.matchMedia('(prefers-color-scheme: dark)');
  /** The src whose model is shown (or whose load failed: not retried until the attribute changes). */
  private loadedSrc: string | null = null;
  private loadedRules = '';
  /** Bumped by load(): a src download that finishes later is dropped. */
  private modelEpoch = 0;
  /** The src download under way: a new src, load(), cancel() or removal aborts it. */
  private download: { controller: AbortController; name: string } | null = null;
  private syncing: Promise<void> | null = null;
  private syncAgain = false;
  /** What the running pass aims at (null between passes). */
  private passTarget: EmbedState | null = null;
  /** cancel() during the running pass: it computes no further level. */
  private passCancelled = false;
  /** Failures reported during the running pass: a pass without any clears the message. */
  private passFailures = 0;
  /** Attribute problems already reported (an attribute's problem is reported once, not on every pass). */
  private reportedProblems = new Set<string>();
  private last: { level: number; facts: MeshFacts | null; busy: boolean; scheme: SchemeName } | null = null;
  private gpuReleasedFlag = false;

  constructor() {
    super();
    const root = this.attachShadow({ mode: 'open', delegatesFocus: false });
    const style = document.createElement('style');
    style.textContent = EMBED_CSS;
    this.stage = el('div', { className: 'stage', attrs: { part: 'stage', role: 'region' } });
    this.placeholder = el('div', { className: 'placeholder', text: 'Loading…' });
    this.message = el('div', { className: 'message', attrs: { part: 'message', role: 'alert' } });
    this.message.hidden = true;
    this.status = el('div', { className: 'status', attrs: { role: 'status', 'aria-live': 'polite' } });
    this.busyLabel = el('span');
    const cancel = el('button', { text: 'Cancel', attrs: { type: 'button', part: 'cancel' } });
    cancel.addEventListener('click', () => this.cancel());
    this.busyBox = el('div', { className: 'busy', attrs: { part: 'progress' } }, this.busyLabel, cancel);
    this.busyBox.hidden = true;
    this.stage.append(this.placeholder, this.message, this.busyBox, this.status);
    this.controlBar = new EmbedControls({
      stepLevel: (delta) => void this.stepLevel(delta),
      scheme: (scheme) => {
        this.scheme = scheme;
      },
      renderMode: (mode) => {
        this.renderMode = mode;
      },
      overlay: (name, on) => this.setFlag(name === 'control' ? 'control-mesh' : 'control-edges', on),
      fit: () => this.viewer?.fitView(),
    });
    root.append(style, el('div', { className: 'frame' }, this.stage, this.controlBar.element));
    this.installKeys();
    this.darkQuery.addEventListener('change', () => this.applyDisplay());
  }

  connectedCallback(): void {
    this.upgradeProperties();
    if (!this.hasAttribute('tabindex')) this.tabIndex = 0;
    this.applyDisplay();
    if (this.viewer) return;
    this.startObserver = new IntersectionObserver(
      (entries) => {
        if (entries.some((e) => e.isIntersecting)) this.start();
      },
      { rootMargin: START_MARGIN },
    );
    this.startObserver.observe(this);
  }

  disconnectedCallback(): void {
    // Moving the element in the page disconnects and connects it in one task: dispose only if it stays out.
    queueMicrotask(() => {
      if (this.isConnected) return;
      this.startObserver?.disconnect();
      this.startObserver = null;
      this.releaseObserver?.disconnect();
      this.releaseObserver = null;
      this.download?.controller.abort();
      this.viewer?.dispose();
      this.viewer = null;
      this.loadedSrc = null;
      this.loadedRules = '';
      this.last = null;
      this.gpuReleasedFlag = false;
      this.reportedProblems.clear();
    });
  }

  attributeChangedCallback(name: string, oldValue: string | null, value: string | null): void {
    if (oldValue === value) return;
    if (DISPLAY_ATTRIBUTES.has(name)) {
      this.applyDisplay(name === 'view');
      return;
    }
    if (name === 'src') this.download?.controller.abort();
    // A change that makes the running step useless stops it; the levels computed so far stay.
    const running = this.passTarget;
    const stepping = this.viewer?.state.busy?.kind === 'subdivide';
    if (running && stepping && (name !== 'levels' || this.readState().levels < running.levels)) this.viewer?.cancel();
    void this.sync();
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
    this.levels = Math.max(0, Math.min(MAX_PARAM_LEVELS, Math.round(n)));
    // The attribute's change started a pass if it changed; otherwise start one (a level that failed before).
    await (this.syncing ?? this.sync());
    return this.level;
  }

  /** Shows a mesh from a File, or from OFF/OBJ text named `name`, in place of `src`'s. */
  async load(input: File | string, name = 'mesh.off'): Promise<void> {
    const viewer = this.start();
    const fileName = input instanceof File ? input.name : name;
    // A src download still running is stopped (or dropped, if it arrives all the same).
    this.modelEpoch++;
    this.download?.controller.abort();
    this.loadedSrc = this.src;
    try {
      const mesh = input instanceof File ? await readFile(input) : meshText(name, input);
      await viewer.loadText(mesh.text, mesh.format, mesh.name);
      this.hideMessage();
      this.dispatch('load', { modelName: mesh.name, facts: viewer.state.facts } as LoadDetail);
    } catch (error) {
      this.fail(fileName, error);
      throw error;
    }
    await this.sync();
  }

  /** Loads `src` again (after load(), or when the file behind the URL changed). */
  reload(): Promise<void> {
    this.loadedSrc = null;
    this.start();
    return this.sync();
  }

  /** PNG of the view at `scale` × its size. */
  exportPng(scale = 1, transparent = false): Promise<Blob> {
    return this.start().exportPng(scale, transparent);
  }

  /** SVG of the view (camera-facing polygons back to front, overlays when shown). */
  exportSvg(transparent = false): string {
    return this.start().exportSvg(transparent);
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
    if (this.passTarget) this.passCancelled = true;
    this.download?.controller.abort();
    this.viewer?.cancel();
  }

  // --- Inside ------------------------------------------------------------------------------

  private start(): SubdivViewer {
    if (this.viewer) return this.viewer;
    this.startObserver?.disconnect();
    this.startObserver = null;
    const initial = this.readState();
    const viewer = new SubdivViewer(this.stage, {
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
    this.controlBar.update(viewer.state);
    this.releaseObserver = new IntersectionObserver(
      (entries) => {
        const near = entries.some((e) => e.isIntersecting);
        if (!near && !this.gpuReleasedFlag) {
          viewer.releaseGpu();
          this.gpuReleasedFlag = true;
        } else if (near) {
          this.gpuReleasedFlag = false;
          viewer.view.requestRender();
        }
      },
      { rootMargin: RELEASE_MARGIN },
    );
    this.releaseObserver.observe(this);
    this.applyDisplay();
    void this.sync();
    return viewer;
  }

  private async stepLevel(delta: number): Promise<void> {
    const level = this.level;
    const next = level + delta;
    if (level < 0 || next < 0 || next > MAX_PARAM_LEVELS) return;
    await this.setLevel(next);
  }

  /**
   * Brings the viewer to what the attributes ask: model, rules, scheme, then
   * levels. One pass at a time; a change during a pass runs another.
   */
  private sync(): Promise<void> {
    if (!this.viewer) return Promise.resolve();
    if (this.syncing) {
      this.syncAgain = true;
      return this.syncing;
    }
    this.syncing = (async () => {
      try {
        do {
          this.syncAgain = false;
          await this.syncOnce();
        } while (this.syncAgain && this.viewer);
      } finally {
        this.syncing = null;
      }
    })();
    return this.syncing;
  }

  private async syncOnce(): Promise<void> {
    const viewer = this.viewer;
    if (!viewer) return;
    const want = this.readState();
    this.passTarget = want;
    this.passFailures = 0;
    this.passCancelled = false;
    try {
      if (await this.syncModel(viewer, want)) await this.syncLevels(viewer, want);
    } finally {
      this.passTarget = null;
    }
    const attributeProblems = this.readState().problems.length;
    if (this.viewer === viewer && this.passFailures === 0 && attributeProblems === 0 && !this.syncAgain) {
      this.hideMessage();
    }
  }

  /** Model and rules as the attributes ask; false when the pass cannot go on (failed, superseded, removed). */
  private async syncModel(viewer: SubdivViewer, want: EmbedState): Promise<boolean> {
    this.reportProblems(want.problems);
    const alive = () => this.viewer === viewer;
    if (want.src && want.src !== this.loadedSrc) {
      this.loadedSrc = want.src;
      const epoch = this.modelEpoch;
      const controller = new AbortController();
      this.download = { controller, name: want.src.split(/[/?#]/).filter(Boolean).pop() ?? want.src };
      this.onState(viewer.state);
      try {
        const mesh = await fetchMesh(want.src, document.baseURI, undefined, controller.signal).finally(() => {
          if (this.download?.controller === controller) this.download = null;
          if (alive()) this.onState(viewer.state);
        });
        // Superseded while downloading: by load(), a new src, or the element's removal.
        if (!alive() || epoch !== this.modelEpoch || this.readState().src !== want.src) return false;
        await viewer.loadText(mesh.text, mesh.format, mesh.name);
        if (!alive()) return false;
        this.placeholder.hidden = true;
        this.applyDisplay(true);
        this.dispatch('load', { modelName: mesh.name, facts: viewer.state.facts } as LoadDetail);
      } catch (error) {
        // Cancelled (Esc while loading): the src is still to be loaded, unless load() replaced it.
        if (error instanceof CancelledError && epoch === this.modelEpoch) this.loadedSrc = null;
        if (alive()) this.fail(want.src, error);
        return false;
      }
    }
    if (want.rules !== this.loadedRules) {
      this.loadedRules = want.rules;
      try {
        viewer.setSchemeOptions(want.rules ? { rules: await fetchRuleSet(want.rules, document.baseURI) } : {});
      } catch (error) {
        if (alive()) this.fail(want.rules, error);
        return false;
      }
      if (!alive()) return false;
    }
    if (want.scheme === 'custom' && !want.rules) {
      this.fail('scheme', new AttributeError('scheme="custom" needs a rules attribute: the URL of a rule-set JSON.'));
      return false;
    }
    if (viewer.state.triangulate !== want.triangulate) viewer.setTriangulate(want.triangulate);
    viewer.setScheme(want.scheme);
    return viewer.state.levelCount > 0;
  }

  /** Computes the levels up to the one asked and shows it (or the highest reached). */
  private async syncLevels(viewer: SubdivViewer, want: EmbedState): Promise<void> {
    try {
      while (viewer.state.levelCount - 1 < want.levels && !this.syncAgain && !this.passCancelled) {
        const stepped = await viewer.subdivide();
        if (this.viewer !== viewer) return;
        if (!stepped) break;
      }
    } catch (error) {
      if (this.viewer !== viewer) return;
      this.fail(viewer.state.modelName ?? 'mesh', error);
    }
    viewer.setLevel(want.levels);
  }

  /** Reports each attribute problem once (until the attribute changes), as an `error` event and the message. */
  private reportProblems(problems: EmbedState['problems']): void {
    const now = new Set(problems.map((p) => `${p.attribute}\n${p.message}`));
    for (const problem of problems) {
      const key = `${problem.attribute}\n${problem.message}`;
      if (!this.reportedProblems.has(key)) this.fail(problem.attribute, new AttributeError(problem.message));
    }
    this.reportedProblems = now;
  }

  /** Applies what changes nothing in the levels: display, overlays, camera, controls, labels, colours. */
  private applyDisplay(applyView = false): void {
    const want = this.readState();
    this.controlBar.setMode(want.controls);
    const viewer = this.viewer;
    const label = want.alt || this.describe();
    this.stage.setAttribute('aria-label', label);
    if (!viewer) return;
    this.reportProblems(want.problems);
    if (!want.src && viewer.state.levelCount === 0) this.placeholder.textContent = 'No model: set the src attribute.';
    if (viewer.state.renderMode !== want.renderMode) viewer.setRenderMode(want.renderMode);
    for (const name of ['control', 'curves', 'bbox'] as OverlayName[]) {
      if (viewer.state.overlays[name] !== want.overlays[name]) viewer.setOverlay(name, want.overlays[name]);
    }
    const background = want.background ?? (this.darkQuery.matches ? '#1f2328' : null);
    viewer.view.setBackground(background === 'transparent' ? null : (background ?? '#f3f4f6'));
    if (applyView && want.view && viewer.state.levelCount > 0) viewer.setView(want.view);
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
    this.placeholder.hidden = state.levelCount > 0 || !this.message.hidden;
    const busy = state.busy !== null || this.download !== null;
    const kind = state.busy?.kind ?? (this.download ? 'load' : null);
    const label = state.busy?.label ?? (this.download ? `Downloading ${this.download.name}…` : '');
    this.busyBox.hidden = !busy;
    this.busyLabel.textContent = label;
    if (!this.getAttribute('alt')) this.stage.setAttribute('aria-label', this.describe());
    const prev = this.last;
    this.last = { level: state.level, facts: state.facts, busy, scheme: state.scheme };
    if (!prev || prev.busy !== busy) {
      this.dispatch('progress', { busy, kind, label } as ProgressDetail);
    }
    const changed = !prev || prev.level !== state.level || prev.facts !== state.facts || prev.scheme !== state.scheme;
    if (state.facts && changed) {
      this.status.textContent = `Level ${state.level}: ${faceTypes(state.facts)}, genus ${state.facts.genus}`;
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
    const toggles: Record<OverlayName, string> = { control: 'control-mesh', curves: 'control-edges', bbox: 'bbox' };
    installShortcuts(
      this,
      {
        subdivide: () => void this.stepLevel(1),
        stepLevel: (delta) => void this.stepLevel(delta),
        cycleRenderMode: () => {
          this.renderMode = nextRenderMode(this.renderMode);
        },
        toggleOverlay: (name) => this.setFlag(toggles[name], !this.readState().overlays[name]),
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
    this.passFailures++;
    const detail = errorDetail(source, error);
    const { line, message } = detail;
    this.message.textContent = `${detail.source}: ${line > 0 && !/\bline \d/.test(message) ? `line ${line}: ` : ''}${message}`;
    this.message.hidden = false;
    this.placeholder.hidden = true;
    this.dispatch('error', detail);
  }

  private hideMessage(): void {
    this.message.hidden = true;
  }

  private dispatch(type: string, detail: unknown): void {
    this.dispatchEvent(new CustomEvent(type, { detail, bubbles: true, composed: true }));
  }
}
