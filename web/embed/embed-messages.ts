/**
 * The iframe route's postMessage API, both ways. Commands from the parent
 * page are plain objects `{ subdivlab: NAME, ...fields }`, checked field by
 * field here and never evaluated; anything else is refused with a reason.
 * Events to the parent carry what the element's events carry.
 *
 * Commands: `load` ({ src } or { text, name }), `set-scheme` ({ scheme }),
 * `subdivide`, `set-level` ({ level }), `set-view` ({ view }: the nine-number
 * string or { position, target, up }), `set-render-mode` ({ mode }),
 * `set-overlay` ({ overlay: control-mesh, control-edges, bbox or creases; on }),
 * `set-triangulate` ({ on }), `set-tool` ({ tool, vertex? }), `set-split` ({ t }).
 * Events: `ready`, `load`, `level-change`, `error`, `progress`, `stencil`, `basis`.
 */
import type { SchemeName } from '../core/mesh';
import { quotedValue } from '../core/quoted-value';
import { RENDER_MODES, type RenderMode } from '../render/render-mode';
import { checkedView, parseViewString, type ViewState } from '../render/view-state';
import { isSchemeName } from '../viewer/scheme-info';
import { MAX_PARAM_LEVELS, OVERLAY_KEYS } from '../viewer/viewer-params';
import { type EmbedTool, isEmbedTool } from './embed-state';

export type EmbedCommand =
  | { subdivlab: 'load'; src: string }
  | { subdivlab: 'load'; text: string; name: string }
  | { subdivlab: 'set-scheme'; scheme: SchemeName }
  | { subdivlab: 'subdivide' }
  | { subdivlab: 'set-level'; level: number }
  | { subdivlab: 'set-view'; view: ViewState }
  | { subdivlab: 'set-render-mode'; mode: RenderMode }
  | { subdivlab: 'set-overlay'; overlay: OverlayAttribute; on: boolean }
  | { subdivlab: 'set-triangulate'; on: boolean }
  | { subdivlab: 'set-tool'; tool: EmbedTool; vertex?: number }
  | { subdivlab: 'set-split'; t: number };

/** The overlays a command may switch, by their attribute names (as links write them). */
const OVERLAY_ATTRIBUTES: readonly string[] = Object.values(OVERLAY_KEYS);
export type OverlayAttribute = (typeof OVERLAY_KEYS)[keyof typeof OVERLAY_KEYS];

export type EmbedEventName =
  | 'ready'
  | 'load'
  | 'level-change'
  | 'error'
  | 'progress'
  | 'stencil'
  | 'basis'
  | 'distance';

/** An event as posted to the parent: the element's event detail plus its name. */
export type EmbedEventMessage = { subdivlab: EmbedEventName } & Record<string, unknown>;

/** Largest mesh text a `load` command may carry (as for `?src=` downloads). */
export const MAX_MESSAGE_TEXT = 64 * 1024 * 1024;

export type Checked = { ok: true; command: EmbedCommand } | { ok: false; reason: string };

function isRecord(value: unknown): value is Record<string, unknown> {
  return typeof value === 'object' && value !== null && !Array.isArray(value);
}

/** Checks a message from the parent page; says why it is refused when it is. */
export function checkCommand(data: unknown): Checked {
  if (!isRecord(data)) return { ok: false, reason: 'a command is an object { subdivlab: NAME, ... }' };
  const name = data.subdivlab;
  switch (name) {
    case 'load': {
      if (typeof data.src === 'string' && data.src.length > 0 && data.src.length <= 4096) {
        return { ok: true, command: { subdivlab: 'load', src: data.src } };
      }
      if (typeof data.text === 'string' && typeof data.name === 'string') {
        if (data.text.length > MAX_MESSAGE_TEXT) return { ok: false, reason: 'load: text is larger than 64 MB' };
        return { ok: true, command: { subdivlab: 'load', text: data.text, name: data.name.slice(0, 256) } };
      }
      return { ok: false, reason: 'load needs src (a URL) or text and name (the mesh file)' };
    }
    case 'set-scheme':
      if (typeof data.scheme === 'string' && isSchemeName(data.scheme)) {
        return { ok: true, command: { subdivlab: 'set-scheme', scheme: data.scheme } };
      }
      return { ok: false, reason: `set-scheme: unknown scheme ${quotedValue(data.scheme)}` };
    case 'subdivide':
      return { ok: true, command: { subdivlab: 'subdivide' } };
    case 'set-level':
      if (typeof data.level === 'number' && Number.isInteger(data.level) && data.level >= 0) {
        if (data.level > MAX_PARAM_LEVELS) return { ok: false, reason: `set-level: at most ${MAX_PARAM_LEVELS}` };
        return { ok: true, command: { subdivlab: 'set-level', level: data.level } };
      }
      return { ok: false, reason: 'set-level needs level, a whole number ≥ 0' };
    case 'set-view': {
      const view = typeof data.view === 'string' ? parseViewString(data.view) : checkedView(data.view);
      if (view) return { ok: true, command: { subdivlab: 'set-view', view } };
      return { ok: false, reason: 'set-view needs view: nine numbers, or { position, target, up }' };
    }
    case 'set-render-mode': {
      const known = RENDER_MODES.find((m) => m.mode === data.mode);
      if (known) return { ok: true, command: { subdivlab: 'set-render-mode', mode: known.mode } };
      return { ok: false, reason: `set-render-mode: unknown mode ${quotedValue(data.mode)}` };
    }
    case 'set-overlay':
      if (
        typeof data.overlay === 'string' &&
        OVERLAY_ATTRIBUTES.includes(data.overlay) &&
        typeof data.on === 'boolean'
      ) {
        return {
          ok: true,
          command: { subdivlab: 'set-overlay', overlay: data.overlay as OverlayAttribute, on: data.on },
        };
      }
      return {
        ok: false,
        reason: 'set-overlay needs overlay (control-mesh, control-edges, bbox or creases) and on (true or false)',
      };
    case 'set-triangulate':
      if (typeof data.on === 'boolean') return { ok: true, command: { subdivlab: 'set-triangulate', on: data.on } };
      return { ok: false, reason: 'set-triangulate needs on (true or false)' };
    case 'set-tool': {
      if (typeof data.tool !== 'string' || !isEmbedTool(data.tool)) {
        return {
          ok: false,
          reason: `set-tool: tool must be none, stencils, basis, split or halfedges, not ${quotedValue(data.tool)}`,
        };
      }
      if (data.vertex === undefined) return { ok: true, command: { subdivlab: 'set-tool', tool: data.tool } };
      if (typeof data.vertex === 'number' && Number.isSafeInteger(data.vertex) && data.vertex >= 0) {
        return { ok: true, command: { subdivlab: 'set-tool', tool: data.tool, vertex: data.vertex } };
      }
      return { ok: false, reason: 'set-tool: vertex must be a whole number ≥ 0' };
    }
    case 'set-split':
      if (typeof data.t === 'number' && data.t >= 0 && data.t <= 1) {
        return { ok: true, command: { subdivlab: 'set-split', t: data.t } };
      }
      return { ok: false, reason: 'set-split needs t, a number from 0 to 1' };
    default:
      return { ok: false, reason: `unknown command ${quotedValue(name)}` };
  }
}
