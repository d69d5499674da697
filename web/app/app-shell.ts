/**
 * The SubdivLab page: one SubdivViewer composed with the panels (samples,
 * scheme, custom rules, levels, display, facts, export, share and embed), the
 * drop zone, the error banner, the progress overlay and the keyboard
 * shortcuts; its state lives in the URL hash (url-state.ts). Every failure
 * ends in {@link AppShell.showError}, the one place errors are shown.
 */
import type { ReadOptions, SchemeName } from '../core/mesh';
import type { RuleSet } from '../core/rule-set';
import { SubdivError } from '../core/subdiv-error';
import { CancelledError, CoreCrashedError } from '../core/worker-client';
import { projectPoints } from '../render/fit';
import { nextRenderMode } from '../render/render-mode';
import { ConfirmDialog } from '../ui/confirm-dialog';
import { DisplayPanel, overlayAvailable } from '../ui/display-panel';
import { button, el } from '../ui/dom';
import { DropZone } from '../ui/drop-zone';
import { EmbedDialog } from '../ui/embed-dialog';
import { type ErrorAction, ErrorBanner } from '../ui/error-banner';
import { ExportPanel } from '../ui/export-panel';
import { FactsPanel } from '../ui/facts-panel';
import { createGallery } from '../ui/gallery';
import { LevelPanel } from '../ui/level-panel';
import { NoticeBar } from '../ui/notice-bar';
import { ProgressOverlay } from '../ui/progress-overlay';
import { RulesPanel } from '../ui/rules-panel';
import { SchemePanel } from '../ui/scheme-panel';
import { SharePanel } from '../ui/share-panel';
import { installShortcuts, shortcutsHelp } from '../ui/shortcuts';
import { skipLinks } from '../ui/skip-links';
import { handleViewKey } from '../ui/view-keys';
import { messageOf } from '../viewer/error-message';
import { formatBytes } from '../viewer/memory-budget';
import { fetchMesh, LoadError, type MeshText, readFile } from '../viewer/mesh-source';
import { checkRulesInCore } from '../viewer/rules-check';
import { hostLabel, hostNeedsTriangles, schemeInfo } from '../viewer/scheme-info';
import {
  type LargeStepInfo,
  type SchemeOptions,
  type StepSettings,
  SubdivViewer,
  type ViewerState,
} from '../viewer/subdiv-viewer';
import { AppTools } from './app-tools';
import { cancelMessage } from './cancel-message';
import { ExportActions } from './export-actions';
import { FirstLook } from './first-look';
import { SAMPLES } from './samples';
import { type ModelSource, ShareActions } from './share-actions';
import type { SubdivLabTestApi, TestError } from './test-api';
import { FIRST_VISIT, UrlState } from './url-state';
import { ViewActions } from './view-actions';

export class AppShell {
  readonly viewer: SubdivViewer;
  private readonly errors = new ErrorBanner();
  private readonly notice = new NoticeBar();
  private readonly confirm = new ConfirmDialog();
  private readonly embedDialog = new EmbedDialog();
  private readonly sharePanel: SharePanel;
  private readonly shareActions: ShareActions;
  private readonly urlState: UrlState;
  private readonly progress: ProgressOverlay;
  private readonly scheme: SchemePanel;
  private readonly rules: RulesPanel;
  private readonly levels: LevelPanel;
  private readonly display: DisplayPanel;
  private readonly views: ViewActions;
  /** The notice says what a Cancel did: hidden when the next step or load starts. */
  private cancelNotice = false;
  private readonly tools: AppTools;
  private readonly facts = new FactsPanel();
  private readonly exports: ExportPanel;
  private readonly exportActions: ExportActions;
  private readonly modelName: HTMLElement;
  private readonly emptyHint: HTMLElement;
  private readonly firstVisitHint: HTMLElement;
  private readonly fileInput: HTMLInputElement;
  private lastError: TestError | null = null;
  /** What the shown error is about: a step's goes once a later step succeeds. */
  private errorKind: 'step' | 'other' | null = null;
  /** The scheme being switched to, shown in the menu while its levels are computed. */
  private pendingScheme: SchemeName | null = null;
  private schemes: string[] = [];
  /** Rules of the custom scheme (from the rules panel) and quad-triangle's border option. */
  private customRules: RuleSet | null = null;
  private fixedBoundary = false;
  /** The notice shows the tags of the shown model that the core does not apply. */
  private tagNotice = false;
  /** Where the shown model came from (null before the first load). */
  private source: ModelSource | null = null;
  /** The first visit's edges and cage, until chosen: a model opened next gets the look that suits it. */
  private readonly firstLook = new FirstLook();

  constructor(root: HTMLElement) {
    this.fileInput = el('input', {
      testId: 'open.input',
      attrs: { type: 'file', accept: '.off,.obj,.ply,.stl,text/plain', 'aria-label': 'Open a mesh file' },
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
        id: 'subdivlab-view',
        role: 'region',
        tabindex: '0',
        'aria-label': '3D view: drag or arrow keys rotate, right-drag or Shift+arrows pan, wheel or +/− zoom',
      },
    });
    stage.addEventListener('keydown', (event) => handleViewKey(this.viewer.view, event));
    this.emptyHint = el(
      'div',
      { testId: 'viewer.empty', className: 'empty-hint' },
      el('p', { text: 'Drop an OFF, OBJ, PLY or STL file anywhere, open one, or pick a sample.' }),
    );
    this.firstVisitHint = el('p', {
      testId: 'viewer.first-visit',
      className: 'first-visit-hint',
      text: 'A sample to start with: drop your own OFF, OBJ, PLY or STL file anywhere (or use Open…).',
    });
    this.firstVisitHint.hidden = true;
    this.viewer = new SubdivViewer(stage, { confirmLargeStep: (info) => this.confirmLargeStep(info) });
    // A crash is said here once, whichever request was running (showError passes over its rejection).
    // It goes, as a step's error does, once a later step succeeds.
    this.viewer.core.client.onCrash((error) =>
      this.displayError('SubdivLab core', new SubdivError(error.code, error.summary), undefined, 'step'),
    );
    this.progress = new ProgressOverlay(() => this.cancel());
    this.exportActions = new ExportActions(
      this.viewer,
      (source, error) => this.showError(source, error),
      () => this.tools.sideBySide.viewers(),
      (text) => this.notice.show(text),
    );
    stage.append(this.emptyHint, this.firstVisitHint, this.facts.element, this.progress.element);

    this.scheme = new SchemePanel({
      onScheme: (s) => void this.switchScheme(s),
      onTriangulate: (t) => void this.changeSteps({ triangulate: t }),
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
      onReset: () => {
        this.viewer.reset();
        this.stepSucceeded();
      },
      onLevel: (k) => this.viewer.setLevel(k),
    });
    this.tools = new AppTools({
      viewer: this.viewer,
      stage,
      modelError: (error) => this.modelError(error),
      reachLevel: (level) => this.reachLevel(level),
      confirmLargeStep: (info, scheme) => this.confirmLargeStep(info, scheme),
    });
    this.views = new ViewActions(this.viewer, (view) => this.tools.sideBySide.fit(view));
    this.display = new DisplayPanel(
      {
        onRenderMode: (m) => {
          this.firstLook.chose('renderMode');
          this.viewer.setRenderMode(m);
        },
        onOverlay: (name, on) => {
          if (name === 'control') this.firstLook.chose('control');
          this.viewer.setOverlay(name, on);
        },
      },
      this.views.controls.element,
    );
    this.exports = new ExportPanel({
      onPng: (scale, transparent) => void this.exportActions.png(scale, transparent),
      onCopy: (transparent) => void this.exportActions.copyImage(transparent),
      onFigure: (format, transparent) => this.exportActions.figure(format, transparent),
      onMesh: (format) => void this.exportActions.mesh(format),
    });

    this.urlState = new UrlState({
      viewer: this.viewer,
      modelSrc: () => (this.source?.kind === 'url' ? this.source.src : null),
      openUrl: (src) => this.openUrl(src, src),
      setScheme: (scheme) => this.setScheme(scheme),
      subdivide: () => this.subdivide(),
      beside: () => this.tools.sideBySide.beside(),
      setBeside: (schemes) => this.tools.sideBySide.setBeside(schemes),
      onBesideChange: (listener) => {
        let last = '';
        this.tools.sideBySide.onChange(() => {
          const now = this.tools.sideBySide.beside().join(',');
          if (now !== last) listener();
          last = now;
        });
      },
      linkProblems: (problems) =>
        this.notice.show(problems.length > 0 ? `Parts of this link were ignored: ${problems.join(' ')}` : ''),
    });
    this.sharePanel = new SharePanel({
      onShare: () => void this.shareActions.share(),
      onEmbed: () => this.shareActions.embed(),
    });
    this.shareActions = new ShareActions(
      { viewer: this.viewer, modelSource: () => this.source, params: () => this.urlState.params() },
      this.sharePanel,
      this.embedDialog,
    );

    this.modelName = el('span', { testId: 'app.model-name', className: 'model-name', text: 'No model loaded' });
    const header = el(
      'header',
      { className: 'app-header' },
      el('h1', { text: 'SubdivLab' }),
      button('Open…', 'open.button', () => this.fileInput.click(), 'Open an OFF, OBJ, PLY or STL file (O)'),
      this.fileInput,
      createGallery(SAMPLES, (sample) => void this.openUrl(sample.path, sample.path.split('/').pop() ?? sample.id)),
      this.exports.element,
      this.sharePanel.element,
      this.modelName,
      el('a', {
        testId: 'app.examples',
        className: 'header-link',
        text: 'Teaching examples',
        attrs: { href: 'examples/', title: 'Pages that embed SubdivLab views, to copy from' },
      }),
    );

    // What a student needs first (scheme, levels, then how the model is shown) before the teaching tools.
    const toolGroup = el(
      'section',
      { testId: 'tools', className: 'tool-group', attrs: { 'aria-labelledby': 'tools-heading' } },
      el('h2', { text: 'Teaching tools', attrs: { id: 'tools-heading' } }),
      this.rules.element,
      ...this.tools.panels,
    );
    const sidebar = el(
      'aside',
      {
        testId: 'controls',
        className: 'sidebar',
        attrs: { id: 'subdivlab-controls', 'aria-label': 'Controls', tabindex: '-1' },
      },
      this.scheme.element,
      this.levels.element,
      this.display.element,
      toolGroup,
      shortcutsHelp(),
    );
    const main = el(
      'main',
      { className: 'app-main' },
      this.errors.element,
      this.notice.element,
      this.tools.paneGrid.element,
    );
    const dropZone = new DropZone(document, (file) => void this.openFile(file));
    root.replaceChildren(
      skipLinks([
        { label: 'Skip to the view', testId: 'skip.view', target: stage },
        { label: 'Skip to the controls', testId: 'skip.controls', target: sidebar },
      ]),
      header,
      el('div', { className: 'app-body' }, sidebar, main),
      dropZone.element,
      this.confirm.element,
      this.embedDialog.element,
    );

    this.viewer.onChange((state) => this.update(state));
    this.update(this.viewer.state);
    installShortcuts(
      document,
      {
        subdivide: () => void this.subdivide(),
        cycleRenderMode: () => {
          this.firstLook.chose('renderMode');
          this.viewer.setRenderMode(nextRenderMode(this.viewer.state.renderMode));
        },
        toggleOverlay: (name) => {
          // As the disabled checkbox: a key may switch an unavailable overlay off, never on.
          const state = this.viewer.state;
          const on = !state.overlays[name];
          if (name === 'control') this.firstLook.chose('control');
          if (!on || overlayAvailable(name, state)) this.viewer.setOverlay(name, on);
        },
        fit: () => this.views.fit(),
        nextView: () => this.views.nextCanonical(),
        stepLevel: (delta) => this.viewer.setLevel(this.viewer.state.level + delta),
        open: () => this.fileInput.click(),
        cancel: () => this.cancel(),
        copyImage: () => void this.exportActions.copyImage(false),
        toggleInspector: () => this.tools.setClickMode(this.tools.inspector.state.inspecting ? null : 'inspect'),
        creases: {
          toggleEditing: () => this.tools.setClickMode(this.tools.creaseEditor.state.editing ? null : 'creases'),
          sharpness: (sharpness) => {
            const { editing, selection } = this.tools.creaseEditor.state;
            if (!editing || !selection) return false;
            void this.tools.creaseEditor.setSharpness(sharpness);
            return true;
          },
          undo: () => this.tools.creaseEditor.undo(),
          redo: () => this.tools.creaseEditor.redo(),
        },
      },
      () => this.confirm.open || this.embedDialog.open,
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
          thinEdges: this.viewer.view.thinEdges(),
          lineWidth: s.lineWidth,
          edgeOpacity: this.viewer.view.edgeOpacity(),
          savedViews: this.views.names,
          canvas: this.viewer.view.size,
          viewOffset: this.viewer.view.viewOffset,
          customRules: this.customRules,
          levelRules: this.viewer.steps().options.rules ?? null,
          smoothBoundary: !this.fixedBoundary,
          modelSource: this.source ? { ...this.source } : null,
          notice: this.notice.text,
          drawn: this.viewer.lastDraw ? { ...this.viewer.lastDraw } : null,
        };
      },
      shareLink: () => {
        const result = this.shareActions.link();
        return 'link' in result ? result.link : null;
      },
      positions: async () => Array.from((await this.viewer.meshOf())?.positions ?? []),
      drawnPositions: () => Array.from(this.viewer.buffersOf(this.viewer.state.level)?.positions ?? []),
      setMemoryBudget: (bytes) => this.viewer.setMemoryBudget(bytes),
      crashCore: (how, during) => this.viewer.core.client.crashForTest(how, during),
      coreMemory: () => this.viewer.core.client.memory(),
      projected: (level, pane = 0) => {
        const viewer = this.tools.sideBySide.viewers()[pane];
        if (!viewer) return [];
        const { camera, size } = viewer.view;
        return projectPoints(viewer.buffersOf(level)?.positions ?? [], camera, size.width, size.height);
      },
      vertexOnScreen: (v, shown) => {
        const at = this.viewer.view.vertexOnScreen(v, shown);
        return at && this.viewer.view.toClient(at.x, at.y);
      },
      halfedges: () => {
        const table = this.tools.halfedges.halfedges;
        return {
          explorer: this.tools.halfedges.state,
          euler: this.tools.euler.state,
          table: table ? { next: [...table.next], target: [...table.target], face: [...table.face] } : null,
        };
      },
      arrowOnScreen: (h) => {
        const at = this.tools.halfedges.arrowOnScreen(h);
        return at && this.viewer.view.toClient(at.x, at.y);
      },
      sideBySide: () => {
        const s = this.tools.sideBySide.state;
        const d = s.distance;
        const farthest = (values: Float64Array | undefined) =>
          (values ?? new Float64Array(0)).reduce((m, x) => Math.max(m, x), 0);
        return {
          count: s.count,
          together: s.together,
          panes: s.panes.map((p, i) => ({
            scheme: p.scheme,
            level: p.viewer.level,
            levelCount: p.viewer.levelCount,
            faces: p.viewer.facts?.faces ?? null,
            busy: p.viewer.busy !== null,
            message: p.message,
            view: (this.tools.sideBySide.viewer(i) ?? this.viewer).getView(),
          })),
          distance: d
            ? {
                panes: d.panes,
                schemes: d.schemes,
                levels: d.levels,
                distance: d.distance,
                relative: d.relative,
                diagonal: d.diagonal,
                errorBound: d.errorBound,
                farthest: [farthest(d.aToB), farthest(d.bToA)],
              }
            : null,
          measuring: s.measuring,
        };
      },
    };
  }

  /**
   * Applies the page's URL: the state in its hash, `?src=URL`, or on a first
   * visit (neither) a sample with a line on how to open one's own file.
   */
  async start(): Promise<void> {
    const firstVisit = window.location.hash.length <= 1 && !new URLSearchParams(window.location.search).has('src');
    // A hash the user goes to (Back, Forward, an edited link) says how to show what it opens.
    for (const type of ['popstate', 'hashchange']) window.addEventListener(type, () => this.firstLook.end());
    await this.urlState.start();
    const sample = this.source?.kind === 'url' && this.source.src === FIRST_VISIT.src;
    this.firstVisitHint.hidden = !(firstVisit && sample);
    const { renderMode, overlays } = this.viewer.state;
    if (firstVisit && sample) this.firstLook.begin({ renderMode, control: overlays.control });
  }

  async openFile(file: File): Promise<boolean> {
    return this.openText(file.name, () => readFile(file), { kind: 'file', name: file.name });
  }

  async openUrl(src: string, displayName: string): Promise<boolean> {
    return this.openText(displayName, () => fetchMesh(src, document.baseURI), { kind: 'url', src });
  }

  /**
   * Shows the error about `source`, with `action` if given; the previous
   * model and its levels stay. A step's error ('step') goes once a later
   * step succeeds; others stay until dismissed or a model loads.
   */
  showError(source: string, error: unknown, action?: ErrorAction, kind: 'step' | 'other' = 'other'): void {
    // A crash has been said by the crash listener (with what was running).
    if (error instanceof CancelledError || error instanceof CoreCrashedError) return;
    this.displayError(source, error, action, kind);
  }

  private displayError(source: string, error: unknown, action: ErrorAction | undefined, kind: 'step' | 'other'): void {
    const message = messageOf(error);
    const where = error instanceof LoadError ? error.source : source;
    this.lastError = {
      source: where,
      message,
      code: error instanceof SubdivError ? error.code : error instanceof LoadError ? 'load_error' : 'error',
    };
    this.errorKind = kind;
    this.errors.show(where, message, action);
  }

  private async openText(
    name: string,
    read: () => Promise<MeshText>,
    source: ModelSource,
    options: ReadOptions = {},
  ): Promise<boolean> {
    try {
      const mesh = await read();
      await this.viewer.loadText(mesh.text, mesh.format, mesh.name, options);
      if (this.viewer.state.modelName !== mesh.name) return false;
      this.source = source;
      const faces = this.viewer.state.facts?.faces;
      if (faces !== undefined) this.firstLook.apply(this.viewer, faces);
      this.firstVisitHint.hidden = true;
      this.sharePanel.clear();
      this.errors.hide();
      this.lastError = null;
      this.errorKind = null;
      this.showTagNotes(mesh.name);
      return true;
    } catch (error) {
      // Faces that only disagree: offer to read the file again with CGAL's repair.
      const repairable = error instanceof SubdivError && error.code === 'inconsistent_orientation';
      const repair = {
        label: 'Repair orientation',
        run: () => void this.openText(name, read, source, { repairOrientation: true }),
      };
      this.showError(name, error, repairable ? repair : undefined);
      return false;
    }
  }

  /** Cancel or Esc: the running step or tool request stops, in every pane. */
  private cancel(): void {
    const { busy, levelCount, level } = this.viewer.state;
    this.viewer.cancel();
    this.tools.sideBySide.cancel();
    const said = cancelMessage(busy, levelCount > 0 ? level : null);
    if (said) this.notice.show(said);
    this.cancelNotice = said !== null;
  }

  /** Shows an error about the shown model (a teaching tool's or an edit's request that failed). */
  private modelError(error: unknown): void {
    this.showError(this.viewer.state.modelName ?? 'mesh', error);
  }

  /** Names the file's tags that the core reads but does not apply (their lines), or hides such a notice of an earlier file. */
  private showTagNotes(name: string): void {
    const all = this.viewer.controlMesh?.tags?.notes ?? [];
    // Notes on the file as a whole (a repair, dropped slivers) are said as they are; the rest are on tags.
    const isGeneral = (note: string) => /^(orientation repaired:|\d+ degenerate triangles? )/.test(note);
    const general = all.filter(isGeneral);
    const notes = all.filter((note) => !isGeneral(note));
    if (general.length > 0) {
      this.notice.show(`${name}: ${general.join('; ')}.`);
    } else if (notes.length > 0) {
      const more = notes.length > 3 ? `; and ${notes.length - 3} more` : '';
      this.notice.show(`${name} loaded without some of its tags: ${notes.slice(0, 3).join('; ')}${more}.`);
    } else if (this.tagNotice) {
      this.notice.hide();
    }
    this.tagNotice = all.length > 0;
  }

  /** Chooses a scheme for a link (which then steps to its own level): the levels of the previous one are dropped. */
  private setScheme(scheme: SchemeName): void {
    this.viewer.setScheme(scheme);
    this.viewer.setSchemeOptions(this.schemeOptions(scheme));
    if (scheme === 'custom') void this.rules.ensureRules();
  }

  /** The scheme menu: the levels are computed again with `scheme` up to the level shown. */
  private async switchScheme(scheme: SchemeName): Promise<void> {
    this.pendingScheme = scheme;
    this.update(this.viewer.state);
    try {
      if (scheme === 'custom') await this.rules.ensureRules();
      if (this.pendingScheme !== scheme) return;
      await this.changeSteps({ scheme, options: this.schemeOptions(scheme) });
    } finally {
      if (this.pendingScheme === scheme) this.pendingScheme = null;
      this.update(this.viewer.state);
    }
  }

  /**
   * Computes the levels again with `change` (SubdivViewer.changeSteps). A
   * failure leaves the previous levels and says why; a step's earlier error
   * goes once the change succeeded.
   */
  private async changeSteps(change: Partial<StepSettings>): Promise<boolean> {
    try {
      await this.viewer.changeSteps(change);
      this.stepSucceeded();
      return true;
    } catch (error) {
      const triangulate =
        error instanceof SubdivError && error.code === 'not_triangles' && !change.triangulate
          ? { label: 'Triangulate and switch', run: () => void this.changeSteps({ ...change, triangulate: true }) }
          : undefined;
      this.showError(this.viewer.state.modelName ?? 'mesh', error, triangulate, 'step');
      return false;
    }
  }

  /** Hides the error of an earlier step (a step, a switch or a reset just succeeded): it no longer holds. */
  private stepSucceeded(): void {
    if (this.errorKind !== 'step') return;
    this.errors.hide();
    this.lastError = null;
    this.errorKind = null;
  }

  private async subdivide(): Promise<boolean> {
    const state = this.viewer.state;
    if (state.levelCount === 0) return false;
    try {
      // The custom scheme steps with the panel's rules: wait for the first preset.
      if (state.scheme === 'custom' && !this.customRules) await this.rules.ensureRules();
      const stepped = await this.viewer.subdivide();
      if (stepped) this.stepSucceeded();
      return stepped;
    } catch (error) {
      const triangulate =
        error instanceof SubdivError && error.code === 'not_triangles'
          ? {
              label: 'Triangulate and subdivide',
              run: () => {
                this.viewer.setTriangulate(true);
                void this.subdivide();
              },
            }
          : undefined;
      this.showError(state.modelName ?? 'mesh', error, triangulate, 'step');
      return false;
    }
  }

  /** Options of every step besides scheme and level: the custom rules, quad-triangle's border. */
  private schemeOptions(scheme = this.viewer.state.scheme): SchemeOptions {
    if (scheme === 'custom') return this.customRules ? { rules: this.customRules } : {};
    if (scheme === 'quad-triangle') return { smoothBoundary: !this.fixedBoundary };
    return {};
  }

  /**
   * Hands the options to the viewer (which drops the levels computed with
   * others) and computes again up to the shown level, or `minLevel` if higher.
   */
  private async recompute(minLevel: number): Promise<void> {
    // Rules applied while another scheme is shown wait for the custom scheme to be chosen.
    const scheme = this.viewer.state.scheme;
    if (scheme !== 'custom' && scheme !== 'quad-triangle') return;
    if (!(await this.changeSteps({ options: this.schemeOptions() }))) return;
    const target = Math.max(minLevel, this.viewer.state.level);
    while (this.viewer.state.levelCount > 0 && this.viewer.state.level < target) {
      if (!(await this.subdivide())) return;
    }
  }

  /** Computes the levels up to `level` (as Subdivide would) and shows it; false when a step failed or was declined. */
  private async reachLevel(level: number): Promise<boolean> {
    while (this.viewer.state.levelCount > 0 && this.viewer.state.levelCount <= level) {
      if (!(await this.subdivide())) return false;
    }
    this.viewer.setLevel(level);
    return this.viewer.state.level === level;
  }

  private confirmLargeStep(info: LargeStepInfo, scheme = this.viewer.state.scheme): Promise<boolean> {
    const p = info.prediction;
    const label = schemeInfo(scheme).label;
    return this.confirm.ask(
      `Level ${info.level} is large`,
      `${label} level ${info.level} would have ${p.vertices.toLocaleString('en')} vertices and ` +
        `${p.faces.toLocaleString('en')} faces and needs about ${formatBytes(info.estimatedBytes)}; ` +
        `this tab can probably give ${formatBytes(info.budgetBytes)}. The step may fail or make the page slow.`,
      'Subdivide anyway',
    );
  }

  private update(state: ViewerState): void {
    this.modelName.textContent = state.modelName ?? 'No model loaded';
    this.emptyHint.hidden = state.levelCount > 0;
    const rules = state.scheme === 'custom' ? this.customRules : null;
    this.scheme.update(state, {
      needsTriangles: rules ? hostNeedsTriangles(rules.host) : undefined,
      needsTrianglesWho: rules ? `The ${hostLabel(rules.host)} host` : undefined,
      fixedBoundary: this.fixedBoundary,
      pending: this.pendingScheme ?? undefined,
    });
    this.rules.element.hidden = (this.pendingScheme ?? state.scheme) !== 'custom';
    this.levels.update(state);
    if (this.cancelNotice && state.busy) {
      this.cancelNotice = false;
      this.notice.hide();
    }
    this.display.update(state);
    this.views.update();
    this.facts.update(state);
    this.exports.update(state);
    this.progress.update(state.busy);
  }
}
