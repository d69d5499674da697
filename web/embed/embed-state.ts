/**
 * What a `<subdiv-viewer>`'s attributes ask for, read with the same rules as
 * a share link (viewer-params.ts): a bad value falls back to the default and
 * is named in `problems`.
 */
import type { SchemeName } from '../core/mesh';
import { DEFAULT_LINE_WIDTH, MAX_LINE_WIDTH, MIN_LINE_WIDTH, parseLineWidth } from '../render/line-style';
import { OVERLAY_DEFAULTS, type OverlayName, RENDER_MODES, type RenderMode } from '../render/render-mode';
import { formatViewString, parseViewString, type ViewState } from '../render/view-state';
import { isSchemeName } from '../viewer/scheme-info';
import {
  CONTROLS_MODES,
  type ControlsMode,
  MAX_PARAM_LEVELS,
  OVERLAY_KEYS,
  parseBeside,
  parseFlag,
  parseLevels,
  type ViewerParams,
} from '../viewer/viewer-params';

export interface EmbedState {
  src: string;
  scheme: SchemeName;
  levels: number;
  renderMode: RenderMode;
  overlays: Record<OverlayName, boolean>;
  triangulate: boolean;
  rules: string;
  view: ViewState | null;
  controls: ControlsMode;
  alt: string;
  /** A CSS colour, `transparent`, or null for the default (light or dark). */
  background: string | null;
  /** The teaching tool switched on. */
  tool: EmbedTool;
  /** The vertex the tool shows (stencils: of the shown level; basis: of the control mesh); null: none yet. */
  vertex: number | null;
  /** Split, then smooth: 0 the split alone … 1 the smoothed level. */
  split: number;
  /** Schemes in panes beside the viewer's own (side by side), empty for none. */
  beside: SchemeName[];
  /** Side by side: the Hausdorff distance between the first two panes, and their colours by it. */
  distance: boolean;
  /** Width of the drawn lines, CSS pixels (render/line-style.ts). */
  lineWidth: number;
  problems: { attribute: string; message: string }[];
}

export const DEFAULT_CONTROLS: ControlsMode = 'minimal';

/** The teaching tools an element can show (web/teach/): none, the stencil inspector, a basis function, split then smooth. */
export type EmbedTool = 'none' | 'stencils' | 'basis' | 'split' | 'halfedges';

export const EMBED_TOOLS: readonly EmbedTool[] = ['none', 'stencils', 'basis', 'split', 'halfedges'];

export function isEmbedTool(value: string): value is EmbedTool {
  return (EMBED_TOOLS as readonly string[]).includes(value);
}

/** Reads the state from `attr(name)` (an element's getAttribute). */
export function readEmbedState(attr: (name: string) => string | null): EmbedState {
  const problems: EmbedState['problems'] = [];
  const flag = (name: string, absent = false): boolean => {
    const value = attr(name);
    if (value === null) return absent;
    const on = parseFlag(value);
    if (on === null)
      problems.push({ attribute: name, message: `${name} must be present (on) or absent, or 1/0; not "${value}".` });
    return on ?? absent;
  };
  const schemeText = attr('scheme');
  let scheme: SchemeName = 'catmull-clark';
  if (schemeText) {
    if (isSchemeName(schemeText)) scheme = schemeText;
    else problems.push({ attribute: 'scheme', message: `Unknown scheme "${schemeText}".` });
  }
  const levelsText = attr('levels');
  let levels = 0;
  if (levelsText !== null) {
    const n = parseLevels(levelsText);
    if (n === null) {
      problems.push({
        attribute: 'levels',
        message: `levels must be a whole number from 0 to ${MAX_PARAM_LEVELS}, not "${levelsText}".`,
      });
    } else {
      levels = n;
    }
  }
  const modeText = attr('render-mode');
  let renderMode: RenderMode = 'smooth';
  if (modeText) {
    const known = RENDER_MODES.find((m) => m.mode === modeText);
    if (known) renderMode = known.mode;
    else problems.push({ attribute: 'render-mode', message: `Unknown render mode "${modeText}".` });
  }
  const viewText = attr('view');
  const view = parseViewString(viewText);
  if (viewText && !view) {
    problems.push({ attribute: 'view', message: 'view must be nine numbers: camera position, target and up.' });
  }
  const controlsText = attr('controls');
  let controls = DEFAULT_CONTROLS;
  if (controlsText) {
    if ((CONTROLS_MODES as readonly string[]).includes(controlsText)) controls = controlsText as ControlsMode;
    else
      problems.push({
        attribute: 'controls',
        message: `controls must be none, minimal or full, not "${controlsText}".`,
      });
  }
  const rules = attr('rules')?.trim() ?? '';
  if (scheme === 'custom' && !rules) {
    problems.push({
      attribute: 'rules',
      message: 'scheme="custom" needs a rules attribute: the URL of a rule-set JSON.',
    });
  }
  const backgroundText = attr('background')?.trim() || null;
  const background = backgroundText !== null && isColour(backgroundText) ? backgroundText : null;
  if (backgroundText !== null && background === null) {
    problems.push({
      attribute: 'background',
      message: `background must be a CSS colour or transparent, not "${backgroundText}".`,
    });
  }
  const toolText = attr('tool')?.trim() || null;
  let tool: EmbedTool = 'none';
  if (toolText !== null) {
    if (isEmbedTool(toolText)) tool = toolText;
    else
      problems.push({
        attribute: 'tool',
        message: `tool must be none, stencils, basis, split or halfedges, not "${toolText}".`,
      });
  }
  const vertexText = attr('vertex');
  let vertex: number | null = null;
  if (vertexText !== null && vertexText.trim() !== '') {
    if (/^\s*\d+\s*$/.test(vertexText) && Number.isSafeInteger(Number(vertexText))) vertex = Number(vertexText);
    else problems.push({ attribute: 'vertex', message: `vertex must be a whole number ≥ 0, not "${vertexText}".` });
  }
  const splitText = attr('split');
  let split = 1;
  if (splitText !== null && splitText.trim() !== '') {
    // With an exponent too: the split property writes String(t), and String(1e-7) is "1e-7".
    const t = /^\s*[+]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?\s*$/.test(splitText) ? Number(splitText) : Number.NaN;
    if (t >= 0 && t <= 1) split = t;
    else problems.push({ attribute: 'split', message: `split must be a number from 0 to 1, not "${splitText}".` });
  }
  const widthText = attr('line-width');
  let lineWidth = DEFAULT_LINE_WIDTH;
  if (widthText !== null && widthText.trim() !== '') {
    const width = parseLineWidth(widthText);
    if (width !== null) lineWidth = width;
    else {
      problems.push({
        attribute: 'line-width',
        message: `line-width must be a width from ${MIN_LINE_WIDTH} to ${MAX_LINE_WIDTH} pixels, not "${widthText}".`,
      });
    }
  }
  const besideText = attr('beside');
  let beside: SchemeName[] = [];
  if (besideText !== null) {
    const parsed = parseBeside(besideText);
    if (parsed.problem) problems.push({ attribute: 'beside', message: parsed.problem });
    beside = parsed.schemes;
  }
  return {
    src: attr('src')?.trim() ?? '',
    scheme,
    levels,
    renderMode,
    overlays: {
      control: flag(OVERLAY_KEYS.control),
      curves: flag(OVERLAY_KEYS.curves),
      bbox: flag(OVERLAY_KEYS.bbox),
      // On unless creases="0" (or off/false).
      creases: flag(OVERLAY_KEYS.creases, OVERLAY_DEFAULTS.creases),
    },
    triangulate: flag('triangulate'),
    rules,
    view,
    controls,
    alt: attr('alt') ?? '',
    background,
    tool,
    vertex,
    split,
    beside,
    lineWidth,
    distance: flag('distance', true),
    problems,
  };
}

/** A CSS colour the browser understands, or `transparent` (outside a browser, any word passes). */
function isColour(value: string): boolean {
  if (value === 'transparent') return true;
  return typeof CSS === 'undefined' || CSS.supports('color', value);
}

/**
 * The attributes that start an element in the state of link parameters, in
 * a fixed order: what the iframe route sets from its query. An overlay is
 * written only away from its default: present when on, "0" when off (the
 * creases are on unless creases="0").
 */
export function attributesOfParams(params: ViewerParams): [string, string][] {
  const out: [string, string][] = [];
  if (params.src) out.push(['src', params.src]);
  if (params.scheme) out.push(['scheme', params.scheme]);
  if (params.levels !== undefined) out.push(['levels', String(params.levels)]);
  if (params.renderMode) out.push(['render-mode', params.renderMode]);
  for (const [name, on] of Object.entries(params.overlays ?? {}) as [OverlayName, boolean][]) {
    if (on !== OVERLAY_DEFAULTS[name]) out.push([OVERLAY_KEYS[name], on ? '' : '0']);
  }
  if (params.triangulate) out.push(['triangulate', '']);
  if (params.view) out.push(['view', formatViewString(params.view)]);
  if (params.rules) out.push(['rules', params.rules]);
  if (params.controls) out.push(['controls', params.controls]);
  if (params.beside) out.push(['beside', params.beside.join(' ')]);
  if (params.lineWidth !== undefined) out.push(['line-width', String(params.lineWidth)]);
  return out;
}
