/**
 * The state a viewer can be started in, as text: the app's URL hash, the
 * iframe route's query and the `<subdiv-viewer>` attributes all read and
 * write it here, so a share link, an embed snippet and an attribute mean
 * the same thing. Unknown keys are ignored; a bad value is left out and
 * named in `problems`, never guessed.
 */
import type { SchemeName } from '../core/mesh';
import { MAX_LINE_WIDTH, MIN_LINE_WIDTH, parseLineWidth } from '../render/line-style';
import { OVERLAY_NAMES, type OverlayName, RENDER_MODES, type RenderMode } from '../render/render-mode';
import { formatViewString, parseViewString, type ViewState } from '../render/view-state';
import { isSchemeName, PANE_SCHEMES } from './scheme-info';

/** Which controls an embedded viewer shows: none, a level stepper and scheme menu, or all of them. */
export type ControlsMode = 'none' | 'minimal' | 'full';

export const CONTROLS_MODES: readonly ControlsMode[] = ['none', 'minimal', 'full'];

/** Most levels a link or attribute may ask for; the core still refuses a run that would not fit. */
export const MAX_PARAM_LEVELS = 8;

/** Most panes side by side: the viewer's own and three beside it. */
export const MAX_PANES = 4;

export interface ViewerParams {
  /** URL of the mesh (http or https, absolute or relative to the page). */
  src?: string;
  scheme?: SchemeName;
  /** Levels to compute after loading. */
  levels?: number;
  renderMode?: RenderMode;
  overlays?: Partial<Record<OverlayName, boolean>>;
  /** Triangulate first (a scheme that needs triangles on a polygon mesh). */
  triangulate?: boolean;
  view?: ViewState;
  /** URL of a rule-set JSON (scheme `custom`). */
  rules?: string;
  controls?: ControlsMode;
  /** Schemes shown side by side with `scheme`, in panes beside it (one to three). */
  beside?: SchemeName[];
  /** The line-width setting, CSS pixels (render/line-style.ts). */
  lineWidth?: number;
}

/** Parameter names in links; the element's attributes use the same names, except `render-mode` for `mode`. */
export const PARAM_KEYS = {
  src: 'src',
  scheme: 'scheme',
  levels: 'levels',
  renderMode: 'mode',
  triangulate: 'triangulate',
  view: 'view',
  rules: 'rules',
  controls: 'controls',
  beside: 'beside',
  lineWidth: 'lines',
} as const;

/** The link/attribute name of each overlay. */
export const OVERLAY_KEYS = {
  control: 'control-mesh',
  curves: 'control-edges',
  bbox: 'bbox',
  creases: 'creases',
} as const satisfies Record<OverlayName, string>;

/** "1", "true", "" (a bare attribute) or "on" mean on; "0", "false", "off" mean off. */
export function parseFlag(value: string): boolean | null {
  const v = value.trim().toLowerCase();
  if (v === '' || v === '1' || v === 'true' || v === 'on' || v === 'yes') return true;
  if (v === '0' || v === 'false' || v === 'off' || v === 'no') return false;
  return null;
}

/** Reads `levels`: a whole number from 0 to {@link MAX_PARAM_LEVELS}. */
export function parseLevels(value: string): number | null {
  if (!/^\s*\d+\s*$/.test(value)) return null;
  const n = Number(value);
  return n <= MAX_PARAM_LEVELS ? n : null;
}

/**
 * Reads `beside`: one to three scheme names (not custom, whose rules belong
 * to the first pane), separated by commas or spaces; an empty value is none.
 */
export function parseBeside(value: string): { schemes: SchemeName[]; problem: string | null } {
  const names = value.split(/[\s,]+/).filter((n) => n !== '');
  const unknown = names.filter((n) => !(PANE_SCHEMES as readonly string[]).includes(n));
  if (unknown.length > 0) {
    const what = unknown.map((n) => `"${n}"`).join(', ');
    return {
      schemes: [],
      problem: `beside takes the names of schemes with built-in rules (${PANE_SCHEMES.join(', ')}), not ${what}.`,
    };
  }
  if (names.length > MAX_PANES - 1) {
    return { schemes: [], problem: `beside takes at most ${MAX_PANES - 1} schemes, not ${names.length}.` };
  }
  return { schemes: names as SchemeName[], problem: null };
}

export interface ParsedParams {
  params: ViewerParams;
  /** One sentence per value that was left out. */
  problems: string[];
}

/** Reads parameters from a query or hash (`a=1&b=2`, with or without the leading `?` or `#`). */
export function parseViewerParams(text: string | URLSearchParams): ParsedParams {
  const query = typeof text === 'string' ? new URLSearchParams(text.replace(/^[?#]/, '')) : text;
  const params: ViewerParams = {};
  const problems: string[] = [];
  const get = (key: string) => query.get(key);
  const src = get(PARAM_KEYS.src);
  if (src) params.src = src;
  const scheme = get(PARAM_KEYS.scheme);
  if (scheme !== null) {
    if (isSchemeName(scheme)) params.scheme = scheme;
    else problems.push(`Unknown scheme "${scheme}".`);
  }
  const levels = get(PARAM_KEYS.levels);
  if (levels !== null) {
    const n = parseLevels(levels);
    if (n === null) problems.push(`levels must be a whole number from 0 to ${MAX_PARAM_LEVELS}, not "${levels}".`);
    else params.levels = n;
  }
  const mode = get(PARAM_KEYS.renderMode);
  if (mode !== null) {
    const known = RENDER_MODES.find((m) => m.mode === mode);
    if (known) params.renderMode = known.mode;
    else problems.push(`Unknown render mode "${mode}" (${RENDER_MODES.map((m) => m.mode).join(', ')}).`);
  }
  for (const name of OVERLAY_NAMES) {
    const value = get(OVERLAY_KEYS[name]);
    if (value === null) continue;
    const on = parseFlag(value);
    if (on === null) problems.push(`${OVERLAY_KEYS[name]} must be 1 or 0, not "${value}".`);
    else params.overlays = { ...params.overlays, [name]: on };
  }
  const triangulate = get(PARAM_KEYS.triangulate);
  if (triangulate !== null) {
    const on = parseFlag(triangulate);
    if (on === null) problems.push(`triangulate must be 1 or 0, not "${triangulate}".`);
    else params.triangulate = on;
  }
  const view = get(PARAM_KEYS.view);
  if (view !== null) {
    const parsed = parseViewString(view);
    if (parsed) params.view = parsed;
    else problems.push('view must be nine numbers: camera position, target and up.');
  }
  const rules = get(PARAM_KEYS.rules);
  if (rules) params.rules = rules;
  const controls = get(PARAM_KEYS.controls);
  if (controls !== null) {
    if ((CONTROLS_MODES as readonly string[]).includes(controls)) params.controls = controls as ControlsMode;
    else problems.push(`controls must be none, minimal or full, not "${controls}".`);
  }
  const beside = get(PARAM_KEYS.beside);
  if (beside !== null) {
    const { schemes, problem } = parseBeside(beside);
    if (problem) problems.push(problem);
    else if (schemes.length > 0) params.beside = schemes;
  }
  const lines = get(PARAM_KEYS.lineWidth);
  if (lines !== null) {
    const width = parseLineWidth(lines);
    if (width === null)
      problems.push(`lines must be a width from ${MIN_LINE_WIDTH} to ${MAX_LINE_WIDTH} pixels, not "${lines}".`);
    else params.lineWidth = width;
  }
  return { params, problems };
}

/** Writes parameters in a fixed order, leaving out what is not set. */
export function formatViewerParams(params: ViewerParams): URLSearchParams {
  const query = new URLSearchParams();
  if (params.src) query.set(PARAM_KEYS.src, params.src);
  if (params.scheme) query.set(PARAM_KEYS.scheme, params.scheme);
  if (params.levels !== undefined) query.set(PARAM_KEYS.levels, String(params.levels));
  if (params.renderMode) query.set(PARAM_KEYS.renderMode, params.renderMode);
  for (const name of OVERLAY_NAMES) {
    const on = params.overlays?.[name];
    if (on !== undefined) query.set(OVERLAY_KEYS[name], on ? '1' : '0');
  }
  if (params.triangulate) query.set(PARAM_KEYS.triangulate, '1');
  if (params.rules) query.set(PARAM_KEYS.rules, params.rules);
  if (params.view) query.set(PARAM_KEYS.view, formatViewString(params.view));
  if (params.controls) query.set(PARAM_KEYS.controls, params.controls);
  if (params.beside && params.beside.length > 0) query.set(PARAM_KEYS.beside, params.beside.join(','));
  if (params.lineWidth !== undefined) query.set(PARAM_KEYS.lineWidth, String(params.lineWidth));
  return query;
}
