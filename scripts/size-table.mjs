#!/usr/bin/env node
// The README's size tables, measured from the built site (the last step of
// `npm run build:site`): each file a page fetches, raw and gzipped (zlib
// level 9), and what the page fetches in all. What a page fetches is found by
// following file names: the page's <script src>, modulepreload and stylesheet
// links, then every built file that a fetched file names by its path from
// that file's folder (a chunk's import, the worker's URL, the .wasm's URL).
//
// Two tables, each between marker comments in README.md:
//   <!-- sizes:begin app -->   dist/: the app (index.html) and embed.html
//   <!-- sizes:begin embed --> dist/embed/: the <subdiv-viewer> module
// ending at <!-- sizes:end -->. tests/e2e/readme-sizes.spec.ts checks them
// against a build. Usage: node scripts/size-table.mjs [--dist dist] [--readme README.md]
import { readdirSync, readFileSync, statSync, writeFileSync } from 'node:fs';
import { basename, join, posix, relative } from 'node:path';
import { gzipSync } from 'node:zlib';

const option = (name, fallback) => {
  const at = process.argv.indexOf(name);
  return at >= 0 ? process.argv[at + 1] : fallback;
};
const dist = option('--dist', 'dist');
const readmePath = option('--readme', 'README.md');

/** The JS, CSS and .wasm files under `dir`, as paths relative to it ('/'-separated). */
function builtFiles(dir) {
  return readdirSync(dir, { recursive: true })
    .map((path) => String(path).split(/[\\/]/).join('/'))
    .filter((path) => /\.(js|mjs|css|wasm)$/.test(path) && statSync(join(dir, path)).isFile());
}

/**
 * What a page fetches from `folder`, starting from `entries` (paths relative to it), in the order met:
 * a built file is fetched when a fetched file names it by its path relative to that file's folder. One
 * file names two it picks between: the element's loader (subdiv-viewer.js, web/embed/subdiv-viewer-loader.ts)
 * adds iframe-route.js when its script tag has `data-route` (embed.html), else the element's module.
 */
function fetchedFrom(folder, entries, candidates, route = false) {
  const fetched = [];
  const queue = [...entries];
  while (queue.length > 0) {
    const path = queue.shift();
    if (fetched.includes(path)) continue;
    fetched.push(path);
    let named = names(folder, path, candidates);
    if (basename(path) === 'subdiv-viewer.js') {
      named = named.filter((other) =>
        route ? !/^subdiv-viewer-[A-Za-z0-9_-]{8}\.js$/.test(basename(other)) : basename(other) !== 'iframe-route.js',
      );
    }
    for (const other of named) if (!fetched.includes(other)) queue.push(other);
  }
  return fetched;
}

/** The files of `candidates` that file `path` names by their path from its folder. */
function names(folder, path, candidates) {
  if (path.endsWith('.wasm')) return [];
  const text = readFileSync(join(folder, path), 'utf8');
  return candidates.filter((other) => other !== path && text.includes(posix.relative(posix.dirname(path), other)));
}

/**
 * The files an HTML page loads itself (scripts, modulepreloads, stylesheets; relative to `folder`),
 * and whether a script of it has `data-route` (embed.html's loader).
 */
function pageEntries(folder, page) {
  const html = readFileSync(join(folder, page), 'utf8');
  const tags = [...html.matchAll(/<(?:script|link)\b[^>]*\b(?:src|href)="([^"]+)"[^>]*>/g)].filter(([tag]) =>
    /<script\b|rel="(?:modulepreload|stylesheet)"/.test(tag),
  );
  return {
    entries: tags.map(([, url]) => url.replace(/^\.\//, '')).filter((path) => !/^[a-z]+:/.test(path)),
    route: tags.some(([tag]) => /<script\b[^>]*\sdata-route\b/.test(tag)),
  };
}

const gzipped = (bytes) => gzipSync(bytes, { level: 9 }).length;

function measure(folder, path) {
  const bytes = readFileSync(join(folder, path));
  return { path, raw: bytes.length, gzip: gzipped(bytes) };
}

/** A built name with its content hash as `*` (assets/subdivlab-BdhYv3zc.wasm → assets/subdivlab-*.wasm). */
const pattern = (path) => path.replace(/-[A-Za-z0-9_-]{8}(\.(?:js|mjs|css|wasm))$/, '-*$1');

/** Sizes as the README writes them: bytes below 1 kB, kB (1,000 bytes) below 1 MB, else MB with two decimals. */
function formatSize(bytes) {
  if (bytes >= 1_000_000) return `${(bytes / 1_000_000).toFixed(2)} MB`;
  if (bytes >= 1000) return `${Math.round(bytes / 1000)} kB`;
  return `${bytes} B`;
}

/** What each kind of built file is, by the name Vite gives it; `fetches` are the files it names. */
function roleOf(path, sharedBy, fetches) {
  const name = basename(path);
  if (name === 'subdiv-viewer.js') {
    return fetches.some((other) => /\.m?js$/.test(other) && !other.includes('subdiv-worker-'))
      ? 'what a page includes: loads the modules beside it'
      : 'element, viewer, three.js';
  }
  if (name.startsWith('subdiv-viewer-element-')) return 'element, viewer, three.js';
  if (/^subdiv-viewer-[A-Za-z0-9_-]{8}\.js$/.test(name)) return 'the module that defines `<subdiv-viewer>`';
  if (name === 'iframe-route.js') return "`embed.html`'s script";
  if (name.startsWith('subdiv-worker-')) return 'worker + Emscripten glue';
  if (name.endsWith('.wasm')) return 'CGAL core';
  if (name.endsWith('.css')) return "the app's styles";
  if (name.startsWith('index-')) return 'the app';
  if (name.startsWith('embed-')) return '`embed.html`, the iframe route';
  if (sharedBy.length > 1) return `viewer and three.js, shared by ${sharedBy.map((p) => `\`${p}\``).join(' and ')}`;
  return 'a chunk';
}

function row(label, size) {
  return `| ${label} | ${formatSize(size.raw)} | ${formatSize(size.gzip)} |`;
}

const total = (sizes) => sizes.reduce((a, b) => ({ raw: a.raw + b.raw, gzip: a.gzip + b.gzip }), { raw: 0, gzip: 0 });

/**
 * A table of what `pages` fetch from `folder` (each `{ name, entries, route, label }`): a row per file
 * (first met first), then a row per page with what it fetches in all.
 */
function table(folder, candidates, pages) {
  const perPage = pages.map((page) => ({ ...page, files: fetchedFrom(folder, page.entries, candidates, page.route) }));
  const files = [...new Set(perPage.flatMap((page) => page.files))];
  const lines = ['| file | size | gzip |', '|---|---:|---:|'];
  for (const path of files) {
    const sharedBy = perPage.filter((page) => page.files.includes(path)).map((page) => page.name);
    const role = roleOf(path, sharedBy, names(folder, path, candidates));
    lines.push(row(`\`${pattern(path)}\` (${role})`, measure(folder, path)));
  }
  for (const page of perPage) lines.push(row(page.label, total(page.files.map((path) => measure(folder, path)))));
  return lines.join('\n');
}

const appTable = table(
  dist,
  builtFiles(dist),
  ['index.html', 'embed.html'].map((name) => ({
    name,
    ...pageEntries(dist, name),
    label: `**${name === 'index.html' ? 'the app' : 'the iframe route'} (\`${name}\`) fetches in all**`,
  })),
);
// The element's folder has no page of its own: a teacher's page loads subdiv-viewer.js.
const embedFolder = join(dist, 'embed');
const embedTable = table(embedFolder, builtFiles(embedFolder), [
  {
    name: 'subdiv-viewer.js',
    entries: ['subdiv-viewer.js'],
    label: '**a page with one `<subdiv-viewer>` fetches in all**',
  },
]);

let readme = readFileSync(readmePath, 'utf8');
for (const [name, text] of [
  ['app', appTable],
  ['embed', embedTable],
]) {
  const block = new RegExp(`(<!-- sizes:begin ${name} -->)[\\s\\S]*?(<!-- sizes:end -->)`);
  if (!block.test(readme)) {
    console.error(`[size-table] ${readmePath} has no "<!-- sizes:begin ${name} -->" … "<!-- sizes:end -->" block`);
    process.exit(1);
  }
  readme = readme.replace(block, (_match, begin, end) => `${begin}\n${text}\n${end}`);
}
writeFileSync(readmePath, readme);
console.log(`[size-table] ${relative('.', readmePath)}: sizes of ${dist}/ and ${dist}/embed/ written`);
console.log(appTable);
console.log(embedTable);
