/**
 * The embedding snippets of README.md (and of any docs/*.md): every fenced
 * block that holds a `<subdiv-viewer>` or an `<iframe>`, with what each viewer
 * in it says it shows. A snippet states that in an HTML comment after the
 * viewer, `<!-- shows level 2: 768 faces, 1,536 edges, 768 vertices -->` (words
 * after the vertices, past a `;`, are for the reader);
 * `https://HOST/subdivlab/` in it stands for where the built site is served.
 * Blocks of JavaScript (the event and postMessage examples) hold no viewer
 * and are not snippets here.
 */
import { existsSync, readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';

/** What the snippets write for the built site's address (the folder that holds embed.html and embed/). */
export const PLACEHOLDER_HOST = 'https://HOST/subdivlab/';

export interface StatedOutcome {
  level: number;
  faces: number;
  edges: number;
  vertices: number;
}

export interface SnippetViewer {
  kind: 'element' | 'iframe';
  /** Its start tag as written. */
  tag: string;
  /** Which of its kind it is on the snippet's page (0 for the first `<subdiv-viewer>`, …). */
  index: number;
  /**
   * The viewer's settings: an element's attributes (a bare attribute is ''), an
   * iframe's query, whose keys are the attributes embed.html sets.
   */
  settings: Record<string, string>;
  /**
   * The mesh's address as the viewer resolves it, on a page at
   * `https://LESSON.example/course/lesson.html` (another host than HOST); '' without `src`.
   */
  meshUrl: string;
  /** What it says it shows, or null when no comment says it. */
  outcome: StatedOutcome | null;
  /** The comment that should state it, as written, when it does not read as one ('' when there is none). */
  outcomeText: string;
}

export interface Snippet {
  /** `README.md:647`, the line of the opening fence. */
  where: string;
  html: string;
  viewers: SnippetViewer[];
}

/** The page a snippet is read on, for resolving addresses: another host than HOST. */
export const LESSON_PAGE = 'https://LESSON.example/course/lesson.html';

const VIEWER_TAG = /<(subdiv-viewer|iframe)\b([^>]*)>/g;
// What follows the counts (after ; , or .) is for the reader.
const OUTCOME = /^<!--\s*shows level (\d+): ([\d,]+) faces, ([\d,]+) edges, ([\d,]+) vertices(?:[;,.][^>]*)?\s*-->$/;

const decode = (value: string) =>
  value
    .replace(/&quot;/g, '"')
    .replace(/&lt;/g, '<')
    .replace(/&gt;/g, '>')
    .replace(/&amp;/g, '&');

/** The attributes of a start tag's text after its name. */
function attributes(text: string): Record<string, string> {
  const out: Record<string, string> = {};
  for (const [, name, quoted, single, bare] of text.matchAll(
    /([^\s"'=<>/]+)(?:\s*=\s*(?:"([^"]*)"|'([^']*)'|([^\s"'=<>`]+)))?/g,
  ))
    out[name.toLowerCase()] = decode(quoted ?? single ?? bare ?? '');
  return out;
}

const number = (text: string) => Number(text.replace(/,/g, ''));

/** The viewers of one snippet's HTML, each with the outcome stated after it. */
export function snippetViewers(html: string): SnippetViewer[] {
  const matches = [...html.matchAll(VIEWER_TAG)];
  const seen = { element: 0, iframe: 0 };
  return matches.map((match, i) => {
    const kind = match[1] === 'iframe' ? 'iframe' : 'element';
    const attrs = attributes(match[2]);
    const after = html.slice((match.index ?? 0) + match[0].length, matches[i + 1]?.index ?? html.length);
    const comment = after.match(/<!--[\s\S]*?-->/)?.[0] ?? '';
    const stated = comment.replace(/\s+/g, ' ').match(OUTCOME);
    let settings = attrs;
    let meshUrl = '';
    if (kind === 'iframe') {
      const frameUrl = new URL(attrs.src ?? '', LESSON_PAGE);
      settings = Object.fromEntries(frameUrl.searchParams);
      if (settings.src) meshUrl = new URL(settings.src, frameUrl).href;
    } else if (attrs.src) {
      meshUrl = new URL(attrs.src, LESSON_PAGE).href;
    }
    return {
      kind,
      tag: match[0],
      index: seen[kind]++,
      settings,
      meshUrl,
      outcome: stated
        ? { level: number(stated[1]), faces: number(stated[2]), edges: number(stated[3]), vertices: number(stated[4]) }
        : null,
      outcomeText: stated ? '' : comment,
    };
  });
}

/** The fenced blocks of `markdown` that embed a viewer, named `file:line`. */
export function readSnippets(markdown: string, file: string): Snippet[] {
  const snippets: Snippet[] = [];
  const lines = markdown.split('\n');
  for (let i = 0; i < lines.length; i++) {
    const fence = lines[i].match(/^\s*(```+|~~~+)\s*(\S*)/);
    if (!fence) continue;
    const close = lines.findIndex((line, k) => k > i && line.trim() === fence[1]);
    const end = close < 0 ? lines.length : close;
    const html = lines.slice(i + 1, end).join('\n');
    const viewers = snippetViewers(html);
    // A block of HTML with a viewer, or one in another block that loads a model (not a tree of folders naming the tag).
    if (fence[2] === 'html' ? viewers.length > 0 : viewers.some((v) => /\ssrc\s*=/.test(v.tag)))
      snippets.push({ where: `${file}:${i + 1}`, html, viewers });
    i = end;
  }
  return snippets;
}

/** Every snippet of README.md and docs/**\/*.md under `root`. */
export function embeddingSnippets(root = '.'): Snippet[] {
  const files = ['README.md'];
  const docs = join(root, 'docs');
  if (existsSync(docs)) {
    for (const path of readdirSync(docs, { recursive: true }).map(String).sort())
      if (path.endsWith('.md')) files.push(join('docs', path));
  }
  return files.flatMap((file) => readSnippets(readFileSync(join(root, file), 'utf8'), file));
}

/** The snippet as a page on another host serves it: HOST's address replaced by `site` (an origin, or a folder ending in /). */
export function onSite(html: string, site: string): string {
  return html.split(PLACEHOLDER_HOST).join(site.endsWith('/') ? site : `${site}/`);
}

/** The path of `url` in the built site when it is on HOST (`meshes/torus.off`), else null. */
export function sitePath(url: string): string | null {
  // URL writes the host in lower case.
  if (!url.toLowerCase().startsWith(PLACEHOLDER_HOST.toLowerCase())) return null;
  return decodeURIComponent(url.slice(PLACEHOLDER_HOST.length).split(/[?#]/)[0]);
}
