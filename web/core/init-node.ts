/**
 * Node entry to the core (CLI, vitest): reads subdivlab.wasm from disk and
 * hands the bytes to init(), since Emscripten 3.1.6's web/worker glue would
 * otherwise fetch it by URL.
 */
import { existsSync, readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { init } from './subdiv-core';

const WASM_NAME = 'subdivlab.wasm';

/**
 * Where the .wasm may be: beside this source file (vitest), or, from a bundle
 * somewhere under build/, in the repository's web/core/generated/.
 */
function wasmCandidates(): string[] {
  let dir = dirname(fileURLToPath(import.meta.url));
  const candidates = [join(dir, 'generated', WASM_NAME)];
  for (let up = 0; up < 4; up++) {
    dir = dirname(dir);
    candidates.push(join(dir, 'web', 'core', 'generated', WASM_NAME));
  }
  return candidates;
}

/**
 * Loads the core in Node. `wasmPath` overrides the search, then
 * SUBDIVLAB_WASM under vitest (vitest.config.ts names the test build of
 * the module there, whose glue it also puts in place of the shipped one:
 * the shipped module has no test hooks); the module is built by
 * `node scripts/setup.mjs` (or `npm run build:wasm`).
 */
export async function initNode(wasmPath?: string): Promise<void> {
  // Read where vitest transforms this file (from process.env); a bundle (the CLI) has it replaced by nothing.
  const testBuild: string | undefined = import.meta.env?.SUBDIVLAB_WASM;
  const path = wasmPath ?? testBuild ?? wasmCandidates().find((p) => existsSync(p));
  if (!path) {
    throw new Error(`${WASM_NAME} not found (looked in ${wasmCandidates().join(', ')}); run npm run build:wasm`);
  }
  await init({ wasmBinary: readFileSync(path) });
}
