/**
 * Every embedding snippet of the README (readme-snippets.ts finds them) runs
 * as a teacher would paste it: on a page served by a second server (another
 * origin), with only `https://HOST/subdivlab/` replaced by the test site's
 * address. Each viewer must reach the level and counts its comment states,
 * and the stated counts must be the scheme's, worked out here from the mesh
 * file's level-0 counts (helpers.ts), not read from the viewer. An iframe's
 * level and counts are read from its `level-change` messages. The JavaScript
 * blocks (event listeners, postMessage commands) are not pages and are left out.
 */
import { readFileSync } from 'node:fs';
import { createServer } from 'node:http';
import type { AddressInfo } from 'node:net';
import { join } from 'node:path';
import type { Page } from '@playwright/test';
import { expect, test } from './fixtures';
import { type Counts, edgeCount, expectedClosedCounts, type OffMesh, readOff } from './helpers';
import {
  embeddingSnippets,
  onSite,
  PLACEHOLDER_HOST,
  readSnippets,
  type Snippet,
  type SnippetViewer,
  type StatedOutcome,
  sitePath,
} from './readme-snippets';

const dist = process.env.SUBDIVLAB_E2E_DIST ?? 'dist';

/** CGAL's Loop and √3 refine triangle meshes only (their hosts PTQ and √3). */
const NEEDS_TRIANGLES = new Set(['loop', 'sqrt3']);

const isOn = (value: string | undefined) =>
  value !== undefined && ['', '1', 'true', 'on', 'yes'].includes(value.toLowerCase());

/** Counts of a closed mesh; throws on an open one (helpers.ts counts closed meshes). */
function closedCounts(mesh: OffMesh, path: string): Counts {
  const uses = new Map<string, number>();
  for (const f of mesh.faces) {
    for (let k = 0; k < f.length; k++) {
      const [a, b] = [f[k], f[(k + 1) % f.length]];
      const key = a < b ? `${a},${b}` : `${b},${a}`;
      uses.set(key, (uses.get(key) ?? 0) + 1);
    }
  }
  if ([...uses.values()].some((n) => n !== 2)) throw new Error(`${path} is not closed: no count formula here`);
  return { vertices: mesh.positions.length, edges: edgeCount(mesh), faces: mesh.faces.length };
}

/** A polygon of n sides becomes n − 2 triangles by n − 3 diagonals; the vertices stay. */
function triangulated(mesh: OffMesh, start: Counts): Counts {
  const diagonals = mesh.faces.reduce((sum, f) => sum + f.length - 3, 0);
  return { vertices: start.vertices, edges: start.edges + diagonals, faces: start.faces + diagonals };
}

/** What `viewer` should show, from its settings and its mesh file in the built site, or why it cannot. */
function expectedOutcome(viewer: SnippetViewer): { outcome: StatedOutcome } | { problem: string } {
  const src = viewer.settings.src;
  if (!src) return { problem: 'it has no src' };
  const path = sitePath(viewer.meshUrl);
  if (path === null) {
    return {
      problem: `its src "${src}" is not on ${PLACEHOLDER_HOST}: from a page on another host it is ${viewer.meshUrl}`,
    };
  }
  if (!path.endsWith('.off')) return { problem: `${path}: this test counts OFF meshes only` };
  const mesh = readOff(readFileSync(join(dist, path), 'utf8'));
  const scheme = viewer.settings.scheme ?? 'catmull-clark';
  const level = Number(viewer.settings.levels ?? 0);
  let start = closedCounts(mesh, path);
  const sides = [...new Set(mesh.faces.map((f) => f.length))].sort();
  if (NEEDS_TRIANGLES.has(scheme) && sides.some((n) => n !== 3)) {
    if (!isOn(viewer.settings.triangulate))
      return {
        problem: `${scheme} needs triangles and ${path} has faces of ${sides.join(', ')} sides: no triangulate`,
      };
    start = triangulated(mesh, start);
  }
  return { outcome: { level, ...expectedClosedCounts(scheme, start, level) } };
}

declare global {
  interface Window {
    /** What the snippet's viewers said, by kind and index: level-change, error and progress. */
    __snippetEvents?: { kind: 'element' | 'iframe'; index: number; type: string; detail: Record<string, unknown> }[];
  }
}

/** Records every viewer's events on the top page, an element's by its place among the page's elements, an iframe's by its frame. */
async function recordViewerEvents(page: Page): Promise<void> {
  await page.addInitScript(() => {
    if (window !== window.top) return;
    const events: NonNullable<Window['__snippetEvents']> = [];
    window.__snippetEvents = events;
    for (const type of ['level-change', 'error', 'progress']) {
      document.addEventListener(type, (event) => {
        const target = event.target as Element;
        if (target.localName !== 'subdiv-viewer') return;
        const index = [...document.querySelectorAll<Element>('subdiv-viewer')].indexOf(target);
        events.push({
          kind: 'element',
          index,
          type,
          detail: JSON.parse(JSON.stringify((event as CustomEvent).detail)),
        });
      });
    }
    window.addEventListener('message', (event) => {
      const data = event.data as { subdivlab?: unknown };
      if (!data || typeof data.subdivlab !== 'string') return;
      const index = [...document.querySelectorAll('iframe')].findIndex((f) => f.contentWindow === event.source);
      if (index >= 0)
        events.push({ kind: 'iframe', index, type: data.subdivlab, detail: JSON.parse(JSON.stringify(data)) });
    });
  });
}

interface Observed {
  level: number;
  busy: boolean;
  counts: Counts | null;
  errors: string[];
}

/** What `viewer` shows now: an element's own properties, an iframe's last level-change and progress messages. */
async function observe(page: Page, viewer: SnippetViewer): Promise<Observed> {
  return page.evaluate(({ kind, index }) => {
    const mine = (window.__snippetEvents ?? []).filter((e) => e.kind === kind && e.index === index);
    const errors = mine.filter((e) => e.type === 'error').map((e) => `${e.detail.code}: ${e.detail.message}`);
    const counts = (facts: { vertices: number; edges: number; faces: number } | null | undefined) =>
      facts ? { vertices: facts.vertices, edges: facts.edges, faces: facts.faces } : null;
    if (kind === 'element') {
      const element = document.querySelectorAll('subdiv-viewer')[index] as HTMLElementTagNameMap['subdiv-viewer'];
      // Busy until started (state null), and while a load or a step runs.
      const busy = element.state === null || element.state.busy !== null;
      return { level: element.level, busy, counts: counts(element.facts), errors };
    }
    const change = mine.filter((e) => e.type === 'level-change').at(-1)?.detail;
    const progress = mine.filter((e) => e.type === 'progress').at(-1)?.detail;
    return {
      level: typeof change?.level === 'number' ? change.level : -1,
      busy: progress?.busy === true,
      counts: counts(change?.facts as { vertices: number; edges: number; faces: number } | undefined),
      errors,
    };
  }, viewer);
}

/** Serves `html` as /course/lesson.html from a second server on this machine (another origin) while `body` runs. */
async function onAnotherOrigin(html: string, body: (url: string) => Promise<void>): Promise<void> {
  const server = createServer((request, response) => {
    if (request.url !== '/course/lesson.html') {
      response.writeHead(404, { 'content-type': 'text/plain' });
      response.end('Not found');
      return;
    }
    response.writeHead(200, { 'content-type': 'text/html; charset=utf-8' });
    response.end(html);
  });
  await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
  try {
    await body(`http://127.0.0.1:${(server.address() as AddressInfo).port}/course/lesson.html`);
  } finally {
    await new Promise<void>((resolve) => server.close(() => resolve()));
  }
}

/** The snippet, as written but for HOST, alone in a page's body. */
const lessonPage = (snippet: Snippet, site: string) =>
  `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>${snippet.where}</title><link rel="icon" href="data:,"></head><body>
${onSite(snippet.html, site)}
</body></html>`;

/** Loads the snippet from another origin and waits until each viewer is idle at its level, or idle after naming a problem. */
async function runSnippet(page: Page, snippet: Snippet, site: string, levels: number[]): Promise<Observed[]> {
  const seen: Observed[] = [];
  await onAnotherOrigin(lessonPage(snippet, site), async (url) => {
    expect(new URL(url).origin).not.toBe(new URL(site).origin);
    await page.goto(url);
    for (const [i, viewer] of snippet.viewers.entries()) {
      // Viewers start when they come near the viewport.
      await page
        .locator(viewer.kind === 'element' ? 'subdiv-viewer' : 'iframe')
        .nth(viewer.index)
        .scrollIntoViewIfNeeded();
      await expect
        .poll(
          async () => {
            const now = await observe(page, viewer);
            return !now.busy && (now.level === levels[i] || now.errors.length > 0);
          },
          { message: `${snippet.where}: ${viewer.tag} reaches level ${levels[i]}`, timeout: 120_000 },
        )
        .toBe(true);
      seen.push(await observe(page, viewer));
    }
  });
  return seen;
}

const snippets = embeddingSnippets();

test('the README has element and iframe snippets, found with what each says it shows', () => {
  const kinds = snippets.flatMap((s) => s.viewers.map((v) => v.kind));
  expect(kinds).toContain('element');
  expect(kinds).toContain('iframe');
  // The extraction itself, on a block written as the README writes them.
  const [sample] = readSnippets(
    [
      '```html',
      `<iframe src="${PLACEHOLDER_HOST}embed.html?src=meshes/cube.off&amp;levels=1" title="t"></iframe>`,
      '<!-- shows level 1:',
      '     24 faces, 48 edges, 26 vertices -->',
      '<subdiv-viewer src="meshes/cube.off" scheme="loop" levels="2"></subdiv-viewer>',
      '<!-- level 2 -->',
      '```',
    ].join('\n'),
    'sample.md',
  );
  expect(sample.where).toBe('sample.md:1');
  expect(
    sample.viewers.map(({ kind, index, settings, outcome, outcomeText }) => ({
      kind,
      index,
      settings,
      outcome,
      outcomeText,
    })),
  ).toEqual([
    {
      kind: 'iframe',
      index: 0,
      settings: { src: 'meshes/cube.off', levels: '1' },
      outcome: { level: 1, faces: 24, edges: 48, vertices: 26 },
      outcomeText: '',
    },
    {
      kind: 'element',
      index: 0,
      settings: { src: 'meshes/cube.off', scheme: 'loop', levels: '2' },
      outcome: null,
      outcomeText: '<!-- level 2 -->',
    },
  ]);
  expect(sitePath(sample.viewers[0].meshUrl)).toBe('meshes/cube.off');
  expect(expectedOutcome(sample.viewers[0])).toEqual({ outcome: { level: 1, faces: 24, edges: 48, vertices: 26 } });
  // A relative src on an element is the lesson page's, not the site's; Loop on quads needs triangulate.
  expect(expectedOutcome(sample.viewers[1])).toEqual({
    problem: `its src "meshes/cube.off" is not on ${PLACEHOLDER_HOST}: from a page on another host it is https://lesson.example/course/meshes/cube.off`,
  });
});

for (const snippet of snippets) {
  const names = snippet.viewers.map((v) => (v.kind === 'iframe' ? '<iframe>' : '<subdiv-viewer>'));
  test(`${snippet.where} (${names.join(', ')}) shows what it states, from a page on another origin`, async ({
    embed,
    page,
    baseURL,
  }) => {
    test.setTimeout(60_000 + 120_000 * snippet.viewers.length);
    const expected = snippet.viewers.map((viewer) => {
      expect(
        viewer.outcome,
        `${snippet.where}: ${viewer.tag} states no outcome (a comment after it such as "<!-- shows level 2: 768 faces, 1,536 edges, 768 vertices -->"${viewer.outcomeText ? `; found ${viewer.outcomeText}` : ''})`,
      ).not.toBeNull();
      const want = expectedOutcome(viewer);
      expect(want, `${snippet.where}: ${viewer.tag}`).not.toHaveProperty('problem');
      if ('problem' in want) throw new Error(want.problem);
      expect(viewer.outcome, `${snippet.where}: ${viewer.tag} states the scheme's counts`).toEqual(want.outcome);
      return want.outcome;
    });
    await recordViewerEvents(page);
    const seen = await runSnippet(
      page,
      snippet,
      new URL(baseURL ?? '').origin,
      expected.map((e) => e.level),
    );
    for (const [i, viewer] of snippet.viewers.entries()) {
      const { level, faces, edges, vertices } = expected[i];
      expect(
        { level: seen[i].level, ...seen[i].counts, errors: seen[i].errors },
        `${snippet.where}: ${viewer.tag}`,
      ).toEqual({ level, faces, edges, vertices, errors: [] });
    }
    await page.evaluate(() => window.scrollTo(0, 0));
    await embed.snapshot(`readme-snippet-${snippet.where.replace(/\W+/g, '-')}`, true);
  });
}

test("issue 29's snippet, Loop on the all-quad torus, is caught: level 0 and not_triangles", async ({
  embed,
  page,
  baseURL,
}) => {
  const [snippet] = readSnippets(
    [
      '```html',
      `<script type="module" src="${PLACEHOLDER_HOST}embed/subdiv-viewer.js"></script>`,
      `<subdiv-viewer src="${PLACEHOLDER_HOST}meshes/torus.off" scheme="loop" levels="2"></subdiv-viewer>`,
      '<!-- shows level 2: 1,536 faces, 2,304 edges, 768 vertices -->',
      '```',
    ].join('\n'),
    'issue-29.md',
  );
  expect(expectedOutcome(snippet.viewers[0])).toEqual({
    problem: 'loop needs triangles and meshes/torus.off has faces of 4 sides: no triangulate',
  });
  await recordViewerEvents(page);
  const [seen] = await runSnippet(page, snippet, new URL(baseURL ?? '').origin, [2]);
  expect(seen).toMatchObject({ level: 0, counts: { vertices: 48, edges: 96, faces: 48 } });
  expect(seen.errors).toEqual([expect.stringMatching(/^not_triangles: /)]);
  expect((await embed.events('error')).map((e) => e.detail.code)).toEqual(['not_triangles']);
});
