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
import { CancelledError } from '../core/worker-client';
import { nextRenderMode, type OverlayName } from '../render/render-mode';
import type { ViewState } from '../render/view-state';
import { el } from '../ui/dom';
import { faceTypes } from '../ui/facts-panel';
import { installShortcuts } from '../ui/shortcuts';
import { handleViewKey } from '../ui/view-keys';
import { fetchMesh, meshText, readFile } from '../viewer/mesh-source';
import { fetchRuleSet } from '../viewer/rules-source';
import { schemeInfo } from '../viewer/scheme-info';
import { SubdivViewer, type ViewerState } from '../viewer/subdiv-viewer';
import { EmbedControls } from './embed-controls';
import {
  AttributeError,
  errorDetail,
  type LevelChangeDetail,
  type LoadDetail,
  type ProgressDetail,
} from './embed-events';
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
  private syncing: Promise<void> | null = null;
  private syncAgain = false;
  /** Set while the element writes its own attributes (the level it shows), so they do not trigger a sync. */
  private reflecting = false;
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
    cancel.addEventListener('click', () => this.viewer?.cancel());
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
      this.viewer?.dispose();
      this.viewer = null;
      this.loadedSrc = null;
      this.loadedRules = '';
      this.last = null;
    });
  }

  attributeChangedCallback(name: string, oldValue: string | null, value: string | null): void {
    if (oldValue === value || this.reflecting) return;
    if (DISPLAY_ATTRIBUTES.has(name)) this.applyDisplay(name === 'view');
    else void this.sync();
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

  /** Computes one more level and shows it; resolves with the level shown. */
  async subdivide(): Promise<number> {
    return this.setLevel(this.levelCountOrZero());
  }

  /** Shows level `n`, computing the levels up to it as needed; resolves with the level shown. */
  async setLevel(n: number): Promise<number> {
    // Setting the attribute starts the pass (when it changed); wait for that one, not another after it.
    this.levels = Math.max(0, Math.round(n));
    await (this.syncing ?? this.sync());
    return this.level;
  }

  /** Shows a mesh from a File, or from OFF/OBJ text named `name`; the `src` attribute no longer applies. */
  async load(input: File | string, name = 'mesh.off'): Promise<void> {
    const viewer = this.start();
    const fileName = input instanceof File ? input.name : name;
    try {
      const mesh = input instanceof File ? await readFile(input) : meshText(name, input);
      await viewer.loadText(mesh.text, mesh.format, mesh.name);
      this.loadedSrc = this.src;
      this.hideMessage();
      this.dispatch('load', { modelName: mesh.name, facts: viewer.state.facts } as LoadDetail);
      await this.sync();
    } catch (error) {
      this.fail(fileName, error);
      throw error;
    }
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

  setView(view: ViewState): void {
    this.start().setView(view);
  }

  /** Stops this viewer's running step (other viewers' work goes on). */
  cancel(): void {
    this.viewer?.cancel();
  }

  // --- Inside ------------------------------------------------------------------------------

  private start(): SubdivViewer {
    if (this.viewer) return this.viewer;
    this.startObserver?.disconnect();
    this.startObserver = null;
    const initial = this.readState();
    const viewer = new SubdivViewer(this.stage, { scheme: initial.scheme, renderMode: initial.renderMode });
    this.viewer = viewer;
    viewer.onChange((state) => this.onState(state));
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

  private levelCountOrZero(): number {
    const state = this.viewer?.state;
    return state && state.levelCount > 0 ? state.level + 1 : 0;
  }

  private async stepLevel(delta: number): Promise<void> {
    const level = this.level;
    if (level < 0) return;
    await this.setLevel(level + delta);
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
    for (const problem of want.problems) this.fail(problem.attribute, new AttributeError(problem.message));
    if (want.src && want.src !== this.loadedSrc) {
      this.loadedSrc = want.src;
      try {
        const mesh = await fetchMesh(want.src, document.baseURI);
        await viewer.loadText(mesh.text, mesh.format, mesh.name);
        this.hideMessage();
        this.placeholder.hidden = true;
        this.applyDisplay(true);
        this.dispatch('load', { modelName: mesh.name, facts: viewer.state.facts } as LoadDetail);
      } catch (error) {
        this.fail(want.src, error);
        return;
      }
    }
    if (want.rules !== this.loadedRules) {
      this.loadedRules = want.rules;
      if (want.rules) {
        try {
          viewer.setSchemeOptions({ rules: await fetchRuleSet(want.rules, document.baseURI) });
        } catch (error) {
          this.fail(want.rules, error);
          return;
        }
      } else {
        viewer.setSchemeOptions({});
      }
    }
    if (want.scheme === 'custom' && !want.rules) {
      this.fail('scheme', new AttributeError('scheme="custom" needs a rules attribute: the URL of a rule-set JSON.'));
      return;
    }
    if (viewer.state.triangulate !== want.triangulate) viewer.setTriangulate(want.triangulate);
    viewer.setScheme(want.scheme);
    if (viewer.state.levelCount === 0) return;
    try {
      while (viewer.state.levelCount - 1 < want.levels) {
        if (!(await viewer.subdivide())) break;
      }
    } catch (error) {
      this.fail(viewer.state.modelName ?? 'mesh', error);
    }
    viewer.setLevel(want.levels);
    this.reflectLevel();
  }

  /** Writes the shown level back to `levels` (it is what the element shows now). */
  private reflectLevel(): void {
    const level = this.level;
    if (level < 0 || String(level) === this.getAttribute('levels')) return;
    if (this.syncAgain) return;
    this.reflecting = true;
    this.setAttribute('levels', String(level));
    this.reflecting = false;
  }

  /** Applies what changes nothing in the levels: display, overlays, camera, controls, labels, colours. */
  private applyDisplay(applyView = false): void {
    const want = this.readState();
    this.controlBar.setMode(want.controls);
    const viewer = this.viewer;
    const label = want.alt || this.describe();
    this.stage.setAttribute('aria-label', label);
    if (!viewer) return;
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
    const busy = state.busy !== null;
    this.busyBox.hidden = !busy;
    this.busyLabel.textContent = state.busy?.label ?? '';
    if (!this.getAttribute('alt')) this.stage.setAttribute('aria-label', this.describe());
    const prev = this.last;
    this.last = { level: state.level, facts: state.facts, busy, scheme: state.scheme };
    if (!prev || prev.busy !== busy) {
      this.dispatch('progress', {
        busy,
        kind: state.busy?.kind ?? null,
        label: state.busy?.label ?? '',
      } as ProgressDetail);
    }
    if (state.facts && (!prev || prev.level !== state.level || prev.facts !== state.facts)) {
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
        cancel: () => this.viewer?.cancel(),
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
