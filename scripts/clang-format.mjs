#!/usr/bin/env node
// Formats the C++ sources with clang-format (Google style, .clang-format), or
// with --check lists the files that are not formatted and exits 1.
// Usage: node scripts/clang-format.mjs [--check]
import { spawnSync } from 'node:child_process';
import { readdirSync } from 'node:fs';
import { dirname, join, relative } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const check = process.argv.includes('--check');
const DIRS = ['wasm/src', 'wasm/bench', 'tests/core', 'tests/fuzz'];

function sources(dir) {
  return readdirSync(join(root, dir), { withFileTypes: true, recursive: true })
    .filter((e) => e.isFile() && /\.(cpp|h)$/.test(e.name))
    .map((e) => relative(root, join(e.parentPath ?? e.path, e.name)));
}

const tool = ['clang-format', 'clang-format-14', 'clang-format-15', 'clang-format-16'].find(
  (name) => spawnSync(name, ['--version']).status === 0,
);
if (!tool) {
  console.error('clang-format not found (Debian package clang-format)');
  process.exit(1);
}
const files = DIRS.flatMap((d) => {
  try {
    return sources(d);
  } catch {
    return [];
  }
});
const args = check ? ['--dry-run', '-Werror', ...files] : ['-i', ...files];
const r = spawnSync(tool, args, { cwd: root, stdio: 'inherit' });
process.exit(r.status ?? 1);
