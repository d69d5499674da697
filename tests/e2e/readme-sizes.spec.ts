/**
 * The README's size tables against the site Playwright built (its folder is
 * SUBDIVLAB_E2E_DIST, default dist/): each file row within 3 % or 2 kB of
 * the built file, raw and gzipped (zlib level 9, measured here); and what a
 * browser fetches, recorded on the page, is the table's files and totals: a
 * page with one `<subdiv-viewer>` for the embed table, the app and
 * embed.html for the app's. `npm run build` rewrites the tables
 * (scripts/size-table.mjs).
 */
import { readdirSync, readFileSync } from 'node:fs';
import { join, sep } from 'node:path';
import { gzipSync } from 'node:zlib';
import type { Page } from '@playwright/test';
import { viewerPage } from './embed-page';
import { expect, test } from './fixtures';

const dist = process.env.SUBDIVLAB_E2E_DIST ?? 'dist';
const FIX = 'run `npm run build` to measure them again (scripts/size-table.mjs rewrites the tables)';

interface Size {
  raw: number;
  gzip: number;
}

interface SizeRow extends Size {
  /** The row's first cell as written. */
  label: string;
  /** A file row's name, `*` for the content hash (`assets/subdivlab-*.wasm`); null on a total row. */
  file: string | null;
}

/** "167 B", "735 kB" → 735,000 bytes, "2.03 MB" → 2,030,000 (the README's kB and MB are 1,000 and 1,000,000 bytes). */
function bytes(text: string): number {
  const match = text.trim().match(/^([\d.,]+) (B|kB|MB)$/);
  if (!match) throw new Error(`not a size: "${text}"`);
  return Number(match[1].replace(/,/g, '')) * { B: 1, kB: 1000, MB: 1_000_000 }[match[2] as 'B' | 'kB' | 'MB'];
}

/** The rows of the README's table between `<!-- sizes:begin name -->` and `<!-- sizes:end -->`. */
function sizeTable(name: string): SizeRow[] {
  const readme = readFileSync('README.md', 'utf8');
  const block = readme.match(new RegExp(`<!-- sizes:begin ${name} -->([\\s\\S]*?)<!-- sizes:end -->`));
  if (!block) throw new Error(`README.md has no "<!-- sizes:begin ${name} -->" … "<!-- sizes:end -->"`);
  return block[1]
    .split('\n')
    .filter((line) => /^\|/.test(line) && !/^\|\s*(file|-)/i.test(line))
    .map((line) => {
      const [label, raw, gzip] = line.split('|').slice(1, 4);
      const total = /fetches in all/.test(label);
      return {
        label: label.trim(),
        file: total ? null : (label.match(/`([^`]+)`/)?.[1] ?? null),
        raw: bytes(raw),
        gzip: bytes(gzip),
      };
    });
}

function measure(path: string): Size {
  const data = readFileSync(path);
  return { raw: data.length, gzip: gzipSync(data, { level: 9 }).length };
}

const sum = (sizes: Size[]) =>
  sizes.reduce((a, b) => ({ raw: a.raw + b.raw, gzip: a.gzip + b.gzip }), { raw: 0, gzip: 0 });

/** A row's figures against measured ones: within 3 % or 2 kB, whichever is more. */
function expectClose(row: SizeRow, actual: Size): void {
  for (const key of ['raw', 'gzip'] as const) {
    const allowed = Math.max(0.03 * actual[key], 2000);
    expect
      .soft(
        Math.abs(row[key] - actual[key]) <= allowed,
        `README.md's size table, "${row.label}" (${key}): says ${row[key].toLocaleString('en')} bytes, the build makes ${actual[key].toLocaleString('en')}; ${FIX}`,
      )
      .toBe(true);
  }
}

/**
 * The table's row for built file `path` (relative to the table's folder): its name with `*` for
 * Vite's 8-character content hash (so `assets/subdiv-viewer-*.js` is not `assets/subdiv-viewer-element-*.js`).
 */
function rowOf(rows: SizeRow[], path: string): SizeRow | undefined {
  return rows.find((row) => {
    if (row.file === null) return false;
    const glob = row.file.replace(/[.+?^${}()|[\]\\]/g, '\\$&').replace(/\*/g, '[A-Za-z0-9_-]{8}');
    return new RegExp(`^${glob}$`).test(path);
  });
}

/** Records the JS, CSS and .wasm the page (and its workers) fetch from the site, as paths in the built folder. */
function recordFetches(page: Page, site: string): string[] {
  const fetched: string[] = [];
  page.on('request', (request) => {
    const url = new URL(request.url());
    if (url.origin !== site || !/\.(js|mjs|css|wasm)$/.test(url.pathname)) return;
    const path = decodeURIComponent(url.pathname.slice(1));
    if (!fetched.includes(path)) fetched.push(path);
  });
  return fetched;
}

/** The built JS, CSS and .wasm files under `folder`, as '/'-separated paths relative to it. */
function builtFiles(folder: string): string[] {
  return readdirSync(folder, { recursive: true })
    .map((path) => String(path).split(sep).join('/'))
    .filter((path) => /\.(js|mjs|css|wasm)$/.test(path));
}

test("each file row of the README's size tables is its built file, raw and gzipped", () => {
  for (const [name, folder] of [
    ['app', dist],
    ['embed', join(dist, 'embed')],
  ] as const) {
    const rows = sizeTable(name);
    expect(
      rows.filter((row) => row.file !== null).length,
      `README.md's ${name} size table's file rows`,
    ).toBeGreaterThan(0);
    const files = builtFiles(folder);
    for (const row of rows) {
      if (row.file === null) continue;
      const matches = files.filter((path) => rowOf([row], path) === row);
      expect(matches, `README.md's "${row.label}": one built file in ${folder}/; ${FIX}`).toHaveLength(1);
      expectClose(row, measure(join(folder, matches[0])));
    }
  }
});

/**
 * The files fetched, each on a row of `rows`, and each page's total on the
 * row whose label names `page` (its page, or the element).
 */
function expectFetchedAsTabled(rows: SizeRow[], folder: string, fetched: Map<string, string[]>): void {
  const all = [...new Set([...fetched.values()].flat())];
  for (const path of all)
    expect.soft(rowOf(rows, path), `${path} is fetched; a row of the table names it; ${FIX}`).toBeDefined();
  const listed = rows.filter((row) => row.file !== null).map((row) => row.label);
  const fetchedRows = new Set(all.map((path) => rowOf(rows, path)?.label));
  expect
    .soft(
      listed.filter((label) => !fetchedRows.has(label)),
      `rows of files no page fetched; ${FIX}`,
    )
    .toEqual([]);
  for (const [page, paths] of fetched) {
    const total = rows.find((row) => row.file === null && row.label.includes(page));
    expect(total, `a row "… ${page} … fetches in all"; ${FIX}`).toBeDefined();
    if (total) expectClose(total, sum(paths.map((path) => measure(join(folder, path)))));
  }
}

test("a page with one <subdiv-viewer> fetches the embed table's files, its total in all", async ({
  embed,
  page,
  baseURL,
}) => {
  const site = new URL(baseURL ?? '').origin;
  const fetched = recordFetches(page, site);
  await embed.serve(
    'e2e/one-viewer.html',
    viewerPage('One viewer', '', '<subdiv-viewer id="one" src="../meshes/cube.off" levels="1"></subdiv-viewer>'),
  );
  await page.goto('./e2e/one-viewer.html');
  await embed.waitForLevel('one', 1);
  const paths = fetched.filter((path) => path.startsWith('embed/')).map((path) => path.slice('embed/'.length));
  expect(
    paths.some((path) => path.endsWith('.wasm')),
    'the .wasm was fetched',
  ).toBe(true);
  expectFetchedAsTabled(sizeTable('embed'), join(dist, 'embed'), new Map([['<subdiv-viewer>', paths]]));
});

test("the app and embed.html fetch the app table's files, each its total in all", async ({
  app,
  page,
  browser,
  baseURL,
}) => {
  const site = new URL(baseURL ?? '').origin;
  const appFetched = recordFetches(page, site);
  await app.openFirstVisit();
  expect(
    appFetched.some((path) => path.endsWith('.wasm')),
    'the app fetched the .wasm',
  ).toBe(true);
  // embed.html in a context of its own, so that nothing comes from the app's cache.
  const context = await browser.newContext();
  try {
    const frame = await context.newPage();
    const errors: string[] = [];
    frame.on('console', (message) => {
      if (message.type() === 'error') errors.push(message.text());
    });
    frame.on('pageerror', (error) => errors.push(error.message));
    const frameFetched = recordFetches(frame, site);
    await frame.goto(`${site}/embed.html?src=meshes/cube.off&levels=1`);
    await expect
      .poll(() =>
        frame.evaluate(
          () => (document.querySelector('subdiv-viewer') as HTMLElementTagNameMap['subdiv-viewer'] | null)?.level,
        ),
      )
      .toBe(1);
    expect(errors, 'console errors in embed.html').toEqual([]);
    expectFetchedAsTabled(
      sizeTable('app'),
      dist,
      new Map([
        ['`index.html`', appFetched],
        ['`embed.html`', frameFetched],
      ]),
    );
  } finally {
    await context.close();
  }
});
