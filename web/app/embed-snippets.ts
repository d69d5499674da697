/**
 * The links and HTML snippets of the Share and Embed actions, from the
 * state as link parameters (viewer-params.ts): the app's own link with the
 * state in the hash, a `<subdiv-viewer>` element and an iframe of
 * `embed.html`. Pure functions of their inputs, so tests can read them.
 */
import { OVERLAY_DEFAULTS, RENDER_MODES } from '../render/render-mode';
import { formatViewString } from '../render/view-state';
import { schemeInfo } from '../viewer/scheme-info';
import { OVERLAY_KEYS, type ViewerParams } from '../viewer/viewer-params';
import { paramsText } from './url-state';

/** Size of the iframe snippet, in CSS pixels. */
export const IFRAME_SIZE = { width: 640, height: 420 };

/** What the snippets describe besides the parameters. */
export interface EmbedSubject {
  /** The app's base URL, ending in `/` (`new URL('.', document.baseURI)`). */
  appBase: string;
  /** Name of the model as shown (`cube.off`). */
  modelName: string;
  /** Faces of the shown level, for the description. */
  faces: number;
}

/** Escapes text for a double-quoted HTML attribute. */
export function escapeAttribute(value: string): string {
  return value.replace(/&/g, '&amp;').replace(/"/g, '&quot;').replace(/</g, '&lt;').replace(/>/g, '&gt;');
}

/** `params` with `src` made absolute against `base`. */
export function withAbsoluteSrc(params: ViewerParams, base: string): ViewerParams {
  return params.src ? { ...params, src: new URL(params.src, base).href } : { ...params };
}

/** The link that opens the app in this state: the page's address with the state as its hash. */
export function shareLink(pageUrl: string, params: ViewerParams): string {
  const url = new URL(pageUrl);
  return `${url.origin}${url.pathname}#${paramsText(params)}`;
}

/** One sentence saying what the embedded view shows (the element's `alt`, the iframe's `title`). */
export function describeView(params: ViewerParams, subject: EmbedSubject): string {
  const scheme = schemeInfo(params.scheme ?? 'catmull-clark').label;
  const levels = params.levels ?? 0;
  const mode = RENDER_MODES.find((m) => m.mode === params.renderMode)?.label.toLowerCase() ?? 'smooth shaded';
  const faces = `${subject.faces.toLocaleString('en')} faces`;
  const what =
    levels === 0
      ? `The control mesh ${subject.modelName} (${faces})`
      : `${subject.modelName} after ${levels} ${scheme} subdivision step${levels === 1 ? '' : 's'} (${faces})`;
  const extras = [
    params.overlays?.control ? 'the control mesh' : null,
    params.overlays?.curves ? 'the control-edge curves' : null,
    params.overlays?.bbox ? 'the bounding box' : null,
  ].filter((x): x is string => x !== null);
  const shown = extras.length > 0 ? `, ${mode}, with ${joinAnd(extras)}` : `, ${mode}`;
  return `${what}${shown}.`;
}

function joinAnd(items: string[]): string {
  return items.length <= 1 ? items.join('') : `${items.slice(0, -1).join(', ')} and ${items[items.length - 1]}`;
}

/**
 * A `<script>` that defines the element and one `<subdiv-viewer>` in this
 * state. Scheme and levels are always written; overlays only away from
 * their defaults, the line width when set.
 */
export function elementSnippet(params: ViewerParams, subject: EmbedSubject): string {
  const p = withAbsoluteSrc(params, subject.appBase);
  const attrs: string[] = [];
  const add = (name: string, value?: string) =>
    attrs.push(value === undefined ? name : `${name}="${escapeAttribute(value)}"`);
  if (p.src) add('src', p.src);
  add('scheme', p.scheme ?? 'catmull-clark');
  add('levels', String(p.levels ?? 0));
  if (p.renderMode) add('render-mode', p.renderMode);
  for (const [name, key] of Object.entries(OVERLAY_KEYS) as [keyof typeof OVERLAY_KEYS, string][]) {
    // Away from its default only: present when on, "0" when off (the creases are on by default).
    const on = p.overlays?.[name];
    if (on !== undefined && on !== OVERLAY_DEFAULTS[name]) add(key, on ? undefined : '0');
  }
  if (p.triangulate) add('triangulate');
  if (p.view) add('view', formatViewString(p.view));
  if (p.beside && p.beside.length > 0) add('beside', p.beside.join(' '));
  if (p.lineWidth !== undefined) add('line-width', String(p.lineWidth));
  add('controls', 'minimal');
  add('alt', describeView(p, subject));
  // A classic script (embed/subdiv-viewer-loader.ts): it runs on a host without CORS too, where it says what is missing.
  const script = `<script defer src="${escapeAttribute(`${subject.appBase}embed/subdiv-viewer.js`)}"></script>`;
  // One attribute a line: a teacher reads and edits the snippet.
  return `${script}\n<subdiv-viewer\n  ${attrs.join('\n  ')}\n></subdiv-viewer>`;
}

/** An `<iframe>` of the app's `embed.html` route with the state in its query. */
export function iframeSnippet(params: ViewerParams, subject: EmbedSubject): string {
  const p = withAbsoluteSrc(params, subject.appBase);
  const query = paramsText({ ...p, scheme: p.scheme ?? 'catmull-clark', levels: p.levels ?? 0, controls: 'minimal' });
  const src = `${subject.appBase}embed.html?${query}`;
  const title = describeView(p, subject);
  const { width, height } = IFRAME_SIZE;
  return (
    `<iframe\n  src="${escapeAttribute(src)}"\n  width="${width}" height="${height}"\n` +
    `  title="${escapeAttribute(title)}"\n  loading="lazy" style="border:0"\n></iframe>`
  );
}
