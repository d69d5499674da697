/**
 * The app's state in the URL hash: model source, scheme, shown level, render
 * mode, overlays, camera and the schemes side by side, in the encoding of viewer-params.ts (the one a
 * share link, the iframe route and `<subdiv-viewer>` read). Model, scheme and
 * level changes push a history entry, so Back returns to them; camera, mode
 * and overlay changes replace the current one. Both are debounced, so a drag
 * or a fast scrub writes once. On load, Back/Forward and an edited hash the
 * state is applied again: the model is loaded if it differs, levels are
 * stepped one at a time (computed ones are reused), then the camera is set.
 */
import type { SchemeName } from '../core/mesh';
import { DEFAULT_LINE_WIDTH } from '../render/line-style';
import { OVERLAY_DEFAULTS, OVERLAY_NAMES, type RenderMode } from '../render/render-mode';
import type { ViewState } from '../render/view-state';
import { overlayAvailable } from '../ui/display-panel';
import { schemeInfo } from '../viewer/scheme-info';
import type { SubdivViewer, ViewerState } from '../viewer/subdiv-viewer';
import { formatViewerParams, parseViewerParams, type ViewerParams } from '../viewer/viewer-params';

/** What a state without a `scheme` or `mode` value means (the viewer's own defaults). */
export const DEFAULT_SCHEME: SchemeName = 'catmull-clark';
export const DEFAULT_RENDER_MODE: RenderMode = 'smooth';

/**
 * The first visit (no hash, no `?src=`): the rhombicuboctahedron (triangles
 * and quads) after two Catmull-Clark steps, polygon edges and the control
 * mesh shown, so the page opens on what subdivision does.
 */
export const FIRST_VISIT: ViewerParams = {
  src: 'meshes/rhombicuboctahedron.off',
  scheme: 'catmull-clark',
  levels: 2,
  renderMode: 'edges',
  overlays: { control: true },
};

/** Milliseconds a change waits before it is written, so a drag or a scrub writes once. */
const WRITE_DELAY_MS = 300;

/** What the URL state needs from the app shell. */
export interface UrlStateHost {
  readonly viewer: SubdivViewer;
  /** The URL the shown model was loaded from, as given; null for a local file or no model. */
  modelSrc(): string | null;
  /** Loads the mesh at `src`; false when it failed (the shell showed why). */
  openUrl(src: string): Promise<boolean>;
  /** Chooses a scheme as the scheme menu does. */
  setScheme(scheme: SchemeName): void;
  /** One more level; false when it failed or was declined (the shell showed why). */
  subdivide(): Promise<boolean>;
  /** Shows the values of a link that were ignored (an empty list hides the message). */
  linkProblems(problems: string[]): void;
  /** The schemes shown side by side beside the viewer's (none: one view), and their change. */
  beside(): SchemeName[];
  setBeside(schemes: SchemeName[]): void;
  onBesideChange(listener: () => void): void;
}

/** The state of `viewer` as link parameters: only overlays not in their default state; level and camera only with a model. */
export function paramsOfState(state: ViewerState, src: string | null, view: ViewState): ViewerParams {
  const params: ViewerParams = { scheme: state.scheme };
  if (src) params.src = src;
  if (state.levelCount > 0) params.levels = state.level;
  if (state.triangulate) params.triangulate = true;
  params.renderMode = state.renderMode;
  for (const name of OVERLAY_NAMES) {
    const on = state.overlays[name];
    if (on !== OVERLAY_DEFAULTS[name]) params.overlays = { ...params.overlays, [name]: on };
  }
  if (state.levelCount > 0) params.view = view;
  if (state.lineWidth !== DEFAULT_LINE_WIDTH) params.lineWidth = state.lineWidth;
  return params;
}

/**
 * Parameters as query or hash text. Commas, slashes and colons stay as they
 * are (they are allowed there), so links stay readable; the parser reads both forms.
 */
export function paramsText(params: ViewerParams): string {
  return formatViewerParams(params).toString().replace(/%2C/gi, ',').replace(/%2F/gi, '/').replace(/%3A/gi, ':');
}

/** The parts of a state whose change makes a new history entry. */
function entryKey(params: ViewerParams): string {
  return JSON.stringify([params.src ?? null, params.scheme ?? null, params.levels ?? null]);
}

/** True when `a` and `b` name the same URL once resolved against `base`. */
export function sameSource(a: string, b: string | null, base: string): boolean {
  if (b === null) return false;
  try {
    return new URL(a, base).href === new URL(b, base).href;
  } catch {
    return a === b;
  }
}

export class UrlState {
  private timer: ReturnType<typeof setTimeout> | undefined;
  /** Hash text (without `#`) last written or applied. */
  private written = '';
  private writtenKey = '';
  /** Bumped by every restore; a restore that is no longer the latest stops. */
  private restoreRun = 0;
  private restoring = false;
  /** Hash text being applied now: Back fires both popstate and hashchange for one move. */
  private applying: string | null = null;

  constructor(
    private readonly host: UrlStateHost,
    private readonly win: Window = window,
  ) {}

  /** Listens for changes and navigation, then applies the page's URL (the first visit when it has none). */
  start(): Promise<void> {
    this.host.viewer.onChange(() => this.schedule());
    this.host.viewer.onViewChange(() => this.schedule());
    this.host.onBesideChange(() => this.schedule());
    const onNavigate = () => {
      const hash = this.currentHash();
      if (hash !== this.written && hash !== this.applying) void this.restore(false);
    };
    this.win.addEventListener('popstate', onNavigate);
    this.win.addEventListener('hashchange', onNavigate);
    return this.restore(true);
  }

  /** The state as link parameters (what the hash holds once written). */
  params(): ViewerParams {
    const { viewer } = this.host;
    const params = paramsOfState(viewer.state, this.host.modelSrc(), viewer.getView());
    const beside = this.host.beside();
    return beside.length > 0 ? { ...params, beside } : params;
  }

  /** Writes the state now (replacing the current entry when `replace`). */
  write(replace = false): void {
    clearTimeout(this.timer);
    this.timer = undefined;
    if (this.restoring || this.host.viewer.state.busy) return;
    const params = this.params();
    const text = paramsText(params);
    const key = entryKey(params);
    if (text === this.written && key === this.writtenKey) return;
    const { pathname, search } = this.win.location;
    const url = `${pathname}${search}#${text}`;
    if (!replace && key !== this.writtenKey) this.win.history.pushState(null, '', url);
    else this.win.history.replaceState(null, '', url);
    this.written = this.currentHash();
    this.writtenKey = key;
  }

  private currentHash(): string {
    return this.win.location.hash.replace(/^#/, '');
  }

  private schedule(): void {
    if (this.restoring) return;
    clearTimeout(this.timer);
    this.timer = setTimeout(() => this.write(), WRITE_DELAY_MS);
  }

  /** The parameters the page's URL asks for, and the values it ignored. */
  private wanted(first: boolean): { params: ViewerParams; problems: string[] } {
    const hash = this.currentHash();
    const querySrc = new URLSearchParams(this.win.location.search).get('src');
    if (first && hash === '' && !querySrc) return { params: { ...FIRST_VISIT }, problems: [] };
    const parsed = parseViewerParams(hash);
    // `?src=` still works; a hash with its own src is the newer state.
    if (!parsed.params.src && querySrc) parsed.params.src = querySrc;
    return parsed;
  }

  private async restore(first: boolean): Promise<void> {
    clearTimeout(this.timer);
    const run = ++this.restoreRun;
    const stale = () => run !== this.restoreRun;
    const { host } = this;
    const { viewer } = host;
    const { params, problems } = this.wanted(first);
    this.restoring = true;
    this.applying = this.currentHash();
    try {
      host.linkProblems(problems);
      // A step or load of an earlier restore (or the user's) gives way to the page the user went to;
      // a turn of the event loop lets the cancelled call settle before the next step starts.
      if (viewer.state.busy) {
        viewer.cancel();
        await new Promise((resolve) => setTimeout(resolve, 0));
        if (stale()) return;
      }
      let haveModel = viewer.state.levelCount > 0;
      if (params.src && !sameSource(params.src, host.modelSrc(), this.win.document.baseURI)) {
        haveModel = await host.openUrl(params.src);
        if (stale()) return;
      }
      const scheme = params.scheme ?? DEFAULT_SCHEME;
      if (viewer.state.scheme !== scheme) host.setScheme(scheme);
      // A link without the key was made without triangulation (it is written only when on).
      viewer.setTriangulate(params.triangulate ?? false);
      // The panes first: with levels together, they follow the viewer's steps.
      host.setBeside(params.beside ?? []);
      if (haveModel) await this.stepTo(params.levels ?? 0, stale);
      if (stale()) return;
      viewer.setRenderMode(params.renderMode ?? DEFAULT_RENDER_MODE);
      viewer.setLineWidth(params.lineWidth ?? DEFAULT_LINE_WIDTH);
      for (const name of OVERLAY_NAMES) {
        const on = params.overlays?.[name] ?? OVERLAY_DEFAULTS[name];
        // As the checkbox: an overlay that cannot be drawn here is not switched on, but one on by
        // default (the creases) stays on for the tagged models to come.
        viewer.setOverlay(name, on && (OVERLAY_DEFAULTS[name] || overlayAvailable(name, viewer.state)));
      }
      if (haveModel && params.view) viewer.setView(params.view);
    } finally {
      if (!stale()) {
        this.restoring = false;
        this.applying = null;
        this.write(true);
      }
    }
  }

  /** Shows level `target`, reusing computed levels and computing the missing ones one step at a time. */
  private async stepTo(target: number, stale: () => boolean): Promise<void> {
    const { viewer } = this.host;
    const state = viewer.state;
    // A link cannot reach level 1 of a triangles-only scheme on polygons unless it triangulated first.
    const polygons = state.levelCount === 1 && state.facts !== null && state.facts.faces > state.facts.triangles;
    if (target > 0 && polygons && schemeInfo(state.scheme).needsTriangles) viewer.setTriangulate(true);
    viewer.setLevel(Math.min(target, viewer.state.levelCount - 1));
    while (viewer.state.level < target) {
      if (!(await this.host.subdivide()) || stale()) return;
    }
  }
}
