/**
 * The SubdivLab page: one SubdivViewer composed with the panels (samples,
 * scheme, custom rules, levels, display, facts, export), the drop zone, the
 * error banner, the progress overlay and the keyboard shortcuts. Every failure ends in
 * {@link AppShell.showError}, the one place errors are shown.
 */
import type { RuleSet } from '../core/rule-set';
import { SubdivError } from '../core/subdiv-error';
import { CancelledError } from '../core/worker-client';
import { nextRenderMode } from '../render/render-mode';
import { parseViewState, type ViewState } from '../render/view-state';
import { ConfirmDialog } from '../ui/confirm-dialog';
import { DisplayPanel, overlayAvailable } from '../ui/display-panel';
import { button, el } from '../ui/dom';
import { DropZone } from '../ui/drop-zone';
import { ErrorBanner } from '../ui/error-banner';
import { ExportPanel } from '../ui/export-panel';
import { FactsPanel } from '../ui/facts-panel';
import { createGallery } from '../ui/gallery';
import { LevelPanel } from '../ui/level-panel';
import { ProgressOverlay } from '../ui/progress-overlay';
import { RulesPanel } from '../ui/rules-panel';
import { saveBlob } from '../ui/save-blob';
import { SchemePanel } from '../ui/scheme-panel';
import { installShortcuts, SHORTCUTS } from '../ui/shortcuts';
import { exportFileName } from '../viewer/file-names';
import { formatBytes } from '../viewer/memory-budget';
import { fetchMesh, LoadError, type MeshText, readFile } from '../viewer/mesh-source';
import { checkRulesInCore } from '../viewer/rules-check';
import { hostLabel, hostNeedsTriangles, schemeInfo } from '../viewer/scheme-info';
import { type LargeStepInfo, type SchemeOptions, SubdivViewer, type ViewerState } from '../viewer/subdiv-viewer';
import { SAMPLES } from './samples';
import type { SubdivLabTestApi, TestError } from './test-api';

const VIEW_STORAGE_KEY = 'subdivlab.view';

export class AppShell {
  readonly viewer: SubdivViewer;
  private readonly errors = new ErrorBanner();
  private readonly confirm = new ConfirmDialog();
  private readonly progress: ProgressOverlay;
  private readonly scheme: SchemePanel;
  private readonly rules: RulesPanel;
  private readonly levels: LevelPanel;
  private readonly display: DisplayPanel;
  private readonly facts = new FactsPanel();
  private readonly exports: ExportPanel;
  private readonly modelName: HTMLElement;
  private readonly emptyHint: HTMLElement;
  private readonly fileInput: HTMLInputElement;
  private lastError: TestError | null = null;
  private schemes: string[] = [];
  /** Rules of the custom scheme (from the rules panel) and quad-triangle's border option. */
  private customRules: RuleSet | null = null;
  private fixedBoundary = false;

  constructor(root: HTMLElement) {
    this.fileInput = el('input', {
      testId: 'open.input',
      attrs: { type: 'file', accept: '.off,.obj,text/plain', 'aria-label': 'Open a mesh file' },
    });
    // The Open… button is the visible, focusable control; the input only opens the picker.
    this.fileInput.hidden = true;
    this.fileInput.addEventListener('change', () => {
      const file = this.fileInput.files?.[0];
      this.fileInput.value = '';
      if (file) void this.openFile(file);
    });
    const stage = el('div', {
      testId: 'viewer',
      className: 'viewer',
      attrs: {
        role: 'region',
        tabindex: '0',
        'aria-label': '3D view: drag or arrow keys rotate, right-drag or Shift+arrows pan, wheel or +/− zoom',
      },
    });
    stage.addEventListener('keydown', (event) => this.onViewKey(event));
    this.emptyHint = el(
      'div',
      { testId: 'viewer.empty', className: 'empty-hint' },
      el('p', { text: 'Drop an OFF or OBJ file anywhere, open one, or pick a sample.' }),
    );
    this.viewer = new SubdivViewer(stage, { confirmLargeStep: (info) => this.confirmLargeStep(info) });
    this.progress = new ProgressOverlay(() => this.viewer.cancel());
    stage.append(this.emptyHint, this.facts.element, this.progress.element);

    this.scheme = new SchemePanel({
      onScheme: (s) => {
        this.viewer.setScheme(s);
        this.viewer.setSchemeOptions(this.schemeOptions());
        if (s === 'custom') void this.rules.ensureRules();
      },
      onTriangulate: (t) => this.viewer.setTriangulate(t),
      onFixedBoundary: (fixed) => {
        this.fixedBoundary = fixed;
        void this.recompute(0);
      },
    });
    this.rules = new RulesPanel({
      check: (rules) => checkRulesInCore(this.viewer.core, rules),
      apply: (rules, minLevel) => {
        this.customRules = rules;
        return this.recompute(minLevel);
      },
    });
    this.levels = new LevelPanel({
      onSubdivide: () => void this.subdivide(),
      onReset: () => this.viewer.reset(),
      onLevel: (k) => this.viewer.setLevel(k),
    });
    this.display = new DisplayPanel({
      onRenderMode: (m) => this.viewer.setRenderMode(m),
      onOverlay: (name, on) => this.viewer.setOverlay(name, on),
      onFit: () => this.viewer.fitView(),
      onSaveView: () => this.saveView(),
      onRestoreView: () => this.restoreView(),
    });
    this.exports = new ExportPanel({
      onPng: (scale, transparent) => void this.exportPng(scale, transparent),
      onCopy: (transparent) => void this.copyImage(transparent),
      onSvg: (transparent) => this.exportSvg(transparent),
      onMesh: (format) => void this.exportMesh(format),
    });

    this.modelName = el('span', { testId: 'app.model-name', className: 'model-name', text: 'No model loaded' });
    const header = el(
      'header',
      { className: 'app-header' },
      el('h1', { text: 'SubdivLab' }),
      button('Open…', 'open.button', () => this.fileInput.click(), 'Open an OFF or OBJ file (O)'),
      this.fileInput,
      createGallery(SAMPLES, (sample) => void this.openUrl(sample.path, sample.path.split('/').pop() ?? sample.id)),
      this.exports.element,
      this.modelName,
    );

    const help = el(
      'details',
      { className: 'panel shortcuts', testId: 'help' },
      el('summary', { text: 'Keyboard shortcuts' }),
      el(
        'dl',
        {},
        ...SHORTCUTS.flatMap(({ keys, action }) => [
          el('dt', {}, el('kbd', { text: keys })),
          el('dd', { text: action }),
        ]),
      ),
    );
    const sidebar = el(
      'aside',
      { className: 'sidebar', attrs: { 'aria-label': 'Controls' } },
      this.scheme.element,
      this.rules.element,
      this.levels.element,
      this.display.element,
      help,
    );
    const main = el('main', { className: 'app-main' }, this.errors.element, stage);
    const dropZone = new DropZone(document, (file) => void this.openFile(file));
    root.replaceChildren(
      header,
      el('div', { className: 'app-body' }, sidebar, main),
      dropZone.element,
      this.confirm.element,
    );

    this.viewer.onChange((state) => this.update(state));
    this.update(this.viewer.state);
    installShortcuts(
      document,
      {
        subdivide: () => void this.subdivide(),
        cycleRenderMode: () => this.viewer.setRenderMode(nextRenderMode(this.viewer.state.renderMode)),
        toggleOverlay: (name) => {
          // As the disabled checkbox: a key may switch an unavailable overlay off, never on.
          const state = this.viewer.state;
          const on = !state.overlays[name];
          if (!on || overlayAvailable(name, state)) this.viewer.setOverlay(name, on);
        },
        fit: () => this.viewer.fitView(),
        stepLevel: (delta) => this.viewer.setLevel(this.viewer.state.level + delta),
        open: () => this.fileInput.click(),
        cancel: () => this.viewer.cancel(),
        copyImage: () => void this.copyImage(false),
      },
      () => this.confirm.open,
    );

    this.viewer
      .schemes()
      .then((all) => {
        this.schemes = all;
        this.scheme.setSchemes(all, this.viewer.state.scheme);
        this.update(this.viewer.state);
      })
      .catch((error: unknown) => this.showError('SubdivLab core', error));
  }

  /** The typed test API (window.__subdivlab). */
  testApi(): SubdivLabTestApi {
    return {
      state: () => {
        const s = this.viewer.state;
        return {
          ready: this.schemes.length > 0,
          schemes: [...this.schemes],
          modelName: s.modelName,
          scheme: s.scheme,
          triangulate: s.triangulate,
          level: s.level,
          levelCount: s.levelCount,
          facts: s.facts,
          renderMode: s.renderMode,
          overlays: s.overlays,
          busy: s.busy !== null,
          lastError: this.lastError,
          view: this.viewer.getView(),
          fov: this.viewer.view.camera.fov,
          aspect: this.viewer.view.camera.aspect,
          gpuGeometries: this.viewer.view.gpuMemory().geometries,
          edgeSegments: this.viewer.view.edgeSegments(),
          customRules: this.customRules,
          smoothBoundary: !this.fixedBoundary,
        };
      },
      positions: () => Array.from(this.viewer.mesh?.positions ?? []),
      setMemoryBudget: (bytes) => this.viewer.setMemoryBudget(bytes),
    };
  }

  /** Loads `?src=URL` if the page has one. */
  async loadFromQuery(search: string): Promise<void> {
    const src = new URLSearchParams(search).get('src');
    if (src) await this.openUrl(src, src);
  }

  async openFile(file: File): Promise<void> {
    await this.openText(file.name, () => readFile(file));
  }

  async openUrl(src: string, displayName: string): Promise<void> {
    await this.openText(displayName, () => fetchMesh(src, document.baseURI));
  }

  /** Shows the error about `source`; the previous model and its levels stay. */
  showError(source: string, error: unknown, retryWithTriangulation = false): void {
    if (error instanceof CancelledError) return;
    const message = messageOf(error);
    const where = error instanceof LoadError ? error.source : source;
    this.lastError = {
      source: where,
      message,
      code: error instanceof SubdivError ? error.code : error instanceof LoadError ? 'load_error' : 'error',
    };
    const action =
      retryWithTriangulation && error instanceof SubdivError && error.code === 'not_triangles'
        ? {
            label: 'Triangulate and subdivide',
            run: () => {
              this.viewer.setTriangulate(true);
              void this.subdivide();
            },
          }
        : undefined;
    this.errors.show(where, message, action);
  }

  private async openText(name: string, read: () => Promise<MeshText>): Promise<void> {
    try {
      const mesh = await read();
      await this.viewer.loadText(mesh.text, mesh.format, mesh.name);
      this.errors.hide();
      this.lastError = null;
    } catch (error) {
      this.showError(name, error);
    }
  }

  private async subdivide(): Promise<boolean> {
    const state = this.viewer.state;
    if (state.levelCount === 0) return false;
    try {
      // The custom scheme steps with the panel's rules: wait for the first preset.
      if (state.scheme === 'custom' && !this.customRules) await this.rules.ensureRules();
      return await this.viewer.subdivide();
    } catch (error) {
      this.showError(state.modelName ?? 'mesh', error, true);
      return false;
    }
  }

  /** Options of every step besides scheme and level: the custom rules, quad-triangle's border. */
  private schemeOptions(): SchemeOptions {
    const scheme = this.viewer.state.scheme;
    if (scheme === 'custom') return this.customRules ? { rules: this.customRules } : {};
    if (scheme === 'quad-triangle') return { smoothBoundary: !this.fixedBoundary };
    return {};
  }

  /**
   * Hands the options to the viewer (which drops the levels computed with
   * others) and computes again up to the shown level, or `minLevel` if higher.
   */
  private async recompute(minLevel: number): Promise<void> {
    const target = Math.max(minLevel, this.viewer.state.level);
    this.viewer.setSchemeOptions(this.schemeOptions());
    while (this.viewer.state.levelCount > 0 && this.viewer.state.level < target) {
      if (!(await this.subdivide())) return;
    }
  }

  /** Camera keys while the view has focus: arrows rotate, Shift+arrows pan, +/− zoom. */
  private onViewKey(event: KeyboardEvent): void {
    if (event.ctrlKey || event.metaKey || event.altKey) return;
    const view = this.viewer.view;
    const step = 10;
    const moves: Record<string, () => void> = event.shiftKey
      ? {
          ArrowLeft: () => view.pan(0.05, 0),
          ArrowRight: () => view.pan(-0.05, 0),
          ArrowUp: () => view.pan(0, -0.05),
          ArrowDown: () => view.pan(0, 0.05),
        }
      : {
          ArrowLeft: () => view.orbit(-step, 0),
          ArrowRight: () => view.orbit(step, 0),
          ArrowUp: () => view.orbit(0, -step),
          ArrowDown: () => view.orbit(0, step),
        };
    const zooms: Record<string, number> = { '+': 1 / 1.2, '=': 1 / 1.2, '-': 1.2, _: 1.2 };
    const move = moves[event.key] ?? (event.key in zooms ? () => view.zoom(zooms[event.key]) : undefined);
    if (!move) return;
    event.preventDefault();
    move();
  }

  private confirmLargeStep(info: LargeStepInfo): Promise<boolean> {
    const p = info.prediction;
    const label = schemeInfo(this.viewer.state.scheme).label;
    return this.confirm.ask(
      `Level ${info.level} is large`,
      `${label} level ${info.level} would have ${p.vertices.toLocaleString('en')} vertices and ` +
        `${p.faces.toLocaleString('en')} faces and needs about ${formatBytes(info.estimatedBytes)}; ` +
        `this tab can probably give ${formatBytes(info.budgetBytes)}. The step may fail or make the page slow.`,
      'Subdivide anyway',
    );
  }

  private saveView(): void {
    localStorage.setItem(VIEW_STORAGE_KEY, JSON.stringify(this.viewer.getView()));
    this.update(this.viewer.state);
  }

  private savedView(): ViewState | null {
    return parseViewState(localStorage.getItem(VIEW_STORAGE_KEY));
  }

  private restoreView(): void {
    const view = this.savedView();
    if (view) this.viewer.setView(view);
  }

  private fileName(extension: string): string {
    const s = this.viewer.state;
    return exportFileName(s.modelName, s.scheme, s.level, extension);
  }

  private async exportPng(scale: number, transparent: boolean): Promise<void> {
    try {
      saveBlob(await this.viewer.exportPng(scale, transparent), this.fileName('png'));
    } catch (error) {
      this.showError(this.fileName('png'), error);
    }
  }

  private async copyImage(transparent: boolean): Promise<void> {
    if (this.viewer.state.levelCount === 0) return;
    try {
      // Hand the promise to ClipboardItem at once: Safari needs the user gesture to be current.
      const png = this.viewer.exportPng(1, transparent);
      await navigator.clipboard.write([new ClipboardItem({ 'image/png': png })]);
    } catch (error) {
      this.showError('Clipboard', error);
    }
  }

  private exportSvg(transparent: boolean): void {
    try {
      const svg = this.viewer.exportSvg(transparent);
      saveBlob(new Blob([svg], { type: 'image/svg+xml' }), this.fileName('svg'));
    } catch (error) {
      this.showError(this.fileName('svg'), error);
    }
  }

  private async exportMesh(format: 'off' | 'obj'): Promise<void> {
    try {
      const text = await this.viewer.exportMesh(format);
      saveBlob(new Blob([text], { type: 'text/plain' }), this.fileName(format));
    } catch (error) {
      this.showError(this.fileName(format), error);
    }
  }

  private update(state: ViewerState): void {
    this.modelName.textContent = state.modelName ?? 'No model loaded';
    this.emptyHint.hidden = state.levelCount > 0;
    const rules = state.scheme === 'custom' ? this.customRules : null;
    this.scheme.update(state, {
      needsTriangles: rules ? hostNeedsTriangles(rules.host) : undefined,
      needsTrianglesWho: rules ? `The ${hostLabel(rules.host)} host` : undefined,
      fixedBoundary: this.fixedBoundary,
    });
    this.rules.element.hidden = state.scheme !== 'custom';
    this.levels.update(state);
    this.display.update(state, this.savedView() !== null);
    this.facts.update(state);
    this.exports.update(state);
    this.progress.update(state.busy);
  }
}

/** The user-facing sentence of an error; the core's line number is added when the message lacks it. */
export function messageOf(error: unknown): string {
  if (error instanceof SubdivError) {
    const hasLine = error.line > 0 && !/\bline\s+\d/i.test(error.message);
    return hasLine ? `line ${error.line}: ${error.message}` : error.message;
  }
  if (error instanceof Error) return error.message;
  return String(error);
}
